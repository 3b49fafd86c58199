//! `cdem fem` against the scikit-fem solution committed in
//! references/skfem.json (references/skfem.md, tests/fem.rs): the column,
//! the slope unperturbed and perturbed, solved here and compared with the
//! recorded values (no Python needed). Rows `fem/skfem/<case>/*`.

use std::path::Path;

use crate::drivers::solve_fem;
use crate::error::Error;
use crate::fem::FemSolution;
use crate::harness::registry::{self as reg, SKFEM_JSON};
use crate::harness::report::Check;
use crate::scene::Scene;

/// One case of the JSON: what was compared and its rows.
pub struct SkfemCase {
    /// The JSON's key (`column`, `slope`, `slope_perturbed`).
    pub name: String,
    /// Cells and free unknowns: ours, and the JSON's.
    pub elements: (usize, u64),
    pub free_dofs: (usize, u64),
    /// (key, ours, scikit-fem) of the summary values.
    pub values: Vec<(&'static str, f64, f64)>,
    /// The largest relative difference of every compared value.
    pub worst: f64,
    pub rows: Vec<Check>,
}

fn bad(what: impl Into<String>) -> Error {
    Error::io(SKFEM_JSON, std::io::Error::other(what.into()))
}

fn centroid(sol: &FemSolution, c: usize) -> [f64; 3] {
    let n = sol.cells[c].corners();
    [0, 1, 2].map(|d| n.iter().map(|&i| sol.coords[i][d]).sum::<f64>() / n.len() as f64)
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Every case of references/skfem.json (under `root`), in its order. A
/// case whose mesh does not match the JSON's (cells, free unknowns) or whose
/// recorded points are not found has rows with that defect.
pub fn cases(root: &Path) -> Result<Vec<SkfemCase>, Error> {
    let path = root.join(SKFEM_JSON);
    let text = std::fs::read_to_string(&path).map_err(|e| Error::io(&path, e))?;
    let refs: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| Error::io(&path, std::io::Error::other(e)))?;
    let num = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
    let cases = refs["cases"].as_object().ok_or_else(|| bad("no \"cases\""))?;
    let mut out = Vec::new();
    for (name, case) in cases {
        let scene_path = case["scene"].as_str().ok_or_else(|| bad(format!("{name}: no scene")))?;
        let mut s = Scene::load(&root.join(scene_path))?;
        let perturbed = case["perturbed"].as_bool().unwrap_or(false);
        let mut defects = Vec::new();
        if !perturbed {
            s.perturbation.ratio = 0.0; // scikit-fem solved the committed mesh as is
        } else if s.perturbation.ratio <= 0.0 {
            defects.push(format!("{name}: the scene is not perturbed"));
        }
        let sol = solve_fem(&s)?;
        let elements = (sol.cells.len(), case["elements"].as_u64().unwrap_or(0));
        let free_dofs = (sol.free_dofs, case["free_dofs"].as_u64().unwrap_or(0));
        if elements.0 as u64 != elements.1 || free_dofs.0 as u64 != free_dofs.1 {
            defects.push(format!("{name}: cells / free unknowns {elements:?} {free_dofs:?} (ours, scikit-fem)"));
        }
        let uz: Vec<f64> = sol.u.iter().skip(2).step_by(3).copied().collect();
        let top = sol.coords.iter().map(|x| x[2]).fold(f64::MIN, f64::max);
        let top_uz: Vec<f64> = (0..uz.len()).filter(|&n| sol.coords[n][2] == top).map(|n| uz[n]).collect();
        let szz: Vec<f64> = sol.stress.iter().map(|s| s[2]).collect();
        let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
        let ours = [
            ("max_abs_uz", sol.summary.max_abs_uz),
            ("min_uz", sol.summary.min_uz),
            ("top_mean_uz", top_uz.iter().sum::<f64>() / top_uz.len() as f64),
            ("rms_uz", rms(&uz)),
            ("min_element_szz", szz.iter().copied().fold(f64::INFINITY, f64::min)),
            ("max_element_szz", szz.iter().copied().fold(f64::NEG_INFINITY, f64::max)),
            ("rms_element_szz", rms(&szz)),
        ];
        let t = sol.summary.wall_s;
        let mut worst: f64 = 0.0;
        let mut rows = Vec::new();
        let mut values = Vec::new();
        let prefix = format!("fem/skfem/{}", name.replace('_', "-"));
        for (key, v) in ours {
            let r = num(&case[key]);
            let id = match key {
                "max_abs_uz" => Some("max-abs-uz"),
                "min_element_szz" => Some("min-szz"),
                _ => None,
            };
            if let Some(id) = id {
                rows.push(reg::row(&format!("{prefix}/{id}")).value(v, r, t));
            }
            values.push((key, v, r));
            worst = worst.max(rel(v, r));
        }
        let u_scale = sol.summary.max_abs_u;
        for p in case["u_at_nodes"].as_array().into_iter().flatten() {
            let x: Vec<f64> = p["x"].as_array().into_iter().flatten().map(num).collect();
            match (0..sol.coords.len())
                .find(|&n| x.len() == 3 && (0..3).all(|d| (sol.coords[n][d] - x[d]).abs() < 1e-9))
            {
                Some(n) => {
                    for d in 0..3 {
                        worst = worst.max((sol.u[3 * n + d] - num(&p["u"][d])).abs() / u_scale);
                    }
                }
                None => defects.push(format!("{name}: no node at {x:?}")),
            }
        }
        let s_scale = szz.iter().map(|v| v.abs()).fold(0.0, f64::max);
        for p in case["szz_of_element_nearest"].as_array().into_iter().flatten() {
            let c: Vec<f64> = p["centroid"].as_array().into_iter().flatten().map(num).collect();
            let found = (0..sol.cells.len())
                .find(|&e| c.len() == 3 && (0..3).all(|d| (centroid(&sol, e)[d] - c[d]).abs() < 1e-9));
            match found {
                Some(e) => worst = worst.max((szz[e] - num(&p["szz"])).abs() / s_scale),
                None => defects.push(format!("{name}: no element with centroid {c:?}")),
            }
        }
        // Same discretisation (trilinear hexahedra, 2x2x2 Gauss, consistent
        // load, Gauss-volume-averaged stress): agreement to round-off.
        rows.push(reg::row(&format!("{prefix}/all")).value(worst, 0.0, t));
        if !defects.is_empty() {
            let d = defects.join("; ");
            rows = rows.into_iter().map(|r| r.with_defect(d.clone())).collect();
        }
        out.push(SkfemCase { name: name.clone(), elements, free_dofs, values, worst, rows });
    }
    Ok(out)
}

/// The name under which a case's rows are recorded (`fem_skfem_<case>`).
pub fn record_name(case: &str) -> String {
    format!("fem_skfem_{}", case.replace(|c: char| !c.is_alphanumeric(), "_"))
}
