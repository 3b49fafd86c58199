//! Cost against size: the paper slope's scene on its `.geo` at several
//! `refine` (1000 refine^2 hexahedra; the committed meshes, [`SLOPE_MESHES`],
//! or gmsh for a whole `refine`, [`slope_mesh`]), and per resolution the
//! build, a step, dynamic relaxation (with lumped masses too on the smaller
//! meshes; block masses up to a size), the elastic phase by PCG, and the FEM
//! solve ([`super::timing`]), with the peak memory of PCG and of the FEM
//! ([`super::memory`]); then the exponents `p` of
//! `cost ~ N^p` against the element count `N`, fitted by least squares on
//! logarithms ([`fit_power`]).

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Serialize;

use super::memory::with_peak;
use super::timing::{time_dr, time_fem, time_pcg, time_steps};
use crate::error::Error;
use crate::scene::Scene;
use crate::solver::SolverParams;

pub use crate::harness::registry::SLOPE_MESHES;

/// The paper slope's `.geo` at `refine`, meshed with gmsh into `dir`
/// (`slope-r<refine>.msh`); the existing file is reused.
pub fn slope_mesh(slope_geo: &Path, refine: u32, dir: &Path) -> Result<PathBuf, Error> {
    let include = slope_geo.canonicalize().map_err(|e| Error::io(slope_geo, e))?;
    let text = format!(
        "// The paper slope at refine = {refine} (cdem perf).\nrefine = {refine};\nInclude \"{}\";\n",
        include.display()
    );
    mesh_text(&text, &slope_mesh_name(refine), dir)
}

/// The name (no extension) of [`slope_mesh`]'s mesh at `refine`.
fn slope_mesh_name(refine: u32) -> String {
    format!("slope-r{refine}")
}

/// Whether [`scaling_meshes`] would run gmsh for `refine` with `dir`: no
/// committed mesh of [`SLOPE_MESHES`], and a whole `refine` from 1 up not
/// meshed into `dir` yet (any other `refine` is its error, not gmsh's).
pub fn needs_gmsh(refine: f64, dir: &Path) -> bool {
    let committed = SLOPE_MESHES.iter().any(|(c, _)| *c == refine);
    let whole = refine.fract() == 0.0 && refine >= 1.0;
    !committed && whole && !dir.join(format!("{}.msh", slope_mesh_name(refine as u32))).is_file()
}

/// Meshes `text` (a `.geo`) with gmsh as `dir/name.msh`, reusing the file.
pub fn mesh_text(text: &str, name: &str, dir: &Path) -> Result<PathBuf, Error> {
    let msh = dir.join(format!("{name}.msh"));
    if msh.is_file() {
        return Ok(msh);
    }
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let geo = dir.join(format!("{name}.geo"));
    std::fs::write(&geo, text).map_err(|e| Error::io(&geo, e))?;
    crate::mesh::gmsh::regenerate(&geo, &msh)?;
    Ok(msh)
}

/// The meshes of the study, `(refine, canonical path)`: a committed mesh of
/// [`SLOPE_MESHES`] under `root`, else for a whole `refine` from 1 up the
/// [`slope_mesh`] in `dir`; any other `refine` is an error.
pub fn scaling_meshes(
    root: &Path,
    refine: &[f64],
    dir: &Path,
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<(f64, PathBuf)>, Error> {
    let mut meshes = Vec::new();
    for &r in refine {
        let committed = SLOPE_MESHES.iter().find(|(c, _)| *c == r).map(|(_, p)| root.join(p));
        let mesh = match committed {
            Some(p) => p,
            None if r.fract() == 0.0 && r >= 1.0 => {
                progress(&format!("gmsh: slope at refine {r}"));
                slope_mesh(
                    &root.join(Path::new(crate::harness::registry::SLOPE.input).with_extension("geo")),
                    r as u32,
                    dir,
                )?
            }
            None => {
                return Err(Error::Gmsh(format!(
                    "refine {r}: only the committed 0.5, 1, 2, 4 or a whole number can be meshed"
                )))
            }
        };
        meshes.push((r, mesh.canonicalize().map_err(|e| Error::io(&mesh, e))?));
    }
    Ok(meshes)
}

/// One resolution of the scaling study.
#[derive(Debug, Clone, Serialize)]
pub struct ScalingRow {
    /// The `.geo`'s `refine` (elements = 1000 refine^2 for the paper slope).
    pub refine: f64,
    pub elements: usize,
    pub node_copies: usize,
    pub springs: usize,
    pub build_s: f64,
    /// Per step, with the scene's solver (block masses).
    pub step_s: f64,
    pub mega_element_steps_per_s: f64,
    pub gbs: f64,
    /// DR with block masses, measured only up to `dr_up_to` elements.
    pub dr_steps: Option<usize>,
    pub dr_converged: Option<bool>,
    pub dr_s: Option<f64>,
    /// DR steps with lumped masses, measured only up to `lumped_up_to` elements.
    pub lumped_steps: Option<usize>,
    /// The elastic phase by PCG (setup included, model built).
    pub pcg_iterations: usize,
    pub pcg_converged: bool,
    pub pcg_setup_s: f64,
    pub pcg_s: f64,
    pub pcg_coarse_dofs: usize,
    /// Peak resident memory while PCG ran (the built model included), MB.
    pub pcg_peak_mb: Option<f64>,
    pub fem_s: f64,
    pub fem_dofs: usize,
    /// Peak resident memory of the FEM solve (end to end), MB.
    pub fem_peak_mb: Option<f64>,
}

/// Cost against size on `scene` with the meshes given as `(refine, mesh)`.
pub fn scaling_study(
    scene: &Scene,
    meshes: &[(f64, PathBuf)],
    lumped_up_to: usize,
    dr_up_to: usize,
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<ScalingRow>, Error> {
    let mut rows = Vec::new();
    for (refine, mesh) in meshes {
        let mut s = scene.clone();
        s.mesh.file = mesh.clone();
        progress(&format!("scaling: refine {refine}: build"));
        let t = Instant::now();
        let model = crate::drivers::build_model(&s)?;
        let build_s = t.elapsed().as_secs_f64();
        let n = model.elements.len();
        progress(&format!("scaling: {n} elements: steps"));
        let steps = (2_000_000 / n.max(1)).clamp(20, 500);
        let step = time_steps(&model, &s.solver, steps)?;
        let dr = match n <= dr_up_to {
            true => {
                progress(&format!("scaling: {n} elements: DR ({:.1} ms per step)", 1e3 * step.step_s));
                Some(time_dr(&model, &s.solver)?)
            }
            false => None,
        };
        let lumped_steps = if n <= lumped_up_to {
            progress(&format!("scaling: {n} elements: DR with lumped masses"));
            Some(time_dr(&model, &SolverParams { block_mass: Some(false), ..s.solver.clone() })?.steps)
        } else {
            None
        };
        progress(&format!("scaling: {n} elements: PCG"));
        let (pcg, pcg_peak_mb) = with_peak(|| time_pcg(&model, &s.solver));
        let pcg = pcg?;
        let (node_copies, springs) = (model.n_nodes(), model.springs.len());
        drop(model); // the FEM solve of the largest meshes needs the memory
        progress(&format!("scaling: {n} elements: FEM"));
        let (fem, fem_peak_mb) = with_peak(|| time_fem(&s, 1));
        let (fem_s, fem_dofs) = fem?;
        rows.push(ScalingRow {
            refine: *refine,
            elements: n,
            node_copies,
            springs,
            build_s,
            step_s: step.step_s,
            mega_element_steps_per_s: step.mega_element_steps_per_s,
            gbs: step.gbs,
            dr_steps: dr.as_ref().map(|d| d.steps),
            dr_converged: dr.as_ref().map(|d| d.converged),
            dr_s: dr.as_ref().map(|d| d.seconds),
            lumped_steps,
            pcg_iterations: pcg.iterations,
            pcg_converged: pcg.converged,
            pcg_setup_s: pcg.setup_s,
            pcg_s: pcg.seconds,
            pcg_coarse_dofs: pcg.coarse_dofs,
            pcg_peak_mb,
            fem_s,
            fem_dofs,
            fem_peak_mb,
        });
    }
    Ok(rows)
}

/// The fitted exponents of the scaling study against the element count
/// (NaN where fewer than two rows have the figure).
#[derive(Debug, Clone, Serialize)]
pub struct Exponents {
    pub step_s: f64,
    pub dr_steps: f64,
    pub dr_s: f64,
    pub pcg_iterations: f64,
    pub pcg_s: f64,
    pub fem_s: f64,
}

/// The exponents of time per step, DR steps and time, PCG iterations and
/// time and FEM time against the element count ([`fit_power`], on the rows
/// that have the figure).
pub fn exponents(rows: &[ScalingRow]) -> Exponents {
    let fit = |f: &dyn Fn(&ScalingRow) -> Option<f64>| {
        let (n, y): (Vec<f64>, Vec<f64>) = rows.iter().filter_map(|r| f(r).map(|y| (r.elements as f64, y))).unzip();
        if n.len() >= 2 {
            fit_power(&n, &y).0
        } else {
            f64::NAN
        }
    };
    Exponents {
        step_s: fit(&|r| Some(r.step_s)),
        dr_steps: fit(&|r| r.dr_steps.map(|s| s as f64)),
        dr_s: fit(&|r| r.dr_s),
        pcg_iterations: fit(&|r| Some(r.pcg_iterations as f64)),
        pcg_s: fit(&|r| Some(r.pcg_s)),
        fem_s: fit(&|r| Some(r.fem_s)),
    }
}

/// Least-squares fit of `y = a x^p` on logarithms: `(p, a)`.
pub fn fit_power(x: &[f64], y: &[f64]) -> (f64, f64) {
    let n = x.len().min(y.len()) as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = x.iter().zip(y).map(|(x, y)| (x.ln(), y.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
    let p = sxy / sxx;
    (p, (my - p * mx).exp())
}
