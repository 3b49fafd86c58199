//! A cell's tetrahedra as lanes (a structure of arrays), so that the
//! screens' loops over tetrahedra vectorize: their stresses, their principal
//! values, and the main plane's return.

use super::principal::{chebyshev_argument, Cubic, COS_THIRD_ACOS};
use super::six;
use crate::mesh::shape::MAX_TETS;

/// A cell's tetrahedra as lanes: component `i` of tetrahedron `t` at
/// `[i][t]` (a structure of arrays), so that a loop over `t` vectorizes.
pub type Lanes<const K: usize> = [[f64; MAX_TETS]; K];

/// What [`MohrCoulomb::common_returns`] decided for each lane: `elastic`
/// (inside the surface), or `main` (returned onto the main plane alone,
/// its stress in `stress`), or neither (the caller's).
pub struct CommonReturns {
    pub stress: Lanes<6>,
    pub elastic: [bool; MAX_TETS],
    pub main: [bool; MAX_TETS],
}

/// The lanes of the first `n` stresses of `sigma` (zero beyond them).
#[inline(always)]
pub fn lanes_of(sigma: &[[f64; 6]], n: usize) -> Lanes<6> {
    let mut comp = [[0.0; MAX_TETS]; 6];
    for (t, s) in sigma[..n.min(MAX_TETS)].iter().enumerate() {
        for i in 0..6 {
            comp[i][t] = s[i];
        }
    }
    comp
}

/// `principal_values` of the first `n` lanes of `sigma` (zero beyond
/// them): loops the compiler vectorizes.
#[inline(always)]
pub fn principal_lanes(sigma: &Lanes<6>, n: usize) -> Lanes<3> {
    const N: usize = MAX_TETS;
    let n = n.min(N);
    let (mut cubic, mut t) = ([Cubic::default(); N], [0.0; N]);
    for l in 0..n {
        cubic[l] = Cubic::of(&six(|i| sigma[i][l]));
        t[l] = chebyshev_argument(cubic[l].r);
    }
    // cos_third_acos's polynomial a degree at a time across the lanes: the
    // same operations per lane, but the lanes' chains side by side rather
    // than one long chain after the other.
    let mut c = [COS_THIRD_ACOS[17]; N];
    for k in (0..17).rev() {
        for l in 0..n {
            c[l] = c[l] * t[l] + COS_THIRD_ACOS[k];
        }
    }
    let mut values = [[0.0; N]; 3];
    for l in 0..n {
        let v = cubic[l].roots(c[l]);
        for i in 0..3 {
            values[i][l] = v[i];
        }
    }
    values
}

/// The return of the principal values `s` onto the main plane alone,
/// `s - dg D n` with `dg = excess / (m . D n)`.
#[inline(always)]
pub(super) fn main_plane_point(s: [f64; 3], excess: f64, dn: [f64; 3], denom: f64) -> [f64; 3] {
    let dg = excess / denom;
    [s[0] - dg * dn[0], s[1] - dg * dn[1], s[2] - dg * dn[2]]
}
