//! Progressive failure: the paper's two phases (section 3.4).
//!
//! 1. Phase 1: elastic, failure off, until converged.
//! 2. Phase 2: breakable interfaces check eq. 17-18; run until a new
//!    equilibrium (unbalanced ratio below the tolerance) or global sliding
//!    (the displacement since phase 1 passes `sliding_displacement`), or the
//!    step limit. Each spring's first failure step is recorded, and a stage
//!    row (failed springs by kind, displacement, kinetic energy) every
//!    `stage_every` steps.

use serde::{Deserialize, Serialize};

use crate::error::{Error, SceneError};
use crate::model::Model;
use crate::physics::spring::SpringStatus;
use crate::run::build_model;
use crate::scene::Scene;
use crate::solver::{RunReport, Solver, State};

/// Scene section `[failure]`: present = run phase 2.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FailureParams {
    /// Step limit of phase 2. Default 200 000.
    pub max_steps: usize,
    /// Record a stage every this many steps. Default 500.
    pub stage_every: usize,
    /// Global sliding: the largest displacement since the end of phase 1
    /// passes this bound (m). Default 1.0.
    pub sliding_displacement: f64,
}

impl Default for FailureParams {
    fn default() -> Self {
        Self { max_steps: 200_000, stage_every: 500, sliding_displacement: 1.0 }
    }
}

impl FailureParams {
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.max_steps == 0 || self.stage_every == 0 {
            return Err(SceneError::invalid("failure.max_steps/stage_every", "must be at least 1"));
        }
        if !(self.sliding_displacement.is_finite() && self.sliding_displacement > 0.0) {
            return Err(SceneError::invalid("failure.sliding_displacement", "must be a finite positive length"));
        }
        Ok(())
    }
}

/// How phase 2 ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum EndState {
    /// Converged again with the failed joints: a new equilibrium.
    Equilibrium,
    /// Displacement passed the sliding bound: the mass slides.
    GlobalSliding,
    /// Neither within the step limit.
    Undecided,
}

/// A milestone of phase 2.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Stage {
    pub step: usize,
    pub failed_tension: usize,
    pub failed_shear: usize,
    /// Largest displacement since the end of phase 1 (m).
    pub max_displacement: f64,
    pub kinetic_energy: f64,
    pub unbalanced_ratio: f64,
}

pub struct ProgressiveResult {
    pub model: Model,
    pub elastic: RunReport,
    /// Displacement at the end of phase 1.
    pub u_elastic: Vec<f64>,
    pub state: State,
    pub stages: Vec<Stage>,
    /// Displacement at each stage (parallel to `stages`), for figures and VTK.
    pub stage_u: Vec<Vec<f64>>,
    /// Phase-2 step of each spring's first failure (None: never failed).
    pub failed_at: Vec<Option<usize>>,
    pub end: EndState,
    pub phase2_steps: usize,
}

fn max_displacement_since(u: &[f64], u0: &[f64]) -> f64 {
    u.chunks(3)
        .zip(u0.chunks(3))
        .map(|(a, b)| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt())
        .fold(0.0, f64::max)
}

/// Runs both phases of a scene.
pub fn run_progressive(
    scene: &Scene,
    params: &FailureParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<ProgressiveResult, Error> {
    let model = build_model(scene)?;
    let mut solver = Solver::new(&model, scene.solver.clone())?;
    let mut state = State::new(&model);
    // Phase 1.
    let elastic =
        solver.relax(&model, &mut state, scene.output.history_every, 100, &mut |st, r| progress(st.step, r))?;
    let u_elastic = state.u.clone();
    // Phase 2.
    solver.set_failure(&model, true);
    let mut failed_at = vec![None; model.springs.len()];
    let mut stages = Vec::new();
    let mut stage_u = Vec::new();
    let start = state.step;
    let mut end = EndState::Undecided;
    while state.step - start < params.max_steps {
        let (unbalanced, kinetic) = solver.step(&model, &mut state)?;
        let k = state.step - start;
        let ratio = solver.ratio(unbalanced);
        for (s, st) in state.springs.status.iter().enumerate() {
            if *st != SpringStatus::Intact && failed_at[s].is_none() {
                failed_at[s] = Some(k);
            }
        }
        let converged = ratio < scene.solver.tolerance;
        let moved = if k % 10 == 0 || converged { max_displacement_since(&state.u, &u_elastic) } else { 0.0 };
        let sliding = moved > params.sliding_displacement;
        if k % params.stage_every == 0 || converged || sliding {
            let failed_tension = state.springs.status.iter().filter(|s| **s == SpringStatus::Tension).count();
            let failed_shear = state.springs.status.iter().filter(|s| **s == SpringStatus::Shear).count();
            let max_displacement = max_displacement_since(&state.u, &u_elastic);
            stages.push(Stage {
                step: k,
                failed_tension,
                failed_shear,
                max_displacement,
                kinetic_energy: kinetic,
                unbalanced_ratio: ratio,
            });
            stage_u.push(state.u.clone());
        }
        if k % 100 == 0 {
            progress(state.step, ratio);
        }
        if converged {
            end = EndState::Equilibrium;
            break;
        }
        if sliding {
            end = EndState::GlobalSliding;
            break;
        }
    }
    let phase2_steps = state.step - start;
    Ok(ProgressiveResult { model, elastic, u_elastic, state, stages, stage_u, failed_at, end, phase2_steps })
}

/// Writes phase-2 outputs: `stages.csv`, `failed_springs.csv` (spring, first
/// failure step, kind, position) and VTK frames of the stages (`stage-NNNNNNNN.vtu`,
/// collected in `failure.pvd`), into `out` (created).
pub fn write_outputs(result: &ProgressiveResult, out: &std::path::Path, vtk: bool) -> Result<(), Error> {
    use crate::output::{vtk as v, write_atomic};
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    let mut w = csv::Writer::from_writer(Vec::new());
    for s in &result.stages {
        w.serialize(s).map_err(|e| Error::io(out, std::io::Error::other(e)))?;
    }
    let bytes = w.into_inner().map_err(|e| Error::io(out, std::io::Error::other(e.to_string())))?;
    write_atomic(&out.join("stages.csv"), &bytes)?;
    let mut text = String::from("spring,first_failure_step,kind,x,y,z\n");
    let sp = &result.model.springs;
    for (k, at) in result.failed_at.iter().enumerate() {
        if let Some(step) = at {
            let x = result.model.x0[sp.a[k] as usize];
            text.push_str(&format!("{k},{step},{:?},{},{},{}\n", result.state.springs.status[k], x[0], x[1], x[2]));
        }
    }
    write_atomic(&out.join("failed_springs.csv"), text.as_bytes())?;
    if vtk {
        let mut pvd = Vec::new();
        for (s, u) in result.stages.iter().zip(&result.stage_u) {
            let name = format!("stage-{:08}.vtu", s.step);
            v::write_vtu(&out.join(&name), &result.model, &v::Frame { u, stress: None })?;
            pvd.push((s.step as f64, name));
        }
        v::write_pvd(&out.join("failure.pvd"), &pvd)?;
    }
    Ok(())
}
