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
//! - **skipped**: a check that cannot run here, with its reason; only a row
//!   whose spec allows it ([`RowSpec::skip`]) may be skipped, and under
//!   `CI=true` no asserted row may ([`Skips::Registry`]).
//!
//! Completeness: every row the table must contain is listed once in the
//! registry ([`crate::harness::registry::ROWS`], a [`RowSpec`] each). Tests
//! make their rows from those specs ([`RowSpec::value`] ...) and record them
//! with [`record`] (one JSON file per test under `target/validation/rows/`);
//! the last test binary (`zz_validation_report`) takes them ([`take_recorded`]:
//! read, then moved aside, so that every row must be written again in the
//! next run) and [`Table::assemble_with`] sets each row of the registry
//! against what was recorded. The table fails on:
//! - a missing row, a row recorded twice, a row the registry does not list;
//! - a **spec mismatch**: a recorded row whose case, quantity, source, kind,
//!   tolerance or goal differ from its spec, or whose reference differs from
//!   the one the spec holds ([`RowSpec::reference`]): the registry, not the
//!   row file, says what a row is;
//! - a skip the spec does not allow;
//! - a **stale** row ([`freshness`]): written by another `cargo test`
//!   invocation, or computed from input files (scene, mesh, reference data)
//!   that have changed since, or whose inputs are missing.
//!
//! `cdem reproduce` and `cdem perf` assemble the same table from their own
//! runs ([`Table::assemble`]); [`header`] gives the commit, date, command and
//! thread count a report starts with; [`html`] makes the report a web page
//! (`report.html`), with [`citations`] (the sections of `references/` the
//! rows cite), [`figures`] (what each figure supports) and [`markdown`].

pub mod citations;
pub mod figures;
pub mod freshness;
pub mod header;
pub mod html;
pub mod inputs;
pub mod markdown;

pub use freshness::{
    current_invocation, record, record_into, record_with, rows_dir, take_recorded, take_recorded_with, Freshness,
    Recorded,
};

use std::collections::BTreeMap;
use std::fmt::Write;

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
    /// Asserted with a direction: the signed relative error
    /// (`(ours - reference) / reference`) at most `above` and at least
    /// `-below`. For a factor of safety `above` is the unsafe side (ours too
    /// high) and `below` the safe side; each bound is derived from the row's
    /// measured error (references/, the row's source, says how).
    Bounded { above: f64, below: f64 },
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
    /// Recorded by another `cargo test` invocation, or from input files that
    /// have changed since (the row's note says which).
    Stale,
    /// Recorded with another case, quantity, source, kind, tolerance, goal or
    /// reference than its spec says (the row's note says which).
    SpecMismatch,
    /// Skipped, but its spec does not allow a skip (or `CI=true` and the row
    /// is asserted).
    SkipRefused,
    /// Recorded, but not listed in the registry.
    Unlisted,
}

impl Status {
    /// Whether the row fails the table (and the run).
    pub fn fails(self) -> bool {
        matches!(
            self,
            Status::Fail
                | Status::Missing
                | Status::Stale
                | Status::SpecMismatch
                | Status::SkipRefused
                | Status::Unlisted
        )
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
            Status::SpecMismatch => "FAIL: spec mismatch",
            Status::SkipRefused => "FAIL: skip not allowed",
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
        self.signed_error().abs()
    }
    /// `(ours - reference) / reference`, or `ours` if the reference is 0.
    pub fn signed_error(&self) -> f64 {
        if self.reference == 0.0 {
            self.ours
        } else {
            (self.ours - self.reference) / self.reference
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
            Kind::Bounded { above, below } => {
                let e = self.signed_error(); // NaN is within nothing
                if self.defect.is_none() && e <= *above && e >= -*below {
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
    /// Asserted with a direction ([`Kind::Bounded`]): (above, below).
    Bounded(f64, f64),
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
    /// The reference value, where the registry holds it as a number (a
    /// published or analytic value, 0 for an error norm): a recorded row with
    /// another reference is a spec mismatch. `None`: the reference is
    /// computed by the test (e.g. our FEM on the same mesh) and only kind,
    /// tolerance or goal, source, case and quantity are compared.
    pub reference: Option<f64>,
    /// `Some(reason)`: the row may be skipped, and why (e.g. gmsh not on
    /// PATH; a timed run only `cdem perf` makes; a flag of `cdem reproduce`
    /// that skips the slow ones). `None`: a skipped row fails. Under
    /// `CI=true` an asserted row may never be skipped.
    pub skip: Option<&'static str>,
}

impl RowSpec {
    /// The spec with its reference value ([`RowSpec::reference`]).
    pub const fn with_reference(mut self, reference: f64) -> Self {
        self.reference = Some(reference);
        self
    }
    /// The spec of a row that may be skipped, and why ([`RowSpec::skip`]).
    pub const fn may_skip(mut self, reason: &'static str) -> Self {
        self.skip = Some(reason);
        self
    }
    /// Whether a failure of the row fails the run (asserted, or an asserted
    /// comparison).
    pub fn is_asserted(&self) -> bool {
        matches!(self.kind, SpecKind::Asserted(_) | SpecKind::Bounded(..) | SpecKind::Compared(true))
    }
    /// How a recorded row differs from this spec (`None`: it does not):
    /// id, case, quantity and source; the kind with its tolerance or goal
    /// (bit for bit: row files keep f64 exactly); the reference if the spec
    /// holds it. A skipped row's kind is judged by [`Skips`], not here.
    pub fn mismatch(&self, c: &Check) -> Option<String> {
        let mut diffs = Vec::new();
        let text = |what: &str, spec: &str, row: &str| format!("{what} {row:?} (the spec: {spec:?})");
        for (what, spec, row) in [
            ("id", self.id, c.id.as_str()),
            ("case", self.case, c.case.as_str()),
            ("quantity", self.quantity, c.quantity.as_str()),
            ("source", self.source, c.source.as_str()),
        ] {
            if spec != row {
                diffs.push(text(what, spec, row));
            }
        }
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        let kind_ok = match (&self.kind, &c.kind) {
            (_, Kind::Skipped { .. }) => true,
            (SpecKind::Asserted(t), Kind::Asserted { tolerance }) => same(*t, *tolerance),
            (SpecKind::Bounded(a, b), Kind::Bounded { above, below }) => same(*a, *above) && same(*b, *below),
            (SpecKind::Reported(g), Kind::Reported { goal }) => match (g, goal) {
                (Goal::Within(a), Goal::Within(b)) => same(*a, *b),
                (a, b) => a == b,
            },
            (SpecKind::Compared(a), Kind::Compared { asserted, .. }) => a == asserted,
            _ => false,
        };
        if !kind_ok {
            diffs.push(format!("kind {:?} (the spec: {:?})", c.kind, self.kind));
        }
        let numeric = matches!(c.kind, Kind::Asserted { .. } | Kind::Bounded { .. } | Kind::Reported { .. });
        if let (Some(r), true) = (self.reference, numeric) {
            if !same(r, c.reference) {
                diffs.push(format!("reference {:e} (the spec: {r:e})", c.reference));
            }
        }
        (!diffs.is_empty()).then(|| diffs.join("; "))
    }
    fn base(&self, seconds: f64) -> Check {
        Check {
            id: self.id.into(),
            case: self.case.into(),
            quantity: self.quantity.into(),
            ours: f64::NAN,
            reference: f64::NAN,
            kind: match self.kind {
                SpecKind::Asserted(tolerance) => Kind::Asserted { tolerance },
                SpecKind::Bounded(above, below) => Kind::Bounded { above, below },
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

/// Which skipped rows a table accepts.
#[derive(Debug, Clone, Copy)]
pub enum Skips<'a> {
    /// Any (the program's own table lists what it does not compute, with
    /// the reason: `cdem reproduce`, `cdem perf` through [`Table::assemble`]).
    Any,
    /// Only rows whose spec allows it ([`RowSpec::skip`]) or that `also`
    /// lists (id, reason: the rows a program does not compute); under `ci`
    /// (`CI=true`) no asserted row, whatever the spec or `also` say.
    Registry { ci: bool, also: &'a [(&'a str, &'a str)] },
}

impl Skips<'_> {
    /// The rule of `cargo test`'s report: the registry's, `CI=true` from the
    /// environment.
    pub fn cargo_test() -> Skips<'static> {
        Skips::Registry { ci: std::env::var("CI").as_deref() == Ok("true"), also: &[] }
    }
    /// Why a skip of `spec` is refused (`None`: it is accepted).
    fn refusal(&self, spec: &RowSpec) -> Option<String> {
        match *self {
            Skips::Any => None,
            Skips::Registry { ci, also } => {
                if ci && spec.is_asserted() {
                    Some("an asserted row may not be skipped under CI=true".into())
                } else if spec.skip.is_none() && !also.iter().any(|(id, _)| *id == spec.id) {
                    Some("its spec does not allow a skip (RowSpec::skip is None)".into())
                } else {
                    None
                }
            }
        }
    }
}

/// How [`Table::assemble_with`] judges the recorded rows.
pub struct Rules<'a> {
    /// Why a recorded row is not fresh, by id ([`Recorded::stale`]).
    pub stale: &'a BTreeMap<String, String>,
    /// The note of a missing row (who should have written it), from its spec.
    pub absent: &'a dyn Fn(&RowSpec) -> String,
    pub skips: Skips<'a>,
}

impl Table {
    /// Sets the registry's rows `expected` against the `recorded` ones, for
    /// a program's own table (`cdem reproduce`, `cdem perf`): a spec
    /// mismatch fails, any skip is accepted ([`Skips::Any`]). `stale`: ids
    /// recorded by an earlier build. `absent`: the note of a missing row.
    pub fn assemble(
        expected: &[RowSpec],
        recorded: Vec<Check>,
        stale: &[String],
        absent: &dyn Fn(&RowSpec) -> String,
    ) -> Self {
        let stale: BTreeMap<String, String> =
            stale.iter().map(|id| (id.clone(), "from an earlier build of its test".to_string())).collect();
        Self::assemble_with(expected, recorded, &Rules { stale: &stale, absent, skips: Skips::Any })
    }

    /// Sets the registry's rows `expected` against the `recorded` ones under
    /// `rules`: each row must be recorded once, fresh, as its spec says, and
    /// skipped only if the rules allow it.
    pub fn assemble_with(expected: &[RowSpec], recorded: Vec<Check>, rules: &Rules) -> Self {
        let mut rows = Vec::new();
        let mut left = recorded;
        for spec in expected {
            let found: Vec<Check> = left.iter().filter(|c| c.id == spec.id).cloned().collect();
            left.retain(|c| c.id != spec.id);
            if found.is_empty() {
                let c = spec.base(0.0).with_note((rules.absent)(spec));
                rows.push((c, Status::Missing));
                continue;
            }
            let mut c = found[0].clone();
            let fail = |c: &mut Check, status: Status, why: String| {
                c.note = if c.note.is_empty() { why } else { format!("{why}; {}", c.note) };
                status
            };
            let status = if found.len() > 1 {
                fail(&mut c, Status::Fail, format!("recorded {} times", found.len()))
            } else if let Some(why) = rules.stale.get(&c.id) {
                fail(&mut c, Status::Stale, why.clone())
            } else if let Some(why) = spec.mismatch(&c) {
                fail(&mut c, Status::SpecMismatch, why)
            } else if let (Kind::Skipped { .. }, Some(why)) = (&c.kind, rules.skips.refusal(spec)) {
                fail(&mut c, Status::SkipRefused, why)
            } else {
                c.status()
            };
            rows.push((c, status));
        }
        for c in left {
            rows.push((c, Status::Unlisted));
        }
        Self { rows }
    }

    /// [`Table::assemble_with`] on what [`take_recorded`] found, under the
    /// skip rule of `cargo test` ([`Skips::cargo_test`]). The row files that
    /// could not be read ([`Recorded::unreadable`]) are the caller's to fail.
    pub fn of_recorded(expected: &[RowSpec], recorded: &Recorded, absent: &dyn Fn(&RowSpec) -> String) -> Self {
        let rules = Rules { stale: &recorded.stale, absent, skips: Skips::cargo_test() };
        Self::assemble_with(expected, recorded.rows.clone(), &rules)
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
            Status::SpecMismatch,
            Status::SkipRefused,
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
            let [ours, reference, err, bound] = cells(c, *status);
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

/// A number as the tables show it (`-` for NaN).
pub(crate) fn num(v: f64) -> String {
    if v.is_nan() {
        "-".to_string()
    } else {
        format!("{v:.5e}")
    }
}

/// (ours, reference, relative error, tolerance or goal) as both tables (the
/// markdown and the web page) show them; a bounded row's error is signed.
pub(crate) fn cells(c: &Check, status: Status) -> [String; 4] {
    let (ours, reference, err) = match &c.kind {
        Kind::Compared { .. } => (c.ours_text.clone(), c.reference_text.clone(), "-".to_string()),
        Kind::Skipped { .. } => ("-".into(), "-".into(), "-".into()),
        _ if status == Status::Missing => ("-".into(), "-".into(), "-".into()),
        Kind::Reported { goal: Goal::AtLeast | Goal::AtMost } => (num(c.ours), num(c.reference), "-".to_string()),
        Kind::Bounded { .. } => (num(c.ours), num(c.reference), format!("{:+.2e}", c.signed_error())),
        _ => (num(c.ours), num(c.reference), format!("{:.2e}", c.rel_error())),
    };
    let bound = match &c.kind {
        Kind::Asserted { tolerance } => format!("{tolerance:.1e}"),
        Kind::Bounded { above, below } => format!("+{above:.1e} / -{below:.1e}"),
        Kind::Reported { goal: Goal::Within(t) } => format!("goal {t:.1e}"),
        Kind::Reported { goal: Goal::AtLeast } => "goal: at least the reference".into(),
        Kind::Reported { goal: Goal::AtMost } => "goal: at most the reference".into(),
        Kind::Compared { asserted: true, .. } => "asserted".into(),
        Kind::Compared { asserted: false, .. } => "reported".into(),
        Kind::Skipped { .. } => "-".into(),
    };
    [ours, reference, err, bound]
}
