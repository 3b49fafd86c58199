//! A report page in a real browser: headless Chromium, found on PATH (or
//! named by `CHROMIUM`). [`check`] loads a copy of the page with a small
//! script put first in its head that records every error event (a resource
//! that does not load, a script error) and `console.error`, and, after the
//! load event, writes into the DOM the rows' cells, the images that did not
//! load, the rows each filter leaves visible and the page's height;
//! `--dump-dom` returns that DOM. Chromium's own console log (stderr) is
//! read too. No Python, no npm, no DevTools client: the browser binary alone.
//!
//! Without Chromium a test skips, saying so; under `CI=true` it fails
//! (`.ci/run` installs it from Debian's packages).
#![allow(dead_code)] // each test binary uses its own part

use std::path::{Path, PathBuf};
use std::process::Command;

/// The browser, or `None` (skipped) outside CI; panics under `CI=true`.
pub fn chromium_or_skip(test: &str) -> Option<PathBuf> {
    let named = std::env::var_os("CHROMIUM").map(PathBuf::from);
    let found = named
        .into_iter()
        .chain(
            ["chromium", "chromium-browser", "google-chrome-stable", "google-chrome"].iter().filter_map(|n| on_path(n)),
        )
        .find(|p| p.is_file());
    if found.is_none() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "{test}: no chromium on PATH under CI=true (.ci/run installs it: apt-get install chromium)"
        );
        eprintln!("{test}: skipped: no chromium on PATH (apt-get install chromium; CI installs it)");
    }
    found
}

fn on_path(name: &str) -> Option<PathBuf> {
    std::env::var_os("PATH").and_then(|p| std::env::split_paths(&p).map(|d| d.join(name)).find(|f| f.is_file()))
}

/// Chromium headless with a fresh profile under `work`, offline as far as
/// flags go.
fn chromium(exe: &Path, work: &Path, tag: &str) -> Command {
    let profile = work.join(format!("profile-{tag}"));
    let _ = std::fs::remove_dir_all(&profile);
    let mut c = Command::new(exe);
    c.args([
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--hide-scrollbars",
        "--enable-logging=stderr",
        "--v=0",
    ]);
    c.arg(format!("--user-data-dir={}", profile.display()));
    c
}

const CHECK_SCRIPT: &str = r#"<script>
(function () {
  var errors = [];
  window.addEventListener('error', function (e) {
    var t = e.target;
    errors.push(t && t !== window && t.tagName ? 'resource ' + t.tagName + ' did not load' : 'error ' + e.message);
  }, true);
  var ce = console.error;
  console.error = function () { errors.push('console.error ' + Array.prototype.join.call(arguments, ' ')); ce.apply(console, arguments); };
  window.addEventListener('load', function () {
    var imgs = document.images, broken = [];
    for (var i = 0; i < imgs.length; i++) if (!(imgs[i].complete && imgs[i].naturalWidth > 0)) broken.push(imgs[i].alt);
    var rows = [];
    document.querySelectorAll('tr.row').forEach(function (r) {
      var c = r.cells;
      rows.push([r.dataset.id, c[0].textContent, c[1].textContent, c[8].querySelector('.status').textContent,
                 c[8].querySelector('.reason') ? c[8].querySelector('.reason').textContent : '',
                 c[8].querySelector('.reason.missing') ? 'missing' : '']);
    });
    var visible = function () { var n = 0; document.querySelectorAll('tr.row').forEach(function (r) { if (r.getClientRects().length) n++; }); return n; };
    var shown = {};
    document.querySelectorAll('.filters input').forEach(function (b) { b.checked = true; shown[b.id.replace('show-', '')] = visible(); });
    document.getElementById('show-all').checked = true;
    var out = document.createElement('pre');
    out.id = 'browser-check';
    out.textContent = JSON.stringify({ rows: rows, images: imgs.length, broken: broken, errors: errors, shown: shown,
                                       height: document.documentElement.scrollHeight });
    document.body.appendChild(out);
  });
})();
</script>"#;

/// What the browser saw.
#[derive(Debug)]
pub struct Checked {
    /// Per row: id, case, quantity, status label, reason text, "missing" if
    /// the page says no reason was found.
    pub rows: Vec<[String; 6]>,
    pub images: usize,
    pub broken: Vec<String>,
    /// Error events and console errors, from the page and from Chromium's log.
    pub errors: Vec<String>,
    /// Visible rows with each filter checked (`all`, `fail`, `not-met`, ...).
    pub shown: std::collections::BTreeMap<String, usize>,
    pub height: u32,
}

/// Loads `page` (a copy with [`CHECK_SCRIPT`] in `work`) and reads back what
/// the script wrote.
pub fn check(exe: &Path, page: &Path, work: &Path) -> Checked {
    std::fs::create_dir_all(work).unwrap();
    let html = std::fs::read_to_string(page).unwrap_or_else(|e| panic!("{}: {e}", page.display()));
    let at = html.find("<head>").map(|k| k + "<head>".len()).expect("the page has a <head>");
    let copy = work.join("checked.html");
    std::fs::write(&copy, format!("{}\n{CHECK_SCRIPT}{}", &html[..at], &html[at..])).unwrap();
    let out = chromium(exe, work, "dom")
        .arg("--dump-dom")
        .arg(format!("file://{}", copy.canonicalize().unwrap().display()))
        .output()
        .expect("chromium runs");
    let dom = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "chromium --dump-dom failed: {}\n{stderr}", out.status);
    let start = dom
        .find("<pre id=\"browser-check\">")
        .unwrap_or_else(|| panic!("no check result in the DOM; stderr:\n{stderr}"));
    let body = &dom[start + "<pre id=\"browser-check\">".len()..];
    let body = &body[..body.find("</pre>").expect("closed")];
    let text = body.replace("&lt;", "<").replace("&gt;", ">").replace("&nbsp;", "\u{a0}").replace("&amp;", "&");
    let v: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("check result {text}: {e}"));
    let strings = |v: &serde_json::Value| -> Vec<String> {
        v.as_array().into_iter().flatten().map(|s| s.as_str().unwrap_or_default().to_string()).collect()
    };
    let mut errors = strings(&v["errors"]);
    // Chromium logs the page's console messages as `CONSOLE(line)] "...", source: ...`.
    errors.extend(stderr.lines().filter(|l| l.contains(":CONSOLE")).map(|l| format!("chromium log: {l}")));
    Checked {
        rows: v["rows"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|r| {
                let s = strings(r);
                std::array::from_fn(|k| s.get(k).cloned().unwrap_or_default())
            })
            .collect(),
        images: v["images"].as_u64().unwrap_or(0) as usize,
        broken: strings(&v["broken"]),
        errors,
        shown: v["shown"]
            .as_object()
            .into_iter()
            .flatten()
            .map(|(k, n)| (k.clone(), n.as_u64().unwrap_or(0) as usize))
            .collect(),
        height: v["height"].as_u64().unwrap_or(0) as u32,
    }
}

/// A screenshot of `page`, `width` x `height` CSS pixels, into `png`.
pub fn screenshot(exe: &Path, page: &Path, work: &Path, png: &Path, width: u32, height: u32) {
    let out = chromium(exe, work, "shot")
        .arg(format!("--window-size={width},{height}"))
        .arg(format!("--screenshot={}", png.display()))
        .arg(format!("file://{}", page.canonicalize().unwrap().display()))
        .output()
        .expect("chromium runs");
    assert!(
        out.status.success() && png.is_file(),
        "chromium --screenshot failed: {}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The rows of a Markdown validation table: (case, quantity, result) each,
/// `\|` unescaped; the result cut at its first `:` (the status label; a
/// failing label keeps its `FAIL: ...` kind).
pub fn markdown_rows(md: &str) -> Vec<[String; 3]> {
    let mut in_table = false;
    let mut rows = Vec::new();
    for line in md.lines() {
        if line.starts_with("| case | quantity |") {
            in_table = true;
            continue;
        }
        if !in_table || line.starts_with("|---") {
            continue;
        }
        if !line.starts_with('|') {
            if !rows.is_empty() {
                break;
            }
            continue;
        }
        let cells = split_cells(line);
        let result = cells.get(8).cloned().unwrap_or_default();
        let label = [
            "FAIL: missing",
            "FAIL: stale",
            "FAIL: spec mismatch",
            "FAIL: skip not allowed",
            "FAIL: not in the registry",
        ]
        .into_iter()
        .find(|l| result.starts_with(l))
        .map_or_else(|| result.split(':').next().unwrap_or_default().to_string(), str::to_string);
        rows.push([cells[0].clone(), cells[1].clone(), label]);
    }
    rows
}

fn split_cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|');
    let inner = inner.strip_suffix('|').unwrap_or(inner);
    let mut cells = vec![String::new()];
    let mut chars = inner.chars().peekable();
    while let Some(ch) = chars.next() {
        match ch {
            '\\' if chars.peek() == Some(&'|') => {
                cells.last_mut().unwrap().push('|');
                chars.next();
            }
            '|' => cells.push(String::new()),
            _ => cells.last_mut().unwrap().push(ch),
        }
    }
    cells.into_iter().map(|c| c.trim().to_string()).collect()
}

/// Asserts what a report page must show: every row of `md`'s table (the
/// page groups them by family), with its case, quantity and status; every image loaded; no error;
/// each filter showing exactly its rows; a reason on every row that differs
/// or is not met. Returns the check.
pub fn assert_page_matches(exe: &Path, page: &Path, md: &str, work: &Path) -> Checked {
    let c = check(exe, page, work);
    let want = markdown_rows(md);
    assert!(!want.is_empty(), "no rows in the markdown table");
    // The page groups the rows by family: the same rows, in another order.
    let mut got: Vec<[String; 3]> = c.rows.iter().map(|r| [r[1].clone(), r[2].clone(), r[3].clone()]).collect();
    let mut want_sorted = want.clone();
    got.sort();
    want_sorted.sort();
    assert_eq!(got.len(), want.len(), "rows in the page against rows in the markdown table");
    for (g, w) in got.iter().zip(&want_sorted) {
        assert_eq!(g, w, "a row of the page against the markdown table (both sorted)");
    }
    assert!(c.broken.is_empty(), "images that did not load: {:?}", c.broken);
    assert!(c.errors.is_empty(), "errors in the page: {:#?}", c.errors);
    assert_eq!(c.shown.get("all"), Some(&want.len()), "filter `all`: {:?}", c.shown);
    for (class, labels) in [
        ("not-met", &["not met"][..]),
        ("differs", &["differs"]),
        ("skipped", &["skipped"]),
        ("ok", &["ok"]),
        ("met", &["met"]),
        ("match", &["match"]),
    ] {
        let n = want.iter().filter(|w| labels.contains(&w[2].as_str())).count();
        assert_eq!(c.shown.get(class), Some(&n), "filter `{class}` shows its {n} rows: {:?}", c.shown);
    }
    let failing = want.iter().filter(|w| w[2].starts_with("FAIL")).count();
    assert_eq!(c.shown.get("fail"), Some(&failing), "filter `fail`: {:?}", c.shown);
    for r in c.rows.iter().filter(|r| r[3] == "differs" || r[3] == "not met") {
        assert!(!r[4].is_empty(), "row {} is {} and shows no reason", r[0], r[3]);
    }
    c
}
