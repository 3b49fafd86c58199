//! Node-block mass scaling (src/solver/block_mass.rs): the stability bound it
//! promises, the step count it saves on the paper slope, and that it reaches
//! the same equilibrium as lumped masses.

use std::path::Path;

use cdem::analysis::compare::relative_l2_between_copies;
use cdem::drivers::{build_model, run_scene};
use cdem::model::Model;
use cdem::scene::Scene;
use cdem::solver::block_mass::BlockMass;
use cdem::solver::{Solver, SolverParams, State};

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Largest eigenvalue of `M^-1 K` on the free components by power iteration
/// (the Rayleigh quotient `x.Kx / x.Mx` of the last iterate, a lower bound
/// that rises towards it).
fn lambda_max(model: &Model, block: &BlockMass, iterations: usize) -> f64 {
    let mut solver = Solver::new(model, SolverParams { block_mass: Some(false), ..SolverParams::default() }).unwrap();
    let mut state = State::new(model);
    let n = 3 * model.n_nodes();
    let free = |k: usize| !model.fixed[k];
    let mut x: Vec<f64> = (0..n).map(|k| if free(k) { 1.0 + (0.61 * k as f64).sin() } else { 0.0 }).collect();
    let (mut scratch, mut mx, mut per_node) = (vec![0.0; n], vec![0.0; n], vec![0.0; model.n_nodes()]);
    let (mut slot_force, mut slot_acc) = (vec![0.0; n], vec![0.0; n]);
    let mut lambda = 0.0;
    for _ in 0..iterations {
        state.u.copy_from_slice(&x);
        solver.internal_forces(model, &mut state);
        let kx = &state.f_int;
        lambda = dot(&x, kx) / block.quadratic(&x, &mut scratch, &mut mx, &mut per_node);
        block.accelerations(
            |i| std::array::from_fn(|d| if free(3 * i + d) { kx[3 * i + d] } else { 0.0 }),
            &mut slot_force,
            &mut slot_acc,
        );
        let y: Vec<f64> = (0..model.n_nodes()).flat_map(|i| block.acceleration(&slot_acc, i)).collect();
        let norm = dot(&y, &y).sqrt();
        x = y.iter().map(|v| v / norm).collect();
    }
    lambda
}

fn scene(path: &str) -> Scene {
    Scene::load(Path::new(path)).unwrap()
}

/// `K <= B + D` makes `lambda_max(M^-1 K) <= 4 safety^2` (the masses are
/// `(B + D) / (4 safety^2)`), so `dt = 1` is stable. Checked on the column
/// (springs 170x stiffer than the rock) and the paper slope.
#[test]
fn block_masses_bound_the_largest_eigenvalue() {
    for path in ["verification/cases/column/column.toml", "verification/cases/slope/slope.toml"] {
        let s = scene(path);
        let model = build_model(&s).unwrap();
        let safety = s.solver.safety;
        let block = BlockMass::new(&model, 1.0 / (4.0 * safety * safety)).unwrap();
        let lambda = lambda_max(&model, &block, 300);
        let bound = 4.0 * safety * safety;
        println!("{path}: lambda_max(M^-1 K) >= {lambda:.4}, bound {bound:.4} (ratio {:.3})", lambda / bound);
        assert!(lambda <= bound * (1.0 + 1e-9), "{path}: lambda {lambda} above the bound {bound}");
        // The bound is not loose by orders of magnitude: the block holds the
        // stiff springs exactly, so their modes sit near it.
        assert!(lambda > 0.25 * bound, "{path}: lambda {lambda} far below the bound {bound}");
    }
}

/// The paper slope reaches the same equilibrium with block and lumped
/// masses, the block one in at least 5x fewer steps (the spring-to-rock
/// stiffness ratio is about 170; references/performance.md).
#[test]
fn paper_slope_same_equilibrium_in_fewer_steps() {
    let mut lumped = scene("verification/cases/slope/slope.toml");
    lumped.solver.elastic = cdem::solver::ElasticSolver::Dr;
    lumped.solver.block_mass = Some(false);
    let mut block = lumped.clone();
    block.solver.block_mass = Some(true);
    let a = run_scene(&lumped, &mut |_, _| {}).unwrap();
    let b = run_scene(&block, &mut |_, _| {}).unwrap();
    assert!(a.summary.converged && b.summary.converged);
    let diff = relative_l2_between_copies(&a.model, &b.state.u, &a.state.u);
    println!(
        "paper slope: lumped {} steps, block {} steps; relative L2 difference {diff:.2e}",
        a.summary.steps, b.summary.steps
    );
    println!("max |u_z|: lumped {:.6e}, block {:.6e}", a.summary.max_abs_uz, b.summary.max_abs_uz);
    assert!(5 * b.summary.steps < a.summary.steps, "block {} vs lumped {} steps", b.summary.steps, a.summary.steps);
    // Both stop at an unbalanced ratio of 1e-5; their fields agree to 1e-3.
    assert!(diff < 1e-3, "relative L2 difference {diff}");
}

/// Block masses need mass scaling and viscous damping; the error names the key.
#[test]
fn block_mass_with_local_damping_is_a_scene_error() {
    let text = std::fs::read_to_string("verification/cases/slope/slope.toml").unwrap();
    let text = text.replace("[solver]", "[solver]\nblock_mass = true\ndamping = \"local\"");
    let dir = Path::new("verification/cases/slope");
    let err = Scene::from_toml(&text, dir, &dir.join("slope.toml")).unwrap_err();
    assert!(err.to_string().contains("solver.block_mass"), "{err}");
}

/// A mesh node that no cell uses (a gmsh file may keep one, say a geometry
/// point) is a cluster without copies. The block masses skip it: the column
/// with its node 0 moved to a new index, leaving index 0 unused, gives every
/// node the same acceleration, bit for bit, as the column itself.
#[test]
fn a_mesh_node_no_cell_uses_changes_no_acceleration() {
    let s = scene("verification/cases/column/column.toml");
    let reference = build_model(&s).unwrap();
    let mut mesh = cdem::drivers::read_mesh(&s).unwrap();
    let moved = mesh.nodes.len();
    mesh.nodes.push(mesh.nodes[0]);
    mesh.node_tags.push(mesh.node_tags.iter().max().unwrap() + 1);
    let remap = |n: &mut usize| {
        if *n == 0 {
            *n = moved;
        }
    };
    mesh.cells.iter_mut().for_each(|c| c.nodes.iter_mut().for_each(remap));
    mesh.groups.iter_mut().flat_map(|g| g.facets.iter_mut()).for_each(|f| f.nodes.iter_mut().for_each(remap));
    let model = cdem::model::build(&mesh, &s.model_spec()).unwrap();
    assert_eq!(model.n_nodes(), reference.n_nodes());
    assert!(!model.mesh_node.contains(&0), "index 0 is unused");
    let n = 3 * model.n_nodes();
    let f: Vec<f64> = (0..n).map(|k| (0.37 * k as f64).sin()).collect();
    let accelerations = |model: &Model| {
        let block = BlockMass::new(model, 1.0).unwrap();
        let (mut r, mut acc) = (vec![0.0; n], vec![0.0; n]);
        block.accelerations(|i| [f[3 * i], f[3 * i + 1], f[3 * i + 2]], &mut r, &mut acc);
        (0..model.n_nodes()).flat_map(|i| block.acceleration(&acc, i)).map(f64::to_bits).collect::<Vec<_>>()
    };
    assert_eq!(accelerations(&model), accelerations(&reference));
}

/// With block masses the step returns one kinetic-energy estimate on every
/// step, `sum_k m_kk v_k^2 / 2` from the blocks' diagonal, the measure the
/// stop rule compares from step to step; before, every 16th step returned
/// `v . M v / 2` instead (many times smaller here), so the rule compared
/// two measures across those steps.
#[test]
fn the_step_returns_the_same_kinetic_estimate_on_every_step() {
    let s = scene("verification/cases/column/column.toml");
    let model = build_model(&s).unwrap();
    let mut params = s.solver.clone();
    params.block_mass = Some(true);
    let mut solver = Solver::new(&model, params).unwrap();
    assert!(solver.inertia().is_block());
    let mut state = State::new(&model);
    let mut exact_smaller = 0;
    for _ in 0..48 {
        let (_, kinetic) = solver.step(&model, &mut state).unwrap();
        let diagonal: f64 = match solver.inertia().masses() {
            cdem::solver::integrate::Masses::Block(b, _) => (0..model.n_nodes())
                .flat_map(|i| (0..3).map(move |d| (i, d)))
                .map(|(i, d)| 0.5 * b.diagonal[i][d] * state.v[3 * i + d] * state.v[3 * i + d])
                .sum(),
            _ => unreachable!("block masses"),
        };
        assert!((kinetic - diagonal).abs() <= 1e-12 * diagonal, "step {}: {kinetic} against {diagonal}", state.step);
        exact_smaller += (solver.kinetic_energy(&state) < 0.5 * diagonal) as usize;
    }
    assert!(exact_smaller > 0, "the two measures differ on this model");
}
