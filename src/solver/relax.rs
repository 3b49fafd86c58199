//! The relax driver: steps until a stop rule fires. Both phases of a run,
//! and every later driver (strength reduction, ensembles), relax through
//! [`relax`]; they differ only in their [`StopRules`] and their
//! [`Observer`].
//!
//! The rules, checked after every step in this order:
//! 1. **tolerance**: the unbalanced-force ratio is below `tolerance` and
//!    the velocities are decaying: the kinetic energy is not above the
//!    previous step's ([`Stop::Converged`]); a state that passes through a
//!    small ratio while it still speeds up is not at rest;
//! 2. **sliding** (if given), checked at the end of every window of
//!    `window` steps ([`Stop::Sliding`]): the mass-weighted mean displacement
//!    since `reference` grew in each of the last `windows` windows by more
//!    than `floor` and by at least as much as in the window before (the
//!    displacement rate does not decay: a mass keeps moving), or (`steady`)
//!    the last `windows` increments sum to at least the `windows` before (a
//!    steady creep whose increments scatter from window to window), or the
//!    largest displacement since `reference` passed `displacement`;
//! 3. **budget**: `max_steps` steps taken ([`Stop::Budget`]);
//! 4. **foresight** (if given; strength-reduction trials), checked at the
//!    end of every sliding window ([`Stop::Foreseen`]): the ratio has
//!    decayed in each of the last `windows` windows, the mass has slowed
//!    down in each (the mean displacement's increments shrink), and at its mean rate
//!    over them it would reach `tolerance` only after more than `margin`
//!    times `max_steps` steps in all: the budget rule would fire, later;
//! 5. **caller**: the observer returns `Break` ([`Stop::Caller`]).

use std::ops::ControlFlow;

use serde::Serialize;

use super::{HistoryRow, Solver, State};
use crate::error::SolveError;
use crate::model::Model;
use crate::summary::distances;
pub use crate::summary::max_displacement_since;

/// Why a relaxation stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Stop {
    Converged,
    Sliding,
    Budget,
    /// The budget foreseen: the ratio decays too slowly to reach the
    /// tolerance within it ([`Foresight`]).
    Foreseen,
    Caller,
}

/// Rule 4: the budget rule foreseen from the ratio's decay.
///
/// Near a strength-reduction trial's critical factor the relaxation slows
/// down (the slowest mode softens as the factor nears the factor of
/// safety): the ratio decays geometrically, by a factor `q` per window that
/// tends to 1. At the end of each sliding window, if the ratio fell in each
/// of the last `windows` windows and the mass slowed down in each (a block
/// sliding steadily can have a falling ratio: the sliding rule decides it),
/// `q` is their mean rate and the steps still
/// needed are `window ln(ratio / tolerance) / ln(1 / q)`. If the steps taken
/// plus those exceed `margin` times the budget, the trial stops as the
/// budget would have stopped it, only sooner. Measured on near-critical
/// plastic trials, `q` creeps up towards 1 as the trial goes on, so the
/// prediction is optimistic, and `margin` > 1 leaves room for a decay that
/// speeds up (docs/method.md section 2.9b).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Foresight {
    /// Windows of decay the rate is measured over.
    pub windows: usize,
    /// The predicted total must exceed this many budgets.
    pub margin: f64,
}

impl Foresight {
    /// The rule of strength-reduction trials: 5 windows (50 crossings), twice
    /// the budget.
    pub const TRIALS: Foresight = Foresight { windows: 5, margin: 2.0 };

    /// Steps still needed to reach `tolerance`, from `history`: one
    /// `(ratio, mean displacement)` per window end, the newest last. None
    /// unless, over the last `windows` windows, the ratio fell in each and
    /// the mean displacement grew by less in each than in the one before (a
    /// mass that keeps sliding may have a falling ratio; it is the sliding
    /// rule's).
    pub fn steps_needed(&self, history: &[(f64, f64)], window: usize, tolerance: f64) -> Option<f64> {
        let k = self.windows.max(1);
        let tail = history.get(history.len().checked_sub(k + 2)?..)?;
        let increments: Vec<f64> = tail.windows(2).map(|w| w[1].1 - w[0].1).collect();
        let slowing = increments.windows(2).all(|w| w[1] < w[0]);
        let ratios = &tail[1..];
        let decaying = ratios.windows(2).all(|w| w[1].0 < w[0].0) && ratios[0].0 > 0.0;
        let (first, last) = (ratios[0].0, ratios[k].0);
        if !decaying || !slowing || !(last > tolerance) {
            return None;
        }
        let rate = (first / last).ln() / k as f64; // ln(1 / q) per window
        Some(window as f64 * (last / tolerance).ln() / rate)
    }
}

/// Global sliding: the mass keeps moving away from a reference state.
///
/// The measure is the mean displacement since `reference` weighted by
/// `weights` (the physical node masses): a sliding mass moves a finite
/// fraction of the model, a single loose block or the chatter of failed
/// springs does not. At the end of every window its increment is compared
/// with the previous window's; `windows` windows in a row with an increment
/// above `floor` and not smaller than the one before decide sliding. A
/// relaxing state has a decaying rate (its increments shrink) and so never
/// meets the rule, whatever its displacement.
#[derive(Debug, Clone, Copy)]
pub struct Sliding<'a> {
    /// Displacement the motion is measured from (3 per node).
    pub reference: &'a [f64],
    /// One weight per node for the mean (the physical masses).
    pub weights: &'a [f64],
    /// Window length (steps); the rule is checked at the end of each.
    pub window: usize,
    /// Windows in a row with a non-decaying increment that decide sliding.
    pub windows: usize,
    /// Increments of the mean displacement per window at or below this (m)
    /// are rest, not motion.
    pub floor: f64,
    /// Also sliding when the largest nodal displacement since `reference`
    /// passes this (m); `f64::INFINITY`: no such bound.
    pub displacement: f64,
    /// The rate rule decides only once the largest nodal displacement since
    /// `reference` has reached this (m; 0: at once): a trial is not called
    /// sliding while its mass has moved only millimetres.
    pub travel: f64,
    /// Also sliding (past `travel`) when the increments of the last
    /// `windows` windows sum to at least those of the `windows` before and
    /// to more than `windows` floors: the rate has not decayed over
    /// `2 windows` windows. A plastic mechanism creeps at a steady rate whose
    /// increments scatter by a few per cent, so three rising windows in a
    /// row are a matter of chance there (references/plastic.md).
    pub steady: bool,
}

/// The running state of the sliding rule.
#[derive(Debug, Clone, Default)]
struct SlidingWatch {
    last_mean: f64,
    last_increment: f64,
    rising: usize,
    /// The increments of the last `2 windows` windows (oldest first).
    increments: Vec<f64>,
}

impl SlidingWatch {
    /// The rate over the last `k` windows has not decayed against the `k`
    /// before, and is above `k` floors.
    fn steady(&self, k: usize, floor: f64) -> bool {
        let n = self.increments.len();
        if k == 0 || n < 2 * k {
            return false;
        }
        let recent: f64 = self.increments[n - k..].iter().sum();
        let before: f64 = self.increments[n - 2 * k..n - k].iter().sum();
        recent > k as f64 * floor && recent >= before
    }
}

impl Sliding<'_> {
    /// Weighted mean displacement of `u` since the reference (m).
    pub fn mean_displacement(&self, u: &[f64]) -> f64 {
        let (mut sum, mut weight) = (0.0, 0.0);
        for (d, w) in distances(u, self.reference).zip(self.weights) {
            sum += w * d;
            weight += w;
        }
        if weight > 0.0 {
            sum / weight
        } else {
            0.0
        }
    }

    /// The check at step `steps` of the relaxation: true if the mass slides.
    fn slides(&self, watch: &mut SlidingWatch, u: &[f64], steps: usize) -> bool {
        if !steps.is_multiple_of(self.window.max(1)) {
            return false;
        }
        if self.displacement.is_finite() && max_displacement_since(u, self.reference) > self.displacement {
            return true;
        }
        let mean = self.mean_displacement(u);
        let increment = mean - watch.last_mean;
        let first = steps == self.window.max(1);
        watch.rising =
            if !first && increment > self.floor && increment >= watch.last_increment { watch.rising + 1 } else { 0 };
        watch.last_mean = mean;
        watch.last_increment = increment;
        if !first && self.steady && self.windows > 0 {
            if watch.increments.len() == 2 * self.windows {
                watch.increments.remove(0);
            }
            watch.increments.push(increment);
        }
        let moving = watch.rising >= self.windows || (self.steady && watch.steady(self.windows, self.floor));
        moving && (self.travel <= 0.0 || max_displacement_since(u, self.reference) >= self.travel)
    }
}

/// When to stop, and how often to record a history row.
#[derive(Debug, Clone, Copy)]
pub struct StopRules<'a> {
    /// Converged: `max |f_unbal| / max |f_ext|` below this.
    pub tolerance: f64,
    /// Step budget of this relaxation.
    pub max_steps: usize,
    pub sliding: Option<Sliding<'a>>,
    /// Stops a relaxation whose budget is foreseen (checked with the
    /// sliding rule's windows; without a sliding rule it is not checked).
    pub foresight: Option<Foresight>,
    /// A history row every this many (global) steps, and at convergence
    /// (a phase that stops by sliding, budget or caller ends on its last
    /// regular row).
    pub history_every: usize,
}

impl<'a> StopRules<'a> {
    /// The rules of one relaxation (the one constructor the drivers use).
    pub fn new(tolerance: f64, max_steps: usize, sliding: Option<Sliding<'a>>, history_every: usize) -> Self {
        Self { tolerance, max_steps, sliding, foresight: None, history_every }
    }
}

/// What one step looked like, for the observer.
pub struct StepView<'a> {
    pub state: &'a State,
    /// Steps taken by this relaxation so far (this one included).
    pub steps: usize,
    pub ratio: f64,
    /// The step's kinetic-energy estimate (J), the one rule 1 compares from
    /// step to step: with node-block masses, from their diagonal (the same
    /// measure every step; it can exceed `v . M v / 2` many times over).
    pub kinetic: f64,
    /// `v . M v / 2` (J), on the steps the observer asks for
    /// ([`Observer::exact_kinetic_at`]), the steps the history records, and
    /// the last.
    pub kinetic_exact: Option<f64>,
    /// The rule that fired on this step, if any: it is the last step.
    pub stop: Option<Stop>,
}

/// The caller's view of a relaxation: progress, stages, frames, a stop.
pub trait Observer {
    /// Called after every step; `Break` stops the relaxation ([`Stop::Caller`])
    /// unless a rule already fired.
    fn step(&mut self, view: &StepView) -> ControlFlow<()>;

    /// Whether the view of step `steps` (of this relaxation) should carry
    /// the exact kinetic energy ([`StepView::kinetic_exact`]; a pass over
    /// the masses).
    fn exact_kinetic_at(&self, _steps: usize) -> bool {
        false
    }
}

impl<F: FnMut(&StepView) -> ControlFlow<()>> Observer for F {
    fn step(&mut self, view: &StepView) -> ControlFlow<()> {
        self(view)
    }
}

/// An observer that watches nothing.
pub fn unobserved(_: &StepView) -> ControlFlow<()> {
    ControlFlow::Continue(())
}

/// How a relaxation ended.
#[derive(Debug, Clone, Serialize)]
pub struct RunReport {
    pub stop: Stop,
    /// `stop == Converged`.
    pub converged: bool,
    pub steps: usize,
    pub dt: f64,
    /// The ratio at the last step.
    pub unbalanced_ratio: f64,
    pub history: Vec<HistoryRow>,
}

/// Rule 1: the ratio is below the tolerance and the kinetic energy is not
/// above the previous step's (the velocities are decaying).
fn at_rest(ratio: f64, tolerance: f64, kinetic: f64, last_kinetic: f64) -> bool {
    ratio < tolerance && kinetic <= last_kinetic
}

/// Rule 4 at step `steps` of a relaxation: records the ratio and the mean
/// displacement at the end of each sliding window in `history`, and tells
/// whether the budget is foreseen.
fn foreseen(rules: &StopRules, history: &mut Vec<(f64, f64)>, ratio: f64, u: &[f64], steps: usize) -> bool {
    let (Some(f), Some(s)) = (rules.foresight, rules.sliding) else {
        return false;
    };
    let window = s.window.max(1);
    if !steps.is_multiple_of(window) {
        return false;
    }
    history.push((ratio, s.mean_displacement(u)));
    f.steps_needed(history, window, rules.tolerance)
        .is_some_and(|more| steps as f64 + more > f.margin * rules.max_steps as f64)
}

/// Steps `state` until a rule of `rules` fires (see the module doc).
pub fn relax(
    solver: &mut Solver,
    model: &Model,
    state: &mut State,
    rules: &StopRules,
    observer: &mut dyn Observer,
) -> Result<RunReport, SolveError> {
    let mut history = Vec::new();
    let mut ratio = f64::INFINITY;
    let first = state.step;
    let mut stop = None;
    let mut watch = SlidingWatch::default();
    let mut last_kinetic = f64::INFINITY;
    let mut window_history = Vec::new();
    while stop.is_none() {
        let (unbalanced, kinetic) = solver.step(model, state)?;
        let steps = state.step - first;
        ratio = solver.ratio(unbalanced);
        let at_rest = at_rest(ratio, rules.tolerance, kinetic, last_kinetic);
        last_kinetic = kinetic;
        stop = if at_rest {
            Some(Stop::Converged)
        } else if rules.sliding.is_some_and(|s| s.slides(&mut watch, &state.u, steps)) {
            Some(Stop::Sliding)
        } else if steps >= rules.max_steps {
            Some(Stop::Budget)
        } else if foreseen(rules, &mut window_history, ratio, &state.u, steps) {
            Some(Stop::Foreseen)
        } else {
            None
        };
        let record = state.step.is_multiple_of(rules.history_every) || stop == Some(Stop::Converged);
        let kinetic_exact = (record || stop.is_some() || observer.exact_kinetic_at(steps))
            .then(|| solver.exact_kinetic(state, kinetic));
        if let (true, Some(exact)) = (record, kinetic_exact) {
            history.push(HistoryRow::of(model, state, exact, ratio));
        }
        let view = StepView { state, steps, ratio, kinetic, kinetic_exact, stop };
        if observer.step(&view).is_break() && stop.is_none() {
            stop = Some(Stop::Caller);
        }
    }
    let stop = stop.expect("the loop ends with a stop");
    let converged = stop == Stop::Converged;
    Ok(RunReport { stop, converged, steps: state.step - first, dt: solver.dt(), unbalanced_ratio: ratio, history })
}

#[cfg(test)]
mod tests {
    use super::{at_rest, Foresight, SlidingWatch};

    #[test]
    fn a_steady_rate_with_scatter_slides_and_a_decaying_one_does_not() {
        let watch = |increments: &[f64]| SlidingWatch { increments: increments.to_vec(), ..Default::default() };
        // The paper slope's F = 1.125 with the tangent damping: 2.3-2.6 mm per
        // window, never three rising windows in a row.
        let creep = [2.4e-3, 2.3e-3, 2.6e-3, 2.4e-3, 2.3e-3, 2.6e-3];
        assert!(watch(&creep).steady(3, 1e-5));
        // A relaxing state: its increments shrink (q = 0.9 per window).
        let relaxing: Vec<f64> = (0..6).map(|k| 1e-3 * 0.9f64.powi(k)).collect();
        assert!(!watch(&relaxing).steady(3, 1e-5));
        // Below the floor, too few windows, or no windows: rest.
        assert!(!watch(&creep).steady(3, 3e-3));
        assert!(!watch(&creep[1..]).steady(3, 1e-5));
        assert!(!watch(&creep).steady(0, 1e-5));
    }

    #[test]
    fn foresight_extrapolates_a_geometric_decay() {
        let f = Foresight { windows: 3, margin: 2.0 };
        // q = 1/2 per window to 1.25e-3: 1e-5 is ln(125) / ln(2) windows on.
        let at = |r: [f64; 5], m: [f64; 5]| -> Vec<(f64, f64)> { r.into_iter().zip(m).collect() };
        let slowing = [0.0, 1.0, 1.5, 1.75, 1.875];
        let h = at([2e-2, 1e-2, 5e-3, 2.5e-3, 1.25e-3], slowing);
        let more = f.steps_needed(&h, 100, 1e-5).unwrap();
        assert!((more - 100.0 * 125f64.ln() / 2f64.ln()).abs() < 1e-9, "{more}");
        // Too few windows, a rise among the ratios, already below the
        // tolerance, or a mass that does not slow down: no forecast.
        assert_eq!(f.steps_needed(&h[1..], 100, 1e-5), None);
        assert_eq!(f.steps_needed(&at([2e-2, 1e-2, 5e-3, 6e-3, 1e-3], slowing), 100, 1e-5), None);
        assert_eq!(f.steps_needed(&h, 100, 2e-3), None);
        let steady = [0.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(f.steps_needed(&at([2e-2, 1e-2, 5e-3, 2.5e-3, 1.25e-3], steady), 100, 1e-5), None);
    }

    #[test]
    fn a_small_ratio_while_the_mass_still_speeds_up_is_not_rest() {
        assert!(at_rest(1e-6, 1e-5, 1.0, 2.0));
        assert!(at_rest(1e-6, 1e-5, 2.0, 2.0));
        assert!(!at_rest(1e-6, 1e-5, 2.5, 2.0), "kinetic energy rising");
        assert!(!at_rest(1e-4, 1e-5, 1.0, 2.0), "ratio above the tolerance");
        // The first step has nothing to compare with.
        assert!(at_rest(1e-6, 1e-5, 3.0, f64::INFINITY));
    }
}
