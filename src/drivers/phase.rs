//! The vocabulary the drivers share: the two phases of a run, what a caller
//! sees of them ([`Watch`], [`Progress`]), the displacement frames and stage
//! rows they record, and the failed-spring count. Every driver imports it;
//! it imports no driver, so `run`, `failure` and `srm` do not import each
//! other in a circle.

use std::ops::ControlFlow;

use serde::Serialize;

use crate::physics::spring::SpringStatus;
use crate::solver::{State, StepView};
use crate::summary::FailedSprings;

/// The two phases of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// Phase 1: intact joints, to equilibrium.
    Elastic = 1,
    /// Phase 2: breakable joints (eq. 17-18).
    Failure = 2,
}

/// What a caller sees of a run as it goes. Both methods default to nothing.
pub trait Watch {
    /// After every step of either phase; `Break` stops the phase
    /// ([`crate::solver::Stop::Caller`]).
    fn step(&mut self, _phase: Phase, _view: &StepView) -> ControlFlow<()> {
        ControlFlow::Continue(())
    }
    /// At every stage row of phase 2, with the state it was taken from.
    fn stage(&mut self, _stage: &Stage, _state: &State) {}
}

/// A watcher that watches nothing.
pub struct NoWatch;

impl Watch for NoWatch {}

/// A watcher that reports `(global step, unbalanced ratio)` every 100 steps.
pub struct Progress<'a>(pub &'a mut dyn FnMut(usize, f64));

impl Watch for Progress<'_> {
    fn step(&mut self, _phase: Phase, view: &StepView) -> ControlFlow<()> {
        if view.steps.is_multiple_of(100) {
            (self.0)(view.state.step, view.ratio);
        }
        ControlFlow::Continue(())
    }
}

/// A displacement frame recorded during a phase.
#[derive(Debug, Clone)]
pub struct Frame {
    /// Step within its phase.
    pub step: usize,
    pub time: f64,
    pub u: Vec<f64>,
}

/// A milestone of phase 2.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Stage {
    /// Step within phase 2.
    pub step: usize,
    pub failed_tension: usize,
    pub failed_shear: usize,
    /// Largest displacement since the end of phase 1 (m).
    pub max_displacement: f64,
    pub kinetic_energy: f64,
    pub unbalanced_ratio: f64,
}

/// A watcher that keeps the displacement at every stage of phase 2 (parallel
/// to the result's stages), for figures and tests that look at every stage.
/// It copies the whole displacement at each stage: a run does not.
#[derive(Debug, Default)]
pub struct StageSnapshots {
    pub u: Vec<Vec<f64>>,
}

impl Watch for StageSnapshots {
    fn stage(&mut self, _stage: &Stage, state: &State) {
        self.u.push(state.u.clone());
    }
}

/// Failed springs by kind.
pub fn failed_springs(status: &[SpringStatus]) -> FailedSprings {
    let mut failed = FailedSprings::default();
    for s in status {
        match s {
            SpringStatus::Tension => failed.tension += 1,
            SpringStatus::Shear => failed.shear += 1,
            SpringStatus::Intact => {}
        }
    }
    failed
}
