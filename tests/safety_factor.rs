//! Eq. 19-22 on states with known answers (references/safety.md): the infinite
//! slope, a hydrostatic state, and the sign-segment rule.

use cdem::analysis::{safety_factors, sign_segments, traction_from_stress, SurfacePoint};

/// Stress of an infinite dry slope of angle beta at depth d below the surface,
/// in x-z (slope descending toward -x): on planes parallel to the surface,
/// sigma_n = gamma d cos^2 beta and the down-slope shear gamma d sin beta cos beta
/// (Duncan & Wright, Soil Strength and Slope Stability, 2nd ed., ch. 6).
/// Returns (Voigt stress, n out of the mass, t down-slope).
fn infinite_slope(gamma: f64, d: f64, beta: f64) -> ([f64; 6], [f64; 3], [f64; 3]) {
    // Surface rises toward +x; the mass lies above the plane, so n (out of the
    // mass) points down into the ground; t points down-slope (-x, -z).
    let (sb, cb) = beta.sin_cos();
    let n = [sb, 0.0, -cb];
    let t = [-cb, 0.0, -sb];
    let (sig_n, tau) = (gamma * d * cb * cb, gamma * d * sb * cb);
    // sigma n = traction on the mass = -sig_n n - tau t (it holds the mass up-slope).
    // Build sigma = -sig_n n n^T - tau (n t^T + t n^T) - q t t^T (q arbitrary: it
    // acts on planes normal to t and does not enter the traction on n).
    let q = 0.4 * gamma * d;
    let mut s = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            s[i][j] = -sig_n * n[i] * n[j] - tau * (n[i] * t[j] + t[i] * n[j]) - q * t[i] * t[j];
        }
    }
    ([s[0][0], s[1][1], s[2][2], s[1][2], s[0][2], s[0][1]], n, t)
}

#[test]
fn infinite_slope_factor_matches_the_textbook_formula() {
    let (gamma, d, beta, c, phi) = (20.6e3, 5.0, 29.1f64.to_radians(), 16e3, 18f64.to_radians());
    let (sigma, n, t) = infinite_slope(gamma, d, beta);
    let (sig_n, tau) = traction_from_stress(sigma, n, t);
    assert!((sig_n - gamma * d * beta.cos().powi(2)).abs() < 1e-9 * gamma * d);
    assert!((tau - gamma * d * beta.sin() * beta.cos()).abs() < 1e-9 * gamma * d);
    let pts: Vec<SurfacePoint> =
        (0..10).map(|i| SurfacePoint { s: i as f64, area: 1.0 + i as f64, sigma_n: sig_n, tau }).collect();
    let f = safety_factors(&pts, c, phi.tan());
    let textbook = c / (gamma * d * beta.sin() * beta.cos()) + phi.tan() / beta.tan();
    assert!((f.k - textbook).abs() < 1e-12 * textbook, "{} vs {textbook}", f.k);
    assert!(f.k_i.iter().all(|&k| (k - textbook).abs() < 1e-12 * textbook));
}

#[test]
fn hydrostatic_stress_has_no_shear_and_full_normal_compression() {
    let p = 3.0e5;
    let n = [0.6, 0.0, -0.8];
    let t = [-0.8, 0.0, -0.6];
    let (sig_n, tau) = traction_from_stress([-p, -p, -p, 0.0, 0.0, 0.0], n, t);
    assert!((sig_n - p).abs() < 1e-9 && tau.abs() < 1e-9);
}

#[test]
fn sign_segments_merge_runs_shorter_than_the_minimum() {
    // Points 1 m apart: + + + - + + - - - - + + + +, with one isolated "-".
    let s: Vec<f64> = (0..14).map(|i| i as f64).collect();
    let k: Vec<f64> = [1., 1., 1., -1., 1., 1., -1., -1., -1., -1., 1., 1., 1., 1.].to_vec();
    let seg = sign_segments(&s, &k, 2.0);
    let signs: Vec<i8> = seg.iter().map(|g| g.sign).collect();
    assert_eq!(signs, vec![1, -1, 1]);
    assert_eq!((seg[0].s0, seg[2].s1), (0.0, 13.0), "segments cover the surface");
    for w in seg.windows(2) {
        assert_eq!(w[0].s1, w[1].s0, "segments are contiguous");
    }
    // Without a minimum every run counts.
    assert_eq!(sign_segments(&s, &k, 0.0).len(), 5);
}
