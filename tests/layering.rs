//! The layer order of `src/`: a module imports only from layers below its
//! own (or from itself). Bottom up:
//!
//! | layer | modules |
//! |---|---|
//! | 0 | `error`, `summary` (vocabulary every layer shares), `simd` (the kernels' instruction set), `atomic` (files written whole or not at all) |
//! | 1 | `mesh`, `geometry` (the one circle type) |
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
//! line and both layers when one points upwards or sideways. A second test
//! checks that no modules import each other in a circle inside a layer, at
//! any depth (`drivers::run` and `drivers::failure`, say).

use std::path::{Path, PathBuf};

const LAYERS: [(&str, u32); 17] = [
    ("atomic", 0),
    ("error", 0),
    ("simd", 0),
    ("summary", 0),
    ("mesh", 1),
    ("geometry", 1),
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

/// The module path of a file: `src/drivers/run.rs` -> `[drivers, run]`,
/// `src/drivers/mod.rs` -> `[drivers]`.
fn module_path(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).unwrap();
    let mut path: Vec<String> = rel.iter().map(|c| c.to_str().unwrap().trim_end_matches(".rs").to_string()).collect();
    if path.last().is_some_and(|l| l == "mod") {
        path.pop();
    }
    path
}

/// The module paths a file's code (comments removed, lines joined) names:
/// `crate::a::b`, `super::x` (`super` of a file module is its folder, of a
/// `mod.rs` the folder's parent), `self::x`, and each item of a brace group
/// (`super::{a::X, b}`). Each is a list of segments; the last may be an item.
fn module_refs(code: &str, module: &[String]) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    for start in ["crate::", "super::", "self::"] {
        for (i, _) in code.match_indices(start) {
            if code[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let mut rest = &code[i..];
            let mut base: Vec<String> = module.to_vec();
            if let Some(r) = rest.strip_prefix("crate::") {
                base.clear();
                rest = r;
            } else if let Some(r) = rest.strip_prefix("self::") {
                rest = r;
            } else {
                while let Some(r) = rest.strip_prefix("super::") {
                    base.pop();
                    rest = r;
                }
            }
            let segment = |s: &str| s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>();
            let mut segs = Vec::new();
            loop {
                let s = segment(rest);
                if s.is_empty() {
                    break;
                }
                rest = &rest[s.len()..];
                segs.push(s);
                match rest.strip_prefix("::") {
                    Some(r) => rest = r,
                    None => break,
                }
            }
            base.extend(segs);
            match rest.strip_prefix('{') {
                // One path per item of the group (nested groups: their first segment).
                Some(group) => {
                    let group = group.split('}').next().unwrap_or("");
                    for item in group.split(',') {
                        let first = segment(item.trim().trim_start_matches('{'));
                        if !first.is_empty() {
                            let mut path = base.clone();
                            path.push(first);
                            out.push(path);
                        }
                    }
                }
                None => out.push(base),
            }
        }
    }
    out
}

/// Whether `path` (segments under `src/`) is a module file or folder.
fn is_module(src: &Path, path: &[String]) -> bool {
    let p: PathBuf = path.iter().collect();
    src.join(&p).with_extension("rs").is_file() || src.join(&p).is_dir()
}

/// The items a folder module re-exports from its own children, from
/// `pub use child::{a, b}` / `pub use child::a` lines of its `mod.rs`:
/// item -> child.
fn reexports(src: &Path, folder: &[String]) -> std::collections::BTreeMap<String, String> {
    let p: PathBuf = folder.iter().collect();
    let mut map = std::collections::BTreeMap::new();
    let Ok(text) = std::fs::read_to_string(src.join(p).join("mod.rs")) else { return map };
    let text = text.replace('\n', " ");
    for stmt in text.split(';') {
        let Some(rest) = stmt.trim().strip_prefix("pub use ") else { continue };
        let Some((child, items)) = rest.split_once("::") else { continue };
        let items = items.trim().trim_start_matches('{').trim_end_matches('}');
        for item in items.split(',') {
            let name = item.split(" as ").last().unwrap_or("").trim();
            let name = name.rsplit("::").next().unwrap_or("").trim();
            if !name.is_empty() && child.chars().all(|c| c.is_alphanumeric() || c == '_') {
                map.insert(name.to_string(), child.to_string());
            }
        }
    }
    map
}

/// Resolves a referenced path to the deepest module it names, following a
/// folder's re-exports of its children's items.
fn resolve(src: &Path, mut path: Vec<String>) -> Vec<String> {
    loop {
        if path.is_empty() || is_module(src, &path) {
            return path;
        }
        let item = path.pop().unwrap();
        if let Some(child) = reexports(src, &path).get(&item) {
            path.push(child.clone());
            return path;
        }
    }
}

/// A cycle in `edges` (module -> modules it imports), if any, as a path.
fn find_cycle(edges: &std::collections::BTreeMap<String, std::collections::BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        n: &str,
        edges: &std::collections::BTreeMap<String, std::collections::BTreeSet<String>>,
        state: &mut std::collections::BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(n.to_string(), 1);
        stack.push(n.to_string());
        for m in edges.get(n).into_iter().flatten() {
            match state.get(m.as_str()).copied().unwrap_or(0) {
                1 => {
                    let at = stack.iter().position(|s| s == m).unwrap();
                    let mut cycle = stack[at..].to_vec();
                    cycle.push(m.clone());
                    return Some(cycle);
                }
                0 => {
                    if let Some(c) = visit(m, edges, state, stack) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(n.to_string(), 2);
        None
    }
    let mut state = std::collections::BTreeMap::new();
    for n in edges.keys() {
        if state.get(n.as_str()).copied().unwrap_or(0) == 0 {
            if let Some(c) = visit(n, edges, &mut state, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

/// The import graph between sibling modules at every depth (`drivers::run`
/// -> `drivers::failure`, `harness::perf::timing` -> `harness::perf::bytes`):
/// an import from module `M` of module `P` is an edge between the two
/// children of their deepest common ancestor that contain them. A folder's
/// own `mod.rs` (its declarations and re-exports) is not a sibling.
fn sibling_edges(src: &Path) -> std::collections::BTreeMap<String, std::collections::BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    files.sort();
    let mut edges: std::collections::BTreeMap<String, std::collections::BTreeSet<String>> = Default::default();
    for file in &files {
        let module = module_path(src, file);
        if module.first().is_none_or(|m| m == "lib" || m == "bin") {
            continue;
        }
        let text = std::fs::read_to_string(file).unwrap();
        let code: Vec<&str> = text.lines().map(|l| l.split("//").next().unwrap_or("")).collect();
        for target in module_refs(&code.join(" "), &module) {
            let target = resolve(src, target);
            let k = module.iter().zip(&target).take_while(|(a, b)| a == b).count();
            if k == 0 || k >= module.len() || k >= target.len() {
                continue; // another top-level module (the layer test), or an ancestor or descendant
            }
            edges.entry(module[..=k].join("::")).or_default().insert(target[..=k].join("::"));
        }
    }
    edges
}

#[test]
fn no_import_cycle_between_modules_inside_a_layer() {
    let edges = sibling_edges(Path::new("src"));
    assert!(
        edges.get("drivers::failure").is_some_and(|t| t.contains("drivers::phase")),
        "the scanner sees drivers::failure import drivers::phase: {edges:?}"
    );
    if let Some(cycle) = find_cycle(&edges) {
        panic!("import cycle between modules: {}", cycle.join(" -> "));
    }
}

#[test]
fn the_module_scanner_reads_paths_groups_and_super() {
    let m = |p: &[&str]| p.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let run = m(&["drivers", "run"]);
    assert_eq!(
        module_refs("use super::failure::{self, FailureResult};", &run),
        vec![m(&["drivers", "failure", "self"]), m(&["drivers", "failure", "FailureResult"])]
    );
    assert_eq!(
        module_refs("use super::{phase::Watch, srm};", &run),
        vec![m(&["drivers", "phase"]), m(&["drivers", "srm"])]
    );
    assert_eq!(module_refs("use crate::solver::relax::unobserved;", &run), vec![m(&["solver", "relax", "unobserved"])]);
}

#[test]
fn the_cycle_finder_finds_a_two_module_cycle() {
    let mut edges: std::collections::BTreeMap<String, std::collections::BTreeSet<String>> = Default::default();
    edges.entry("drivers::run".into()).or_default().insert("drivers::failure".into());
    edges.entry("drivers::failure".into()).or_default().insert("drivers::phase".into());
    assert_eq!(find_cycle(&edges), None);
    edges.entry("drivers::failure".into()).or_default().insert("drivers::run".into());
    assert_eq!(
        find_cycle(&edges),
        Some(vec!["drivers::failure".to_string(), "drivers::run".to_string(), "drivers::failure".to_string()])
    );
}
