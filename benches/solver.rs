//! Whole-solver costs on the paper slope (hexahedra in the name; meshes as in
//! `benches/kernels.rs`):
//!
//! - `step/hex_N`: one `Solver::step` (internal forces, damping, explicit
//!   update, monitor) with the scene's settings (node-block masses),
//!   throughput `Elements(n_elements)`: element-steps/s; `step_lumped/hex_N`
//!   the same with lumped masses (`block_mass = false`);
//! - `dr_to_1e-5/hex_1000`: dynamic relaxation from rest to the unbalanced
//!   ratio 1e-5 on the paper's mesh (`Solver::new` + `relax`, the model
//!   already built), the scene's solver settings (viscous damping, mass
//!   scaling, node-block masses); `dr_to_1e-5_lumped/hex_1000` with lumped
//!   masses; 10 samples;
//! - `build_model/hex_1000`: reading, perturbing and building the CDEM model
//!   (element operators, springs, gather lists), for the end-to-end total;
//! - `fem_solve_scene/hex_N`: the implicit FEM reference end to end
//!   (`cdem::drivers::solve_fem`: read and perturb the mesh, assemble, sparse
//!   Cholesky, solve, residual and stresses); 10 samples.
//!
//! DR against FEM on the same mesh: `dr_to_1e-5 / fem_solve_scene`
//! (or `(build_model + dr_to_1e-5) / fem_solve_scene` end to end).

mod common;

use std::path::Path;

use cdem::model::Model;
use cdem::scene::Scene;
use cdem::solver::{Solver, SolverParams, State};
use common::{meshes, slope_scene};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

fn build(scene: &Scene) -> Model {
    cdem::drivers::build_model(scene).expect("slope model builds")
}

fn step(c: &mut Criterion) {
    let mut group = c.benchmark_group("solver");
    for (mesh, n_hex) in meshes() {
        let scene = slope_scene(&mesh);
        let model = build(&scene);
        assert_eq!(model.elements.len(), n_hex, "{}: expected {n_hex} hexahedra", mesh.display());
        group.throughput(Throughput::Elements(n_hex as u64));
        for (name, block_mass) in [("step", None), ("step_lumped", Some(false))] {
            let params = SolverParams { block_mass, ..scene.solver.clone() };
            let mut solver = Solver::new(&model, params).expect("time step");
            let mut state = State::new(&model);
            // Start from a loaded, moving state rather than rest.
            for _ in 0..100 {
                solver.step(&model, &mut state).expect("stable");
            }
            group.bench_function(BenchmarkId::new(name, format!("hex_{n_hex}")), |b| {
                b.iter(|| solver.step(&model, &mut state).expect("stable"))
            });
        }
    }
    group.finish();
}

fn relax(c: &mut Criterion) {
    let mut group = c.benchmark_group("solver");
    group.sample_size(10);
    let scene = slope_scene(Path::new("slope.msh"));
    assert_eq!(scene.solver.tolerance, 1e-5, "the slope scene relaxes to 1e-5");
    let model = build(&scene);
    let n = model.elements.len();
    for (name, block_mass) in [("dr_to_1e-5", None), ("dr_to_1e-5_lumped", Some(false))] {
        let params = SolverParams { block_mass, ..scene.solver.clone() };
        let mut steps = 0;
        group.bench_function(BenchmarkId::new(name, format!("hex_{n}")), |b| {
            b.iter(|| {
                let mut solver = Solver::new(&model, params.clone()).expect("time step");
                let mut state = State::new(&model);
                let report = solver.relax(&model, &mut state, usize::MAX).expect("stable");
                assert!(report.converged, "DR did not reach 1e-5 in {} steps", report.steps);
                steps = report.steps;
            })
        });
        eprintln!("{name}/hex_{n}: {steps} steps");
    }
    group.bench_function(BenchmarkId::new("build_model", format!("hex_{n}")), |b| b.iter(|| build(&scene)));
    group.finish();
}

fn fem(c: &mut Criterion) {
    let mut group = c.benchmark_group("solver");
    group.sample_size(10);
    for (mesh, n_hex) in meshes() {
        let scene = slope_scene(&mesh);
        let sol = cdem::drivers::solve_fem(&scene).expect("FEM solves");
        let t = sol.timings;
        eprintln!(
            "fem hex_{n_hex}: {} free dofs; assemble {:.4} s, factor {:.4} s, solve {:.4} s, post {:.4} s",
            sol.free_dofs, t.assemble_s, t.factor_s, t.solve_s, t.post_s
        );
        group.throughput(Throughput::Elements(n_hex as u64));
        group.bench_function(BenchmarkId::new("fem_solve_scene", format!("hex_{n_hex}")), |b| {
            b.iter(|| cdem::drivers::solve_fem(&scene).expect("FEM solves"))
        });
    }
    group.finish();
}

criterion_group!(benches, step, relax, fem);
criterion_main!(benches);
