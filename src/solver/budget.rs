//! The default step budget: the model's characteristic response time `N_r`
//! (3DEC and FLAC call the number of steps a model needs to come to
//! equilibrium its characteristic response time and size their
//! strength-reduction trials by it).
//!
//! With mass scaling every node sits at the same fraction of its own stability
//! limit, so a disturbance crosses about one element per step and a model
//! `n_c` elements across (`n_c = L / h`: `L` the largest extent of the model,
//! `h` the median element size `V_e^(1/3)`) needs a fixed number of crossings
//! to relax. With lumped masses the stiff joint springs set the masses while
//! the rock sets the slowest mode, which adds `sqrt(kappa)`, `kappa` the
//! largest ratio over the nodes of the row sum of the whole stiffness to the
//! row sum of the elements alone (node-block masses remove it: `kappa = 1`).
//! Rock of very different stiffness in one model (a layered column with a
//! modulus contrast of 1e4 needs 23,600 steps where one rock needs 240) slows
//! the slowest mode by the square root of the contrast `chi`, the ratio of the
//! largest to the smallest P-wave modulus `lambda + 2 mu` of the materials in
//! use. So
//!
//! `N_r = C n_c sqrt(kappa chi)`,
//!
//! with `C` per damping kind, measured on every case of `verification/cases/`
//! and the block on a plane (`references/performance.md`, "step budget"): the
//! largest ratio of the steps to converge to `n_c sqrt(kappa)` there, times
//! about 3 for margin. Never less than [`MIN_STEPS`].

use super::params::{DampingKind, SolverParams};
use super::timestep::{element_row_sums, stiffness_row_sums};
use crate::model::Model;

/// `C` for viscous damping (measured ratio at most 33.5: the block on a
/// plane to 1e-9; the slope 15.5 with block masses, 9.3 lumped).
pub const CROSSINGS_VISCOUS: f64 = 100.0;
/// `C` for local damping (measured ratio at most 416: the column with
/// springs; the slope 226).
pub const CROSSINGS_LOCAL: f64 = 1500.0;
/// `C` for kinetic damping (measured ratio at most 112: the merged column;
/// it blows up on the slopes and the block).
pub const CROSSINGS_KINETIC: f64 = 500.0;
/// The budget is never below this.
pub const MIN_STEPS: usize = 2000;

/// `n_c`: the largest extent of the model over its median element size.
pub fn crossing_elements(model: &Model) -> f64 {
    let (lo, hi) = model.bounds();
    let extent = (0..3).map(|d| hi[d] - lo[d]).fold(0.0, f64::max);
    let mut sizes: Vec<f64> = model.elements.volume.iter().map(|v| v.cbrt()).collect();
    if sizes.is_empty() || !(extent > 0.0) {
        return 1.0;
    }
    sizes.sort_by(f64::total_cmp);
    let h = sizes[sizes.len() / 2];
    (extent / h).max(1.0)
}

/// `kappa`: the largest ratio of a node's stiffness row sum (elements and
/// springs) to that of its elements alone.
pub fn spring_stiffness_ratio(model: &Model) -> f64 {
    let all = stiffness_row_sums(model);
    let el = element_row_sums(model);
    all.iter().zip(&el).filter(|(_, &e)| e > 0.0).map(|(a, e)| a / e).fold(1.0, f64::max)
}

/// `chi`: the largest over the smallest P-wave modulus `lambda + 2 mu` of the
/// materials the elements use (1 for one rock).
pub fn stiffness_contrast(model: &Model) -> f64 {
    let mut used = vec![false; model.materials.len()];
    for &m in &model.elements.material {
        used[m as usize] = true;
    }
    let moduli = model.materials.iter().zip(&used).filter(|(_, &u)| u).map(|(m, _)| m.lame.lambda + 2.0 * m.lame.mu);
    let (lo, hi) = moduli.fold((f64::INFINITY, 0.0f64), |(lo, hi), p| (lo.min(p), hi.max(p)));
    if lo > 0.0 && hi.is_finite() {
        hi / lo
    } else {
        1.0
    }
}

/// `N_r` for a model relaxed with `params` and node-block masses or not.
pub fn response_steps(model: &Model, params: &SolverParams, block_masses: bool) -> usize {
    let c = match params.damping {
        DampingKind::Viscous => CROSSINGS_VISCOUS,
        DampingKind::Local => CROSSINGS_LOCAL,
        DampingKind::Kinetic => CROSSINGS_KINETIC,
    };
    let kappa = if block_masses || !params.mass_scaling { 1.0 } else { spring_stiffness_ratio(model) };
    let n = c * crossing_elements(model) * (kappa * stiffness_contrast(model)).sqrt();
    (n.ceil() as usize).max(MIN_STEPS)
}

/// The default budget of phase 2 (and of each strength-reduction trial), in
/// response times `N_r`. Near the limit the response slows down: on the
/// stable slope (`SLOPE_SLIP_STABLE`) the trial at F = 1.6357 reached
/// Equilibrium after 17,967 steps = 4.2 `N_r`; on the block on a plane the
/// trial at F = 1.2109 (0.16 % below the analytic FS) after 6,050 steps =
/// 3.0 `N_r` (references/srm.md).
pub const PHASE2_RESPONSE_TIMES: usize = 10;

/// The step budget of a relaxation, the one formula every phase uses: the
/// scene's `max_steps` if it gives one, else `response_times` `N_r` with
/// `params`' damping and node-block masses or not (phase 1: one `N_r`, with
/// block masses for PCG, where it is a generous cap on the iterations;
/// phase 2: [`PHASE2_RESPONSE_TIMES`]).
pub fn step_budget(
    model: &Model,
    params: &SolverParams,
    block_masses: bool,
    max_steps: Option<usize>,
    response_times: usize,
) -> usize {
    max_steps.unwrap_or_else(|| response_times * response_steps(model, params, block_masses))
}
