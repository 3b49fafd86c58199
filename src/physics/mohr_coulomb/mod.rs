//! The Mohr-Coulomb rock mass: elastic-perfectly-plastic, with a tension
//! cut-off and a non-associated flow rule, integrated by a return mapping in
//! principal stresses (de Souza Neto, Peric & Owen 2008, section 8.2; the
//! FLAC3D manual's Mohr-Coulomb model).
//!
//! Stresses are positive in tension. With the principal stresses ordered
//! `s1 >= s2 >= s3` the elastic domain is bounded by six planes in principal
//! space, each `m . s <= k`, with the flow direction `n` (the gradient of the
//! plastic potential):
//!
//! | plane | `m` | `k` | `n` |
//! |---|---|---|---|
//! | shear 1-3 (the main plane) | `(1 + sin phi, 0, -(1 - sin phi))` | `2 c cos phi` | `(1 + sin psi, 0, -(1 - sin psi))` |
//! | shear 1-2 (edge `s2 = s3`)  | `(1 + sin phi, -(1 - sin phi), 0)` | `2 c cos phi` | `(1 + sin psi, -(1 - sin psi), 0)` |
//! | shear 2-3 (edge `s1 = s2`)  | `(0, 1 + sin phi, -(1 - sin phi))` | `2 c cos phi` | `(0, 1 + sin psi, -(1 - sin psi))` |
//! | tension `i` = 1, 2, 3 | `e_i` | `T` | `e_i` |
//!
//! The return from a trial stress `s*` onto an active set `A` of planes is
//! `s = s* - sum_(b in A) dg_b D n_b` with the multipliers from the linear
//! system `sum_b (m_a . D n_b) dg_b = m_a . s* - k_a` (perfect plasticity:
//! the planes do not move), `D` the elastic matrix in principal axes
//! (`K + 4G/3` on the diagonal, `K - 2G/3` off it). The active set is the
//! smallest one (the main plane, then edges and the tension corner, then the
//! apex) whose multipliers are non-negative and whose result violates no
//! plane: this is the main-plane, edge and apex logic of de Souza Neto's
//! Box 8.5 with the tension planes added. The principal directions are
//! kept (isotropy), and the stress is rebuilt from them.
//!
//! The files: this one holds the surface and its return mapping
//! ([`RockStrength`], [`MohrCoulomb`]); [`principal`] the principal values in
//! closed form and the polynomial they use; [`lanes`] a cell's tetrahedra as
//! lanes for the vectorized screens; [`spectral`] the stress rebuilt from
//! new principal values; `tests.rs` the tests.

use crate::mesh::shape::MAX_TETS;
use nalgebra::Matrix3;

use super::elasticity::Lame;

mod lanes;
mod principal;
mod spectral;
#[cfg(test)]
mod tests;

use lanes::main_plane_point;
pub use lanes::{lanes_of, principal_lanes, CommonReturns, Lanes};
use principal::principal_values;
#[cfg(test)]
use principal::{cos_third_acos, from_principal, principal};
use spectral::{spectral_general, spectral_update};

/// The strength of a Mohr-Coulomb rock mass as the scene gives it (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RockStrength {
    /// Cohesion `c` (Pa).
    pub cohesion: f64,
    /// `tan(phi)`.
    pub tan_phi: f64,
    /// Tensile strength `T` (Pa); the kernel caps it at the apex `c / tan(phi)`.
    pub tensile: f64,
    /// `tan(psi)` of the dilation angle (`psi <= phi`).
    pub tan_psi: f64,
}

impl RockStrength {
    /// Strength reduction by `f`: `c / f`, `tan(phi) / f`, `T / f`, and the
    /// dilation angle capped at the reduced friction angle,
    /// `psi_f = min(psi, phi_f)` (the convention of Dawson, Roth & Drescher
    /// 1999 and FLAC's factor-of-safety solve).
    pub fn reduced(&self, f: f64) -> Self {
        let tan_phi = self.tan_phi / f;
        Self { cohesion: self.cohesion / f, tan_phi, tensile: self.tensile / f, tan_psi: self.tan_psi.min(tan_phi) }
    }
}

/// The yield surface and flow rule in the kernel's constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MohrCoulomb {
    /// `2 c cos phi` (Pa).
    pub k: f64,
    pub sin_phi: f64,
    pub sin_psi: f64,
    /// Tension cut-off `T` (Pa).
    pub tensile: f64,
}

/// What the return mapping did at one point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Yield {
    #[default]
    Elastic,
    /// On a shear plane (an edge or the apex included).
    Shear,
    /// On a tension plane (with or without a shear plane).
    Tension,
}

const PLANES: usize = 6;

impl MohrCoulomb {
    /// The kernel's form of a strength.
    pub fn of(r: &RockStrength) -> Self {
        let phi = r.tan_phi.atan();
        let psi = r.tan_psi.atan();
        let apex = if r.tan_phi > 0.0 { r.cohesion / r.tan_phi } else { f64::INFINITY };
        Self { k: 2.0 * r.cohesion * phi.cos(), sin_phi: phi.sin(), sin_psi: psi.sin(), tensile: r.tensile.min(apex) }
    }

    /// Plane `p` of the table above in principal space: `(m, k, n)`.
    fn plane(&self, p: usize) -> ([f64; 3], f64, [f64; 3]) {
        let (sf, sp) = (self.sin_phi, self.sin_psi);
        let shear = |i: usize, j: usize| {
            let mut m = [0.0; 3];
            let mut n = [0.0; 3];
            (m[i], m[j], n[i], n[j]) = (1.0 + sf, -(1.0 - sf), 1.0 + sp, -(1.0 - sp));
            (m, self.k, n)
        };
        let tension = |i: usize| {
            let mut e = [0.0; 3];
            e[i] = 1.0;
            (e, self.tensile, e)
        };
        match p {
            0 => shear(0, 2),
            1 => shear(0, 1),
            2 => shear(1, 2),
            t => tension(t - 3),
        }
    }

    /// The largest violation `m . s - k` over the six planes (Pa), for
    /// principal stresses `s` ordered `s1 >= s2 >= s3`.
    pub fn violation(&self, s: [f64; 3]) -> f64 {
        (0..PLANES).map(|p| self.excess(p, s)).fold(f64::NEG_INFINITY, f64::max)
    }

    #[inline(always)]
    fn excess(&self, p: usize, s: [f64; 3]) -> f64 {
        let (a, b) = (1.0 + self.sin_phi, 1.0 - self.sin_phi);
        match p {
            0 => a * s[0] - b * s[2] - self.k,
            1 => a * s[0] - b * s[1] - self.k,
            2 => a * s[1] - b * s[2] - self.k,
            t => s[t - 3] - self.tensile,
        }
    }

    /// How far inside the surface `sigma` (Voigt, tension positive) is, in
    /// stress (Pa): `-max(m . s - k)` over the main plane and the cut-off on
    /// `s1`, which bound the other four planes. Negative outside. A change
    /// `ds` of the stress changes the main plane's value by at most
    /// `(1 + sin phi) + (1 - sin phi) = 2` times its spectral norm (Weyl: no
    /// principal value moves more than that norm) and the cut-off's by at
    /// most once: `sigma + ds` is inside while `2 |ds| < margin`.
    pub fn margin(&self, sigma: &[f64; 6]) -> f64 {
        self.margin_of(principal_values(sigma))
    }

    /// [`Self::margin`] from the principal values `s` (descending), for a
    /// batch whose values came from [`principal_lanes`].
    #[inline(always)]
    pub fn margin_of(&self, s: [f64; 3]) -> f64 {
        -self.excess(0, s).max(s[0] - self.tensile)
    }

    /// A cheap sufficient test that `sigma` (Voigt, tension positive) is
    /// inside the surface, from its invariants: with `p` the mean stress and
    /// `q = sqrt(J2)`, `s1 - s3 <= 2 q`, `|s2 - p| <= q / sqrt(3)` and
    /// `s1 <= p + 2 q / sqrt(3)` bound the main plane and the cut-off:
    /// inside if `(2 + sin phi / sqrt 3) q < k - 2 p sin phi` and
    /// `2 q / sqrt 3 < T - p`, tested squared (no square root or division
    /// on the hot path; a filter only: what it lets through the exact test
    /// below would return unchanged too).
    #[inline(always)]
    fn surely_elastic(&self, sigma: &[f64; 6]) -> bool {
        const THIRD: f64 = 1.0 / 3.0;
        const FRAC_1_SQRT_3: f64 = 0.577_350_269_189_625_8;
        let p = (sigma[0] + sigma[1] + sigma[2]) * THIRD;
        let d = [sigma[0] - p, sigma[1] - p, sigma[2] - p];
        let j2 = 0.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
            + sigma[3] * sigma[3]
            + sigma[4] * sigma[4]
            + sigma[5] * sigma[5];
        let a = 2.0 + self.sin_phi * FRAC_1_SQRT_3;
        let shear = self.k - 2.0 * p * self.sin_phi;
        let tension = self.tensile - p;
        shear > 0.0 && tension > 0.0 && a * a * j2 < shear * shear && 4.0 * THIRD * j2 < tension * tension
    }

    /// The return onto the main plane alone (the active set `[0]`, by far
    /// the most frequent), in closed form: `s = s* - dg D n` with
    /// `dg = (m . s* - k) / (m . D n)`. The same return as
    /// `return_to(.., &[0], ..)`. If the result violates another plane (an
    /// edge, the apex or the cut-off is active), the error names the edge
    /// to try first: the shear plane the result violates more (2: it left
    /// the sextant across `s1 = s2`, 1: across `s2 = s3`; de Souza Neto's
    /// Box 8.5 picks the edge the same way).
    #[inline(always)]
    fn main_plane_return(&self, lame: Lame, s: [f64; 3], excess: f64, tol: f64) -> Result<[f64; 3], usize> {
        let (dn, denom) = self.main_plane_flow(lame);
        if !(denom > 0.0) {
            return Err(1);
        }
        let r = main_plane_point(s, excess, dn, denom);
        match self.admissible_off_main(r, tol) {
            true => Ok(r),
            false if self.excess(2, r) > self.excess(1, r) => Err(2),
            false => Err(1),
        }
    }

    /// The main plane's flow through the elasticity, `D n` (`D` =
    /// `lambda + 2 mu` on the diagonal, `lambda` off it), and `m . D n`.
    #[inline(always)]
    fn main_plane_flow(&self, lame: Lame) -> ([f64; 3], f64) {
        let Lame { lambda, mu } = lame;
        let (sf, sp) = (self.sin_phi, self.sin_psi);
        let (n1, n3) = (1.0 + sp, -(1.0 - sp));
        let dn =
            [(lambda + 2.0 * mu) * n1 + lambda * n3, lambda * n1 + lambda * n3, lambda * n1 + (lambda + 2.0 * mu) * n3];
        (dn, (1.0 + sf) * dn[0] - (1.0 - sf) * dn[2])
    }

    /// Whether `r` violates none of the planes but the main one by more
    /// than `tol`; branch-free.
    #[inline(always)]
    fn admissible_off_main(&self, r: [f64; 3], tol: f64) -> bool {
        (1..PLANES).fold(true, |ok, p| ok & (self.excess(p, r) <= tol))
    }

    /// The tolerance of a return from the principal values `values`:
    /// `1e-12` of the largest of them, `k` and the cut-off. The cut-off is
    /// infinite without one (phi = 0 and no `tensile`): it does not set the
    /// scale then, or every trial would pass as elastic.
    #[inline(always)]
    fn tolerance(&self, values: [f64; 3]) -> f64 {
        let cut = if self.tensile.is_finite() { self.tensile.abs() } else { 0.0 };
        let scale = values.iter().fold(self.k.abs().max(cut), |a, v| a.max(v.abs()));
        1e-12 * scale.max(f64::MIN_POSITIVE)
    }

    /// The return mapping's common cases for the first `n` tetrahedra of a
    /// cell at once, branch-free so that the loop over them vectorizes,
    /// from the lanes of their trial stresses `sigma` and of their principal
    /// values `values` ([`principal_lanes`]): which are inside the surface,
    /// and which return onto the main plane alone with three principal
    /// values apart (the spectral update's general case), with their
    /// stresses ([`CommonReturns`]). For both, this is what
    /// [`Self::return_map_with`] gives, bit for bit: the same kernels, the
    /// same operations in the same order. The others (edges, tension, the
    /// apex, two equal principal values) are the caller's, by
    /// [`Self::return_map_with`].
    #[inline(always)]
    pub fn common_returns(&self, lame: Lame, sigma: &Lanes<6>, values: &Lanes<3>, n: usize) -> CommonReturns {
        let n = n.min(MAX_TETS);
        let mut out =
            CommonReturns { stress: [[0.0; MAX_TETS]; 6], elastic: [false; MAX_TETS], main: [false; MAX_TETS] };
        let (mut tol, mut excess) = ([0.0; MAX_TETS], [0.0; MAX_TETS]);
        let mut outside = false;
        for t in 0..n {
            let v = [values[0][t], values[1][t], values[2][t]];
            (tol[t], excess[t]) = (self.tolerance(v), self.excess(0, v));
            out.elastic[t] = excess[t].max(v[0] - self.tensile) <= tol[t];
            outside |= !out.elastic[t];
        }
        if !outside {
            return out;
        }
        let (dn, denom) = self.main_plane_flow(lame);
        for t in 0..n {
            let s = six(|i| sigma[i][t]);
            let v = [values[0][t], values[1][t], values[2][t]];
            let r = main_plane_point(v, excess[t], dn, denom);
            let (general, returned) = spectral_general(&s, v, r);
            out.main[t] =
                !out.elastic[t] & (excess[t] > tol[t]) & (denom > 0.0) & self.admissible_off_main(r, tol[t]) & general;
            for i in 0..6 {
                out.stress[i][t] = returned[i];
            }
        }
        out
    }

    /// The return onto the main plane and shear plane `q` (1: the edge
    /// `s2 = s3`, 2: the edge `s1 = s2`) together, the active set `[0, q]`,
    /// in closed form (Cramer's rule on the 2 x 2 system of the module
    /// documentation): None if a multiplier is negative or the result
    /// violates another plane. Equal to `return_to(.., &[0, q], ..)` to
    /// rounding.
    #[inline(always)]
    fn edge_return(&self, lame: Lame, s: [f64; 3], q: usize, tol: f64) -> Option<[f64; 3]> {
        let Lame { lambda, mu } = lame;
        let (m0, _, n0) = self.plane(0);
        let (mq, _, nq) = self.plane(q);
        // D n = lambda tr(n) + 2 mu n.
        let dn = |n: [f64; 3]| {
            let t = lambda * (n[0] + n[1] + n[2]);
            [t + 2.0 * mu * n[0], t + 2.0 * mu * n[1], t + 2.0 * mu * n[2]]
        };
        let (d0, dq) = (dn(n0), dn(nq));
        let (a00, a01, a10, a11) = (dot3(m0, d0), dot3(m0, dq), dot3(mq, d0), dot3(mq, dq));
        let (r0, r1) = (self.excess(0, s), self.excess(q, s));
        let det = a00 * a11 - a01 * a10;
        if !(det.abs() > 1e-12 * a00.abs().max(a11.abs()).powi(2)) {
            return None;
        }
        let g = [(r0 * a11 - a01 * r1) / det, (a00 * r1 - a10 * r0) / det];
        let largest = g[0].abs().max(g[1].abs());
        if g.iter().any(|&x| x < -1e-12 * largest) {
            return None;
        }
        let r = [
            s[0] - g[0] * d0[0] - g[1] * dq[0],
            s[1] - g[0] * d0[1] - g[1] * dq[1],
            s[2] - g[0] * d0[2] - g[1] * dq[2],
        ];
        let admissible = (1..PLANES).filter(|&p| p != q).all(|p| self.excess(p, r) <= tol);
        admissible.then_some(r)
    }

    /// The return mapping: the stress (Voigt xx yy zz yz xz xy, Pa, tension
    /// positive) on or inside the surface for the elastic trial stress
    /// `trial`, and what it did. See the module documentation.
    pub fn return_map(&self, lame: Lame, trial: [f64; 6]) -> ([f64; 6], Yield) {
        if self.surely_elastic(&trial) {
            return (trial, Yield::Elastic);
        }
        self.return_from(lame, trial, principal_values(&trial))
    }

    /// [`Self::return_map`] given the trial's principal values `values`
    /// (from [`principal_lanes`], as a cell's pass computes them for all
    /// its tetrahedra at once): the same stress and flag, bit for bit. With
    /// the values at hand the invariant filter has nothing left to save, and
    /// it is skipped: in the paper slope's strength reduction it cleared 1.8 %
    /// of the tetrahedra of the cells that made a full pass (their screens
    /// keep the clearly elastic cells out), for 6 % of the pass's time.
    #[inline(always)]
    pub fn return_map_with(&self, lame: Lame, trial: [f64; 6], values: [f64; 3]) -> ([f64; 6], Yield) {
        self.return_from(lame, trial, values)
    }

    /// The return mapping past the invariant filter, from the trial's
    /// principal values `values`.
    #[inline(always)]
    fn return_from(&self, lame: Lame, trial: [f64; 6], values: [f64; 3]) -> ([f64; 6], Yield) {
        let tol = self.tolerance(values);
        // With s1 >= s2 >= s3 the main plane and the cut-off on s1 bound the
        // other four: the largest violation is one of these two.
        let main = self.excess(0, values);
        if main.max(values[0] - self.tensile) <= tol {
            return (trial, Yield::Elastic);
        }
        let mut edges = [1, 2];
        if main > tol {
            match self.main_plane_return(lame, values, main, tol) {
                Ok(r) => return (spectral_update(&trial, values, r), Yield::Shear),
                Err(first) => edges = [first, 3 - first],
            }
        }
        // Below the cut-off the general search's sets [0] and [3] decline,
        // and it tries the two edges next: in closed form here, the edge
        // the main-plane return pointed to first. The old order's stress
        // either way while the two never both answer (checked, not proven:
        // `at_most_one_edge_answers_and_the_main_plane_points_to_it`).
        if values[0] <= self.tensile {
            for q in edges {
                if let Some(r) = self.edge_return(lame, values, q, tol) {
                    return (spectral_update(&trial, values, r), Yield::Shear);
                }
            }
        }
        self.return_general(lame, trial, values, tol)
    }

    /// The return onto a tension plane or the apex, the general search
    /// over [`ACTIVE_SETS`]. Not inlined, unlike the frequent part above
    /// (the main plane, about 78 % of the yielding tetrahedra on the paper
    /// slope's strength reduction, and the edges, 19 %): the hot kernels of
    /// the plastic pass are `#[inline(always)]` into
    /// [`super::plastic::plastic_element_force`], 1.15x faster than as
    /// calls (references/performance.md, "2026-12-06 (eleventh)"), and this
    /// rare part would only swell it.
    #[inline(never)]
    fn return_general(&self, lame: Lame, trial: [f64; 6], values: [f64; 3], tol: f64) -> ([f64; 6], Yield) {
        let d = principal_elasticity(lame);
        let planes = [0, 1, 2, 3, 4, 5].map(|p| {
            let (m, k, n) = self.plane(p);
            Plane { m, k, dn: mat_vec(&d, n), excess: dot3(m, values) - k }
        });
        for set in ACTIVE_SETS {
            if let Some((r, tension)) = return_to(&planes, set, values, tol) {
                let kind = if tension { Yield::Tension } else { Yield::Shear };
                return (spectral_update(&trial, values, r), kind);
            }
        }
        // No set of at most three planes returns the stress: a degenerate
        // surface (c = 0 and phi = 0). The stress-free state is on it.
        ([0.0; 6], Yield::Shear)
    }
}

/// One plane of the surface for one return: `m . s <= k`, its flow
/// direction through the elasticity `D n`, and the trial's excess `m . s* - k`.
#[derive(Clone, Copy)]
struct Plane {
    m: [f64; 3],
    k: f64,
    dn: [f64; 3],
    excess: f64,
}

/// The return of `s` onto the planes `set`, if its multipliers are
/// non-negative and the result is admissible; `true` if a tension plane is
/// active.
fn return_to(planes: &[Plane; PLANES], set: &[usize], s: [f64; 3], tol: f64) -> Option<([f64; 3], bool)> {
    // No cut-off (an infinite plane) is never active.
    if set.iter().any(|&p| !planes[p].k.is_finite()) {
        return None;
    }
    let n = set.len();
    let mut a = [[0.0; 3]; 3];
    let mut rhs = [0.0; 3];
    for (i, &p) in set.iter().enumerate() {
        rhs[i] = planes[p].excess;
        for (j, &q) in set.iter().enumerate() {
            a[i][j] = dot3(planes[p].m, planes[q].dn);
        }
    }
    let dg = solve(&a, &rhs, n)?;
    let largest = dg[..n].iter().fold(0.0, |m: f64, v| m.max(v.abs()));
    if dg[..n].iter().any(|&g| g < -1e-12 * largest) {
        return None;
    }
    let mut r = s;
    for (g, &q) in dg[..n].iter().zip(set) {
        for i in 0..3 {
            r[i] -= g * planes[q].dn[i];
        }
    }
    if (0..PLANES).any(|p| !set.contains(&p) && dot3(planes[p].m, r) - planes[p].k > tol) {
        return None;
    }
    Some((r, set.iter().any(|&p| p >= 3)))
}

/// The candidate active sets in the order they are tried: one plane, two,
/// three (0-2 the shear planes, 3-5 tension on `s1`, `s2`, `s3`).
const ACTIVE_SETS: &[&[usize]] = &[
    &[0],
    &[3],
    &[0, 1],
    &[0, 2],
    &[0, 3],
    &[3, 4],
    &[0, 1, 2],
    &[0, 2, 3],
    &[0, 3, 4],
    &[0, 1, 3],
    &[3, 4, 5],
    &[0, 1, 4],
    &[2, 3, 4],
    &[0, 4, 5],
    &[1, 3, 4],
    &[0, 3, 5],
];

/// `D` in principal axes: `K + 4G/3` on the diagonal, `K - 2G/3` off it.
fn principal_elasticity(lame: Lame) -> Matrix3<f64> {
    let Lame { lambda, mu } = lame;
    Matrix3::from_fn(|i, j| if i == j { lambda + 2.0 * mu } else { lambda })
}

/// `[f(0), .., f(5)]`, written out: the hot kernels' arrays without
/// `array::map`'s closure calls, which the compiler does not always inline.
#[inline(always)]
pub fn six(f: impl Fn(usize) -> f64) -> [f64; 6] {
    [f(0), f(1), f(2), f(3), f(4), f(5)]
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn mat_vec(d: &Matrix3<f64>, v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| d[(i, 0)] * v[0] + d[(i, 1)] * v[1] + d[(i, 2)] * v[2])
}

/// Solves the leading `n x n` block of `a x = b` (n <= 3) by Gaussian
/// elimination with partial pivoting; None if it is singular.
fn solve(a: &[[f64; 3]; 3], b: &[f64; 3], n: usize) -> Option<[f64; 3]> {
    let mut m = *a;
    let mut x = *b;
    let scale = (0..n).flat_map(|i| (0..n).map(move |j| (i, j))).fold(0.0, |s: f64, (i, j)| s.max(a[i][j].abs()));
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))?;
        if m[p][c].abs() <= 1e-12 * scale {
            return None;
        }
        m.swap(c, p);
        x.swap(c, p);
        for r in c + 1..n {
            let f = m[r][c] / m[c][c];
            for k in c..n {
                m[r][k] -= f * m[c][k];
            }
            x[r] -= f * x[c];
        }
    }
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| m[c][k] * x[k]).sum();
        x[c] = (x[c] - s) / m[c][c];
    }
    Some(x)
}

/// Strain of a stress increment through the elastic compliance (Voigt,
/// engineering shear): `eps = D^-1 sigma`.
#[inline(always)]
pub fn compliance(lame: Lame, sigma: [f64; 6]) -> [f64; 6] {
    let Lame { lambda, mu } = lame;
    let tr = sigma[0] + sigma[1] + sigma[2];
    // D^-1 sigma = (sigma - lambda / (3 lambda + 2 mu) tr I) / (2 mu).
    let a = lambda / (3.0 * lambda + 2.0 * mu);
    let (at, g2) = (a * tr, 2.0 * mu);
    [(sigma[0] - at) / g2, (sigma[1] - at) / g2, (sigma[2] - at) / g2, sigma[3] / mu, sigma[4] / mu, sigma[5] / mu]
}
