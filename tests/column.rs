//! The laterally confined column under gravity against the analytic solution
//! (references/column.md): with stiff springs within 1 %, the spring
//! compliance error falling as 1/k, and exact (to solver tolerance) with the
//! interfaces merged.

use std::path::Path;

use cdem::drivers::{run_scene, RunResult};
use cdem::harness::report::Check;
use cdem::scene::{JointMode, Scene};

// references/column.md
const H: f64 = 40.0;
const RHO: f64 = 2100.0;
const G: f64 = 9.81;
const E: f64 = 3.0e8;
const NU: f64 = 0.3;
const AREA: f64 = 16.0;

fn m_modulus() -> f64 {
    E * (1.0 - NU) / ((1.0 + NU) * (1.0 - 2.0 * NU))
}
fn uz_exact(z: f64) -> f64 {
    -RHO * G * (H * z - 0.5 * z * z) / m_modulus()
}
fn szz_exact(z: f64) -> f64 {
    -RHO * G * (H - z)
}

fn scene(file: &str) -> Scene {
    Scene::load(Path::new("verification/cases/column").join(file).as_path()).unwrap()
}

fn run(scene: &Scene) -> RunResult {
    let r = run_scene(scene, &mut |_, _| {}).unwrap();
    assert!(r.summary.converged, "not converged: ratio {}", r.summary.unbalanced_ratio);
    r
}

/// Mean u_z of the node copies at the top.
fn top_uz(r: &RunResult) -> f64 {
    let top: Vec<usize> = (0..r.model.n_nodes()).filter(|&i| (r.model.x0[i][2] - H).abs() < 1e-9).collect();
    top.iter().map(|&i| r.state.u[3 * i + 2]).sum::<f64>() / top.len() as f64
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
    -rz / AREA
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
            ((stress[e][2] - szz_exact(zc)) / szz_exact(zc)).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn column_with_stiff_springs_within_one_percent() {
    let r = run(&scene("column.toml"));
    let (uz, exact) = (top_uz(&r), uz_exact(H));
    let err_u = ((uz - exact) / exact).abs();
    let err_base = ((base_stress(&r) - szz_exact(0.0)) / szz_exact(0.0)).abs();
    let err_el = element_stress_error(&r);
    println!("springs: top u_z {uz:.5e} (exact {exact:.5e}, err {err_u:.2e}); base {:.5e} (err {err_base:.2e}); element sigma_zz max err {err_el:.2e}", base_stress(&r));
    let t = r.summary.wall_s;
    cdem::harness::report::record(
        "column_springs",
        &[
            Check::new("column, springs E_j/L=1e11", "top u_z (m)", uz, exact, 0.01, "references/column.md", t),
            Check::new(
                "column, springs E_j/L=1e11",
                "base sigma_zz from reactions (Pa)",
                base_stress(&r),
                szz_exact(0.0),
                0.01,
                "references/column.md",
                t,
            ),
            Check::new(
                "column, springs E_j/L=1e11",
                "max element sigma_zz error vs centroid value",
                err_el,
                0.0,
                0.01,
                "references/column.md",
                t,
            ),
        ],
    );
    assert!(err_u < 0.01, "top displacement off by {:.3} %", 100.0 * err_u);
    assert!(err_base < 0.01, "base stress off by {:.3} %", 100.0 * err_base);
    assert!(err_el < 0.01, "element stress off by {:.3} %", 100.0 * err_el);
}

#[test]
fn spring_compliance_error_falls_as_one_over_joint_stiffness() {
    let mut errors = Vec::new();
    for e_j in [1.0e9, 1.0e10, 1.0e11] {
        let mut s = scene("column.toml");
        s.joints.normal_modulus = Some(e_j);
        s.joints.shear_modulus = Some(e_j / 2.6);
        s.output.vtk = false;
        let r = run(&s);
        errors.push(((top_uz(&r) - uz_exact(H)) / uz_exact(H)).abs());
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
    let s = scene("column-merged.toml");
    assert_eq!(s.joints.mode, JointMode::Merged);
    let r = run(&s);
    assert_eq!(r.model.springs.len(), 0, "merged interfaces make no springs");
    let (uz, exact) = (top_uz(&r), uz_exact(H));
    let err = ((uz - exact) / exact).abs();
    println!(
        "merged: top u_z {uz:.6e} (exact {exact:.6e}, err {err:.2e}); element sigma_zz max err {:.2e}",
        element_stress_error(&r)
    );
    cdem::harness::report::record(
        "column_merged",
        &[Check::new("column, merged", "top u_z (m)", uz, exact, 1e-5, "references/column.md", r.summary.wall_s)],
    );
    assert!(err < 1e-5, "top displacement off by {err:.2e}");
    assert!(element_stress_error(&r) < 1e-5);
}
