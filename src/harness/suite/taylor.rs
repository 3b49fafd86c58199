//! Taylor's stability chart for purely cohesive slopes (references/lem.md,
//! "Taylor's chart", tests/lem.rs): a slope of height H at beta deg in a
//! soil of cohesion c and unit weight gamma, phi = 0, slip circles not below
//! the toe's level (a base at toe level, no foundation layer), has the
//! factor of safety F = c / (N gamma H), N Taylor's stability number.

use std::path::Path;

use crate::error::Error;
use crate::harness::registry::{self as reg, Reference};
use crate::harness::report::Check;
use crate::lem::{analyse, CriticalCircle, LemInput, LemResult, Method};

/// H (m), c (Pa), gamma (N/m^3) of the chart cases.
pub const HEIGHT: f64 = 10.0;
pub const COHESION: f64 = 20e3;
pub const UNIT_WEIGHT: f64 = 20e3;

/// The LEM file of the slope at `beta` deg with `slices` slices (a vertical
/// face is 1 mm wide: the ground's x must increase strictly).
pub fn taylor_text(beta: f64, slices: usize) -> String {
    let dx = (HEIGHT / beta.to_radians().tan()).max(1e-3);
    format!(
        "[section]\nground = [[0.0, 0.0], [20.0, 0.0], [{}, {HEIGHT}], [60.0, {HEIGHT}]]\nz_min = 0.0\n\
         [[material]]\ncohesion = {COHESION}\nfriction_angle = 0.0\nunit_weight = {UNIT_WEIGHT}\n[analysis]\nslices = {slices}\n",
        20.0 + dx
    )
}

/// One chart case: our Bishop minimum (100 slices), the chart's F and row `id`.
pub struct TaylorRun {
    pub result: LemResult,
    pub bishop: CriticalCircle,
    /// Taylor's F = c / (N gamma H).
    pub expected: f64,
    pub row: Check,
}

/// Runs the chart case at `beta` deg against Taylor's number `n`.
pub fn run(beta: f64, n: Reference, id: &str) -> Result<TaylorRun, Error> {
    let input = LemInput::from_toml(&taylor_text(beta, 100), Path::new("verification/lem"), Path::new("inline.toml"))?;
    let result = analyse(&input)?;
    let bishop = *result.critical.get(Method::Bishop).ok_or_else(|| {
        Error::from(crate::error::SceneError::invalid("lem", format!("Taylor {beta} deg: no Bishop critical circle")))
    })?;
    let expected = COHESION / (n.value * UNIT_WEIGHT * HEIGHT);
    let row = reg::row(id).value(bishop.fs, expected, result.wall_s);
    Ok(TaylorRun { result, bishop, expected, row })
}

/// The three chart rows (60, 75 and 90 deg).
pub fn rows() -> Result<Vec<Check>, Error> {
    [
        (60.0, reg::TAYLOR_N_60, "lem/taylor-60"),
        (75.0, reg::TAYLOR_N_75, "lem/taylor-75"),
        (90.0, reg::TAYLOR_N_90, "lem/taylor-90"),
    ]
    .into_iter()
    .map(|(beta, n, id)| run(beta, n, id).map(|r| r.row))
    .collect()
}
