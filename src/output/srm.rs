//! The files of a strength reduction ([`write_srm`]): `srm.json`
//! ([`SrmResult`]: `fs`, `bracket` [lo, hi], `trials` [{`factor`, `outcome`,
//! `steps`, `max_displacement`, `failed_springs`}], `elastic_steps`,
//! `trial_budget`, `wall_s`, `reduced`: what was divided by F, `model`: which
//! model answered and its note) and, if a trial was unstable,
//! `mechanism.vtu`: the point field `displacement` is the displacement since
//! the elastic state at the smallest unstable factor, and with plastic
//! blocks the cell fields of [`vtk::plastic_fields`] mark the slip band and
//! the tension cracks. Staged like a run's files.

use std::path::Path;

use super::{staged, vtk, write_json};
use crate::drivers::SrmResult;
use crate::error::Error;
use crate::model::Model;

/// Writes `srm.json` and the mechanism into `out` (see the module doc).
pub fn write_srm(result: &SrmResult, model: &Model, out: &Path) -> Result<(), Error> {
    staged(out, |dir| {
        let mut files = vec!["srm.json".to_string()];
        write_json(&dir.join("srm.json"), result)?;
        if let Some(u) = &result.mechanism {
            let fields = result.mechanism_cells.as_deref().map(vtk::plastic_fields).unwrap_or_default();
            vtk::write_vtu(&dir.join("mechanism.vtu"), model, &vtk::Frame { u, stress: None, cells: &fields })?;
            files.push("mechanism.vtu".into());
        }
        Ok(files)
    })
}
