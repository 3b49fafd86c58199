//! VTK XML unstructured grids (`.vtu`, ASCII) and their collection (`.pvd`).
//! Points are the node copies at their reference (perturbed) positions, so a
//! joint that opens shows as a gap once warped by `displacement`.
//!
//! A perturbed hexahedron or prism has non-planar quadrilateral faces, which
//! VTK's own cell checks reject for VTK_HEXAHEDRON and VTK_WEDGE. They are
//! written as what they are: VTK_POLYHEDRON (42) cells whose faces are
//! planar: a planar quadrilateral stays whole, a non-planar one is split into
//! two triangles along the diagonal that folds outward (the convex split).
//! Tetrahedra stay VTK_TETRA. `scripts/check_vtk.py` checks a file with
//! VTK's cell validator.

use std::fmt::Write;
use std::path::Path;

use super::write_atomic;
use crate::error::Error;
use crate::mesh::shape::{cross, dot, sub, CellKind};
use crate::model::Model;

/// One frame's fields.
pub struct Frame<'a> {
    pub u: &'a [f64],
    /// Element stresses (Voigt xx yy zz yz xz xy), if computed.
    pub stress: Option<&'a [[f64; 6]]>,
    /// Further cell fields, one value per element (e.g. the plastic blocks'
    /// [`plastic_fields`]).
    pub cells: &'a [(&'static str, Vec<f64>)],
}

/// The cell fields of plastic blocks: `plastic_shear` (the volume-averaged
/// plastic shear strain, FLAC's shear-strain measure), `yielding` and
/// `yielded` (the volume fraction of each element's tetrahedra yielding now
/// and ever, in shear or tension), `yielding_tension` and `yielded_tension`
/// (the fraction of those in tension: `yielding - yielding_tension` yields in
/// shear alone).
pub fn plastic_fields(cells: &[crate::physics::plastic::CellPlastic]) -> Vec<(&'static str, Vec<f64>)> {
    vec![
        ("plastic_shear", cells.iter().map(|c| c.plastic_shear).collect()),
        ("yielding", cells.iter().map(|c| c.yielding).collect()),
        ("yielded", cells.iter().map(|c| c.yielded).collect()),
        ("yielding_tension", cells.iter().map(|c| c.yielding_tension).collect()),
        ("yielded_tension", cells.iter().map(|c| c.yielded_tension).collect()),
    ]
}

/// The `.vtu` text of a model's frame: points the node copies, cells the elements.
pub fn vtu_string(model: &Model, frame: &Frame) -> String {
    let el = &model.elements;
    let cells: Vec<(CellKind, &[u32])> = (0..el.len()).map(|e| (el.kind[e], el.corners(e))).collect();
    let pore: Vec<(&'static str, &[f64])> =
        model.water.iter().map(|w| ("pore_pressure", w.node_pressure.as_slice())).collect();
    grid_vtu(&model.x0, &cells, frame.u, &el.material, frame.stress, frame.cells, &pore)
}

/// The `.vtu` text (ASCII VTK XML unstructured grid) of `points`, `cells`
/// (kind and point ids, written as in the module doc) and the fields: the
/// point field `displacement` (m, 3 per point), the scalar `point_fields`
/// (`pore_pressure` (Pa) with water), and the cell fields `material`
/// and, if given, `sxx syy szz syz sxz sxy` (Pa) and `fields`. `cdem run`
/// and `cdem fem` both write through it.
pub fn grid_vtu<C: AsRef<[u32]>>(
    points: &[[f64; 3]],
    cells: &[(CellKind, C)],
    u: &[f64],
    material: &[u16],
    stress: Option<&[[f64; 6]]>,
    fields: &[(&'static str, Vec<f64>)],
    point_fields: &[(&'static str, &[f64])],
) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>");
    let _ = writeln!(s, "<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">", points.len(), cells.len());
    s.push_str("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for x in points {
        let _ = writeln!(s, "{:e} {:e} {:e}", x[0], x[1], x[2]);
    }
    s.push_str("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for (_, c) in cells {
        let ids: Vec<String> = c.as_ref().iter().map(|v| v.to_string()).collect();
        let _ = writeln!(s, "{}", ids.join(" "));
    }
    s.push_str("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    let mut offset = 0;
    for (_, c) in cells {
        offset += c.as_ref().len();
        let _ = write!(s, "{offset} ");
    }
    s.push_str("\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (k, _) in cells {
        let _ = write!(s, "{} ", if *k == CellKind::Tet4 { VTK_TETRA } else { VTK_POLYHEDRON });
    }
    s.push_str("\n</DataArray>\n");
    if cells.iter().any(|(k, _)| *k != CellKind::Tet4) {
        // Per cell: the face stream (number of faces, then per face its point
        // count and ids; empty for a tetrahedron) and its end offset.
        let (mut faces, mut offsets, mut end) = (String::new(), String::new(), 0usize);
        for (k, c) in cells {
            let stream = polyhedron_faces(*k, c.as_ref(), points);
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
    for d in u.chunks(3) {
        let _ = writeln!(s, "{:e} {:e} {:e}", d[0], d[1], d[2]);
    }
    s.push_str("</DataArray>\n");
    for (name, values) in point_fields {
        let _ = writeln!(s, "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">");
        for v in values.iter() {
            let _ = writeln!(s, "{v:e}");
        }
        s.push_str("</DataArray>\n");
    }
    s.push_str("</PointData>\n<CellData>\n");
    s.push_str("<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">\n");
    for m in material {
        let _ = write!(s, "{m} ");
    }
    s.push_str("\n</DataArray>\n");
    if let Some(stress) = stress {
        for (c, name) in ["sxx", "syy", "szz", "syz", "sxz", "sxy"].iter().enumerate() {
            let _ = writeln!(s, "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">");
            for st in stress {
                let _ = write!(s, "{:e} ", st[c]);
            }
            s.push_str("\n</DataArray>\n");
        }
    }
    for (name, values) in fields {
        let _ = writeln!(s, "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">");
        for v in values {
            let _ = write!(s, "{v:e} ");
        }
        s.push_str("\n</DataArray>\n");
    }
    s.push_str("</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    s
}

pub fn write_vtu(path: &Path, model: &Model, frame: &Frame) -> Result<(), Error> {
    write_atomic(path, vtu_string(model, frame).as_bytes())
}

/// A quadrilateral whose fourth corner lies within this fraction of its size
/// from the plane of the other three is written as one planar face.
const PLANAR: f64 = 1e-12;

/// VTK's cell types: a tetrahedron, and a polyhedron given by its faces.
const VTK_TETRA: u8 = 10;
const VTK_POLYHEDRON: u8 = 42;

/// The VTK face stream of a cell (empty for a tetrahedron): the number of
/// faces, then each face as its point count and point ids, outward. A planar
/// quadrilateral stays one face; a non-planar `a b c d` becomes two
/// triangles split along `a c` when `d` lies on the inner side of the plane
/// `a b c` (the fold is convex), along `b d` otherwise.
pub fn polyhedron_faces(kind: CellKind, corners: &[u32], x: &[[f64; 3]]) -> Vec<u32> {
    if kind == CellKind::Tet4 {
        return Vec::new();
    }
    let mut polys: Vec<Vec<u32>> = Vec::new();
    for face in kind.faces() {
        let ids: Vec<u32> = face.iter().map(|&k| corners[k]).collect();
        match ids[..] {
            [a, b, c, d] => {
                let p = |i: u32| x[i as usize];
                let n = cross(sub(p(b), p(a)), sub(p(c), p(a)));
                let size = [sub(p(c), p(a)), sub(p(d), p(b))].iter().map(|v| dot(*v, *v)).fold(0.0, f64::max);
                // Signed volume of the fold: d's height over the plane a b c, times |n|.
                let fold = dot(n, sub(p(d), p(a)));
                if fold.abs() <= PLANAR * size * size.sqrt() {
                    polys.push(ids); // planar: one face (a flat fold would read as non-convex)
                } else if fold < 0.0 {
                    polys.extend([vec![a, b, c], vec![a, c, d]]);
                } else {
                    polys.extend([vec![a, b, d], vec![b, c, d]]);
                }
            }
            _ => polys.push(ids),
        }
    }
    let mut stream = vec![polys.len() as u32];
    for f in polys {
        stream.push(f.len() as u32);
        stream.extend(f);
    }
    stream
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
