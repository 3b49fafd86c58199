//! The files of a scene's `[analysis]` ([`write_analysis`]):
//! - `analysis.json` ([`AnalysisReport`]): the circle and its arc, the state,
//!   where the strength comes from, and per traction source (`stresses`,
//!   `springs`) eq. 21 K, its resisting and driving sums and the K_i sign
//!   segments;
//! - `analysis.csv`: one row per point, toe to crest: `source` (`stresses`
//!   or `springs`), arc length `s` (m), `x`, `z` (m), `area` (m^2; per metre
//!   of width for stations), `sigma_n` (Pa, compression positive), `tau`
//!   (Pa, positive down-slope), `cohesion` (Pa), `friction_angle` (deg) and
//!   eq. 22 `k_i`.

use std::path::Path;

use serde::Serialize;

use super::{write_csv, write_json};
use crate::drivers::analysis::Factors;
use crate::drivers::AnalysisReport;
use crate::error::Error;

#[derive(Serialize)]
struct Row {
    source: &'static str,
    s: f64,
    x: f64,
    z: f64,
    area: f64,
    sigma_n: f64,
    tau: f64,
    cohesion: f64,
    friction_angle: f64,
    k_i: f64,
}

/// Writes `analysis.json` and `analysis.csv` into `dir`; returns their names.
pub fn write_analysis(report: &AnalysisReport, dir: &Path) -> Result<Vec<String>, Error> {
    write_json(&dir.join("analysis.json"), report)?;
    let rows = |source: &'static str, f: &Factors| -> Vec<Row> {
        f.points
            .iter()
            .zip(&f.k_i)
            .zip(&f.strength)
            .map(|((p, &k_i), &(cohesion, friction_angle))| {
                let [x, z] = report.arc.point_at(p.s);
                Row {
                    source,
                    s: p.s,
                    x,
                    z,
                    area: p.area,
                    sigma_n: p.sigma_n,
                    tau: p.tau,
                    cohesion,
                    friction_angle,
                    k_i,
                }
            })
            .collect()
    };
    let mut all = rows("stresses", &report.stresses);
    if let Some(sp) = &report.springs {
        all.extend(rows("springs", sp));
    }
    write_csv(&dir.join("analysis.csv"), all)?;
    Ok(vec!["analysis.json".into(), "analysis.csv".into()])
}
