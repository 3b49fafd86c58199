//! The `cdem` command line. The only place errors become text and exit codes.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};

use cdem::scene::Scene;

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
    },
    /// Regenerate a case's .msh from its .geo with gmsh (gmsh must be on PATH).
    Mesh {
        geo: PathBuf,
        /// Output mesh (default: the .geo's path with extension .msh).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Solve the scene with the implicit FEM reference (continuous mesh); write summary.json and VTK.
    Fem {
        scene: PathBuf,
        #[arg(long, default_value = "out-fem")]
        out: PathBuf,
    },
    /// Limit-equilibrium slope stability (2D circular search): print a table, write JSON.
    #[command(long_about = LEM_HELP)]
    Lem {
        input: PathBuf,
        /// Output JSON (default: the input's path with extension .json).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Error against run time for CDEM and FEM (column, slope): DIR/study.csv and figures.
    Study {
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// Performance: step bandwidth against stream, DR against FEM, LEM against pySlope, the
    /// damping table and cost against size (gmsh for refine 7, 10): DIR/perf.md and CSVs.
    /// Run from the repository root; about 20 minutes with the defaults.
    Perf {
        #[arg(long, default_value = "perf")]
        out: PathBuf,
        /// Resolutions of the scaling study (`refine` of slope.geo: 1000 refine^2 elements).
        #[arg(long, value_delimiter = ',', default_values_t = vec![0.5, 1.0, 2.0, 4.0, 7.0, 10.0])]
        refine: Vec<f64>,
        /// Skip the damping table (about 3 minutes).
        #[arg(long)]
        no_damping: bool,
        /// A Python interpreter with pySlope installed (scripts/requirements-lem.txt): time pySlope
        /// in the same run. Without it the LEM ratio uses pySlope's recorded time (references/pyslope.json).
        #[arg(long, value_name = "PYTHON")]
        pyslope: Option<PathBuf>,
    },
    /// Run every paper case and write DIR/report.md with the validation table and figures.
    Reproduce {
        #[arg(long, default_value = "reproduce")]
        out: PathBuf,
        /// Regenerate the meshes from their .geo with gmsh first.
        #[arg(long)]
        regenerate: bool,
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
  2  invalid input: the scene, the mesh, or what the model makes of them (the message names the place)
  3  the step budget ran out: outputs are written, summary.json says end_state \"Undecided\"";

/// How a command ended, for the exit code.
enum Outcome {
    Reached,
    OutOfSteps,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let reached = |r: cdem::Result<()>| r.map(|()| Outcome::Reached);
    let result = match cli.command {
        Command::Run { scene, out } => run(&scene, &out),
        Command::Fem { scene, out } => fem(&scene, &out),
        Command::Mesh { geo, out } => {
            let out = out.unwrap_or_else(|| geo.with_extension("msh"));
            reached(cdem::mesh::gmsh::regenerate(&geo, &out).map(|_| eprintln!("wrote {}", out.display())))
        }
        Command::Lem { input, out } => reached(lem(&input, out.as_deref())),
        Command::Study { out } => {
            let mut st = Stages::new("study");
            let r = cdem::harness::study::run_study(&out, &mut |what| st.stage(what));
            st.finish();
            reached(r.map(|rows| eprintln!("study: {} points -> {}", rows.len(), out.join("study.csv").display())))
        }
        Command::Perf { out, refine, no_damping, pyslope } => {
            let opts = cdem::harness::perf::PerfOptions { damping: !no_damping, refine, pyslope, ..Default::default() };
            let mut st = Stages::new("perf");
            let r = cdem::harness::perf::run_perf(Path::new("."), &out, &opts, &mut |what| st.stage(what));
            st.finish();
            reached(r.map(|md| println!("{md}")))
        }
        Command::Reproduce { out, regenerate } => {
            let mut st = Stages::new("reproduce");
            let r = cdem::harness::reproduce::reproduce(&out, regenerate, &mut |what| st.stage(what));
            st.finish();
            reached(r)
        }
    };
    match result {
        Ok(Outcome::Reached) => ExitCode::SUCCESS,
        Ok(Outcome::OutOfSteps) => ExitCode::from(3),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(if e.is_input() { 2 } else { 1 })
        }
    }
}

/// `cdem run`: phase 1 and, for a scene with `[failure]`, phase 2.
fn run(scene_path: &Path, out: &Path) -> cdem::Result<Outcome> {
    let scene = Scene::load(scene_path)?;
    let budget = scene.solver.max_steps + scene.failure.as_ref().map_or(0, |f| f.max_steps);
    let pb = progress_bar(budget);
    let result = cdem::drivers::run_scene(&scene, &mut |step, ratio| {
        pb.set_position(step as u64);
        pb.set_message(format!("unbalanced ratio {ratio:.2e}"));
    })?;
    pb.finish_and_clear();
    cdem::output::write_run(&scene, &result, out)?;
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
    Ok(if s.end_state == cdem::EndState::Undecided { Outcome::OutOfSteps } else { Outcome::Reached })
}

/// `cdem fem`: the implicit FEM reference on the continuous mesh.
fn fem(scene_path: &Path, out: &Path) -> cdem::Result<Outcome> {
    let scene = Scene::load(scene_path)?;
    let sol = cdem::drivers::solve_fem(&scene)?;
    cdem::output::write_fem(&sol, out)?;
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
    Ok(if s.converged { Outcome::Reached } else { Outcome::OutOfSteps })
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
    let result = cdem::lem::analyse(&cdem::drivers::load_lem_input(input)?)?;
    let out = out.map(Path::to_path_buf).unwrap_or_else(|| input.with_extension("json"));
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| cdem::Error::io(dir, e))?;
    }
    cdem::output::write_json(&out, &result)?;
    // A closed stdout (e.g. `| head`) is not an error of the analysis.
    let _ = writeln!(std::io::stdout().lock(), "{}wrote {}", cdem::lem::table(&result), out.display());
    Ok(())
}
