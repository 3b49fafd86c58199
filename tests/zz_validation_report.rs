//! The validation report: runs last (test binaries run in name order). It
//! takes the rows every test recorded under target/validation/rows/ (and
//! moves them aside, so that each row must be written again by the next run),
//! sets them against every row the registry lists (`registry::rows()`), prints
//! the table and writes it to target/validation-report.md, headed by the
//! commit, date, command and thread count of the run.
//!
//! It fails on an asserted row outside its tolerance, a run that did not
//! converge, a row listed in the registry but not recorded in this run (its
//! test failed before recording, or did not run), a recorded row whose kind,
//! tolerance, goal, source or reference differ from its spec, a skipped row
//! whose spec does not allow a skip (or an asserted one under `CI=true`), a
//! stale row (from another `cargo test` invocation, or computed from input
//! files that have changed since or are missing), a recorded row the registry
//! does not list, and a row file that cannot be read. Reported rows show
//! `met` / `not met` and do not fail it. Run alone (`cargo test --test
//! zz_validation_report`) it fails: no test has recorded anything in this
//! invocation. Under `cargo nextest` the invocation id is nextest's run id,
//! but nextest does not run this binary last: use `cargo test`.

use cdem::harness::registry as reg;
use cdem::harness::report::header::RunHeader;
use cdem::harness::report::{rows_dir, take_recorded, Table};

#[test]
fn validation_report() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let recorded = take_recorded(&rows_dir());
    let table = Table::of_recorded(&reg::rows(), &recorded, &|spec| {
        format!("not recorded in this run by {} (it failed before recording, or did not run)", spec.test)
    });
    let mut failures = table.failures();
    failures.extend(recorded.unreadable.iter().map(|u| format!("unreadable row file {u}")));
    let mut md = format!(
        "# Validation report\n\n{}\n{}; {} failing.\n\n",
        RunHeader::cargo_test(root).markdown(),
        table.counts(),
        failures.len()
    );
    md.push_str(&table.markdown());
    if !failures.is_empty() {
        md.push_str(&format!("\nFailing:\n\n- {}\n", failures.join("\n- ")));
    }
    // Written to the stderr handle, not through eprintln!, so that the test
    // harness does not capture it: the table shows in every `cargo test`.
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "\n{md}");
    let path = root.join("target/validation-report.md");
    std::fs::write(&path, &md).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    println!("written to {}", path.display());
    assert!(failures.is_empty(), "failing rows:\n{}", failures.join("\n"));
}
