//! The `cdem` command line. The only place errors become text and exit codes.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

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
        /// Run dynamic relaxation (block masses) in the scaling study only up to this many
        /// elements (it takes about 16 minutes at 1e5); PCG and the FEM run at every size.
        #[arg(long)]
        dr_up_to: Option<usize>,
        /// Skip the damping table (about 3 minutes).
        #[arg(long)]
        no_damping: bool,
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
        Command::Study { out } => reached(
            cdem::harness::study::run_study(&out, &mut |what| eprintln!("study: {what}"))
                .map(|rows| eprintln!("study: {} points -> {}", rows.len(), out.join("study.csv").display())),
        ),
        Command::Perf { out, refine, dr_up_to, no_damping } => {
            let mut opts = cdem::harness::perf::PerfOptions { damping: !no_damping, refine, ..Default::default() };
            opts.dr_up_to = dr_up_to.unwrap_or(opts.dr_up_to);
            reached(
                cdem::harness::perf::run_perf(Path::new("."), &out, &opts, &mut |what| eprintln!("perf: {what}"))
                    .map(|md| println!("{md}")),
            )
        }
        Command::Reproduce { out, regenerate } => {
            reached(cdem::harness::reproduce::reproduce(&out, regenerate, &mut |what| eprintln!("reproduce: {what}")))
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

/// `cdem lem`: runs a LEM input, prints a short table and writes the JSON
/// (to `out`, or beside the input with extension `.json`).
fn lem(input: &Path, out: Option<&Path>) -> cdem::Result<()> {
    let result = cdem::lem::analyse(&cdem::lem::LemInput::load(input)?)?;
    let out = out.map(Path::to_path_buf).unwrap_or_else(|| input.with_extension("json"));
    cdem::output::write_json(&out, &result)?;
    // A closed stdout (e.g. `| head`) is not an error of the analysis.
    let _ = writeln!(std::io::stdout().lock(), "{}wrote {}", cdem::lem::table(&result), out.display());
    Ok(())
}
