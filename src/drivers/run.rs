//! The CDEM run of a scene: read the mesh, build the model, solve phase 1
//! (elastic; dynamic relaxation or conjugate gradients, `[solver] elastic`,
//! as its [`PhasePlan`] chose), then, for a scene with `[failure]`, phase 2
//! (breakable joints, [`super::failure`]); summarise. Orchestration only: the arithmetic is in
//! the solver, the files are written by `output`.

use std::time::Instant;

use super::analysis::{run_analysis, AnalysisReport, SpringSource};
use super::failure::{self, FailureResult};
use super::input::read_mesh;
use super::phase::{failed_springs, Frame, Phase, Progress, Watch};
use crate::error::{Error, ModelError};
use crate::model::{self, Model};
use crate::scene::Scene;
use crate::solver::relax::{max_displacement_since, unobserved};
use crate::solver::{PhasePlan, RunReport, SolverParams, State, StepView};
use crate::summary::{EndState, FieldExtremes, PhaseSummary, Summary};

/// Everything a run produced.
pub struct RunResult {
    pub model: Model,
    /// The final state (end of phase 2 if there is one).
    pub state: State,
    /// Phase 1.
    pub elastic: RunReport,
    /// Phase 2, for a scene with `[failure]`.
    pub failure: Option<FailureResult>,
    /// Element stresses of the final state, if the scene asks for them.
    pub stress: Option<Vec<[f64; 6]>>,
    /// The scene's `[analysis]` on the elastic state (the end of phase 1).
    pub surface: Option<AnalysisReport>,
    /// Phase-1 frames (`output.frame_every`); the final state is not among them.
    pub frames: Vec<Frame>,
    /// The runout, for a scene with `[runout]` (its displacement is not in `state`).
    pub runout: Option<super::runout::RunoutResult>,
    pub summary: Summary,
}

/// Before the first step: every connected part of the model must be held
/// against all six rigid motions by its fixities (the FEM makes the same
/// check on the continuous mesh).
pub fn check_supports(model: &Model) -> Result<(), Error> {
    match crate::model::supports::unsupported_part(model) {
        None => Ok(()),
        Some(p) => Err(ModelError::FreeRigidMotion {
            part: p.part,
            elements: p.elements,
            first_element: p.first_element,
            motion: p.motion,
        }
        .into()),
    }
}

/// Runs a scene (both phases if it has `[failure]`), reporting
/// `(step, unbalanced ratio)` every 100 steps.
pub fn run_scene(scene: &Scene, progress: &mut dyn FnMut(usize, f64)) -> Result<RunResult, Error> {
    run_watched(scene, &mut Progress(progress))
}

/// Runs a scene under a [`Watch`].
pub fn run_watched(scene: &Scene, watch: &mut dyn Watch) -> Result<RunResult, Error> {
    let t0 = Instant::now();
    let mesh = read_mesh(scene)?;
    let model = model::build(&mesh, &scene.model_spec())?;
    check_supports(&model)?;
    let mut state = State::new(&model);

    // Phase 1.
    let frame_every = if scene.output.vtk { scene.output.frame_every } else { 0 };
    let mut frames = Vec::new();
    let mut observe = |view: &StepView| {
        if frame_every > 0 && view.state.step.is_multiple_of(frame_every) {
            frames.push(Frame { step: view.state.step, time: view.state.time, u: view.state.u.clone() });
        }
        watch.step(Phase::Elastic, view)
    };
    let mut plan = PhasePlan::elastic(&model, &scene.solver, scene.output.history_every)?;
    let elastic = plan.run(&model, &mut state, false, None, &mut observe)?;
    let phase1 = PhaseSummary {
        end_state: if elastic.converged { EndState::Equilibrium } else { EndState::Undecided },
        steps: elastic.steps,
        unbalanced_ratio: elastic.unbalanced_ratio,
        failed_springs: failed_springs(&state.springs.status),
        max_displacement: FieldExtremes::of(&state.u, None).max_abs_u,
    };

    // The scene's `[analysis]` on the elastic state; its stresses are the
    // final ones too when there is no phase 2.
    let elastic_stress = scene.analysis.is_some().then(|| model.element_stresses(&state.u));
    let surface = match &elastic_stress {
        Some(stress) => {
            let springs = SpringSource { model: &model, u: &state.u, springs: &state.springs };
            run_analysis(scene, &mesh, &model.mesh_coords, stress, Some(springs), "elastic (end of phase 1)")?
        }
        None => None,
    };

    // Phase 2, from the state phase 1 left, by dynamic relaxation whatever
    // solved phase 1 (its DR solver goes on if its masses fit).
    let failure = match &scene.failure {
        Some(params) => {
            let history_every = scene.output.history_every;
            let mut plan = failure::phase_plan(&model, &scene.solver, params, history_every, plan.into_solver())?;
            Some(failure::run(&mut plan, &model, &mut state, params, scene.output.vtk, watch)?)
        }
        None => None,
    };
    let phase2 = failure.as_ref().map(|f| PhaseSummary {
        end_state: f.end,
        steps: f.report.steps,
        unbalanced_ratio: f.report.unbalanced_ratio,
        failed_springs: failed_springs(&state.springs.status),
        max_displacement: max_displacement_since(&state.u, &f.u_elastic),
    });

    let last_end = phase2.as_ref().map_or(phase1.end_state, |p| p.end_state);
    let runout = match &scene.runout {
        Some(section) => Some(super::runout::run(section, &model, &state, last_end)?),
        None => None,
    };

    let stress = scene.output.stress.then(|| match (&failure, elastic_stress) {
        (None, Some(elastic)) => elastic,
        _ => model.element_stresses_in(&state.rock, &state.u),
    });
    let plastic = model.plastic_cells(&state.rock, &state.u).map(|cells| model.plastic_summary(&cells));
    let field = FieldExtremes::of(&state.u, stress.as_deref());
    let last = phase2.as_ref().unwrap_or(&phase1);
    let summary = Summary {
        end_state: last.end_state,
        converged: last.end_state == EndState::Equilibrium,
        steps: phase1.steps + phase2.as_ref().map_or(0, |p| p.steps),
        wall_s: t0.elapsed().as_secs_f64(),
        dt: elastic.dt,
        unbalanced_ratio: last.unbalanced_ratio,
        max_abs_uz: field.max_abs_uz,
        min_uz: field.min_uz,
        max_abs_u: field.max_abs_u,
        min_szz: field.min_szz,
        failed_springs: last.failed_springs,
        elements: model.elements.len(),
        nodes: model.n_nodes(),
        springs: model.springs.len(),
        phase1: Some(phase1),
        phase2,
        plastic,
        water: model.water.as_ref().map(|w| w.summary()),
        runout: runout.as_ref().map(|r| r.summary.clone()),
    };
    Ok(RunResult { model, state, elastic, failure, stress, surface, frames, runout, summary })
}

/// Relaxes a model to equilibrium with the given settings and no watcher
/// (benches, perf, tests): phase 1 of [`run_watched`] without the scene,
/// by the solver `params.elastic` names.
pub fn relax_elastic(model: &Model, params: &SolverParams, history_every: usize) -> Result<(State, RunReport), Error> {
    let mut state = State::new(model);
    let report =
        PhasePlan::elastic(model, params, history_every)?.run(model, &mut state, false, None, &mut unobserved)?;
    Ok((state, report))
}
