//! Stiff and extreme suite (verification/extreme/): for each case the
//! automatic step stays stable (no blow-up, kinetic energy decays) and the
//! result matches the analytic answer within the stated tolerance, or the run
//! says `converged: false` — never NaN, never silently wrong. Analytic
//! references: references/extreme.md. Steps and times go to
//! target/extreme-report.md.

use std::fmt::Write;

use cdem::drivers::{run_scene, RunResult};
use cdem::harness::registry::{extreme_cases, ExtremeCase};
use cdem::harness::report::{Check, Status};
use cdem::harness::validation::extreme_row;
use cdem::mesh::adjacency::FaceAdjacency;
use cdem::mesh::gmsh::read_msh;
use cdem::mesh::perturb::perturb_nodes;

/// Runs a case: never NaN, the kinetic energy decays (its last recorded
/// value is a small fraction of its peak: `KE_DECAY`), and its row.
fn run_case(case: &ExtremeCase) -> (RunResult, Check) {
    let name = case.name;
    let scene = case.scene().unwrap();
    let r = run_scene(&scene, &mut |_, _| {}).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(r.state.u.iter().all(|v| v.is_finite()), "{name}: non-finite displacement");
    let row = extreme_row(case, &r);
    (r, row)
}

/// The last recorded kinetic energy of a converged case against its peak
/// (references/extreme.md: measured at most 5e-14 of the peak).
const KE_DECAY: f64 = 1e-10;

/// The cases and their analytic answers: [`extreme_cases`] (references/extreme.md).
/// Every case has its row; a case that does not converge fails its row (and
/// the report), it is not dropped.
#[test]
fn stiff_and_extreme_cases_are_stable_and_right_or_say_not_converged() {
    let mut rows = Vec::new();
    let mut md = String::from("| case | top u_z (m) | analytic (m) | rel. error | tolerance | converged | steps | KE last / peak | wall (s) |\n|---|---|---|---|---|---|---|---|---|\n");
    let mut decay = Vec::new();
    for case in extreme_cases() {
        let (r, row) = run_case(&case);
        if case.name == "zero-gravity" {
            assert!(r.summary.converged && r.state.u.iter().all(|&v| v == 0.0), "zero load must stay exactly at rest");
        }
        let ke: Vec<f64> = r.elastic.history.iter().map(|h| h.kinetic_energy).collect();
        let peak = ke.iter().cloned().fold(0.0, f64::max);
        let last = ke.last().copied().unwrap_or(0.0);
        let ratio = if peak > 0.0 { last / peak } else { 0.0 };
        decay.push((case.name, ratio));
        let _ = writeln!(
            md,
            "| {} | {:.6e} | {:.6e} | {:.2e} | {:.0e} | {} | {} | {:.1e} | {:.2} |",
            case.name,
            row.ours,
            row.reference,
            row.rel_error(),
            case.tolerance,
            r.summary.converged,
            r.summary.steps,
            ratio,
            r.summary.wall_s
        );
        rows.push(row);
    }
    println!("{md}");
    cdem::harness::report::record("extreme", &rows);
    let _ = std::fs::create_dir_all("target");
    let _ = std::fs::write("target/extreme-report.md", &md);
    let failed: Vec<String> = rows
        .iter()
        .filter(|c| !c.passed())
        .map(|c| format!("{}: {:.2e} {:?}", c.id, c.rel_error(), c.defect))
        .collect();
    assert!(failed.is_empty(), "{failed:?}");
    for (name, ratio) in decay {
        assert!(ratio <= KE_DECAY, "{name}: kinetic energy at the end {ratio:.1e} of its peak");
    }
}

/// A case that runs out of steps is not dropped and not `ok`: its row fails
/// (the mutation of issue 18: poisson-0499 with `max_steps = 50`).
#[test]
fn a_case_that_does_not_converge_fails_its_row() {
    let case = extreme_cases().into_iter().find(|c| c.name == "poisson-0499").unwrap();
    let mut scene = case.scene().unwrap();
    // Dynamic relaxation: PCG (the default) converges within 50 iterations.
    scene.solver.elastic = cdem::solver::ElasticSolver::Dr;
    scene.solver.max_steps = Some(50);
    let r = run_scene(&scene, &mut |_, _| {}).unwrap();
    assert!(!r.summary.converged);
    let row = extreme_row(&case, &r);
    println!("poisson-0499 in 50 steps: error {:.2e}, {:?}", row.rel_error(), row.defect);
    assert_eq!(row.status(), Status::Fail);
    assert!(row.defect.as_deref().unwrap_or("").contains("not converged"));
}

/// The near-limit scene's ratio is within 10 % below the inversion limit of
/// its seed (found by bisection; on the column mesh, whose nodes nearly all
/// slide in their boundary planes, that is the validator's cap of 0.5), so
/// the case tests what it claims.
#[test]
fn near_limit_ratio_is_just_below_the_inversion_limit() {
    let near = extreme_cases().into_iter().find(|c| c.name == "perturbation-near-limit").unwrap();
    let scene = near.scene().unwrap();
    let mesh = read_msh(&scene.mesh_path()).unwrap();
    let adj = FaceAdjacency::build(&mesh).unwrap();
    let seed = scene.perturbation.seed;
    // The limit is the inversion ratio or the scene validator's cap of 0.5.
    let (mut ok, mut bad) = (0.0, 0.5);
    if perturb_nodes(&mesh, &adj, 0.4999, seed, &[]).is_ok() {
        ok = 0.5;
    } else {
        for _ in 0..30 {
            let mid = 0.5 * (ok + bad);
            if perturb_nodes(&mesh, &adj, mid, seed, &[]).is_ok() {
                ok = mid;
            } else {
                bad = mid;
            }
        }
    }
    let r = scene.perturbation.ratio;
    println!("inversion limit for seed {seed}: {ok:.4}; scene ratio {r}");
    assert!(r < ok && r >= 0.9 * ok, "ratio {r} is not just below the limit {ok}");
}
