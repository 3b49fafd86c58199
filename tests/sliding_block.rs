//! Physical-time runs obey Coulomb friction (references/sliding-block.md):
//! a block on a plane inclined at
//! theta with friction angle phi and no cohesion stays at rest if theta < phi
//! and otherwise slides with acceleration g (sin theta - cos theta tan phi).
//!
//! The plane is horizontal and gravity is tilted by theta. Phase 1 relaxes
//! the bonded block to equilibrium; then, from rest, the contact is
//! frictional (failure on) and time runs with physical masses and no damping.

use cdem::harness::registry::{self as reg, sliding_block_acceleration, GRAVITY as G, SLIDING_BLOCK_PHI_DEG};
use cdem::solver::{DampingKind, Solver, State};

/// Mean x displacement of the block's nodes after `t_end` seconds of sliding.
fn slide(theta_deg: f64, t_end: f64) -> (f64, f64) {
    let mut scene = reg::SLIDING_BLOCK.scene().unwrap();
    let th = theta_deg.to_radians();
    scene.loads.gravity = [G * th.sin(), 0.0, -G * th.cos()];
    let model = cdem::drivers::build_model(&scene).unwrap();
    // Phase 1: bonded, static.
    let mut solver = Solver::new(&model, scene.solver.clone()).unwrap();
    let mut state = State::new(&model);
    let rep = solver.relax(&model, &mut state, 100).unwrap();
    assert!(rep.converged);
    // Phase 2: physical time, frictional contact, undamped.
    let mut params = scene.solver.clone();
    params.mass_scaling = false;
    params.damping = DampingKind::Local;
    params.local_damping = 0.0;
    let mut dynamic = Solver::new(&model, params).unwrap();
    dynamic.set_failure(&model, true);
    state.v.fill(0.0);
    let u0 = state.u.clone();
    let block: Vec<usize> = (0..model.n_nodes())
        .filter(|&i| model.x0[i][2] > 1.0 + 1e-9 || (model.x0[i][2] > 1.0 - 1e-9 && is_block_copy(&model, i)))
        .collect();
    let steps = (t_end / dynamic.dt()).round() as usize;
    for _ in 0..steps {
        dynamic.step(&model, &mut state).unwrap();
    }
    let t = steps as f64 * dynamic.dt();
    let x = block.iter().map(|&i| state.u[3 * i] - u0[3 * i]).sum::<f64>() / block.len() as f64;
    (x, t)
}

/// Node copies at z = 1 belong to the block if their element is the upper one.
fn is_block_copy(model: &cdem::model::Model, node: usize) -> bool {
    (0..model.elements.len()).any(|e| {
        let c = model.elements.corners(e);
        c.contains(&(node as u32)) && c.iter().map(|&i| model.x0[i as usize][2]).sum::<f64>() / c.len() as f64 > 1.0
    })
}

#[test]
fn block_below_the_friction_angle_stays_at_rest() {
    let (x, t) = slide(15.0, 0.5);
    println!("theta 15 deg, phi 20 deg: block moved {x:.3e} m in {t:.3} s");
    // At rest: only elastic wobble. The static shear-spring displacement is
    // W sin(theta) / K_s = 24525 N x 0.259 / 4e9 N/m = 1.6e-6 m; sliding at
    // even 1 % of g would move 0.5 x 0.098 x 0.25 = 1.2e-2 m.
    cdem::harness::report::record("sliding_block_15", &[reg::row("block/at-rest-15").value(x, 0.0, 0.0)]);
    assert!(x.abs() < reg::TOL_BLOCK_AT_REST, "block moved {x} m");
}

#[test]
fn block_above_the_friction_angle_slides_with_the_coulomb_acceleration() {
    let analytic = sliding_block_acceleration(30.0, SLIDING_BLOCK_PHI_DEG);
    let (x, t) = slide(30.0, 0.5);
    let a = 2.0 * x / (t * t);
    println!("theta 30 deg, phi 20 deg: a = {a:.4} m/s^2 (analytic {analytic:.4})");
    cdem::harness::report::record("sliding_block_30", &[reg::row("block/acceleration-30").value(a, analytic, 0.0)]);
    assert!(((a - analytic) / analytic).abs() < reg::TOL_SLIDING_BLOCK, "a = {a}, analytic {analytic}");
}
