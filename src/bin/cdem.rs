//! The `cdem` command line. The only place errors become text and exit codes.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::{Args, Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};

use cdem::app::RunProgress;

#[derive(Parser)]
#[command(
    name = "cdem",
    version,
    about = "Continuum-discontinuum element method for jointed rock slopes",
    after_help = EXIT_CODES
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene to equilibrium; write summary.json, history.csv and VTK frames.
    Run {
        scene: PathBuf,
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Also run phase 1 on meshes refined by each factor (default 2; `--mesh-check 2,4` for three)
        /// and extrapolate the elastic state's min u_z and min sigma_zz (Richardson; second order
        /// assumed without three meshes), as `cdem fem --mesh-check` does: DIR/mesh-check.json and
        /// DIR/mesh-check/ (gmsh on the .geo beside the mesh when it takes `refine`, else every
        /// element split into eight).
        #[arg(long, value_delimiter = ',', num_args = 0.., default_missing_value = "2", value_name = "R")]
        mesh_check: Option<Vec<f64>>,
    },
    /// Factor of safety by strength reduction (c/F, tan(phi)/F, T/F on the breakable interfaces
    /// and the plastic blocks, bracketing then bisection to a width of 0.01): DIR/srm.json,
    /// mechanism.vtu, mechanism.png, slip-band.png.
    ///
    /// Which model answers which question: plastic blocks (a [[material]] strength) find the
    /// failure through the rock mass and along the breakable interfaces: a slope whose slip
    /// surface nobody drew. Elastic blocks with breakable interfaces (a drawn slip surface, real
    /// joints) fail only along those interfaces. Elastic blocks with every element interface
    /// breakable interlock: that FS is biased high (+22 % to +73 % on six published homogeneous
    /// slopes, references/srm.md), and srm says so.
    #[command(verbatim_doc_comment)]
    Srm {
        scene: PathBuf,
        #[arg(long, default_value = "out-srm")]
        out: PathBuf,
        /// Also estimate the factor's discretisation error: the reduction again on meshes refined by
        /// each factor (default 2; `--mesh-check 1.5,2` for three meshes), every reduction bisected to
        /// 0.0025; gmsh on the .geo beside the mesh when it takes `refine`, else every element split
        /// into eight (factors 2 or 4). Prints "FS on this mesh; about .. converged; this mesh errs ..
        /// (unsafe side)" and writes srm.json's `discretisation` and DIR/mesh-check/.
        #[arg(long, value_delimiter = ',', num_args = 0.., default_missing_value = "2", value_name = "R")]
        mesh_check: Option<Vec<f64>>,
        /// Write a checkpoint, DIR/checkpoint.cdem (the bracket, the finished trials, the warm start's
        /// state), at the end of a trial once this many seconds of wall time have passed since the last
        /// (0: after every trial), and on SIGINT/SIGTERM (then exit 130/143). Removed once the files are
        /// written.
        #[arg(long, value_name = "SECONDS", default_value_t = cdem::drivers::checkpoint::DEFAULT_EVERY_S, conflicts_with = "mesh_check")]
        checkpoint_every: f64,
        /// Go on from the checkpoint in DIR (usually the --out of the run that stopped; none there:
        /// start from the beginning). The files are byte-identical to a run never stopped (srm.json's
        /// wall times aside). A checkpoint of another scene, mesh, format version, or a truncated or
        /// corrupt one is refused (exit 2).
        #[arg(long, value_name = "DIR", conflicts_with = "mesh_check")]
        resume: Option<PathBuf>,
    },
    /// Regenerate a case's .msh from its .geo with gmsh (gmsh must be on PATH); or, given a
    /// geometry file (.toml: a slope and its [[joint_set]]s), write DIR/NAME.geo, .msh and a
    /// scene skeleton NAME.toml.
    Mesh {
        geo: PathBuf,
        /// Output mesh (default: the .geo's path with extension .msh); for a geometry file, the
        /// output directory (default: the geometry file's).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Kinematic analysis of a geometry file's joint sets on its slope face (Markland / Hoek-Bray:
    /// plane sliding, wedge sliding, flexural toppling): DIR/kinematics.md and stereonet.png.
    Kinematics {
        geometry: PathBuf,
        #[arg(long, default_value = "out-kinematics")]
        out: PathBuf,
    },
    /// Solve the scene with the implicit FEM reference (continuous mesh); write summary.json and VTK.
    Fem {
        scene: PathBuf,
        #[arg(long, default_value = "out-fem")]
        out: PathBuf,
        /// Also solve on meshes refined by each factor (default 2; `--mesh-check 2,4` for three) and
        /// extrapolate min u_z and min sigma_zz (Richardson; second order assumed without three meshes):
        /// DIR/mesh-check.json and DIR/mesh-check/ (gmsh on the .geo beside the mesh when it takes
        /// `refine`, else every element split into eight).
        #[arg(long, value_delimiter = ',', num_args = 0.., default_missing_value = "2", value_name = "R")]
        mesh_check: Option<Vec<f64>>,
    },
    /// Limit-equilibrium slope stability (2D circular search): print a table, write JSON.
    #[command(long_about = LEM_HELP)]
    Lem {
        input: PathBuf,
        /// Output JSON (default: the input's path with extension .json).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Monte-Carlo ensemble over the random structural planes and random strengths:
    /// DIR/members.jsonl, ensemble.json, ensemble.md, fs-histogram.png, convergence.png.
    #[command(long_about = ENSEMBLE_HELP)]
    Ensemble(EnsembleArgs),
    /// Error against run time for CDEM and FEM (column, slope): DIR/study.csv and figures.
    Study {
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// Performance: step bandwidth against stream, DR against FEM, LEM against pySlope, phase 2
    /// and `cdem srm` on the slip-surface slope, ensembles of it, the damping table, cost
    /// against size (gmsh for refine 7, 10) and phase 2 and `cdem srm` against size (gmsh):
    /// DIR/perf.md (with the validation rows perf/*) and CSVs. Run from the repository root;
    /// about 70 to 110 minutes with the defaults (the plastic strength reductions about 3 of them,
    /// phase 2 and `cdem srm` against size 30 to 50: its finest slab alone took 43 minutes on
    /// 2026-12-05, on a loaded machine).
    Perf {
        #[arg(long, default_value = "perf")]
        out: PathBuf,
        /// Resolutions of the scaling study (`refine` of slope.geo: 1000 refine^2 elements).
        /// Several values comma- or space-separated: `--refine 1,2,4` or `--refine 1 2 4`.
        #[arg(long, value_delimiter = ',', num_args = 1.., default_value = "0.5,1,2,4,7,10")]
        refine: Vec<f64>,
        /// Run dynamic relaxation (block masses) in the scaling study only up to this many
        /// elements (it takes about 16 minutes at 1e5); PCG and the FEM run at every size.
        #[arg(long)]
        dr_up_to: Option<usize>,
        /// Skip the damping table (about 3 minutes).
        #[arg(long)]
        no_damping: bool,
        /// Skip the timed strength reductions: the slip-surface slope, brittle and ductile (about 12 s and 28 s), and
        /// the plastic blocks of Griffiths & Lane and the paper slope with and without the foresight rule (about 8
        /// min, references/performance.md); phase 2 to a decision (node-block against lumped masses, a few seconds)
        /// always runs.
        #[arg(long)]
        no_srm: bool,
        /// Skip the timed ensembles of the slip-surface slope (about 2 minutes): members per hour
        /// without and with `cdem srm` per member, two shard processes of this binary against one.
        #[arg(long)]
        no_ensemble: bool,
        /// A Python interpreter with pySlope installed (scripts/requirements-lem.txt): time pySlope
        /// in the same run. Without it the LEM ratio uses pySlope's recorded time (references/pyslope.json).
        #[arg(long, value_name = "PYTHON")]
        pyslope: Option<PathBuf>,
        /// Skip phase 2 and `cdem srm` against size (the slip-surface slab at 5 resolutions, 269 to
        /// 15,974 elements, and the 3D wedge at 4 mesh sizes, 1,382 to 16,579 tetrahedra; 30 to 50
        /// minutes, most of it the finest slab; gmsh on PATH).
        #[arg(long)]
        no_trial_scaling: bool,
    },
    /// Run every paper case and write DIR/report.md with the validation table and figures.
    Reproduce {
        #[arg(long, default_value = "reproduce")]
        out: PathBuf,
        /// Regenerate the meshes from their .geo with gmsh first.
        #[arg(long)]
        regenerate: bool,
        /// Only these of the five published slopes of the plastic rock mass
        /// beside Griffiths & Lane's (by key, comma-separated; default: all
        /// five, about 14 minutes of the run on 2 cores); the others' rows are
        /// skipped.
        #[arg(long, num_args = 1.., value_delimiter = ',', value_parser = published_slope_keys())]
        published_slopes: Option<Vec<String>>,
        /// Skip the five published slopes (their 20 asserted rows are then
        /// reported as skipped, with this flag as the reason).
        #[arg(long, conflicts_with = "published_slopes")]
        skip_published_slopes: bool,
    },
}

fn progress_bar(max: usize) -> ProgressBar {
    let pb = ProgressBar::new(max as u64);
    pb.set_style(
        ProgressStyle::with_template("{spinner} step {pos} {msg} [{elapsed_precise}]").expect("valid template"),
    );
    pb
}

/// The progress of a long command (reproduce, study, perf): the harness
/// names each stage through its callback; each is printed with the time
/// since the start, and a spinner shows the current one with the elapsed
/// time (on a terminal).
struct Stages {
    name: &'static str,
    pb: ProgressBar,
    t0: Instant,
    last: Option<(String, Instant)>,
}

impl Stages {
    fn new(name: &'static str) -> Self {
        let pb = ProgressBar::new_spinner();
        pb.set_style(
            ProgressStyle::with_template("{spinner} [{elapsed_precise}] {prefix}: {msg}").expect("valid template"),
        );
        pb.set_prefix(name);
        pb.enable_steady_tick(Duration::from_millis(250));
        Self { name, pb, t0: Instant::now(), last: None }
    }
    fn line(&self, text: String) {
        if self.pb.is_hidden() {
            eprintln!("{text}");
        } else {
            self.pb.println(text);
        }
    }
    /// Closes the previous stage (with its duration) and starts `what`.
    fn stage(&mut self, what: &str) {
        self.close();
        self.line(format!("{}: [{:>7.1} s] {what}", self.name, self.t0.elapsed().as_secs_f64()));
        self.pb.set_message(what.to_string());
        self.last = Some((what.to_string(), Instant::now()));
    }
    fn close(&mut self) {
        if let Some((what, t)) = self.last.take() {
            let s = t.elapsed().as_secs_f64();
            if s >= 1.0 {
                self.line(format!("{}:             ({what}: {s:.1} s)", self.name));
            }
        }
    }
    fn finish(mut self) {
        self.close();
        self.pb.finish_and_clear();
        eprintln!("{}: done in {:.1} s", self.name, self.t0.elapsed().as_secs_f64());
    }
}

const EXIT_CODES: &str = "Exit codes:
  0  the run reached what it was asked for (equilibrium; with [failure], a phase-2 end state)
  1  the run failed (non-finite state, instability, a file that cannot be written)
  2  invalid input: the scene, the mesh, or what the model makes of them (the message names the place),
     or a checkpoint refused by --resume (another scene or mesh, format version, truncated, corrupt)
  3  the step budget ran out: outputs are written, summary.json says end_state \"Undecided\"
  130, 143  stopped by SIGINT, SIGTERM after writing a checkpoint (cdem srm; continue with --resume)";

#[derive(Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
struct EnsembleArgs {
    #[command(subcommand)]
    merge: Option<EnsembleCommand>,
    /// A scene (with [perturbation], [[ensemble.random]] or [lem]) or a LEM file with [ensemble].
    #[arg(required = true)]
    input: Option<PathBuf>,
    /// Members (default: [ensemble] members, else 100).
    #[arg(long)]
    members: Option<usize>,
    #[arg(long, default_value = "out-ensemble")]
    out: PathBuf,
    /// Base seed BASE (default: [ensemble] seed, else 1).
    #[arg(long)]
    seed: Option<u64>,
    /// Run shard I of N (0-based): members [I M / N, (I + 1) M / N); merge the shards after.
    #[arg(long, value_parser = parse_shard)]
    shard: Option<(usize, usize)>,
    /// Go on from the members already in DIR's journal (members.jsonl or members-I-of-N.jsonl,
    /// appended as each batch ends): they are not run again; a torn last line is dropped (and said
    /// so). The files are byte-identical to a run never stopped.
    #[arg(long)]
    resume: bool,
}

#[derive(Subcommand)]
enum EnsembleCommand {
    /// Merge shard directories into one ensemble (checks that every member is there once).
    Merge {
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
        #[arg(long, default_value = "out-ensemble")]
        out: PathBuf,
    },
}

fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    let (i, n) = s.split_once('/').ok_or("expected I/N, e.g. 0/4")?;
    let i = i.parse().map_err(|_| format!("shard index {i:?} is not a number"))?;
    let n = n.parse().map_err(|_| format!("shard count {n:?} is not a number"))?;
    Ok((i, n))
}

const ENSEMBLE_HELP: &str = "Monte-Carlo ensemble over the stochastic structural planes (the node perturbation's
seed) and, optionally, random strengths, as Slide's probabilistic analysis.

Member k of base seed BASE is INPUT with perturbation.seed = splitmix64_(k+1)(BASE) >> 1
(the (k+1)-th output of a SplitMix64 stream started at BASE) and each [[ensemble.random]]
number drawn from its own stream. A member depends on (INPUT, BASE, k) only: records are
byte-identical whatever --shard and the thread count.

  [ensemble]
  members = 200                 # default of --members
  seed = 1                      # default of --seed
  analyses = [\"cdem\", \"lem\"]    # default: cdem for a scene (+ lem with [lem]); lem for a LEM file
  lem_surface = \"critical\"      # LEM on the mean critical circle, or \"search\" per member
  [[ensemble.random]]
  key = \"lem.material[0].cohesion\"  # any number of the file, by its key
  distribution = \"normal\"       # or \"lognormal\"
  mean = 16e3                   # default: the file's value
  std_dev = 2e3
  min = 0.0                     # optional truncation (redrawn)

Per member (members.jsonl, one JSON line): seed, draws, the LEM FS (Bishop), the CDEM
elastic max |u|, phase-2 end state, failed springs and where failure started. The whole
ensemble (ensemble.json, ensemble.md): mean, standard deviation, percentiles, PF = P(FS < 1)
with its 95 % Wilson interval, reliability index (normal and lognormal), convergence
with the member count; fs-histogram.png and convergence.png.

On a cluster: run shards as independent processes (scripts/slurm/ensemble.sbatch: a job
array, SLURM_ARRAY_TASK_ID -> --shard I/N), then `cdem ensemble merge DIR... --out OUT`.

Exit codes: 0 done, 1 failed, 2 invalid input.";

/// The keys `--published-slopes` takes: the published slopes beside Griffiths & Lane's.
fn published_slope_keys() -> clap::builder::PossibleValuesParser {
    clap::builder::PossibleValuesParser::new(cdem::harness::suite::plastic::heavy_published_slopes().map(|s| s.key))
}

/// How a command ended, for the exit code.
enum Outcome {
    Reached,
    OutOfSteps,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    // A value of CDEM_SIMD the kernels would not understand is an input error.
    if let Err(e) = cdem::simd::baseline_from_env() {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    // The command runs on a worker of rayon's pool, not on this thread: a
    // parallel pass started from outside the pool hands its work over and
    // sleeps on a latch each time, thousands of times a second in a
    // relaxation (references/performance.md, "2026-12-03").
    rayon::scope(|_| command(cli))
}

fn command(cli: Cli) -> ExitCode {
    let reached = |r: cdem::Result<()>| r.map(|()| Outcome::Reached);
    let result = match cli.command {
        Command::Run { scene, out, mesh_check } => run(&scene, &out, mesh_check.as_deref()),
        Command::Fem { scene, out, mesh_check } => fem(&scene, &out, mesh_check.as_deref()),
        Command::Srm { scene, out, mesh_check, checkpoint_every, resume } => {
            let ck = mesh_check.is_none().then(|| checkpointing(&out, checkpoint_every, resume.as_deref()));
            srm(&scene, &out, mesh_check.as_deref(), ck.as_ref())
        }
        Command::Mesh { geo, out } if geo.extension().is_some_and(|e| e == "toml") => {
            let dir = out.unwrap_or_else(|| geo.parent().map(PathBuf::from).unwrap_or_default());
            reached(cdem::scene::joint_sets::mesh_geometry(&geo, &dir).map(|m| {
                for p in [&m.geo, &m.msh, &m.scene] {
                    eprintln!("wrote {}", p.display());
                }
            }))
        }
        Command::Mesh { geo, out } => {
            let out = out.unwrap_or_else(|| geo.with_extension("msh"));
            reached(cdem::mesh::gmsh::regenerate(&geo, &out).map(|_| eprintln!("wrote {}", out.display())))
        }
        Command::Kinematics { geometry, out } => reached(cdem::app::kinematics::kinematics(&geometry, &out).map(|k| {
            print!("{}", k.table);
            eprintln!("wrote {}", out.join("kinematics.md").display());
            eprintln!("wrote {}", out.join("stereonet.png").display());
        })),
        Command::Lem { input, out } => reached(lem(&input, out.as_deref())),
        Command::Ensemble(args) => reached(ensemble(args)),
        Command::Study { out } => {
            let mut st = Stages::new("study");
            let r = cdem::harness::study::run_study(&out, &mut |what| st.stage(what));
            st.finish();
            reached(r.map(|rows| eprintln!("study: {} points -> {}", rows.len(), out.join("study.csv").display())))
        }
        Command::Perf { out, refine, dr_up_to, no_damping, no_srm, no_ensemble, pyslope, no_trial_scaling } => {
            let mut opts = cdem::harness::perf::PerfOptions {
                damping: !no_damping,
                srm: !no_srm,
                ensemble: (!no_ensemble).then(|| std::env::current_exe().expect("the path of this executable")),
                refine,
                pyslope,
                trials: !no_trial_scaling,
                ..Default::default()
            };
            opts.dr_up_to = dr_up_to.unwrap_or(opts.dr_up_to);
            let mut st = Stages::new("perf");
            let r = cdem::harness::perf::run_perf(Path::new("."), &out, &opts, &mut |what| st.stage(what));
            st.finish();
            reached(r.map(|md| println!("{md}")))
        }
        Command::Reproduce { out, regenerate, published_slopes, skip_published_slopes } => {
            let mut st = Stages::new("reproduce");
            let slopes = match published_slopes {
                _ if skip_published_slopes => Vec::new(),
                None => cdem::harness::suite::plastic::heavy_published_slopes().map(|s| s.key.to_string()).collect(),
                Some(keys) => keys,
            };
            let r = cdem::harness::reproduce::reproduce(&out, regenerate, &slopes, &mut |what| st.stage(what));
            st.finish();
            reached(r)
        }
    };
    match result {
        Ok(Outcome::Reached) => ExitCode::SUCCESS,
        Ok(Outcome::OutOfSteps) => ExitCode::from(3),
        Err(cdem::Error::Interrupted { signal, name, checkpoint }) => {
            eprintln!("stopped by {name}: checkpoint {} (continue with --resume)", checkpoint.display());
            ExitCode::from(128 + signal as u8)
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(if e.is_input() { 2 } else { 1 })
        }
    }
}

/// Checkpoints into `out`, resumed from `resume`; SIGINT and SIGTERM set
/// the stop flag the command checks at every step.
fn checkpointing(out: &Path, every_s: f64, resume: Option<&Path>) -> cdem::drivers::checkpoint::Checkpointing {
    let ck = cdem::drivers::checkpoint::Checkpointing::new(out, every_s, resume);
    for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        if let Err(e) = signal_hook::flag::register_usize(sig, ck.stop.clone(), sig as usize) {
            eprintln!("warning: signal {sig} not caught ({e}): it stops the run without a checkpoint");
        }
    }
    ck
}

/// `cdem run`: phase 1 and, for a scene with `[failure]`, phase 2.
fn run(scene_path: &Path, out: &Path, mesh_check: Option<&[f64]>) -> cdem::Result<Outcome> {
    let pb = progress_bar(0);
    let mut progress = |p: RunProgress| match p {
        RunProgress::Loaded { budget } => pb.set_length(budget as u64),
        RunProgress::Step { step, ratio } => {
            pb.set_position(step as u64);
            pb.set_message(format!("unbalanced ratio {ratio:.2e}"));
        }
    };
    let (result, check) = match mesh_check {
        None => (cdem::app::run(scene_path, out, &mut progress)?, None),
        Some(refine) => {
            let refine = if refine.is_empty() { &cdem::drivers::mesh_check::DEFAULT_REFINE[..] } else { refine };
            let (result, check) = cdem::app::run_mesh_check(scene_path, refine, out, &mut progress)?;
            (result, Some(check))
        }
    };
    pb.finish_and_clear();
    let s = &result.summary;
    let p1 = s.phase1.as_ref().expect("a CDEM run has phase 1");
    match &s.phase2 {
        None => println!(
            "{} after {} steps ({:.2} s): ratio {:.2e}, min u_z {:.4e} m, min sigma_zz {} Pa -> {}",
            if s.converged { "converged" } else { "NOT converged" },
            s.steps,
            s.wall_s,
            s.unbalanced_ratio,
            s.min_uz,
            s.min_szz.map_or("-".into(), |v| format!("{v:.4e}")),
            out.display()
        ),
        Some(p2) => println!(
            "phase 1: {:?} after {} steps (ratio {:.2e}); phase 2: {:?} after {} steps (ratio {:.2e}), \
             failed springs {} (tension) {} (shear), max displacement since phase 1 {:.3e} m ({:.2} s) -> {}",
            p1.end_state,
            p1.steps,
            p1.unbalanced_ratio,
            p2.end_state,
            p2.steps,
            p2.unbalanced_ratio,
            p2.failed_springs.tension,
            p2.failed_springs.shear,
            p2.max_displacement,
            s.wall_s,
            out.display()
        ),
    }
    if let Some(report) = &result.surface {
        print_surface(report);
    }
    if let Some(c) = &check {
        print_elastic_check(c);
    }
    if let Some(r) = &s.runout {
        match (&r.reason, r.time_to_rest) {
            (Some(why), _) => println!("runout: not run: {why}"),
            (None, rest) => println!(
                "runout: {:.2} s in {} steps, {}; runout distance {:.3} m, peak velocity {:.2} m/s, moved volume {:.1} m^3, its centre of mass {:.2} m down and {:.2} m across (travel angle {:.1} deg), energy budget closes to {:.1e} -> {}",
                r.time,
                r.steps,
                rest.map_or("still moving at the end".to_string(), |t| format!("at rest after {t:.2} s")),
                r.runout_distance,
                r.peak_velocity,
                r.moved_volume,
                r.mass_drop,
                r.mass_travel,
                r.travel_angle,
                r.energy_closure,
                out.join("runout.csv").display()
            ),
        }
        if !r.ran {
            return Ok(Outcome::OutOfSteps);
        }
    }
    Ok(if s.end_state == cdem::EndState::Undecided { Outcome::OutOfSteps } else { Outcome::Reached })
}

/// One line per traction source of the scene's `[analysis]`.
fn print_surface(r: &cdem::drivers::AnalysisReport) {
    let segments = |f: &cdem::drivers::analysis::Factors| {
        f.segments
            .iter()
            .map(|g| format!("{} {:.1}-{:.1} m", if g.sign > 0 { "+" } else { "-" }, g.s0.max(0.0), g.s1))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let (lem, c) = (r.lem_fs.map_or(String::new(), |f| format!(", LEM Bishop FS {f:.3}")), r.arc.circle);
    println!(
        "eq. 21 on the circle ({}{lem}; centre ({:.3}, {:.3}) m, r {:.3} m, toe ({:.2}, {:.2}) m, arc {:.2} m), {}:",
        r.circle_from, c.xc, c.zc, c.r, r.arc.toe[0], r.arc.toe[1], r.arc.length, r.state
    );
    println!(
        "  K = {:.4} from element stresses; K_i sign segments from the toe: {}",
        r.stresses.k,
        segments(&r.stresses)
    );
    if let Some(sp) = &r.springs {
        println!("  K = {:.4} from the interface's springs; K_i sign segments: {}", sp.k, segments(sp));
    }
}

/// `cdem ensemble`: a shard or the whole ensemble, or `merge`.
fn ensemble(args: EnsembleArgs) -> cdem::Result<()> {
    use cdem::app::ensemble as ens;
    let summary = match (args.merge, args.input) {
        (Some(EnsembleCommand::Merge { dirs, out }), _) => (ens::merge(&dirs, &out)?, out),
        (None, Some(input)) => {
            let req = ens::Request {
                input,
                out: args.out.clone(),
                members: args.members,
                seed: args.seed,
                shard: args.shard.unwrap_or((0, 1)),
                resume: args.resume,
            };
            let pb = ProgressBar::new(0);
            pb.set_style(
                ProgressStyle::with_template("{spinner} member {pos}/{len} [{elapsed_precise}, {eta} left]")
                    .expect("valid template"),
            );
            let outcome = ens::run(&req, &mut |done, total| {
                pb.set_length(total as u64);
                pb.set_position(done as u64);
            })?;
            pb.finish_and_clear();
            let resumed = match &outcome {
                ens::Outcome::Shard { resumed, .. } | ens::Outcome::Whole { resumed, .. } => *resumed,
            };
            if args.resume {
                eprintln!("resumed: {} members from the journal, not run again", resumed.members);
            }
            if resumed.torn_bytes > 0 {
                eprintln!(
                    "resumed: dropped a torn last line of the journal ({} bytes: a record cut by the kill), run again",
                    resumed.torn_bytes
                );
            }
            match outcome {
                ens::Outcome::Shard { info, .. } => {
                    println!(
                        "shard {}/{}: members {}..{} of {} ({:.1} s) -> {}",
                        info.shard[0],
                        info.shard[1],
                        info.first,
                        info.end,
                        info.members,
                        info.wall_s,
                        args.out.display()
                    );
                    return Ok(());
                }
                ens::Outcome::Whole { summary, .. } => (*summary, args.out),
            }
        }
        (None, None) => unreachable!("clap requires INPUT without a subcommand"),
    };
    let (s, out) = summary;
    let text = cdem::output::ensemble::markdown(&s);
    let _ = writeln!(std::io::stdout().lock(), "{text}-> {}", out.display());
    Ok(())
}

/// `cdem srm`: strength reduction (with `mesh_check`, on the refined meshes
/// too); progress per trial on the terminal.
fn srm(
    scene_path: &Path,
    out: &Path,
    mesh_check: Option<&[f64]>,
    ck: Option<&cdem::drivers::checkpoint::Checkpointing>,
) -> cdem::Result<Outcome> {
    use cdem::drivers::mesh_check::CheckProgress;
    use cdem::drivers::SrmProgress;
    let pb = progress_bar(0);
    let mut on_srm = |p: SrmProgress| match p {
        SrmProgress::Elastic(steps) => pb.suspend(|| eprintln!("elastic phase: {steps} steps")),
        SrmProgress::TrialStart(f) => pb.set_message(format!("trial F = {f:.4}")),
        SrmProgress::Step(step, ratio) => {
            pb.set_position(step as u64);
            pb.tick();
            let _ = ratio;
        }
        SrmProgress::Resumed(n) => pb.suspend(|| eprintln!("resumed from the checkpoint: {n} trials done")),
        SrmProgress::TrialEnd(t) => pb.suspend(|| {
            eprintln!(
                "F = {:.4}: {:?}{} after {} steps, max displacement {:.3e} m, {} failed springs, {:.3e} m^3 yielded \
                 ({:.3e} m^3 in tension)",
                t.factor,
                t.outcome,
                if t.foreseen { " (foreseen: the ratio decays too slowly for the budget)" } else { "" },
                t.steps,
                t.max_displacement,
                t.failed_springs,
                t.yielded_volume,
                t.yielded_tension_volume
            )
        }),
    };
    let result = match mesh_check {
        None => cdem::app::srm(scene_path, out, ck, &mut on_srm)?,
        Some(refine) => {
            let refine = if refine.is_empty() { &cdem::drivers::mesh_check::DEFAULT_REFINE[..] } else { refine };
            cdem::app::srm_mesh_check(scene_path, refine, out, &mut |p| match p {
                CheckProgress::Meshing(r) => pb.suspend(|| eprintln!("mesh check: meshing at refine {r}")),
                CheckProgress::Mesh(r) => pb.suspend(|| eprintln!("mesh check: strength reduction at refine {r}")),
                CheckProgress::Srm(p) => on_srm(p),
            })?
        }
    };
    pb.finish_and_clear();
    if let Some(note) = &result.model.note {
        println!("note: {note}");
    }
    let [lo, hi] = result.bracket;
    let show = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.4}"));
    match result.fs {
        Some(fs) => println!(
            "FS = {fs:.3} (bracket [{}, {}], {} trials of at most {} steps, {:.1} s) -> {}",
            show(lo),
            show(hi),
            result.trials.len(),
            result.trial_budget,
            result.wall_s,
            out.display()
        ),
        None => println!(
            "no bracket: stable up to {}, unstable from {} ({} trials, {:.1} s) -> {}",
            show(lo),
            show(hi),
            result.trials.len(),
            result.wall_s,
            out.display()
        ),
    }
    if result.hi_outcome == Some(cdem::EndState::Undecided) {
        println!(
            "note: the bracket's upper end F = {} did not decide within its {} steps (or foreseeably would not: its \
             ratio decayed too slowly) and is counted unstable, as FLAC counts a trial that does not converge; {}",
            show(hi),
            result.trial_budget,
            match result.sliding_from {
                Some(f) => format!("the smallest factor that slid is {f:.4}"),
                None => "no trial slid".to_string(),
            }
        );
    }
    match (&result.discretisation, &result.slip_band) {
        (Some(d), _) => {
            for m in &d.meshes {
                println!(
                    "  refine {}: {} elements, FS {} [{}, {}], {} trials, {:.1} s",
                    m.refine,
                    m.elements,
                    m.fs.map_or("-".to_string(), |f| format!("{f:.4}")),
                    show(m.bracket[0]),
                    show(m.bracket[1]),
                    m.trials,
                    m.wall_s
                );
            }
            println!("{} (the check took {:.1} times the reduction on this mesh)", d.line, d.cost_ratio);
        }
        (None, Some(band)) => {
            println!("slip band: crosses {} elements, {:.1} thick", band.along, band.across);
            if let Some(w) = &result.band_warning {
                println!("warning: {w}");
            }
        }
        (None, None) => {}
    }
    Ok(if result.fs.is_some() { Outcome::Reached } else { Outcome::OutOfSteps })
}

/// `cdem fem`: the implicit FEM reference on the continuous mesh.
fn fem(scene_path: &Path, out: &Path, mesh_check: Option<&[f64]>) -> cdem::Result<Outcome> {
    let (fem, check) = match mesh_check {
        None => (cdem::app::fem(scene_path, out)?, None),
        Some(refine) => {
            let refine = if refine.is_empty() { &cdem::drivers::mesh_check::DEFAULT_REFINE[..] } else { refine };
            let (fem, check) = cdem::app::fem_mesh_check(scene_path, refine, out)?;
            (fem, Some(check))
        }
    };
    let sol = &fem.solution;
    let s = &sol.summary;
    println!(
        "FEM solved {} unknowns ({:.2} s): residual {:.2e}, min u_z {:.4e} m, min sigma_zz {} Pa -> {}",
        sol.free_dofs,
        s.wall_s,
        s.unbalanced_ratio,
        s.min_uz,
        s.min_szz.map_or("-".into(), |v| format!("{v:.4e}")),
        out.display()
    );
    if let Some(report) = &fem.surface {
        print_surface(report);
    }
    if let Some(c) = &check {
        print_elastic_check(c);
    }
    Ok(if s.converged { Outcome::Reached } else { Outcome::OutOfSteps })
}

/// The lines of `cdem run --mesh-check` and `cdem fem --mesh-check`.
fn print_elastic_check(c: &cdem::drivers::mesh_check::ElasticCheck) {
    for m in &c.meshes {
        println!("  refine {}: {} elements, min u_z {:.4e} m ({:.2} s)", m.refine, m.elements, m.min_uz, m.wall_s);
    }
    for line in &c.lines {
        println!("{line}");
    }
}

const LEM_HELP: &str = "Limit-equilibrium slope stability: ordinary, Bishop simplified and Spencer on circular
slip surfaces (a search, or one given circle). Prints a table, writes JSON.

INPUT is either a LEM file or a CDEM scene with a [lem] table (units m, Pa, deg, N/m^3).

A CDEM scene (a file with [mesh]): the section is the mesh cut by the plane y = y_plane
(an outer face; default the lowest y), its ground the top of that section (or the nodes
of a surface group), its zones the volume groups met by it:
  [lem]
  ground_group = \"ground\"   # optional
  y_plane = 0.0               # optional
  z_min = 0.0                 # optional: no circle below (default the lowest node; the toe's level allowed)
  facing = \"left\"           # optional: detected from the ground (crest at the higher end)
  slices = 50                 # optional; methods = [\"ordinary\", \"bishop\", \"spencer\"]
  [[lem.material]]            # one per volume group met by the section
  group = \"rock\"
  cohesion = 16.0e3           # c' (Pa)
  friction_angle = 18.0       # phi' (deg)
  unit_weight = 20.6e3        # optional: the group's density x |gravity|
  # [lem.circle] xc, zc, r    or [lem.search] as below

A LEM file:
  [section]
  ground = [[20.0, 25.0], [30.0, 25.0], [50.0, 35.0], [70.0, 35.0]]   # (x, z), x increasing
  # or from_mesh = \"slope.msh\", ground_group = \"ground\", y_plane = 0.0
  z_min = 20.0                # or lower_bound = [[x, z], ...]; may equal the lowest ground point
  facing = \"left\"           # optional: \"left\" (sliding toward -x) or \"right\"
  [[material]]                # without zone: the whole section (at most one)
  cohesion = 3.0e3
  friction_angle = 19.6
  unit_weight = 20.0e3
  # zone = [[x, z], ...]      # a polygon; the first zone containing a point wins
  [analysis]
  slices = 50
  methods = [\"ordinary\", \"bishop\", \"spencer\"]
  [search]                    # optional: [search.grid] nx, nz, radii, x, z; [search.entry_exit]
  refine = true               #   n_exit, n_entry, radii, exit, entry; min_depth, min_width (m)
  # [circle] xc, zc, r        # one circle instead of a search

Exit codes: 0 done, 1 failed, 2 invalid input (the message names the key).";

/// `cdem lem`: runs a LEM input, prints a short table and writes the JSON
/// (to `out`, or beside the input with extension `.json`).
fn lem(input: &Path, out: Option<&Path>) -> cdem::Result<()> {
    let (result, out) = cdem::app::lem(input, out)?;
    // A closed stdout (e.g. `| head`) is not an error of the analysis.
    let _ = writeln!(std::io::stdout().lock(), "{}wrote {}", cdem::lem::table(&result), out.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refine(args: &[&str]) -> Vec<f64> {
        let argv = ["cdem", "perf"].iter().chain(args).copied();
        match Cli::try_parse_from(argv).expect("parses").command {
            Command::Perf { refine, .. } => refine,
            _ => unreachable!("a perf command"),
        }
    }

    #[test]
    fn perf_refine_takes_the_default_its_help_shows_and_both_separators() {
        assert_eq!(refine(&[]), [0.5, 1.0, 2.0, 4.0, 7.0, 10.0]);
        assert_eq!(refine(&["--refine", "0.5,1,2,4,7,10"]), refine(&[]));
        assert_eq!(refine(&["--refine", "1", "2", "4"]), [1.0, 2.0, 4.0]);
        assert_eq!(refine(&["--refine", "1,2", "4", "--no-srm"]), [1.0, 2.0, 4.0]);
    }

    fn slopes(args: &[&str]) -> Result<(Option<Vec<String>>, bool), clap::Error> {
        let argv = ["cdem", "reproduce"].iter().chain(args).copied();
        Ok(match Cli::try_parse_from(argv)?.command {
            Command::Reproduce { published_slopes, skip_published_slopes, .. } => {
                (published_slopes, skip_published_slopes)
            }
            _ => unreachable!("a reproduce command"),
        })
    }

    #[test]
    fn reproduce_takes_all_some_by_key_or_none_of_the_published_slopes() {
        // Default: all five (None); some by key; none with the skip flag.
        assert_eq!(slopes(&[]).unwrap(), (None, false));
        assert!(slopes(&["--published-slopes"]).is_err(), "the keys are needed");
        let some = slopes(&["--published-slopes", "acads,at"]).unwrap();
        assert_eq!(some, (Some(vec!["acads".into(), "at".into()]), false));
        assert_eq!(slopes(&["--skip-published-slopes"]).unwrap(), (None, true));
        assert!(slopes(&["--skip-published-slopes", "--published-slopes", "at"]).is_err(), "one or the other");
        assert!(slopes(&["--published-slopes", "gl1"]).is_err(), "Griffiths & Lane's rows are cargo test's own");
        // Every key of the library's parses.
        for s in cdem::harness::suite::plastic::heavy_published_slopes() {
            assert_eq!(slopes(&["--published-slopes", s.key]).unwrap(), (Some(vec![s.key.to_string()]), false));
        }
    }
}
