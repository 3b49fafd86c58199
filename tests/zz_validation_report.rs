//! The validation report: runs last (test binaries run in name order) and
//! prints the rows every test recorded in this run as one table, also written
//! to target/validation-report.md. Rows older than the newest by more than
//! an hour come from an earlier run (their test did not record this time) and
//! are listed apart as stale.

#[test]
fn validation_report() {
    let recorded = cdem::harness::report::recorded();
    let newest = recorded.iter().map(|r| r.1).fold(f64::INFINITY, f64::min);
    let (fresh, stale): (Vec<_>, Vec<_>) = recorded.into_iter().partition(|r| r.1 - newest < 3600.0);
    let rows: Vec<cdem::harness::report::Check> = fresh.iter().flat_map(|r| r.2.clone()).collect();
    let mut md = format!("# Validation report\n\n{} checks from {} tests.\n\n", rows.len(), fresh.len());
    md.push_str(&cdem::harness::report::markdown_table(&rows));
    if !stale.is_empty() {
        md.push_str(&format!(
            "\nStale (not recorded in this run): {:?}\n",
            stale.iter().map(|s| &s.0).collect::<Vec<_>>()
        ));
    }
    // Written to the stderr handle, not through eprintln!, so that the test
    // harness does not capture it: the table shows in every `cargo test`.
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "\n{md}");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/validation-report.md");
    std::fs::write(&path, &md).unwrap();
    println!("written to {}", path.display());
    let failed: Vec<String> = rows
        .iter()
        .filter(|c| !c.passed())
        .map(|c| {
            format!("{} / {}: {:.2e} > {:.1e}", c.case, c.quantity, c.rel_error(), c.tolerance.unwrap_or(f64::NAN))
        })
        .collect();
    assert!(failed.is_empty(), "failed checks: {failed:?}");
}
