//! Error against run time (issue: FEM reference): CDEM and the implicit FEM
//! on the column and the slope, varying one factor at a time around a base
//! point: mesh resolution (3), joint stiffness E_j (3), convergence
//! tolerance (3). Writes `study.csv` and a log-log figure per case.
//!
//! Error measure: the relative L2 error of the displacement field,
//! mass-weighted over nodes (see [`crate::analysis::compare`]):
//! - column: against the analytic `u_z(z)` ([`registry::column_uz`],
//!   references/column.md) at each node;
//! - slope: against the FEM on the finest mesh (`slope-h05`, 0.5 m), sampled
//!   at the coincident nodes (the transfinite meshes are nested). The study
//!   meshes are not perturbed, so that they nest.

use std::collections::HashMap;
use std::fmt::Write;
use std::path::Path;

use serde::Serialize;

use crate::drivers::run_scene;
use crate::drivers::solve_fem as solve_scene;
use crate::error::Error;
use crate::fem::FemSolution;
use crate::harness::registry;
use crate::output::figures::{line_plot, Scale, Series};
use crate::scene::Scene;

/// One point of the study.
#[derive(Debug, Clone, Serialize)]
pub struct StudyRow {
    pub case: String,
    pub method: String,
    /// Which factor this row varies: "resolution", "stiffness", "tolerance" or "base".
    pub varied: String,
    pub elements: usize,
    pub joint_modulus: f64,
    pub tolerance: f64,
    pub error: f64,
    pub wall_s: f64,
    pub steps: usize,
}

/// Reference displacement at a point.
trait Reference {
    fn at(&self, x: [f64; 3]) -> [f64; 3];
}

/// The analytic confined column (references/column.md).
struct Column;
impl Reference for Column {
    fn at(&self, x: [f64; 3]) -> [f64; 3] {
        [0.0, 0.0, registry::column_uz(x[2])]
    }
}

/// The finest FEM solution, looked up at coincident nodes.
struct Nodal(HashMap<[i64; 3], [f64; 3]>);
fn key(x: [f64; 3]) -> [i64; 3] {
    x.map(|v| (v * 1e6).round() as i64)
}
impl Nodal {
    fn new(fem: &FemSolution) -> Self {
        Self(
            fem.coords
                .iter()
                .enumerate()
                .map(|(i, &x)| (key(x), [fem.u[3 * i], fem.u[3 * i + 1], fem.u[3 * i + 2]]))
                .collect(),
        )
    }
}
impl Reference for Nodal {
    fn at(&self, x: [f64; 3]) -> [f64; 3] {
        self.0.get(&key(x)).copied().unwrap_or([f64::NAN; 3])
    }
}

/// Mass- (or volume-) weighted relative L2 error of nodal displacements.
fn l2_error(points: impl Iterator<Item = ([f64; 3], [f64; 3], f64)>, reference: &dyn Reference) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for (x, u, w) in points {
        let r = reference.at(x);
        for d in 0..3 {
            num += w * (u[d] - r[d]).powi(2);
            den += w * r[d] * r[d];
        }
    }
    (num / den).sqrt()
}

fn cdem_point(case: &str, varied: &str, scene: &Scene, reference: &dyn Reference) -> Result<StudyRow, Error> {
    let r = run_scene(scene, &mut |_, _| {})?;
    let m = &r.model;
    let err = l2_error(
        (0..m.n_nodes()).map(|i| (m.x0[i], [r.state.u[3 * i], r.state.u[3 * i + 1], r.state.u[3 * i + 2]], m.mass[i])),
        reference,
    );
    Ok(StudyRow {
        case: case.into(),
        method: "cdem".into(),
        varied: varied.into(),
        elements: m.elements.len(),
        joint_modulus: scene.joints.normal_modulus.unwrap_or(f64::NAN),
        tolerance: scene.solver.tolerance,
        error: err,
        wall_s: r.summary.wall_s,
        steps: r.summary.steps,
    })
}

fn fem_point(case: &str, scene: &Scene, reference: &dyn Reference) -> Result<(StudyRow, FemSolution), Error> {
    let sol = solve_scene(scene)?;
    // Nodal weights: one per node (the FEM meshes are uniform enough here;
    // the study compares orders of magnitude).
    let err = l2_error(
        (0..sol.coords.len()).map(|i| (sol.coords[i], [sol.u[3 * i], sol.u[3 * i + 1], sol.u[3 * i + 2]], 1.0)),
        reference,
    );
    let row = StudyRow {
        case: case.into(),
        method: "fem".into(),
        varied: "resolution".into(),
        elements: sol.cells.len(),
        joint_modulus: f64::NAN,
        tolerance: f64::NAN,
        error: err,
        wall_s: sol.summary.wall_s,
        steps: 1,
    };
    Ok((row, sol))
}

fn with_mesh(base: &Scene, mesh: &str) -> Scene {
    let mut s = base.clone();
    s.mesh.file = mesh.into();
    s.perturbation.ratio = 0.0;
    s.output.vtk = false;
    s
}

/// The factors varied around the base point of one case.
struct Factors<'a> {
    /// Meshes coarse to fine (paths relative to the base scene's directory).
    meshes: &'a [&'a str],
    /// Index of the base mesh in `meshes`.
    base: usize,
    /// Joint normal moduli E_j (Pa).
    moduli: [f64; 3],
    /// Convergence tolerances.
    tolerances: [f64; 3],
}

/// The study of one case.
fn study_case(
    case: &str,
    base_scene: &Scene,
    factors: &Factors,
    reference: &dyn Reference,
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<StudyRow>, Error> {
    let Factors { meshes, base, moduli, tolerances } = *factors;
    let mut rows = Vec::new();
    let base_scene = with_mesh(base_scene, meshes[base]);
    for (k, mesh) in meshes.iter().enumerate() {
        progress(&format!("{case}: mesh {mesh}"));
        let s = with_mesh(&base_scene, mesh);
        rows.push(cdem_point(case, if k == base { "base" } else { "resolution" }, &s, reference)?);
        rows.push(fem_point(case, &s, reference)?.0);
    }
    for e_j in moduli {
        if Some(e_j) == base_scene.joints.normal_modulus {
            continue;
        }
        progress(&format!("{case}: E_j {e_j:e}"));
        let mut s = base_scene.clone();
        s.joints.normal_modulus = Some(e_j);
        s.joints.shear_modulus = Some(e_j / 2.6);
        rows.push(cdem_point(case, "stiffness", &s, reference)?);
    }
    for tol in tolerances {
        if tol == base_scene.solver.tolerance {
            continue;
        }
        progress(&format!("{case}: tolerance {tol:e}"));
        let mut s = base_scene.clone();
        s.solver.tolerance = tol;
        rows.push(cdem_point(case, "tolerance", &s, reference)?);
    }
    Ok(rows)
}

/// One small point of the column study (10 layers, E_j = 1e11, tolerance
/// 1e-7): (CDEM error, FEM error) against the analytic solution.
pub fn column_base_point() -> Result<(f64, f64), Error> {
    let scene = registry::COLUMN.scene()?;
    let c = cdem_point("column", "base", &with_mesh(&scene, "column.msh"), &Column)?;
    let f = fem_point("column", &with_mesh(&scene, "column.msh"), &Column)?.0;
    Ok((c.error, f.error))
}

/// Runs the whole study into `out/study.csv`, `out/study-column.png`,
/// `out/study-slope.png`, and draws `out/study-fs.png`
/// ([`fs_against_run_time`]).
pub fn run_study(out: &Path, progress: &mut dyn FnMut(&str)) -> Result<Vec<StudyRow>, Error> {
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    let column = registry::COLUMN.scene()?;
    let column_factors = Factors {
        meshes: &["column.msh", "../../study/column-l20.msh", "../../study/column-l40.msh"],
        base: 0,
        moduli: [1e10, 1e11, 1e12],
        tolerances: [1e-3, 1e-5, 1e-7],
    };
    let mut rows = study_case("column", &column, &column_factors, &Column, progress)?;
    let slope = registry::SLOPE.scene()?;
    progress("slope: reference FEM on slope-h05 (0.5 m)");
    let (_, finest) = fem_point("slope", &with_mesh(&slope, "../../study/slope-h05.msh"), &Column)?;
    let reference = Nodal::new(&finest);
    let slope_factors = Factors {
        meshes: &["../../study/slope-h4.msh", "slope.msh", "../../study/slope-h1.msh"],
        base: 1,
        moduli: [1e10, 1e11, 1e12],
        tolerances: [1e-3, 1e-4, 1e-5],
    };
    rows.extend(study_case("slope", &slope, &slope_factors, &reference, progress)?);
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in &rows {
        w.serialize(r).map_err(|e| Error::io(out, std::io::Error::other(e)))?;
    }
    let bytes = w.into_inner().map_err(|e| Error::io(out, std::io::Error::other(e.to_string())))?;
    crate::output::write_atomic(&out.join("study.csv"), &bytes)?;
    for case in ["column", "slope"] {
        let pick = |method: &str, varied: &[&str]| -> Vec<(f64, f64)> {
            let mut v: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.case == case && r.method == method && varied.contains(&r.varied.as_str()))
                .map(|r| (r.wall_s.max(1e-4), r.error.max(1e-12)))
                .collect();
            v.sort_by(|a, b| a.0.total_cmp(&b.0));
            v
        };
        let (res, stiff, tol, fem) = (
            pick("cdem", &["base", "resolution"]),
            pick("cdem", &["base", "stiffness"]),
            pick("cdem", &["base", "tolerance"]),
            pick("fem", &["resolution"]),
        );
        let series = [
            Series { name: "CDEM, mesh resolution", points: &res },
            Series { name: "CDEM, joint stiffness", points: &stiff },
            Series { name: "CDEM, tolerance", points: &tol },
            Series { name: "FEM, mesh resolution", points: &fem },
        ];
        let title = format!("{case}: displacement error against run time");
        line_plot(
            &out.join(format!("study-{case}.png")),
            &title,
            "wall time (s)",
            "relative L2 error of u",
            &series,
            Scale::Log,
            Scale::Log,
        )?;
    }
    let mut md = String::from("| case | method | varied | elements | E_j (Pa) | tolerance | error | wall (s) | steps |\n|---|---|---|---|---|---|---|---|---|\n");
    for r in &rows {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {:.0e} | {:.0e} | {:.3e} | {:.3} | {} |",
            r.case, r.method, r.varied, r.elements, r.joint_modulus, r.tolerance, r.error, r.wall_s, r.steps
        );
    }
    md.push_str(&fs_against_run_time(&out.join("study-fs.png"))?);
    crate::output::write_atomic(&out.join("study.md"), md.as_bytes())?;
    Ok(rows)
}

/// The factor of safety against run time (issue 61 item 4) on Griffiths &
/// Lane's hexahedra and the paper slope: each mesh's factor of
/// `cdem srm --mesh-check 1.5,2` as its error against Richardson's
/// extrapolation, against the wall time of its reduction, from the figures
/// references/srm.md measured ([`registry::MESH_CHECK_STUDIES`]; no
/// reduction runs here). Writes `path`; returns its table.
pub fn fs_against_run_time(path: &Path) -> Result<String, Error> {
    let studies = &registry::MESH_CHECK_STUDIES;
    let points: Vec<Vec<(f64, f64)>> = studies
        .iter()
        .map(|s| s.meshes.iter().map(|&(_, fs, wall)| (wall, 100.0 * (fs / s.extrapolated - 1.0))).collect())
        .collect();
    let names: Vec<String> = studies
        .iter()
        .map(|s| format!("{} (extrapolated FS {:.4} +/- {:.3})", s.name, s.extrapolated, s.uncertainty))
        .collect();
    let (t0, t1) = points.iter().flatten().fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let zero = [(t0, 0.0), (t1, 0.0)];
    let mut series: Vec<Series> = names.iter().zip(&points).map(|(n, p)| Series { name: n, points: p }).collect();
    series.push(Series { name: "the extrapolated FS", points: &zero });
    line_plot(
        path,
        "factor of safety against run time: 3 meshes each, the coarsest highest",
        "wall time of the reduction, bracket 0.0025 (s)",
        "FS / extrapolated FS - 1 (%)",
        &series,
        Scale::Log,
        Scale::Linear,
    )?;
    let mut md = String::from(
        "\n### Factor of safety against run time (`cdem srm --mesh-check 1.5,2`; references/srm.md, \"Discretisation error\")\n\n\
         | slope | elements | FS (bracket 0.0025) | against the extrapolated | wall (s) | timed by |\n|---|---|---|---|---|---|\n",
    );
    for s in studies {
        for &(elements, fs, wall) in &s.meshes {
            let _ = writeln!(
                md,
                "| {} | {elements} | {fs:.4} | {:+.1} % | {wall:.1} | {} |",
                s.name,
                100.0 * (fs / s.extrapolated - 1.0),
                s.timing
            );
        }
        let _ =
            writeln!(md, "| {} | extrapolated | {:.4} +/- {:.3} | 0 | - | - |", s.name, s.extrapolated, s.uncertainty);
    }
    Ok(md)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The factor-of-safety figure is drawn from references/srm.md's
    /// figures alone: its table has each slope's three meshes and the
    /// extrapolated factor, and the committed meshes' errors that
    /// references/srm.md states (+2.5 %, +3.3 %, the unsafe side).
    #[test]
    fn the_fs_figure_tabulates_both_slopes_three_meshes() {
        let path = std::env::temp_dir().join(format!("cdem-study-fs-{}.png", std::process::id()));
        let md = fs_against_run_time(&path).unwrap();
        assert!(std::fs::metadata(&path).unwrap().len() > 1000);
        for s in &registry::MESH_CHECK_STUDIES {
            assert_eq!(md.lines().filter(|l| l.starts_with(&format!("| {} |", s.name))).count(), 4, "{md}");
        }
        assert!(md.contains("| 384 | 1.3928 | +2.5 % |") && md.contains("| 1000 | 1.0928 | +3.3 % |"), "{md}");
        if std::env::var_os("CDEM_KEEP_FIGURE").is_none() {
            let _ = std::fs::remove_file(&path);
        }
    }
}
