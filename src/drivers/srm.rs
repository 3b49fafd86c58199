//! Strength reduction: the factor of safety of a scene (`cdem srm`), as
//! FLAC and 3DEC compute it after Dawson, Roth & Drescher (1999).
//!
//! The elastic state and the phase-2 plan (solver, masses, budget) are made
//! once (phase 1 of [`super::run`]; [`super::failure::phase_plan`]). For a
//! trial factor `F` every breakable spring gets `T / F`, `c / F` and
//! `tan(phi) / F` in its joint state ([`JointState::reduced`]; the model is
//! not touched), and phase 2 ([`super::failure`]) runs with the plan
//! restarted as new from the end state of the largest stable trial below `F`
//! ([`TrialStart::Warm`], the default; the elastic state if there is none,
//! or always with [`TrialStart::Elastic`]): `Equilibrium` is
//! stable, `GlobalSliding` unstable, and `Undecided` (the per-trial step
//! budget, by default the model's response time `N_r`, ran out) is counted
//! as unstable, as FLAC counts a trial that does not converge; with plastic
//! blocks, a trial whose ratio decays too slowly to reach the tolerance
//! within twice its budget is stopped as `Undecided` at once
//! ([`Foresight::TRIALS`], `Trial::foreseen`) rather than stepped to the
//! budget. Brittle
//! interfaces lose their (reduced) cohesion and tensile strength where they
//! fail, ductile ones keep them (scene key `softening`).
//!
//! Search: from `F = 1`, multiply (stable) or divide (unstable) by
//! [`BRACKET_RATIO`] until the outcome changes; then bisect the bracket
//! `[lo, hi]` (`lo` stable, `hi` unstable) to a width of at most
//! [`BRACKET_WIDTH`]. `fs` is the bracket's midpoint. The mechanism is the
//! displacement since the elastic state of the trial at the final `hi`;
//! with plastic blocks its slip band says how many elements it crosses, and
//! fewer than [`MIN_ELEMENTS_ALONG`] give the result a warning
//! ([`crate::analysis::slip_band`]; `cdem srm --mesh-check`,
//! [`super::mesh_check`], estimates the error).

use std::ops::ControlFlow;
use std::sync::atomic::{AtomicUsize, Ordering};

use serde::Serialize;

use super::checkpoint::{self, Checkpointing, Codec, Dec, Enc};
use super::failure::{self, phase_plan};
use super::phase::{failed_springs, NoWatch, Phase, Watch};
use super::run::run_watched;
use crate::analysis::slip_band::{slip_band, SlipBand, MIN_ELEMENTS_ALONG};
use crate::error::{CheckpointError, Error, SceneError};
use crate::model::Model;
use crate::physics::joint::JointState;
use crate::physics::plastic::CellPlastic;
use crate::scene::{FailureParams, Scene};
use crate::solver::{Foresight, PhasePlan, State, StepView, Stop};
use crate::summary::{max_displacement, EndState};

/// Bracket growth factor per trial before a bracket is found.
pub const BRACKET_RATIO: f64 = 1.25;
/// The bisection stops when `hi - lo` is at most this.
pub const BRACKET_WIDTH: f64 = 0.01;
/// The search gives up (no bracket) outside `[MIN_FACTOR, MAX_FACTOR]`.
pub const MIN_FACTOR: f64 = 0.05;
pub const MAX_FACTOR: f64 = 100.0;

/// The state a trial starts from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum TrialStart {
    /// The elastic state, for every trial.
    Elastic,
    /// The end state of the largest stable trial below the trial's factor
    /// (its displacements, velocities and spring histories; the strengths
    /// reduced by the new factor), else the elastic state. Its stable trials
    /// start near their equilibrium (references/srm.md, "Warm starts").
    Warm,
}

/// One trial factor and what phase 2 did with it.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Trial {
    pub factor: f64,
    pub outcome: EndState,
    /// An `Undecided` trial stopped before its budget because the ratio's
    /// decay foresaw it ([`crate::solver::Foresight`]).
    pub foreseen: bool,
    pub steps: usize,
    /// Largest displacement since the elastic state (m).
    pub max_displacement: f64,
    /// Springs that failed (either kind).
    pub failed_springs: usize,
    /// Volume of the plastic blocks' tetrahedra that have yielded at the
    /// trial's end, the state it started from included (m^3; 0 without
    /// plastic blocks).
    pub yielded_volume: f64,
    /// Of `yielded_volume`, the tetrahedra that yielded in tension at some
    /// step (m^3: the tension cracks).
    pub yielded_tension_volume: f64,
    /// The stable factor whose end state the trial started from (None: the
    /// elastic state).
    pub started_from: Option<f64>,
    /// The trial's own setup before its first step: the elastic state
    /// copied, its strengths reduced, the plan restarted (s).
    pub setup_s: f64,
    /// The whole trial, setup included (s).
    pub wall_s: f64,
    /// The trial was phase 2 of the same scene's run, taken over rather than
    /// run again ([`Phase2Run`]; its `setup_s` and `wall_s` are then 0).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub from_run: bool,
}

impl Trial {
    pub fn stable(&self) -> bool {
        self.outcome == EndState::Equilibrium
    }
}

/// One trial and what it leaves: the displacement since the elastic state
/// and, with plastic blocks, the state of every element.
pub struct TrialRun {
    pub trial: Trial,
    pub since: Vec<f64>,
    pub cells: Option<Vec<CellPlastic>>,
}

/// Phase 2 of a run of the scene a strength reduction searches
/// ([`super::run_scene`]). With the strengths as given, from the same
/// elastic state and under the same plan, it is the search's first trial,
/// at F = 1: an ensemble member that runs both (`analyses = ["cdem",
/// "srm"]`) need not run it twice. [`Reduction::adopt`] takes it only where
/// that holds: elastic blocks (plastic ones add the foresight rule to the
/// trials, not to phase 2), the same elastic state, bit for bit, and a
/// phase 2 that started with a new solver, as a trial does (after a DR
/// phase 1 it goes on with that solver's damping state); else the trial
/// runs.
#[derive(Clone, Copy)]
pub struct Phase2Run<'a> {
    pub failure: &'a failure::FailureResult,
    /// The state phase 2 ended in.
    pub state: &'a State,
}

/// What the strength reduction found (`srm.json`).
#[derive(Debug, Clone, Serialize)]
pub struct SrmResult {
    /// Midpoint of the final bracket; None without a bracket.
    pub fs: Option<f64>,
    /// `[lo, hi]`: the largest stable and the smallest unstable factor tried
    /// (either None if never found).
    pub bracket: [Option<f64>; 2],
    pub trials: Vec<Trial>,
    /// The outcome of the trial at `hi`: `Undecided` means the bracket's
    /// upper end is a trial that ran out of budget (counted unstable), not
    /// one that slid.
    pub hi_outcome: Option<EndState>,
    /// The smallest factor whose trial slid (`GlobalSliding`), if any did.
    pub sliding_from: Option<f64>,
    /// Trials that ran out of their budget (`Undecided`).
    pub undecided: usize,
    /// Steps of the elastic phase.
    pub elastic_steps: usize,
    /// Step budget of each trial.
    pub trial_budget: usize,
    /// Building the phase-2 plan (solver, masses, time step, budget), once
    /// for every trial (s): what each trial paid again before the plan was
    /// shared.
    pub plan_setup_s: f64,
    pub wall_s: f64,
    /// What was divided by `F`: one line per material and interface.
    pub reduced: Vec<String>,
    /// Which model answered (see [`Answer`]).
    pub model: Answer,
    /// The pore water, held fixed through the reduction (absent: dry).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub water: Option<crate::summary::WaterSummary>,
    /// The displacement since the elastic state at the final `hi` (the
    /// mechanism), 3 per node.
    #[serde(skip)]
    pub mechanism: Option<Vec<f64>>,
    /// The plastic blocks at the final `hi` (the slip band), per element.
    #[serde(skip)]
    pub mechanism_cells: Option<Vec<CellPlastic>>,
    /// The slip band at the final `hi` with plastic blocks: how many
    /// elements it crosses ([`crate::analysis::slip_band`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slip_band: Option<SlipBand>,
    /// The warning of a band that crosses fewer than
    /// [`crate::analysis::slip_band::MIN_ELEMENTS_ALONG`] elements.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub band_warning: Option<String>,
    /// The discretisation error (`cdem srm --mesh-check`,
    /// [`super::mesh_check`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub discretisation: Option<super::discretisation::Discretisation>,
}

/// The warning of a slip band that crosses fewer than
/// [`MIN_ELEMENTS_ALONG`] elements (None: enough).
pub fn band_warning(band: &SlipBand) -> Option<String> {
    (band.along < MIN_ELEMENTS_ALONG).then(|| {
        format!(
            "the slip band crosses {} elements (fewer than {MIN_ELEMENTS_ALONG}): the factor of safety is likely \
             unconservative on this mesh (references/srm.md, \"Discretisation error\"); `cdem srm --mesh-check` \
             estimates its error",
            band.along
        )
    })
}

/// Which model a factor of safety comes from, and what it answers.
#[derive(Debug, Clone, Serialize)]
pub struct Answer {
    /// `"plastic blocks"` (a Mohr-Coulomb rock mass, the failure finds its
    /// own way through the blocks and along the breakable interfaces),
    /// `"interfaces only"` (elastic blocks; failure only along breakable
    /// interfaces), or `"every interface, elastic blocks"` (elastic blocks
    /// that may part along any face: the interlocking bias applies).
    pub kind: &'static str,
    /// A warning the result carries, if any.
    pub note: Option<String>,
    /// Whether the trials' springs carried dashpots
    /// ([`crate::solver::has_dashpots`]; docs/method.md 2.9b).
    pub dashpots: bool,
}

/// The interlocking bias of elastic blocks that part only along their faces
/// when every element interface is breakable at the rock mass strength,
/// measured against published FE strength reduction and our LEM on
/// six published homogeneous slopes (references/srm.md, "Homogeneous
/// slopes: interfaces only against plastic blocks").
pub const INTERLOCKING_NOTE: &str = "every element interface is breakable while the blocks are elastic: the factor of \
     safety carries the interlocking bias of blocks that can part only along their faces, measured at +22 % to +73 % \
     (unconservative) on six published homogeneous slopes and mesh-dependent (+29 % hexahedra, +38 % prisms, +52 % \
     tetrahedra on Griffiths & Lane's slope; references/srm.md); for a rock mass whose failure must find its own \
     way, give the blocks a [[material]] strength";

/// Plastic prisms and tetrahedra average their strains over the cells at
/// each mesh vertex, across interfaces whether their springs hold or not
/// (docs/method.md 2.9b, "Stiff triangles"): with breakable interfaces they
/// also average across a crack once it opens.
pub const NODAL_ACROSS_CRACKS_NOTE: &str = "plastic prisms or tetrahedra with breakable interfaces: their \
     volumetric and smoothed deviatoric strains are averaged over the cells at each mesh vertex, across an interface \
     once it opens too (docs/method.md 2.9b); hexahedra average nothing across cells";

impl Answer {
    /// The answer of `model`'s strength reduction.
    pub fn of(model: &Model) -> Self {
        // The bias is that of the mesh's own faces, every one breakable;
        // real joints between real blocks carry none.
        let every = model.every_face_breakable();
        let dashpots = crate::solver::has_dashpots(model);
        match (model.has_plastic_blocks(), every) {
            (true, _) => {
                let breakable = model.joint_state().strength.iter().any(Option::is_some);
                let note = (breakable && model.plastic.any_nodal()).then(|| NODAL_ACROSS_CRACKS_NOTE.into());
                Answer { kind: "plastic blocks", note, dashpots }
            }
            (false, true) => {
                Answer { kind: "every interface, elastic blocks", note: Some(INTERLOCKING_NOTE.into()), dashpots }
            }
            (false, false) => Answer { kind: "interfaces only", note: None, dashpots },
        }
    }
}

/// What a strength reduction of `model` divides by `F`.
pub fn reduced_strengths(model: &Model) -> Vec<String> {
    let mut out = Vec::new();
    for (i, m) in model.materials.iter().enumerate() {
        if m.law.strength().is_some() {
            out.push(format!("material[{i}]: c, tan(phi), T; psi capped at the reduced phi"));
        }
    }
    for (i, f) in model.interfaces.iter().enumerate() {
        if f.props.strength.is_some() {
            let name = if i == 0 { "joints".to_string() } else { format!("interface {}", f.name) };
            out.push(format!("{name}: T, c, tan(phi)"));
        }
    }
    out
}

/// What the caller sees of a strength reduction as it goes.
pub enum SrmProgress<'a> {
    /// The elastic phase ended after this many steps.
    Elastic(usize),
    /// A trial starts.
    TrialStart(f64),
    /// Every 100 steps of a trial: (step, unbalanced ratio).
    Step(usize, f64),
    /// A trial ended (on resume: each trial the checkpoint holds, after
    /// [`SrmProgress::Resumed`]).
    TrialEnd(&'a Trial),
    /// The search goes on from a checkpoint holding this many finished trials.
    Resumed(usize),
}

/// Forwards the steps to the progress callback; stops the trial when the
/// stop flag (a signal, [`Checkpointing::stop`]) is set.
struct Forward<'a, 'b, 'c>(&'a mut dyn FnMut(SrmProgress<'b>), Option<&'c AtomicUsize>);

impl Watch for Forward<'_, '_, '_> {
    fn step(&mut self, _phase: Phase, view: &StepView) -> ControlFlow<()> {
        if self.1.is_some_and(|s| s.load(Ordering::Relaxed) != 0) {
            return ControlFlow::Break(());
        }
        if view.steps.is_multiple_of(100) {
            (self.0)(SrmProgress::Step(view.steps, view.ratio));
        }
        ControlFlow::Continue(())
    }
}

/// The model, its strengths as given, the elastic state and the phase-2
/// plan, made once and shared by every trial.
pub struct Reduction {
    pub model: Model,
    strengths: JointState,
    elastic: State,
    plan: PhasePlan,
    /// Building `plan` (s).
    pub plan_setup_s: f64,
    params: FailureParams,
    start: TrialStart,
    /// The largest stable factor tried so far and its end state.
    stable: Option<(f64, State)>,
}

impl Reduction {
    /// Phase 1 of `scene` (its `[failure]` section, if any, gives the trial
    /// settings). Needs a breakable interface.
    pub fn new(scene: &Scene, start: TrialStart) -> Result<(Self, usize), Error> {
        Self::with_foresight(scene, start, Some(Foresight::TRIALS))
    }

    /// [`Self::new`] with the trials' foresight rule `foresight` (None: every
    /// trial that neither converges nor slides steps to its budget).
    pub fn with_foresight(
        scene: &Scene,
        start: TrialStart,
        foresight: Option<Foresight>,
    ) -> Result<(Self, usize), Error> {
        let params = scene.failure.clone().unwrap_or_default();
        let mut elastic_scene = scene.clone();
        elastic_scene.failure = None;
        elastic_scene.output.stress = false;
        let run = run_watched(&elastic_scene, &mut NoWatch)?;
        if !run.elastic.converged {
            return Err(SceneError::invalid(
                "solver.max_steps",
                format!("the elastic phase did not converge in {} steps: no state to reduce from", run.elastic.steps),
            )
            .into());
        }
        if !run.model.has_breakable_interface() && !run.model.has_plastic_blocks() {
            return Err(SceneError::invalid(
                "interface",
                "strength reduction needs a breakable interface or plastic blocks: a `strength` on [joints], \
                 an [[interface]] or a [[material]]",
            )
            .into());
        }
        let t = std::time::Instant::now();
        let mut plan = phase_plan(&run.model, &scene.solver, &params, usize::MAX, None)?;
        // Measured on plastic blocks only: near the limit of a joint model a
        // trial can slow towards steady sliding, its ratio falling to a
        // plateau, and the sliding rule must decide it (docs/method.md 2.9b).
        plan.foresight = foresight.filter(|_| run.model.has_plastic_blocks());
        let plan_setup_s = t.elapsed().as_secs_f64();
        let steps = run.elastic.steps;
        let strengths = run.state.joints.clone();
        let reduction =
            Self { model: run.model, strengths, elastic: run.state, plan, plan_setup_s, params, start, stable: None };
        Ok((reduction, steps))
    }

    /// Phase 2 with every breakable strength divided by `factor`; returns the
    /// trial, the displacement since the elastic state and the plastic
    /// blocks (if any).
    pub fn trial(&mut self, factor: f64, watch: &mut dyn Watch) -> Result<TrialRun, Error> {
        let t = std::time::Instant::now();
        let (started_from, mut state) = match &self.stable {
            Some((f, end)) if self.start == TrialStart::Warm && *f < factor => (Some(*f), end.clone()),
            _ => (None, self.elastic.clone()),
        };
        (state.step, state.time) = (self.elastic.step, self.elastic.time);
        state.joints = self.strengths.reduced(factor);
        state.rock.reduce(factor);
        self.plan.restart();
        let setup_s = t.elapsed().as_secs_f64();
        let r = failure::run(&mut self.plan, &self.model, &mut state, &self.params, false, watch)?;
        Ok(self.finish(factor, &r, state, started_from, setup_s, Some(t)))
    }

    /// `run` as the trial at F = 1 if it is that trial ([`Phase2Run`]):
    /// None if the model has plastic blocks, if `run` started from another
    /// elastic state, or if its phase 2 went on with phase 1's solver (a
    /// trial starts with a new one's damping state).
    pub fn adopt(&mut self, run: Phase2Run) -> Option<TrialRun> {
        let bits =
            |a: &[f64], b: &[f64]| a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits());
        if self.model.has_plastic_blocks() || run.failure.continued || !bits(&run.failure.u_elastic, &self.elastic.u) {
            return None;
        }
        Some(self.finish(1.0, run.failure, run.state.clone(), None, 0.0, None))
    }

    /// The record of the trial at `factor` whose phase 2 `r` left `state`,
    /// started from the stable factor `started_from` (None: the elastic
    /// state) at `started` (None: taken over from a run, [`Self::adopt`]);
    /// a stable trial's state is kept for the warm starts above it.
    fn finish(
        &mut self,
        factor: f64,
        r: &failure::FailureResult,
        state: State,
        started_from: Option<f64>,
        setup_s: f64,
        started: Option<std::time::Instant>,
    ) -> TrialRun {
        let since: Vec<f64> = state.u.iter().zip(&self.elastic.u).map(|(a, b)| a - b).collect();
        let cells = self.model.plastic_cells(&state.rock, &state.u);
        let plastic = cells.as_deref().map(|c| self.model.plastic_summary(c));
        let (yielded_volume, yielded_tension_volume) =
            plastic.map_or((0.0, 0.0), |p| (p.yielded_volume, p.yielded_tension_volume));
        let trial = Trial {
            factor,
            outcome: r.end,
            foreseen: r.report.stop == Stop::Foreseen,
            steps: r.report.steps,
            max_displacement: max_displacement(&since),
            failed_springs: failed_springs(&state.springs.status).total(),
            yielded_volume,
            yielded_tension_volume,
            started_from,
            setup_s,
            wall_s: started.map_or(0.0, |t| t.elapsed().as_secs_f64()),
            from_run: started.is_none(),
        };
        if trial.stable() && self.stable.as_ref().is_none_or(|(f, _)| *f < factor) {
            self.stable = Some((factor, state));
        }
        TrialRun { trial, since, cells }
    }

    /// The step budget of one trial.
    pub fn budget(&self) -> usize {
        self.plan.budget
    }
}

/// The strength reduction of a scene (see the module doc), trials warm-started.
pub fn run_srm(scene: &Scene, progress: &mut dyn FnMut(SrmProgress)) -> Result<(SrmResult, Model), Error> {
    run_srm_from(scene, TrialStart::Warm, progress)
}

/// [`run_srm`] with the trials started from `start`.
pub fn run_srm_from(
    scene: &Scene,
    start: TrialStart,
    progress: &mut dyn FnMut(SrmProgress),
) -> Result<(SrmResult, Model), Error> {
    run_srm_with(scene, start, Some(Foresight::TRIALS), progress)
}

/// [`run_srm_from`] with the trials' foresight rule `foresight` (None: off;
/// `cdem perf` measures what the rule saves and that it moves no factor).
pub fn run_srm_with(
    scene: &Scene,
    start: TrialStart,
    foresight: Option<Foresight>,
    progress: &mut dyn FnMut(SrmProgress),
) -> Result<(SrmResult, Model), Error> {
    search(scene, start, foresight, None, BRACKET_WIDTH, None, progress)
}

/// [`run_srm_with`] bisected to a bracket of at most `width` (the mesh
/// check's, [`super::mesh_check::CHECK_BRACKET_WIDTH`]).
pub fn search_to(
    scene: &Scene,
    start: TrialStart,
    foresight: Option<Foresight>,
    width: f64,
    progress: &mut dyn FnMut(SrmProgress),
) -> Result<(SrmResult, Model), Error> {
    search(scene, start, foresight, None, width, None, progress)
}

/// [`run_srm`] after a run of the same scene, whose phase 2 is taken over
/// as the trial at F = 1 where it is that trial ([`Phase2Run`]): the same
/// result, one trial fewer to run.
pub fn run_srm_after(
    scene: &Scene,
    run: Phase2Run,
    progress: &mut dyn FnMut(SrmProgress),
) -> Result<(SrmResult, Model), Error> {
    search(scene, TrialStart::Warm, Some(Foresight::TRIALS), Some(run), BRACKET_WIDTH, None, progress)
}

/// [`run_srm`] with checkpoints (`cdem srm --checkpoint-every`, `--resume`):
/// the search's bracket, its finished trials, the mechanism so far and the
/// warm start's state are written at the end of a trial once `ck.every` has
/// passed since the last, and when `ck.stop` is set (the trial under way is
/// then dropped: its steps are done again on resume); with `ck.resume` the
/// search goes on from the checkpoint in `ck.dir`. The result is the same,
/// bit for bit, wherever the run was stopped (its wall times aside).
pub fn run_srm_checkpointed(
    scene: &Scene,
    ck: &Checkpointing,
    progress: &mut dyn FnMut(SrmProgress),
) -> Result<(SrmResult, Model), Error> {
    search(scene, TrialStart::Warm, Some(Foresight::TRIALS), None, BRACKET_WIDTH, Some(ck), progress)
}

/// Where the search stands between two trials: all a checkpoint holds.
struct Bracket {
    trials: Vec<Trial>,
    lo: Option<f64>,
    hi: Option<f64>,
    /// The next factor of the bracketing.
    f: f64,
    /// The bracketing is over: bisect.
    bisect: bool,
    /// The displacement since the elastic state and the plastic blocks at
    /// the current `hi`.
    mechanism: Option<(Vec<f64>, Option<Vec<CellPlastic>>)>,
}

impl Bracket {
    fn new() -> Self {
        Self { trials: Vec::new(), lo: None, hi: None, f: 1.0, bisect: false, mechanism: None }
    }

    /// The next factor to try, None when the search is over.
    fn next(&self, width: f64) -> Option<f64> {
        if !self.bisect {
            return Some(self.f);
        }
        match (self.lo, self.hi) {
            (Some(l), Some(h)) if h - l > width => Some(0.5 * (l + h)),
            _ => None,
        }
    }

    /// The trial at `f` ended (`stable` or not) leaving `since`.
    fn record(&mut self, f: f64, stable: bool, since: (Vec<f64>, Option<Vec<CellPlastic>>)) {
        if stable {
            self.lo = Some(f);
        } else {
            self.hi = Some(f);
            self.mechanism = Some(since);
        }
        if self.bisect {
            return;
        }
        if stable {
            self.f *= BRACKET_RATIO;
            self.bisect = self.hi.is_some() || self.f > MAX_FACTOR;
        } else {
            self.f /= BRACKET_RATIO;
            self.bisect = self.lo.is_some() || self.f < MIN_FACTOR;
        }
    }
}

impl Codec for Trial {
    fn put(&self, w: &mut Enc) {
        let Trial {
            factor,
            outcome,
            foreseen,
            steps,
            max_displacement,
            failed_springs,
            yielded_volume,
            yielded_tension_volume,
            started_from,
            setup_s,
            wall_s,
            from_run,
        } = self;
        factor.put(w);
        outcome.put(w);
        foreseen.put(w);
        steps.put(w);
        max_displacement.put(w);
        failed_springs.put(w);
        yielded_volume.put(w);
        yielded_tension_volume.put(w);
        started_from.put(w);
        setup_s.put(w);
        wall_s.put(w);
        from_run.put(w);
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        Ok(Trial {
            factor: Codec::get(r)?,
            outcome: Codec::get(r)?,
            foreseen: Codec::get(r)?,
            steps: Codec::get(r)?,
            max_displacement: Codec::get(r)?,
            failed_springs: Codec::get(r)?,
            yielded_volume: Codec::get(r)?,
            yielded_tension_volume: Codec::get(r)?,
            started_from: Codec::get(r)?,
            setup_s: Codec::get(r)?,
            wall_s: Codec::get(r)?,
            from_run: Codec::get(r)?,
        })
    }
}

/// The command name a strength reduction's checkpoint carries.
const COMMAND: &str = "srm";

/// The payload of a strength reduction's checkpoint: the elastic state's
/// digest (phase 1 is run again on resume and must give the same bits), the
/// wall time spent so far, the bracket, and the warm start's state.
fn encode(elastic: u64, wall_s: f64, b: &Bracket, stable: &Option<(f64, State)>) -> Vec<u8> {
    let mut w = Enc::default();
    elastic.put(&mut w);
    wall_s.put(&mut w);
    b.trials.put(&mut w);
    b.lo.put(&mut w);
    b.hi.put(&mut w);
    b.f.put(&mut w);
    b.bisect.put(&mut w);
    b.mechanism.as_ref().map(|m| m.0.clone()).put(&mut w);
    b.mechanism.as_ref().and_then(|m| m.1.clone()).put(&mut w);
    stable.as_ref().map(|s| s.0).put(&mut w);
    if let Some((_, state)) = stable {
        state.put(&mut w);
    }
    w.0
}

type Decoded = (u64, f64, Bracket, Option<(f64, State)>);

fn decode(bytes: &[u8]) -> Result<Decoded, CheckpointError> {
    let mut r = Dec::new(bytes);
    let elastic = u64::get(&mut r)?;
    let wall_s = f64::get(&mut r)?;
    let trials = Codec::get(&mut r)?;
    let (lo, hi, f, bisect) = (Codec::get(&mut r)?, Codec::get(&mut r)?, Codec::get(&mut r)?, Codec::get(&mut r)?);
    let since: Option<Vec<f64>> = Codec::get(&mut r)?;
    let cells: Option<Vec<CellPlastic>> = Codec::get(&mut r)?;
    let stable_f: Option<f64> = Codec::get(&mut r)?;
    let stable = match stable_f {
        Some(f) => Some((f, State::get(&mut r)?)),
        None => None,
    };
    r.finish()?;
    let mechanism = since.map(|u| (u, cells));
    Ok((elastic, wall_s, Bracket { trials, lo, hi, f, bisect, mechanism }, stable))
}

/// The search of the module documentation; `given` may stand in for the
/// trial at F = 1; `ck` checkpoints it ([`run_srm_checkpointed`]).
fn search(
    scene: &Scene,
    start: TrialStart,
    foresight: Option<Foresight>,
    mut given: Option<Phase2Run>,
    width: f64,
    ck: Option<&Checkpointing>,
    progress: &mut dyn FnMut(SrmProgress),
) -> Result<(SrmResult, Model), Error> {
    let t0 = std::time::Instant::now();
    let digest = ck.map(|_| checkpoint::scene_digest(scene)).transpose()?;
    let (mut red, elastic_steps) = Reduction::with_foresight(scene, start, foresight)?;
    progress(SrmProgress::Elastic(elastic_steps));
    let trial_budget = red.budget();
    let elastic = checkpoint::state_digest(&red.elastic.u);
    let mut b = Bracket::new();
    let mut wall_before = 0.0;
    if let (Some(ck), Some(digest)) = (ck, digest) {
        if let Some(bytes) = ck.read(COMMAND, digest)? {
            let path = ck.resume.as_deref().unwrap_or(&ck.dir).join(checkpoint::FILE_NAME);
            let (found, wall_s, bracket, stable) =
                decode(&bytes).map_err(|source| Error::Checkpoint { path: path.clone(), source })?;
            if found != elastic {
                let source = CheckpointError::ElasticState { found, computed: elastic };
                return Err(Error::Checkpoint { path, source });
            }
            (wall_before, b, red.stable) = (wall_s, bracket, stable);
            progress(SrmProgress::Resumed(b.trials.len()));
            for t in &b.trials {
                progress(SrmProgress::TrialEnd(t));
            }
        }
    }
    let mut clock = ck.map(|c| checkpoint::Clock::new(c.every));
    let save = |b: &Bracket, red: &Reduction| -> Result<(), Error> {
        if let (Some(ck), Some(digest)) = (ck, digest) {
            let wall_s = wall_before + t0.elapsed().as_secs_f64();
            ck.write(COMMAND, digest, &encode(elastic, wall_s, b, &red.stable))?;
        }
        Ok(())
    };
    while let Some(f) = b.next(width) {
        progress(SrmProgress::TrialStart(f));
        let adopted = given.take().filter(|_| f == 1.0).and_then(|g| red.adopt(g));
        let run = match adopted {
            Some(run) => run,
            None => {
                let mut watch = Forward(progress, ck.map(|c| &*c.stop));
                red.trial(f, &mut watch)?
            }
        };
        if let Some(sig) = ck.and_then(|c| c.signal()) {
            // The trial was cut short: the checkpoint holds the trials before it.
            save(&b, &red)?;
            return Err(ck.expect("a signal comes with checkpoints").interrupted(sig));
        }
        let TrialRun { trial: t, since, cells } = run;
        progress(SrmProgress::TrialEnd(&t));
        b.trials.push(t);
        b.record(f, t.stable(), (since, cells));
        if clock.as_mut().is_some_and(|c| c.due()) {
            save(&b, &red)?;
        }
    }
    let Bracket { trials, lo, hi, mechanism, .. } = b;
    let (mechanism, mechanism_cells) = mechanism.map_or((None, None), |(u, c)| (Some(u), c));
    let band = mechanism_cells.as_deref().and_then(|c| slip_band(&red.model, c));
    let fs = lo.zip(hi).map(|(l, h)| 0.5 * (l + h));
    let hi_outcome = hi.and_then(|h| trials.iter().find(|t| t.factor == h)).map(|t| t.outcome);
    let sliding = trials.iter().filter(|t| t.outcome == EndState::GlobalSliding);
    let sliding_from = sliding.map(|t| t.factor).reduce(f64::min);
    let undecided = trials.iter().filter(|t| t.outcome == EndState::Undecided).count();
    let result = SrmResult {
        fs,
        bracket: [lo, hi],
        hi_outcome,
        sliding_from,
        undecided,
        trials,
        elastic_steps,
        trial_budget,
        plan_setup_s: red.plan_setup_s,
        wall_s: wall_before + t0.elapsed().as_secs_f64(),
        reduced: reduced_strengths(&red.model),
        model: Answer::of(&red.model),
        water: red.model.water.as_ref().map(|w| w.summary()),
        mechanism,
        mechanism_cells,
        band_warning: band.as_ref().and_then(band_warning),
        slip_band: band,
        discretisation: None,
    };
    Ok((result, red.model))
}
