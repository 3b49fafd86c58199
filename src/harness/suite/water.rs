//! Pore water (references/water.md, tests/water.rs): the joint water of
//! [`crate::model::water`] against Terzaghi's effective stress in a
//! submerged column and against the closed forms of the infinite slope with
//! a parallel water table and of Hoek & Bray's plane failure with a
//! water-filled tension crack.

use crate::drivers::{run_scene, RunResult};
use crate::error::Error;
use crate::harness::registry::{self as reg, Case, CONFINED_COLUMN, INFINITE_SLOPE_SET, PLANE_FAILURE_SET};
use crate::harness::report::Check;
use crate::harness::suite::joints::reduce;
use crate::physics::spring::{relative_displacement, spring_force};

/// The submerged column's rows: the springs' effective stress at mid-height,
/// the base reaction, the blocks' total stress.
pub fn column_rows() -> Result<(Vec<Check>, RunResult), Error> {
    let t0 = std::time::Instant::now();
    let r = run_scene(&reg::WATER_COLUMN.scene()?, &mut |_, _| {})?;
    let seconds = t0.elapsed().as_secs_f64();
    let (h, gamma) = (CONFINED_COLUMN.height, reg::WATER_COLUMN_GAMMA);
    let gamma_w = r.model.water.as_ref().and_then(|w| w.surface.as_ref()).map_or(f64::NAN, |s| s.unit_weight);
    let effective = |z: f64| -(gamma - gamma_w) * (h - z);
    let m = &r.model;
    // The interface at mid-height: springs at z = H/2 with a vertical normal.
    let z_mid = 0.5 * h;
    let mut force = 0.0;
    for s in 0..m.springs.len() {
        let (a, b) = (m.springs.a[s] as usize, m.springs.b[s] as usize);
        if (m.x0[a][2] - z_mid).abs() < 1e-9 && m.springs.normal[s][2].abs() > 0.999 {
            let d = relative_displacement(&r.state.u, a, b);
            force += spring_force(m.springs.kn[s], m.springs.ks[s], m.springs.normal[s], d, [0.0; 3]).0;
        }
    }
    let mid = force / CONFINED_COLUMN.area;
    let base = crate::harness::validation::column_base_stress(&r);
    let mut worst = (0.0, 0.0, 0.0);
    if let Some(stress) = r.stress.as_ref() {
        for e in 0..m.elements.len() {
            let c = m.elements.corners(e);
            let zc = c.iter().map(|&i| m.x0[i as usize][2]).sum::<f64>() / c.len() as f64;
            let total = -gamma * (h - zc);
            let err = ((stress[e][2] - total) / total).abs();
            if err >= worst.0 {
                worst = (err, stress[e][2], total);
            }
        }
    }
    let mut rows = vec![
        reg::row("water/column-effective").value(mid, effective(z_mid), seconds),
        reg::row("water/column-base").value(base, effective(0.0), seconds),
        reg::row("water/column-total").value(worst.1, worst.2, seconds),
    ];
    if !r.summary.converged {
        rows = rows.into_iter().map(|c| c.with_defect("the column did not converge")).collect();
    }
    Ok((rows, r))
}

/// The strength-reduction cases: (case, closed form, row id).
pub fn srm_cases() -> [(Case, f64, &'static str); 5] {
    let (gw, z) = (9810.0, PLANE_FAILURE_SET.crack_depth());
    [
        (reg::WATER_INFINITE_HALF, INFINITE_SLOPE_SET.fs(0.5), "water/infinite-half-srm"),
        (reg::WATER_INFINITE_FULL, INFINITE_SLOPE_SET.fs(1.0), "water/infinite-full-srm"),
        (reg::WATER_PLANE_HALF, PLANE_FAILURE_SET.fs_with_water(gw, 0.5 * z, true), "water/plane-half-srm"),
        (reg::WATER_PLANE_FULL, PLANE_FAILURE_SET.fs_with_water(gw, z, true), "water/plane-full-srm"),
        (reg::WATER_PLANE_CRACK, PLANE_FAILURE_SET.fs_with_water(gw, z, false), "water/plane-crack-srm"),
    ]
}

/// One reduction's row: failed unless the bracket is narrow, its upper end
/// slid, and its midpoint is within [`reg::TOL_WATER_SRM`] of the closed form.
pub fn srm_row(
    case: Case,
    closed_form: f64,
    id: &str,
) -> Result<(Check, crate::drivers::SrmResult, crate::model::Model), Error> {
    reduce(case, closed_form, id, reg::TOL_WATER_SRM)
}

/// A reduction of this suite: its row id, result and model.
pub type SrmRun = (&'static str, crate::drivers::SrmResult, crate::model::Model);

/// Every row of this suite, and each reduction's result and model (for
/// the mechanism figures of `cdem reproduce`).
pub fn rows() -> Result<(Vec<Check>, Vec<SrmRun>), Error> {
    let mut rows = column_rows()?.0;
    let mut runs = Vec::new();
    for (case, fs, id) in srm_cases() {
        let (row, result, model) = srm_row(case, fs, id)?;
        rows.push(row);
        runs.push((id, result, model));
    }
    Ok((rows, runs))
}
