//! The files of a CDEM run ([`write_run`]):
//! - `summary.json` ([`Summary`](crate::summary::Summary));
//! - `history.csv`: one row every `output.history_every` steps of both
//!   phases, with a `phase` column (1 elastic, 2 failure);
//! - with `output.vtk`: `final.vtu`, the phase-1 frames `step-NNNNNNNN.vtu`,
//!   and `run.pvd` collecting them;
//! - for a scene with `[failure]`: `stages.csv`, `failed_springs.csv`
//!   (spring, first failure step, kind, position) and, with `output.vtk`, the
//!   phase-2 frames `stage-NNNNNNNN.vtu` (where the failure state changed,
//!   and the last) collected in `failure.pvd`;
//! - for a scene with `[analysis]`: `analysis.json` and `analysis.csv`
//!   ([`super::analysis`]), on the elastic state.

use std::fmt::Write;
use std::path::Path;

use serde::Serialize;

use super::{staged, vtk, write_atomic, write_csv, write_json};
use crate::drivers::{FailureResult, RunResult};
use crate::error::Error;
use crate::scene::Scene;
use crate::solver::HistoryRow;

/// A `history.csv` row.
#[derive(Serialize)]
struct PhasedRow {
    phase: u8,
    step: usize,
    time: f64,
    kinetic_energy: f64,
    external_work: f64,
    strain_energy: f64,
    unbalanced_ratio: f64,
    max_displacement: f64,
}

impl PhasedRow {
    fn new(phase: u8, h: &HistoryRow) -> Self {
        Self {
            phase,
            step: h.step,
            time: h.time,
            kinetic_energy: h.kinetic_energy,
            external_work: h.external_work,
            strain_energy: h.strain_energy,
            unbalanced_ratio: h.unbalanced_ratio,
            max_displacement: h.max_displacement,
        }
    }
}

/// Writes every file of a run into `out`, staged (see the module doc).
pub fn write_run(scene: &Scene, result: &RunResult, out: &Path) -> Result<(), Error> {
    staged(out, |dir| write_all(scene, result, dir))
}

fn write_all(scene: &Scene, result: &RunResult, dir: &Path) -> Result<Vec<String>, Error> {
    let mut files = vec!["summary.json".to_string(), "history.csv".to_string()];
    write_json(&dir.join("summary.json"), &result.summary)?;
    let phase2 = result.failure.iter().flat_map(|f| &f.report.history);
    let rows = result.elastic.history.iter().map(|h| PhasedRow::new(1, h)).chain(phase2.map(|h| PhasedRow::new(2, h)));
    write_csv(&dir.join("history.csv"), rows)?;
    if scene.output.vtk {
        let mut pvd = Vec::new();
        for f in &result.frames {
            let name = format!("step-{:08}.vtu", f.step);
            vtk::write_vtu(&dir.join(&name), &result.model, &vtk::Frame { u: &f.u, stress: None, cells: &[] })?;
            pvd.push((f.time, name));
        }
        let plastic = result.model.plastic_cells(&result.state.rock, &result.state.u);
        let fields = plastic.as_deref().map(vtk::plastic_fields).unwrap_or_default();
        let frame = vtk::Frame { u: &result.state.u, stress: result.stress.as_deref(), cells: &fields };
        vtk::write_vtu(&dir.join("final.vtu"), &result.model, &frame)?;
        pvd.push((result.state.time, "final.vtu".to_string()));
        vtk::write_pvd(&dir.join("run.pvd"), &pvd)?;
        files.extend(pvd.into_iter().map(|(_, n)| n));
        files.push("run.pvd".into());
    }
    if let Some(report) = &result.surface {
        files.extend(super::analysis::write_analysis(report, dir)?);
    }
    if let Some(f) = &result.failure {
        files.extend(write_failure(result, f, dir, scene.output.vtk)?);
    }
    if let Some(r) = result.runout.as_ref().filter(|r| r.summary.ran) {
        files.extend(write_runout(result, r, dir, scene.output.vtk)?);
    }
    Ok(files)
}

/// `runout.csv` (one row every `[runout] row_every` steps) and, with VTK
/// output, `runout.pvd`: a frame every `[runout] frame_every` seconds, the
/// blocks where they are (displacement from the rest coordinates).
fn write_runout(
    result: &RunResult,
    r: &crate::drivers::runout::RunoutResult,
    dir: &Path,
    vtk: bool,
) -> Result<Vec<String>, Error> {
    let mut files = vec!["runout.csv".to_string()];
    write_csv(&dir.join("runout.csv"), &r.rows)?;
    if vtk {
        let mut pvd = Vec::new();
        for (k, f) in r.frames.iter().enumerate() {
            let name = format!("runout-{k:04}.vtu");
            vtk::write_vtu(&dir.join(&name), &result.model, &vtk::Frame { u: &f.u, stress: None, cells: &[] })?;
            pvd.push((f.time, name));
        }
        vtk::write_pvd(&dir.join("runout.pvd"), &pvd)?;
        files.extend(pvd.into_iter().map(|(_, n)| n));
        files.push("runout.pvd".into());
    }
    Ok(files)
}

fn write_failure(result: &RunResult, f: &FailureResult, dir: &Path, vtk: bool) -> Result<Vec<String>, Error> {
    let mut files = vec!["stages.csv".to_string(), "failed_springs.csv".to_string()];
    write_csv(&dir.join("stages.csv"), &f.stages)?;
    let mut text = String::from("spring,first_failure_step,kind,x,y,z\n");
    let sp = &result.model.springs;
    for (k, at) in f.failed_at.iter().enumerate() {
        if let Some(step) = at {
            let x = result.model.x0[sp.a[k] as usize];
            let _ = writeln!(text, "{k},{step},{:?},{},{},{}", result.state.springs.status[k], x[0], x[1], x[2]);
        }
    }
    write_atomic(&dir.join("failed_springs.csv"), text.as_bytes())?;
    if vtk {
        let mut pvd = Vec::new();
        for frame in &f.frames {
            let name = format!("stage-{:08}.vtu", frame.step);
            vtk::write_vtu(&dir.join(&name), &result.model, &vtk::Frame { u: &frame.u, stress: None, cells: &[] })?;
            pvd.push((frame.step as f64, name));
        }
        vtk::write_pvd(&dir.join("failure.pvd"), &pvd)?;
        files.extend(pvd.into_iter().map(|(_, n)| n));
        files.push("failure.pvd".into());
    }
    Ok(files)
}
