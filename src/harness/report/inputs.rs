//! The input files each row of the validation table is computed from: the
//! scenes and LEM inputs of its case (the registry's cases), the
//! files those name (meshes, the scene of an ensemble), the reference data it
//! is compared with (JSON, snapshots) and its source under references/.
//! [`super::freshness`] digests them when a row is recorded and again when the
//! report takes it: a row whose inputs changed since is stale.
//!
//! Declared by row-id prefix ([`DECLARED`], the longest prefix wins), so
//! that a new row under an existing prefix needs no entry; a row no prefix
//! covers fails `every_row_declares_its_inputs` (tests/report_mutations.rs).
//! The paths are written out, not taken from the registry's cases: the
//! registry imports this module's parent (`report`), and the layering test
//! forbids the cycle; `every_case_input_is_declared` checks they agree.

use std::path::Path;

/// The committed meshes and their sources, which `meshes/regenerated`
/// compares: these and every case folder under them, and [`MESH_DIRS`].
const CASE_DIRS: [&str; 2] = ["verification/cases", "verification/plastic"];
const MESH_DIRS: [&str; 4] =
    ["verification/extreme", "verification/study", "verification/tutorial", "verification/joints"];

/// Row-id prefix, and the files (relative to the repository root) its rows
/// read besides their source. The extreme rows read
/// `verification/extreme/<name>.toml` ([`declared`]); `meshes/regenerated`
/// every `.geo` and `.msh` under [`CASE_DIRS`] and [`MESH_DIRS`].
#[rustfmt::skip]
pub const DECLARED: &[(&str, &[&str])] = &[
    ("column/springs/", &["verification/cases/column/column.toml"]),
    ("column/merged/", &["verification/cases/column/column-merged.toml"]),
    ("study/column/", &["verification/cases/column/column.toml"]),
    ("extreme/", &[]),
    ("fem/skfem/", &["references/skfem.json", "verification/cases/column/column-merged.toml", "verification/cases/slope/slope.toml"]),
    ("slope/", &["verification/cases/slope/slope.toml"]),
    ("lem/acads/", &["verification/lem/acads-1a.toml", "references/pyslope.json"]),
    ("lem/acads-1c/", &["verification/lem/acads-1c.toml"]),
    ("laws/bb-shear-", &[]),
    ("laws/bb-plane-srm", &["verification/laws/plane-barton-bandis.toml", "verification/joints/plane.msh"]),
    ("laws/bb-plane-wet-srm", &["verification/laws/plane-barton-bandis-wet.toml", "verification/joints/plane.msh"]),
    ("lem/paper/", &["verification/lem/paper-slope.toml", "references/pyslope.json"]),
    ("lem/taylor-", &[]),
    ("plastic/", &[]),
    ("plastic/column-compression", &["verification/plastic/column/column-compression.toml"]),
    ("plastic/column-tension", &["verification/plastic/column/column-tension.toml"]),
    ("plastic/prandtl", &["verification/plastic/prandtl/prandtl.toml"]),
    ("plastic/gl1-hex-srm", &["verification/plastic/griffiths-lane-1/gl1-hex.toml"]),
    ("plastic/gl1-prism-srm", &["verification/plastic/griffiths-lane-1/gl1-prism.toml"]),
    ("plastic/gl1-tet-srm", &["verification/plastic/griffiths-lane-1/gl1-tet.toml"]),
    ("plastic/paper-slope-srm", &["verification/plastic/paper-slope/paper-slope.toml", "verification/cases/slope/slope.msh"]),
    ("plastic/gl1-mesh-spread", &["verification/plastic/griffiths-lane-1/gl1-hex.toml", "verification/plastic/griffiths-lane-1/gl1-prism.toml", "verification/plastic/griffiths-lane-1/gl1-tet.toml"]),
    ("fserror/gl1/", &["verification/plastic/griffiths-lane-1/gl1-hex.toml", "verification/plastic/griffiths-lane-1/gl1-hex.msh", "verification/plastic/griffiths-lane-1/gl1-hex.geo", "verification/plastic/griffiths-lane-1/section.geo", "verification/plastic/slab.geo"]),
    ("plastic/slopes/at/", &["verification/plastic/arai-tagyo/at-hex.toml", "verification/plastic/arai-tagyo/at-prism.toml", "verification/plastic/arai-tagyo/at-tet.toml", "verification/plastic/arai-tagyo/at-lem.toml"]),
    ("plastic/slopes/yu/", &["verification/plastic/yamagami-ueta/yu-hex.toml", "verification/plastic/yamagami-ueta/yu-prism.toml", "verification/plastic/yamagami-ueta/yu-tet.toml", "verification/plastic/yamagami-ueta/yu-lem.toml"]),
    ("plastic/slopes/c63/", &["verification/plastic/cheng-63/c63-hex-fine.toml", "verification/plastic/cheng-63/c63-prism.toml", "verification/plastic/cheng-63/c63-tet.toml", "verification/plastic/cheng-63/c63-lem.toml"]),
    ("plastic/slopes/c61/", &["verification/plastic/cheng-61/c61-hex-fine.toml", "verification/plastic/cheng-61/c61-prism-face.toml", "verification/plastic/cheng-61/c61-tet-face.toml", "verification/plastic/cheng-61/c61-lem.toml"]),
    ("plastic/slopes/acads/", &["verification/plastic/acads-1a/acads-hex.toml", "verification/plastic/acads-1a/acads-prism.toml", "verification/plastic/acads-1a/acads-tet.toml", "verification/lem/acads-1a.toml"]),
    ("slip/", &["verification/cases/slope-slip/slope-slip.toml", "verification/lem/paper-slope.toml", "tests/snapshots/slip_surface__ki_segments_cdem_springs.snap"]),
    ("slope-failure/", &["verification/cases/slope-slip/slope-slip.toml", "verification/cases/slope-slip/slope-slip-stable.toml", "tests/snapshots/progressive_slope__slope_failure_sequence.snap"]),
    ("wulong/wet-", &["verification/cases/wulong/wulong-wet.toml", "verification/cases/wulong/wulong.geo"]),
    ("wulong/", &["verification/cases/wulong/wulong.toml", "tests/snapshots/wulong__wulong_failure_sequence.snap"]),
    ("block/", &["tests/fixtures/block-on-plane.toml"]),
    ("runout/3dec-sliding", &["verification/runout/sliding.toml", "verification/runout/sliding.msh"]),
    ("runout/energy-3dec-sliding", &["verification/runout/sliding.toml", "verification/runout/sliding.msh"]),
    ("runout/determinism", &["verification/runout/sliding.toml", "verification/runout/sliding.msh"]),
    ("runout/determinism-water", &["verification/runout/launched.toml", "verification/runout/launched.msh"]),
    ("runout/3dec-at-rest", &["verification/runout/at-rest.toml", "verification/runout/at-rest.msh"]),
    ("runout/3dec-toppling", &["verification/runout/toppling.toml", "verification/runout/toppling.msh"]),
    ("runout/energy-3dec-toppling", &["verification/runout/toppling.toml", "verification/runout/toppling.msh"]),
    ("runout/launched", &["verification/runout/launched.toml", "verification/runout/launched.msh"]),
    ("runout/energy-launched", &["verification/runout/launched.toml", "verification/runout/launched.msh"]),
    ("runout/dropped", &["verification/runout/dropped.toml", "verification/runout/dropped.msh"]),
    ("runout/energy-dropped", &["verification/runout/dropped.toml", "verification/runout/dropped.msh"]),
    ("runout/objectivity", &["verification/runout/dropped.toml", "verification/runout/dropped.msh"]),
    ("runout/slope-slip", &["verification/runout/slope-slip-runout.toml", "verification/cases/slope-slip/slope-slip.msh"]),
    ("runout/energy-slope-slip", &["verification/runout/slope-slip-runout.toml", "verification/cases/slope-slip/slope-slip.msh"]),
    ("srm/block-friction", &["verification/cases/block-srm/block-srm-friction.toml"]),
    ("srm/block-cohesion", &["verification/cases/block-srm/block-srm-cohesion.toml"]),
    ("water/column-", &["verification/water/column-submerged.toml", "verification/cases/column/column.geo"]),
    ("water/infinite-half-srm", &["verification/water/infinite-slope-half.toml", "verification/water/infinite-slope.geo"]),
    ("water/infinite-full-srm", &["verification/water/infinite-slope-full.toml", "verification/water/infinite-slope.geo"]),
    ("water/plane-half-srm", &["verification/water/plane-half.toml", "verification/joints/plane-geometry.toml"]),
    ("water/plane-full-srm", &["verification/water/plane-full.toml", "verification/joints/plane-geometry.toml"]),
    ("water/plane-crack-srm", &["verification/water/plane-crack.toml", "verification/joints/plane-geometry.toml"]),
    ("joints/plane-srm", &["verification/joints/plane.toml", "verification/joints/plane-geometry.toml"]),
    ("joints/wedge-srm", &["verification/joints/wedge.toml", "verification/joints/wedge-geometry.toml"]),
    ("joints/wedge-general-srm", &["verification/joints/wedge-general.toml", "verification/joints/wedge-general-geometry.toml"]),
    ("joints/toppling-srm", &["verification/joints/toppling.toml"]),
    ("analysis/column/", &["verification/analysis/column-circle.toml"]),
    ("analysis/slope/", &["verification/cases/slope/slope.toml"]),
    ("ensemble/segment/", &["verification/ensemble/cohesive-segment.toml"]),
    ("meshes/regenerated", &[]),
    ("perf/", &["verification/cases/slope/slope.toml"]),
    ("perf/plastic-over-condensed", &["verification/cases/slope/slope.toml", "verification/plastic/paper-slope/paper-slope.toml"]),
    ("perf/avx2-speedup", &["verification/plastic/paper-slope/paper-slope.toml"]),
    ("perf/lem/", &["verification/lem/paper-slope-explicit.toml", "verification/lem/acads-1a.toml", "references/pyslope.json"]),
    ("perf/phase2/", &["verification/cases/slope-slip/slope-slip.toml"]),
    ("perf/srm/", &["verification/cases/slope-slip/slope-slip.toml"]),
    ("perf/srm/plastic-gl1-hex/", &["verification/plastic/griffiths-lane-1/gl1-hex.toml"]),
    ("perf/srm/plastic-paper-slope/", &["verification/plastic/paper-slope/paper-slope.toml"]),
    ("perf/ensemble/", &["verification/ensemble/paper-slope-slip.toml", "verification/ensemble/paper-slope-slip-srm.toml"]),
    ("lem/water-fk-ru/", &["verification/lem/fredlund-krahn-1977-ru.toml"]),
    ("lem/water-arai-tagyo/", &["verification/lem/arai-tagyo-1985-water.toml"]),
    ("lem/water-acads-1b/", &["verification/lem/acads-1b.toml"]),
];

/// The declared files of row `id` with reference `source` (its
/// [`super::RowSpec::source`]; relative paths, sorted, each once): its
/// prefix's entry, the source's file under references/, and what the TOML
/// files among them name (recursively). `None`: no prefix covers it.
pub fn declared(id: &str, source: &str, root: &Path) -> Option<Vec<String>> {
    let (prefix, files) = DECLARED.iter().filter(|(p, _)| id.starts_with(p)).max_by_key(|(p, _)| p.len())?;
    let mut out: Vec<String> = files.iter().map(|f| f.to_string()).collect();
    if *prefix == "extreme/" {
        // `extreme/<case>` (PCG) and `extreme/<case>/dr` read the same scene.
        let name = id.trim_start_matches(prefix).trim_end_matches("/dr");
        out.push(format!("verification/extreme/{name}.toml"));
    }
    if *prefix == "meshes/regenerated" {
        out.extend(case_meshes(root));
    }
    // The source's file: "references/x.md", or "cdem fem (references/skfem.md)".
    out.extend(
        source
            .split(|c: char| c.is_whitespace() || c == '(' || c == ')')
            .filter(|w| w.starts_with("references/"))
            .map(str::to_string),
    );
    let mut k = 0;
    while k < out.len() {
        if out[k].ends_with(".toml") {
            for named in named_files(root, &out[k]) {
                if !out.contains(&named) {
                    out.push(named);
                }
            }
        }
        k += 1;
    }
    out.sort();
    out.dedup();
    Some(out)
}

/// Every `.geo` and `.msh` in the directories under [`CASE_DIRS`].
fn case_meshes(root: &Path) -> Vec<String> {
    let mut dirs: Vec<String> = MESH_DIRS.iter().map(|d| d.to_string()).collect();
    for cases in CASE_DIRS {
        dirs.push(cases.to_string());
        for dir in std::fs::read_dir(root.join(cases)).into_iter().flatten().flatten() {
            if dir.path().is_dir() {
                if let Some(d) = dir.file_name().to_str() {
                    dirs.push(format!("{cases}/{d}"));
                }
            }
        }
    }
    let mut out = Vec::new();
    for dir in dirs {
        for f in std::fs::read_dir(root.join(&dir)).into_iter().flatten().flatten() {
            let path = f.path();
            if path.extension().is_some_and(|e| e == "geo" || e == "msh") {
                if let Some(n) = path.file_name().and_then(|n| n.to_str()) {
                    out.push(format!("{dir}/{n}"));
                }
            }
        }
    }
    out.sort();
    out
}

/// The files a TOML input names: its string values ending in `.msh` and
/// those ending in `.toml`, `.json` or `.csv` that are files, relative to
/// its directory (a scene's mesh, an LEM input's `from_mesh`, an ensemble's
/// scene). An
/// unreadable TOML names nothing here: it is digested as it is (or as
/// missing) by [`super::freshness`].
fn named_files(root: &Path, toml_file: &str) -> Vec<String> {
    let Ok(text) = std::fs::read_to_string(root.join(toml_file)) else { return Vec::new() };
    let Ok(value) = text.parse::<toml::Table>() else { return Vec::new() };
    let dir = Path::new(toml_file).parent().unwrap_or(Path::new(""));
    let mut strings = Vec::new();
    collect_strings(&toml::Value::Table(value), &mut strings);
    strings
        .into_iter()
        .filter(|s| [".msh", ".toml", ".json", ".csv"].iter().any(|e| s.ends_with(e)))
        .filter_map(|s| normalise(&dir.join(&s)))
        // A mesh is an input even when it is missing (then the row is stale:
        // fail closed); other names count if they are files (not outputs).
        .filter(|p| p.ends_with(".msh") || root.join(p).is_file())
        .collect()
}

fn collect_strings(v: &toml::Value, out: &mut Vec<String>) {
    match v {
        toml::Value::String(s) => out.push(s.clone()),
        toml::Value::Array(a) => a.iter().for_each(|x| collect_strings(x, out)),
        toml::Value::Table(t) => t.values().for_each(|x| collect_strings(x, out)),
        _ => {}
    }
}

/// `a/b/../c` as `a/c`, with `/` separators; `None` if it leaves the root.
fn normalise(p: &Path) -> Option<String> {
    let mut parts: Vec<String> = Vec::new();
    for c in p.components() {
        match c {
            std::path::Component::Normal(s) => parts.push(s.to_str()?.to_string()),
            std::path::Component::ParentDir => {
                parts.pop()?;
            }
            std::path::Component::CurDir => {}
            _ => return None,
        }
    }
    Some(parts.join("/"))
}
