//! The committed meshes against what gmsh makes of their `.geo` (row
//! `meshes/regenerated`, as tests/gmsh_regen.rs checks it): every `.geo`
//! under verification/extreme, verification/study, verification/tutorial,
//! verification/joints, verification/cases/* and verification/plastic/*
//! is regenerated into a temporary directory and compared with the `.msh`
//! beside it (connectivity, tags and groups exactly, node coordinates within
//! 1e-9 of the model size). Without gmsh the row is skipped, with the reason.

use std::path::{Path, PathBuf};

use crate::harness::registry as reg;
use crate::harness::report::Check;
use crate::mesh::gmsh::{gmsh_available, mesh_drift, read_msh, regenerate};

/// The reason of the skipped row without gmsh (as tests/gmsh_regen.rs gives it).
pub const NO_GMSH: &str = "gmsh is not on PATH (it must be in CI)";

/// Every `.geo` with a committed `.msh` beside it, under `root`, sorted.
pub fn geos(root: &Path) -> Vec<PathBuf> {
    let v = root.join("verification");
    let mut dirs = vec![v.join("extreme"), v.join("study"), v.join("tutorial"), v.join("joints"), v.join("runout")];
    for parent in ["cases", "plastic"] {
        dirs.extend(std::fs::read_dir(v.join(parent)).into_iter().flatten().flatten().map(|e| e.path()));
    }
    let mut geos: Vec<PathBuf> = dirs
        .iter()
        .flat_map(|d| std::fs::read_dir(d).into_iter().flatten().flatten().map(|f| f.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "geo") && p.with_extension("msh").exists())
        .collect();
    geos.sort();
    geos
}

/// The row: skipped without gmsh; else how many meshes equal their
/// regenerated `.geo` (a mesh that differs, or a `.geo` gmsh refuses, is
/// named in the row's defect).
pub fn regenerated_row(root: &Path) -> Check {
    let spec = reg::row("meshes/regenerated");
    if !gmsh_available() {
        return spec.skipped(NO_GMSH);
    }
    let t0 = std::time::Instant::now();
    let geos = geos(root);
    let dir = std::env::temp_dir().join(format!("cdem-reproduce-gmsh-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let mut failures = Vec::new();
    for geo in &geos {
        let committed = geo.with_extension("msh");
        let fresh = dir.join(committed.file_name().unwrap_or_default());
        let drift = regenerate(geo, &fresh)
            .and_then(|_| Ok(mesh_drift(&read_msh(&committed)?, &read_msh(&fresh)?, 1e-9)))
            .unwrap_or_else(|e| Some(e.to_string()));
        if let Some(d) = drift {
            failures.push(format!("{}: {d}", committed.strip_prefix(root).unwrap_or(&committed).display()));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    let n = geos.len();
    let row = spec.compared(
        &format!("{} of {n} meshes equal", n - failures.len()),
        &format!("{n} of {n} meshes equal"),
        failures.is_empty() && n > 0,
        t0.elapsed().as_secs_f64(),
    );
    if failures.is_empty() {
        row
    } else {
        row.with_defect(failures.join("; "))
    }
}
