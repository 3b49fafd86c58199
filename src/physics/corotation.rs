//! Large rotations of a small-strain block: the corotational element
//! (docs/method.md 2.13). A block may translate and rotate without limit
//! while its strain stays small: its rigid rotation `R` is taken out of the
//! motion of its corners, the small-strain operator `K_e` acts on what is
//! left in the block's own frame, and the force is rotated back:
//!
//! `u_c' = R^T (x_c - x_bar) - (X_c - X_bar)`, `f_e = R K_e u'`,
//!
//! with `X` the corners at rest, `x` where they are, and bars the corner
//! means. A rigid motion leaves `u' = 0` to rounding (objectivity).
//!
//! `R` is the rotation nearest to the corners' motion: the polar factor of
//! `A = sum_c (x_c - x_bar)(X_c - X_bar)^T` (Kabsch's, Horn's), by the
//! singular value decomposition with the reflection removed.

use nalgebra::Matrix3;

/// A 3 x 3 matrix, row-major.
pub type Mat3 = [[f64; 3]; 3];

/// The identity.
pub const IDENTITY: Mat3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// `R v`.
#[inline]
pub fn rotate(r: &Mat3, v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2])
}

/// `R^T v`.
#[inline]
pub fn rotate_back(r: &Mat3, v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| r[0][i] * v[0] + r[1][i] * v[1] + r[2][i] * v[2])
}

/// The angle of a rotation (rad, 0 to pi): `acos((tr R - 1) / 2)`.
pub fn rotation_angle(r: &Mat3) -> f64 {
    ((r[0][0] + r[1][1] + r[2][2] - 1.0) / 2.0).clamp(-1.0, 1.0).acos()
}

fn mean(points: &[[f64; 3]]) -> [f64; 3] {
    let mut m = [0.0; 3];
    for p in points {
        for d in 0..3 {
            m[d] += p[d];
        }
    }
    m.map(|v| v / points.len() as f64)
}

/// The rotation that best carries the corners `x0` (at rest) onto `x` (now):
/// the polar factor of `A = sum_c (x_c - x_bar)(X_c - X_bar)^T`. Exact for a
/// rigid motion; the identity for a block that has not moved.
pub fn best_rotation(x0: &[[f64; 3]], x: &[[f64; 3]]) -> Mat3 {
    polar_by_svd(&cross_covariance(x0, x))
}

/// The rotation nearest to `a` (its polar factor), by the singular value
/// decomposition with the reflection removed.
fn polar_by_svd(a: &Mat3) -> Mat3 {
    let svd = Matrix3::from_fn(|i, j| a[i][j]).svd(true, true);
    let (Some(u), Some(vt)) = (svd.u, svd.v_t) else { return IDENTITY };
    let mut r = u * vt;
    if r.determinant() < 0.0 {
        // A reflection: flip the axis of the smallest singular value.
        let k = (0..3).min_by(|&i, &j| svd.singular_values[i].total_cmp(&svd.singular_values[j])).unwrap_or(2);
        let mut u = u;
        for i in 0..3 {
            u[(i, k)] = -u[(i, k)];
        }
        r = u * vt;
    }
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| r[(i, j)]))
}

/// The cross-covariance `A = sum_c (x_c - x_bar)(X_c - X_bar)^T`.
fn cross_covariance(x0: &[[f64; 3]], x: &[[f64; 3]]) -> Mat3 {
    let (c0, c) = (mean(x0), mean(x));
    let mut a = [[0.0; 3]; 3];
    for (p0, p) in x0.iter().zip(x) {
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] += (p[i] - c[i]) * (p0[j] - c0[j]);
            }
        }
    }
    a
}

/// The unit quaternion `[w, x, y, z]` of a rotation (Shepperd's method).
fn quaternion(r: &Mat3) -> [f64; 4] {
    let t = r[0][0] + r[1][1] + r[2][2];
    let q = if t > r[0][0].max(r[1][1]).max(r[2][2]) {
        let s = 2.0 * (1.0 + t).sqrt();
        [0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s]
    } else if r[0][0] >= r[1][1] && r[0][0] >= r[2][2] {
        let s = 2.0 * (1.0 + r[0][0] - r[1][1] - r[2][2]).sqrt();
        [(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s]
    } else if r[1][1] >= r[2][2] {
        let s = 2.0 * (1.0 + r[1][1] - r[0][0] - r[2][2]).sqrt();
        [(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s]
    } else {
        let s = 2.0 * (1.0 + r[2][2] - r[0][0] - r[1][1]).sqrt();
        [(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s]
    };
    let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
    q.map(|v| v / n)
}

/// The rotation of a unit quaternion.
fn quaternion_matrix([w, x, y, z]: [f64; 4]) -> Mat3 {
    [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)],
    ]
}

/// Newton steps of [`nearest_rotation`] before it falls back to the SVD.
const NEWTON_STEPS: usize = 8;

/// [`best_rotation`] by Newton's method from a nearby rotation `start`
/// (the block's rotation at the last step): with `B = R^T A`, `S` its
/// symmetric part and `g` the axial vector of `B - B^T`, the correction
/// `R <- R exp([d])` with `(tr S I - S) d = g` makes `R^T A` symmetric to
/// second order, so one or two steps suffice from the last step's rotation.
/// Falls back to the SVD when `start` is far (`tr S I - S` not positive
/// definite) or the steps do not converge. The same rotation as
/// [`best_rotation`] to rounding (unit test), at a fraction of its cost.
pub fn nearest_rotation(start: &Mat3, x0: &[[f64; 3]], x: &[[f64; 3]]) -> Mat3 {
    let a = cross_covariance(x0, x);
    let size: f64 = a.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    if size == 0.0 {
        return IDENTITY;
    }
    let mut q = quaternion(start);
    for _ in 0..NEWTON_STEPS {
        let r = quaternion_matrix(q);
        // B = R^T A.
        let b: Mat3 = [0, 1, 2].map(|i| [0, 1, 2].map(|j| r[0][i] * a[0][j] + r[1][i] * a[1][j] + r[2][i] * a[2][j]));
        let g = [b[2][1] - b[1][2], b[0][2] - b[2][0], b[1][0] - b[0][1]];
        let tr = b[0][0] + b[1][1] + b[2][2];
        let m: Mat3 =
            [0, 1, 2].map(|i| [0, 1, 2].map(|j| f64::from(u8::from(i == j)) * tr - 0.5 * (b[i][j] + b[j][i])));
        // Positive definite (Sylvester), else the start is too far.
        let m2 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        if m[0][0] <= 0.0 || m2 <= 0.0 || det <= 0.0 {
            break;
        }
        // d = M^-1 g by cofactors (M is symmetric).
        let inv = [
            [
                m[1][1] * m[2][2] - m[1][2] * m[2][1],
                m[0][2] * m[2][1] - m[0][1] * m[2][2],
                m[0][1] * m[1][2] - m[0][2] * m[1][1],
            ],
            [
                m[1][2] * m[2][0] - m[1][0] * m[2][2],
                m[0][0] * m[2][2] - m[0][2] * m[2][0],
                m[0][2] * m[1][0] - m[0][0] * m[1][2],
            ],
            [
                m[1][0] * m[2][1] - m[1][1] * m[2][0],
                m[0][1] * m[2][0] - m[0][0] * m[2][1],
                m[0][0] * m[1][1] - m[0][1] * m[1][0],
            ],
        ];
        let d = [0, 1, 2].map(|i| (inv[i][0] * g[0] + inv[i][1] * g[1] + inv[i][2] * g[2]) / det);
        let angle = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if angle < 1e-15 {
            return r;
        }
        // q <- q * (cos(angle/2), sin(angle/2) d/angle): R <- R exp([d]).
        let (s, c) = (0.5 * angle).sin_cos();
        let e = d.map(|v| s * v / angle);
        let [w, x1, y1, z1] = q;
        let p = [
            w * c - x1 * e[0] - y1 * e[1] - z1 * e[2],
            w * e[0] + x1 * c + y1 * e[2] - z1 * e[1],
            w * e[1] - x1 * e[2] + y1 * c + z1 * e[0],
            w * e[2] + x1 * e[1] - y1 * e[0] + z1 * c,
        ];
        let n = p.iter().map(|v| v * v).sum::<f64>().sqrt();
        q = p.map(|v| v / n);
        if angle < 1e-10 {
            // Quadratic convergence: the next correction is below rounding.
            return quaternion_matrix(q);
        }
    }
    polar_by_svd(&a)
}

/// The corners' deformation in the block's own frame,
/// `u_c' = R^T (x_c - x_bar) - (X_c - X_bar)`, written to `out` (3 per corner).
pub fn local_deformation(r: &Mat3, x0: &[[f64; 3]], x: &[[f64; 3]], out: &mut [f64]) {
    let (c0, c) = (mean(x0), mean(x));
    for (k, (p0, p)) in x0.iter().zip(x).enumerate() {
        let back = rotate_back(r, [p[0] - c[0], p[1] - c[1], p[2] - c[2]]);
        for d in 0..3 {
            out[3 * k + d] = back[d] - (p0[d] - c0[d]);
        }
    }
}

/// Local corner indices, for [`super::element::element_force`] on a block's own vector.
const LOCAL: [u32; 8] = [0, 1, 2, 3, 4, 5, 6, 7];

/// `y = K x` for a packed `K_e` of `m` corners on local vectors: eq. 12's
/// kernel ([`super::element::element_force`]) with the corners numbered 0..m.
pub fn packed_product(k: &[f64], m: usize, x: &[f64], y: &mut [f64]) {
    super::element::element_force(k, &LOCAL[..m], x, &mut y[..3 * m]);
}

/// What the corotational element gives for one block now.
#[derive(Debug, Clone, Copy)]
pub struct Corotated {
    pub rotation: Mat3,
    /// Strain energy `u'^T K_e u' / 2` (J).
    pub energy: f64,
}

/// The corotational force of one element: `f_e = R K_e u'` into `f_e` (3 per
/// corner, the force that resists deformation, as [`super::element::element_force`]),
/// from its packed `K_e`, its corners at rest `x0` and now `x`.
pub fn corotated_force(k: &[f64], x0: &[[f64; 3]], x: &[[f64; 3]], f_e: &mut [f64]) -> Corotated {
    corotated_force_from(&IDENTITY, k, x0, x, f_e)
}

/// [`corotated_force`] with the rotation found from `start` (the block's
/// rotation at the last step) by [`nearest_rotation`].
pub fn corotated_force_from(start: &Mat3, k: &[f64], x0: &[[f64; 3]], x: &[[f64; 3]], f_e: &mut [f64]) -> Corotated {
    let m = x0.len();
    let r = nearest_rotation(start, x0, x);
    let mut u = [0.0; 24];
    local_deformation(&r, x0, x, &mut u);
    let mut f = [0.0; 24];
    packed_product(k, m, &u, &mut f);
    let energy = 0.5 * (0..3 * m).map(|i| u[i] * f[i]).sum::<f64>();
    for c in 0..m {
        let g = rotate(&r, [f[3 * c], f[3 * c + 1], f[3 * c + 2]]);
        f_e[3 * c..3 * c + 3].copy_from_slice(&g);
    }
    Corotated { rotation: r, energy }
}

/// The rotation about the unit axis `axis` by `angle` (rad), Rodrigues.
pub fn axis_angle(axis: [f64; 3], angle: f64) -> Mat3 {
    let (s, c) = angle.sin_cos();
    let [x, y, z] = axis;
    let t = 1.0 - c;
    [
        [c + x * x * t, x * y * t - z * s, x * z * t + y * s],
        [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
        [z * x * t - y * s, z * y * t + x * s, c + z * z * t],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> Vec<[f64; 3]> {
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
            [0.0, 1.0, 1.0],
        ]
    }

    #[test]
    fn a_rigid_motion_is_recovered_exactly() {
        let x0 = cube();
        let r = axis_angle([0.0, 0.6, 0.8], 2.1);
        let x: Vec<[f64; 3]> =
            x0.iter().map(|&p| rotate(&r, p)).map(|p| [p[0] + 5.0, p[1] - 2.0, p[2] + 1.0]).collect();
        let got = best_rotation(&x0, &x);
        for i in 0..3 {
            for j in 0..3 {
                assert!((got[i][j] - r[i][j]).abs() < 1e-13, "{got:?} vs {r:?}");
            }
        }
        let mut u = [0.0; 24];
        local_deformation(&got, &x0, &x, &mut u);
        assert!(u.iter().all(|v| v.abs() < 1e-13), "{u:?}");
    }

    #[test]
    fn newton_from_the_last_rotation_is_the_svd_rotation() {
        // A slender deformed block (10 x 25 x 1, the toppling case's shape),
        // turned 1.3 rad; starts near it, at it, and far from it.
        let x0: Vec<[f64; 3]> = cube().iter().map(|p| [10.0 * p[0], p[1], 25.0 * p[2]]).collect();
        let r = axis_angle([0.36, 0.48, 0.8], 1.3);
        let strained: Vec<[f64; 3]> = x0
            .iter()
            .enumerate()
            .map(|(k, p)| [p[0] * 1.002 + 1e-3 * k as f64, p[1] - 2e-3 * p[2], p[2] * 0.999 + 5e-4 * (k % 3) as f64])
            .collect();
        let x: Vec<[f64; 3]> = strained.iter().map(|&p| rotate(&r, p)).collect();
        let svd = best_rotation(&x0, &x);
        for start in [axis_angle([0.36, 0.48, 0.8], 1.2999), axis_angle([0.0, 1.0, 0.0], 1.25), svd, IDENTITY] {
            let got = nearest_rotation(&start, &x0, &x);
            for i in 0..3 {
                for j in 0..3 {
                    assert!((got[i][j] - svd[i][j]).abs() < 1e-13, "{got:?} vs {svd:?}");
                }
            }
        }
    }

    #[test]
    fn a_stretch_is_not_a_rotation() {
        let x0 = cube();
        let x: Vec<[f64; 3]> = x0.iter().map(|p| [1.01 * p[0], p[1], p[2]]).collect();
        let r = best_rotation(&x0, &x);
        assert!(rotation_angle(&r) < 1e-12);
        let mut u = [0.0; 24];
        local_deformation(&r, &x0, &x, &mut u);
        assert!((u[3] - 0.005).abs() < 1e-12, "corner 1 moves +0.005 from the centroid: {}", u[3]);
    }
}
