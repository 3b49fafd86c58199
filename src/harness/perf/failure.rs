//! Phase 2 and strength reduction on the paper's slip-surface slope
//! ([`registry::SLOPE_SLIP`]), timed in the run that measures the other
//! figures (issue 13, item 5):
//!
//! - [`phase2_figure`]: phase 2 to a decision with node-block masses (the
//!   default) and with lumped masses, each from the scene's elastic state, as
//!   `cdem run` runs it (the scene's `[failure]`: 0.5 m bound, 200,000-step
//!   cap); steps are deterministic, the times are reported;
//! - [`srm_figure`]: `cdem srm` on the scene the strength-reduction figures of
//!   references/srm.md were measured on: the slip-surface scene without its
//!   `[failure]` `max_steps` and `sliding_displacement` (default budget
//!   10 `N_r` per trial), brittle (the paper's) or ductile joints on the
//!   circle ([`SRM_VARIANTS`]); its wall time and the steps per trial.
//!
//! The goals and the baseline are in the registry ([`registry::GOAL_PHASE2_STEPS`],
//! [`registry::PHASE2_STEPS_BASELINE`], [`registry::GOAL_SRM_SECONDS`],
//! [`registry::THREEDEC_TRIAL_STEP_CAP`]).

use std::path::Path;
use std::time::Instant;

use serde::Serialize;

use crate::drivers::srm::{run_srm_with, Reduction, SrmProgress, TrialStart};
use crate::drivers::Watch;
use crate::error::Error;
use crate::harness::registry;
use crate::model::spec::Softening;
use crate::scene::Scene;
use crate::solver::Foresight;
use crate::summary::EndState;

/// What `cdem perf` measures on the slip-surface slope: phase 2 with both
/// masses, and the strength reductions (none with `--no-srm`).
#[derive(Debug, Clone, Serialize)]
pub struct FailureFigures {
    pub phase2: Phase2Figure,
    /// Every variant with its trials warm-started (the default).
    pub srm: Vec<SrmFigure>,
    /// The same variants with every trial from the elastic state, run just
    /// before each warm-started one (side by side).
    pub srm_elastic: Vec<SrmFigure>,
    /// The plastic-block strength reductions ([`PLASTIC_SRM_VARIANTS`]) as
    /// `cdem srm` runs them.
    pub plastic: Vec<SrmFigure>,
    /// The same without the trials' foresight rule, run just before each.
    pub plastic_plain: Vec<SrmFigure>,
    /// `cdem srm --mesh-check` on Griffiths & Lane's hexahedra (issue 61:
    /// its cost against the plain reduction's, [`mesh_check_figure`]).
    pub mesh_check: Option<MeshCheckFigure>,
}

/// `cdem srm --mesh-check` (its default refinement,
/// [`crate::drivers::mesh_check::DEFAULT_REFINE`]) on Griffiths & Lane's
/// committed hexahedra, timed in the run that times the plain reduction.
#[derive(Debug, Clone, Serialize)]
pub struct MeshCheckFigure {
    /// The whole check: both meshes' reductions and the meshing (s).
    pub seconds: f64,
    /// The check's own line ("FS ... on this mesh; about ... converged ...").
    pub line: String,
    /// The check over its own reduction on the committed mesh (bracket 0.0025).
    pub over_own: f64,
    /// Why the check failed (gmsh missing, ...), if it did.
    pub error: Option<String>,
}

/// Times `cdem srm --mesh-check` on [`registry::PLASTIC_GL1_HEX`] under
/// `root`, its meshes in a temporary folder; a failure is kept as
/// [`MeshCheckFigure::error`] (the row then carries a defect).
pub fn mesh_check_figure(root: &Path, progress: &mut dyn FnMut(&str)) -> MeshCheckFigure {
    let dir = std::env::temp_dir().join(format!("cdem-perf-mesh-check-{}", std::process::id()));
    let t = Instant::now();
    let run = Scene::load(&root.join(registry::PLASTIC_GL1_HEX.input)).and_then(|scene| {
        crate::drivers::mesh_check::mesh_check(&scene, &crate::drivers::mesh_check::DEFAULT_REFINE, &dir, &mut |p| {
            if let crate::drivers::mesh_check::CheckProgress::Mesh(r) = p {
                progress(&format!("cdem srm --mesh-check, Griffiths & Lane's hexahedra, refine {r}"));
            }
        })
    });
    let seconds = t.elapsed().as_secs_f64();
    let _ = std::fs::remove_dir_all(&dir);
    match run.map(|(r, _)| r.discretisation) {
        Ok(Some(d)) => MeshCheckFigure { seconds, line: d.line, over_own: d.cost_ratio, error: None },
        Ok(None) => MeshCheckFigure {
            seconds,
            line: String::new(),
            over_own: f64::NAN,
            error: Some("no discretisation section".into()),
        },
        Err(e) => MeshCheckFigure { seconds, line: String::new(), over_own: f64::NAN, error: Some(e.to_string()) },
    }
}

/// [`phase2_figure`], and with `srm` every [`srm_figure`] of [`SRM_VARIANTS`]
/// and every [`plastic_srm_figure`] of [`PLASTIC_SRM_VARIANTS`].
pub fn failure_figures(root: &Path, srm: bool, progress: &mut dyn FnMut(&str)) -> Result<FailureFigures, Error> {
    let phase2 = phase2_figure(root, progress)?;
    let (mut warm, mut elastic) = (Vec::new(), Vec::new());
    for &(v, s) in SRM_VARIANTS.iter().filter(|_| srm) {
        elastic.push(srm_figure(root, v, s, TrialStart::Elastic, progress)?);
        warm.push(srm_figure(root, v, s, TrialStart::Warm, progress)?);
    }
    let (mut plastic, mut plain) = (Vec::new(), Vec::new());
    for &(v, case) in PLASTIC_SRM_VARIANTS.iter().filter(|_| srm) {
        plain.push(plastic_srm_figure(root, v, case, false, progress)?);
        plastic.push(plastic_srm_figure(root, v, case, true, progress)?);
    }
    let mesh_check = srm.then(|| mesh_check_figure(root, progress));
    Ok(FailureFigures { phase2, srm: warm, srm_elastic: elastic, plastic, plastic_plain: plain, mesh_check })
}

/// The plastic-block strength reductions timed beside the slip-surface
/// slope's (issue 24 item 7: a homogeneous slope of a few hundred elements;
/// issue 28 item 1: the 1000-element paper slope): `(variant, case)`.
pub const PLASTIC_SRM_VARIANTS: [(&str, &registry::Case); 2] =
    [("plastic-gl1-hex", &registry::PLASTIC_GL1_HEX), ("plastic-paper-slope", &registry::PLASTIC_PAPER_SLOPE)];

/// Phase 2 of the slip-surface slope with one kind of mass.
#[derive(Debug, Clone, Serialize)]
pub struct Phase2Run {
    pub block_mass: bool,
    pub end: EndState,
    pub steps: usize,
    /// Largest displacement since the elastic state (m).
    pub max_displacement: f64,
    pub failed_springs: usize,
    /// Phase 2 alone (its solver's setup and the steps), the elastic state given (s).
    pub seconds: f64,
}

impl Phase2Run {
    /// Phase 2 ended in a decision (Equilibrium or GlobalSliding), not the step cap.
    pub fn decided(&self) -> bool {
        self.end != EndState::Undecided
    }
}

/// Phase 2 of the slip-surface slope with node-block and with lumped masses.
#[derive(Debug, Clone, Serialize)]
pub struct Phase2Figure {
    /// Steps of the elastic phase both start from.
    pub elastic_steps: usize,
    pub block: Phase2Run,
    pub lumped: Phase2Run,
}

impl Phase2Figure {
    /// Lumped-mass steps over node-block-mass steps.
    pub fn lumped_over_block(&self) -> f64 {
        self.lumped.steps as f64 / self.block.steps as f64
    }
}

struct Quiet;
impl Watch for Quiet {}

/// The slip-surface scene under `root` with phase 2 on node-block masses or
/// lumped ones (`[failure] block_mass`), its elastic phase solved: phase 2 is
/// then `reduction.trial(1.0, ..)` (a factor of 1 leaves every strength as it
/// is), as `cdem run` runs it after its PCG elastic phase (the bench
/// `benches/phase2.rs` times that).
pub fn slip_surface_reduction(root: &Path, block_mass: bool) -> Result<(Reduction, usize), Error> {
    let mut scene = Scene::load(&root.join(registry::SLOPE_SLIP.input))?;
    scene.failure.get_or_insert_with(Default::default).block_mass = block_mass;
    Reduction::new(&scene, TrialStart::Elastic)
}

/// Runs phase 2 of the slip-surface slope under `root` with node-block masses
/// and with lumped masses, each from the elastic state.
pub fn phase2_figure(root: &Path, progress: &mut dyn FnMut(&str)) -> Result<Phase2Figure, Error> {
    let mut run = |block_mass: bool| -> Result<(Phase2Run, usize), Error> {
        let masses = if block_mass { "node-block" } else { "lumped" };
        progress(&format!("slip-surface slope: phase 2, {masses} masses"));
        let (mut red, elastic_steps) = slip_surface_reduction(root, block_mass)?;
        let t = Instant::now();
        let trial = red.trial(1.0, &mut Quiet)?.trial;
        let seconds = t.elapsed().as_secs_f64();
        let run = Phase2Run {
            block_mass,
            end: trial.outcome,
            steps: trial.steps,
            max_displacement: trial.max_displacement,
            failed_springs: trial.failed_springs,
            seconds,
        };
        Ok((run, elastic_steps))
    };
    let (block, elastic_steps) = run(true)?;
    let (lumped, _) = run(false)?;
    Ok(Phase2Figure { elastic_steps, block, lumped })
}

/// The softening of the slip circle's joints in the timed strength
/// reductions: brittle (the paper's, the scene's own) and ductile
/// (references/srm.md, the slowest of its rows).
pub const SRM_VARIANTS: [(&str, Softening); 2] = [("brittle", Softening::Brittle), ("ductile", Softening::Ductile)];

/// The strength-reduction scene of references/srm.md: the slip-surface scene
/// under `root` without its `[failure]` `max_steps` and
/// `sliding_displacement`, every breakable interface with `softening`.
pub fn srm_scene(root: &Path, softening: Softening) -> Result<Scene, Error> {
    let mut scene = Scene::load(&root.join(registry::SLOPE_SLIP.input))?;
    let failure = scene.failure.get_or_insert_with(Default::default);
    failure.max_steps = None;
    failure.sliding_displacement = None;
    for strength in scene.interface.iter_mut().filter_map(|i| i.strength.as_mut()) {
        *strength.softening_mut() = softening;
    }
    if let Some(s) = scene.joints.strength.as_mut() {
        *s.softening_mut() = softening;
    }
    Ok(scene)
}

/// One timed `cdem srm`.
#[derive(Debug, Clone, Serialize)]
pub struct SrmFigure {
    /// "brittle" or "ductile" ([`SRM_VARIANTS`]), or a plastic variant
    /// ([`PLASTIC_SRM_VARIANTS`]).
    pub variant: String,
    /// The scene, for the table.
    pub case: String,
    /// Where its trials started.
    pub start: TrialStart,
    /// Whether the trials' foresight rule was on (`cdem srm`'s default).
    pub foresight: bool,
    pub fs: Option<f64>,
    /// `[lo, hi]` of the search.
    pub bracket_lo: Option<f64>,
    pub bracket_hi: Option<f64>,
    pub trials: usize,
    /// Mean and largest phase-2 steps of a trial.
    pub mean_trial_steps: f64,
    pub max_trial_steps: usize,
    /// Trials that ran to their step budget (Undecided, counted unstable).
    pub undecided: usize,
    /// The step budget of each trial (10 `N_r`).
    pub trial_budget: usize,
    /// The whole strength reduction: model, elastic phase, every trial (s).
    pub seconds: f64,
    /// The phase-2 plan, built once for all trials (s); before it was
    /// shared, every trial built its own, at this cost each.
    pub plan_setup_s: f64,
    /// Mean setup of a trial now: state copy, reduced strengths (s).
    pub mean_trial_setup_s: f64,
    /// Mean wall time of a trial (s).
    pub mean_trial_s: f64,
}

/// Runs `cdem srm`'s strength reduction on [`srm_scene`] (no files written),
/// its trials started from `start`.
pub fn srm_figure(
    root: &Path,
    variant: &str,
    softening: Softening,
    start: TrialStart,
    progress: &mut dyn FnMut(&str),
) -> Result<SrmFigure, Error> {
    let scene = srm_scene(root, softening)?;
    time_srm(&scene, "slip-surface slope", variant, start, true, progress)
}

/// Runs `cdem srm`'s strength reduction of the plastic case `case` under
/// `root` (no files written), with or without the trials' foresight rule.
pub fn plastic_srm_figure(
    root: &Path,
    variant: &str,
    case: &registry::Case,
    foresight: bool,
    progress: &mut dyn FnMut(&str),
) -> Result<SrmFigure, Error> {
    let scene = Scene::load(&root.join(case.input))?;
    time_srm(&scene, case.name, variant, TrialStart::Warm, foresight, progress)
}

/// One timed strength reduction of `scene`.
fn time_srm(
    scene: &Scene,
    case: &str,
    variant: &str,
    start: TrialStart,
    foresight: bool,
    progress: &mut dyn FnMut(&str),
) -> Result<SrmFigure, Error> {
    let rule = foresight.then_some(Foresight::TRIALS);
    let what = format!("cdem srm, {variant}, {start:?} start, foresight {}", if foresight { "on" } else { "off" });
    progress(&what);
    let (r, _) = run_srm_with(scene, start, rule, &mut |p| {
        if let SrmProgress::TrialStart(f) = p {
            progress(&format!("{what}, trial F = {f:.4}"));
        }
    })?;
    let steps: Vec<usize> = r.trials.iter().map(|t| t.steps).collect();
    Ok(SrmFigure {
        variant: variant.to_string(),
        case: case.to_string(),
        start,
        foresight,
        fs: r.fs,
        bracket_lo: r.bracket[0],
        bracket_hi: r.bracket[1],
        trials: r.trials.len(),
        mean_trial_steps: steps.iter().sum::<usize>() as f64 / steps.len().max(1) as f64,
        max_trial_steps: steps.iter().copied().max().unwrap_or(0),
        undecided: r.undecided,
        trial_budget: r.trial_budget,
        seconds: r.wall_s,
        plan_setup_s: r.plan_setup_s,
        mean_trial_setup_s: r.trials.iter().map(|t| t.setup_s).sum::<f64>() / steps.len().max(1) as f64,
        mean_trial_s: r.trials.iter().map(|t| t.wall_s).sum::<f64>() / steps.len().max(1) as f64,
    })
}
