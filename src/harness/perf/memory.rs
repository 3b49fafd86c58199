//! Peak resident memory of this process (Linux): `VmHWM` of
//! `/proc/self/status`, reset between measurements by writing 5 to
//! `/proc/self/clear_refs` (so a peak belongs to the stage measured after
//! the reset; memory already held, such as the built model, counts in it).
//! Elsewhere, or where the files cannot be read or written, `None`.

/// Resets the peak to the current resident size; false if not possible.
pub fn reset_peak() -> bool {
    std::fs::write("/proc/self/clear_refs", "5").is_ok()
}

/// The peak resident size since the last reset (MB, 1e6 bytes).
pub fn peak_mb() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024.0 / 1e6)
}

/// Runs `f` and returns its value with the peak resident size during it
/// (`None` if the peak cannot be reset and read).
pub fn with_peak<T>(f: impl FnOnce() -> T) -> (T, Option<f64>) {
    let reset = reset_peak();
    let value = f();
    (value, if reset { peak_mb() } else { None })
}
