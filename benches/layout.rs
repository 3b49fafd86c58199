//! Element-force layouts side by side (references/layout.md): the condensed
//! `K_e u_e` of the solver (`forces::element_forces`, 2400 B of packed `K_e` per
//! hexahedron) against the per-tetrahedron operator form
//! (`physics::tet_operator`, 24 x 9 f64 = 1728 B per hexahedron), on the
//! paper slope at 1000, 4000 and 16000 hexahedra, each on a 1-thread and a
//! 2-thread rayon pool. Throughput is `Elements(n)`: element-steps/s.
//!
//! - `condensed_Tt/hex_N`: `forces::element_forces` on a T-thread pool;
//! - `per_tet_Tt/hex_N`: the same pass (same slots, same rayon chunking) with
//!   `tet_element_force`.
//!
//! Before each model's criterion runs, the two passes are also alternated on
//! one thread and the best time of each printed (`interleaved best`), a
//! ratio less sensitive to other jobs on a shared machine.
//!
//! Meshes as in benches/kernels.rs: `verification/cases/slope/slope.msh`
//! (1000), `verification/study/slope-h1.msh` (4000), `slope-h05.msh` (16000),
//! built from `verification/cases/slope/slope.toml` with its mesh replaced.

mod common;

use std::time::Instant;

use cdem::model::{Model, ELEMENT_SLOT};
use cdem::physics::tet_operator::{tet_element_force, TetOperators};
use cdem::solver::forces;
use common::{meshes, slope_model};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rayon::prelude::*;

/// Same minimum task length as `forces::element_forces`.
const MIN_ELEMENTS: usize = 64;

/// The per-tet element pass, shaped like `forces::element_forces`.
fn per_tet_forces(model: &Model, ops: &TetOperators, u: &[f64], f_elem: &mut [f64]) {
    let el = &model.elements;
    f_elem.par_chunks_mut(ELEMENT_SLOT).with_min_len(MIN_ELEMENTS).enumerate().for_each(|(e, f_e)| {
        let nodes = el.corners(e);
        tet_element_force(ops.topology(el.kind[e]), ops.tets(e), ops.lame[e], nodes, u, &mut f_e[..3 * nodes.len()]);
    });
}

/// On a shared machine a criterion mean mixes in other jobs' time slices.
/// This alternates the two passes on one thread (about 2e6 element-steps
/// each) and prints the best pass of each: the least disturbed estimate, for
/// the ratio.
fn interleaved_best(
    model: &Model,
    ops: &TetOperators,
    u: &[f64],
    f_k: &mut [f64],
    f_t: &mut [f64],
    pool: &rayon::ThreadPool,
) {
    let n_el = model.elements.len();
    let reps = (2_000_000 / n_el).max(20);
    let (mut best_k, mut best_t) = (f64::INFINITY, f64::INFINITY);
    pool.install(|| {
        for _ in 0..reps {
            let t0 = Instant::now();
            forces::element_forces(model, u, f_k);
            best_k = best_k.min(t0.elapsed().as_secs_f64());
            let t0 = Instant::now();
            per_tet_forces(model, ops, u, f_t);
            best_t = best_t.min(t0.elapsed().as_secs_f64());
        }
    });
    let rate = |t: f64| n_el as f64 / t / 1e6;
    eprintln!(
        "hex_{n_el}: interleaved best of {reps}, 1 thread: condensed {:.2} M/s, per-tet {:.2} M/s, \
         per-tet/condensed {:.2}",
        rate(best_k),
        rate(best_t),
        best_k / best_t
    );
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("layout");
    let pools: Vec<(usize, rayon::ThreadPool)> = [1, 2]
        .into_iter()
        .map(|t| (t, rayon::ThreadPoolBuilder::new().num_threads(t).build().expect("rayon pool")))
        .collect();
    // The paper's mesh and larger (250 hexes is too small to tell the forms apart).
    for (mesh, n_hex) in meshes().into_iter().skip(1) {
        let model = slope_model(&mesh);
        let n_el = model.elements.len();
        assert_eq!(n_el, n_hex, "{}: expected {n_hex} hexahedra", mesh.display());
        let ops = model.tet_operators().expect("slope cells are valid");
        eprintln!(
            "hex_{n_el}: K_e {:.1} MiB, per-tet {:.1} MiB",
            (model.elements.k.len() * 8) as f64 / (1 << 20) as f64,
            ops.bytes() as f64 / (1 << 20) as f64
        );
        let u: Vec<f64> = (0..3 * model.n_nodes()).map(|k| 1e-3 * (0.37 * k as f64).sin()).collect();
        let mut f_k = vec![0.0; ELEMENT_SLOT * n_el];
        let mut f_t = vec![0.0; ELEMENT_SLOT * n_el];
        forces::element_forces(&model, &u, &mut f_k);
        per_tet_forces(&model, &ops, &u, &mut f_t);
        let diff = f_k.iter().zip(&f_t).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        let fmax = f_k.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        eprintln!("hex_{n_el}: max |f_condensed - f_per_tet| / max |f| = {:.1e}", diff / fmax);

        interleaved_best(&model, &ops, &u, &mut f_k, &mut f_t, &pools[0].1);

        group.throughput(Throughput::Elements(n_el as u64));
        for (threads, pool) in &pools {
            let id = |name: &str| BenchmarkId::new(format!("{name}_{threads}t"), format!("hex_{n_el}"));
            group.bench_function(id("condensed"), |b| {
                pool.install(|| b.iter(|| forces::element_forces(&model, &u, &mut f_k)))
            });
            group.bench_function(id("per_tet"), |b| {
                pool.install(|| b.iter(|| per_tet_forces(&model, &ops, &u, &mut f_t)))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
