//! Phase 2 of a run: progressive failure (the paper's section 3.4).
//!
//! From the elastic state of phase 1, the breakable interfaces check
//! eq. 17-18 and the model relaxes again ([`crate::solver::relax()`]) until:
//! - a new equilibrium: the unbalanced ratio below the tolerance
//!   ([`EndState::Equilibrium`]);
//! - global sliding: the largest displacement since phase 1 passes
//!   `sliding_displacement` ([`EndState::GlobalSliding`]);
//! - the step budget `max_steps` ([`EndState::Undecided`]).
//!
//! Each spring's first failure step is recorded, and a stage row (failed
//! springs by kind, displacement since phase 1, kinetic energy) every
//! `stage_every` steps and at the end. A stage copies no state; a frame (a
//! copy of the displacement, for VTK) is taken at a stage only when the
//! failure state changed since the last frame, and at the end.

use serde::Serialize;

use super::run::{failed_springs, Frame, Phase, Watch};
use crate::error::Error;
use crate::model::Model;
use crate::physics::spring::SpringStatus;
use crate::scene::FailureParams;
use crate::solver::relax::max_displacement_since;
use crate::solver::{relax, RunReport, Sliding, Solver, State, StepView, Stop, StopRules};
use crate::summary::{EndState, FailedSprings};

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

/// What phase 2 produced.
pub struct FailureResult {
    pub report: RunReport,
    pub end: EndState,
    /// Displacement at the end of phase 1.
    pub u_elastic: Vec<f64>,
    pub stages: Vec<Stage>,
    /// Phase-2 step of each spring's first failure (None: never failed).
    pub failed_at: Vec<Option<usize>>,
    /// Frames where the failure state changed, and the last one.
    pub frames: Vec<Frame>,
}

/// The scene's output settings phase 2 needs.
#[derive(Debug, Clone, Copy)]
pub struct Options {
    /// Take frames (for VTK).
    pub vtk: bool,
    pub history_every: usize,
}

/// Runs phase 2 from the elastic `state` (which it advances).
pub fn run(
    solver: &mut Solver,
    model: &Model,
    state: &mut State,
    params: &FailureParams,
    tolerance: f64,
    options: Options,
    watch: &mut dyn Watch,
) -> Result<FailureResult, Error> {
    solver.set_failure(model, true);
    let u_elastic = state.u.clone();
    let mut failed_at = vec![None; model.springs.len()];
    let mut stages = Vec::new();
    let mut frames = Vec::new();
    let mut framed = None::<FailedSprings>;
    let rules = StopRules {
        tolerance,
        max_steps: params.max_steps,
        sliding: Some(Sliding { reference: &u_elastic, displacement: params.sliding_displacement, check_every: 10 }),
        history_every: options.history_every,
    };
    let mut observe = |view: &StepView| {
        let (st, k) = (view.state, view.steps);
        for (s, status) in st.springs.status.iter().enumerate() {
            if *status != SpringStatus::Intact && failed_at[s].is_none() {
                failed_at[s] = Some(k);
            }
        }
        if k % params.stage_every == 0 || view.stop.is_some() {
            let failed = failed_springs(&st.springs.status);
            let stage = Stage {
                step: k,
                failed_tension: failed.tension,
                failed_shear: failed.shear,
                max_displacement: max_displacement_since(&st.u, &u_elastic),
                kinetic_energy: view.kinetic,
                unbalanced_ratio: view.ratio,
            };
            stages.push(stage);
            watch.stage(&stage, st);
            if options.vtk && (framed != Some(failed) || view.stop.is_some()) {
                frames.push(Frame { step: k, time: st.time, u: st.u.clone() });
                framed = Some(failed);
            }
        }
        watch.step(Phase::Failure, view)
    };
    let report = relax(solver, model, state, &rules, &mut observe)?;
    let end = match report.stop {
        Stop::Converged => EndState::Equilibrium,
        Stop::Sliding => EndState::GlobalSliding,
        Stop::Budget | Stop::Caller => EndState::Undecided,
    };
    Ok(FailureResult { report, end, u_elastic, stages, failed_at, frames })
}

/// A watcher that keeps the displacement at every stage of phase 2 (parallel
/// to [`FailureResult::stages`]), for figures and tests that look at every
/// stage. It copies the whole displacement at each stage: a run does not.
#[derive(Debug, Default)]
pub struct StageSnapshots {
    pub u: Vec<Vec<f64>>,
}

impl Watch for StageSnapshots {
    fn stage(&mut self, _stage: &Stage, state: &State) {
        self.u.push(state.u.clone());
    }
}
