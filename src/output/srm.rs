//! The files of a strength reduction ([`write_srm`]): `srm.json`
//! ([`SrmResult`]: `fs`, `bracket` [lo, hi], `trials` [{`factor`, `outcome`,
//! `steps`, `max_displacement`, `failed_springs`}], `elastic_steps`,
//! `trial_budget`, `wall_s`) and, if a trial was unstable, `mechanism.vtu`:
//! the point field `displacement` is the displacement since the elastic
//! state at the smallest unstable factor. Staged like a run's files.

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
            vtk::write_vtu(&dir.join("mechanism.vtu"), model, &vtk::Frame { u, stress: None })?;
            files.push("mechanism.vtu".into());
        }
        Ok(files)
    })
}
