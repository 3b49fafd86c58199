//! The stress with new principal values on the old principal directions,
//! by the spectral projectors (no eigenvectors).

use super::six;

/// The stress whose principal values are `new` on the principal directions
/// of `sigma` (principal values `old`), without the directions themselves:
/// `sigma + sum_i (new_i - old_i) P_i` with the spectral projectors from
/// Sylvester's formula, `P_1 = (A - s_2 I)(A - s_3 I) / ((s_1 - s_2)(s_1 - s_3))`
/// and the like, `P_2 = I - P_1 - P_3`. Where two principal values coincide
/// (within 1e-6 of the spread) only their pair's projector is defined, and
/// the pair takes its mean change (the return keeps a pair equal).
#[inline(always)]
pub(super) fn spectral_update(sigma: &[f64; 6], old: [f64; 3], new: [f64; 3]) -> [f64; 6] {
    let (general, updated) = spectral_general(sigma, old, new);
    if general {
        return updated;
    }
    let d = [new[0] - old[0], new[1] - old[1], new[2] - old[2]];
    let spread = old[0] - old[2];
    let scale = old[0].abs().max(old[2].abs()).max(f64::MIN_POSITIVE);
    let mut out = *sigma;
    let mut add = |w: f64, m: [f64; 6]| {
        for i in 0..6 {
            out[i] += w * m[i];
        }
    };
    if spread <= 1e-12 * scale {
        add((d[0] + d[1] + d[2]) / 3.0, I);
        return out;
    }
    let lin = |a: f64, w: f64| six(|i| (sigma[i] - a * I[i]) / w);
    if old[0] - old[1] <= 1e-6 * spread {
        // P_12 = (A - s_3 I) / (s_1 - s_3), P_3 = I - P_12.
        add(d[2], I);
        add(0.5 * (d[0] + d[1]) - d[2], lin(old[2], spread));
    } else {
        // s_2 = s_3: P_1 = (A - s_3 I) / (s_1 - s_3), P_23 = I - P_1.
        add(0.5 * (d[1] + d[2]), I);
        add(d[0] - 0.5 * (d[1] + d[2]), lin(old[2], spread));
    }
    out
}

/// The unit tensor in Voigt order.
pub(super) const I: [f64; 6] = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0];

/// [`spectral_update`]'s general case, three principal values apart:
/// `sigma + d_2 I + (d_1 - d_2) P_1 + (d_3 - d_2) P_3`, `d_i = new_i - old_i`,
/// computed whatever the values (branch-free, for
/// [`MohrCoulomb::common_returns`]), and whether it is the case.
#[inline(always)]
pub(super) fn spectral_general(sigma: &[f64; 6], old: [f64; 3], new: [f64; 3]) -> (bool, [f64; 6]) {
    let d = [new[0] - old[0], new[1] - old[1], new[2] - old[2]];
    let spread = old[0] - old[2];
    let scale = old[0].abs().max(old[2].abs()).max(f64::MIN_POSITIVE);
    let (g12, g23) = (old[0] - old[1], old[1] - old[2]);
    let general = !(spread <= 1e-12 * scale) & !(g12 <= 1e-6 * spread) & !(g23 <= 1e-6 * spread);
    // A^2 of the symmetric sigma (Voigt xx yy zz yz xz xy).
    let [xx, yy, zz, yz, xz, xy] = *sigma;
    let a2 = [
        xx * xx + xy * xy + xz * xz,
        xy * xy + yy * yy + yz * yz,
        xz * xz + yz * yz + zz * zz,
        xy * xz + yy * yz + yz * zz,
        xx * xz + xy * yz + xz * zz,
        xx * xy + xy * yy + xz * yz,
    ];
    // (A - a I)(A - b I) / w.
    let quad = |a: f64, b: f64, w: f64| six(|i| (a2[i] - (a + b) * sigma[i] + a * b * I[i]) / w);
    let (p1, p3) = (quad(old[1], old[2], g12 * spread), quad(old[0], old[1], spread * g23));
    let out = six(|i| ((sigma[i] + d[1] * I[i]) + (d[0] - d[1]) * p1[i]) + (d[2] - d[1]) * p3[i]);
    (general, out)
}
