//! Joint sets (references/joints.md, tests/joints.rs): the rock-slope
//! mechanisms meshed from their joint sets (`cdem mesh GEOMETRY.toml`), their
//! factor of safety by strength reduction (`cdem srm`) against the closed
//! forms: Hoek & Bray's plane failure with a dry tension crack (row
//! `joints/plane-srm`) and a symmetric wedge by the wedge factor (row
//! `joints/wedge-srm`, 3D), a general wedge with cohesion by the vector
//! solution (row `joints/wedge-general-srm`), and Goodman & Bray's block toppling by their
//! limit-equilibrium recursion (row `joints/toppling-srm`; its mesh is a
//! hand-written `.geo`: the stepped base is not persistent joint sets).

use crate::drivers::{run_srm, SrmResult};
use crate::error::Error;
use crate::harness::registry::{self as reg, Case, TOL_JOINTS_SRM, TOL_JOINTS_TOPPLING, TOL_JOINTS_WEDGE_GENERAL};
use crate::harness::report::Check;
use crate::harness::suite::srm::BRACKET_WIDTH;
use crate::model::Model;
use crate::EndState;

/// One case: the reduction, the closed form, the mesh size and the row.
pub struct JointRun {
    pub case: Case,
    pub result: SrmResult,
    pub closed_form: f64,
    /// Tetrahedra of the mesh.
    pub cells: usize,
    pub row: Check,
    /// The model (for the mechanism's figure).
    pub model: Model,
}

/// The cases: (case, closed-form FS, row id).
pub fn cases() -> [(Case, f64, &'static str); 4] {
    [
        (reg::PLANE_FAILURE, reg::PLANE_FAILURE_SET.fs(), "joints/plane-srm"),
        (reg::WEDGE_SYMMETRIC, reg::WEDGE_SYMMETRIC_SET.fs(), "joints/wedge-srm"),
        (reg::WEDGE_GENERAL, reg::WEDGE_GENERAL_SET.fs(), "joints/wedge-general-srm"),
        (reg::TOPPLING, reg::TOPPLING_SET.fs(reg::TOPPLING_FRICTION_DEG), "joints/toppling-srm"),
    ]
}

/// The tolerance of row `id`.
fn tolerance(id: &str) -> f64 {
    match id {
        "joints/toppling-srm" => TOL_JOINTS_TOPPLING,
        "joints/wedge-general-srm" => TOL_JOINTS_WEDGE_GENERAL,
        _ => TOL_JOINTS_SRM,
    }
}

/// Runs `case`; its row fails (with the reason) unless the reduction found
/// a bracket at most [`BRACKET_WIDTH`] wide whose upper end slid and whose
/// midpoint is within the row's tolerance ([`TOL_JOINTS_SRM`],
/// [`TOL_JOINTS_TOPPLING`]) of the closed form.
pub fn run(case: Case, closed_form: f64, id: &str) -> Result<JointRun, Error> {
    let (row, result, model) = reduce(case, closed_form, id, tolerance(id))?;
    Ok(JointRun { case, result, closed_form, cells: model.elements.len(), row, model })
}

/// `cdem srm` on `case` and its row `id` against `closed_form`, failed (with
/// the reason) by [`defect`] at tolerance `tol`.
pub fn reduce(case: Case, closed_form: f64, id: &str, tol: f64) -> Result<(Check, SrmResult, Model), Error> {
    let t0 = std::time::Instant::now();
    let (result, model) = run_srm(&case.scene()?, &mut |_| {})?;
    let fs = result.fs.unwrap_or(f64::NAN);
    let mut row = reg::row(id).value(fs, closed_form, t0.elapsed().as_secs_f64());
    if let Some(d) = defect(&result, closed_form, tol) {
        row = row.with_defect(d);
    }
    Ok((row, result, model))
}

/// What is wrong with a reduction, if anything.
pub fn defect(r: &SrmResult, closed_form: f64, tol: f64) -> Option<String> {
    let [Some(lo), Some(hi)] = r.bracket else { return Some(format!("no bracket: {:?}", r.bracket)) };
    let fs = 0.5 * (lo + hi);
    if hi - lo > BRACKET_WIDTH + 1e-12 {
        Some(format!("bracket [{lo:.4}, {hi:.4}] wider than {BRACKET_WIDTH}"))
    } else if r.hi_outcome != Some(EndState::GlobalSliding) {
        Some(format!("the bracket's upper end did not slide: {:?}", r.hi_outcome))
    } else if ((fs - closed_form) / closed_form).abs() > tol {
        Some(format!("FS {fs:.4} more than {tol} from the closed form {closed_form:.4}"))
    } else {
        None
    }
}

/// Every case.
pub fn run_all() -> Result<Vec<JointRun>, Error> {
    cases().iter().map(|&(case, fs, id)| run(case, fs, id)).collect()
}
