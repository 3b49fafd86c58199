//! The validation report: runs last (test binaries run in name order). It
//! takes the rows every test recorded under target/validation/rows/ (and
//! moves them aside, so that each row must be written again by the next run),
//! sets them against every row the registry lists (`registry::rows()`), prints
//! the table and writes it to target/validation-report.md.
//!
//! It fails on an asserted row outside its tolerance, a run that did not
//! converge, a row listed in the registry but not recorded in this run (its
//! test failed before recording, or did not run), a row from an earlier build
//! of its test, a recorded row the registry does not list, and a row file that
//! cannot be read. Reported rows show `met` / `not met` and do not fail it.
//! Run alone (`cargo test --test zz_validation_report`) it fails: no test has
//! recorded anything.

use cdem::harness::registry as reg;
use cdem::harness::report::{rows_dir, take_recorded, Table};

#[test]
fn validation_report() {
    let recorded = take_recorded(&rows_dir());
    let table = Table::assemble(&reg::rows(), recorded.rows, &recorded.stale, &|spec| {
        format!("not recorded in this run by {} (it failed before recording, or did not run)", spec.test)
    });
    let mut failures = table.failures();
    failures.extend(recorded.unreadable.iter().map(|u| format!("unreadable row file {u}")));
    let mut md = format!("# Validation report\n\n{}; {} failing.\n\n", table.counts(), failures.len());
    md.push_str(&table.markdown());
    if !failures.is_empty() {
        md.push_str(&format!("\nFailing:\n\n- {}\n", failures.join("\n- ")));
    }
    // Written to the stderr handle, not through eprintln!, so that the test
    // harness does not capture it: the table shows in every `cargo test`.
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "\n{md}");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/validation-report.md");
    std::fs::write(&path, &md).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    println!("written to {}", path.display());
    assert!(failures.is_empty(), "failing rows:\n{}", failures.join("\n"));
}
