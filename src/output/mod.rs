//! Outputs of a run: `summary.json`, `history.csv`, VTK frames (`.vtu` + `.pvd`).
//! Every file is written to a temporary name and renamed, so a failed run
//! leaves no half-written file behind.

pub mod figures;
pub mod section;
pub mod vtk;

use std::io::Write;
use std::path::Path;

use serde::Serialize;

use crate::error::Error;
use crate::solver::HistoryRow;

/// Writes `bytes` to `path` atomically (temporary file + rename).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let tmp = path.with_extension(format!("{}.partial", path.extension().and_then(|e| e.to_str()).unwrap_or("")));
    let mut f = std::fs::File::create(&tmp).map_err(|e| Error::io(&tmp, e))?;
    f.write_all(bytes).and_then(|_| f.sync_all()).map_err(|e| Error::io(&tmp, e))?;
    std::fs::rename(&tmp, path).map_err(|e| Error::io(path, e))
}

pub fn write_json<T: Serialize>(path: &Path, value: &T) -> Result<(), Error> {
    let text = serde_json::to_string_pretty(value).expect("summary serialises");
    write_atomic(path, text.as_bytes())
}

pub fn write_history(path: &Path, rows: &[HistoryRow]) -> Result<(), Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r).map_err(|e| Error::io(path, std::io::Error::other(e)))?;
    }
    let bytes = w.into_inner().map_err(|e| Error::io(path, std::io::Error::other(e.to_string())))?;
    write_atomic(path, &bytes)
}
