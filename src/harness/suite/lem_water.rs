//! The LEM with pore water against the published water benchmarks
//! (references/lem.md, "With water"; tests/lem_water.rs and `cdem
//! reproduce`): Fredlund & Krahn's (1977) r_u = 0.25 on their circle,
//! Arai & Tagyo's (1985) slope with a water table, and ACADS 1(b) with a
//! water-filled tension crack, each against Slide2's verification manual
//! and its paper or referee.

use std::path::Path;

use crate::error::{Error, SceneError};
use crate::harness::registry::{self as reg, Reference};
use crate::harness::report::Check;
use crate::lem::{analyse, LemInput, LemResult, Method};

/// One water case: its file, its result and its rows.
pub struct WaterRun {
    pub file: &'static str,
    pub result: LemResult,
    pub rows: Vec<Check>,
}

/// `(row id, method, published value)` of each case's rows.
type RowRefs = &'static [(&'static str, Method, Reference)];

const CASES: [(&str, RowRefs); 3] = [
    (
        reg::LEM_FK_RU,
        &[
            ("lem/water-fk-ru/ordinary-vs-fk", Method::Ordinary, reg::FK_RU_ORDINARY),
            ("lem/water-fk-ru/bishop-vs-fk", Method::Bishop, reg::FK_RU_BISHOP),
            ("lem/water-fk-ru/spencer-vs-fk", Method::Spencer, reg::FK_RU_SPENCER),
            ("lem/water-fk-ru/bishop-vs-slide", Method::Bishop, reg::FK_RU_SLIDE_BISHOP),
            ("lem/water-fk-ru/spencer-vs-slide", Method::Spencer, reg::FK_RU_SLIDE_SPENCER),
        ],
    ),
    (
        reg::LEM_ARAI_TAGYO,
        &[
            ("lem/water-arai-tagyo/bishop-vs-slide", Method::Bishop, reg::ARAI_TAGYO_SLIDE_BISHOP),
            ("lem/water-arai-tagyo/spencer-vs-slide", Method::Spencer, reg::ARAI_TAGYO_SLIDE_SPENCER),
            ("lem/water-arai-tagyo/bishop-vs-paper", Method::Bishop, reg::ARAI_TAGYO_PAPER),
        ],
    ),
    (
        reg::LEM_ACADS_1B,
        &[
            ("lem/water-acads-1b/bishop-vs-slide", Method::Bishop, reg::ACADS_1B_SLIDE_BISHOP),
            ("lem/water-acads-1b/spencer-vs-slide", Method::Spencer, reg::ACADS_1B_SLIDE_SPENCER),
            ("lem/water-acads-1b/bishop-vs-referee", Method::Bishop, reg::ACADS_1B_REFEREE),
        ],
    ),
];

/// Runs one case file (its own circle or search) and its rows.
fn run(file: &'static str, refs: RowRefs) -> Result<WaterRun, Error> {
    let result = analyse(&LemInput::load(Path::new(file))?)?;
    let mut rows = Vec::with_capacity(refs.len());
    for (id, m, reference) in refs {
        let fs = *result
            .fs
            .get(*m)
            .ok_or_else(|| Error::from(SceneError::invalid("lem", format!("{file}: no {} FS", m.name()))))?;
        rows.push(reg::row(id).value(fs, reference.value, result.wall_s));
    }
    Ok(WaterRun { file, result, rows })
}

/// The three cases, in the registry's order.
pub fn runs() -> Result<Vec<WaterRun>, Error> {
    CASES.iter().map(|(file, refs)| run(file, refs)).collect()
}

/// Every water row.
pub fn rows() -> Result<Vec<Check>, Error> {
    Ok(runs()?.into_iter().flat_map(|r| r.rows).collect())
}
