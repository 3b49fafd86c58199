//! Stress-based safety factor on a slip surface (paper eq. 19-22).
//!
//! At points `i` of the surface, with area `A_i`, unit normal `n` out of the
//! sliding mass and unit tangent `t` in the sliding direction (down-slope,
//! toward the toe):
//!
//! - normal compression `sigma_n = -n . (sigma n)` (positive in compression);
//! - driving shear `tau = -t . (sigma n)`: `sigma n` is the traction the
//!   ground exerts on the mass, so its component against `t` is the shear the
//!   mass exerts on its base in the sliding direction (positive where the
//!   mass pushes down-slope). docs/method.md (section 2.10) writes `t . (sigma n)` "in the sliding
//!   direction"; this is that quantity with the sign that makes it positive
//!   when it drives sliding;
//! - resisting force `R_i = (sigma_n tan(phi) + c) A_i` (eq. 19), driving
//!   force `D_i = tau A_i` (eq. 20);
//! - `K = sum R_i / sum D_i` (eq. 21), `K_i = R_i / D_i` (eq. 22).
//!
//! `K_i < 0` where the local shear acts up-slope (the base there pushes the
//! mass down-slope instead of holding it).

use crate::mesh::shape::dot;

/// One sample of the slip surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfacePoint {
    /// Arc length from the toe (m).
    pub s: f64,
    /// Area represented (m^2).
    pub area: f64,
    /// Normal compression (Pa).
    pub sigma_n: f64,
    /// Driving shear (Pa), positive down-slope.
    pub tau: f64,
}

/// `(sigma_n, tau)` on a plane with normal `n` (out of the mass) and sliding
/// direction `t` from a stress (Voigt xx yy zz yz xz xy).
pub fn traction_from_stress(sigma: [f64; 6], n: [f64; 3], t: [f64; 3]) -> (f64, f64) {
    let [xx, yy, zz, yz, xz, xy] = sigma;
    let sn = [xx * n[0] + xy * n[1] + xz * n[2], xy * n[0] + yy * n[1] + yz * n[2], xz * n[0] + yz * n[1] + zz * n[2]];
    (-dot(n, sn), -dot(t, sn))
}

/// Eq. 21 and 22 on a set of points.
#[derive(Debug, Clone, PartialEq)]
pub struct SafetyFactors {
    /// `K = sum R_i / sum D_i`.
    pub k: f64,
    /// `K_i = R_i / D_i`, one per point.
    pub k_i: Vec<f64>,
    pub resisting: f64,
    pub driving: f64,
}

pub fn safety_factors(points: &[SurfacePoint], cohesion: f64, tan_phi: f64) -> SafetyFactors {
    safety_factors_with(points, |_, sigma_n| sigma_n * tan_phi + cohesion)
}

/// Eq. 21 and 22 with the shear strength `tau = strength(i, sigma_n)` (Pa)
/// of each point `i` at its normal stress: `c + sigma_n tan(phi)` of
/// Mohr-Coulomb, or a joint law's envelope
/// ([`crate::physics::joint::JointStrength::shear_strength`]), for a surface
/// through several materials.
pub fn safety_factors_with(points: &[SurfacePoint], strength: impl Fn(usize, f64) -> f64) -> SafetyFactors {
    let mut resisting = 0.0;
    let mut driving = 0.0;
    let k_i = points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let r = strength(i, p.sigma_n) * p.area;
            let d = p.tau * p.area;
            resisting += r;
            driving += d;
            r / d
        })
        .collect();
    SafetyFactors { k: resisting / driving, k_i, resisting, driving }
}

/// A maximal run of equal sign of K_i along the surface.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Segment {
    /// +1 or -1.
    pub sign: i8,
    /// Arc-length extent from the toe (m).
    pub s0: f64,
    pub s1: f64,
}

/// Sign segments of `k_i` at arc lengths `s` (sorted, toe to crest).
///
/// Minimum-length rule: a run shorter than `min_length` (m) is merged into its
/// neighbours (the shortest run first, repeatedly, until every run is at least
/// `min_length` or only one is left), so that isolated sign flips at single
/// points do not count as segments. Each point owns the interval halfway to its
/// neighbours.
pub fn sign_segments(s: &[f64], k_i: &[f64], min_length: f64) -> Vec<Segment> {
    let n = s.len().min(k_i.len());
    if n == 0 {
        return Vec::new();
    }
    let edge = |i: usize| -> f64 {
        if i == 0 {
            s[0]
        } else if i == n {
            s[n - 1]
        } else {
            0.5 * (s[i - 1] + s[i])
        }
    };
    let mut runs: Vec<Segment> = Vec::new();
    for i in 0..n {
        let sign = if k_i[i] < 0.0 { -1 } else { 1 };
        match runs.last_mut() {
            Some(r) if r.sign == sign => r.s1 = edge(i + 1),
            _ => runs.push(Segment { sign, s0: edge(i), s1: edge(i + 1) }),
        }
    }
    loop {
        let shortest = (0..runs.len())
            .filter(|&i| runs[i].s1 - runs[i].s0 < min_length)
            .min_by(|&a, &b| (runs[a].s1 - runs[a].s0).total_cmp(&(runs[b].s1 - runs[b].s0)));
        let Some(i) = shortest else { break };
        if runs.len() == 1 {
            break;
        }
        // Merge the short run into its neighbours: they take its extent.
        let r = runs.remove(i);
        if i > 0 && i < runs.len() {
            // Between two runs of the other sign: all three become one.
            runs[i - 1].s1 = runs[i].s1;
            runs.remove(i);
        } else if i > 0 {
            runs[i - 1].s1 = r.s1;
        } else {
            runs[0].s0 = r.s0;
        }
    }
    runs
}
