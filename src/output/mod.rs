//! Writing results: `summary.json`, `history.csv`, VTK frames (`.vtu` +
//! `.pvd`), the phase-2 tables, and the FEM's files ([`fem`]); with the
//! feature `plot`, the product's figures ([`figures`]: `analysis.png`,
//! `mechanism.png`, the ensemble's). It writes what the drivers return.
//!
//! Every file is written to a temporary name and renamed; a run's files are
//! written into a staging directory and moved into place together
//! ([`write_run`]), so a failed run leaves nothing half-written behind.

pub mod analysis;
pub mod ensemble;
pub mod fem;
#[cfg(feature = "plot")]
pub mod figures;
pub mod run;
pub mod srm;
pub mod vtk;

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::error::Error;

pub use fem::write_fem;
pub use run::write_run;
pub use srm::write_srm;

pub use crate::atomic::partial_path;

/// Writes `bytes` to `path` atomically ([`crate::atomic::write_atomic`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    crate::atomic::write_atomic(path, bytes).map_err(|e| Error::io(path, e))
}

/// Moves the finished `tmp` into place as `path` ([`crate::atomic::commit`]).
pub fn commit(tmp: &Path, path: &Path) -> Result<(), Error> {
    crate::atomic::commit(tmp, path).map_err(|e| Error::io(path, e))
}

pub fn write_json<T: Serialize>(path: &Path, value: &T) -> Result<(), Error> {
    let text = serde_json::to_string_pretty(value).map_err(|e| Error::io(path, std::io::Error::other(e)))?;
    write_atomic(path, text.as_bytes())
}

/// Writes serialisable rows as CSV (header from the field names).
pub fn write_csv<T: Serialize>(path: &Path, rows: impl IntoIterator<Item = T>) -> Result<(), Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r).map_err(|e| Error::io(path, std::io::Error::other(e)))?;
    }
    let bytes = w.into_inner().map_err(|e| Error::io(path, std::io::Error::other(e.to_string())))?;
    write_atomic(path, &bytes)
}

/// A sibling of `out` named `.<name>.partial-<pid>`.
pub fn staging_dir(out: &Path) -> PathBuf {
    let name = out.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "out".into());
    out.with_file_name(format!(".{name}.partial-{}", std::process::id()))
}

/// Runs `write` on a fresh staging directory, which returns the names of the
/// files it wrote; moves them all into `out` only if it succeeded, then
/// removes the staging directory.
pub fn staged(out: &Path, write: impl FnOnce(&Path) -> Result<Vec<String>, Error>) -> Result<(), Error> {
    let staging = staging_dir(out);
    let _ = std::fs::remove_dir_all(&staging);
    let written = std::fs::create_dir_all(&staging).map_err(|e| Error::io(&staging, e)).and_then(|_| write(&staging));
    let moved = written.and_then(|files| {
        std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
        for f in files {
            std::fs::rename(staging.join(&f), out.join(&f)).map_err(|e| Error::io(out.join(&f), e))?;
        }
        Ok(())
    });
    let _ = std::fs::remove_dir_all(&staging);
    moved
}
