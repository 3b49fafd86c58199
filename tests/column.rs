//! The laterally confined column under gravity against the analytic solution
//! (references/column.md): with stiff springs within 1 %, the spring
//! compliance error falling as 1/k, and exact (to solver tolerance) with the
//! interfaces merged.

use cdem::drivers::{run_scene, RunResult};
use cdem::harness::registry::{self as reg, column_szz, column_uz, measured_top_uz, CONFINED_COLUMN};
use cdem::harness::validation::{
    column_base_stress, column_element_stress_error, column_merged_row, column_springs_rows, joint_stiffness,
};
use cdem::scene::{JointMode, Scene};

const H: f64 = CONFINED_COLUMN.height;

fn scene(case: reg::Case) -> Scene {
    case.scene().unwrap()
}

fn run(scene: &Scene) -> RunResult {
    let r = run_scene(scene, &mut |_, _| {}).unwrap();
    assert!(r.summary.converged, "not converged: ratio {}", r.summary.unbalanced_ratio);
    r
}

#[test]
fn column_with_stiff_springs_within_one_percent() {
    let r = run(&scene(reg::COLUMN));
    let rows = column_springs_rows(&r);
    for c in &rows {
        println!("springs: {} {:.5e} (exact {:.5e}, err {:.2e})", c.quantity, c.ours, c.reference, c.rel_error());
    }
    cdem::harness::report::record("column_springs", &rows);
    // Top u_z: within 1 % of the continuum (the joints' series compliance,
    // references/column.md), and within 2e-4 of the joints in series.
    let err_u = ((measured_top_uz(&r) - column_uz(H)) / column_uz(H)).abs();
    assert!(err_u < reg::TOL_COLUMN_SPRINGS, "top displacement off by {:.3} %", 100.0 * err_u);
    let jointed = reg::column_top_uz_jointed(joint_stiffness(&r));
    let err_j = ((measured_top_uz(&r) - jointed) / jointed).abs();
    assert!(err_j < reg::TOL_COLUMN_SERIES_JOINTS, "top displacement off the jointed column by {err_j:.2e}");
    // Stresses: statically determinate, so independent of the joints: to the
    // convergence tolerance.
    let err_base = ((column_base_stress(&r) - column_szz(0.0)) / column_szz(0.0)).abs();
    assert!(err_base < reg::TOL_COLUMN_REACTION, "base stress off by {err_base:.2e}");
    let err_el = column_element_stress_error(&r);
    assert!(err_el < reg::TOL_COLUMN_STRESS, "element stress off by {err_el:.2e}");
    assert!(rows.iter().all(|c| c.passed()), "{rows:?}");
}

#[test]
fn spring_compliance_error_falls_as_one_over_joint_stiffness() {
    let mut errors = Vec::new();
    for e_j in [1.0e9, 1.0e10, 1.0e11] {
        let mut s = scene(reg::COLUMN);
        s.joints.normal_modulus = Some(e_j);
        s.joints.shear_modulus = Some(e_j / 2.6);
        s.output.vtk = false;
        let r = run(&s);
        errors.push(((measured_top_uz(&r) - column_uz(H)) / column_uz(H)).abs());
    }
    println!("top displacement error for E_j = 1e9, 1e10, 1e11: {errors:?}");
    for w in errors.windows(2) {
        let rate = w[0] / w[1];
        // Series compliance: error ~ 1/k, so 10x stiffer gives ~10x smaller error.
        assert!((5.0..20.0).contains(&rate), "error ratio {rate} for 10x stiffer joints");
    }
}

#[test]
fn column_with_merged_interfaces_is_exact_to_solver_tolerance() {
    let s = scene(reg::COLUMN_MERGED);
    assert_eq!(s.joints.mode, JointMode::Merged);
    let r = run(&s);
    assert_eq!(r.model.springs.len(), 0, "merged interfaces make no springs");
    let (uz, exact) = (measured_top_uz(&r), column_uz(H));
    let err = ((uz - exact) / exact).abs();
    println!(
        "merged: top u_z {uz:.6e} (exact {exact:.6e}, err {err:.2e}); element sigma_zz max err {:.2e}",
        column_element_stress_error(&r)
    );
    cdem::harness::report::record("column_merged", &[column_merged_row(&r)]);
    assert!(err < reg::TOL_COLUMN_MERGED, "top displacement off by {err:.2e}");
    // Not a row: the merged column's element stresses (measured 1.5e-9).
    assert!(column_element_stress_error(&r) < 1e-8);
}
