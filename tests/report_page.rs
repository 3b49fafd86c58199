//! The report page (`report.html`, issue 60) on a table with every status:
//! in headless Chromium every row of the markdown table is in the page in
//! order, every image loads, no error is logged, each filter shows exactly
//! its rows, and every row that differs or is not met shows its reason
//! from `references/`; a screenshot goes to target/report-page/. Without
//! Chromium this part skips, saying so; under `CI=true` it must run.
//!
//! Without a browser: the page is one file (images as data URIs, no
//! script, no style sheet or image fetched), and every row that can differ
//! or miss its goal (outside the machine-dependent `perf/` rows) has its
//! reason paragraph in `references/`.

#[path = "common/browser.rs"]
mod browser;

use std::path::Path;

use cdem::harness::registry as reg;
use cdem::harness::report::citations::References;
use cdem::harness::report::header::RunHeader;
use cdem::harness::report::html::{page, Page};
use cdem::harness::report::{Check, RowSpec, Rules, Skips, SpecKind, Table};
use cdem::output::figures::{line_plot, Scale, Series};

fn passing(spec: &RowSpec) -> Check {
    match spec.kind {
        SpecKind::Compared(_) => spec.compared("same", "same", true, 0.1),
        _ => {
            let r = spec.reference.unwrap_or(2.0);
            spec.value(r, r, 0.1)
        }
    }
}

/// The registry's rows, each passing, but one of every other status.
fn table() -> Table {
    let mut rows: Vec<Check> = reg::rows().iter().map(passing).collect();
    let set = |rows: &mut Vec<Check>, c: Check| {
        let k = rows.iter().position(|r| r.id == c.id).expect("a registry row");
        rows[k] = c;
    };
    set(&mut rows, reg::row("column/merged/top-uz").value(1.1, 1.0, 0.1)); // FAIL
    set(&mut rows, reg::row("lem/acads/spencer-vs-referee").value(0.98402, 1.0, 0.1)); // not met
    set(
        &mut rows,
        reg::row("slip/ki-signs-vs-paper").compared("+ from 0 m to 45 m", "ab -, bc +, cd -, de +", false, 0.1),
    ); // differs
    set(&mut rows, reg::row("meshes/regenerated").skipped("gmsh not on PATH")); // skipped
    rows.retain(|r| r.id != "study/column/fem-l2"); // missing
    let rules = Rules {
        stale: &Default::default(),
        absent: &|s| format!("not recorded by {}", s.test),
        skips: Skips::Registry { ci: false, also: &[] },
    };
    Table::assemble_with(&reg::rows(), rows, &rules)
}

fn render(dir: &Path) -> (String, String) {
    std::fs::create_dir_all(dir).unwrap();
    let pts: Vec<(f64, f64)> = (0..20).map(|k| (k as f64, (k as f64 * 0.3).sin() + 1.2)).collect();
    line_plot(
        &dir.join("fig9.png"),
        "K_i (synthetic)",
        "x (m)",
        "K_i",
        &[Series { name: "K_i", points: &pts }],
        Scale::Linear,
        Scale::Linear,
    )
    .unwrap();
    let table = table();
    let failures = table.failures();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = RunHeader::collect(root, "tests/report_page.rs".into());
    let sections = "## Slip circle (Fig. 9)\n\nA paragraph with `code`, **bold** and a table:\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\n![Fig. 9: K_i along the slip surface (synthetic)](fig9.png)\n";
    let p = Page {
        title: "report page test",
        header: &header,
        table: &table,
        summary: table.counts(),
        failures: &failures,
        sections,
        dir,
        root,
    };
    (page(&p), table.markdown())
}

#[test]
fn the_page_is_one_file_without_script() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/report-page");
    let (html, _) = render(&dir);
    assert!(
        !html.contains("<script") && !html.contains("<link") && !html.contains("@import"),
        "no script, no fetched style"
    );
    let srcs: Vec<&str> = html.split("src=\"").skip(1).collect();
    assert_eq!(srcs.len(), 1, "the one figure");
    assert!(srcs.iter().all(|s| s.starts_with("data:image/png;base64,")), "images inlined");
    // Each row links to its section of references/, which the page holds.
    for anchor in html.split("<a href=\"#ref-").skip(1).map(|s| &s[..s.find('"').unwrap()]) {
        assert!(html.contains(&format!("id=\"ref-{anchor}\"")), "cited section ref-{anchor} is on the page");
    }
    assert!(html.contains("href=\"#fig-fig9-png\""), "slip rows link to their figure");
}

#[test]
fn every_row_that_can_differ_or_miss_has_its_reason_in_references() {
    let refs = References::new(Path::new(env!("CARGO_MANIFEST_DIR")));
    let mut missing = Vec::new();
    for spec in reg::rows() {
        let can = matches!(spec.kind, SpecKind::Reported(_) | SpecKind::Compared(false));
        if !can || spec.id.starts_with("perf/") {
            continue;
        }
        match refs.cite(spec.id, spec.source) {
            Some(c) if c.reason.is_some() => {}
            other => missing.push(format!("{} ({}): {:?}", spec.id, spec.source, other.map(|c| c.section.heading))),
        }
    }
    assert!(missing.is_empty(), "rows without a paragraph naming them in references/:\n{}", missing.join("\n"));
}

#[test]
fn the_page_in_a_real_browser() {
    let Some(exe) = browser::chromium_or_skip("the_page_in_a_real_browser") else { return };
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/report-page");
    let (html, md) = render(&dir);
    let path = dir.join("report.html");
    std::fs::write(&path, html).unwrap();
    let c = browser::assert_page_matches(&exe, &path, &md, &dir.join("browser"));
    assert_eq!(c.images, 1);
    assert_eq!(c.shown.get("fail"), Some(&2), "the failing and the missing row: {:?}", c.shown);
    let png = dir.join("report-page.png");
    browser::screenshot(&exe, &path, &dir.join("browser"), &png, 1400, c.height.clamp(800, 30_000));
    println!("screenshot {} ({} px high)", png.display(), c.height);
}
