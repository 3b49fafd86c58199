//! The deformable element (paper section 3.3 (1), eq. 12).
//!
//! A cell is a polyhedron of constant-strain tetrahedra (see
//! [`crate::mesh::shape`]). Its decomposition points (face and body centroids)
//! are fixed averages of the corners, `x_p = sum_c T_pc x_c`, so each tetrahedron
//! `t` contributes, for every corner `c`, the gradient
//! `g_tc = sum_k T_(p_k) c grad N_k` of its linear shape functions. With
//! `grad u = sum_c u_c (x) g_c` the condensed stiffness block of corners `c, d` is
//!
//! `K_cd = sum_t V_t (lambda g_c g_d^T + mu (g_c . g_d) I + mu g_d g_c^T)`,
//!
//! i.e. `K_e = T^T (sum_t K_t) T`. The lumped mass puts `rho V_t / 4` on each
//! tetrahedron point and maps it to the corners through `T^T`. The element
//! stress (volume average over its tetrahedra) is linear in the gradients, so
//! it is the stress of the volume-averaged gradients `g_c = sum_t V_t g_tc / V`.

use crate::mesh::shape::{check_cell, sub, CellDefect, CellKind, Decomposition};
use crate::physics::material::{Lame, Material};

/// What the solver needs of one element, built once.
#[derive(Debug, Clone)]
pub struct ElementOperators {
    /// Condensed stiffness, `3n x 3n` row-major, dof `3c + i` (N/m).
    pub k: Vec<f64>,
    /// Volume-averaged corner gradients (1/m), for the element stress.
    pub grad: Vec<[f64; 3]>,
    /// Lumped mass of each corner (kg).
    pub mass: Vec<f64>,
    /// Element volume (m^3).
    pub volume: f64,
}

/// Gradients of the four linear shape functions of a tetrahedron and its volume.
pub fn tet_gradients(x: [[f64; 3]; 4]) -> ([[f64; 3]; 4], f64) {
    let a = sub(x[1], x[0]);
    let b = sub(x[2], x[0]);
    let c = sub(x[3], x[0]);
    // Rows of J^-1 (J has columns a, b, c) are the cross products over det.
    let det =
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    let inv = 1.0 / det;
    let g1 = crate::mesh::shape::cross(b, c).map(|v| v * inv);
    let g2 = crate::mesh::shape::cross(c, a).map(|v| v * inv);
    let g3 = crate::mesh::shape::cross(a, b).map(|v| v * inv);
    let g0 = [-(g1[0] + g2[0] + g3[0]), -(g1[1] + g2[1] + g3[1]), -(g1[2] + g2[2] + g3[2])];
    ([g0, g1, g2, g3], det / 6.0)
}

/// Builds the element operators of a cell from its corner positions.
pub fn element_operators(
    kind: CellKind,
    corners: &[[f64; 3]],
    material: &Material,
) -> Result<ElementOperators, CellDefect> {
    let volume = check_cell(kind, corners)?;
    let dec = Decomposition::of(kind);
    let n = dec.n_corners;
    let points = dec.points(corners);
    let mut k = vec![0.0; 9 * n * n];
    let mut grad = vec![[0.0; 3]; n];
    let mut point_mass = vec![0.0; points.len()];
    let mut g = vec![[0.0; 3]; n];
    let mixed = !material.law.condenses();
    let mut per_tet = Vec::new();
    for tet in &dec.tets {
        let (gn, vt) = tet_gradients([points[tet[0]], points[tet[1]], points[tet[2]], points[tet[3]]]);
        for gc in g.iter_mut() {
            *gc = [0.0; 3];
        }
        for (kk, &p) in tet.iter().enumerate() {
            point_mass[p] += 0.25 * material.density * vt;
            for (c, gc) in g.iter_mut().enumerate() {
                let w = dec.weights[p][c];
                if w != 0.0 {
                    for i in 0..3 {
                        gc[i] += w * gn[kk][i];
                    }
                }
            }
        }
        for c in 0..n {
            for i in 0..3 {
                grad[c][i] += vt * g[c][i] / volume;
            }
        }
        match mixed {
            true => per_tet.push((g.clone(), vt)),
            false => add_isotropic_stiffness(&mut k, &g, vt, material.lame),
        }
    }
    if mixed {
        mixed_stiffness(&mut k, &per_tet, &grad, volume, material.lame);
    }
    let mass = (0..n).map(|c| (0..points.len()).map(|p| dec.weights[p][c] * point_mass[p]).sum()).collect();
    Ok(ElementOperators { k, grad, mass, volume })
}

/// The mixed (B-bar) stiffness of a cell whose material yields
/// ([`crate::physics::plastic`]): `sum_t V_t K_dev(g_t) + V K g g^T` with `K`
/// the bulk modulus, from each tetrahedron's corner gradients `g_t` and
/// volume `V_t` and the cell's volume-averaged gradients `g`: the
/// volumetric strain is the cell's average, the deviatoric one each
/// tetrahedron's own. Added to `k`.
pub fn mixed_stiffness(k: &mut [f64], tets: &[(Vec<[f64; 3]>, f64)], grad: &[[f64; 3]], volume: f64, lame: Lame) {
    let deviatoric = Lame { lambda: -2.0 * lame.mu / 3.0, mu: lame.mu };
    for (g, v) in tets {
        add_isotropic_stiffness(k, g, *v, deviatoric);
    }
    let bulk = Lame { lambda: lame.lambda + 2.0 * lame.mu / 3.0, mu: 0.0 };
    add_isotropic_stiffness(k, grad, volume, bulk);
}

/// Adds `w (lambda g_c g_d^T + mu (g_c . g_d) I + mu g_d g_c^T)` to every
/// corner block `(c, d)` of `k` (`3n x 3n`, row-major): the stiffness of a
/// linear-elastic point (a tetrahedron, or a Gauss point of weight `w`) whose
/// displacement gradient is `sum_c u_c (x) g_c`.
pub fn add_isotropic_stiffness(k: &mut [f64], g: &[[f64; 3]], w: f64, lame: Lame) {
    let n = g.len();
    let Lame { lambda, mu } = lame;
    for c in 0..n {
        for d in 0..n {
            let gcgd = g[c][0] * g[d][0] + g[c][1] * g[d][1] + g[c][2] * g[d][2];
            for i in 0..3 {
                let row = (3 * c + i) * 3 * n + 3 * d;
                for j in 0..3 {
                    let iso = if i == j { mu * gcgd } else { 0.0 };
                    k[row + j] += w * (lambda * g[c][i] * g[d][j] + iso + mu * g[d][i] * g[c][j]);
                }
            }
        }
    }
}

/// Eq. 12: the deformation force of one element, `f_e = K_e u_e`, written to
/// the element's own slot `f_e` (`3n` values, corner-major). `nodes` maps
/// corners to model nodes; `u` is the global displacement (3 per node).
#[inline]
pub fn element_force(k: &[f64], nodes: &[u32], u: &[f64], f_e: &mut [f64]) {
    let n = 3 * nodes.len();
    let mut u_e = [0.0; 24];
    for (c, &node) in nodes.iter().enumerate() {
        let b = 3 * node as usize;
        u_e[3 * c..3 * c + 3].copy_from_slice(&u[b..b + 3]);
    }
    // K_e is symmetric, so f = K u is accumulated column by column (row j of
    // K is column j): n independent sums the compiler can vectorise, instead
    // of one dependent 24-term sum per row.
    f_e.fill(0.0);
    for (col, &u_j) in k.chunks_exact(n).zip(&u_e[..n]) {
        for (f, k_ij) in f_e.iter_mut().zip(col) {
            *f += k_ij * u_j;
        }
    }
}

/// Element stress (Pa, Voigt order xx yy zz yz xz xy) from its averaged
/// gradients and the corner displacements.
pub fn element_stress(grad: &[[f64; 3]], nodes: &[u32], u: &[f64], lame: Lame) -> [f64; 6] {
    let mut h = [[0.0; 3]; 3]; // displacement gradient du_i/dx_j
    for (c, &node) in nodes.iter().enumerate() {
        let b = 3 * node as usize;
        for i in 0..3 {
            for j in 0..3 {
                h[i][j] += u[b + i] * grad[c][j];
            }
        }
    }
    lame.stress(&h)
}
