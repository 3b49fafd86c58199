//! The layer order of `src/`: a module imports only from layers below its
//! own (or from itself). Bottom up:
//!
//! | layer | modules |
//! |---|---|
//! | 0 | `error`, `summary` (vocabulary every layer shares) |
//! | 1 | `mesh` |
//! | 2 | `physics` |
//! | 3 | `model` |
//! | 4 | `solver`, `fem`, `lem`, `analysis` (beside each other: none imports another) |
//! | 5 | `scene` |
//! | 6 | `drivers` |
//! | 7 | `output` (its `figures` with feature `plot`) |
//! | 8 | `app` (feature `plot`: one function per product command) |
//! | 9 | `harness` (feature `harness`: verification only) |
//!
//! The CLI (`src/bin/cdem.rs`) sits on top and reaches the library through
//! `cdem::`. The test reads every `.rs` file under `src/`, takes each
//! `crate::<module>` path outside comments, and fails naming the file, the
//! line and both layers when one points upwards or sideways.

use std::path::{Path, PathBuf};

const LAYERS: [(&str, u32); 14] = [
    ("error", 0),
    ("summary", 0),
    ("mesh", 1),
    ("physics", 2),
    ("model", 3),
    ("solver", 4),
    ("fem", 4),
    ("lem", 4),
    ("analysis", 4),
    ("scene", 5),
    ("drivers", 6),
    ("output", 7),
    ("app", 8),
    ("harness", 9),
];

/// The crate root's re-exports (all from layer 0: `error`, `summary`).
const ROOT_REEXPORTS: [&str; 8] =
    ["Error", "Result", "MeshError", "ModelError", "SceneError", "SolveError", "EndState", "Summary"];

fn layer(module: &str) -> Option<u32> {
    LAYERS.iter().find(|(m, _)| *m == module).map(|(_, l)| *l)
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The top-level module a file belongs to (`src/solver/relax.rs` -> `solver`),
/// None for the crate root and the binaries.
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).unwrap();
    let first = rel.components().next()?.as_os_str().to_str()?.trim_end_matches(".rs").to_string();
    (first != "lib" && first != "bin").then_some(first)
}

/// The `crate::<name>` modules a line of code refers to.
fn crate_refs(line: &str) -> Vec<String> {
    let code = line.split("//").next().unwrap_or("");
    code.match_indices("crate::")
        .filter(|(i, _)| !code[..*i].ends_with(|c: char| c.is_alphanumeric() || c == '_'))
        .map(|(i, m)| code[i + m.len()..].chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect())
        .collect()
}

#[test]
fn every_module_imports_only_from_layers_below_its_own() {
    let src = Path::new("src");
    let mut files = Vec::new();
    rust_files(src, &mut files);
    files.sort();
    let mut modules_seen = std::collections::BTreeSet::new();
    let mut violations = Vec::new();
    for file in &files {
        let Some(module) = module_of(src, file) else { continue };
        let own = layer(&module).unwrap_or_else(|| panic!("{}: module `{module}` has no layer", file.display()));
        modules_seen.insert(module.clone());
        let text = std::fs::read_to_string(file).unwrap();
        for (n, line) in text.lines().enumerate() {
            for target in crate_refs(line) {
                if target == module || target.is_empty() {
                    continue;
                }
                let Some(theirs) = layer(&target) else {
                    // A crate-root item is a re-export of a layer-0 item.
                    assert!(
                        ROOT_REEXPORTS.contains(&target.as_str()),
                        "{}:{}: `crate::{target}` is not a module with a layer",
                        file.display(),
                        n + 1
                    );
                    continue;
                };
                if theirs >= own {
                    violations.push(format!(
                        "{}:{}: `{module}` (layer {own}) imports `{target}` (layer {theirs})",
                        file.display(),
                        n + 1
                    ));
                }
            }
        }
    }
    assert!(violations.is_empty(), "imports against the layer order:\n{}", violations.join("\n"));
    let all: std::collections::BTreeSet<String> = LAYERS.iter().map(|(m, _)| m.to_string()).collect();
    assert_eq!(modules_seen, all, "every layered module exists and every module has a layer");
}

#[test]
fn the_reference_scanner_sees_paths_and_skips_comments() {
    assert_eq!(crate_refs("use crate::solver::State; // crate::harness"), vec!["solver"]);
    assert_eq!(crate_refs("    let m = crate::model::build(&mesh, &spec)?;"), vec!["model"]);
    assert_eq!(crate_refs("//! see [`crate::drivers`]"), Vec::<String>::new());
    assert_eq!(crate_refs("use mycrate::x;"), Vec::<String>::new());
}
