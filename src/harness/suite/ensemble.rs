//! The analytic ensemble (references/ensemble.md, tests/ensemble.rs): a
//! purely cohesive circular segment whose FS is `kappa c` exactly, with `c`
//! normal, so the FS is normal with known mean and deviation and
//! `PF = Phi((1 - mean) / deviation)`. Rows `ensemble/segment/mean` and
//! `ensemble/segment/pf`.

use std::path::Path;

use crate::analysis::stats::normal_cdf;
use crate::drivers::ensemble::{aggregate, mean_critical_circle, run_members, EnsembleInput, EnsembleSummary};
use crate::error::Error;
use crate::harness::registry as reg;
use crate::harness::report::Check;

/// The input.
pub const SEGMENT: &str = "verification/ensemble/cohesive-segment.toml";
/// The normal cohesion of the input (Pa): mean and deviation.
pub const COHESION: (f64, f64) = (38523.203379970284, 4815.4004224962855);

/// kappa of FS = kappa c for the circular segment of [`SEGMENT`] (ground
/// z = s x, circle centre (0, zc), radius r, unit weight gamma): half-angle
/// t = acos(d / r), d = zc / sqrt(1 + s^2); area r^2 (t - sin t cos t); arc
/// 2 r t; centroid 2 r sin^3 t / (3 (t - sin t cos t)) from the centre, its
/// lever arm that times s / sqrt(1 + s^2). FS = c (2 r t) r / (gamma A x_g).
pub fn segment_kappa() -> f64 {
    let (s, zc, r, gamma) = (0.5f64, 12.0f64, 20.0f64, 18e3);
    let k = (1.0 + s * s).sqrt();
    let t = (zc / k / r).acos();
    let area = r * r * (t - t.sin() * t.cos());
    let g = 2.0 * r * t.sin().powi(3) / (3.0 * (t - t.sin() * t.cos()));
    2.0 * r * t * r / (gamma * area * g * s / k)
}

/// The ensemble and the exact values.
pub struct Segment {
    pub members: usize,
    pub summary: EnsembleSummary,
    /// Exact mean, deviation and PF of the FS.
    pub mean: f64,
    pub sd: f64,
    pub pf: f64,
    pub rows: Vec<Check>,
}

/// The default members of [`SEGMENT`] (4000), their statistics and rows. A
/// row fails (with the reason) if the exact value is outside the ensemble's
/// own 95 % interval or a member has no FS.
pub fn segment(root: &Path) -> Result<Segment, Error> {
    let t0 = std::time::Instant::now();
    let input = EnsembleInput::load(&root.join(SEGMENT))?;
    let (mean, sd) = (segment_kappa() * COHESION.0, segment_kappa() * COHESION.1);
    let pf = normal_cdf((1.0 - mean) / sd);
    let n = input.default_members();
    let circle = mean_critical_circle(&input)?;
    let records = run_members(&input, input.default_seed(), 0..n, circle, &mut |_| {})?;
    let summary = aggregate("cohesive-segment", 7, &input.analyses, None, circle, &records);
    let t = t0.elapsed().as_secs_f64();
    let (fs, rel) = (summary.fs.as_ref(), summary.reliability.as_ref());
    let mut mean_row = reg::row("ensemble/segment/mean").value(fs.map_or(f64::NAN, |f| f.mean), mean, t);
    let mut pf_row = reg::row("ensemble/segment/pf").value(rel.map_or(f64::NAN, |r| r.probability_of_failure), pf, t);
    if summary.members_without_fs > 0 {
        let d = format!("{} members without an FS", summary.members_without_fs);
        mean_row = mean_row.with_defect(d.clone());
        pf_row = pf_row.with_defect(d);
    }
    if let Some(ci) = fs.map(|f| f.mean_ci95).filter(|ci| !(ci[0] <= mean && mean <= ci[1])) {
        mean_row = mean_row.with_defect(format!("exact mean {mean} outside the 95 % interval {ci:?}"));
    }
    if let Some(ci) = rel.map(|r| r.pf_ci95).filter(|ci| !(ci[0] <= pf && pf <= ci[1])) {
        pf_row = pf_row.with_defect(format!("exact PF {pf:.5} outside the 95 % interval {ci:?}"));
    }
    Ok(Segment { members: n, summary, mean, sd, pf, rows: vec![mean_row, pf_row] })
}
