//! A whole run of a scene: read the mesh, build the model, relax, summarise,
//! write outputs. This is orchestration only; the arithmetic is elsewhere.

use std::path::Path;
use std::time::Instant;

use serde::Serialize;

use crate::error::Error;
use crate::mesh::gmsh::read_msh;
use crate::model::{self, Model};
use crate::output::{self, vtk};
use crate::physics::spring::SpringStatus;
use crate::scene::Scene;
use crate::solver::{RunReport, Solver, State};

/// Number of failed springs by kind.
#[derive(Debug, Clone, Copy, Default, Serialize, PartialEq, Eq)]
pub struct FailedSprings {
    pub tension: usize,
    pub shear: usize,
}

/// `summary.json`: the numbers a run is judged by.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    pub converged: bool,
    pub steps: usize,
    pub wall_s: f64,
    /// Time step (s; 1 with mass scaling, a fictitious time).
    pub dt: f64,
    pub unbalanced_ratio: f64,
    /// Largest |u_z| over all nodes (m).
    pub max_abs_uz: f64,
    /// Most negative u_z (m).
    pub min_uz: f64,
    /// Largest displacement magnitude (m).
    pub max_abs_u: f64,
    /// Most compressive element sigma_zz (Pa), if stresses were computed.
    pub min_szz: Option<f64>,
    pub failed_springs: FailedSprings,
    pub elements: usize,
    pub nodes: usize,
    pub springs: usize,
}

/// A displacement frame recorded during a run.
pub struct Frame {
    pub step: usize,
    pub time: f64,
    pub u: Vec<f64>,
}

/// Everything a run produced.
pub struct RunResult {
    pub model: Model,
    pub state: State,
    pub report: RunReport,
    pub stress: Option<Vec<[f64; 6]>>,
    /// Intermediate frames (`output.frame_every`); the final state is not among them.
    pub frames: Vec<Frame>,
    pub summary: Summary,
}

/// Builds the model of a scene (mesh read and perturbed, springs made).
pub fn build_model(scene: &Scene) -> Result<Model, Error> {
    let path = scene.mesh_path();
    let mesh = read_msh(&path).map_err(|e| match e {
        Error::Mesh(source) => Error::MeshFile { path, source },
        other => other,
    })?;
    model::build(&mesh, scene)
}

/// Runs a scene to equilibrium (elastic phase).
pub fn run_scene(scene: &Scene, progress: &mut dyn FnMut(usize, f64)) -> Result<RunResult, Error> {
    let t0 = Instant::now();
    let model = build_model(scene)?;
    let mut solver = Solver::new(&model, scene.solver.clone())?;
    let mut state = State::new(&model);
    let frame_every = if scene.output.vtk { scene.output.frame_every } else { 0 };
    let mut frames = Vec::new();
    let mut observe = |st: &State, ratio: f64| {
        if st.step % 100 == 0 {
            progress(st.step, ratio);
        }
        if frame_every > 0 && st.step % frame_every == 0 {
            frames.push(Frame { step: st.step, time: st.time, u: st.u.clone() });
        }
    };
    let every = if frame_every > 0 { gcd(frame_every, 100) } else { 100 };
    let report = solver.relax(&model, &mut state, scene.output.history_every, every, &mut observe)?;
    let stress = scene.output.stress.then(|| model.element_stresses(&state.u));
    let summary = summarize(&model, &state, &report, stress.as_deref(), t0.elapsed().as_secs_f64());
    Ok(RunResult { model, state, report, stress, frames, summary })
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

pub fn summarize(
    model: &Model,
    state: &State,
    report: &RunReport,
    stress: Option<&[[f64; 6]]>,
    wall_s: f64,
) -> Summary {
    let u = &state.u;
    let uz = u.chunks(3).map(|d| d[2]);
    let mut failed = FailedSprings::default();
    for s in &state.springs.status {
        match s {
            SpringStatus::Tension => failed.tension += 1,
            SpringStatus::Shear => failed.shear += 1,
            SpringStatus::Intact => {}
        }
    }
    Summary {
        converged: report.converged,
        steps: report.steps,
        wall_s,
        dt: report.dt,
        unbalanced_ratio: report.unbalanced_ratio,
        max_abs_uz: uz.clone().map(f64::abs).fold(0.0, f64::max),
        min_uz: uz.fold(0.0, f64::min),
        max_abs_u: u.chunks(3).map(|d| (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()).fold(0.0, f64::max),
        min_szz: stress.map(|s| s.iter().map(|x| x[2]).fold(f64::INFINITY, f64::min)),
        failed_springs: failed,
        elements: model.elements.len(),
        nodes: model.n_nodes(),
        springs: model.springs.len(),
    }
}

/// Writes `summary.json`, `history.csv` and (if asked) the VTK frames
/// (`step-NNNNNNNN.vtu`, `final.vtu`) with their collection `run.pvd`.
/// Everything is written to a staging directory first and moved into `out`
/// only when all of it is written: a failed run leaves nothing behind.
pub fn write_outputs(scene: &Scene, result: &RunResult, out: &Path) -> Result<(), Error> {
    let staging = staging_dir(out);
    let written = write_all(scene, result, &staging);
    let moved = written.and_then(|files| {
        std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
        for f in files {
            std::fs::rename(staging.join(&f), out.join(&f)).map_err(|e| Error::io(out.join(&f), e))?;
        }
        Ok(())
    });
    let _ = std::fs::remove_dir_all(&staging);
    moved
}

/// A sibling of `out` named `.<name>.partial-<pid>`.
pub fn staging_dir(out: &Path) -> std::path::PathBuf {
    let name = out.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "out".into());
    out.with_file_name(format!(".{name}.partial-{}", std::process::id()))
}

fn write_all(scene: &Scene, result: &RunResult, dir: &Path) -> Result<Vec<String>, Error> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let mut files = vec!["summary.json".to_string(), "history.csv".to_string()];
    output::write_json(&dir.join("summary.json"), &result.summary)?;
    output::write_history(&dir.join("history.csv"), &result.report.history)?;
    if scene.output.vtk {
        let mut pvd = Vec::new();
        for f in &result.frames {
            let name = format!("step-{:08}.vtu", f.step);
            vtk::write_vtu(&dir.join(&name), &result.model, &vtk::Frame { u: &f.u, stress: None })?;
            pvd.push((f.time, name));
        }
        let frame = vtk::Frame { u: &result.state.u, stress: result.stress.as_deref() };
        vtk::write_vtu(&dir.join("final.vtu"), &result.model, &frame)?;
        pvd.push((result.state.time, "final.vtu".to_string()));
        vtk::write_pvd(&dir.join("run.pvd"), &pvd)?;
        files.extend(pvd.into_iter().map(|(_, n)| n));
        files.push("run.pvd".into());
    }
    Ok(files)
}
