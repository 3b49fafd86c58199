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
    /// Condensed stiffness, `3n x 3n` row-major, dof `3c + i` (N/m); the model
    /// stores its upper triangle ([`pack_symmetric`]).
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

/// Number of values of a symmetric `K_e` of `n_corners` corners stored by
/// [`pack_symmetric`]: the upper triangle, `3n (3n + 1) / 2` (300 of 576 for a
/// hexahedron).
pub const fn packed_len(n_corners: usize) -> usize {
    3 * n_corners * (3 * n_corners + 1) / 2
}

/// Index in a symmetric diagonal block `[xx, xy, xz, yy, yz, zz]` of its entry `(a, b)`.
const DIAG: [[usize; 3]; 3] = [[0, 1, 2], [1, 3, 4], [2, 4, 5]];

/// Start of corner `c`'s group in the packed layout of `m` corners: each
/// earlier corner `c'` holds its diagonal block (6) and its `m - c' - 1`
/// blocks to the right (9 each).
const fn group_start(m: usize, c: usize) -> usize {
    6 * c + 9 * (c * (m - 1) - c * (c.saturating_sub(1)) / 2)
}

/// The upper triangle of the symmetric `K_e` (`3n x 3n`, row-major, dof
/// `3c + i`) in corner blocks, the layout [`element_force`] reads: for each
/// corner `c` in turn, its diagonal block `K_cc` as `[xx, xy, xz, yy, yz, zz]`,
/// then the blocks `K_cd` (`d > c`, 3 x 3 row-major). `K_dc = K_cd^T` is not
/// stored. 2400 B per hexahedron instead of 4608 (references/layout.md).
pub fn pack_symmetric(k: &[f64], n_corners: usize) -> Vec<f64> {
    let n = 3 * n_corners;
    let mut out = Vec::with_capacity(packed_len(n_corners));
    for c in 0..n_corners {
        for (a, b) in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)] {
            out.push(k[(3 * c + a) * n + 3 * c + b]);
        }
        for d in c + 1..n_corners {
            for a in 0..3 {
                for b in 0..3 {
                    out.push(k[(3 * c + a) * n + 3 * d + b]);
                }
            }
        }
    }
    out
}

/// Entry `(row, col)` of the symmetric `K_e` stored by [`pack_symmetric`]
/// (`m` corners): the assembly's and the mass rules' access, not the step's.
pub fn packed_entry(k: &[f64], m: usize, row: usize, col: usize) -> f64 {
    let (c, a, d, b) =
        if row / 3 <= col / 3 { (row / 3, row % 3, col / 3, col % 3) } else { (col / 3, col % 3, row / 3, row % 3) };
    let start = group_start(m, c);
    if c == d {
        k[start + DIAG[a][b]]
    } else {
        k[start + 6 + 9 * (d - c - 1) + 3 * a + b]
    }
}

/// The full `K_e` (`3m x 3m` row-major, in the first `(3m)^2` values) of
/// the packed one of `m <= 8` corners: for the passes that assemble or bound
/// `K_e` once (masses, time step, coarse space), not for the step.
pub fn unpack_symmetric(k: &[f64], m: usize) -> [f64; 576] {
    let n = 3 * m;
    let mut full = [0.0; 576];
    let mut at = 0;
    for c in 0..m {
        for (a, b) in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)] {
            full[(3 * c + a) * n + 3 * c + b] = k[at];
            full[(3 * c + b) * n + 3 * c + a] = k[at];
            at += 1;
        }
        for d in c + 1..m {
            for a in 0..3 {
                for b in 0..3 {
                    full[(3 * c + a) * n + 3 * d + b] = k[at];
                    full[(3 * d + b) * n + 3 * c + a] = k[at];
                    at += 1;
                }
            }
        }
    }
    full
}

/// Eq. 12: the deformation force of one element, `f_e = K_e u_e`, written to
/// the element's own slot `f_e` (`3n` values, corner-major). `k` is the
/// upper triangle of `K_e` in corner blocks ([`pack_symmetric`]); `nodes`
/// maps corners to model nodes; `u` is the global displacement (3 per node).
///
/// Each stored block is read once and used twice: `f_c += K_cd u_d` and
/// `f_d += K_cd^T u_c`. The sums run in a fixed order (corner by corner),
/// so the force does not depend on the thread that computes it.
///
/// Runs with AVX2 where the CPU has it ([`crate::simd`]; the same bits).
#[inline]
pub fn element_force(k: &[f64], nodes: &[u32], u: &[f64], f_e: &mut [f64]) {
    crate::simd::avx2!({
        let m = nodes.len();
        let mut u_e = [[0.0; 3]; 8];
        for (c, &node) in nodes.iter().enumerate() {
            let b = 3 * node as usize;
            u_e[c].copy_from_slice(&u[b..b + 3]);
        }
        let mut f = [[0.0; 3]; 8];
        let mut at = 0;
        for c in 0..m {
            let s = &k[at..at + 6];
            at += 6;
            let uc = u_e[c];
            f[c][0] += s[0] * uc[0] + s[1] * uc[1] + s[2] * uc[2];
            f[c][1] += s[1] * uc[0] + s[3] * uc[1] + s[4] * uc[2];
            f[c][2] += s[2] * uc[0] + s[4] * uc[1] + s[5] * uc[2];
            for d in c + 1..m {
                let b = &k[at..at + 9];
                at += 9;
                let ud = u_e[d];
                for i in 0..3 {
                    f[c][i] += b[3 * i] * ud[0] + b[3 * i + 1] * ud[1] + b[3 * i + 2] * ud[2];
                }
                for j in 0..3 {
                    f[d][j] += b[j] * uc[0] + b[3 + j] * uc[1] + b[6 + j] * uc[2];
                }
            }
        }
        for (slot, fc) in f_e.chunks_exact_mut(3).zip(&f[..m]) {
            slot.copy_from_slice(fc);
        }
    })
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
