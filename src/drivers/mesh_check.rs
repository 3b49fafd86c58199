//! The discretisation error of a factor of safety (`cdem srm --mesh-check`;
//! references/srm.md, "Discretisation error"): the strength reduction on
//! the scene's mesh and on meshes refined by the factors `R` asked for, each
//! bisected to [`CHECK_BRACKET_WIDTH`], then Richardson's extrapolation of
//! the factors in the element size `h = 1 / R`
//! ([`crate::analysis::richardson`]: the order observed from three meshes,
//! assumed from two, and said which), and the error of the scene's mesh
//! `(FS - FS_0) / FS_0` with its side: above the extrapolated factor is the
//! unsafe side.
//!
//! The refined meshes: where the scene's `.msh` has its `.geo` beside it
//! (the same stem) and that `.geo` or a file it includes takes `refine` (as
//! every committed `.geo` with transfinite divisions or a size `h / refine`
//! does), gmsh meshes it with `refine` multiplied by `R` (a top-level
//! `refine = x;` of the `.geo` becomes `refine = x R;`, else `refine = R;` is
//! set before it); otherwise every element is split into eight
//! ([`crate::mesh::refine::split`]: no gmsh; `R` 2 or 4). The meshes are
//! written into the output's `mesh-check/` folder.

use std::path::{Path, PathBuf};

use serde::Serialize;

pub use super::discretisation::{discretisation, CheckedMesh, Discretisation, Side, CHECK_BRACKET_WIDTH};
use super::srm::{search_to, SrmProgress, SrmResult, TrialStart};
use crate::analysis::richardson::{extrapolate_assuming, Extrapolation, OrderSource};
use crate::error::{Error, SceneError};
use crate::model::Model;
use crate::scene::Scene;
use crate::solver::Foresight;

/// The refinement a bare `--mesh-check` asks for: one mesh at half the size.
pub const DEFAULT_REFINE: [f64; 1] = [2.0];

/// The refinement factors `refine`, checked: each above 1, increasing; with
/// no `.geo` to mesh, 2 or 4.
fn check_factors(refine: &[f64], split: bool) -> Result<(), Error> {
    let bad = |why: String| Err(SceneError::invalid("--mesh-check", why).into());
    if refine.is_empty() {
        return bad("no refinement factor".into());
    }
    for (i, &r) in refine.iter().enumerate() {
        if !(r > 1.0 && r.is_finite()) {
            return bad(format!("factor {i} is {r}: each refinement factor must be above 1"));
        }
        if i > 0 && r <= refine[i - 1] {
            return bad(format!(
                "factor {i} ({r}) is not above factor {} ({}): give them increasing",
                i - 1,
                refine[i - 1]
            ));
        }
        if split && r != 2.0 && r != 4.0 {
            return bad(format!(
                "factor {i} is {r}: without a .geo that takes `refine` beside the mesh, every element is split, \
                 which refines by 2 or 4"
            ));
        }
    }
    Ok(())
}

/// The `.geo` beside the scene's mesh, if it (or a file it includes, by
/// name) mentions `refine`.
fn refinable_geo(scene: &Scene) -> Option<PathBuf> {
    let geo = scene.mesh_path().with_extension("geo");
    let text = std::fs::read_to_string(&geo).ok()?;
    let dir = geo.parent().map(Path::to_path_buf).unwrap_or_default();
    let takes = |t: &str| t.lines().any(|l| l.split("//").next().unwrap_or("").contains("refine"));
    let included = includes(&text).into_iter().filter_map(|p| std::fs::read_to_string(dir.join(p)).ok());
    (takes(&text) || included.into_iter().any(|t| takes(&t))).then_some(geo)
}

/// The file names of the `Include "..."` lines of a `.geo`.
fn includes(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| l.trim_start().strip_prefix("Include"))
        .filter_map(|rest| rest.split('"').nth(1).map(str::to_string))
        .collect()
}

/// The text of `geo` at `refine` multiplied by `factor`, its includes made
/// absolute (see the module doc).
fn geo_at(geo: &Path, factor: f64) -> Result<String, Error> {
    let text = std::fs::read_to_string(geo).map_err(|e| Error::io(geo, e))?;
    let dir = geo.parent().map(Path::to_path_buf).unwrap_or_default();
    let dir = dir.canonicalize().map_err(|e| Error::io(&dir, e))?;
    let mut set = false;
    let mut out = String::new();
    for line in text.lines() {
        let trimmed = line.trim();
        let assigned = trimmed
            .strip_prefix("refine")
            .map(str::trim_start)
            .and_then(|r| r.strip_prefix('='))
            .and_then(|r| r.split(';').next())
            .and_then(|v| v.trim().parse::<f64>().ok());
        if let (Some(x), false) = (assigned, line.starts_with(char::is_whitespace)) {
            out.push_str(&format!("refine = {}; // {x} x {factor} (cdem srm --mesh-check)\n", x * factor));
            set = true;
        } else if let Some(name) = trimmed.strip_prefix("Include").and_then(|r| r.split('"').nth(1)) {
            let abs = if Path::new(name).is_absolute() { PathBuf::from(name) } else { dir.join(name) };
            out.push_str(&format!("Include \"{}\";\n", abs.display()));
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    if !set {
        out = format!("refine = {factor}; // cdem srm --mesh-check\n{out}");
    }
    Ok(out)
}

/// The mesh at `factor` in `dir`: gmsh on `geo`, else the scene's mesh split.
fn refined_mesh(scene: &Scene, geo: Option<&Path>, factor: f64, dir: &Path) -> Result<PathBuf, Error> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let stem = scene.mesh_path().file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let msh = dir.join(format!("{stem}-r{factor}.msh"));
    match geo {
        Some(geo) => {
            let wrapper = dir.join(format!("{stem}-r{factor}.geo"));
            crate::atomic::write_atomic(&wrapper, geo_at(geo, factor)?.as_bytes())
                .map_err(|e| Error::io(&wrapper, e))?;
            crate::mesh::gmsh::regenerate(&wrapper, &msh)?;
        }
        None => {
            let mut mesh = super::input::read_mesh(scene)?;
            let mut r = 1.0;
            while r < factor {
                mesh = crate::mesh::refine::split(&mesh);
                r *= 2.0;
            }
            crate::mesh::refine::write_msh(&mesh, &msh)?;
        }
    }
    msh.canonicalize().map_err(|e| Error::io(&msh, e))
}

/// What the check tells the caller as it goes.
pub enum CheckProgress<'a> {
    /// A mesh is being made (its factor).
    Meshing(f64),
    /// The reduction on the mesh of this factor (1: the scene's) starts.
    Mesh(f64),
    /// Its progress.
    Srm(SrmProgress<'a>),
}

/// The check of `scene` at the factors `refine` (see the module doc): the
/// scene's reduction (its `srm.json` with the section `discretisation`) and
/// model. The refined meshes go into `dir`.
pub fn mesh_check(
    scene: &Scene,
    refine: &[f64],
    dir: &Path,
    progress: &mut dyn FnMut(CheckProgress),
) -> Result<(SrmResult, Model), Error> {
    let t0 = std::time::Instant::now();
    let geo = refinable_geo(scene);
    check_factors(refine, geo.is_none())?;
    let refined_by = match &geo {
        Some(g) => format!("gmsh on {} with refine multiplied by each factor", g.display()),
        None => "every element split into eight (no .geo beside the mesh takes refine)".to_string(),
    };
    let run = |s: &Scene, r: f64, progress: &mut dyn FnMut(CheckProgress)| {
        progress(CheckProgress::Mesh(r));
        let t = std::time::Instant::now();
        let out = search_to(s, TrialStart::Warm, Some(Foresight::TRIALS), CHECK_BRACKET_WIDTH, &mut |p| {
            progress(CheckProgress::Srm(p))
        })?;
        Ok::<_, Error>((out, t.elapsed().as_secs_f64()))
    };
    let ((mut result, model), own_s) = run(scene, 1.0, progress)?;
    let mut meshes = vec![checked(1.0, scene.mesh_path(), &result, model.elements.len(), own_s, 0.0)];
    for &r in refine {
        progress(CheckProgress::Meshing(r));
        let t = std::time::Instant::now();
        let msh = refined_mesh(scene, geo.as_deref(), r, dir)?;
        let mesh_s = t.elapsed().as_secs_f64();
        let mut s = scene.clone();
        s.mesh.file = msh.clone();
        let ((fine, fine_model), wall_s) = run(&s, r, progress)?;
        meshes.push(checked(r, msh, &fine, fine_model.elements.len(), wall_s, mesh_s));
    }
    let cost_ratio = t0.elapsed().as_secs_f64() / own_s.max(1e-9);
    result.discretisation = Some(discretisation(refined_by, meshes, cost_ratio));
    Ok((result, model))
}

fn checked(refine: f64, mesh: PathBuf, r: &SrmResult, elements: usize, wall_s: f64, mesh_s: f64) -> CheckedMesh {
    CheckedMesh {
        refine,
        mesh,
        elements,
        fs: r.fs,
        bracket: r.bracket,
        hi_outcome: r.hi_outcome,
        trials: r.trials.len(),
        wall_s,
        mesh_s,
    }
}

/// The order assumed for the elastic headline values of linear elements
/// where three meshes observe none: second (the displacement's order in L2).
pub const ELASTIC_ASSUMED_ORDER: f64 = 2.0;

/// One mesh of the FEM's check.
#[derive(Debug, Clone, Serialize)]
pub struct ElasticMesh {
    pub refine: f64,
    pub mesh: PathBuf,
    pub elements: usize,
    /// The smallest vertical displacement (m).
    pub min_uz: f64,
    /// The smallest cell sigma_zz (Pa), if any.
    pub min_szz: Option<f64>,
    pub wall_s: f64,
}

/// `cdem fem --mesh-check` (`DIR/mesh-check.json`): the FEM's headline
/// values on the scene's mesh and the refined ones, and Richardson's
/// extrapolation of each (the order observed from three meshes, else
/// [`ELASTIC_ASSUMED_ORDER`]).
#[derive(Debug, Clone, Serialize)]
pub struct ElasticCheck {
    pub refined_by: String,
    pub meshes: Vec<ElasticMesh>,
    pub min_uz: Option<Extrapolation>,
    pub min_szz: Option<Extrapolation>,
    /// One line per headline value.
    pub lines: Vec<String>,
}

/// The headline values of one elastic solve on one mesh (the FEM's or
/// phase 1 of `cdem run`'s): its [`crate::summary::Summary`]'s.
fn headline(refine: f64, mesh: PathBuf, s: &crate::summary::Summary) -> ElasticMesh {
    ElasticMesh { refine, mesh, elements: s.elements, min_uz: s.min_uz, min_szz: s.min_szz, wall_s: s.wall_s }
}

/// One solve of [`elastic_check`]: the scene (its mesh set), the factor and
/// the mesh file, to the result and its headline values.
type Solve<'a, R> = dyn FnMut(&Scene, f64, PathBuf) -> Result<(R, ElasticMesh), Error> + 'a;

/// The elastic check shared by `cdem fem --mesh-check` and `cdem run
/// --mesh-check`: `solve` on `scene`'s mesh (its result is returned) and on
/// each mesh refined by `refine` (written into `dir`), then Richardson's
/// extrapolation of min u_z and min sigma_zz.
fn elastic_check<R>(
    scene: &Scene,
    refine: &[f64],
    dir: &Path,
    solve: &mut Solve<R>,
) -> Result<(R, ElasticCheck), Error> {
    let geo = refinable_geo(scene);
    check_factors(refine, geo.is_none())?;
    let refined_by = match &geo {
        Some(g) => format!("gmsh on {} with refine multiplied by each factor", g.display()),
        None => "every element split into eight (no .geo beside the mesh takes refine)".to_string(),
    };
    let (own, first) = solve(scene, 1.0, scene.mesh_path())?;
    let mut meshes = vec![first];
    for &r in refine {
        let msh = refined_mesh(scene, geo.as_deref(), r, dir)?;
        let mut s = scene.clone();
        s.mesh.file = msh.clone();
        meshes.push(solve(&s, r, msh)?.1);
    }
    let h: Vec<f64> = meshes.iter().map(|m| 1.0 / m.refine).collect();
    let uz: Vec<f64> = meshes.iter().map(|m| m.min_uz).collect();
    let szz: Option<Vec<f64>> = meshes.iter().map(|m| m.min_szz).collect();
    let min_uz = extrapolate_assuming(&h, &uz, 0.0, ELASTIC_ASSUMED_ORDER);
    let min_szz = szz.as_ref().and_then(|v| extrapolate_assuming(&h, v, 0.0, ELASTIC_ASSUMED_ORDER));
    let line = |name: &str, unit: &str, own: f64, e: Option<Extrapolation>| match e {
        Some(e) => format!(
            "{name} {own:.4e} {unit} on this mesh; about {:.4e} {unit} converged (+/- {:.1e}, order {:.2} {}); this \
             mesh differs {:+.2} %",
            e.value,
            e.uncertainty,
            e.order,
            if e.order_source == OrderSource::Observed { "observed" } else { "assumed" },
            100.0 * (own / e.value - 1.0)
        ),
        None => format!("{name}: no extrapolation"),
    };
    let mut lines = vec![line("min u_z", "m", uz[0], min_uz)];
    if let Some(v) = &szz {
        lines.push(line("min sigma_zz", "Pa", v[0], min_szz));
    }
    Ok((own, ElasticCheck { refined_by, meshes, min_uz, min_szz, lines }))
}

/// The FEM of `scene` on its mesh and on the meshes refined by `refine`
/// (written into `dir`), with the extrapolations of its headline values.
pub fn fem_mesh_check(scene: &Scene, refine: &[f64], dir: &Path) -> Result<(super::FemRun, ElasticCheck), Error> {
    elastic_check(scene, refine, dir, &mut |s, r, mesh| {
        let run = super::run_fem(s)?;
        let em = headline(r, mesh, &run.solution.summary);
        Ok((run, em))
    })
}

/// `cdem run --mesh-check`: the scene's run (returned whole, with its
/// `[failure]` and `[runout]` phases if it has them) and the check of its
/// elastic state: phase 1 on the scene's mesh and on the meshes refined by
/// `refine` (written into `dir`), min u_z and min sigma_zz extrapolated as
/// [`fem_mesh_check`] does. A scene with a phase 2 or a runout gets one more
/// phase-1 run on its own mesh, so that every mesh's values are those of
/// the elastic state (the end of phase 1).
pub fn run_mesh_check(
    scene: &Scene,
    refine: &[f64],
    dir: &Path,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(super::RunResult, ElasticCheck), Error> {
    let elastic_only = scene.failure.is_none() && scene.runout.is_none();
    let mut elastic = scene.clone();
    elastic.failure = None;
    elastic.runout = None;
    let (own, check) = elastic_check(&elastic, refine, dir, &mut |s, r, mesh| {
        let mut quiet = |_: usize, _: f64| {};
        let run = super::run_scene(s, if r == 1.0 && elastic_only { &mut *progress } else { &mut quiet })?;
        let em = headline(r, mesh, &run.summary);
        Ok(((r == 1.0 && elastic_only).then_some(run), em))
    })?;
    let own = match own {
        Some(run) => run,
        None => super::run_scene(scene, progress)?,
    };
    Ok((own, check))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_top_level_refine_is_multiplied_and_includes_made_absolute() {
        let dir = std::env::temp_dir().join(format!("cdem-geo-at-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let geo = dir.join("a.geo");
        std::fs::write(&geo, "shape = 0;\nrefine = 2;\nInclude \"section.geo\";\nIf (x)\n  refine = 3;\nEndIf\n")
            .unwrap();
        let text = geo_at(&geo, 1.5).unwrap();
        assert!(text.contains("refine = 3; // 2 x 1.5"), "{text}");
        assert!(text.contains("  refine = 3;\n"), "an indented assignment is left alone: {text}");
        let abs = dir.canonicalize().unwrap().join("section.geo");
        assert!(text.contains(&format!("Include \"{}\";", abs.display())), "{text}");
        std::fs::write(&geo, "Include \"section.geo\";\n").unwrap();
        assert!(geo_at(&geo, 2.0).unwrap().starts_with("refine = 2;"));
    }

    #[test]
    fn factors_must_rise_above_one_and_split_only_by_two_or_four() {
        assert!(check_factors(&[2.0], true).is_ok());
        assert!(check_factors(&[1.5, 2.0], false).is_ok());
        for (bad, split) in [(&[1.5][..], true), (&[1.0][..], false), (&[2.0, 1.5][..], false), (&[][..], false)] {
            let e = check_factors(bad, split).unwrap_err().to_string();
            assert!(e.contains("--mesh-check"), "{e}");
        }
    }
}
