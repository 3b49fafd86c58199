//! Recorded rows, and whether they are fresh: of this `cargo test`
//! invocation, and computed from the input files as they are now.
//!
//! - **Invocation**: every test binary of one `cargo test` is a child of the
//!   same cargo process; [`current_invocation`] names it by its pid and its
//!   start time (`/proc/<ppid>/stat`, clock ticks since boot) and the boot id,
//!   so a pid reused later is another invocation. Under `cargo nextest` it
//!   is `NEXTEST_RUN_ID`. Where neither exists (no `/proc`) the invocation is
//!   unknown and every row fails as stale: fail closed.
//! - **Inputs**: [`record_with`] digests (FNV-1a, 64 bits, of the bytes) the
//!   files each row declares ([`super::inputs::declared`]); the report
//!   digests them again ([`take_recorded_with`]): a row whose inputs changed,
//!   or one of whose inputs is missing, is stale.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::{inputs, Check};

/// The rows directory of `cargo test`.
pub fn rows_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("target/validation/rows")
}

/// Where the inputs are (the repository root) and which invocation records
/// or takes rows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Freshness {
    pub root: PathBuf,
    /// `None`: unknown (every row is stale).
    pub invocation: Option<String>,
}

impl Freshness {
    /// This process: the repository root and [`current_invocation`].
    pub fn current() -> Self {
        Self { root: PathBuf::from(env!("CARGO_MANIFEST_DIR")), invocation: current_invocation() }
    }
}

/// The id of the `cargo test` (or `cargo nextest run`) invocation this
/// process belongs to: see the module's documentation.
pub fn current_invocation() -> Option<String> {
    if let Ok(id) = std::env::var("NEXTEST_RUN_ID") {
        return Some(format!("nextest run {id}"));
    }
    parent_invocation()
}

#[cfg(unix)]
fn parent_invocation() -> Option<String> {
    let ppid = std::os::unix::process::parent_id();
    let stat = std::fs::read_to_string(format!("/proc/{ppid}/stat")).ok()?;
    // Fields after the command (in parentheses, which may hold spaces):
    // state is field 3, the start time field 22.
    let after = &stat[stat.rfind(')')? + 1..];
    let start = after.split_whitespace().nth(19)?;
    let boot = std::fs::read_to_string("/proc/sys/kernel/random/boot_id").unwrap_or_default();
    let boot = boot.trim();
    Some(format!("pid {ppid} started {start} (boot {})", boot.get(..8).unwrap_or(boot)))
}

#[cfg(not(unix))]
fn parent_invocation() -> Option<String> {
    None
}

/// A declared input file as digested: relative path, FNV-1a 64 of its bytes
/// (`None`: missing or unreadable).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
struct InputDigest {
    path: String,
    fnv1a64: Option<String>,
}

/// A test's row file.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct RowFile {
    /// The writing invocation ([`current_invocation`]; "unknown" if none).
    invocation: String,
    /// The digests of each row's declared inputs, by row id.
    inputs: BTreeMap<String, Vec<InputDigest>>,
    rows: Vec<Check>,
}

/// FNV-1a, 64 bits.
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(*b)).wrapping_mul(0x0000_0100_0000_01b3))
}

/// The digests of row `c`'s declared inputs under `root` (`None`: no
/// inputs are declared for its id). Its source is the row's own: a source
/// other than its spec's fails the row as a spec mismatch anyway.
fn digests(root: &Path, c: &Check) -> Option<Vec<InputDigest>> {
    let files = inputs::declared(&c.id, &c.source, root)?;
    Some(
        files
            .into_iter()
            .map(|path| {
                let fnv1a64 = std::fs::read(root.join(&path)).ok().map(|b| format!("{:016x}", fnv1a64(&b)));
                InputDigest { path, fnv1a64 }
            })
            .collect(),
    )
}

/// Records a test's rows (overwriting that test's previous rows) with this
/// invocation and the digests of their inputs. A row file that cannot be
/// written is a failure (this is called by tests), not a silently shorter
/// table.
pub fn record(test: &str, checks: &[Check]) {
    record_into(&rows_dir(), test, checks).unwrap_or_else(|e| panic!("validation rows of {test}: {e}"));
}

/// [`record`] into `dir`.
pub fn record_into(dir: &Path, test: &str, checks: &[Check]) -> std::io::Result<()> {
    record_with(dir, &Freshness::current(), test, checks)
}

/// [`record`] into `dir`, as invocation `fresh.invocation`, the inputs
/// digested under `fresh.root`.
pub fn record_with(dir: &Path, fresh: &Freshness, test: &str, checks: &[Check]) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let inputs = checks.iter().filter_map(|c| Some((c.id.clone(), digests(&fresh.root, c)?))).collect();
    let file = RowFile {
        invocation: fresh.invocation.clone().unwrap_or_else(|| "unknown".into()),
        inputs,
        rows: checks.to_vec(),
    };
    let text = serde_json::to_string_pretty(&file).map_err(std::io::Error::other)?;
    let tmp = dir.join(format!(".{test}.json.tmp"));
    std::fs::write(&tmp, text)?;
    std::fs::rename(&tmp, dir.join(format!("{test}.json")))
}

/// What [`take_recorded`] found.
#[derive(Debug, Default)]
pub struct Recorded {
    pub rows: Vec<Check>,
    /// Why a row is not fresh, by id: from another invocation, or its inputs
    /// changed or are missing.
    pub stale: BTreeMap<String, String>,
    /// Row files that cannot be read, with the reason.
    pub unreadable: Vec<String>,
}

/// [`take_recorded_with`] as this process ([`Freshness::current`]).
pub fn take_recorded(dir: &Path) -> Recorded {
    take_recorded_with(dir, &Freshness::current())
}

/// Reads every row file in `dir`, moves it to `dir/../taken/` (so the next
/// report sees only rows written again after this one) and judges each row's
/// freshness against `fresh`.
pub fn take_recorded_with(dir: &Path, fresh: &Freshness) -> Recorded {
    let mut out = Recorded::default();
    let taken = dir.with_file_name("taken");
    let _ = std::fs::create_dir_all(&taken);
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    for path in paths {
        let parsed = std::fs::read_to_string(&path)
            .map_err(|e| e.to_string())
            .and_then(|t| serde_json::from_str::<RowFile>(&t).map_err(|e| e.to_string()));
        match parsed {
            Ok(file) => {
                for c in &file.rows {
                    if let Some(why) = staleness(fresh, &file, c) {
                        out.stale.insert(c.id.clone(), why);
                    }
                }
                out.rows.extend(file.rows);
            }
            Err(e) => out.unreadable.push(format!("{}: {e}", path.display())),
        }
        if let Some(name) = path.file_name() {
            let _ = std::fs::rename(&path, taken.join(name));
        }
    }
    out
}

/// Why row `c` of `file` is not fresh (`None`: it is).
fn staleness(fresh: &Freshness, file: &RowFile, c: &Check) -> Option<String> {
    let Some(own) = &fresh.invocation else {
        return Some("the invocation of this run is unknown (no /proc and no NEXTEST_RUN_ID)".into());
    };
    if file.invocation != *own {
        return Some(format!("from another cargo test run (invocation {}; this run: {own})", file.invocation));
    }
    let now = digests(&fresh.root, c);
    let then = file.inputs.get(&c.id);
    let (now, then) = match (now, then) {
        (None, None) => return None, // no inputs declared: the table lists it as unlisted, or a test fails
        (Some(_), None) => return Some("no digests of its inputs were recorded".into()),
        (None, Some(_)) => return Some("its inputs are no longer declared".into()),
        (Some(now), Some(then)) => (now, then.clone()),
    };
    let mut why = Vec::new();
    for d in &now {
        match (&d.fnv1a64, then.iter().find(|t| t.path == d.path)) {
            (None, _) => why.push(format!("input {} is missing", d.path)),
            (_, None) => why.push(format!("input {} was not declared when it was computed", d.path)),
            (_, Some(t)) if t.fnv1a64.is_none() => why.push(format!("input {} was missing when computed", d.path)),
            (Some(h), Some(t)) if t.fnv1a64.as_ref() != Some(h) => {
                why.push(format!("inputs changed since it was computed: {}", d.path))
            }
            _ => {}
        }
    }
    for t in then.iter().filter(|t| !now.iter().any(|d| d.path == t.path)) {
        why.push(format!("input {} is no longer declared", t.path));
    }
    (!why.is_empty()).then(|| why.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a64_of_known_strings() {
        // The published test vectors of FNV-1a 64.
        assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn the_invocation_is_known_on_linux_and_stable_in_a_process() {
        let a = current_invocation().expect("an invocation id from /proc");
        assert_eq!(Some(a), current_invocation());
    }
}
