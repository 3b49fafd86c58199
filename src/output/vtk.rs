//! VTK XML unstructured grids (`.vtu`, ASCII) and their collection (`.pvd`).
//! Points are the node copies at their reference (perturbed) positions, so a
//! joint that opens shows as a gap once warped by `displacement`.

use std::fmt::Write;
use std::path::Path;

use super::write_atomic;
use crate::error::Error;
use crate::model::Model;

/// One frame's fields.
pub struct Frame<'a> {
    pub u: &'a [f64],
    /// Element stresses (Voigt xx yy zz yz xz xy), if computed.
    pub stress: Option<&'a [[f64; 6]]>,
}

pub fn vtu_string(model: &Model, frame: &Frame) -> String {
    let el = &model.elements;
    let mut s = String::new();
    let n = model.n_nodes();
    let _ = writeln!(s, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>");
    let _ = writeln!(s, "<Piece NumberOfPoints=\"{n}\" NumberOfCells=\"{}\">", el.len());
    s.push_str("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for x in &model.x0 {
        let _ = writeln!(s, "{:e} {:e} {:e}", x[0], x[1], x[2]);
    }
    s.push_str("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for e in 0..el.len() {
        let c: Vec<String> = el.corners(e).iter().map(|v| v.to_string()).collect();
        let _ = writeln!(s, "{}", c.join(" "));
    }
    s.push_str("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for e in 0..el.len() {
        let _ = write!(s, "{} ", el.offset[e + 1]);
    }
    s.push_str("\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for k in &el.kind {
        let _ = write!(s, "{} ", k.vtk_type());
    }
    s.push_str("\n</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\">\n");
    s.push_str("<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for d in frame.u.chunks(3) {
        let _ = writeln!(s, "{:e} {:e} {:e}", d[0], d[1], d[2]);
    }
    s.push_str("</DataArray>\n</PointData>\n<CellData>\n");
    s.push_str("<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">\n");
    for m in &el.material {
        let _ = write!(s, "{m} ");
    }
    s.push_str("\n</DataArray>\n");
    if let Some(stress) = frame.stress {
        for (c, name) in ["sxx", "syy", "szz", "syz", "sxz", "sxy"].iter().enumerate() {
            let _ = writeln!(s, "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">");
            for st in stress {
                let _ = write!(s, "{:e} ", st[c]);
            }
            s.push_str("\n</DataArray>\n");
        }
    }
    s.push_str("</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    s
}

pub fn write_vtu(path: &Path, model: &Model, frame: &Frame) -> Result<(), Error> {
    write_atomic(path, vtu_string(model, frame).as_bytes())
}

/// A `.pvd` collection of `(time, file name)` frames.
pub fn write_pvd(path: &Path, frames: &[(f64, String)]) -> Result<(), Error> {
    let mut s = String::from("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n");
    for (t, f) in frames {
        let _ = writeln!(s, "<DataSet timestep=\"{t:e}\" part=\"0\" file=\"{f}\"/>");
    }
    s.push_str("</Collection>\n</VTKFile>\n");
    write_atomic(path, s.as_bytes())
}
