//! Supports against rigid motion: a body whose fixed components leave one of
//! its six rigid motions free has no static equilibrium (dynamic relaxation
//! drifts without end, the FEM stiffness is singular). Checked before the
//! first step, per connected part.
//!
//! The six motions of a part (translations `e_k`, rotations `e_k x r` about
//! the part's centroid with `r` scaled by the part's size) evaluated at its
//! fixed components form the rows of `R`; a null vector of the Gram matrix
//! `R^T R` (eigenvalue below `1e-12` of the largest) is a motion no fixity
//! resists.

use nalgebra::{Matrix6, SymmetricEigen};

use super::union_find::UnionFind;
use super::Model;

/// A rigid motion that the fixities of a part leave free, described for a
/// message: `translation (tx, ty, tz) + rotation (rx, ry, rz) about (x, y, z) m`.
pub fn free_rigid_motion(coords: &[[f64; 3]], fixed: &[bool], nodes: &[usize]) -> Option<String> {
    let mut c = [0.0; 3];
    for &n in nodes {
        for d in 0..3 {
            c[d] += coords[n][d] / nodes.len() as f64;
        }
    }
    let l = nodes
        .iter()
        .map(|&n| (0..3).map(|d| (coords[n][d] - c[d]).abs()).fold(0.0, f64::max))
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut gram = Matrix6::<f64>::zeros();
    for &n in nodes {
        let r = [0, 1, 2].map(|d| (coords[n][d] - c[d]) / l);
        for i in 0..3 {
            if !fixed[3 * n + i] {
                continue;
            }
            // Component i of the six motions at node n: e_k (translations), e_k x r (rotations).
            let mut v = [0.0; 6];
            v[i] = 1.0;
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            v[3 + j] = r[k]; // (e_j x r)_i = r_k for cyclic (i, j, k)
            v[3 + k] = -r[j];
            for a in 0..6 {
                for b in 0..6 {
                    gram[(a, b)] += v[a] * v[b];
                }
            }
        }
    }
    let eig = SymmetricEigen::new(gram);
    let (imin, lmin) =
        eig.eigenvalues
            .iter()
            .enumerate()
            .fold((0, f64::INFINITY), |acc, (i, &v)| if v < acc.1 { (i, v) } else { acc });
    let lmax = eig.eigenvalues.iter().fold(0.0f64, |a, &v| a.max(v));
    if lmax > 0.0 && lmin > 1e-12 * lmax {
        return None;
    }
    let v = eig.eigenvectors.column(imin);
    let s = v.iter().map(|x| x.abs()).fold(0.0, f64::max);
    let w: Vec<f64> = v.iter().map(|x| if x.abs() < 1e-9 * s { 0.0 } else { x / s }).collect();
    Some(format!(
        "translation ({:.2}, {:.2}, {:.2}) + rotation ({:.2}, {:.2}, {:.2}) about ({:.3}, {:.3}, {:.3}) m",
        w[0], w[1], w[2], w[3], w[4], w[5], c[0], c[1], c[2]
    ))
}

/// A connected part of a model that its supports leave free to move.
#[derive(Debug, Clone, PartialEq)]
pub struct FreePart {
    /// Part index, in the order of the parts' first elements.
    pub part: usize,
    /// Elements in the part, and the gmsh tag of its first one.
    pub elements: usize,
    pub first_element: u64,
    pub motion: String,
}

/// The first connected part of the model (elements joined by shared node
/// copies or by springs) whose fixities leave a rigid motion free.
pub fn unsupported_part(model: &Model) -> Option<FreePart> {
    let n = model.n_nodes();
    let mut uf = UnionFind::new(n);
    let el = &model.elements;
    for e in 0..el.len() {
        let c = el.corners(e);
        for w in c.windows(2) {
            uf.union(w[0] as usize, w[1] as usize);
        }
    }
    for s in 0..model.springs.len() {
        uf.union(model.springs.a[s] as usize, model.springs.b[s] as usize);
    }
    // Parts in the order of their first element.
    let mut part_of_root = std::collections::HashMap::new();
    let mut parts: Vec<(Vec<usize>, usize, u64)> = Vec::new();
    for e in 0..el.len() {
        let root = uf.find(el.corners(e)[0] as usize);
        let k = *part_of_root.entry(root).or_insert_with(|| {
            parts.push((Vec::new(), 0, el.tag[e]));
            parts.len() - 1
        });
        parts[k].1 += 1;
    }
    for i in 0..n {
        if let Some(&k) = part_of_root.get(&uf.find(i)) {
            parts[k].0.push(i);
        }
    }
    parts.into_iter().enumerate().find_map(|(part, (nodes, elements, first_element))| {
        free_rigid_motion(&model.x0, &model.fixed, &nodes).map(|motion| FreePart {
            part,
            elements,
            first_element,
            motion,
        })
    })
}
