//! Principal stresses in closed form ([`principal_values`], Smith 1961) and
//! `cos(acos(r) / 3)` as a polynomial ([`cos_third_acos`]), with the
//! eigensolver the tests check them against.

#[cfg(test)]
use nalgebra::{Matrix3, SymmetricEigen};

/// Principal stresses ordered `s1 >= s2 >= s3`, in closed form (the
/// trigonometric solution of the characteristic cubic, Smith 1961), without
/// the trigonometry: the largest root `c = cos(acos(r) / 3)` of
/// `4 c^3 - 3 c = r` is [`cos_third_acos`]. Branch-free, so that
/// [`principal_lanes`] vectorizes it: an isotropic stress (`p2 = 0`)
/// takes `q` thrice at the end, its other values discarded.
#[inline(always)]
pub(super) fn principal_values(sigma: &[f64; 6]) -> [f64; 3] {
    let cubic = Cubic::of(sigma);
    cubic.roots(cos_third_acos(cubic.r))
}

/// The characteristic cubic of a stress in [`principal_values`]' terms:
/// its mean `q`, `p2 = |A - q I|^2`, `p = sqrt(p2 / 6)` and
/// `r = det((A - q I) / p) / 2` in `[-1, 1]`.
#[derive(Clone, Copy, Default)]
pub(super) struct Cubic {
    q: f64,
    p2: f64,
    p: f64,
    pub(super) r: f64,
}

impl Cubic {
    #[inline(always)]
    pub(super) fn of(sigma: &[f64; 6]) -> Self {
        let [xx, yy, zz, yz, xz, xy] = *sigma;
        let q = (xx + yy + zz) / 3.0;
        let p1 = yz * yz + xz * xz + xy * xy;
        let (a, b, c) = (xx - q, yy - q, zz - q);
        let p2 = a * a + b * b + c * c + 2.0 * p1;
        let p = (p2 / 6.0).sqrt();
        let det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
        Self { q, p2, p, r: (det / (2.0 * p * p * p)).clamp(-1.0, 1.0) }
    }

    /// The roots, descending, from `c = cos(acos(r) / 3)`; an isotropic
    /// stress (`p2 = 0`) takes `q` thrice.
    #[inline(always)]
    pub(super) fn roots(&self, c: f64) -> [f64; 3] {
        let Self { q, p2, p, .. } = *self;
        // cos(a + 2 pi / 3) = -cos(a) / 2 - sin(a) sqrt(3) / 2, a in [0, pi / 3].
        let s = (1.0 - c * c).max(0.0).sqrt();
        let s1 = q + 2.0 * p * c;
        let s3 = q - p * (c + 3f64.sqrt() * s);
        let s2 = 3.0 * q - s1 - s3;
        let round = p2 > 0.0;
        [if round { s1 } else { q }, if round { s2 } else { q }, if round { s3 } else { q }]
    }
}

/// `cos(acos(r) / 3)` for `r` in `[-1, 1]`: with `x = sqrt((1 + r) / 2)`
/// (`r = cos(3 a)` gives `x = cos(3 a / 2)`) it is `cos(2 acos(x) / 3)`,
/// analytic on `[0, 1]` (even in `acos(x)` at `x = 1`), here its degree-17
/// Chebyshev interpolant in `t = 2 x - 1`: within 2.3e-16 of 50-digit
/// values (scripts/cos_third_acos.py computes the coefficients and that
/// error), within 4.5e-16 of libm's `(r.acos() / 3.0).cos()` (a test). It
/// replaces that libm pair, a fifth of a yielding tetrahedron's cost, and
/// unlike it vectorizes ([`principal_lanes`]; references/performance.md,
/// "2026-12-05 (sixth)").
#[inline(always)]
pub(super) fn cos_third_acos(r: f64) -> f64 {
    let t = chebyshev_argument(r);
    let mut h = COS_THIRD_ACOS[17];
    for k in (0..17).rev() {
        h = h * t + COS_THIRD_ACOS[k];
    }
    h
}

/// [`cos_third_acos`]'s Chebyshev variable `t = 2 sqrt((1 + r) / 2) - 1`.
#[inline(always)]
pub(super) fn chebyshev_argument(r: f64) -> f64 {
    let x = (0.5 * (1.0 + r)).max(0.0).sqrt();
    2.0 * x - 1.0
}

/// [`cos_third_acos`]'s Chebyshev interpolant in monomials of `t`
/// (scripts/cos_third_acos.py).
pub(super) const COS_THIRD_ACOS: [f64; 18] = [
    0.7660444431189779,
    0.2474090663228531,
    -0.015509188436466925,
    0.0024663528150807865,
    -0.0005041246916471823,
    0.00011642545310520361,
    -2.8919931061417995e-05,
    7.541076906895577e-06,
    -2.0358967113961453e-06,
    5.6415984269464e-07,
    -1.5946504043853947e-07,
    4.583483187568922e-08,
    -1.348180209578561e-08,
    3.972853735371566e-09,
    -1.0526658241086324e-09,
    3.1461757039177313e-10,
    -1.6358250988858183e-10,
    4.9908110575962183e-11,
];

/// Principal stresses ordered `s1 >= s2 >= s3` and their directions
/// (columns), by nalgebra's eigensolver: the tests' independent check of
/// [`principal_values`] and [`spectral_update`].
#[cfg(test)]
pub(super) fn principal(sigma: &[f64; 6]) -> ([f64; 3], Matrix3<f64>) {
    let m = Matrix3::new(
        sigma[0], sigma[5], sigma[4], //
        sigma[5], sigma[1], sigma[3], //
        sigma[4], sigma[3], sigma[2],
    );
    let eig = SymmetricEigen::new(m);
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
    let s = order.map(|i| eig.eigenvalues[i]);
    let axes = Matrix3::from_columns(&order.map(|i| eig.eigenvectors.column(i).into_owned()));
    (s, axes)
}

/// `sigma = sum_i s_i a_i a_i^T` in Voigt order.
#[cfg(test)]
pub(super) fn from_principal(s: [f64; 3], axes: &Matrix3<f64>) -> [f64; 6] {
    let mut out = [0.0; 6];
    const IJ: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)];
    for (o, &(i, j)) in out.iter_mut().zip(&IJ) {
        *o = (0..3).map(|k| s[k] * axes[(i, k)] * axes[(j, k)]).sum();
    }
    out
}
