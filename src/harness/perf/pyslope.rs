//! The LEM slip-circle search timed against pySlope: the same work as
//! scripts/pyslope_check.py times in pySlope (Bishop on the default
//! 20 x 20 x 10 grid, no entry-exit search, no refinement, one thread), the
//! best of a few runs, and pySlope's recorded time from
//! references/pyslope.json.

use std::path::Path;
use std::time::Instant;

use crate::error::Error;
use crate::harness::registry;

/// LEM cases timed against pySlope: (name in references/pyslope.json, input).
pub const LEM_CASES: [(&str, &str); 2] =
    [("paper_slope", registry::LEM_PAPER_SLOPE_EXPLICIT.input), ("acads_1a", registry::LEM_ACADS_1A.input)];

/// `base` with the search pySlope's timing repeats (scripts/pyslope_check.py):
/// Bishop on the default 20 x 20 x 10 grid only, no entry-exit search, no
/// refinement, one thread.
pub fn pyslope_grid_search(base: crate::lem::LemInput) -> crate::lem::LemInput {
    use crate::lem::{LemInput, Method, Mode, SearchSpec};
    let spec = SearchSpec { entry_exit: None, refine: false, parallel: false, ..SearchSpec::default() };
    LemInput { mode: Mode::Search(spec), methods: vec![Method::Bishop], ..base }
}

/// The time of [`pyslope_grid_search`] on the LEM input at `input`: best of
/// `repeats` (s).
pub fn time_lem_grid(input: &Path, repeats: usize) -> Result<f64, Error> {
    let input = pyslope_grid_search(crate::lem::LemInput::load(input)?);
    let mut best = f64::INFINITY;
    for _ in 0..repeats.max(1) {
        let t = Instant::now();
        crate::lem::analyse(&input)?;
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok(best)
}

/// pySlope's recorded time for our grid (`cases.<case>.timing_our_grid.total_s`).
pub fn pyslope_seconds(json: &Path, case: &str) -> Result<f64, Error> {
    let text = std::fs::read_to_string(json).map_err(|e| Error::io(json, e))?;
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| Error::io(json, std::io::Error::other(e)))?;
    v["cases"][case]["timing_our_grid"]["total_s"]
        .as_f64()
        .ok_or_else(|| Error::io(json, std::io::Error::other(format!("no cases.{case}.timing_our_grid.total_s"))))
}
