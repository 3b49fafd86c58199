//! Face adjacency of volume cells: which faces two cells share (the element
//! interfaces that get springs) and which lie on the boundary.

use std::collections::HashMap;

use super::Mesh;
use crate::error::MeshError;

/// Sorted node set of a face, padded with `usize::MAX` (a hash key).
pub type FaceKey = [usize; 4];

pub fn face_key(nodes: &[usize]) -> FaceKey {
    let mut k = [usize::MAX; 4];
    k[..nodes.len()].copy_from_slice(nodes);
    k.sort_unstable();
    k
}

/// A face shared by two cells: `(cell, local face)` on each side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SharedFace {
    pub cells: [usize; 2],
    pub faces: [u8; 2],
}

#[derive(Debug, Clone, Default)]
pub struct FaceAdjacency {
    /// Interior faces, in order of first appearance (deterministic).
    pub shared: Vec<SharedFace>,
    /// Boundary faces as `(cell, local face)`.
    pub exterior: Vec<(usize, u8)>,
}

/// The global node indices of face `f` of cell `c`, outward ordered.
pub fn face_nodes(mesh: &Mesh, c: usize, f: u8) -> Vec<usize> {
    let cell = &mesh.cells[c];
    cell.kind.faces()[f as usize].iter().map(|&k| cell.nodes[k]).collect()
}

impl FaceAdjacency {
    pub fn build(mesh: &Mesh) -> Result<Self, MeshError> {
        let mut first: HashMap<FaceKey, (usize, u8, usize)> = HashMap::new();
        let mut slots: Vec<Option<SharedFace>> = Vec::new();
        let mut open: Vec<(usize, u8)> = Vec::new();
        for (c, cell) in mesh.cells.iter().enumerate() {
            for (f, face) in cell.kind.faces().iter().enumerate() {
                let nodes: Vec<usize> = face.iter().map(|&k| cell.nodes[k]).collect();
                let key = face_key(&nodes);
                match first.get_mut(&key) {
                    None => {
                        first.insert(key, (c, f as u8, open.len()));
                        open.push((c, f as u8));
                        slots.push(None);
                    }
                    Some(&mut (c0, f0, slot)) => {
                        if slots[slot].is_some() {
                            let s = slots[slot].unwrap();
                            return Err(MeshError::NonManifold {
                                elements: vec![mesh.cells[s.cells[0]].tag, mesh.cells[s.cells[1]].tag, cell.tag],
                            });
                        }
                        slots[slot] = Some(SharedFace { cells: [c0, c], faces: [f0, f as u8] });
                    }
                }
            }
        }
        let mut shared = Vec::new();
        let mut exterior = Vec::new();
        for (slot, s) in slots.into_iter().enumerate() {
            match s {
                Some(s) => shared.push(s),
                None => exterior.push(open[slot]),
            }
        }
        Ok(Self { shared, exterior })
    }
}

/// Unit normal (Newell's method) and area of a possibly non-planar polygon.
pub fn polygon_normal_area(p: &[[f64; 3]]) -> ([f64; 3], f64) {
    let mut n = [0.0; 3];
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    let len = super::shape::norm(n);
    if len > 0.0 {
        ([n[0] / len, n[1] / len, n[2] / len], 0.5 * len)
    } else {
        ([0.0; 3], 0.0)
    }
}

/// Each corner's share of a face: `(corner, area, unit normal)`, the normal
/// along the face's node order (outward for the cell it was taken from).
pub fn corner_shares(p: &[[f64; 3]]) -> Vec<(usize, f64, [f64; 3])> {
    let m = p.len() as f64;
    let f = [0, 1, 2].map(|d| p.iter().map(|x| x[d]).sum::<f64>() / m);
    (0..p.len())
        .filter_map(|k| {
            let (prev, a, next) = (p[(k + p.len() - 1) % p.len()], p[k], p[(k + 1) % p.len()]);
            let t1 = super::shape::cross(super::shape::sub(next, a), super::shape::sub(f, a));
            let t2 = super::shape::cross(super::shape::sub(a, prev), super::shape::sub(f, prev));
            let nsum = [t1[0] + t2[0], t1[1] + t2[1], t1[2] + t2[2]];
            let nlen = super::shape::norm(nsum);
            (nlen > 0.0).then(|| (k, 0.25 * (super::shape::norm(t1) + super::shape::norm(t2)), nsum.map(|v| v / nlen)))
        })
        .collect()
}
