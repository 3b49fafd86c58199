//! Outputs of `cdem fem`, in the form `cdem run` writes them: `summary.json`
//! and `final.vtu` + `run.pvd`. The VTK grid is the continuous mesh (cells as
//! in [`super::vtk`]: hexahedra and prisms as planar-faced polyhedra): points
//! are the mesh nodes at their (perturbed) reference positions, with the point
//! field `displacement` (m) and the cell fields `material` and `sxx syy szz
//! syz sxz sxy` (Pa, volume averages over the Gauss points).

use std::fmt::Write;
use std::path::Path;

use super::vtk::{polyhedron_faces, write_pvd};
use super::{staged, write_atomic, write_json};
use crate::error::Error;
use crate::fem::FemSolution;
use crate::mesh::CellKind;

/// The `.vtu` text of a solution (ASCII VTK XML unstructured grid).
pub fn vtu_string(sol: &FemSolution) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>");
    let _ = writeln!(s, "<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">", sol.coords.len(), sol.cells.len());
    s.push_str("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for x in &sol.coords {
        let _ = writeln!(s, "{:e} {:e} {:e}", x[0], x[1], x[2]);
    }
    s.push_str("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for c in &sol.cells {
        let ids: Vec<String> = c.corners().iter().map(|v| v.to_string()).collect();
        let _ = writeln!(s, "{}", ids.join(" "));
    }
    s.push_str("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    let mut offset = 0;
    for c in &sol.cells {
        offset += c.kind.n_nodes();
        let _ = write!(s, "{offset} ");
    }
    s.push_str("\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for c in &sol.cells {
        let _ = write!(s, "{} ", if c.kind == CellKind::Tet4 { 10 } else { 42 });
    }
    s.push_str("\n</DataArray>\n");
    if sol.cells.iter().any(|c| c.kind != CellKind::Tet4) {
        let (mut faces, mut offsets, mut end) = (String::new(), String::new(), 0usize);
        for c in &sol.cells {
            let corners: Vec<u32> = c.corners().iter().map(|&n| n as u32).collect();
            let stream = polyhedron_faces(c.kind, &corners, &sol.coords);
            end += stream.len();
            let ids: Vec<String> = stream.iter().map(|v| v.to_string()).collect();
            let _ = writeln!(faces, "{}", ids.join(" "));
            let _ = write!(offsets, "{} ", if stream.is_empty() { -1 } else { end as i64 });
        }
        let _ = write!(s, "<DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">\n{faces}</DataArray>\n");
        let _ =
            write!(s, "<DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">\n{offsets}\n</DataArray>\n");
    }
    s.push_str("</Cells>\n<PointData Vectors=\"displacement\">\n");
    s.push_str("<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for d in sol.u.chunks(3) {
        let _ = writeln!(s, "{:e} {:e} {:e}", d[0], d[1], d[2]);
    }
    s.push_str(
        "</DataArray>\n</PointData>\n<CellData>\n<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">\n",
    );
    for m in &sol.cell_material {
        let _ = write!(s, "{m} ");
    }
    s.push_str("\n</DataArray>\n");
    for (c, name) in ["sxx", "syy", "szz", "syz", "sxz", "sxy"].iter().enumerate() {
        let _ = writeln!(s, "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">");
        for st in &sol.stress {
            let _ = write!(s, "{:e} ", st[c]);
        }
        s.push_str("\n</DataArray>\n");
    }
    s.push_str("</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    s
}

/// Writes `out/summary.json`, `out/final.vtu` and `out/run.pvd`, staged
/// (moved into `out` together).
pub fn write_fem(sol: &FemSolution, out: &Path) -> Result<(), Error> {
    staged(out, |dir| {
        write_json(&dir.join("summary.json"), &sol.summary)?;
        write_atomic(&dir.join("final.vtu"), vtu_string(sol).as_bytes())?;
        write_pvd(&dir.join("run.pvd"), &[(0.0, "final.vtu".to_string())])?;
        Ok(vec!["summary.json".into(), "final.vtu".into(), "run.pvd".into()])
    })
}
