//! The application layer (feature `plot`): one function per product command
//! (`cdem run`, `srm`, `fem`, `lem`, `ensemble`) that loads the input, calls
//! the drivers, writes the files through [`crate::output`] (figures
//! included) and returns what the command line prints. The command line
//! (`src/bin/cdem.rs`) keeps the argument parsing, the progress bars and the
//! printing; the verification harness sits above this layer.

pub mod ensemble;
pub mod kinematics;

use std::path::{Path, PathBuf};

use crate::drivers::checkpoint::Checkpointing;
use crate::drivers::{FemRun, RunResult, SrmProgress, SrmResult};
use crate::lem::LemResult;
use crate::output::figures;
use crate::scene::Scene;

/// What `cdem run` reports while it runs.
pub enum RunProgress {
    /// The scene is loaded: the step budget of phase 1 and phase 2 as the
    /// scene gives them (0 where the solver chooses).
    Loaded { budget: usize },
    /// A step and its unbalanced-force ratio.
    Step { step: usize, ratio: f64 },
}

/// `cdem run SCENE --out DIR`: phase 1 and, for a scene with `[failure]`,
/// phase 2; writes the run's files and, with `[analysis]`, `analysis.png`.
pub fn run(scene_path: &Path, out: &Path, progress: &mut dyn FnMut(RunProgress)) -> crate::Result<RunResult> {
    let scene = loaded(scene_path, progress)?;
    let result = crate::drivers::run_scene(&scene, &mut |step, ratio| progress(RunProgress::Step { step, ratio }))?;
    write_run(&scene, &result, out)?;
    Ok(result)
}

/// `cdem run SCENE --mesh-check [R,...] --out DIR`: [`run`]'s files, and
/// `DIR/mesh-check.json`: the elastic state's headline values (the end of
/// phase 1) on the meshes refined by each `R` (in `DIR/mesh-check/`) and
/// their extrapolation ([`crate::drivers::mesh_check::run_mesh_check`],
/// the same check as [`fem_mesh_check`]'s).
pub fn run_mesh_check(
    scene_path: &Path,
    refine: &[f64],
    out: &Path,
    progress: &mut dyn FnMut(RunProgress),
) -> crate::Result<(RunResult, crate::drivers::mesh_check::ElasticCheck)> {
    let scene = loaded(scene_path, progress)?;
    let (result, check) =
        crate::drivers::mesh_check::run_mesh_check(&scene, refine, &out.join("mesh-check"), &mut |step, ratio| {
            progress(RunProgress::Step { step, ratio })
        })?;
    write_run(&scene, &result, out)?;
    crate::output::write_json(&out.join("mesh-check.json"), &check)?;
    Ok((result, check))
}

/// The scene, its step budget reported.
fn loaded(scene_path: &Path, progress: &mut dyn FnMut(RunProgress)) -> crate::Result<Scene> {
    let scene = Scene::load(scene_path)?;
    let budget = scene.solver.max_steps.unwrap_or(0) + scene.failure.as_ref().map_or(0, |f| f.max_steps.unwrap_or(0));
    progress(RunProgress::Loaded { budget });
    Ok(scene)
}

/// The files of `cdem run`.
fn write_run(scene: &Scene, result: &RunResult, out: &Path) -> crate::Result<()> {
    crate::output::write_run(scene, result, out)?;
    if result.surface.is_some() {
        figures::analysis::run_png(result, &out.join("analysis.png"))?;
    }
    if let Some(r) = result.runout.as_ref().filter(|r| r.summary.ran) {
        figures::runout::runout_png(&result.model, r, &out.join("runout.png"))?;
    }
    Ok(())
}

/// `cdem srm SCENE --out DIR`: strength reduction; writes `srm.json`,
/// `mechanism.vtu`, `mechanism.png` and, with plastic blocks, `slip-band.png`.
///
/// With `ck` the search checkpoints into `ck.dir` and, with `ck.resume`,
/// goes on from the checkpoint there ([`crate::drivers::srm::run_srm_checkpointed`]);
/// the checkpoint is removed once every file is written.
pub fn srm(
    scene_path: &Path,
    out: &Path,
    ck: Option<&Checkpointing>,
    progress: &mut dyn FnMut(SrmProgress),
) -> crate::Result<SrmResult> {
    let scene = Scene::load(scene_path)?;
    // What a killed run was writing when it died (never read: every file
    // is moved into place whole).
    for dir in ck.iter().flat_map(|c| [Some(&c.dir), c.resume.as_ref()]).flatten() {
        crate::atomic::remove_stale_partials(dir);
    }
    let (result, model) = match ck {
        Some(ck) => crate::drivers::srm::run_srm_checkpointed(&scene, ck, progress)?,
        None => crate::drivers::run_srm(&scene, progress)?,
    };
    crate::output::write_srm(&result, &model, out)?;
    figures::mechanism::mechanism_png(&result, &model, &out.join("mechanism.png"))?;
    figures::mechanism::slip_band_png(&result, &model, &out.join("slip-band.png"))?;
    if let Some(ck) = ck {
        ck.remove();
    }
    Ok(result)
}

/// `cdem srm SCENE --mesh-check [R,...] --out DIR`: the reduction on the
/// scene's mesh and on meshes refined by each factor `R` (written into
/// `DIR/mesh-check/`), and the discretisation error of the factor
/// ([`crate::drivers::mesh_check`]); the files of [`srm`], `srm.json` with
/// its section `discretisation`.
pub fn srm_mesh_check(
    scene_path: &Path,
    refine: &[f64],
    out: &Path,
    progress: &mut dyn FnMut(crate::drivers::mesh_check::CheckProgress),
) -> crate::Result<SrmResult> {
    let scene = Scene::load(scene_path)?;
    let (result, model) = crate::drivers::mesh_check::mesh_check(&scene, refine, &out.join("mesh-check"), progress)?;
    crate::output::write_srm(&result, &model, out)?;
    figures::mechanism::mechanism_png(&result, &model, &out.join("mechanism.png"))?;
    figures::mechanism::slip_band_png(&result, &model, &out.join("slip-band.png"))?;
    Ok(result)
}

/// `cdem fem SCENE --out DIR`: the implicit FEM reference on the continuous
/// mesh; writes its files and, with `[analysis]`, `analysis.png`.
pub fn fem(scene_path: &Path, out: &Path) -> crate::Result<FemRun> {
    let scene = Scene::load(scene_path)?;
    let fem = crate::drivers::run_fem(&scene)?;
    crate::output::write_fem(&fem.solution, fem.surface.as_ref(), out)?;
    if fem.surface.is_some() {
        figures::analysis::fem_png(&fem, &out.join("analysis.png"))?;
    }
    Ok(fem)
}

/// `cdem fem SCENE --mesh-check [R,...] --out DIR`: [`fem`]'s files for the
/// scene's mesh, and `DIR/mesh-check.json`: its headline values on the
/// meshes refined by each `R` (in `DIR/mesh-check/`) and their
/// extrapolation ([`crate::drivers::mesh_check::fem_mesh_check`]).
pub fn fem_mesh_check(
    scene_path: &Path,
    refine: &[f64],
    out: &Path,
) -> crate::Result<(FemRun, crate::drivers::mesh_check::ElasticCheck)> {
    let scene = Scene::load(scene_path)?;
    let (fem, check) = crate::drivers::mesh_check::fem_mesh_check(&scene, refine, &out.join("mesh-check"))?;
    crate::output::write_fem(&fem.solution, fem.surface.as_ref(), out)?;
    if fem.surface.is_some() {
        figures::analysis::fem_png(&fem, &out.join("analysis.png"))?;
    }
    crate::output::write_json(&out.join("mesh-check.json"), &check)?;
    Ok((fem, check))
}

/// `cdem lem INPUT [--out FILE]`: the LEM of a LEM file or of a scene's
/// `[lem]`; writes the JSON (to `out`, or beside the input with extension
/// `.json`) and returns the result and the path written.
pub fn lem(input: &Path, out: Option<&Path>) -> crate::Result<(LemResult, PathBuf)> {
    let result = crate::lem::analyse(&crate::drivers::load_lem_input(input)?)?;
    let out = out.map(Path::to_path_buf).unwrap_or_else(|| input.with_extension("json"));
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| crate::Error::io(dir, e))?;
    }
    crate::output::write_json(&out, &result)?;
    Ok((result, out))
}
