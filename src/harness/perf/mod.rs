//! Performance figures (issue: performance), measured in-process so that one
//! run puts every ratio side by side: the criterion benches measure the same
//! things more carefully; this module gives them to the validation report
//! (`tests/performance.rs`) and to `cdem perf` ([`run_perf`]), which adds the
//! strength reductions of the slip-surface slope, timed ensembles of it, the
//! damping table and the growth with size (references/performance.md).
//!
//! One file per concern:
//! - [`stream`]: the machine's memory bandwidth (STREAM triad);
//! - [`bytes`]: the bytes one step must move (counted as in
//!   references/performance.md), so `bytes / step time` is the step's
//!   effective bandwidth;
//! - [`timing`]: a step, dynamic relaxation to the scene's tolerance, PCG
//!   to the same tolerance, the implicit FEM solve of the same mesh;
//! - [`memory`]: peak resident memory of a stage (Linux);
//! - [`pyslope`]: the LEM grid search against pySlope, timed in the same run
//!   or from its recorded time;
//! - [`headline`](mod@headline): the four figures on the paper slope;
//! - [`failure`]: phase 2 to a decision (node-block against lumped masses),
//!   `cdem srm` on the slip-surface slope, and the plastic-block `cdem srm` of
//!   Griffiths & Lane and the paper slope with and without the foresight rule;
//! - [`ensemble`](mod@ensemble): members per hour of ensembles of the
//!   slip-surface slope (with and without strength reduction) and the
//!   speed-up of two shard processes;
//! - [`damping`]: damping kind x mass scaling x block masses on one scene;
//! - [`scaling`]: cost against size, fitted exponents;
//! - [`trials`]: phase 2 and strength reduction against size (a slab and a
//!   3D wedge), fitted exponents;
//! - [`tables`]: the Markdown tables, the CSV files and the figure.
//!
//! The items are also re-exported here (`perf::step_bytes`, ...).
//!
//! Times are wall-clock on whatever else the machine is doing: they are
//! reported, never asserted.

use std::path::Path;

use crate::error::Error;

pub mod bytes;
pub mod checkpoint;
pub mod damping;
pub mod ensemble;
pub mod failure;
pub mod headline;
pub mod laws;
pub mod memory;
pub mod pyslope;
pub mod rows;
pub mod scaling;
pub mod stream;
pub mod tables;
pub mod timing;
pub mod trials;

pub use bytes::step_bytes;
pub use damping::{damping_table, DampingRow};
pub use ensemble::{ensemble_figures, members_figure, shards_figure, EnsembleFigures, MembersFigure, ShardsFigure};
pub use failure::{
    failure_figures, phase2_figure, srm_figure, srm_scene, FailureFigures, Phase2Figure, Phase2Run, SrmFigure,
    SRM_VARIANTS,
};
pub use headline::{headline, headline_with, paper_slope, Headline};
pub use pyslope::{pyslope_grid_search, pyslope_seconds, time_lem_grid, time_pyslope_grid, LEM_CASES};
pub use scaling::{
    exponents, fit_power, scaling_meshes, scaling_study, slope_mesh, Exponents, ScalingRow, SLOPE_MESHES,
};
pub use stream::{triad, triad_par, Triad};
pub use tables::{damping_markdown, scaling_markdown, write_report};
pub use timing::{time_dr, time_fem, time_pcg, time_steps, DrFigure, PcgFigure, StepFigure};

/// What `cdem perf` runs.
#[derive(Debug, Clone)]
pub struct PerfOptions {
    /// Run the damping table (about 3 minutes: local damping is slow).
    pub damping: bool,
    /// Run `cdem srm` on the slip-surface slope, brittle and ductile
    /// ([`failure::SRM_VARIANTS`]; about 15 s and 90 s), and the plastic
    /// blocks' ([`failure::PLASTIC_SRM_VARIANTS`], with and without the
    /// foresight rule: about 1 + 3 min and 4 + 4 min). Phase 2 to a decision
    /// (a few seconds) always runs.
    pub srm: bool,
    /// The `cdem` binary that runs the ensemble's shard processes (`cdem
    /// perf` passes its own): with it, the timed ensembles of the
    /// slip-surface slope ([`ensemble::ensemble_figures`], about 2 minutes;
    /// their own strength reductions too, whatever `srm` says); None skips them.
    pub ensemble: Option<std::path::PathBuf>,
    /// Resolutions of the scaling study (`refine` of slope.geo); those
    /// without a committed mesh need gmsh on PATH.
    pub refine: Vec<f64>,
    /// Lumped-mass DR is also run up to this many elements.
    pub lumped_up_to: usize,
    /// DR (block masses) is run up to this many elements (at 1e5 it takes
    /// about 16 minutes); PCG and the FEM at every size.
    pub dr_up_to: usize,
    /// A Python interpreter with pySlope (scripts/requirements-lem.txt):
    /// pySlope is then timed in the same run; without it the ratio uses
    /// its recorded time.
    pub pyslope: Option<std::path::PathBuf>,
    /// Phase 2 and strength reduction against size ([`trials`]; about
    /// 15 minutes, gmsh on PATH).
    pub trials: bool,
}

impl Default for PerfOptions {
    fn default() -> Self {
        Self {
            damping: true,
            srm: true,
            ensemble: None,
            refine: vec![0.5, 1.0, 2.0, 4.0, 7.0, 10.0],
            lumped_up_to: 4000,
            dr_up_to: usize::MAX,
            pyslope: None,
            trials: true,
        }
    }
}

/// Step cap of each run of the damping table (local damping with mass
/// scaling takes about 274,000 on the paper slope).
const DAMPING_MAX_STEPS: usize = 400_000;

/// Fails at once, not after the headline's minutes, if the run will need
/// gmsh and it does not run from PATH: a scaling resolution without a
/// committed mesh or one already in `meshes`, or the trials against size.
fn gmsh_preflight(opts: &PerfOptions, meshes: &Path) -> Result<(), Error> {
    let refine = opts.refine.iter().filter(|&&r| scaling::needs_gmsh(r, meshes)).map(|r| format!("refine {r}"));
    let trials = opts.trials.then(|| "the trials against size".to_string());
    let needs: Vec<String> = refine.chain(trials).collect();
    if needs.is_empty() || crate::mesh::gmsh::gmsh_available() {
        return Ok(());
    }
    Err(Error::Gmsh(format!(
        "gmsh does not run from PATH, and the run needs it ({}): install it (`pip install gmsh==4.15.0`, as \
         .ci/run does) or leave those out (`--refine 0.5,1,2,4`, `--no-trial-scaling`)",
        needs.join(", ")
    )))
}

/// `cdem perf`: headline figures, phase 2 and strength reduction on the
/// slip-surface slope, timed ensembles of it, damping table, scaling study
/// and phase 2 and strength reduction against size ([`trials`], `trials.csv`,
/// appended to `perf.md`); writes `perf.md` (with the validation rows `perf/*` of the run),
/// `phase2.csv`, `srm.csv`, `ensemble.csv`, `damping.csv`, `scaling.csv` and
/// `scaling.png` to `out` (gmsh meshes in `out/meshes`, the ensemble
/// processes' output in `out/ensemble`) and returns `perf.md`.
pub fn run_perf(root: &Path, out: &Path, opts: &PerfOptions, progress: &mut dyn FnMut(&str)) -> Result<String, Error> {
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    gmsh_preflight(opts, &out.join("meshes"))?;
    let (scene, model) = paper_slope(root)?;
    let head = headline_with(root, &scene, &model, opts.pyslope.as_deref(), progress)?;
    let failure = failure_figures(root, opts.srm, progress)?;
    let ensemble = match &opts.ensemble {
        Some(exe) => Some(ensemble_figures(exe, root, &out.join("ensemble"), progress)?),
        None => None,
    };
    let damping =
        if opts.damping { damping_table(&model, &scene.solver, DAMPING_MAX_STEPS, progress) } else { Vec::new() };
    let meshes = scaling_meshes(root, &opts.refine, &out.join("meshes"), progress)?;
    let scaling = scaling_study(&scene, &meshes, opts.lumped_up_to, opts.dr_up_to, progress)?;
    let trials = match opts.trials {
        true => {
            let (slab, wedge) = (trials::SLAB_REFINE, trials::WEDGE_SIZES);
            trials::trial_scaling(root, &out.join("meshes"), &slab, &wedge, progress)?
        }
        false => Vec::new(),
    };
    progress("joint-law cost");
    let law_row = laws::spring_law_row(&laws::spring_law_cost(root, 10)?);
    progress("checkpoint cost");
    let ck = checkpoint::checkpoint_cost(root, &out.join("checkpoint"), 5)?;
    let mut md = write_report(out, &head, &failure, ensemble.as_ref(), &damping, &scaling)?;
    let row = checkpoint::checkpoint_row(&ck);
    md.push_str(&format!(
        "\n## Checkpoint cost\n\n`{}`: {:.2e} of the wall time at the default interval (goal <= {}; {:?}): {}\n",
        row.id,
        row.ours,
        row.reference,
        row.status(),
        row.note
    ));
    md.push_str(&format!(
        "\n## Joint-law cost\n\n`{}`: {:.3} (goal <= {}; {:?}): {}\n",
        law_row.id,
        law_row.ours,
        law_row.reference,
        law_row.status(),
        law_row.note
    ));
    crate::output::write_atomic(&out.join("perf.md"), md.as_bytes())?;
    if !trials.is_empty() {
        tables::write_csv(&out.join("trials.csv"), &trials)?;
        md.push_str("\n## Phase 2 and strength reduction against size (trials.csv)\n\n");
        md.push_str(&trials::trial_markdown(&trials));
        crate::output::write_atomic(&out.join("perf.md"), md.as_bytes())?;
    }
    Ok(md)
}
