//! The laterally confined column under gravity against the analytic solution
//! (references/column.md): with stiff springs within 1 %, the spring
//! compliance error falling as 1/k, and exact (to solver tolerance) with the
//! interfaces merged.

use cdem::drivers::{run_scene, RunResult};
use cdem::harness::registry::{self as reg, column_szz, column_uz, measured_top_uz, CONFINED_COLUMN};
use cdem::harness::report::Check;
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

/// Base stress from the bottom reactions: sum (f_int - f_ext)_z / area.
fn base_stress(r: &RunResult) -> f64 {
    let m = &r.model;
    let mut rz = 0.0;
    for i in 0..m.n_nodes() {
        if m.x0[i][2].abs() < 1e-9 && m.fixed[3 * i + 2] {
            rz += r.state.f_int[3 * i + 2] - m.f_ext[3 * i + 2];
        }
    }
    -rz / CONFINED_COLUMN.area
}

/// Largest relative error of the element sigma_zz against the exact value at
/// the element centroid.
fn element_stress_error(r: &RunResult) -> f64 {
    let m = &r.model;
    let stress = r.stress.as_ref().unwrap();
    (0..m.elements.len())
        .map(|e| {
            let c = m.elements.corners(e);
            let zc = c.iter().map(|&i| m.x0[i as usize][2]).sum::<f64>() / c.len() as f64;
            ((stress[e][2] - column_szz(zc)) / column_szz(zc)).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn column_with_stiff_springs_within_one_percent() {
    let r = run(&scene(reg::COLUMN));
    let (uz, exact) = (measured_top_uz(&r), column_uz(H));
    let err_u = ((uz - exact) / exact).abs();
    let err_base = ((base_stress(&r) - column_szz(0.0)) / column_szz(0.0)).abs();
    let err_el = element_stress_error(&r);
    println!("springs: top u_z {uz:.5e} (exact {exact:.5e}, err {err_u:.2e}); base {:.5e} (err {err_base:.2e}); element sigma_zz max err {err_el:.2e}", base_stress(&r));
    let t = r.summary.wall_s;
    cdem::harness::report::record(
        "column_springs",
        &[
            Check::new(
                "column, springs E_j/L=1e11",
                "top u_z (m)",
                uz,
                exact,
                reg::TOL_COLUMN_SPRINGS,
                reg::COLUMN_MD,
                t,
            ),
            Check::new(
                "column, springs E_j/L=1e11",
                "base sigma_zz from reactions (Pa)",
                base_stress(&r),
                column_szz(0.0),
                reg::TOL_COLUMN_SPRINGS,
                reg::COLUMN_MD,
                t,
            ),
            Check::new(
                "column, springs E_j/L=1e11",
                "max element sigma_zz error vs centroid value",
                err_el,
                0.0,
                reg::TOL_COLUMN_SPRINGS,
                reg::COLUMN_MD,
                t,
            ),
        ],
    );
    assert!(err_u < reg::TOL_COLUMN_SPRINGS, "top displacement off by {:.3} %", 100.0 * err_u);
    assert!(err_base < reg::TOL_COLUMN_SPRINGS, "base stress off by {:.3} %", 100.0 * err_base);
    assert!(err_el < reg::TOL_COLUMN_SPRINGS, "element stress off by {:.3} %", 100.0 * err_el);
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
        element_stress_error(&r)
    );
    cdem::harness::report::record(
        "column_merged",
        &[Check::new(
            "column, merged",
            "top u_z (m)",
            uz,
            exact,
            reg::TOL_COLUMN_MERGED,
            reg::COLUMN_MD,
            r.summary.wall_s,
        )],
    );
    assert!(err < reg::TOL_COLUMN_MERGED, "top displacement off by {err:.2e}");
    assert!(element_stress_error(&r) < reg::TOL_COLUMN_MERGED);
}
