//! The discretisation error of a factor of safety (issue 61; the rows
//! `fserror/*`, references/srm.md, "Discretisation error"): `cdem srm
//! --mesh-check 1.5,2` on Griffiths & Lane's committed hexahedra, meshed
//! again by gmsh from their `.geo` at `refine` 1.5 and 2.
//!
//! - the three meshes' Richardson factor against the published FE strength
//!   reduction and the chart (reported: the 1 %);
//! - the committed mesh's side of it (asserted: unsafe, as the issue found);
//! - what a user who asks for two meshes (`--mesh-check`, refine 2) is told:
//!   its uncertainty (Roache's index with the assumed first order) must
//!   cover the distance from its extrapolation to the three meshes' (the
//!   third mesh is the outside check of the two-mesh statement).

use std::path::PathBuf;

use crate::drivers::mesh_check::{discretisation, mesh_check, Discretisation};
use crate::drivers::SrmResult;
use crate::error::Error;
use crate::harness::registry as reg;
use crate::harness::report::Check;

/// The check on Griffiths & Lane's hexahedra and its rows.
pub struct FsErrorRun {
    /// The committed mesh's reduction, with its three-mesh `discretisation`.
    pub result: SrmResult,
    /// What the committed mesh and refine 2 alone give.
    pub two: Discretisation,
    pub rows: Vec<Check>,
}

impl FsErrorRun {
    /// The three-mesh section.
    pub fn three(&self) -> &Discretisation {
        self.result.discretisation.as_ref().expect("mesh_check sets it")
    }
}

/// Where the refined meshes go: a folder of this process under the system's
/// temporary directory.
fn work_dir() -> PathBuf {
    std::env::temp_dir().join(format!("cdem-fserror-{}", std::process::id()))
}

/// Runs the check and makes its rows (gmsh on PATH; without it the check
/// fails with gmsh's error).
pub fn gl1_rows(progress: &mut dyn FnMut(&str)) -> Result<FsErrorRun, Error> {
    let t0 = std::time::Instant::now();
    let scene = reg::PLASTIC_GL1_HEX.scene()?;
    let dir = work_dir();
    let (result, _) = mesh_check(&scene, &reg::FSERROR_GL1_REFINE, &dir, &mut |p| {
        if let crate::drivers::mesh_check::CheckProgress::Mesh(r) = p {
            progress(&format!("Griffiths & Lane: strength reduction at refine {r}"));
        }
    })?;
    let _ = std::fs::remove_dir_all(&dir);
    let seconds = t0.elapsed().as_secs_f64();
    let three = result.discretisation.clone().expect("mesh_check sets it");
    let meshes = &three.meshes;
    let two = discretisation(three.refined_by.clone(), vec![meshes[0].clone(), meshes[2].clone()], f64::NAN);
    let table: Vec<String> = meshes
        .iter()
        .map(|m| format!("refine {} ({} hexahedra): {:?} {:?}", m.refine, m.elements, m.fs, m.bracket))
        .collect();
    let note = format!("{}; {}", table.join(", "), three.line);
    let mut rows = Vec::new();
    let ex = three.extrapolated.unwrap_or(f64::NAN);
    let defect = three.extrapolated.is_none().then(|| three.line.clone());
    let with_defect = |c: Check| match &defect {
        Some(d) => c.with_defect(d.clone()),
        None => c,
    };
    rows.push(with_defect(
        reg::row("fserror/gl1/extrapolated-vs-fe").value(ex, reg::GL1_FE_FS, seconds).with_note(note.clone()),
    ));
    rows.push(with_defect(
        reg::row("fserror/gl1/extrapolated-vs-chart").value(ex, reg::GL1_CHART_FS.value, 0.0).with_note(format!(
            "coarsest mesh {:+.1} % from the chart, extrapolated {:+.1} %",
            100.0 * (meshes[0].fs.unwrap_or(f64::NAN) / reg::GL1_CHART_FS.value - 1.0),
            100.0 * (ex / reg::GL1_CHART_FS.value - 1.0)
        )),
    ));
    let side = three.side.map_or("none".to_string(), |s| format!("{s:?}").to_lowercase());
    let err = three.error.map_or("-".to_string(), |e| format!("{:+.2} %", 100.0 * e));
    rows.push(reg::row("fserror/gl1/coarse-side").compared(
        &format!("{err} ({side} side)"),
        "unsafe side (issue 61)",
        three.side == Some(crate::drivers::mesh_check::Side::Unsafe),
        0.0,
    ));
    let cover = match (two.extrapolated, two.uncertainty) {
        (Some(e2), Some(u2)) => (e2 - ex).abs() / u2,
        _ => f64::NAN,
    };
    rows.push(with_defect(
        reg::row("fserror/gl1/two-mesh-covers")
            .value(cover, 0.0, 0.0)
            .with_note(format!("two meshes (refine 1, 2): {}; three: {:.4} (order {:?})", two.line, ex, three.order)),
    ));
    Ok(FsErrorRun { result, two, rows })
}
