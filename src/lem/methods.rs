//! Methods of slices on filled [`Slices`] (equations in the module docs of
//! [`crate::lem`]). Kernels use math names: `W`, `alpha`, `l`, `c`, `tan_phi`,
//! `F` (factor of safety), `theta` (Spencer's interslice inclination).

use serde::Serialize;

use super::geometry::{fill_slices, Limits, Reject, Slices};
use super::{Circle, LemSection, Method};

/// Bishop: stop when the update `|dF| <= BISHOP_TOL F` (Newton, see [`bishop`]).
const BISHOP_TOL: f64 = 1e-10;
const MAX_ITER: usize = 200;
/// Spencer: Newton stops when both updates are below this (F relative, theta rad).
const SPENCER_TOL: f64 = 1e-11;

/// Ordinary (Fellenius): `F = sum(c l + (W cos(alpha) - u l) tan_phi) / (sum(W sin(alpha)) + H (zc - z_H) / r)`.
pub(crate) fn ordinary(s: &Slices) -> Option<f64> {
    let f = s.resist_ordinary / s.drive;
    (f.is_finite() && f > 0.0).then_some(f)
}

/// Bishop simplified: the root of
/// `g(F) = F D - sum[(c b + (W - u b) tan_phi) / m_alpha(F)]`, `b = l cos(alpha)`,
/// `D = sum(W sin(alpha)) + H (zc - z_H) / r` (the crack water force's moment over `r`),
/// `m_alpha = cos(alpha) + sin(alpha) tan_phi / F`, by Halley's method (Newton
/// with the second derivative, cubic convergence: 3.0 passes per grid circle
/// against Newton's 3.8) from `f0` (the ordinary F), stopping when
/// `|dF| <= BISHOP_TOL F`. Where the step is unusable (`g' <= 0`, or a step
/// to `F <= 0`) the step is the
/// classical fixed-point one, `F <- sum[...] / sum(W sin(alpha))`. `None` if
/// `m_alpha <= 0` for some slice at some iterate, or no convergence in
/// `MAX_ITER` steps.
pub(crate) fn bishop(s: &Slices, f0: f64) -> Option<f64> {
    bishop_counted(s, f0).map(|(f, _)| f)
}

/// [`bishop`] and the number of passes over the slices it took.
pub(crate) fn bishop_counted(s: &Slices, f0: f64) -> Option<(f64, usize)> {
    let mut f = f0;
    let drive = s.drive;
    for pass in 1..=MAX_ITER {
        let inv_f = 1.0 / f;
        // resist = sum a / m, slope = sum a b / m^2 = F^2 d(resist)/dF.
        // a = c b + (W - u b) tan_phi, b = sin(alpha) tan_phi (from fill_slices).
        // Four interleaved partial sums (lane k takes slices k, k + 4, ...),
        // added in a fixed order: the loop vectorizes, and the result
        // depends on nothing but the slices.
        const L: usize = 4;
        let (mut resist, mut slope, mut curve, mut min_m) = ([0.0; L], [0.0; L], [0.0; L], [f64::INFINITY; L]);
        let mut lane = |k: usize, a: f64, b: f64, cos_a: f64| {
            let m_alpha = cos_a + b * inv_f;
            min_m[k] = if m_alpha < min_m[k] { m_alpha } else { min_m[k] };
            let inv_m = 1.0 / m_alpha;
            let q = a * inv_m;
            let qb = q * b * inv_m;
            resist[k] += q;
            slope[k] += qb;
            curve[k] += qb * b * inv_m;
        };
        let (a, b, cos_a) = (s.bishop_a.chunks_exact(L), s.bishop_b.chunks_exact(L), s.cos_a.chunks_exact(L));
        let rest = (a.remainder(), b.remainder(), cos_a.remainder());
        for ((a, b), cos_a) in a.zip(b).zip(cos_a) {
            for k in 0..L {
                lane(k, a[k], b[k], cos_a[k]);
            }
        }
        for k in 0..rest.0.len() {
            lane(k, rest.0[k], rest.1[k], rest.2[k]);
        }
        let sum = |v: [f64; L]| (v[0] + v[1]) + (v[2] + v[3]);
        // A NaN m_alpha is not caught here (it never compares below the
        // minimum); it makes the sums NaN, and the fixed-point test below
        // returns None.
        if min_m.iter().any(|&m| m <= 0.0) {
            return None;
        }
        let (resist, slope, curve) = (sum(resist), sum(slope), sum(curve));
        let fixed_point = resist / drive;
        if !(fixed_point.is_finite() && fixed_point > 0.0) {
            return None;
        }
        // g = F D - resist, g' = D - slope / F^2, g'' = 2 (slope F - curve) / F^4:
        // Halley's step (cubic convergence).
        let dg = drive - slope * inv_f * inv_f;
        let g = f * drive - resist;
        let ddg = 2.0 * (slope * f - curve) * (inv_f * inv_f) * (inv_f * inv_f);
        let newton = f - 2.0 * g * dg / (2.0 * dg * dg - g * ddg);
        let f_new = if dg > 0.0 && newton > 0.0 && newton.is_finite() { newton } else { fixed_point };
        if (f_new - f).abs() <= BISHOP_TOL * f_new {
            return Some((f_new, pass));
        }
        f = f_new;
    }
    None
}

/// Spencer's residuals: `[sum Q, sum Q cos(alpha - theta) - K]` and their
/// Jacobian in `(F, theta)`, `Q = (R / F - D) / m` with the slices' `R`, `D`
/// and `K` (effective stress, crack water force: `Slices::spencer_r`). `None`
/// if some `m <= 0`.
fn spencer_residuals(s: &Slices, f: f64, theta: f64) -> Option<([f64; 2], [[f64; 2]; 2])> {
    let (st, ct) = theta.sin_cos();
    let (mut r, mut j) = ([0.0, -s.moment_k], [[0.0; 2]; 2]);
    for i in 0..s.len() {
        let (sa, ca, t) = (s.sin_a[i], s.cos_a[i], s.tan_phi[i]);
        let cd = ca * ct + sa * st; // cos(alpha - theta)
        let sd = sa * ct - ca * st; // sin(alpha - theta)
        let m = cd + sd * t / f;
        if m <= 0.0 {
            return None;
        }
        let (big_r, d) = (s.spencer_r[i], s.spencer_d[i]);
        let q = (big_r / f - d) / m;
        let dm_df = -sd * t / (f * f);
        let dm_dtheta = sd - cd * t / f;
        let dq_df = (-big_r / (f * f) - q * dm_df) / m;
        let dq_dtheta = -q * dm_dtheta / m;
        r[0] += q;
        r[1] += q * cd;
        j[0][0] += dq_df;
        j[0][1] += dq_dtheta;
        j[1][0] += dq_df * cd;
        j[1][1] += dq_dtheta * cd + q * sd;
    }
    Some((r, j))
}

/// Spencer `(F, theta)`: damped Newton from `(f_bishop, 0)`, else bracketing.
pub(crate) fn spencer(s: &Slices, f_bishop: f64) -> Option<(f64, f64)> {
    spencer_newton(s, f_bishop).or_else(|| spencer_bracketing(s, f_bishop))
}

fn spencer_newton(s: &Slices, f0: f64) -> Option<(f64, f64)> {
    let scale: f64 = s.w.iter().sum::<f64>().max(f64::MIN_POSITIVE);
    let norm = |r: [f64; 2]| (r[0] * r[0] + r[1] * r[1]).sqrt() / scale;
    let (mut f, mut theta) = (f0, 0.0f64);
    let (mut r, mut j) = spencer_residuals(s, f, theta)?;
    for _ in 0..60 {
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let mut df = -(j[1][1] * r[0] - j[0][1] * r[1]) / det;
        let mut dt = -(-j[1][0] * r[0] + j[0][0] * r[1]) / det;
        // Damping: at most half of F and 0.2 rad per step; then backtrack.
        let cap = (df.abs() / (0.5 * f)).max(dt.abs() / 0.2).max(1.0);
        (df, dt) = (df / cap, dt / cap);
        let n0 = norm(r);
        let mut accepted = None;
        for _ in 0..30 {
            let (fn_, tn) = (f + df, theta + dt);
            if fn_ > 0.0 && tn.abs() < 1.5 {
                if let Some((rn, jn)) = spencer_residuals(s, fn_, tn) {
                    if norm(rn) < n0 || n0 < 1e-14 {
                        accepted = Some((fn_, tn, rn, jn));
                        break;
                    }
                }
            }
            (df, dt) = (0.5 * df, 0.5 * dt);
        }
        let (fn_, tn, rn, jn) = accepted?;
        let done = (fn_ - f).abs() <= SPENCER_TOL * fn_ && (tn - theta).abs() <= SPENCER_TOL;
        (f, theta, r, j) = (fn_, tn, rn, jn);
        if done || norm(r) < 1e-15 {
            return Some((f, theta));
        }
    }
    None
}

/// F from one equilibrium equation at fixed theta (`moment`: weights
/// `cos(alpha - theta)` and right-hand side `K`), by fixed-point iteration
/// `F = sum(R w/m) / (sum(D w/m) + K)`.
fn spencer_fs_at(s: &Slices, theta: f64, moment: bool, f0: f64) -> Option<f64> {
    let (st, ct) = theta.sin_cos();
    let mut f = f0;
    for _ in 0..MAX_ITER {
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..s.len() {
            let (sa, ca, t) = (s.sin_a[i], s.cos_a[i], s.tan_phi[i]);
            let cd = ca * ct + sa * st;
            let m = cd + (sa * ct - ca * st) * t / f;
            if m <= 0.0 {
                return None;
            }
            let w = if moment { cd } else { 1.0 };
            num += s.spencer_r[i] * w / m;
            den += s.spencer_d[i] * w / m;
        }
        let f_new = num / (den + if moment { s.moment_k } else { 0.0 });
        if !(f_new.is_finite() && f_new > 0.0) {
            return None;
        }
        if (f_new - f).abs() <= BISHOP_TOL * f_new {
            return Some(f_new);
        }
        f = f_new;
    }
    None
}

/// Scan theta outward from 0 in 2 degree steps up to +-60 degrees for a sign
/// change of `F_force - F_moment`, then bisect to 1e-12 rad.
fn spencer_bracketing(s: &Slices, f0: f64) -> Option<(f64, f64)> {
    let gap = |theta: f64| -> Option<(f64, f64)> {
        let fm = spencer_fs_at(s, theta, true, f0)?;
        let ff = spencer_fs_at(s, theta, false, fm)?;
        Some((ff - fm, fm))
    };
    let step = 2f64.to_radians();
    let (g0, _) = gap(0.0)?;
    for dir in [1.0, -1.0] {
        let (mut a, mut ga) = (0.0, g0);
        for k in 1..=30 {
            let b = dir * k as f64 * step;
            let Some((gb, _)) = gap(b) else { break };
            if ga.signum() != gb.signum() {
                let (mut lo, mut hi, mut glo) = (a, b, ga);
                for _ in 0..80 {
                    let mid = 0.5 * (lo + hi);
                    let (gm, _) = gap(mid)?;
                    if gm.signum() == glo.signum() {
                        (lo, glo) = (mid, gm);
                    } else {
                        hi = mid;
                    }
                    if (hi - lo).abs() < 1e-12 {
                        break;
                    }
                }
                let theta = 0.5 * (lo + hi);
                return gap(theta).map(|(_, fm)| (fm, theta));
            }
            (a, ga) = (b, gb);
        }
    }
    None
}

/// All three methods on one circle (user frame), no minimum depth or width.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CircleFs {
    pub ordinary: Option<f64>,
    pub bishop: Option<f64>,
    pub spencer: Option<f64>,
    pub spencer_theta_deg: Option<f64>,
    pub entry: [f64; 2],
    pub exit: [f64; 2],
}

impl CircleFs {
    pub fn get(&self, m: Method) -> Option<f64> {
        match m {
            Method::Ordinary => self.ordinary,
            Method::Bishop => self.bishop,
            Method::Spencer => self.spencer,
        }
    }
}

/// Every method's FS on a given circle with `n` slices.
pub fn evaluate_circle(section: &LemSection, circle: Circle, n: usize) -> Result<CircleFs, Reject> {
    let f = &section.frame;
    let c = Circle { xc: f.x(circle.xc), ..circle };
    let mut s = Slices::with_capacity(n);
    fill_slices(f, c, n.max(1), Limits::NONE, &mut s)?;
    let o = ordinary(&s);
    let b = o.and_then(|o| bishop(&s, o));
    let sp = b.and_then(|b| spencer(&s, b));
    let point = |x: f64| [f.x(x), section.ground_z(f.x(x))];
    Ok(CircleFs {
        ordinary: o,
        bishop: b,
        spencer: sp.map(|p| p.0),
        spencer_theta_deg: sp.map(|p| p.1.to_degrees()),
        entry: point(s.x_entry),
        exit: point(s.x_exit),
    })
}
