//! Isoparametric element kernels of the implicit reference FEM.
//!
//! With the shape functions `N_c(xi)` of a reference cell and the isoparametric
//! map `x(xi) = sum_c N_c(xi) x_c`, the physical gradients are
//! `grad N_c = J^-T dN_c/dxi`, `J = dx/dxi`. For the isotropic law
//! `sigma = lambda tr(eps) I + 2 mu eps` (Pa) the element stiffness block of
//! corners `c, d` (N/m) and the consistent body-force vector (N) are
//!
//! `K_(ci)(dj) = sum_q w_q det J_q (lambda g_ci g_dj + mu (g_c . g_d) delta_ij + mu g_cj g_di)`,
//! `f_(ci) = sum_q w_q det J_q N_c(xi_q) rho g_i`,
//!
//! with `g_c = grad N_c` at Gauss point `q`. The element stress reported is the
//! volume average of the Gauss-point stresses,
//! `sigma_e = sum_q w_q det J_q sigma_q / sum_q w_q det J_q`.
//!
//! Cells and rules (gmsh node order, equal to VTK's):
//! - hexahedron (8 nodes, trilinear), reference `[-1, 1]^3`, full 2x2x2 Gauss
//!   (points `+-1/sqrt 3`, weights 1): exact stiffness for parallelepipeds,
//!   exact consistent load for any hexahedron;
//! - prism / wedge (6 nodes, linear triangle x linear line), reference
//!   `{xi, eta >= 0, xi + eta <= 1} x [-1, 1]`: a 3-point triangle rule
//!   (points `(1/6, 1/6) (2/3, 1/6) (1/6, 2/3)`, weights 1/6, degree 2) times
//!   2-point Gauss in `zeta`: 6 points ("3x2"), exact for a right prism;
//! - tetrahedron (4 nodes, linear), reference unit simplex, 1 point at the
//!   centroid (weight 1/6): exact (constant strain; `int N_c = V/4`).

use crate::mesh::shape::CellKind;
use crate::physics::element::add_isotropic_stiffness;
use crate::physics::material::Lame;

/// A Gauss point of a reference cell: coordinates and weight.
#[derive(Debug, Clone, Copy)]
pub struct GaussPoint {
    pub xi: [f64; 3],
    pub w: f64,
}

const G: f64 = 0.577_350_269_189_625_8; // 1 / sqrt(3)

/// Reference corners of the hexahedron (gmsh order).
pub const HEX_CORNERS: [[f64; 3]; 8] = [
    [-1., -1., -1.],
    [1., -1., -1.],
    [1., 1., -1.],
    [-1., 1., -1.],
    [-1., -1., 1.],
    [1., -1., 1.],
    [1., 1., 1.],
    [-1., 1., 1.],
];

/// The quadrature rule used for a cell kind (see the module docs).
pub fn gauss_points(kind: CellKind) -> Vec<GaussPoint> {
    match kind {
        CellKind::Hex8 => HEX_CORNERS.iter().map(|c| GaussPoint { xi: c.map(|s| s * G), w: 1.0 }).collect(),
        CellKind::Prism6 => {
            let tri = [[1.0 / 6.0, 1.0 / 6.0], [2.0 / 3.0, 1.0 / 6.0], [1.0 / 6.0, 2.0 / 3.0]];
            let mut v = Vec::with_capacity(6);
            for z in [-G, G] {
                for t in tri {
                    v.push(GaussPoint { xi: [t[0], t[1], z], w: 1.0 / 6.0 });
                }
            }
            v
        }
        CellKind::Tet4 => vec![GaussPoint { xi: [0.25; 3], w: 1.0 / 6.0 }],
    }
}

/// Shape function values and reference derivatives `dN_c/dxi_k` at `xi`
/// (only the first `kind.n_nodes()` entries are meaningful).
pub fn shape(kind: CellKind, xi: [f64; 3]) -> ([f64; 8], [[f64; 3]; 8]) {
    let mut n = [0.0; 8];
    let mut dn = [[0.0; 3]; 8];
    let [a, b, c] = xi;
    match kind {
        CellKind::Hex8 => {
            for (k, s) in HEX_CORNERS.iter().enumerate() {
                let (fa, fb, fc) = (1.0 + s[0] * a, 1.0 + s[1] * b, 1.0 + s[2] * c);
                n[k] = 0.125 * fa * fb * fc;
                dn[k] = [0.125 * s[0] * fb * fc, 0.125 * fa * s[1] * fc, 0.125 * fa * fb * s[2]];
            }
        }
        CellKind::Prism6 => {
            let l = [1.0 - a - b, a, b];
            let dl = [[-1.0, -1.0], [1.0, 0.0], [0.0, 1.0]];
            for (half, s) in [(0usize, -1.0), (3usize, 1.0)] {
                let h = 0.5 * (1.0 + s * c);
                for t in 0..3 {
                    n[half + t] = l[t] * h;
                    dn[half + t] = [dl[t][0] * h, dl[t][1] * h, l[t] * 0.5 * s];
                }
            }
        }
        CellKind::Tet4 => {
            n[..4].copy_from_slice(&[1.0 - a - b - c, a, b, c]);
            dn[..4].copy_from_slice(&[[-1.0, -1.0, -1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        }
    }
    (n, dn)
}

/// Physical gradients `grad N_c` (1/m) and `det J` at reference point `xi`.
/// `det J <= 0` (an inverted map) is returned as is; callers check it.
pub fn gradients(kind: CellKind, x: &[[f64; 3]], xi: [f64; 3]) -> ([f64; 8], [[f64; 3]; 8], f64) {
    let (n, dn) = shape(kind, xi);
    let mut j = [[0.0; 3]; 3]; // j[i][k] = dx_i / dxi_k
    for (c, xc) in x.iter().enumerate() {
        for i in 0..3 {
            for k in 0..3 {
                j[i][k] += xc[i] * dn[c][k];
            }
        }
    }
    let det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0])
        + j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
    // inv[k][i] = dxi_k / dx_i (cofactors over det)
    let inv_det = 1.0 / det;
    let inv = [
        [
            (j[1][1] * j[2][2] - j[1][2] * j[2][1]) * inv_det,
            (j[0][2] * j[2][1] - j[0][1] * j[2][2]) * inv_det,
            (j[0][1] * j[1][2] - j[0][2] * j[1][1]) * inv_det,
        ],
        [
            (j[1][2] * j[2][0] - j[1][0] * j[2][2]) * inv_det,
            (j[0][0] * j[2][2] - j[0][2] * j[2][0]) * inv_det,
            (j[0][2] * j[1][0] - j[0][0] * j[1][2]) * inv_det,
        ],
        [
            (j[1][0] * j[2][1] - j[1][1] * j[2][0]) * inv_det,
            (j[0][1] * j[2][0] - j[0][0] * j[2][1]) * inv_det,
            (j[0][0] * j[1][1] - j[0][1] * j[1][0]) * inv_det,
        ],
    ];
    let mut g = [[0.0; 3]; 8];
    for c in 0..x.len() {
        for i in 0..3 {
            g[c][i] = dn[c][0] * inv[0][i] + dn[c][1] * inv[1][i] + dn[c][2] * inv[2][i];
        }
    }
    (n, g, det)
}

/// A Gauss point whose Jacobian determinant is not positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BadJacobian {
    pub point: usize,
    pub det: f64,
}

/// Stiffness and consistent load of one element.
#[derive(Debug, Clone)]
pub struct ElementMatrices {
    /// `3n x 3n`, row-major, dof `3c + i` (N/m).
    pub k: Vec<f64>,
    /// Consistent body force, `3c + i` (N).
    pub f: Vec<f64>,
    /// Element volume `sum_q w_q det J_q` (m^3).
    pub volume: f64,
}

/// Element stiffness and the consistent load of the body force `b = rho g`
/// (N/m^3), by the cell's Gauss rule.
pub fn element_matrices(
    kind: CellKind,
    x: &[[f64; 3]],
    lame: Lame,
    b: [f64; 3],
) -> Result<ElementMatrices, BadJacobian> {
    let n = kind.n_nodes();
    let mut k = vec![0.0; 9 * n * n];
    let mut f = vec![0.0; 3 * n];
    let mut volume = 0.0;
    for (q, gp) in gauss_points(kind).iter().enumerate() {
        let (nq, g, det) = gradients(kind, x, gp.xi);
        if !(det > 0.0) {
            return Err(BadJacobian { point: q, det });
        }
        let wd = gp.w * det;
        volume += wd;
        for c in 0..n {
            for i in 0..3 {
                f[3 * c + i] += wd * nq[c] * b[i];
            }
        }
        add_isotropic_stiffness(&mut k[..], &g[..n], wd, lame);
    }
    Ok(ElementMatrices { k, f, volume })
}

/// Volume-averaged element stress from the corner displacements `ue`
/// (`3c + i`, m).
pub fn element_stress(kind: CellKind, x: &[[f64; 3]], ue: &[f64], lame: Lame) -> Result<[f64; 6], BadJacobian> {
    let mut sum = [0.0; 6];
    let mut volume = 0.0;
    for (q, gp) in gauss_points(kind).iter().enumerate() {
        let (_, g, det) = gradients(kind, x, gp.xi);
        if !(det > 0.0) {
            return Err(BadJacobian { point: q, det });
        }
        let mut h = [[0.0; 3]; 3];
        for c in 0..x.len() {
            for i in 0..3 {
                for j in 0..3 {
                    h[i][j] += ue[3 * c + i] * g[c][j];
                }
            }
        }
        let s = lame.stress(&h);
        let wd = gp.w * det;
        volume += wd;
        for (acc, v) in sum.iter_mut().zip(s) {
            *acc += wd * v;
        }
    }
    Ok(sum.map(|v| v / volume))
}

/// Inverse isoparametric map by Newton iteration: the reference point of the
/// physical point `p`, if the iteration converges (to `1e-12` in `xi`).
pub fn reference_point(kind: CellKind, x: &[[f64; 3]], p: [f64; 3]) -> Option<[f64; 3]> {
    let mut xi = match kind {
        CellKind::Hex8 => [0.0; 3],
        CellKind::Prism6 => [1.0 / 3.0, 1.0 / 3.0, 0.0],
        CellKind::Tet4 => [0.25; 3],
    };
    for _ in 0..30 {
        let (n, dn) = shape(kind, xi);
        let mut r = [0.0; 3];
        let mut j = [[0.0; 3]; 3];
        for (c, xc) in x.iter().enumerate() {
            for i in 0..3 {
                r[i] += n[c] * xc[i];
                for k in 0..3 {
                    j[i][k] += xc[i] * dn[c][k];
                }
            }
        }
        let r = [p[0] - r[0], p[1] - r[1], p[2] - r[2]];
        let d = solve3(j, r)?;
        for k in 0..3 {
            xi[k] += d[k];
        }
        if d.iter().map(|v| v.abs()).fold(0.0, f64::max) < 1e-12 {
            return Some(xi);
        }
    }
    None
}

/// Whether a reference point lies in the reference cell (with tolerance `tol`).
pub fn inside_reference(kind: CellKind, xi: [f64; 3], tol: f64) -> bool {
    let [a, b, c] = xi;
    match kind {
        CellKind::Hex8 => xi.iter().all(|v| v.abs() <= 1.0 + tol),
        CellKind::Prism6 => a >= -tol && b >= -tol && a + b <= 1.0 + tol && c.abs() <= 1.0 + tol,
        CellKind::Tet4 => a >= -tol && b >= -tol && c >= -tol && a + b + c <= 1.0 + tol,
    }
}

/// Solves the 3x3 system `J d = r` by Cramer's rule (None if singular).
fn solve3(j: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det3 = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let det = det3(j);
    if !(det.abs() > 0.0) || !det.is_finite() {
        return None;
    }
    let mut d = [0.0; 3];
    for (k, dk) in d.iter_mut().enumerate() {
        let mut m = j;
        for i in 0..3 {
            m[i][k] = r[i];
        }
        *dk = det3(m) / det;
    }
    Some(d)
}
