//! Richardson extrapolation of a value computed on meshes of decreasing size
//! `h_1 > h_2 (> h_3)` (Richardson 1911; Roache 1998, "Verification and
//! Validation in Computational Science and Engineering", ch. 5; Celik et al.
//! 2008, J. Fluids Eng. 130, 078001, the procedure for non-constant
//! refinement ratios; references/srm.md, "Discretisation error").
//!
//! With `f(h) = f_0 + C h^p`, three meshes give the observed order `p` as the
//! root of
//!
//! ```text
//! (f_2 - f_1) / (f_3 - f_2) = (h_1^p - h_2^p) / (h_2^p - h_3^p)
//! ```
//!
//! (for a constant ratio `r = h_1 / h_2 = h_2 / h_3`: `p = ln((f_2 - f_1) /
//! (f_3 - f_2)) / ln r`); two meshes, or three whose changes do not shrink
//! monotonically, leave `p` to be assumed. Then, from the two finest meshes,
//!
//! ```text
//! f_0 = f_fine + (f_fine - f_prev) / (r^p - 1),   r = h_prev / h_fine
//! ```
//!
//! and Roache's grid convergence index bounds the error of `f_0` itself:
//! `U = F_s |f_fine - f_0| + d (1 + 2 / (r^p - 1))`, with the safety factor
//! `F_s` = 1.25 for an observed order and 3 for an assumed one, and `d` the
//! resolution of each value (a factor of safety is known to half its
//! bracket: the second term carries it through the formula for `f_0`). An
//! order is observed only where both changes exceed `2 d` (else they are
//! the brackets' noise) and the root lies in [`ORDER_RANGE`].

use serde::Serialize;

/// The order assumed when it cannot be observed: first order, the largest
/// correction of the usual orders (for a value that converges monotonically
/// it puts `f_0` furthest from the coarse meshes).
pub const ASSUMED_ORDER: f64 = 1.0;
/// Roache's safety factor of the grid convergence index with an observed order.
pub const SAFETY_OBSERVED: f64 = 1.25;
/// The same with an assumed order (two meshes).
pub const SAFETY_ASSUMED: f64 = 3.0;
/// The range an observed order is searched in: a root outside it is not
/// taken for an order (the changes are noise, or the meshes are not in the
/// asymptotic range). Linear elements converge at first to second order.
pub const ORDER_RANGE: [f64; 2] = [0.5, 2.0];

/// How the order of an extrapolation was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum OrderSource {
    /// From three meshes.
    Observed,
    /// The assumed order ([`ASSUMED_ORDER`] for a factor of safety): two meshes.
    AssumedTwoMeshes,
    /// The assumed order: three meshes whose changes do not shrink
    /// monotonically, are not resolved (a change within twice the values'
    /// resolution) or give an order outside [`ORDER_RANGE`]; the two finest
    /// extrapolate.
    AssumedNotObserved,
}

/// A Richardson extrapolation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Extrapolation {
    /// `f_0`, the value at `h -> 0`.
    pub value: f64,
    /// The order `p`.
    pub order: f64,
    pub order_source: OrderSource,
    /// Roache's grid convergence index `U = F_s |f_fine - f_0|` (the
    /// uncertainty of `f_0`, in the value's unit).
    pub uncertainty: f64,
}

/// The extrapolation of `f[i]` computed at mesh sizes `h[i]` (any unit,
/// decreasing: coarse first), each value known to `resolution` (its unit);
/// None with fewer than two meshes, sizes that do not decrease, or a
/// non-finite value.
pub fn extrapolate(h: &[f64], f: &[f64], resolution: f64) -> Option<Extrapolation> {
    extrapolate_assuming(h, f, resolution, ASSUMED_ORDER)
}

/// [`extrapolate`] with `assumed` the order taken where none is observed
/// (the elastic displacements of linear elements: 2).
pub fn extrapolate_assuming(h: &[f64], f: &[f64], resolution: f64, assumed: f64) -> Option<Extrapolation> {
    let n = h.len();
    if n < 2 || n != f.len() || !h.windows(2).all(|w| w[1] < w[0] && w[1] > 0.0) || !f.iter().all(|v| v.is_finite()) {
        return None;
    }
    let observed = (n >= 3).then(|| observed_order(&h[n - 3..], &f[n - 3..], resolution)).flatten();
    let (order, order_source) = match observed {
        Some(p) => (p, OrderSource::Observed),
        None if n >= 3 => (assumed, OrderSource::AssumedNotObserved),
        None => (assumed, OrderSource::AssumedTwoMeshes),
    };
    let (fine, prev) = (f[n - 1], f[n - 2]);
    let r = h[n - 2] / h[n - 1];
    let gain = 1.0 / (r.powf(order) - 1.0);
    let value = fine + (fine - prev) * gain;
    let safety = if order_source == OrderSource::Observed { SAFETY_OBSERVED } else { SAFETY_ASSUMED };
    let uncertainty = safety * (fine - value).abs() + resolution * (1.0 + 2.0 * gain);
    Some(Extrapolation { value, order, order_source, uncertainty })
}

/// The observed order of three meshes whose values are known to
/// `resolution` (None: the changes do not shrink monotonically, one is
/// within `2 resolution`, or the root lies outside [`ORDER_RANGE`]).
pub fn observed_order(h: &[f64], f: &[f64], resolution: f64) -> Option<f64> {
    let (e21, e32) = (f[1] - f[0], f[2] - f[1]);
    let resolved = |e: f64| e != 0.0 && e.abs() > 2.0 * resolution;
    if !resolved(e21) || !resolved(e32) || e21.signum() != e32.signum() || e32.abs() >= e21.abs() {
        return None;
    }
    let target = e21 / e32;
    // g(p) = (h1^p - h2^p) / (h2^p - h3^p) grows with p for h1 > h2 > h3.
    let g = |p: f64| (h[0].powf(p) - h[1].powf(p)) / (h[1].powf(p) - h[2].powf(p)) - target;
    let [mut lo, mut hi] = ORDER_RANGE;
    // A rounding band at the ends: an order of exactly 2 is in range.
    let band = 1e-12 * target.abs();
    if g(lo) > band || g(hi) < -band {
        return None;
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if g(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f = 1 + 0.3 h^2 on h = 1, 1/2, 1/4: order 2 and f_0 = 1 exactly.
    #[test]
    fn a_second_order_sequence_extrapolates_to_its_limit() {
        let h = [1.0, 0.5, 0.25];
        let f: Vec<f64> = h.iter().map(|h| 1.0 + 0.3 * h * h).collect();
        let e = extrapolate(&h, &f, 0.0).unwrap();
        assert_eq!(e.order_source, OrderSource::Observed);
        assert!((e.order - 2.0).abs() < 1e-9, "{e:?}");
        assert!((e.value - 1.0).abs() < 1e-12, "{e:?}");
        assert!((e.uncertainty - 1.25 * 0.3 / 16.0).abs() < 1e-9, "{e:?}");
        // A resolution of 1e-3 adds 1e-3 (1 + 2 / 3) to the uncertainty.
        let d = extrapolate(&h, &f, 1e-3).unwrap();
        assert!((d.uncertainty - e.uncertainty - 1e-3 * (1.0 + 2.0 / 3.0)).abs() < 1e-9, "{d:?}");
    }

    /// A non-constant ratio (h = 1, 2/3, 1/2, as refine 1, 1.5, 2): the
    /// order of f = 2 - 0.1 h^1.5 is found again.
    #[test]
    fn a_non_constant_ratio_finds_the_order() {
        let h = [1.0, 2.0 / 3.0, 0.5];
        let f: Vec<f64> = h.iter().map(|h: &f64| 2.0 - 0.1 * h.powf(1.5)).collect();
        let e = extrapolate(&h, &f, 0.0).unwrap();
        assert!((e.order - 1.5).abs() < 1e-9, "{e:?}");
        assert!((e.value - 2.0).abs() < 1e-12, "{e:?}");
    }

    /// Two meshes assume first order: f_0 = f_2 + (f_2 - f_1) / (r - 1).
    #[test]
    fn two_meshes_assume_first_order() {
        let e = extrapolate(&[1.0, 0.5], &[1.59, 1.548], 0.0).unwrap();
        assert_eq!(e.order_source, OrderSource::AssumedTwoMeshes);
        assert!((e.value - 1.506).abs() < 1e-12, "{e:?}");
        assert!((e.uncertainty - 3.0 * 0.042).abs() < 1e-12, "{e:?}");
    }

    /// Changes that grow or change sign are no order: the two finest meshes
    /// extrapolate at the assumed order, and say so.
    #[test]
    fn an_oscillating_sequence_falls_back_to_the_assumed_order() {
        let e = extrapolate(&[1.0, 0.5, 0.25], &[1.40, 1.38, 1.39], 0.0).unwrap();
        assert_eq!(e.order_source, OrderSource::AssumedNotObserved);
        assert!((e.value - 1.40).abs() < 1e-12, "{e:?}");
        assert!(extrapolate(&[1.0, 1.0], &[1.0, 2.0], 0.0).is_none());
        assert!(extrapolate(&[1.0], &[1.0], 0.0).is_none());
    }

    /// Griffiths & Lane's hexahedra (refine 1, 1.5, 2; brackets 0.0025 wide,
    /// references/srm.md): the last change, 0.0024, is within the brackets'
    /// 0.0025, so its "order" 5.4 is the brackets' noise: first order is
    /// assumed on the two finest meshes.
    #[test]
    fn a_change_within_the_brackets_observes_no_order() {
        let (h, f) = ([1.0, 2.0 / 3.0, 0.5], [1.3928, 1.3684, 1.3660]);
        assert!(observed_order(&h, &f, 0.0).is_none(), "5.4 lies outside the range of an order");
        let e = extrapolate(&h, &f, 0.00125).unwrap();
        assert_eq!(e.order_source, OrderSource::AssumedNotObserved);
        assert!((e.value - (1.3660 - 0.0024 * 3.0)).abs() < 1e-9, "{e:?}");
    }
}
