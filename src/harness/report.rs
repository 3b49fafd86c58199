//! The validation table: one row per checked number or stated result (case,
//! quantity, ours, reference, relative error, tolerance or goal, source of the
//! reference, run time, result).
//!
//! A row is one of four kinds ([`Kind`]), never confused:
//! - **asserted**: `ok` within its tolerance, `FAIL` outside it (the run
//!   fails); a number that cannot be trusted (a run that did not converge,
//!   [`Check::defect`]) is `FAIL` too;
//! - **reported** against a goal ([`Goal`]): `met` / `not met`, in plain
//!   sight; it never fails the run (a miss of a published band is a
//!   `not met` row, never an `ok`);
//! - **compared**: a qualitative result against a snapshot or the paper's
//!   statement: `match` / `differs` (an asserted comparison that differs is a
//!   `FAIL`);
//! - **skipped**: a check that cannot run here (gmsh absent outside CI), with
//!   its reason.
//!
//! Completeness: every row the table must contain is listed once in the
//! registry ([`crate::harness::registry::ROWS`], a [`RowSpec`] each). Tests
//! make their rows from those specs ([`RowSpec::value`] ...) and record them
//! with [`record`] (one JSON file per test under `target/validation/rows/`);
//! the last test binary (`zz_validation_report`) takes them ([`take_recorded`]:
//! read, then moved aside, so that every row must be written again in the
//! next run) and [`Table::assemble`] sets each row of the registry against what
//! was recorded: a missing row, a stale row (written by a test binary that has
//! been rebuilt since) or a row the registry does not list fails the table.
//! `cdem reproduce` assembles the same table from its own runs.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

/// What a reported row aims at.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Goal {
    /// Relative error to the reference at most this (e.g. a published band).
    Within(f64),
    /// Ours at least the reference (e.g. a speed-up).
    AtLeast,
    /// Ours at most the reference (e.g. a time ratio).
    AtMost,
}

/// The kind of a row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Kind {
    /// Asserted: allowed relative error (`|ours - reference| / |reference|`,
    /// or `|ours|` if the reference is 0).
    Asserted { tolerance: f64 },
    /// Reported against a goal.
    Reported { goal: Goal },
    /// A qualitative result compared with a reference statement; `asserted`:
    /// a difference fails the run.
    Compared { asserted: bool, matches: bool },
    /// Not run here, with the reason.
    Skipped { reason: String },
}

/// The result of a row in the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    Ok,
    Fail,
    Met,
    NotMet,
    Match,
    Differs,
    Skipped,
    /// Listed in the registry, not recorded in this run.
    Missing,
    /// Recorded by a test binary that has been rebuilt since.
    Stale,
    /// Recorded, but not listed in the registry.
    Unlisted,
}

impl Status {
    /// Whether the row fails the table (and the run).
    pub fn fails(self) -> bool {
        matches!(self, Status::Fail | Status::Missing | Status::Stale | Status::Unlisted)
    }
    pub fn label(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Fail => "FAIL",
            Status::Met => "met",
            Status::NotMet => "not met",
            Status::Match => "match",
            Status::Differs => "differs",
            Status::Skipped => "skipped",
            Status::Missing => "FAIL: missing",
            Status::Stale => "FAIL: stale",
            Status::Unlisted => "FAIL: not in the registry",
        }
    }
}

/// One row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Check {
    /// The registry's id of the row ([`RowSpec::id`]).
    pub id: String,
    pub case: String,
    pub quantity: String,
    #[serde(with = "nan_as_null")]
    pub ours: f64,
    #[serde(with = "nan_as_null")]
    pub reference: f64,
    pub kind: Kind,
    /// Where the reference comes from (file under references/).
    pub source: String,
    /// Wall time of the computation behind it (s).
    pub seconds: f64,
    /// Why the number cannot be trusted (e.g. the run did not converge): an
    /// asserted row then fails whatever its error.
    pub defect: Option<String>,
    /// Ours and the reference as text (compared rows).
    pub ours_text: String,
    pub reference_text: String,
    /// A remark shown with the result (e.g. where a miss is explained).
    pub note: String,
}

impl Check {
    /// An asserted row outside the registry (its id is empty: the table
    /// lists it as not in the registry until [`RowSpec`] names it).
    pub fn new(
        case: &str,
        quantity: &str,
        ours: f64,
        reference: f64,
        tolerance: f64,
        source: &str,
        seconds: f64,
    ) -> Self {
        Self {
            id: String::new(),
            case: case.into(),
            quantity: quantity.into(),
            ours,
            reference,
            kind: Kind::Asserted { tolerance },
            source: source.into(),
            seconds,
            defect: None,
            ours_text: String::new(),
            reference_text: String::new(),
            note: String::new(),
        }
    }
    pub fn rel_error(&self) -> f64 {
        if self.reference == 0.0 {
            self.ours.abs()
        } else {
            ((self.ours - self.reference) / self.reference).abs()
        }
    }
    /// The row's own result (before the completeness check of [`Table`]).
    pub fn status(&self) -> Status {
        match &self.kind {
            Kind::Asserted { tolerance } => {
                // A NaN error or tolerance is not within anything.
                if self.defect.is_none() && self.rel_error() <= *tolerance {
                    Status::Ok
                } else {
                    Status::Fail
                }
            }
            Kind::Reported { goal } => {
                let met = self.defect.is_none()
                    && match goal {
                        Goal::Within(t) => self.rel_error() <= *t,
                        Goal::AtLeast => self.ours >= self.reference,
                        Goal::AtMost => self.ours <= self.reference,
                    };
                if met {
                    Status::Met
                } else {
                    Status::NotMet
                }
            }
            Kind::Compared { asserted, matches } => match (matches, asserted) {
                (true, _) => Status::Match,
                (false, true) => Status::Fail,
                (false, false) => Status::Differs,
            },
            Kind::Skipped { .. } => Status::Skipped,
        }
    }
    /// Not failing (ok, met, not met, match, differs, skipped).
    pub fn passed(&self) -> bool {
        !self.status().fails()
    }
    /// The row with a defect (its number cannot be trusted).
    pub fn with_defect(mut self, defect: impl Into<String>) -> Self {
        self.defect = Some(defect.into());
        self
    }
    /// The row with a remark.
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.note = note.into();
        self
    }
}

/// NaN (not representable in JSON) as null.
mod nan_as_null {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};
    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        v.is_finite().then_some(*v).serialize(s)
    }
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
    }
}

/// The kind a [`RowSpec`] fixes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpecKind {
    Asserted(f64),
    Reported(Goal),
    /// Compared; `true`: asserted.
    Compared(bool),
}

/// A row the table must contain, stated once in the registry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowSpec {
    /// Unique, stable id (`case/quantity` in short).
    pub id: &'static str,
    pub case: &'static str,
    pub quantity: &'static str,
    pub kind: SpecKind,
    /// The file under references/ with the reference and the reason for the
    /// tolerance or goal.
    pub source: &'static str,
    /// The test file that records it (`cargo test`).
    pub test: &'static str,
}

impl RowSpec {
    fn base(&self, seconds: f64) -> Check {
        Check {
            id: self.id.into(),
            case: self.case.into(),
            quantity: self.quantity.into(),
            ours: f64::NAN,
            reference: f64::NAN,
            kind: match self.kind {
                SpecKind::Asserted(tolerance) => Kind::Asserted { tolerance },
                SpecKind::Reported(goal) => Kind::Reported { goal },
                SpecKind::Compared(asserted) => Kind::Compared { asserted, matches: false },
            },
            source: self.source.into(),
            seconds,
            defect: None,
            ours_text: String::new(),
            reference_text: String::new(),
            note: String::new(),
        }
    }
    /// A numeric row: ours against the reference.
    pub fn value(&self, ours: f64, reference: f64, seconds: f64) -> Check {
        Check { ours, reference, ..self.base(seconds) }
    }
    /// A compared row: ours and the reference as text, and whether they match.
    pub fn compared(&self, ours: &str, reference: &str, matches: bool, seconds: f64) -> Check {
        let mut c = self.base(seconds);
        if let Kind::Compared { matches: m, .. } = &mut c.kind {
            *m = matches;
        }
        c.ours_text = ours.into();
        c.reference_text = reference.into();
        c
    }
    /// The row, not run here, with the reason.
    pub fn skipped(&self, reason: &str) -> Check {
        Check { kind: Kind::Skipped { reason: reason.into() }, ..self.base(0.0) }
    }
}

/// The assembled table: the registry's rows in its order, each with its
/// result, then the rows the registry does not list.
#[derive(Debug, Clone, Default)]
pub struct Table {
    pub rows: Vec<(Check, Status)>,
}

impl Table {
    /// Sets the registry's rows `expected` against the `recorded` ones.
    /// `stale`: ids recorded by a test binary rebuilt since. `absent`: the
    /// note of a missing row (who should have written it), from its spec.
    pub fn assemble(
        expected: &[RowSpec],
        recorded: Vec<Check>,
        stale: &[String],
        absent: &dyn Fn(&RowSpec) -> String,
    ) -> Self {
        let mut rows = Vec::new();
        let mut left = recorded;
        for spec in expected {
            let found: Vec<Check> = left.iter().filter(|c| c.id == spec.id).cloned().collect();
            left.retain(|c| c.id != spec.id);
            match found.len() {
                0 => {
                    let c = spec.base(0.0).with_note(absent(spec));
                    rows.push((c, Status::Missing));
                }
                n => {
                    let mut c = found[0].clone();
                    let status = if n > 1 {
                        c.note = format!("recorded {n} times");
                        Status::Fail
                    } else if stale.contains(&c.id) {
                        c.note = format!("from an earlier build of {}", spec.test);
                        Status::Stale
                    } else {
                        c.status()
                    };
                    rows.push((c, status));
                }
            }
        }
        for c in left {
            rows.push((c, Status::Unlisted));
        }
        Self { rows }
    }
    /// The failing rows, one line each.
    pub fn failures(&self) -> Vec<String> {
        self.rows
            .iter()
            .filter(|(_, s)| s.fails())
            .map(|(c, s)| {
                let why = c.defect.clone().unwrap_or_else(|| c.note.clone());
                format!("{} ({} / {}): {} {:.2e} {why}", c.id, c.case, c.quantity, s.label(), c.rel_error())
            })
            .collect()
    }
    /// How many rows have each result, e.g. "40 ok, 3 not met, 1 skipped".
    pub fn counts(&self) -> String {
        let all = [
            Status::Ok,
            Status::Fail,
            Status::Met,
            Status::NotMet,
            Status::Match,
            Status::Differs,
            Status::Skipped,
            Status::Missing,
            Status::Stale,
            Status::Unlisted,
        ];
        let parts: Vec<String> = all
            .iter()
            .map(|s| (s, self.rows.iter().filter(|r| r.1 == *s).count()))
            .filter(|(_, n)| *n > 0)
            .map(|(s, n)| format!("{n} {}", s.label()))
            .collect();
        format!("{} rows: {}", self.rows.len(), parts.join(", "))
    }
    /// The table as Markdown.
    pub fn markdown(&self) -> String {
        let mut md = String::from(
            "| case | quantity | ours | reference | rel. error | tolerance / goal | source | time (s) | result |\n\
             |---|---|---|---|---|---|---|---|---|\n",
        );
        let esc = |s: &str| s.replace('|', "\\|");
        for (c, status) in &self.rows {
            let num = |v: f64| if v.is_nan() { "-".to_string() } else { format!("{v:.5e}") };
            let (ours, reference, err) = match &c.kind {
                Kind::Compared { .. } => (c.ours_text.clone(), c.reference_text.clone(), "-".to_string()),
                Kind::Skipped { .. } => ("-".into(), "-".into(), "-".into()),
                _ if *status == Status::Missing => ("-".into(), "-".into(), "-".into()),
                Kind::Reported { goal: Goal::AtLeast | Goal::AtMost } => {
                    (num(c.ours), num(c.reference), "-".to_string())
                }
                _ => (num(c.ours), num(c.reference), format!("{:.2e}", c.rel_error())),
            };
            let bound = match &c.kind {
                Kind::Asserted { tolerance } => format!("{tolerance:.1e}"),
                Kind::Reported { goal: Goal::Within(t) } => format!("goal {t:.1e}"),
                Kind::Reported { goal: Goal::AtLeast } => "goal: at least the reference".into(),
                Kind::Reported { goal: Goal::AtMost } => "goal: at most the reference".into(),
                Kind::Compared { asserted: true, .. } => "asserted".into(),
                Kind::Compared { asserted: false, .. } => "reported".into(),
                Kind::Skipped { .. } => "-".into(),
            };
            let mut result = status.label().to_string();
            for extra in [
                c.defect.as_deref().unwrap_or(""),
                if let Kind::Skipped { reason } = &c.kind { reason } else { "" },
                &c.note,
            ] {
                if !extra.is_empty() {
                    let _ = write!(result, ": {extra}");
                }
            }
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} | {} | {:.2} | {} |",
                esc(&c.case),
                esc(&c.quantity),
                esc(&ours),
                esc(&reference),
                err,
                bound,
                c.source,
                c.seconds,
                esc(&result)
            );
        }
        md
    }
}

/// The rows directory of `cargo test`.
pub fn rows_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("target/validation/rows")
}

/// A test's row file: the rows and the test binary that wrote them.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct RowFile {
    /// The writing executable and its modification time (ns since the epoch).
    writer: String,
    writer_modified_ns: u128,
    rows: Vec<Check>,
}

fn modified_ns(path: &Path) -> Option<u128> {
    let t = std::fs::metadata(path).ok()?.modified().ok()?;
    Some(t.duration_since(std::time::UNIX_EPOCH).ok()?.as_nanos())
}

/// Records a test's rows (overwriting that test's previous rows). A row file
/// that cannot be written is a failure (this is called by tests), not a
/// silently shorter table.
pub fn record(test: &str, checks: &[Check]) {
    record_into(&rows_dir(), test, checks).unwrap_or_else(|e| panic!("validation rows of {test}: {e}"));
}

/// [`record`] into `dir`.
pub fn record_into(dir: &Path, test: &str, checks: &[Check]) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let exe = std::env::current_exe()?;
    let file = RowFile {
        writer: exe.display().to_string(),
        writer_modified_ns: modified_ns(&exe).unwrap_or(0),
        rows: checks.to_vec(),
    };
    let text = serde_json::to_string_pretty(&file).map_err(std::io::Error::other)?;
    let tmp = dir.join(format!(".{test}.json.tmp"));
    std::fs::write(&tmp, text)?;
    std::fs::rename(&tmp, dir.join(format!("{test}.json")))
}

/// What [`take_recorded`] found.
#[derive(Debug, Default)]
pub struct Recorded {
    pub rows: Vec<Check>,
    /// Ids of rows whose writer has been rebuilt since it wrote them.
    pub stale: Vec<String>,
    /// Row files that cannot be read, with the reason.
    pub unreadable: Vec<String>,
}

/// Reads every row file in `dir` and moves it to `dir/../taken/` (so the
/// next report sees only rows written again after this one).
pub fn take_recorded(dir: &Path) -> Recorded {
    let mut out = Recorded::default();
    let taken = dir.with_file_name("taken");
    let _ = std::fs::create_dir_all(&taken);
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    for path in paths {
        let parsed = std::fs::read_to_string(&path)
            .map_err(|e| e.to_string())
            .and_then(|t| serde_json::from_str::<RowFile>(&t).map_err(|e| e.to_string()));
        match parsed {
            Ok(file) => {
                let rebuilt = modified_ns(Path::new(&file.writer)).is_some_and(|m| m != file.writer_modified_ns);
                if rebuilt {
                    out.stale.extend(file.rows.iter().map(|c| c.id.clone()));
                }
                out.rows.extend(file.rows);
            }
            Err(e) => out.unreadable.push(format!("{}: {e}", path.display())),
        }
        if let Some(name) = path.file_name() {
            let _ = std::fs::rename(&path, taken.join(name));
        }
    }
    out
}
