//! The `cdem` command line. The only place errors become text and exit codes.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};

use cdem::scene::Scene;

#[derive(Parser)]
#[command(name = "cdem", version, about = "Continuum-discontinuum element method for jointed rock slopes")]
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

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Run { scene, out } => run(&scene, &out),
        Command::Mesh { geo, out } => {
            let out = out.unwrap_or_else(|| geo.with_extension("msh"));
            cdem::mesh::gmsh::regenerate(&geo, &out).map(|_| eprintln!("wrote {}", out.display()))
        }
        Command::Fem { scene, out } => fem(&scene, &out),
        Command::Lem { input, out } => cdem::lem::run_file(&input, out.as_deref()).map(|_| ()),
        Command::Study { out } => cdem::study::run_study(&out, &mut |what| eprintln!("study: {what}")).map(|rows| {
            eprintln!("study: {} points -> {}", rows.len(), out.join("study.csv").display());
        }),
        Command::Perf { out, refine, no_damping } => {
            let opts = cdem::perf::PerfOptions { damping: !no_damping, refine, ..Default::default() };
            cdem::perf::run_perf(std::path::Path::new("."), &out, &opts, &mut |what| eprintln!("perf: {what}"))
                .map(|md| println!("{md}"))
        }
        Command::Reproduce { out, regenerate } => {
            cdem::reproduce::reproduce(&out, regenerate, &mut |what| eprintln!("reproduce: {what}"))
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(scene_path: &std::path::Path, out: &std::path::Path) -> cdem::Result<()> {
    let scene = Scene::load(scene_path)?;
    if let Some(params) = &scene.failure {
        return run_progressive(&scene, params, out);
    }
    let pb = progress_bar(scene.solver.max_steps);
    let result = cdem::run::run_scene(&scene, &mut |step, ratio| {
        pb.set_position(step as u64);
        pb.set_message(format!("unbalanced ratio {ratio:.2e}"));
    })?;
    pb.finish_and_clear();
    cdem::run::write_outputs(&scene, &result, out)?;
    let s = &result.summary;
    println!(
        "{} after {} steps ({:.2} s): ratio {:.2e}, min u_z {:.4e} m, min sigma_zz {} Pa -> {}",
        if s.converged { "converged" } else { "NOT converged" },
        s.steps,
        s.wall_s,
        s.unbalanced_ratio,
        s.min_uz,
        s.min_szz.map_or("-".into(), |v| format!("{v:.4e}")),
        out.display()
    );
    Ok(())
}

fn fem(scene_path: &std::path::Path, out: &std::path::Path) -> cdem::Result<()> {
    let scene = Scene::load(scene_path)?;
    let sol = cdem::fem::solve_scene(&scene)?;
    cdem::fem::write_outputs(&sol, out)?;
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
    Ok(())
}

/// A scene with `[failure]`: phase 1 (elastic) then phase 2 (breakable joints).
fn run_progressive(
    scene: &Scene,
    params: &cdem::progressive::FailureParams,
    out: &std::path::Path,
) -> cdem::Result<()> {
    let t0 = std::time::Instant::now();
    let pb = progress_bar(scene.solver.max_steps + params.max_steps);
    let r = cdem::progressive::run_progressive(scene, params, &mut |step, ratio| {
        pb.set_position(step as u64);
        pb.set_message(format!("unbalanced ratio {ratio:.2e}"));
    })?;
    pb.finish_and_clear();
    let stress = scene.output.stress.then(|| r.model.element_stresses(&r.state.u));
    let converged = r.end == cdem::progressive::EndState::Equilibrium;
    let report = cdem::solver::RunReport { converged, steps: r.elastic.steps + r.phase2_steps, ..r.elastic.clone() };
    let summary = cdem::run::summarize(&r.model, &r.state, &report, stress.as_deref(), t0.elapsed().as_secs_f64());
    let result = cdem::run::RunResult {
        model: r.model.clone(),
        state: r.state.clone(),
        report,
        stress,
        frames: Vec::new(),
        summary,
    };
    cdem::run::write_outputs(scene, &result, out)?;
    cdem::progressive::write_outputs(&r, out, scene.output.vtk)?;
    let last = r.stages.last();
    println!(
        "phase 1: {} steps; phase 2: {:?} after {} steps, failed springs {} (tension) {} (shear), max displacement since phase 1 {:.3e} m -> {}",
        r.elastic.steps,
        r.end,
        r.phase2_steps,
        last.map_or(0, |s| s.failed_tension),
        last.map_or(0, |s| s.failed_shear),
        last.map_or(0.0, |s| s.max_displacement),
        out.display()
    );
    Ok(())
}
