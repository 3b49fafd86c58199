//! Strength reduction (`cdem srm`) of the block on a plane against the
//! analytic factor of safety (references/srm.md, tests/srm.rs):
//! `FS = (c A + W cos(theta) tan(phi)) / (W sin(theta))`, rows
//! `srm/block-friction` and `srm/block-cohesion`.

use crate::drivers::{run_srm, SrmResult};
use crate::error::Error;
use crate::harness::registry::{self as reg, BlockOnPlane, Case};
use crate::harness::report::Check;
use crate::EndState;

/// The widest final bracket the SRM may leave (references/srm.md).
pub const BRACKET_WIDTH: f64 = 0.01;

/// One case: the reduction, the analytic FS and the row.
pub struct BlockSrm {
    pub case: Case,
    pub result: SrmResult,
    pub analytic: f64,
    pub row: Check,
}

/// The two cases: friction only, then with cohesion.
pub const CASES: [(Case, BlockOnPlane, &str); 2] = [
    (reg::BLOCK_SRM_FRICTION, reg::BLOCK_SRM_FRICTION_SET, "srm/block-friction"),
    (reg::BLOCK_SRM_COHESION, reg::BLOCK_SRM_COHESION_SET, "srm/block-cohesion"),
];

/// Runs `case`; its row fails (with the reason) unless the reduction found
/// a bracket at most [`BRACKET_WIDTH`] wide that contains the analytic FS,
/// whose upper end is a trial that slid.
pub fn run(case: Case, set: BlockOnPlane, id: &str) -> Result<BlockSrm, Error> {
    let t0 = std::time::Instant::now();
    let (result, _) = run_srm(&case.scene()?, &mut |_| {})?;
    let analytic = set.fs();
    let mut row = reg::row(id).value(result.fs.unwrap_or(f64::NAN), analytic, t0.elapsed().as_secs_f64());
    if let Some(d) = defect(&result, analytic) {
        row = row.with_defect(d);
    }
    Ok(BlockSrm { case, result, analytic, row })
}

/// What is wrong with a reduction of the block, if anything.
pub fn defect(r: &SrmResult, analytic: f64) -> Option<String> {
    let [Some(lo), Some(hi)] = r.bracket else { return Some(format!("no bracket: {:?}", r.bracket)) };
    if hi - lo > BRACKET_WIDTH + 1e-12 {
        Some(format!("bracket [{lo:.4}, {hi:.4}] wider than {BRACKET_WIDTH}"))
    } else if !(lo <= analytic && analytic <= hi) {
        Some(format!("analytic FS {analytic:.4} outside the bracket [{lo:.4}, {hi:.4}]"))
    } else if r.hi_outcome != Some(EndState::GlobalSliding) {
        Some(format!("the bracket's upper end did not slide: {:?}", r.hi_outcome))
    } else {
        None
    }
}

/// Both cases.
pub fn run_all() -> Result<Vec<BlockSrm>, Error> {
    CASES.iter().map(|&(case, set, id)| run(case, set, id)).collect()
}
