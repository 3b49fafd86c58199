//! Files that appear whole or not at all: every file the commands write goes
//! through [`write_atomic`] (a temporary sibling, `fsync`, rename, then the
//! directory synced), or is written under a [`partial_path`] and moved into
//! place with [`commit`]. A process killed at any instant leaves either the
//! old file, the new one, or a stray `.partial` sibling, never a torn file.

use std::io::Write;
use std::path::{Path, PathBuf};

/// A temporary sibling of `path` for this process and this write:
/// `.NAME.partial-PID-N.EXT` (`N` counts the writes of the process, so that
/// two threads writing the same file never share a temporary file).
pub fn partial_path(path: &Path) -> PathBuf {
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let ext = path.extension().map(|e| format!(".{}", e.to_string_lossy())).unwrap_or_default();
    static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    path.with_file_name(format!(".{stem}.partial-{}-{n}{ext}", std::process::id()))
}

/// Writes `bytes` to `path` atomically (temporary sibling, fsync, rename,
/// directory fsync). The error is the file system's (the caller names the path:
/// this layer-0 module imports nothing of the crate).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = partial_path(path);
    let written = std::fs::File::create(&tmp).and_then(|mut f| f.write_all(bytes).and_then(|_| f.sync_all()));
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(e);
    }
    rename_synced(&tmp, path)
}

/// Moves the finished file `tmp` (a [`partial_path`]) to `path`: its bytes
/// synced first, the directory after.
pub fn commit(tmp: &Path, path: &Path) -> std::io::Result<()> {
    std::fs::File::open(tmp).and_then(|f| f.sync_all())?;
    rename_synced(tmp, path)
}

fn rename_synced(tmp: &Path, path: &Path) -> std::io::Result<()> {
    if let Err(e) = std::fs::rename(tmp, path) {
        let _ = std::fs::remove_file(tmp);
        return Err(e);
    }
    sync_dir(path);
    Ok(())
}

/// Syncs the directory holding `path` (the rename made durable); a file
/// system that cannot sync a directory is not an error.
pub fn sync_dir(path: &Path) {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    if let Ok(d) = std::fs::File::open(dir) {
        let _ = d.sync_all();
    }
}

/// Removes the [`partial_path`] files other processes left in `dir` (killed
/// while they wrote); this process's own are kept. Returns how many.
pub fn remove_stale_partials(dir: &Path) -> usize {
    let own = format!(".partial-{}-", std::process::id());
    let Ok(entries) = std::fs::read_dir(dir) else { return 0 };
    let mut n = 0;
    for e in entries.filter_map(Result::ok) {
        let name = e.file_name().to_string_lossy().into_owned();
        let ours = name.starts_with('.') && name.contains(".partial-") && !name.contains(&own);
        if ours && e.file_type().is_ok_and(|t| t.is_file()) && std::fs::remove_file(e.path()).is_ok() {
            n += 1;
        }
    }
    n
}
