//! The validation report: runs last (test binaries run in name order). It
//! takes the rows every test recorded under target/validation/rows/ (and
//! moves them aside, so that each row must be written again by the next run),
//! sets them against every row the registry lists (`registry::rows()`), prints
//! the table and writes it to target/validation-report.md, headed by the
//! commit, date, command and thread count of the run; and the same as a web
//! page, target/report.html (the figures the tests wrote inlined), which it
//! checks in headless Chromium (tests/common/browser.rs: every row of the
//! markdown table in the page, every image loaded, no error, the filters)
//! with a screenshot in target/report.png; without Chromium that check
//! says it skipped, and under `CI=true` it must run.
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

#[path = "common/browser.rs"]
mod browser;

use std::path::Path;
use std::time::SystemTime;

use cdem::harness::registry as reg;
use cdem::harness::report::header::RunHeader;
use cdem::harness::report::html::{page, Page};
use cdem::harness::report::{rows_dir, take_recorded, Table};

/// The figures the tests of this run wrote into target/figures (Figs. 9,
/// 10, 13, 14), as the report's sections: a figure older than the oldest
/// row file of this run is from an earlier run and is listed, not shown.
fn figures_section(figures: &Path, since: Option<SystemTime>) -> String {
    let mut files: Vec<(String, SystemTime)> = std::fs::read_dir(figures)
        .into_iter()
        .flatten()
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "png"))
        .filter_map(|e| Some((e.file_name().to_str()?.to_string(), e.metadata().ok()?.modified().ok()?)))
        .collect();
    files.sort();
    let (fresh, old): (Vec<_>, Vec<_>) = files.into_iter().partition(|(_, t)| since.is_some_and(|s| *t >= s));
    let mut md = String::from("## Figures written by the tests (target/figures)\n\n");
    for (f, _) in &fresh {
        md.push_str(&format!("![{f}]({f})\n\n"));
    }
    if !old.is_empty() {
        let names: Vec<&str> = old.iter().map(|(f, _)| f.as_str()).collect();
        md.push_str(&format!("From an earlier run, not shown: {}.\n", names.join(", ")));
    }
    md
}

#[test]
fn validation_report() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let since = std::fs::read_dir(rows_dir())
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| e.metadata().ok()?.modified().ok())
        .min();
    let recorded = take_recorded(&rows_dir());
    let table = Table::of_recorded(&reg::rows(), &recorded, &|spec| {
        format!("not recorded in this run by {} (it failed before recording, or did not run)", spec.test)
    });
    let mut failures = table.failures();
    failures.extend(recorded.unreadable.iter().map(|u| format!("unreadable row file {u}")));
    let header = RunHeader::cargo_test(root);
    let summary = format!("{}; {} failing.", table.counts(), failures.len());
    let mut md = format!("# Validation report\n\n{}\n{summary}\n\n", header.markdown());
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
    // The same as a web page, checked in a real browser (skipped without
    // Chromium outside CI; tests/common/browser.rs).
    let figures = root.join("target/figures");
    let sections = figures_section(&figures, since);
    let p = Page {
        title: "Validation report (cargo test)",
        header: &header,
        table: &table,
        summary,
        failures: &failures,
        sections: &sections,
        dir: &figures,
        root,
    };
    let html = root.join("target/report.html");
    std::fs::write(&html, page(&p)).unwrap_or_else(|e| panic!("{}: {e}", html.display()));
    println!("written to {}", html.display());
    if let Some(exe) = browser::chromium_or_skip("validation_report (report.html)") {
        let work = root.join("target/report-page/cargo-test");
        let c = browser::assert_page_matches(&exe, &html, &md, &work);
        let png = root.join("target/report.png");
        browser::screenshot(&exe, &html, &work, &png, 1400, c.height.clamp(800, 30_000));
        println!("{} rows and {} figures in the browser; screenshot {}", c.rows.len(), c.images, png.display());
    }
    assert!(failures.is_empty(), "failing rows:\n{}", failures.join("\n"));
}
