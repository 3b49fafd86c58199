//! Stochastic structural planes: seeded random perturbation of the nodes of
//! the continuous mesh (docs/method.md section 2).
//!
//! Each node moves by an independent uniform offset in `[-r h, r h]` per axis,
//! `h` the length of its shortest incident edge and `r` the ratio. A node on
//! the boundary moves only within the boundary planes it lies on (on an edge
//! of the box, along the edge; at a corner, not at all); the same holds for
//! nodes of `keep_flat` surface groups. The random stream is SplitMix64 with
//! three draws per node in node order, so a seed gives the same mesh bit for
//! bit on every machine and thread count.

use super::adjacency::{face_nodes, polygon_normal_area, FaceAdjacency};
use super::shape::{check_cell, dot, norm, sub, CellDefect};
use super::{Mesh, PhysicalGroup};

/// A small, portable, seeded generator (SplitMix64, Steele et al. 2014).
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1) with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// Shortest incident edge length of every node.
pub fn local_edge_length(mesh: &Mesh) -> Vec<f64> {
    let mut h = vec![f64::INFINITY; mesh.nodes.len()];
    for cell in &mesh.cells {
        for face in cell.kind.faces() {
            for k in 0..face.len() {
                let (a, b) = (cell.nodes[face[k]], cell.nodes[face[(k + 1) % face.len()]]);
                let l = norm(sub(mesh.nodes[a], mesh.nodes[b]));
                h[a] = h[a].min(l);
                h[b] = h[b].min(l);
            }
        }
    }
    h
}

/// An orthonormal set of plane normals each node must not move along.
fn constraint_normals(mesh: &Mesh, adj: &FaceAdjacency, flat: &[&PhysicalGroup]) -> Vec<Vec<[f64; 3]>> {
    let mut normals: Vec<Vec<[f64; 3]>> = vec![Vec::new(); mesh.nodes.len()];
    let mut add = |nodes: &[usize]| {
        let p: Vec<[f64; 3]> = nodes.iter().map(|&i| mesh.nodes[i]).collect();
        let (n, area) = polygon_normal_area(&p);
        if area <= 0.0 {
            return;
        }
        for &i in nodes {
            // Gram-Schmidt against the normals the node already has.
            let mut r = n;
            for q in &normals[i] {
                let c = dot(r, *q);
                r = [r[0] - c * q[0], r[1] - c * q[1], r[2] - c * q[2]];
            }
            let len = norm(r);
            if len > 1e-3 && normals[i].len() < 3 {
                normals[i].push([r[0] / len, r[1] / len, r[2] / len]);
            }
        }
    };
    for &(c, f) in &adj.exterior {
        add(&face_nodes(mesh, c, f));
    }
    for g in flat {
        for f in &g.facets {
            if f.n >= 3 {
                add(f.nodes());
            }
        }
    }
    normals
}

/// Returns the perturbed node coordinates, or the first cell the perturbation
/// inverts (index into `mesh.cells`) with its defect.
pub fn perturb_nodes(
    mesh: &Mesh,
    adj: &FaceAdjacency,
    ratio: f64,
    seed: u64,
    flat: &[&PhysicalGroup],
) -> Result<Vec<[f64; 3]>, (usize, CellDefect)> {
    if ratio == 0.0 {
        return Ok(mesh.nodes.clone());
    }
    let h = local_edge_length(mesh);
    let normals = constraint_normals(mesh, adj, flat);
    let mut rng = SplitMix64::new(seed);
    let mut out = mesh.nodes.clone();
    for (i, x) in out.iter_mut().enumerate() {
        let amp = ratio * if h[i].is_finite() { h[i] } else { 0.0 };
        let mut d = [0.0; 3].map(|_: f64| (2.0 * rng.next_f64() - 1.0) * amp);
        for q in &normals[i] {
            let c = dot(d, *q);
            d = [d[0] - c * q[0], d[1] - c * q[1], d[2] - c * q[2]];
        }
        for k in 0..3 {
            x[k] += d[k];
        }
    }
    for (c, cell) in mesh.cells.iter().enumerate() {
        let corners: Vec<[f64; 3]> = cell.corners().iter().map(|&i| out[i]).collect();
        check_cell(cell.kind, &corners).map_err(|e| (c, e))?;
    }
    Ok(out)
}
