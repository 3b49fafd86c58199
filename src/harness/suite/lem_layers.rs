//! A layered section in limit equilibrium (references/lem.md, "Layered
//! sections"; tests/lem.rs): ACADS 1(c), three soils, searched with the
//! default 50 slices and with 400; the slices end where the arc changes
//! material, so the two agree (row `lem/acads-1c/slices-50-vs-400`).

use crate::error::Error;
use crate::harness::registry as reg;
use crate::lem::{analyse, LemInput, LemResult};

/// ACADS 1(c) searched with its input's 50 slices and with 400.
pub fn acads_1c() -> Result<(LemResult, LemResult), Error> {
    let input = LemInput::load(std::path::Path::new(reg::LEM_ACADS_1C))?;
    let fine = LemInput { slices: 400, ..input.clone() };
    Ok((analyse(&input)?, analyse(&fine)?))
}
