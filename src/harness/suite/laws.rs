//! Constitutive laws (references/laws.md, tests/laws.rs): a Barton-Bandis
//! joint in a direct shear test (its peak at three normal stresses and its
//! residual against the envelope: rows `laws/bb-shear-*`), and Hoek & Bray's
//! plane failure with the sliding plane a Barton-Bandis joint, by strength
//! reduction against the closed form, dry and with the tension crack full
//! (rows `laws/bb-plane-srm`, `laws/bb-plane-wet-srm`).

use crate::drivers::{run_srm, SrmResult};
use crate::error::Error;
use crate::harness::registry::{self as reg, BartonBandisJoint, Case, PLANE_FAILURE_SET};
use crate::harness::report::Check;
use crate::harness::suite::joints::defect;
use crate::physics::joint::{BartonBandisSection, JointStrength, Softening};
use crate::physics::spring::{Spring, SpringStatus};

/// One direct shear test of a joint of unit area under the normal stress
/// `sigma_n` (Pa): the shear displacement ramps to six times the elastic
/// displacement at the peak in 600 steps with the normal displacement held.
/// Returns the largest shear stress reached and the last one (Pa), and the
/// spring's status at the end.
pub fn direct_shear(j: &BartonBandisJoint, sigma_n: f64, softening: Softening) -> (f64, f64, SpringStatus) {
    let section = BartonBandisSection {
        jrc: j.jrc,
        jcs: j.jcs,
        residual_friction_angle: j.phi_r_deg,
        max_friction_angle: j.cap_deg,
        tensile: 0.0,
        softening,
    };
    let law = JointStrength::BartonBandis(section.strength());
    // 1 m^2 of a joint with K_n = K_s = 1e10 N/m, normal (0, 0, 1).
    let spring = Spring { kn: 1e10, ks: 1e10, normal: [0.0, 0.0, 1.0], area: 1.0 };
    let d_n = -sigma_n * spring.area / spring.kn;
    let d_peak = j.tau(sigma_n) * spring.area / spring.ks;
    let (mut slip, mut status) = ([0.0; 3], SpringStatus::Intact);
    let (mut largest, mut last) = (0.0f64, 0.0);
    for k in 1..=600 {
        let d = [6.0 * d_peak * k as f64 / 600.0, 0.0, d_n];
        let f = law.force(&spring, d, &mut slip, &mut status);
        last = f[0].hypot(f[1]) / spring.area;
        largest = largest.max(last);
    }
    (largest, last, status)
}

/// The direct-shear rows: the ductile joint's plateau at each of
/// [`reg::BB_SHEAR_STRESSES`] against the envelope, and the brittle joint's
/// stress after its peak at 1 MPa against `sigma_n tan(phi_r)`.
pub fn shear_rows() -> Vec<Check> {
    let j = reg::BB_SHEAR_JOINT;
    let ids = ["laws/bb-shear-peak-0.1mpa", "laws/bb-shear-peak-1mpa", "laws/bb-shear-peak-10mpa"];
    let mut rows: Vec<Check> = (0..3)
        .map(|k| {
            let t0 = std::time::Instant::now();
            let (_, plateau, _) = direct_shear(&j, reg::BB_SHEAR_STRESSES[k], Softening::Ductile);
            reg::row(ids[k]).value(plateau, reg::BB_SHEAR_PEAKS[k], t0.elapsed().as_secs_f64())
        })
        .collect();
    let t0 = std::time::Instant::now();
    let (_, after, status) = direct_shear(&j, 1e6, Softening::Brittle);
    let mut row =
        reg::row("laws/bb-shear-residual-1mpa").value(after, reg::BB_SHEAR_RESIDUAL_1MPA, t0.elapsed().as_secs_f64());
    if status != SpringStatus::Shear {
        row = row.with_defect(format!("the joint did not fail in shear: {status:?}"));
    }
    rows.push(row);
    rows
}

/// The plane-failure cases: (case, closed form, row id).
pub fn plane_cases() -> [(Case, f64, &'static str); 2] {
    [
        (reg::PLANE_BB, reg::BB_PLANE_FS_DRY, "laws/bb-plane-srm"),
        (reg::PLANE_BB_WET, reg::BB_PLANE_FS_WET, "laws/bb-plane-wet-srm"),
    ]
}

/// The registry's plane-failure closed form on the Barton-Bandis joint, dry
/// and with the crack full (against [`reg::BB_PLANE_FS_DRY`] and
/// [`reg::BB_PLANE_FS_WET`], the script's numbers).
pub fn plane_closed_forms() -> [f64; 2] {
    let (gw, z) = (9810.0, PLANE_FAILURE_SET.crack_depth());
    let j = reg::BB_PLANE_JOINT;
    [0.0, z].map(|z_w| reg::plane_failure_bb_fs(&PLANE_FAILURE_SET, &j, gw, z_w))
}

/// `cdem srm` on a plane-failure case and its row, failed by
/// [`defect`] (the bracket and its sliding end; the bounds are the row's).
pub fn plane(case: Case, closed_form: f64, id: &str) -> Result<(Check, SrmResult), Error> {
    let t0 = std::time::Instant::now();
    let (result, _) = run_srm(&case.scene()?, &mut |_| {})?;
    let mut row = reg::row(id).value(result.fs.unwrap_or(f64::NAN), closed_form, t0.elapsed().as_secs_f64());
    if let Some(d) = defect(&result, closed_form, f64::INFINITY) {
        row = row.with_defect(d);
    }
    Ok((row, result))
}
