//! A seeded fuzz run over scene-and-mesh combinations (issue: no silent
//! mistakes). Each case is a scene on the column mesh or the slip slope's,
//! built from random valid choices (fixities that hold the model, plane
//! `keep_flat` groups, curved `keep_on` groups, internal interfaces, joints,
//! perturbation) with 0 to 2 defects injected from a list whose error is
//! known. Expected: no panic; a scene with no defect is accepted (the model
//! builds and its supports hold); a scene with a defect is refused with the
//! error of one of its defects. Nothing invalid is accepted silently.
//! `CDEM_FUZZ_SCENES=N` sets the number of cases (default 400); counts in
//! references/fuzz.md.

use std::collections::BTreeMap;
use std::path::Path;

use cdem::drivers::build_model;
use cdem::drivers::run::check_supports;
use cdem::mesh::perturb::SplitMix64;
use cdem::scene::Scene;
use cdem::{Error, ModelError};

/// The errors a defect must produce.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Defect {
    UnknownBoundaryGroup,
    UnknownMaterialGroup,
    MissingMaterial,
    OuterInterface,
    CurvedKeepFlat,
    Unsupported,
}

impl Defect {
    fn matches(self, e: &Error) -> bool {
        match (self, e) {
            (Defect::UnknownBoundaryGroup, Error::Model(ModelError::UnknownGroup { key, .. })) => {
                key.starts_with("boundary[")
            }
            (Defect::UnknownMaterialGroup, Error::Model(ModelError::UnknownGroup { key, .. })) => {
                key.starts_with("material[")
            }
            (Defect::MissingMaterial, Error::Model(ModelError::NoMaterial { .. })) => true,
            (Defect::OuterInterface, Error::Model(ModelError::NotAnInterface { .. })) => true,
            (Defect::CurvedKeepFlat, Error::Model(ModelError::NotPlanar { .. })) => true,
            (Defect::Unsupported, Error::Model(ModelError::FreeRigidMotion { .. })) => true,
            _ => false,
        }
    }
}

struct Mesh {
    dir: &'static str,
    file: &'static str,
    volumes: &'static [&'static str],
    /// Outer plane surfaces, and the fixities that hold the model (the base fully fixed).
    planes: &'static [&'static str],
    base: &'static str,
    /// Internal surfaces (curved).
    internal: &'static [&'static str],
}

const MESHES: [Mesh; 2] = [
    Mesh {
        dir: "verification/cases/column",
        file: "column.msh",
        volumes: &["rock"],
        planes: &["bottom", "top", "xmin", "xmax", "ymin", "ymax"],
        base: "bottom",
        internal: &[],
    },
    Mesh {
        dir: "verification/cases/slope-slip",
        file: "slope-slip.msh",
        volumes: &["mass", "rest"],
        planes: &["bottom", "left", "right", "front", "back"],
        base: "bottom",
        internal: &["slip"],
    },
];

fn pick<'a>(rng: &mut SplitMix64, v: &[&'a str]) -> &'a str {
    v[(rng.next_u64() % v.len() as u64) as usize]
}

/// One scene's text and its injected defects.
fn scene_case(rng: &mut SplitMix64, mesh: &Mesh) -> (String, Vec<Defect>) {
    let mut defects = Vec::new();
    let n_defects = rng.next_u64() % 3;
    let inject = |rng: &mut SplitMix64| {
        let all = [
            Defect::UnknownBoundaryGroup,
            Defect::UnknownMaterialGroup,
            Defect::MissingMaterial,
            Defect::OuterInterface,
            Defect::CurvedKeepFlat,
            Defect::Unsupported,
        ];
        let d = all[(rng.next_u64() % all.len() as u64) as usize];
        if d == Defect::CurvedKeepFlat && mesh.internal.is_empty()
            || d == Defect::MissingMaterial && mesh.volumes.len() < 2
        {
            return None;
        }
        Some(d)
    };
    for _ in 0..n_defects {
        if let Some(d) = inject(rng) {
            if !defects.contains(&d) {
                defects.push(d);
            }
        }
    }
    let has = |d: Defect| defects.contains(&d);
    let mut t = format!("[mesh]\nfile = {:?}\n", mesh.file);
    // Perturbation; keep_flat on plane groups, keep_on on curved ones.
    let ratio = [0.0, 0.05, 0.1, 0.15][(rng.next_u64() % 4) as usize];
    t += &format!("[perturbation]\nratio = {ratio}\nseed = {}\n", rng.next_u64() % 1000);
    let mut flat: Vec<&str> = mesh.planes.iter().copied().filter(|_| rng.next_u64().is_multiple_of(3)).collect();
    if has(Defect::CurvedKeepFlat) {
        flat.push(mesh.internal[0]);
    }
    t += &format!("keep_flat = {flat:?}\n");
    if !mesh.internal.is_empty() && !has(Defect::CurvedKeepFlat) {
        t += &format!("keep_on = {:?}\n", mesh.internal);
    }
    // Materials: every volume group, unless the last is dropped; the first maybe
    // misspelt (its group then also lacks a material, reported after the unknown name).
    for (k, v) in mesh.volumes.iter().enumerate() {
        if has(Defect::MissingMaterial) && k == mesh.volumes.len() - 1 {
            continue;
        }
        let name = if has(Defect::UnknownMaterialGroup) && k == 0 { format!("{v}_x") } else { v.to_string() };
        t +=
            &format!("[[material]]\ngroup = {name:?}\nyoungs_modulus = 3.0e8\npoisson_ratio = 0.3\ndensity = 2100.0\n");
    }
    let springs = rng.next_u64().is_multiple_of(2);
    t += if springs {
        "[joints]\nmode = \"springs\"\nnormal_modulus = 1.0e11\nshear_modulus = 3.85e10\nthickness = 1.0\n"
    } else {
        "[joints]\nmode = \"merged\"\n"
    };
    for g in mesh.internal {
        if rng.next_u64().is_multiple_of(2) {
            t += &format!("[[interface]]\ngroup = {g:?}\nmode = \"springs\"\nnormal_modulus = 1.0e11\nshear_modulus = 3.85e10\nthickness = 1.0\nstrength = {{ tensile = 1.0e4, cohesion = 1.0e4, friction_angle = 20.0 }}\n");
        }
    }
    if has(Defect::OuterInterface) {
        t += &format!("[[interface]]\ngroup = {:?}\nmode = \"merged\"\n", pick(rng, mesh.planes));
    }
    // Supports: the base fully fixed (held) or only in z (free to slide and spin),
    // plus random rollers on the planes.
    let base_fix = if has(Defect::Unsupported) { "[\"z\"]" } else { "[\"x\", \"y\", \"z\"]" };
    let base = if has(Defect::UnknownBoundaryGroup) { format!("{}_", mesh.base) } else { mesh.base.to_string() };
    t += &format!("[[boundary]]\ngroup = {base:?}\nfix = {base_fix}\n");
    if !has(Defect::Unsupported) {
        for g in mesh.planes.iter().filter(|g| **g != mesh.base) {
            if rng.next_u64().is_multiple_of(3) {
                t += &format!("[[boundary]]\ngroup = {g:?}\nfix = [{:?}]\n", pick(rng, &["x", "y", "z"]));
            }
        }
    }
    (t, defects)
}

#[test]
fn scenes_with_injected_defects_are_refused_and_valid_ones_accepted() {
    let n: usize = std::env::var("CDEM_FUZZ_SCENES").ok().and_then(|v| v.parse().ok()).unwrap_or(400);
    let mut rng = SplitMix64::new(20261201);
    let (mut accepted, mut refused, mut panics) = (0, 0, 0);
    let mut by_defect: BTreeMap<String, usize> = BTreeMap::new();
    let mut wrong = Vec::new();
    for k in 0..n {
        let mesh = &MESHES[k % MESHES.len()];
        let (text, defects) = scene_case(&mut rng, mesh);
        let outcome = std::panic::catch_unwind(|| {
            let scene = Scene::from_toml(&text, Path::new(mesh.dir), Path::new("fuzz.toml")).map_err(Error::from)?;
            let model = build_model(&scene)?;
            check_supports(&model)
        });
        let Ok(result) = outcome else {
            panics += 1;
            wrong.push(format!("case {k}: panic\n{text}"));
            continue;
        };
        for d in &defects {
            *by_defect.entry(format!("{d:?}")).or_default() += 1;
        }
        match (&result, defects.is_empty()) {
            (Ok(()), true) => accepted += 1,
            (Err(e), false) if defects.iter().any(|d| d.matches(e)) => refused += 1,
            (Ok(()), false) => wrong.push(format!("case {k}: accepted with defects {defects:?}\n{text}")),
            (Err(e), _) => wrong.push(format!("case {k}: defects {defects:?} but error: {e}\n{text}")),
        }
    }
    println!("{n} scenes: {accepted} valid accepted, {refused} invalid refused with their error, {panics} panics; defects injected {by_defect:?}");
    assert!(wrong.is_empty(), "{} of {n} cases wrong; first:\n{}", wrong.len(), wrong[0]);
    assert!(accepted > n / 5 && refused > n / 5, "both kinds exercised");
}
