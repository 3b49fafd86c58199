//! The three passes of stage 1 of a step (src/solver/forces.rs), each on its
//! own, on the paper slope at four mesh sizes (hexahedra in the name):
//!
//! - `element_forces/hex_N`: every element writes `K_e u_e` (eq. 12) into
//!   its slot: reads the upper triangle of its condensed `K_e` (300 values,
//!   2400 B; 4608 B before it was packed), gathers 8 corners x
//!   3 displacements, writes 24 values;
//! - `element_forces_1thread/hex_N`: the same on a one-thread rayon pool
//!   (to compare with the single-thread stream triad);
//! - `spring_forces/hex_N`: every spring writes its force on node `a`
//!   (eq. 15, elastic phase);
//! - `gather/hex_N`: every node sums its element slots and spring ends.
//!
//! Throughput is `Elements(n_elements)` for all of them, so criterion prints
//! element-steps per second and the three rates add as
//! `1 / r_step ~ sum 1 / r_pass`. The model sizes (nodes, springs) are
//! printed once at the start, for per-spring and per-node rates.
//!
//! Meshes: `verification/study/slope-h4.msh` (250 hexes),
//! `verification/cases/slope/slope.msh` (1000, the paper's case),
//! `verification/study/slope-h1.msh` (4000), `slope-h05.msh` (16000), built
//! from `verification/cases/slope/slope.toml` with its mesh file replaced.

mod common;

use cdem::model::{Model, ELEMENT_SLOT};
use cdem::physics::spring::SpringState;
use cdem::solver::forces;
use common::{meshes, slope_model};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

/// A smooth, deterministic displacement field (m); the kernels have no
/// data-dependent branches in the elastic phase, so any finite field times
/// the same.
fn displacement(model: &Model) -> Vec<f64> {
    (0..3 * model.n_nodes()).map(|k| 1e-3 * (0.37 * k as f64).sin()).collect()
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("kernels");
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("one-thread pool");
    for (mesh, n_hex) in meshes() {
        let model = slope_model(&mesh);
        let n_el = model.elements.len();
        assert_eq!(n_el, n_hex, "{}: expected {n_hex} hexahedra", mesh.display());
        eprintln!(
            "hex_{n_el}: {} nodes, {} springs, K_e total {:.1} MiB, {} rayon threads",
            model.n_nodes(),
            model.springs.len(),
            (model.elements.k.len() * 8) as f64 / (1 << 20) as f64,
            rayon::current_num_threads()
        );
        let u = displacement(&model);
        let springs = SpringState::new(model.springs.len());
        let mut f_elem = vec![0.0; ELEMENT_SLOT * n_el];
        let mut f_spring = vec![[0.0; 3]; model.springs.len()];
        let mut f_int = vec![0.0; 3 * model.n_nodes()];
        // Realistic inputs for the gather.
        forces::element_forces(&model, &u, &mut f_elem);
        forces::spring_forces(&model, &springs, &u, &mut f_spring);

        group.throughput(Throughput::Elements(n_el as u64));
        let id = |name: &str| BenchmarkId::new(name, format!("hex_{n_el}"));
        group.bench_function(id("element_forces"), |b| b.iter(|| forces::element_forces(&model, &u, &mut f_elem)));
        group.bench_function(id("element_forces_1thread"), |b| {
            one.install(|| b.iter(|| forces::element_forces(&model, &u, &mut f_elem)))
        });
        group.bench_function(id("spring_forces"), |b| {
            b.iter(|| forces::spring_forces(&model, &springs, &u, &mut f_spring))
        });
        group.bench_function(id("gather"), |b| b.iter(|| forces::gather(&model, &f_elem, &f_spring, &mut f_int)));
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
