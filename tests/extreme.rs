//! Stiff and extreme suite (verification/extreme/): for each case the
//! automatic step stays stable (no blow-up, kinetic energy decays) and the
//! result matches the analytic answer within the stated tolerance, or the run
//! says `converged: false` — never NaN, never silently wrong. Analytic
//! references: references/extreme.md. Steps and times go to
//! target/extreme-report.md.

use std::fmt::Write;
use std::path::Path;

use cdem::drivers::{run_scene, RunResult};
use cdem::mesh::adjacency::FaceAdjacency;
use cdem::mesh::gmsh::read_msh;
use cdem::mesh::perturb::perturb_nodes;
use cdem::scene::Scene;

const G: f64 = 9.81;
const H: f64 = 40.0;

fn p_modulus(e: f64, nu: f64) -> f64 {
    e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))
}

/// Top settlement of a laterally confined column of layers
/// `(z0, z1, rho, M)` from the bottom up (references/extreme.md):
/// `u(H) = -int_0^H W(z) / M(z) dz` with `W(z)` the weight per area above z.
fn layered_top_uz(layers: &[(f64, f64, f64, f64)]) -> f64 {
    let mut u = 0.0;
    for (k, &(z0, z1, rho, m)) in layers.iter().enumerate() {
        let above: f64 = layers[k + 1..].iter().map(|&(a, b, r, _)| r * G * (b - a)).sum();
        // int_z0^z1 [above + rho g (z1 - z)] dz
        u -= (above * (z1 - z0) + 0.5 * rho * G * (z1 - z0).powi(2)) / m;
    }
    u
}

fn top_uz(r: &RunResult) -> f64 {
    let top: Vec<usize> = (0..r.model.n_nodes()).filter(|&i| (r.model.x0[i][2] - H).abs() < 1e-9).collect();
    top.iter().map(|&i| r.state.u[3 * i + 2]).sum::<f64>() / top.len() as f64
}

struct Row {
    case: &'static str,
    ours: f64,
    reference: f64,
    tolerance: f64,
    converged: bool,
    steps: usize,
    wall_s: f64,
}

fn run_case(case: &'static str, reference: f64, tolerance: f64, rows: &mut Vec<Row>) -> RunResult {
    let scene = Scene::load(&Path::new("verification/extreme").join(format!("{case}.toml"))).unwrap();
    let r = run_scene(&scene, &mut |_, _| {}).unwrap_or_else(|e| panic!("{case}: {e}"));
    assert!(r.state.u.iter().all(|v| v.is_finite()), "{case}: non-finite displacement");
    let ke: Vec<f64> = r.elastic.history.iter().map(|h| h.kinetic_energy).collect();
    let peak = ke.iter().cloned().fold(0.0, f64::max);
    assert!(ke.last().copied().unwrap_or(0.0) <= peak, "{case}: kinetic energy grew to the end");
    let ours = top_uz(&r);
    rows.push(Row {
        case,
        ours,
        reference,
        tolerance,
        converged: r.summary.converged,
        steps: r.summary.steps,
        wall_s: r.summary.wall_s,
    });
    r
}

#[test]
fn stiff_and_extreme_cases_are_stable_and_right_or_say_not_converged() {
    let m = p_modulus(3.0e8, 0.3);
    let rho = 2100.0;
    let column = layered_top_uz(&[(0.0, H, rho, m)]);
    let mut rows = Vec::new();

    // Soft joints, one element wide (column-single.msh): each horizontal
    // interface (z = 4, 8, ..., 36) adds the settlement W(z_i) L / E_j in
    // series, and there is no other interface.
    let e_j = 3.0e8;
    let soft = column - (1..10).map(|i| rho * G * (H - 4.0 * i as f64)).sum::<f64>() * 1.0 / e_j;
    run_case("joints-soft", soft, 1e-5, &mut rows);
    run_case("joints-stiff", column, 1e-3, &mut rows);
    run_case("poisson-0499", layered_top_uz(&[(0.0, H, rho, p_modulus(3.0e8, 0.499))]), 1e-5, &mut rows);
    run_case("perturbation-near-limit", column, 2e-3, &mut rows);
    run_case("aspect-1-50", column, 1e-5, &mut rows);
    run_case("contrast-modulus-1e4", layered_top_uz(&[(0.0, 20.0, rho, m), (20.0, H, rho, 1e4 * m)]), 1e-5, &mut rows);
    run_case("contrast-density-1e3", layered_top_uz(&[(0.0, 20.0, 2.1, m), (20.0, H, rho, m)]), 1e-5, &mut rows);
    let zero = run_case("zero-gravity", 0.0, 0.0, &mut rows);
    assert!(zero.summary.converged && zero.state.u.iter().all(|&v| v == 0.0), "zero load must stay exactly at rest");

    let mut md = String::from("| case | top u_z (m) | analytic (m) | rel. error | tolerance | converged | steps | wall (s) |\n|---|---|---|---|---|---|---|---|\n");
    let mut failures = Vec::new();
    for r in &rows {
        let err = if r.reference == 0.0 { r.ours.abs() } else { ((r.ours - r.reference) / r.reference).abs() };
        let _ = writeln!(
            md,
            "| {} | {:.6e} | {:.6e} | {:.2e} | {:.0e} | {} | {} | {:.2} |",
            r.case, r.ours, r.reference, err, r.tolerance, r.converged, r.steps, r.wall_s
        );
        // Converged runs must be right; a non-converged run must say so (it does, in its summary).
        if r.converged && err > r.tolerance {
            failures.push(format!("{}: error {err:.2e} > {:.0e}", r.case, r.tolerance));
        }
    }
    println!("{md}");
    cdem::harness::report::record(
        "extreme",
        &rows
            .iter()
            .filter(|r| r.converged)
            .map(|r| {
                cdem::harness::report::Check::new(
                    &format!("extreme: {}", r.case),
                    "top u_z (m)",
                    r.ours,
                    r.reference,
                    r.tolerance.max(1e-300),
                    "references/extreme.md",
                    r.wall_s,
                )
            })
            .collect::<Vec<_>>(),
    );
    let _ = std::fs::create_dir_all("target");
    let _ = std::fs::write("target/extreme-report.md", &md);
    assert!(failures.is_empty(), "{failures:?}");
    // The stiff case converges or reports that it did not.
    let stiff = rows.iter().find(|r| r.case == "joints-stiff").unwrap();
    if !stiff.converged {
        assert_eq!(stiff.steps, 100_000);
    }
}

/// The near-limit scene's ratio is within 10 % below the inversion limit of
/// its seed (found by bisection; on the column mesh, whose nodes nearly all
/// slide in their boundary planes, that is the validator's cap of 0.5), so
/// the case tests what it claims.
#[test]
fn near_limit_ratio_is_just_below_the_inversion_limit() {
    let scene = Scene::load(Path::new("verification/extreme/perturbation-near-limit.toml")).unwrap();
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
