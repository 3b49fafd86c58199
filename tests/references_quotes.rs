//! The numbers references/ quotes from the registry are the registry's: every
//! Markdown table row under references/ whose first cell is a row id of the
//! validation table (`` `column/springs/top-uz` ``) must state that row's
//! kind (asserted / reported) and its tolerance or goal as the registry
//! holds them (`src/harness/registry.rs`), so a tolerance changed in code
//! cannot leave a stale one in the text that justifies it.

use cdem::harness::registry as reg;
use cdem::harness::report::{Goal, RowSpec, SpecKind};

/// The first number of a cell, with its unit: "0.5 % (`TOL`)" -> 0.005,
/// "2e-4" -> 2e-4, "goal 2 %" -> 0.02.
fn quoted_number(cell: &str) -> Option<f64> {
    let start = cell.find(|c: char| c.is_ascii_digit())?;
    let rest = &cell[start..];
    let end = rest.find(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == '-')).unwrap_or(rest.len());
    let v: f64 = rest[..end].trim_end_matches(['e', '-', '.']).parse().ok()?;
    Some(if rest[end..].trim_start().starts_with('%') { v / 100.0 } else { v })
}

/// The registry's bound of a row and its kind word, if it has a numeric one.
fn bound(spec: &RowSpec) -> Option<(f64, &'static str)> {
    match spec.kind {
        SpecKind::Asserted(t) => Some((t, "asserted")),
        SpecKind::Reported(Goal::Within(t)) => Some((t, "reported")),
        _ => None,
    }
}

/// `(file, line, row id, cells)` of every table row quoting a registry row id.
fn quoting_rows() -> Vec<(String, usize, &'static RowSpec, Vec<String>)> {
    let rows: &'static [RowSpec] = Box::leak(reg::rows().into_boxed_slice());
    let mut out = Vec::new();
    let mut files: Vec<_> = std::fs::read_dir("references")
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    files.sort();
    for path in files {
        let text = std::fs::read_to_string(&path).unwrap();
        for (n, line) in text.lines().enumerate() {
            let cells: Vec<String> = line.trim().trim_matches('|').split('|').map(|c| c.trim().to_string()).collect();
            if !line.trim_start().starts_with('|') || cells.len() < 3 {
                continue;
            }
            let id = cells[0].trim_matches('`');
            if let Some(spec) = rows.iter().find(|s| s.id == id && cells[0].starts_with('`')) {
                out.push((path.display().to_string(), n + 1, spec, cells));
            }
        }
    }
    out
}

#[test]
fn every_tolerance_quoted_in_references_is_the_registrys() {
    let quotes = quoting_rows();
    assert!(quotes.len() >= 10, "the references quote registry rows in tables: found {}", quotes.len());
    let mut wrong = Vec::new();
    for (file, line, spec, cells) in &quotes {
        let Some((tol, kind)) = bound(spec) else { continue };
        // The cell that names the kind, and the cell before it with the bound.
        let Some(k) = cells.iter().position(|c| c == "asserted" || c == "reported") else {
            wrong.push(format!("{file}:{line}: `{}` quoted without its kind (asserted / reported)", spec.id));
            continue;
        };
        if cells[k] != kind {
            wrong.push(format!("{file}:{line}: `{}` is {kind} in the registry, the text says {}", spec.id, cells[k]));
        }
        match quoted_number(&cells[k - 1]) {
            Some(q) if ((q - tol) / tol).abs() < 1e-9 => {}
            q => wrong.push(format!(
                "{file}:{line}: `{}` has tolerance {tol:e} in the registry, the text quotes {q:?} (`{}`)",
                spec.id,
                cells[k - 1]
            )),
        }
    }
    assert!(wrong.is_empty(), "references/ out of date with the registry:\n{}", wrong.join("\n"));
}

#[test]
fn the_quote_reader_reads_percent_and_exponents() {
    assert_eq!(quoted_number("0.5 % (`TOL_EQ21_CDEM_VS_FEM`)"), Some(0.005));
    assert_eq!(quoted_number("goal 2 %"), Some(0.02));
    assert_eq!(quoted_number("2e-4 (`TOL_COLUMN_SERIES_JOINTS`)"), Some(2e-4));
    assert_eq!(quoted_number("5e-14"), Some(5e-14));
    assert_eq!(quoted_number("asserted"), None);
}

/// Issue 61 item 4: every plastic strength-reduction row (a `plastic/` row
/// whose quantity is a strength-reduction FS) has exactly one discretisation
/// figure in `registry::ROW_MESH_ERRORS`, every entry names such a row, and
/// each measured pair (the row's factor and the finer answer) is written
/// as the table has it in the section of references/ it cites.
#[test]
fn every_plastic_srm_row_has_its_discretisation_figure_from_references() {
    let rows = reg::rows();
    let plastic_srm = |s: &&RowSpec| s.id.starts_with("plastic/") && s.quantity.starts_with("FS (strength reduction)");
    for spec in rows.iter().filter(plastic_srm) {
        let n = reg::ROW_MESH_ERRORS.iter().filter(|(id, _)| *id == spec.id).count();
        assert_eq!(n, 1, "{}: {n} entries in ROW_MESH_ERRORS", spec.id);
    }
    for (id, figure) in reg::ROW_MESH_ERRORS {
        assert!(rows.iter().filter(plastic_srm).any(|s| s.id == *id), "{id} is not a plastic strength-reduction row");
        if let reg::MeshErrorFigure::Measured { fs, against, source, .. } = figure {
            let (file, section) = source.split_once(", ").expect("file, \"section\"");
            let text = std::fs::read_to_string(file).unwrap();
            let heading = section.trim_matches('"');
            let start = text.find(&format!("# {heading}")).unwrap_or_else(|| panic!("{file} has no section {heading}"));
            let body = &text[start + 1..];
            let body = &body[..body.find("\n#").unwrap_or(body.len())];
            for v in [fs, against] {
                assert!(body.contains(&v.to_string()), "{id}: {v} is not in {file}, {heading}");
            }
            let side = if fs > against { "(unsafe side)" } else { "(safe side)" };
            assert!(figure.note().contains(side), "{id}: {}", figure.note());
        }
    }
    // The rows `cdem reproduce` skips carry it too (their note is the only
    // place the report shows it).
    let skipped = cdem::harness::suite::plastic::published_slopes_skipped("test");
    for c in skipped.iter().filter(|c| c.id.ends_with("-srm")) {
        assert!(c.note.starts_with("discretisation error "), "{}: {:?}", c.id, c.note);
    }
    let c61 = skipped.iter().find(|c| c.id == "plastic/slopes/c61/hex-srm").unwrap();
    assert!(c61.note.contains("at least +1.5 % (unsafe side): 1.343 on this mesh, 1.323"), "{}", c61.note);
}
