//! Damping for dynamic relaxation (paper eq. 13 uses a damping matrix `C`).
//!
//! - local (non-viscous, Cundall): `f_d = alpha |f_unbal| sign(v)` per
//!   component, independent of the frequency;
//! - viscous, mass proportional: `f_d = c m v`, with `c = 2 omega` where
//!   `omega^2 = (u . K u) / (u . M u)` is the Rayleigh quotient of the current
//!   displacement (adaptive, Underwood 1983); with plastic blocks in the
//!   failure phase, `omega^2 = (du . df) / (du . M du)` of the last step's
//!   increment instead ([`tangent_numerator`]): the tangent stiffness along
//!   the motion, which softens as a trial nears its critical factor while
//!   the secant `u . K u` stays near the elastic one;
//! - kinetic: no force; velocities are zeroed at each peak of kinetic energy;
//! - spring dashpots (failure phase with plastic blocks or every mesh face
//!   breakable, on top of the viscous damping): `f_d = beta K_spring
//!   (v_b - v_a)` per spring, stiffness proportional, so it damps the stiff
//!   relative modes of the node copies that mass-proportional damping
//!   leaves undamped ([`spring_dashpot`], [`dashpot_beta`]).

/// Local damping force for one component.
#[inline]
pub fn local_damping(alpha: f64, f_unbal: f64, v: f64) -> f64 {
    if v > 0.0 {
        alpha * f_unbal.abs()
    } else if v < 0.0 {
        -alpha * f_unbal.abs()
    } else {
        0.0
    }
}

/// Rayleigh-quotient estimate of the lowest angular frequency squared
/// (rad^2/s^2) from displacements `u`, internal forces `f_int = K u` and the
/// (possibly scaled) nodal masses.
pub fn rayleigh_omega2(u: &[f64], f_int: &[f64], mass: &[f64]) -> f64 {
    let mut num = 0.0;
    let mut den = 0.0;
    for (i, m) in mass.iter().enumerate() {
        for d in 0..3 {
            let k = 3 * i + d;
            num += u[k] * f_int[k];
            den += m * u[k] * u[k];
        }
    }
    rayleigh_omega2_with(num, den)
}

/// The tangent Rayleigh quotient's numerator `du . df` of one step, from
/// the displacements and internal forces after it (`u`, `f`) and before it
/// (`u0`, `f0`); also writes `du = u - u0` (for `du . M du`). Its quotient
/// by `du . M du` ([`rayleigh_omega2_with`]) is the square of the lowest
/// frequency of the tangent operator once the motion has settled into the
/// slowest mode: Underwood's local-stiffness estimate (1983), taken along
/// the increment rather than per component.
pub fn tangent_numerator(u: &[f64], f: &[f64], u0: &[f64], f0: &[f64], du: &mut [f64]) -> f64 {
    let mut num = 0.0;
    for ((((d, u), f), u0), f0) in du.iter_mut().zip(u).zip(f).zip(u0).zip(f0) {
        *d = u - u0;
        num += *d * (f - f0);
    }
    num
}

/// The Rayleigh quotient `(u . K u) / (u . M u)` from its two parts (0 if
/// either is not positive).
pub fn rayleigh_omega2_with(u_k_u: f64, u_m_u: f64) -> f64 {
    if u_m_u > 0.0 && u_k_u > 0.0 {
        u_k_u / u_m_u
    } else {
        0.0
    }
}

/// The fraction of the stability allowance the spring dashpots take
/// ([`dashpot_beta`]).
pub const DASHPOT_SHARE: f64 = 0.5;

/// The spring dashpots' `beta` (in steps `dt`) for the step's `safety`.
///
/// Central differences with a stiffness-proportional damping `beta K`
/// evaluated at the half-step velocity are stable for a mode of
/// `Omega = omega dt` while `Omega^2 (1 + 2 beta / dt) < 4` (the
/// characteristic polynomial `z^2 + (Omega^2 (1 + beta / dt) - 2) z +
/// (1 - Omega^2 beta / dt) = 0`, Jury's conditions); for matrices, while
/// `M > dt^2 K / 4 + dt C / 2`. The masses keep `M >= K / (4 safety^2)`
/// (every mode at `Omega <= 2 safety`), and the dashpots' `C = beta K_springs`
/// is at most `beta K`, so `beta / dt < (1 / safety^2 - 1) / 2` is stable: the
/// dashpots take [`DASHPOT_SHARE`] of that (0.059 at safety 0.9), which
/// damps the highest modes by about 10 % per step and the slow modes that
/// decide convergence by a fraction `beta omega / 2` of critical, next to
/// nothing.
pub fn dashpot_beta(safety: f64, dt: f64) -> f64 {
    DASHPOT_SHARE * 0.5 * (1.0 / (safety * safety) - 1.0) * dt
}

/// A spring's dashpot force on its node `a` (node `b` gets the opposite):
/// `beta (K_n (n . w) n + K_s (w - (n . w) n))` for the relative velocity
/// `w = v_b - v_a` (N). It uses the intact stiffnesses whatever the
/// spring's state (the bound of [`dashpot_beta`] holds for every state),
/// and vanishes at rest: it changes the path of the relaxation, not its
/// equilibria.
#[inline]
pub fn spring_dashpot(beta: f64, kn: f64, ks: f64, n: [f64; 3], w: [f64; 3]) -> [f64; 3] {
    let wn = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
    [0, 1, 2].map(|i| beta * (kn * wn * n[i] + ks * (w[i] - wn * n[i])))
}

#[cfg(test)]
mod tests {
    use super::{dashpot_beta, rayleigh_omega2, rayleigh_omega2_with, spring_dashpot, tangent_numerator};

    #[test]
    fn the_tangent_quotient_sees_a_softened_mode_that_the_secant_does_not() {
        // One node of unit mass on a softening spring, f = k u - a u^3 per
        // component, moved a little further along (1, 1, 1) near u = 0.5.
        let (k, a) = (4.0, 5.0);
        let f = |u: &[f64]| -> Vec<f64> { u.iter().map(|&x| k * x - a * x * x * x).collect() };
        let (u0, u) = (vec![0.5; 3], vec![0.5 + 1e-6; 3]);
        let mut du = vec![0.0; 3];
        let num = tangent_numerator(&u, &f(&u), &u0, &f(&u0), &mut du);
        let tangent = rayleigh_omega2_with(num, du.iter().map(|d| d * d).sum());
        let secant = rayleigh_omega2(&u, &f(&u), &[1.0]);
        // k - 3 a u^2 = 0.25 against the secant's k - a u^2 = 2.75.
        assert!((tangent - 0.25).abs() < 1e-4, "{tangent}");
        assert!((secant - 2.75).abs() < 1e-4, "{secant}");
        assert_eq!(du, vec![1e-6 + 0.5 - 0.5; 3]);
    }

    /// The largest root modulus of `z^2 + (W (1 + b) - 2) z + (1 - b W) = 0`,
    /// `W = Omega^2`: one mode of central differences with a
    /// stiffness-proportional damping `b = beta / dt` at the half-step velocity.
    fn amplification(omega: f64, b: f64) -> f64 {
        let w = omega * omega;
        let (p, q) = (w * (1.0 + b) - 2.0, 1.0 - b * w);
        let disc = p * p - 4.0 * q;
        if disc >= 0.0 {
            let s = disc.sqrt();
            ((-p + s) / 2.0).abs().max(((-p - s) / 2.0).abs())
        } else {
            q.sqrt()
        }
    }

    /// The recurrence itself, stepped: `x_{n+1} = 2 x_n - x_{n-1} - W x_n - b W (x_n - x_{n-1})`.
    fn stepped(omega: f64, b: f64, steps: usize) -> f64 {
        let w = omega * omega;
        let (mut prev, mut x) = (1.0f64, 0.9f64);
        for _ in 0..steps {
            let next = 2.0 * x - prev - w * x - b * w * (x - prev);
            (prev, x) = (x, next);
        }
        x.abs().max(prev.abs())
    }

    #[test]
    fn the_dashpots_keep_every_mode_the_masses_allow_stable_and_damp_the_highest() {
        for safety in [0.5, 0.8, 0.9, 0.95] {
            let b = dashpot_beta(safety, 1.0);
            let limit = 0.5 * (1.0 / (safety * safety) - 1.0);
            assert!((b - 0.5 * limit).abs() < 1e-15, "half the allowance at safety {safety}");
            // Every mode up to the masses' bound Omega = 2 safety decays.
            for k in 1..=100 {
                let omega = 2.0 * safety * k as f64 / 100.0;
                assert!(amplification(omega, b) < 1.0, "safety {safety}, Omega {omega}");
            }
            // The highest mode loses a share each step (about 10 % at 0.9) ...
            let top = amplification(2.0 * safety, b);
            assert!(top < 1.0 - 0.02, "safety {safety}: {top}");
            assert!(stepped(2.0 * safety, b, 200) < 1e-2, "safety {safety}");
            // ... and beyond the allowance the top mode grows.
            assert!(amplification(2.0 * safety, 1.05 * limit) > 1.0, "safety {safety}");
            assert!(stepped(2.0 * safety, 1.05 * limit, 2000) > 1.0, "safety {safety}");
        }
    }

    #[test]
    fn a_dashpot_resists_relative_motion_only_along_its_spring_stiffnesses() {
        let n = [0.0, 0.6, 0.8];
        // Normal relative velocity: K_n along n; tangential: K_s.
        let f = spring_dashpot(0.5, 10.0, 2.0, n, [0.0, 0.6, 0.8]);
        assert!((0..3).all(|i| (f[i] - 5.0 * n[i]).abs() < 1e-12), "{f:?}");
        let f = spring_dashpot(0.5, 10.0, 2.0, n, [1.0, 0.0, 0.0]);
        assert!((f[0] - 1.0).abs() < 1e-12 && f[1].abs() < 1e-12 && f[2].abs() < 1e-12, "{f:?}");
        // No relative motion, no force.
        assert_eq!(spring_dashpot(0.5, 10.0, 2.0, n, [0.0; 3]), [0.0; 3]);
    }
}
