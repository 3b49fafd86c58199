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

/// The time of the search `input` (made by [`pyslope_grid_search`]): best of
/// `repeats` (s).
pub fn time_lem_grid(input: &crate::lem::LemInput, repeats: usize) -> Result<f64, Error> {
    let mut best = f64::INFINITY;
    for _ in 0..repeats.max(1) {
        let t = Instant::now();
        crate::lem::analyse(input)?;
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

/// pySlope's time for our grid on `case`, measured now: runs
/// `python scripts/pyslope_check.py --time-grid CASE` under `root` (pySlope
/// installed for that interpreter, scripts/requirements-lem.txt) and reads
/// `total_s` from the JSON line it prints; the best of `repeats` (s).
pub fn time_pyslope_grid(python: &Path, root: &Path, case: &str, repeats: usize) -> Result<f64, Error> {
    let script = root.join("scripts/pyslope_check.py");
    let mut best = f64::INFINITY;
    for _ in 0..repeats.max(1) {
        let out = std::process::Command::new(python)
            .arg(&script)
            .args(["--time-grid", case])
            .current_dir(root)
            .output()
            .map_err(|e| Error::io(python, e))?;
        let fail = |why: String| Error::io(&script, std::io::Error::other(why));
        if !out.status.success() {
            return Err(fail(format!(
                "{} --time-grid {case} exited with {}: {}",
                python.display(),
                out.status,
                String::from_utf8_lossy(&out.stderr).lines().last().unwrap_or("")
            )));
        }
        let text = String::from_utf8_lossy(&out.stdout);
        let line = text.lines().rev().find(|l| l.trim_start().starts_with('{')).unwrap_or("");
        let v: serde_json::Value =
            serde_json::from_str(line).map_err(|e| fail(format!("no JSON timing line in its output: {e}")))?;
        let t = v["total_s"].as_f64().ok_or_else(|| fail("no total_s in its timing line".into()))?;
        best = best.min(t);
    }
    Ok(best)
}
