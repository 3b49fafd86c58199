//! Instruction counts (callgrind, through gungraun) of the kernels a
//! regression would show in first, on the paper slope (1000 hexahedra,
//! `verification/cases/slope/slope.toml`):
//!
//! - `element_forces`: every element's `K_e u_e` (eq. 12) into its slot;
//! - `spring_forces`: every spring's force on node `a` (eq. 15, elastic);
//! - `plastic_forces_elastic`, `plastic_forces_yielding`: the same elements as plastic blocks (Mohr-Coulomb, the
//!   paper's rock mass strength), every tetrahedron integrated with its
//!   history: elastic at a displacement 1e-4 times the others' (nothing
//!   yields: the yield test and the mixed kernel), yielding at the same
//!   displacement as `element_forces` (most tetrahedra return to the
//!   surface); the ratio to `element_forces` is the cost of plasticity;
//!   the elastic pass is a first pass (the screens are armed in it);
//! - `plastic_forces_screened`: the elastic case's second pass, every
//!   hexahedron behind its armed elastic screen (`K_e u_e - f_p`), the cost
//!   of a plastic block that is not yielding in a relaxation;
//! - `one_step`: one explicit step of the scene's solver (block masses), after
//!   20 warm-up steps from rest;
//! - `short_dr`: `Solver::new` and 50 steps of dynamic relaxation from rest,
//!   as phase 1 starts;
//! - `lem_grid`: the LEM Bishop search on the 20 x 20 x 10 grid, one thread
//!   (the search pySlope is timed against).
//!
//! Counts do not depend on the machine's load, unlike criterion's wall
//! times (kept for those). rayon runs on the calling thread alone, so every
//! instruction is counted in the benchmark's thread. The inputs are built
//! outside the measured function. `scripts/instructions.py` runs this bench
//! and compares with the committed baseline `references/perf/instructions.json`.
//!
//! Needs valgrind and `gungraun-runner` of the same version as the library
//! (see docs/commands.md, "Instruction counts"); run with `cargo bench --features iai --bench instructions`.

use std::hint::black_box;
use std::path::Path;

use cdem::model::{Model, ELEMENT_SLOT};
use cdem::physics::plastic::RockState;
use cdem::physics::spring::SpringState;
use cdem::scene::RockStrengthSection;
use cdem::solver::{forces, Solver, SolverParams, State};
use gungraun::{library_benchmark, library_benchmark_group, main, LibraryBenchmarkConfig};

/// rayon's global pool on the calling thread (one thread): the work of a
/// parallel loop is then counted in the benchmark's own thread.
fn one_thread() {
    // The baseline kernels (SSE2), so that a count does not depend on whether
    // the measuring CPU has AVX2 (`cdem::simd`; both give the same bits).
    cdem::simd::set_baseline(true);
    let _ = rayon::ThreadPoolBuilder::new().num_threads(1).use_current_thread().build_global();
}

fn paper_slope() -> (cdem::scene::Scene, Model) {
    one_thread();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = cdem::scene::Scene::load(&root.join(cdem::harness::registry::SLOPE.input)).expect("slope scene");
    let model = cdem::drivers::build_model(&scene).expect("slope model");
    (scene, model)
}

/// A smooth, deterministic displacement field (m).
fn displacement(model: &Model) -> Vec<f64> {
    (0..3 * model.n_nodes()).map(|k| 1e-3 * (0.37 * k as f64).sin()).collect()
}

struct Kernel {
    model: Model,
    u: Vec<f64>,
    springs: SpringState,
    f_elem: Vec<f64>,
    f_spring: Vec<[f64; 3]>,
}

fn kernel() -> Kernel {
    let (_, model) = paper_slope();
    let u = displacement(&model);
    let springs = SpringState::new(model.springs.len());
    let f_elem = vec![0.0; ELEMENT_SLOT * model.elements.len()];
    let f_spring = vec![[0.0; 3]; model.springs.len()];
    Kernel { model, u, springs, f_elem, f_spring }
}

#[library_benchmark]
#[bench::paper_slope(kernel())]
fn element_forces(mut k: Kernel) -> Kernel {
    forces::element_forces(black_box(&k.model), black_box(&k.u), &mut k.f_elem);
    k
}

struct Plastic {
    model: Model,
    u: Vec<f64>,
    rock: RockState,
    f_elem: Vec<f64>,
}

fn plastic(scale: f64) -> Plastic {
    one_thread();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scene = cdem::scene::Scene::load(&root.join(cdem::harness::registry::SLOPE.input)).expect("slope scene");
    for m in &mut scene.material {
        m.strength =
            Some(RockStrengthSection { cohesion: 16e3, friction_angle: 18.0, tensile: None, dilation_angle: 0.0 });
    }
    let model = cdem::drivers::build_model(&scene).expect("slope model");
    let u: Vec<f64> = displacement(&model).iter().map(|v| scale * v).collect();
    let rock = model.rock_state();
    let f_elem = vec![0.0; ELEMENT_SLOT * model.elements.len()];
    Plastic { model, u, rock, f_elem }
}

#[library_benchmark]
#[bench::paper_slope(plastic(1e-4))]
fn plastic_forces_elastic(mut k: Plastic) -> Plastic {
    forces::element_forces_plastic(black_box(&k.model), &mut k.rock, black_box(&k.u), &mut k.f_elem);
    k
}

/// [`plastic`] after one pass: every elastic hexahedron's screen armed.
fn plastic_armed(scale: f64) -> Plastic {
    let mut k = plastic(scale);
    forces::element_forces_plastic(&k.model, &mut k.rock, &k.u, &mut k.f_elem);
    k
}

#[library_benchmark]
#[bench::paper_slope(plastic_armed(1e-4))]
fn plastic_forces_screened(mut k: Plastic) -> Plastic {
    forces::element_forces_plastic(black_box(&k.model), &mut k.rock, black_box(&k.u), &mut k.f_elem);
    k
}

#[library_benchmark]
#[bench::paper_slope(plastic(1.0))]
fn plastic_forces_yielding(mut k: Plastic) -> Plastic {
    forces::element_forces_plastic(black_box(&k.model), &mut k.rock, black_box(&k.u), &mut k.f_elem);
    k
}

#[library_benchmark]
#[bench::paper_slope(kernel())]
fn spring_forces(mut k: Kernel) -> Kernel {
    forces::spring_forces(black_box(&k.model), &k.springs, black_box(&k.u), &mut k.f_spring);
    k
}

struct Stepping {
    model: Model,
    solver: Solver,
    state: State,
}

fn stepping() -> Stepping {
    let (scene, model) = paper_slope();
    let mut solver = Solver::new(&model, scene.solver.clone()).expect("solver");
    let mut state = State::new(&model);
    for _ in 0..20 {
        solver.step(&model, &mut state).expect("warm-up step");
    }
    Stepping { model, solver, state }
}

#[library_benchmark]
#[bench::paper_slope(stepping())]
fn one_step(mut s: Stepping) -> Stepping {
    black_box(s.solver.step(&s.model, &mut s.state).expect("step"));
    s
}

fn dr_input() -> (Model, SolverParams) {
    let (scene, model) = paper_slope();
    // Dynamic relaxation (PCG, the default elastic solver, is not a 50-step DR).
    (model, SolverParams { max_steps: Some(50), elastic: cdem::solver::ElasticSolver::Dr, ..scene.solver })
}

#[library_benchmark]
#[bench::paper_slope_50_steps(dr_input())]
fn short_dr(input: (Model, SolverParams)) -> (Model, SolverParams) {
    black_box(cdem::drivers::run::relax_elastic(&input.0, &input.1, usize::MAX).expect("relax"));
    input
}

fn lem_input() -> cdem::lem::LemInput {
    one_thread();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = cdem::lem::LemInput::load(&root.join(cdem::harness::registry::LEM_PAPER_SLOPE_EXPLICIT.input))
        .expect("LEM input");
    cdem::harness::perf::pyslope_grid_search(base)
}

#[library_benchmark]
#[bench::paper_slope_bishop_grid(lem_input())]
fn lem_grid(input: cdem::lem::LemInput) -> cdem::lem::LemInput {
    black_box(cdem::lem::analyse(black_box(&input)).expect("LEM search"));
    input
}

library_benchmark_group!(
    name = kernels;
    benchmarks = element_forces, plastic_forces_elastic, plastic_forces_screened, plastic_forces_yielding, spring_forces, one_step, short_dr, lem_grid
);

main!(
    config = LibraryBenchmarkConfig::default().env("RAYON_NUM_THREADS", "1");
    library_benchmark_groups = kernels
);
