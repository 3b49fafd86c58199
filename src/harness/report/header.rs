//! What a validation report was made from: the commit (and whether the tree
//! had changes), the date (UTC), the command and the thread count. The
//! report of `cargo test` ([`RunHeader::cargo_test`]) and, later, the one of
//! `cdem reproduce` ([`RunHeader::of_this_process`]) start with it.

use std::path::Path;
use std::process::Command;

/// The facts of a run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RunHeader {
    /// `git rev-parse HEAD`, or "unknown" (no git, not a repository).
    pub commit: String,
    /// Changed or untracked files (`git status --porcelain`); `None`: unknown.
    pub changed_files: Option<usize>,
    /// `YYYY-MM-DD HH:MM:SS UTC`.
    pub date: String,
    /// The command, as far as it is known.
    pub command: String,
    /// Rayon's thread count, and the machine's available parallelism.
    pub threads: usize,
    pub cores: usize,
}

impl RunHeader {
    /// The facts of a run of `command` on the repository at `root`.
    pub fn collect(root: &Path, command: String) -> Self {
        let git = |args: &[&str]| {
            let out = Command::new("git").arg("-C").arg(root).args(args).output().ok()?;
            out.status.success().then(|| String::from_utf8_lossy(&out.stdout).into_owned())
        };
        Self {
            commit: git(&["rev-parse", "HEAD"]).map_or_else(|| "unknown".into(), |s| s.trim().to_string()),
            changed_files: git(&["status", "--porcelain"]).map(|s| s.lines().count()),
            date: utc_date(std::time::SystemTime::now()),
            command,
            threads: rayon::current_num_threads(),
            cores: std::thread::available_parallelism().map_or(0, |n| n.get()),
        }
    }
    /// The header of `cargo test`'s report, from a test binary: the command
    /// is its parent's (cargo's) command line where `/proc` shows it, with
    /// the invocation id the rows must carry ([`super::current_invocation`])
    /// and the build profile.
    pub fn cargo_test(root: &Path) -> Self {
        let invocation = super::current_invocation().unwrap_or_else(|| "unknown".into());
        let cargo = parent_command_line().unwrap_or_else(|| "cargo test".into());
        let profile = if cfg!(debug_assertions) { "debug assertions on" } else { "release (no debug assertions)" };
        let command = format!(
            "{cargo} (invocation {invocation}; cdem {}, {profile}{})",
            env!("CARGO_PKG_VERSION"),
            match std::env::var("CI").as_deref() {
                Ok("true") => ", CI=true",
                _ => "",
            }
        );
        Self::collect(root, command)
    }
    /// The header of a program's own report: its arguments, the program
    /// named without its directory.
    pub fn of_this_process(root: &Path) -> Self {
        Self::collect(root, without_directory(std::env::args().collect()))
    }
    /// The header as Markdown lines.
    pub fn markdown(&self) -> String {
        let tree = match self.changed_files {
            Some(0) => "clean tree".to_string(),
            Some(n) => format!("dirty tree: {n} changed or untracked files"),
            None => "tree state unknown".to_string(),
        };
        let threads = match std::env::var("RAYON_NUM_THREADS") {
            Ok(v) => format!("{} rayon threads (RAYON_NUM_THREADS={v})", self.threads),
            Err(_) => format!("{} rayon threads", self.threads),
        };
        format!(
            "- commit: {} ({tree})\n- date: {}\n- command: `{}`\n- threads: {threads}, {} cores available\n",
            self.commit, self.date, self.command, self.cores
        )
    }
}

/// The parent process's command line (`/proc/<ppid>/cmdline`, Linux).
fn parent_command_line() -> Option<String> {
    #[cfg(unix)]
    {
        let ppid = std::os::unix::process::parent_id();
        let raw = std::fs::read(format!("/proc/{ppid}/cmdline")).ok()?;
        let args: Vec<String> =
            raw.split(|b| *b == 0).filter(|a| !a.is_empty()).map(|a| String::from_utf8_lossy(a).into_owned()).collect();
        (!args.is_empty()).then(|| without_directory(args))
    }
    #[cfg(not(unix))]
    None
}

/// The arguments joined, the program without its directory.
fn without_directory(mut args: Vec<String>) -> String {
    if let Some(first) = args.first_mut() {
        if let Some(name) = Path::new(first.as_str()).file_name().and_then(|n| n.to_str()) {
            *first = name.to_string();
        }
    }
    args.join(" ")
}

/// `t` as `YYYY-MM-DD HH:MM:SS UTC` (proleptic Gregorian, from days since
/// 1970-01-01: H. Hinnant's `civil_from_days`).
pub fn utc_date(t: std::time::SystemTime) -> String {
    let secs = t.duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs()) as i64;
    let (days, rest) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02} UTC", rest / 3600, rest % 3600 / 60, rest % 60)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, UNIX_EPOCH};

    #[test]
    fn utc_dates_of_known_instants() {
        assert_eq!(utc_date(UNIX_EPOCH), "1970-01-01 00:00:00 UTC");
        // 2000-02-29 12:34:56 UTC (a leap day of a century leap year).
        assert_eq!(utc_date(UNIX_EPOCH + Duration::from_secs(951_827_696)), "2000-02-29 12:34:56 UTC");
        assert_eq!(utc_date(UNIX_EPOCH + Duration::from_secs(4_102_444_799)), "2099-12-31 23:59:59 UTC");
    }

    #[test]
    fn a_program_is_named_without_its_directory() {
        assert_eq!(without_directory(vec!["/a/b/cargo".into(), "test".into()]), "cargo test");
    }
}
