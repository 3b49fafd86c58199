//! The validation table: one row per checked number (case, quantity, ours,
//! reference, relative error, tolerance, source of the reference, run time).
//!
//! Tests record their rows with [`record`] (one JSON file per test under
//! `target/validation/rows/`); the last test binary (`zz_validation_report`)
//! prints them as one table and writes `target/validation-report.md`.
//! `cdem reproduce` builds the same table from its own runs.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

/// One checked number.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Check {
    pub case: String,
    pub quantity: String,
    pub ours: f64,
    pub reference: f64,
    /// Allowed relative error (`|ours - reference| / |reference|`); None: reported only.
    pub tolerance: Option<f64>,
    /// Where the reference comes from (file under references/).
    pub source: String,
    /// Wall time of the computation behind it (s).
    pub seconds: f64,
}

impl Check {
    /// A check; a NaN `tolerance` makes a reported-only row.
    pub fn new(
        case: &str,
        quantity: &str,
        ours: f64,
        reference: f64,
        tolerance: f64,
        source: &str,
        seconds: f64,
    ) -> Self {
        let tolerance = (!tolerance.is_nan()).then_some(tolerance);
        Self {
            case: case.into(),
            quantity: quantity.into(),
            ours,
            reference,
            tolerance,
            source: source.into(),
            seconds,
        }
    }
    pub fn rel_error(&self) -> f64 {
        if self.reference == 0.0 {
            self.ours.abs()
        } else {
            ((self.ours - self.reference) / self.reference).abs()
        }
    }
    /// Within tolerance (a reported-only row passes).
    pub fn passed(&self) -> bool {
        self.tolerance.is_none_or(|t| self.rel_error() <= t)
    }
}

/// The table as Markdown.
pub fn markdown_table(checks: &[Check]) -> String {
    let mut md = String::from("| case | quantity | ours | reference | rel. error | tolerance | source | time (s) | |\n|---|---|---|---|---|---|---|---|---|\n");
    for c in checks {
        let tol = c.tolerance.map_or("reported".to_string(), |t| format!("{t:.1e}"));
        let _ = writeln!(
            md,
            "| {} | {} | {:.5e} | {:.5e} | {:.2e} | {} | {} | {:.2} | {} |",
            c.case.replace('|', "\\|"),
            c.quantity.replace('|', "\\|"),
            c.ours,
            c.reference,
            c.rel_error(),
            tol,
            c.source,
            c.seconds,
            if c.passed() { "ok" } else { "FAIL" }
        );
    }
    md
}

fn rows_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("target/validation/rows")
}

/// Records a test's rows (overwriting that test's previous rows).
pub fn record(test: &str, checks: &[Check]) {
    let dir = rows_dir();
    let _ = std::fs::create_dir_all(&dir);
    if let Ok(text) = serde_json::to_string_pretty(checks) {
        let _ = std::fs::write(dir.join(format!("{test}.json")), text);
    }
}

/// All recorded rows with the age of their file (s), sorted by test name.
pub fn recorded() -> Vec<(String, f64, Vec<Check>)> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(rows_dir()).into_iter().flatten().flatten() {
        let path = e.path();
        let age = e
            .metadata()
            .ok()
            .and_then(|m| m.modified().ok())
            .and_then(|t| t.elapsed().ok())
            .map_or(f64::INFINITY, |d| d.as_secs_f64());
        if let Some(rows) =
            std::fs::read_to_string(&path).ok().and_then(|t| serde_json::from_str::<Vec<Check>>(&t).ok())
        {
            out.push((path.file_stem().unwrap_or_default().to_string_lossy().into_owned(), age, rows));
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}
