//! Outputs of `cdem fem`, in the form `cdem run` writes them: `summary.json`,
//! `final.vtu` + `run.pvd`, and `analysis.json` + `analysis.csv` for a scene
//! with `[analysis]`. The VTK grid is the continuous mesh (cells as
//! in [`super::vtk`]: hexahedra and prisms as planar-faced polyhedra): points
//! are the mesh nodes at their (perturbed) reference positions, with the point
//! field `displacement` (m) and the cell fields `material` and `sxx syy szz
//! syz sxz sxy` (Pa, volume averages over the Gauss points).

use std::path::Path;

use super::vtk::{grid_vtu, write_pvd};
use super::{staged, write_atomic, write_json};
use crate::drivers::AnalysisReport;
use crate::error::Error;
use crate::fem::FemSolution;
use crate::mesh::CellKind;

/// The `.vtu` text of a solution (ASCII VTK XML unstructured grid).
pub fn vtu_string(sol: &FemSolution) -> String {
    let cells: Vec<(CellKind, Vec<u32>)> =
        sol.cells.iter().map(|c| (c.kind, c.corners().iter().map(|&n| n as u32).collect())).collect();
    grid_vtu(&sol.coords, &cells, &sol.u, &sol.cell_material, Some(&sol.stress), &[], &[])
}

/// Writes `out/summary.json`, `out/final.vtu` and `out/run.pvd`, and for a
/// scene with `[analysis]` its files ([`super::analysis`]), staged (moved into
/// `out` together).
pub fn write_fem(sol: &FemSolution, analysis: Option<&AnalysisReport>, out: &Path) -> Result<(), Error> {
    staged(out, |dir| {
        write_json(&dir.join("summary.json"), &sol.summary)?;
        write_atomic(&dir.join("final.vtu"), vtu_string(sol).as_bytes())?;
        write_pvd(&dir.join("run.pvd"), &[(0.0, "final.vtu".to_string())])?;
        let mut files = vec!["summary.json".into(), "final.vtu".into(), "run.pvd".into()];
        if let Some(report) = analysis {
            files.extend(super::analysis::write_analysis(report, dir)?);
        }
        Ok(files)
    })
}
