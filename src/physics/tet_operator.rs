//! The element force of eq. 12 in per-tetrahedron operator form: the same
//! `f_e = K_e u_e` as [`element::element_force`](crate::physics::element::element_force),
//! computed from each sub-tetrahedron's shape-function gradients instead of
//! the condensed `3n x 3n` matrix. Kept for the layout comparison of
//! `references/layout.md` (benches/layout.rs); the solver uses the condensed
//! form, which measured faster.
//!
//! # What is computed
//!
//! The decomposition points of a cell ([`Decomposition`]) are its `n` corners,
//! one centroid per face and the body centroid (a tetrahedron has only its
//! corners). The face and body centroids are *not* independent nodes that a
//! static condensation eliminates: they are fixed averages of the corners,
//! `x_p = sum_c T_pc x_c`, and so are their displacements, `u_p = T u_c`. The
//! condensed matrix is `K_e = T^T (sum_t K_t) T` with `K_t` the stiffness of
//! the constant-strain tetrahedron `t` over its 4 points. This module applies
//! the same three factors one after the other:
//!
//! 1. `u_p = T u_c`: point displacements (face centroid = mean of its corners,
//!    body centroid = mean of all corners), kept relative to the body centroid
//!    `u_r` (for a tetrahedron: relative to corner 3), `d_p = u_p - u_r`;
//! 2. per tetrahedron `t` with points `(p_0, p_1, p_2, r)` (every
//!    sub-tetrahedron of a hexahedron or prism has the body centroid as its 4th
//!    point): `H = sum_{k<3} d_(p_k) (x) b_k`, `sigma = lambda tr(H) I +
//!    mu (H + H^T)`, `f_(p_k) += sigma b_k`, where `b_k = sqrt(V_t) grad N_k`
//!    (so `sigma(H) b_k = V_t sigma(grad u) grad N_k`, the tetrahedron's nodal
//!    force), and the 4th vertex's gradient `-(b_0 + b_1 + b_2)` is never
//!    stored: the force on `r` is minus the sum of all the others (every
//!    tetrahedron's forces sum to zero);
//! 3. `f_c = T^T f_p`: each corner keeps its own point force plus a quarter
//!    (a third on a triangle) of each of its faces' centroid forces plus `1/n`
//!    of the body centroid's.
//!
//! Per tetrahedron only the 9 values `b_0, b_1, b_2` are stored; the point
//! indices are the same for every cell of a kind ([`TetTopology`]). The result
//! equals `K_e u_e` up to round-off (tests/tet_operator.rs, 1e-12 relative).

use crate::mesh::shape::{check_cell, CellDefect, CellKind, Decomposition, MAX_POINTS};
use crate::physics::element::tet_gradients;
use crate::physics::material::Lame;

/// The point indices of the sub-tetrahedra of one cell kind, shared by all its
/// cells. Points are numbered as in [`Decomposition`]: corners, face
/// centroids, body centroid.
#[derive(Debug, Clone)]
pub struct TetTopology {
    pub kind: CellKind,
    pub n_corners: usize,
    /// Faces whose centroids are points `n_corners + f` (none for a tetrahedron).
    pub faces: &'static [&'static [usize]],
    /// The point every sub-tetrahedron has as its 4th vertex: the body
    /// centroid (last point), or corner 3 of a tetrahedron.
    pub base: usize,
    /// Vertices 0, 1, 2 of each sub-tetrahedron (point indices).
    pub tets: Vec<[u8; 3]>,
}

impl TetTopology {
    pub fn of(kind: CellKind) -> Self {
        let dec = Decomposition::of(kind);
        let faces = if kind == CellKind::Tet4 { &[][..] } else { kind.faces() };
        let base = dec.tets[0][3];
        debug_assert!(dec.tets.iter().all(|t| t[3] == base), "every sub-tetrahedron shares its 4th point");
        let tets = dec.tets.iter().map(|t| [t[0] as u8, t[1] as u8, t[2] as u8]).collect();
        Self { kind, n_corners: dec.n_corners, faces, base, tets }
    }

    pub fn has_body_point(&self) -> bool {
        self.base >= self.n_corners
    }
}

/// Per-tetrahedron data of one cell: `b_k = sqrt(V_t) grad N_k` of vertices
/// 0, 1, 2, row-major `[b_0x, b_0y, b_0z, b_1x, ..]` (m^(1/2)), one entry per
/// sub-tetrahedron in [`TetTopology::tets`] order.
pub fn tet_operator(kind: CellKind, corners: &[[f64; 3]]) -> Result<Vec<[f64; 9]>, CellDefect> {
    check_cell(kind, corners)?;
    Ok(scaled_gradients(kind, corners).map(|(b, _)| b).collect())
}

/// Per sub-tetrahedron, in [`TetTopology::tets`] order: `b_k = sqrt(V_t)
/// grad N_k` of vertices 0, 1, 2 (as [`tet_operator`], the cell unchecked)
/// and `sqrt(V_t)`.
pub fn scaled_gradients(kind: CellKind, corners: &[[f64; 3]]) -> impl Iterator<Item = ([f64; 9], f64)> {
    let dec = Decomposition::of(kind);
    let points = dec.points(corners);
    dec.tets.into_iter().map(move |t| {
        let (g, v) = tet_gradients([points[t[0]], points[t[1]], points[t[2]], points[t[3]]]);
        let s = v.sqrt();
        let mut b = [0.0; 9];
        for k in 0..3 {
            for i in 0..3 {
                b[3 * k + i] = s * g[k][i];
            }
        }
        (b, s)
    })
}

/// Eq. 12 in per-tetrahedron form: writes `f_e = K_e u_e` (`3n` values,
/// corner-major) of one cell from its tetrahedra `b` ([`tet_operator`]), its
/// Lamé parameters, its corners `nodes` (model node indices) and the global
/// displacement `u` (3 per node). Steps 1-3 of the module documentation.
#[inline]
pub fn tet_element_force(topo: &TetTopology, b: &[[f64; 9]], lame: Lame, nodes: &[u32], u: &[f64], f_e: &mut [f64]) {
    let Lame { lambda, mu } = lame;
    let d = point_displacements(topo, nodes, u);
    // d[base] is zero: the base point is the reference.

    // 2. Per tetrahedron: gradient, stress, nodal forces on vertices 0-2.
    let mut f = [[0.0; 3]; MAX_POINTS];
    for (t, b) in topo.tets.iter().zip(b) {
        let mut h = [[0.0; 3]; 3]; // sqrt(V_t) du_i/dx_j
        for (k, &p) in t.iter().enumerate() {
            let dp = d[p as usize];
            for i in 0..3 {
                for j in 0..3 {
                    h[i][j] += dp[i] * b[3 * k + j];
                }
            }
        }
        let tr = h[0][0] + h[1][1] + h[2][2];
        let (sxx, syy, szz) =
            (lambda * tr + 2.0 * mu * h[0][0], lambda * tr + 2.0 * mu * h[1][1], lambda * tr + 2.0 * mu * h[2][2]);
        let (syz, sxz, sxy) = (mu * (h[1][2] + h[2][1]), mu * (h[0][2] + h[2][0]), mu * (h[0][1] + h[1][0]));
        for (k, &p) in t.iter().enumerate() {
            let (bx, by, bz) = (b[3 * k], b[3 * k + 1], b[3 * k + 2]);
            let fp = &mut f[p as usize];
            fp[0] += sxx * bx + sxy * by + sxz * bz;
            fp[1] += sxy * bx + syy * by + syz * bz;
            fp[2] += sxz * bx + syz * by + szz * bz;
        }
    }
    corner_forces(topo, &mut f, f_e);
}

/// Step 1: the displacements of a cell's decomposition points relative to
/// its base point, `d_p = (T u)_p - u_r` (so `d[base]` is zero).
#[inline(always)]
pub fn point_displacements(topo: &TetTopology, nodes: &[u32], u: &[f64]) -> [[f64; 3]; MAX_POINTS] {
    let n = topo.n_corners;
    let mut d = [[0.0; 3]; MAX_POINTS];
    for (dc, &node) in d.iter_mut().zip(nodes) {
        let k = 3 * node as usize;
        dc.copy_from_slice(&u[k..k + 3]);
    }
    let u_r = if topo.has_body_point() { mean(&d[..n]) } else { d[topo.base] };
    for dc in &mut d[..n] {
        for i in 0..3 {
            dc[i] -= u_r[i];
        }
    }
    for (fi, face) in topo.faces.iter().enumerate() {
        let mut s = [0.0; 3];
        for &c in *face {
            for i in 0..3 {
                s[i] += d[c][i];
            }
        }
        let w = 1.0 / face.len() as f64;
        d[n + fi] = s.map(|v| w * v);
    }
    d
}

/// Step 3: the point forces `f` (vertices 0-2 of every tetrahedron summed;
/// the base point's entry is overwritten) to the corners, `f_c = (T^T f)_c`,
/// written to `f_e` (`3n` values, corner-major). The base point takes minus
/// the sum of the others: each tetrahedron's forces sum to zero and its own
/// gradient was never stored.
#[inline(always)]
pub fn corner_forces(topo: &TetTopology, f: &mut [[f64; 3]; MAX_POINTS], f_e: &mut [f64]) {
    let n = topo.n_corners;
    let n_points = if topo.has_body_point() { topo.base + 1 } else { n };
    let mut f_r = [0.0; 3];
    for (p, fp) in f[..n_points].iter().enumerate() {
        if p != topo.base {
            for i in 0..3 {
                f_r[i] -= fp[i];
            }
        }
    }
    f[topo.base] = f_r;
    let mut out = [[0.0; 3]; 8];
    out[..n].copy_from_slice(&f[..n]);
    for (fi, face) in topo.faces.iter().enumerate() {
        let w = 1.0 / face.len() as f64;
        let share = f[n + fi].map(|v| w * v);
        for &c in *face {
            for i in 0..3 {
                out[c][i] += share[i];
            }
        }
    }
    if topo.has_body_point() {
        let w = 1.0 / n as f64;
        let share = f[topo.base].map(|v| w * v);
        for oc in &mut out[..n] {
            for i in 0..3 {
                oc[i] += share[i];
            }
        }
    }
    for (fc, oc) in f_e.chunks_exact_mut(3).zip(&out[..n]) {
        fc.copy_from_slice(oc);
    }
}

fn mean(x: &[[f64; 3]]) -> [f64; 3] {
    let mut s = [0.0; 3];
    for p in x {
        for i in 0..3 {
            s[i] += p[i];
        }
    }
    let w = 1.0 / x.len() as f64;
    s.map(|v| w * v)
}

/// Per-tetrahedron operators of a whole model, struct of arrays: element `e`
/// has tetrahedra `b[offset[e]..offset[e + 1]]`, Lamé parameters `lame[e]`
/// and the topology of its kind.
#[derive(Debug, Clone)]
pub struct TetOperators {
    pub offset: Vec<usize>,
    pub b: Vec<[f64; 9]>,
    pub lame: Vec<Lame>,
    topo: [TetTopology; 3],
}

impl Default for TetOperators {
    fn default() -> Self {
        Self::new()
    }
}

impl TetOperators {
    pub fn new() -> Self {
        Self {
            offset: vec![0],
            b: Vec::new(),
            lame: Vec::new(),
            topo: [TetTopology::of(CellKind::Tet4), TetTopology::of(CellKind::Prism6), TetTopology::of(CellKind::Hex8)],
        }
    }

    /// Appends one cell.
    pub fn push(&mut self, kind: CellKind, corners: &[[f64; 3]], lame: Lame) -> Result<(), CellDefect> {
        self.b.extend(tet_operator(kind, corners)?);
        self.offset.push(self.b.len());
        self.lame.push(lame);
        Ok(())
    }

    pub fn len(&self) -> usize {
        self.lame.len()
    }
    pub fn is_empty(&self) -> bool {
        self.lame.is_empty()
    }

    pub fn topology(&self, kind: CellKind) -> &TetTopology {
        match kind {
            CellKind::Tet4 => &self.topo[0],
            CellKind::Prism6 => &self.topo[1],
            CellKind::Hex8 => &self.topo[2],
        }
    }

    /// The tetrahedra of element `e`.
    pub fn tets(&self, e: usize) -> &[[f64; 9]] {
        &self.b[self.offset[e]..self.offset[e + 1]]
    }

    /// Bytes of the per-tetrahedron data (`b`, offsets, Lamé parameters).
    pub fn bytes(&self) -> usize {
        std::mem::size_of_val(&self.b[..])
            + std::mem::size_of_val(&self.offset[..])
            + std::mem::size_of_val(&self.lame[..])
    }
}
