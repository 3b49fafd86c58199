//! The block on an inclined plane in physical time (references/sliding-block.md,
//! tests/sliding_block.rs): a block on a plane inclined at theta with friction
//! angle phi and no cohesion stays at rest if theta < phi and otherwise slides
//! with acceleration g (sin theta - cos theta tan phi).
//!
//! The plane is horizontal and gravity is tilted by theta. Phase 1 relaxes
//! the bonded block to equilibrium; then, from rest, the contact is
//! frictional (failure on) and time runs with physical masses and no damping.

use crate::error::Error;
use crate::harness::registry::{self as reg, sliding_block_acceleration, GRAVITY as G, SLIDING_BLOCK_PHI_DEG};
use crate::harness::report::Check;
use crate::model::Model;
use crate::solver::{DampingKind, Solver, State};

/// The slide: mean x displacement of the block's nodes after `t` seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slide {
    pub theta_deg: f64,
    /// m.
    pub x: f64,
    /// The time run (s), whole steps.
    pub t: f64,
    /// Wall time (s).
    pub seconds: f64,
    /// Phase 1 (the bonded block) reached equilibrium.
    pub phase1_converged: bool,
}

impl Slide {
    /// `check`, failed if phase 1 did not converge (the slide starts from no equilibrium).
    fn judge(&self, check: Check) -> Check {
        if self.phase1_converged {
            check
        } else {
            check.with_defect("phase 1 (the bonded block) did not converge")
        }
    }
}

/// Runs the block at `theta_deg` for about `t_end` seconds of physical time.
pub fn slide(theta_deg: f64, t_end: f64) -> Result<Slide, Error> {
    let t0 = std::time::Instant::now();
    let mut scene = reg::SLIDING_BLOCK.scene()?;
    let th = theta_deg.to_radians();
    scene.loads.gravity = [G * th.sin(), 0.0, -G * th.cos()];
    let model = crate::drivers::build_model(&scene)?;
    // Phase 1: bonded, static.
    let mut solver = Solver::new(&model, scene.solver.clone())?;
    let mut state = State::new(&model);
    let rep = solver.relax(&model, &mut state, 100)?;
    // Phase 2: physical time, frictional contact, undamped.
    let mut params = scene.solver.clone();
    params.mass_scaling = false;
    params.damping = DampingKind::Local;
    params.local_damping = 0.0;
    let mut dynamic = Solver::new(&model, params)?;
    dynamic.set_failure(&model, true);
    state.v.fill(0.0);
    let u0 = state.u.clone();
    let block: Vec<usize> = (0..model.n_nodes())
        .filter(|&i| model.x0[i][2] > 1.0 + 1e-9 || (model.x0[i][2] > 1.0 - 1e-9 && is_block_copy(&model, i)))
        .collect();
    let steps = (t_end / dynamic.dt()).round() as usize;
    for _ in 0..steps {
        dynamic.step(&model, &mut state)?;
    }
    let t = steps as f64 * dynamic.dt();
    let x = block.iter().map(|&i| state.u[3 * i] - u0[3 * i]).sum::<f64>() / block.len() as f64;
    Ok(Slide { theta_deg, x, t, seconds: t0.elapsed().as_secs_f64(), phase1_converged: rep.converged })
}

/// Node copies at z = 1 belong to the block if their element is the upper one.
fn is_block_copy(model: &Model, node: usize) -> bool {
    (0..model.elements.len()).any(|e| {
        let c = model.elements.corners(e);
        c.contains(&(node as u32)) && c.iter().map(|&i| model.x0[i as usize][2]).sum::<f64>() / c.len() as f64 > 1.0
    })
}

/// theta 15 deg < phi 20 deg for 0.5 s: row `block/at-rest-15` (the displacement, reference 0).
pub fn at_rest() -> Result<(Slide, Check), Error> {
    let s = slide(15.0, 0.5)?;
    Ok((s, s.judge(reg::row("block/at-rest-15").value(s.x, 0.0, s.seconds))))
}

/// theta 30 deg > phi 20 deg for 0.5 s: row `block/acceleration-30`, the
/// acceleration `2 x / t^2` against Coulomb's.
pub fn sliding() -> Result<(Slide, Check), Error> {
    let s = slide(30.0, 0.5)?;
    let a = 2.0 * s.x / (s.t * s.t);
    let analytic = sliding_block_acceleration(30.0, SLIDING_BLOCK_PHI_DEG);
    Ok((s, s.judge(reg::row("block/acceleration-30").value(a, analytic, s.seconds))))
}
