//! Where in `references/` a row of the validation table is explained: the
//! section and, for a row that differs or is not met, the paragraph that
//! says why.
//!
//! A row cites the Markdown file its source names (`references/lem.md`; a
//! source without one, such as `references/pyslope.json`, is looked up in
//! every file of `references/`). Its **section** is the one under the
//! heading above the first line that names the row: its id in backticks
//! (`` `slip/eq21-fem-vs-lem` ``), or a pattern that covers it
//! (`` `slip/*` ``); a file that names it nowhere is cited whole. Its
//! **reason** is the first prose paragraph or list item that names it; where
//! only a table row names it, the first paragraph after that table (the
//! table's commentary). No such paragraph: no reason, and the page says so.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::markdown::slug;

/// One section of a references file.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// `references/lem.md`.
    pub file: String,
    /// The heading's text ("" for the text before the first heading).
    pub heading: String,
    /// The section's lines (its heading first).
    pub lines: Vec<String>,
}

impl Section {
    /// The page's id of the section.
    pub fn anchor(&self) -> String {
        format!("ref-{}-{}", slug(&self.file), slug(&self.heading))
    }
    /// The section as Markdown.
    pub fn text(&self) -> String {
        self.lines.join("\n")
    }
}

/// What a row cites.
#[derive(Debug, Clone, PartialEq)]
pub struct Citation {
    pub section: Section,
    /// The paragraph that names the row (Markdown), if any.
    pub reason: Option<String>,
}

/// The references files, read once each.
pub struct References {
    root: PathBuf,
    files: BTreeMap<String, Vec<Section>>,
}

/// Whether backticked text in `line` names row `id`: the id itself, or a
/// pattern ending in `/*` whose stem the id starts with.
pub fn names(line: &str, id: &str) -> bool {
    names_exactly(line, id) || covers(line, id)
}

fn names_exactly(line: &str, id: &str) -> bool {
    line.split('`').skip(1).step_by(2).any(|tok| tok == id)
}

fn covers(line: &str, id: &str) -> bool {
    line.split('`')
        .skip(1)
        .step_by(2)
        .any(|tok| tok.strip_suffix('*').is_some_and(|stem| stem.ends_with('/') && id.starts_with(stem)))
}

impl References {
    /// The files under `root/references/`.
    pub fn new(root: &Path) -> Self {
        let mut files = BTreeMap::new();
        let mut paths: Vec<PathBuf> = std::fs::read_dir(root.join("references"))
            .into_iter()
            .flatten()
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|e| e == "md"))
            .collect();
        paths.sort();
        for p in paths {
            let name = format!("references/{}", p.file_name().and_then(|n| n.to_str()).unwrap_or_default());
            if let Ok(text) = std::fs::read_to_string(&p) {
                files.insert(name.clone(), sections(&name, &text));
            }
        }
        Self { root: root.to_path_buf(), files }
    }

    /// The repository root the files were read from.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// What row `id` with source `source` cites (`None`: no file of
    /// `references/` goes with the source).
    pub fn cite(&self, id: &str, source: &str) -> Option<Citation> {
        let named: Vec<&String> = self.files.keys().filter(|f| source.contains(f.as_str())).collect();
        let candidates: Vec<&String> = if named.is_empty() { self.files.keys().collect() } else { named.clone() };
        // The id itself first, anywhere; then a pattern that covers it.
        let exact = |l: &str| names_exactly(l, id);
        let pattern = |l: &str| covers(l, id);
        for test in [&exact as &dyn Fn(&str) -> bool, &pattern] {
            for file in &candidates {
                let secs = &self.files[*file];
                if let Some(k) = secs.iter().position(|s| s.lines.iter().any(|l| test(l))) {
                    let why = reason(secs, &|l: &str| exact(l)).or_else(|| reason(secs, &|l: &str| pattern(l)));
                    return Some(Citation { section: secs[k].clone(), reason: why });
                }
            }
        }
        // Not named: the file the source names, whole (its first section),
        // or for another source the section whose heading names its file.
        if let Some(file) = named.first() {
            return self.files[*file].first().map(|s| Citation { section: s.clone(), reason: None });
        }
        let base = Path::new(source).file_name().and_then(|n| n.to_str())?;
        self.files
            .values()
            .flatten()
            .find(|s| s.heading.contains(base))
            .map(|s| Citation { section: s.clone(), reason: None })
    }
}

/// `text` cut at its headings.
fn sections(file: &str, text: &str) -> Vec<Section> {
    let mut out = vec![Section { file: file.into(), heading: String::new(), lines: Vec::new() }];
    let mut fence = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fence = !fence;
        }
        if !fence && line.starts_with('#') {
            let heading = line.trim_start_matches('#').trim().to_string();
            out.push(Section { file: file.into(), heading, lines: Vec::new() });
        }
        out.last_mut().expect("one section").lines.push(line.to_string());
    }
    out.retain(|s| !(s.heading.is_empty() && s.lines.iter().all(|l| l.trim().is_empty())));
    out
}

/// The paragraph that says why a row is what it is, the lines naming it
/// told by `names`: see the module.
fn reason(secs: &[Section], names: &dyn Fn(&str) -> bool) -> Option<String> {
    let mut after_table = None;
    for s in secs {
        let lines = &s.lines;
        for (k, l) in lines.iter().enumerate() {
            if !names(l) || l.starts_with('#') {
                continue;
            }
            if l.trim_start().starts_with('|') {
                if after_table.is_none() {
                    let end =
                        (k..lines.len()).find(|&j| !lines[j].trim_start().starts_with('|')).unwrap_or(lines.len());
                    after_table = paragraph_from(lines, end);
                }
                continue;
            }
            return Some(block_around(lines, k));
        }
    }
    after_table
}

/// The first paragraph at or after line `from` (before the next heading or table).
fn paragraph_from(lines: &[String], from: usize) -> Option<String> {
    let start = (from..lines.len()).find(|&j| !lines[j].trim().is_empty())?;
    let t = lines[start].trim_start();
    if t.starts_with('#') || t.starts_with('|') {
        return None;
    }
    Some(block_around(lines, start))
}

/// The list item or paragraph that holds line `k`.
fn block_around(lines: &[String], k: usize) -> String {
    let is_item = |l: &str| {
        let t = l.trim_start();
        t.starts_with("- ")
            || t.starts_with("* ")
            || t.split_once(". ").is_some_and(|(n, _)| n.chars().all(|c| c.is_ascii_digit()) && !n.is_empty())
    };
    // Up to the start of the item that holds it, or of the paragraph.
    let mut start = k;
    while start > 0
        && !is_item(&lines[start])
        && !lines[start - 1].trim().is_empty()
        && !lines[start - 1].starts_with('#')
    {
        start -= 1;
    }
    let item = is_item(&lines[start]);
    let mut end = start + 1;
    while end < lines.len() {
        let l = &lines[end];
        if l.trim().is_empty() || l.starts_with('#') || l.trim_start().starts_with('|') {
            break;
        }
        if is_item(l) {
            break;
        }
        end += 1;
    }
    let text: Vec<&str> = lines[start..end].iter().map(|l| l.trim()).collect();
    let text = text.join(" ");
    if item {
        text.trim_start_matches(|c: char| c == '-' || c == '*' || c.is_ascii_digit() || c == '.').trim().to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOC: &str = "# Title\n\nintro\n\n## A (rows `a/*`)\n\n| row | x |\n|---|---|\n| `a/one` | 1 |\n\nThe table's commentary,\non two lines.\n\n## B\n\n- `b/two`, **not met**: because\n  it is so.\n  - a sub-item\n- `b/three` else\n";

    #[test]
    fn sections_reasons_and_patterns() {
        let secs = sections("references/x.md", DOC);
        assert_eq!(secs.iter().map(|s| s.heading.as_str()).collect::<Vec<_>>(), ["Title", "A (rows `a/*`)", "B"]);
        let why = |id: &str| reason(&secs, &|l: &str| names(l, id));
        assert_eq!(why("a/one").as_deref(), Some("The table's commentary, on two lines."));
        assert_eq!(why("b/two").as_deref(), Some("`b/two`, **not met**: because it is so."));
        assert!(names("rows `a/*`", "a/zzz") && !names("rows `a/*`", "ab/c") && !names("`a/one`", "a/on"));
        assert_eq!(why("c/none"), None);
    }
}
