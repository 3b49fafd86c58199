//! One small point of the error-against-run-time study (src/harness/study.rs;
//! the full study runs in `cdem study` / `cdem reproduce`): the 10-layer
//! column against the analytic solution (references/column.md). The
//! continuous FEM is nodally exact for this 1-D problem; CDEM with
//! E_j/L = 1e11 Pa/m is within the 1 % of the core issue (series joint
//! compliance, about 0.1 %).
//!
//! The error is recomputed here from the raw displacements and the analytic
//! `u_z(z)` of the registry (docs/method.md section 4.2: mass-weighted for
//! CDEM, unit weights for the FEM), and the study's value must equal it: the
//! study's own error function is under test, not trusted.

use cdem::harness::registry as reg;

/// `sqrt(sum w |u - u_ref|^2 / sum w |u_ref|^2)`, `u_ref = (0, 0, u_z(z))`.
fn l2(points: impl Iterator<Item = ([f64; 3], [f64; 3], f64)>) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for (x, u, w) in points {
        let r = [0.0, 0.0, reg::column_uz(x[2])];
        num += w * (0..3).map(|d| (u[d] - r[d]).powi(2)).sum::<f64>();
        den += w * r[2] * r[2];
    }
    (num / den).sqrt()
}

#[test]
fn column_point_of_the_study_fem_exact_cdem_within_one_percent() {
    let (cdem, fem) = cdem::harness::study::column_base_point().unwrap();
    println!("study column point: CDEM L2 error {cdem:.3e}, FEM {fem:.3e}");
    // Independently: the same runs, the error from the registry's analytic column.
    let scene = reg::COLUMN.scene().unwrap();
    let r = cdem::drivers::run_scene(&scene, &mut |_, _| {}).unwrap();
    let m = &r.model;
    let u = |i: usize| [r.state.u[3 * i], r.state.u[3 * i + 1], r.state.u[3 * i + 2]];
    let cdem_here = l2((0..m.n_nodes()).map(|i| (m.x0[i], u(i), m.mass[i])));
    let sol = cdem::drivers::solve_fem(&scene).unwrap();
    let fu = |i: usize| [sol.u[3 * i], sol.u[3 * i + 1], sol.u[3 * i + 2]];
    let fem_here = l2((0..sol.coords.len()).map(|i| (sol.coords[i], fu(i), 1.0)));
    println!("recomputed: CDEM {cdem_here:.3e}, FEM {fem_here:.3e}");
    assert!(((cdem - cdem_here) / cdem_here).abs() < 1e-12, "study {cdem} vs recomputed {cdem_here}");
    assert!((fem - fem_here).abs() < 1e-14, "study {fem} vs recomputed {fem_here}");
    cdem::harness::report::record(
        "study_point",
        &[
            reg::row("study/column/cdem-l2").value(cdem_here, 0.0, r.summary.wall_s),
            reg::row("study/column/fem-l2").value(fem_here, 0.0, sol.summary.wall_s),
        ],
    );
    assert!(fem_here < 1e-10, "FEM error {fem_here}");
    assert!(cdem_here < reg::TOL_COLUMN_SPRINGS, "CDEM error {cdem_here}");
    assert!(cdem_here > 1e-5, "CDEM with springs cannot be exact: joint compliance is missing");
}
