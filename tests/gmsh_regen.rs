//! Every committed case mesh is what its `.geo` makes: gmsh regenerates each
//! `verification/cases/*/*.geo`, `verification/extreme/*.geo`,
//! `verification/study/*.geo` and `verification/tutorial/*.geo` (every
//! `.geo` with a committed `.msh` beside it) into a temporary directory and the result must
//! equal the committed `.msh` (connectivity, tags and groups exactly, node
//! coordinates within 1e-9 of the model size). Without gmsh on PATH the test
//! is skipped with a note and a visible `skipped` row in the validation table,
//! except in CI (`CI=true`), where gmsh must run.

use std::io::Write;
use std::path::{Path, PathBuf};

use cdem::mesh::gmsh::{gmsh_available, mesh_drift, read_msh, regenerate};
use cdem::Error;

fn case_geos() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("verification");
    let mut dirs = vec![root.join("extreme"), root.join("study"), root.join("tutorial")];
    for case in std::fs::read_dir(root.join("cases")).expect("verification/cases exists") {
        dirs.push(case.expect("readable directory entry").path());
    }
    let mut geos = Vec::new();
    for dir in dirs {
        for file in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
            if file.path().extension().is_some_and(|e| e == "geo") {
                geos.push(file.path());
            }
        }
    }
    geos.sort();
    geos
}

/// True (after a note) if gmsh is not on PATH; panics instead in CI.
fn skip_without_gmsh(what: &str) -> bool {
    if gmsh_available() {
        return false;
    }
    if std::env::var("CI").as_deref() == Ok("true") {
        panic!("gmsh must run in CI, but it is not on PATH");
    }
    // Straight to stderr: the test harness would capture `eprintln!`.
    let _ = writeln!(std::io::stderr(), "note: gmsh is not on PATH; skipping {what}");
    true
}

#[test]
fn committed_case_meshes_match_their_geo() {
    let spec = cdem::harness::registry::row("meshes/regenerated");
    if skip_without_gmsh("the regeneration check") {
        cdem::harness::report::record("gmsh_regen", &[spec.skipped("gmsh is not on PATH (it must be in CI)")]);
        return;
    }
    let t0 = std::time::Instant::now();
    let geos = case_geos();
    assert!(!geos.is_empty(), "no .geo under verification/cases/*/");
    let dir = std::env::temp_dir().join(format!("cdem-gmsh-regen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let mut failures = Vec::new();
    for geo in &geos {
        let committed = geo.with_extension("msh");
        let fresh = dir.join(committed.file_name().expect("a file name"));
        regenerate(geo, &fresh).unwrap_or_else(|e| panic!("{}: {e}", geo.display()));
        let a = read_msh(&committed).unwrap_or_else(|e| panic!("{}: {e}", committed.display()));
        let b = read_msh(&fresh).unwrap_or_else(|e| panic!("{}: {e}", fresh.display()));
        if let Some(drift) = mesh_drift(&a, &b, 1e-9) {
            failures.push(format!(
                "{}: {drift} (regenerate it with `gmsh {} -3 -format msh41 -o {}`)",
                committed.display(),
                geo.display(),
                committed.display()
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    let ours = format!("{} of {} meshes equal", geos.len() - failures.len(), geos.len());
    let row = spec.compared(
        &ours,
        &format!("{} of {} meshes equal", geos.len(), geos.len()),
        failures.is_empty(),
        t0.elapsed().as_secs_f64(),
    );
    cdem::harness::report::record("gmsh_regen", &[row]);
    assert!(failures.is_empty(), "committed meshes differ from their .geo:\n{}", failures.join("\n"));
}

/// gmsh exits with status 0 on a syntax error (and writes an empty mesh):
/// `regenerate` still reports it, with gmsh's message.
#[test]
fn a_broken_geo_is_a_gmsh_error() {
    if skip_without_gmsh("the broken .geo check") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("cdem-gmsh-broken-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let geo = dir.join("broken.geo");
    std::fs::write(&geo, "Point(1) = {0, 0, 0;\n").expect("write the .geo");
    let result = regenerate(&geo, &dir.join("broken.msh"));
    let _ = std::fs::remove_dir_all(&dir);
    match result {
        Err(Error::Gmsh(message)) => assert!(message.contains("syntax error"), "{message}"),
        other => panic!("expected Error::Gmsh, got {other:?}"),
    }
}
