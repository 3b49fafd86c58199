//! The VTK cells `cdem run` writes pass VTK's own cell checks
//! (`scripts/check_vtk.py`, vtkCellValidator; record in references/vtk.md).
//! Here, without Python, the same properties on the paper slope's perturbed
//! mesh and the slip slope's: every polyhedron face is planar, the surface
//! is closed (each edge in two faces, once each way), and the cell is convex
//! (every corner on the inner side of every face plane).

use std::collections::HashMap;

use cdem::drivers::build_model;
use cdem::harness::registry;
use cdem::mesh::shape::{cross, dot, sub};
use cdem::output::vtk::polyhedron_faces;

fn faces_of(stream: &[u32]) -> Vec<Vec<u32>> {
    let mut faces = Vec::new();
    let mut k = 1;
    while k < stream.len() {
        let n = stream[k] as usize;
        faces.push(stream[k + 1..k + 1 + n].to_vec());
        k += 1 + n;
    }
    assert_eq!(faces.len(), stream[0] as usize);
    faces
}

#[test]
fn polyhedra_are_planar_faced_closed_and_convex() {
    for case in [registry::SLOPE, registry::SLOPE_SLIP] {
        let model = build_model(&case.elastic_scene().unwrap()).unwrap();
        let x = &model.x0;
        let (mut polyhedra, mut split) = (0, 0);
        for e in 0..model.elements.len() {
            let corners = model.elements.corners(e);
            let stream = polyhedron_faces(model.elements.kind[e], corners, x);
            if stream.is_empty() {
                continue;
            }
            polyhedra += 1;
            let faces = faces_of(&stream);
            split += faces.len() - model.elements.kind[e].faces().len();
            let size = corners
                .iter()
                .map(|&a| {
                    let d = sub(x[a as usize], x[corners[0] as usize]);
                    dot(d, d).sqrt()
                })
                .fold(0.0, f64::max);
            let mut edges: HashMap<(u32, u32), i32> = HashMap::new();
            for f in &faces {
                let p = |i: u32| x[i as usize];
                let n = cross(sub(p(f[1]), p(f[0])), sub(p(f[2]), p(f[0])));
                let len = dot(n, n).sqrt();
                for &v in f {
                    let h = dot(n, sub(p(v), p(f[0]))) / len;
                    assert!(h.abs() < 1e-9 * size, "element {e}: face {f:?} not planar ({h:e} m)");
                }
                for &c in corners {
                    let h = dot(n, sub(p(c), p(f[0]))) / len;
                    assert!(h < 1e-9 * size, "element {e}: corner {c} outside face {f:?} by {h:e} m");
                }
                for k in 0..f.len() {
                    let (a, b) = (f[k], f[(k + 1) % f.len()]);
                    *edges.entry((a.min(b), a.max(b))).or_default() += if a < b { 1 } else { -1 };
                }
            }
            assert!(edges.values().all(|&s| s == 0), "element {e}: surface not closed or misoriented");
        }
        println!("{}: {polyhedra} polyhedra, {split} non-planar quadrilaterals split", case.name);
        assert_eq!(polyhedra, model.elements.len());
        assert!(split > 0, "the perturbation makes some faces non-planar");
    }
}
