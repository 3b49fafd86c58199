//! Cost against size of phase 2 and strength reduction (issue 28, item 5):
//! `cdem srm` (the default warm-started trials) on two cases at several
//! resolutions, and per mesh the trials, the phase-2 steps per trial and the
//! wall time per trial and per step; then the exponents `p` of `cost ~ N^p`
//! against the element count ([`super::fit_power`]).
//!
//! - **slab**: the slip-surface slope of references/srm.md (brittle joints,
//!   the paper's; one hexahedron through y), `slope-slip.geo` at `refine`
//!   (the element size divided by it; 1 is the committed mesh);
//! - **3D**: the symmetric wedge of references/joints.md (tetrahedra),
//!   `wedge.geo` with its `Mesh.MeshSizeMax` replaced.
//!
//! Each trial is one phase 2 at a reduced strength, so its steps and time are
//! phase 2's cost at that size; the first trial (F = 1, from the elastic
//! state) is the phase 2 that `cdem run` does.

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Serialize;

use super::fit_power;
use super::scaling::mesh_text;
use crate::drivers::{run_srm, SrmProgress};
use crate::error::Error;
use crate::harness::registry as reg;
use crate::scene::Scene;

/// The slab's resolutions (`refine` of slope-slip.geo): 269 to 15,974
/// elements, the 250 to 16,000 of issue 28 item 5 (references/performance.md).
pub const SLAB_REFINE: [f64; 5] = [0.65, 1.0, 2.0, 4.0, 5.45];

/// The wedge's `Mesh.MeshSizeMax` (m): 1,382 to 16,579 tetrahedra. No
/// coarser wedge exists: from 4 m up the wedge's own points set the size
/// (6 m and 4 m give the same 1,382).
pub const WEDGE_SIZES: [f64; 4] = [6.0, 3.0, 2.0, 1.45];

/// One mesh of the study.
#[derive(Debug, Clone, Serialize)]
pub struct TrialScalingRow {
    /// `"slab"` or `"3D"`.
    pub case: &'static str,
    /// `refine` (slab) or the mesh size in m (3D).
    pub resolution: f64,
    pub elements: usize,
    pub trials: usize,
    /// Phase-2 steps of the first trial (F = 1 from the elastic state).
    pub first_steps: usize,
    pub mean_steps: f64,
    pub max_steps: usize,
    /// The whole `cdem srm` (elastic phase and setup included), s.
    pub srm_s: f64,
    /// Mean wall time of a trial, s.
    pub trial_s: f64,
    /// Wall time per phase-2 step over all trials, ms.
    pub step_ms: f64,
    pub fs: Option<f64>,
    /// The final bracket `[lo, hi]` (two columns: a CSV row has no arrays).
    pub bracket_lo: Option<f64>,
    pub bracket_hi: Option<f64>,
}

/// The slab's mesh at `refine` in `dir` (the committed mesh at 1).
pub fn slab_mesh(root: &Path, refine: f64, dir: &Path) -> Result<PathBuf, Error> {
    let geo = root.join(Path::new(reg::SLOPE_SLIP.input).with_extension("geo"));
    if refine == 1.0 {
        return Ok(geo.with_extension("msh"));
    }
    let include = geo.canonicalize().map_err(|e| Error::io(&geo, e))?;
    let text = format!(
        "// The slip-surface slope at refine = {refine} (cdem perf).\nrefine = {refine};\nInclude \"{}\";\n",
        include.display()
    );
    mesh_text(&text, &format!("slope-slip-r{refine}"), dir)
}

/// The wedge's mesh at `Mesh.MeshSizeMax = size` in `dir`.
pub fn wedge_mesh(root: &Path, size: f64, dir: &Path) -> Result<PathBuf, Error> {
    let geo = root.join(Path::new(reg::WEDGE_SYMMETRIC.input).with_extension("geo"));
    let text = std::fs::read_to_string(&geo).map_err(|e| Error::io(&geo, e))?;
    let Some(line) = text.lines().find(|l| l.starts_with("Mesh.MeshSizeMax")) else {
        return Err(Error::Gmsh(format!("{}: no Mesh.MeshSizeMax line to replace", geo.display())));
    };
    mesh_text(&text.replacen(line, &format!("Mesh.MeshSizeMax = {size};"), 1), &format!("wedge-h{size}"), dir)
}

/// One `cdem srm` of `scene` on `mesh`, timed.
fn measure(
    case: &'static str,
    resolution: f64,
    scene: &Scene,
    mesh: PathBuf,
    progress: &mut dyn FnMut(&str),
) -> Result<TrialScalingRow, Error> {
    let mut s = scene.clone();
    // The scene resolves its mesh against its own folder: give it the
    // mesh's absolute path (a path relative to the working directory would
    // be taken from the scene's folder).
    s.mesh.file = mesh.canonicalize().map_err(|e| Error::io(&mesh, e))?;
    s.output.vtk = false;
    progress(&format!("phase 2 and srm against size: {case} at {resolution}"));
    let t = Instant::now();
    let (r, model) = run_srm(&s, &mut |p| {
        if let SrmProgress::TrialStart(f) = p {
            progress(&format!("phase 2 and srm against size: {case} at {resolution}, trial F = {f:.4}"));
        }
    })?;
    let srm_s = t.elapsed().as_secs_f64();
    let steps: Vec<usize> = r.trials.iter().map(|t| t.steps).collect();
    let total: usize = steps.iter().sum();
    let wall: f64 = r.trials.iter().map(|t| t.wall_s).sum();
    let n = steps.len().max(1) as f64;
    Ok(TrialScalingRow {
        case,
        resolution,
        elements: model.elements.len(),
        trials: steps.len(),
        first_steps: steps.first().copied().unwrap_or(0),
        mean_steps: total as f64 / n,
        max_steps: steps.iter().copied().max().unwrap_or(0),
        srm_s,
        trial_s: wall / n,
        step_ms: 1e3 * wall / total.max(1) as f64,
        fs: r.fs,
        bracket_lo: r.bracket[0],
        bracket_hi: r.bracket[1],
    })
}

/// The study: the slab at each of `slab` (`refine`), the wedge at each of
/// `wedge` (mesh size), the meshes written to `dir` by gmsh (the slab's
/// committed mesh at refine 1).
pub fn trial_scaling(
    root: &Path,
    dir: &Path,
    slab: &[f64],
    wedge: &[f64],
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<TrialScalingRow>, Error> {
    let mut rows = Vec::new();
    let scene = super::srm_scene(root, crate::physics::joint::Softening::Brittle)?;
    for &r in slab {
        rows.push(measure("slab", r, &scene, slab_mesh(root, r, dir)?, progress)?);
    }
    let scene = Scene::load(&root.join(reg::WEDGE_SYMMETRIC.input))?;
    for &h in wedge {
        rows.push(measure("3D", h, &scene, wedge_mesh(root, h, dir)?, progress)?);
    }
    Ok(rows)
}

/// The exponents of one case's rows against the element count: steps per
/// trial (mean), wall time per trial, wall time per step (NaN with fewer
/// than two rows).
#[derive(Debug, Clone, Serialize)]
pub struct TrialExponents {
    pub case: &'static str,
    pub mean_steps: f64,
    pub trial_s: f64,
    pub step_ms: f64,
    pub srm_s: f64,
}

/// [`TrialExponents`] of each case in `rows`.
pub fn trial_exponents(rows: &[TrialScalingRow]) -> Vec<TrialExponents> {
    let mut out = Vec::new();
    for case in ["slab", "3D"] {
        let of: Vec<&TrialScalingRow> = rows.iter().filter(|r| r.case == case).collect();
        if of.is_empty() {
            continue;
        }
        let fit = |f: &dyn Fn(&TrialScalingRow) -> f64| {
            let (n, y): (Vec<f64>, Vec<f64>) = of.iter().map(|r| (r.elements as f64, f(r))).unzip();
            if n.len() >= 2 {
                fit_power(&n, &y).0
            } else {
                f64::NAN
            }
        };
        out.push(TrialExponents {
            case,
            mean_steps: fit(&|r| r.mean_steps),
            trial_s: fit(&|r| r.trial_s),
            step_ms: fit(&|r| r.step_ms),
            srm_s: fit(&|r| r.srm_s),
        });
    }
    out
}

/// The Markdown table and the exponents.
pub fn trial_markdown(rows: &[TrialScalingRow]) -> String {
    let mut md = String::from(
        "| case | resolution | elements | trials | steps, first trial | steps per trial (mean / max) | wall per trial | \
         wall per step | `cdem srm` | FS [bracket] |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let res = if r.case == "slab" { format!("refine {}", r.resolution) } else { format!("h = {} m", r.resolution) };
        let fs = match (r.fs, r.bracket_lo, r.bracket_hi) {
            (Some(fs), Some(lo), Some(hi)) => format!("{fs:.3} [{lo:.4}, {hi:.4}]"),
            (_, lo, hi) => format!("none [{lo:?}, {hi:?}]"),
        };
        md.push_str(&format!(
            "| {} | {res} | {} | {} | {} | {:.0} / {} | {:.2} s | {:.2} ms | {:.1} s | {fs} |\n",
            r.case, r.elements, r.trials, r.first_steps, r.mean_steps, r.max_steps, r.trial_s, r.step_ms, r.srm_s
        ));
    }
    md.push_str("\nFitted exponents p of cost ~ N^p (least squares on logarithms):\n\n");
    md.push_str("| case | steps per trial | wall per trial | wall per step | `cdem srm` |\n|---|---|---|---|---|\n");
    for e in trial_exponents(rows) {
        md.push_str(&format!(
            "| {} | {:.2} | {:.2} | {:.2} | {:.2} |\n",
            e.case, e.mean_steps, e.trial_s, e.step_ms, e.srm_s
        ));
    }
    md
}

#[cfg(test)]
mod tests {
    use super::TrialScalingRow;

    #[test]
    fn a_row_writes_as_csv() {
        // `cdem perf` writes trials.csv from these rows after the whole study:
        // a field csv cannot write (an array) would lose the study.
        let row = TrialScalingRow {
            case: "slab",
            resolution: 0.5,
            elements: 250,
            trials: 8,
            first_steps: 100,
            mean_steps: 200.0,
            max_steps: 300,
            srm_s: 1.0,
            trial_s: 0.1,
            step_ms: 0.5,
            fs: Some(0.8),
            bracket_lo: Some(0.79),
            bracket_hi: None,
        };
        let mut w = csv::Writer::from_writer(Vec::new());
        w.serialize(&row).unwrap();
        let text = String::from_utf8(w.into_inner().unwrap()).unwrap();
        assert!(text.starts_with("case,resolution,elements,"), "{text}");
        assert!(text.contains("0.79,\n"), "{text}");
    }
}
