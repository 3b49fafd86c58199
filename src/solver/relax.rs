//! The relax driver: steps until a stop rule fires. Both phases of a run,
//! and every later driver (strength reduction, ensembles), relax through
//! [`relax`]; they differ only in their [`StopRules`] and their
//! [`Observer`].
//!
//! The rules, checked after every step in this order:
//! 1. **tolerance**: the unbalanced-force ratio is below `tolerance`
//!    ([`Stop::Converged`]);
//! 2. **sliding** (if given): every `check_every` steps, the largest
//!    displacement since `reference` passes `displacement` ([`Stop::Sliding`]);
//! 3. **budget**: `max_steps` steps taken ([`Stop::Budget`]);
//! 4. **caller**: the observer returns `Break` ([`Stop::Caller`]).

use std::ops::ControlFlow;

use serde::Serialize;

use super::{HistoryRow, Solver, State};
use crate::error::SolveError;
use crate::model::Model;

/// Why a relaxation stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Stop {
    Converged,
    Sliding,
    Budget,
    Caller,
}

/// Global sliding: the mass keeps moving away from a reference state.
#[derive(Debug, Clone, Copy)]
pub struct Sliding<'a> {
    /// Displacement the motion is measured from (3 per node).
    pub reference: &'a [f64],
    /// Bound on the largest nodal displacement since `reference` (m).
    pub displacement: f64,
    /// Check every this many steps (the check reads every node).
    pub check_every: usize,
}

/// When to stop, and how often to record a history row.
#[derive(Debug, Clone, Copy)]
pub struct StopRules<'a> {
    /// Converged: `max |f_unbal| / max |f_ext|` below this.
    pub tolerance: f64,
    /// Step budget of this relaxation.
    pub max_steps: usize,
    pub sliding: Option<Sliding<'a>>,
    /// A history row every this many (global) steps, and at the stop.
    pub history_every: usize,
}

/// What one step looked like, for the observer.
pub struct StepView<'a> {
    pub state: &'a State,
    /// Steps taken by this relaxation so far (this one included).
    pub steps: usize,
    pub ratio: f64,
    pub kinetic: f64,
    /// The rule that fired on this step, if any: it is the last step.
    pub stop: Option<Stop>,
}

/// The caller's view of a relaxation: progress, stages, frames, a stop.
pub trait Observer {
    /// Called after every step; `Break` stops the relaxation ([`Stop::Caller`])
    /// unless a rule already fired.
    fn step(&mut self, view: &StepView) -> ControlFlow<()>;
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

/// Largest nodal displacement of `u` since `u0` (m).
pub fn max_displacement_since(u: &[f64], u0: &[f64]) -> f64 {
    u.chunks(3)
        .zip(u0.chunks(3))
        .map(|(a, b)| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt())
        .fold(0.0, f64::max)
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
    while stop.is_none() {
        let (unbalanced, kinetic) = solver.step(model, state)?;
        let steps = state.step - first;
        ratio = solver.ratio(unbalanced);
        stop = if ratio < rules.tolerance {
            Some(Stop::Converged)
        } else if rules.sliding.is_some_and(|s| {
            steps.is_multiple_of(s.check_every) && max_displacement_since(&state.u, s.reference) > s.displacement
        }) {
            Some(Stop::Sliding)
        } else if steps >= rules.max_steps {
            Some(Stop::Budget)
        } else {
            None
        };
        if state.step.is_multiple_of(rules.history_every) || stop == Some(Stop::Converged) {
            history.push(solver.history_row(model, state, kinetic, ratio));
        }
        let view = StepView { state, steps, ratio, kinetic, stop };
        if observer.step(&view).is_break() && stop.is_none() {
            stop = Some(Stop::Caller);
        }
    }
    let stop = stop.expect("the loop ends with a stop");
    let converged = stop == Stop::Converged;
    Ok(RunReport { stop, converged, steps: state.step - first, dt: solver.dt(), unbalanced_ratio: ratio, history })
}
