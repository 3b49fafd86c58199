//! Damping for dynamic relaxation (paper eq. 13 uses a damping matrix `C`).
//!
//! - local (non-viscous, Cundall): `f_d = alpha |f_unbal| sign(v)` per
//!   component, independent of the frequency;
//! - viscous, mass proportional: `f_d = c m v`, with `c = 2 omega` where
//!   `omega^2 = (u . K u) / (u . M u)` is the Rayleigh quotient of the current
//!   displacement (adaptive, Underwood 1983);
//! - kinetic: no force; velocities are zeroed at each peak of kinetic energy.

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

/// The Rayleigh quotient `(u . K u) / (u . M u)` from its two parts (0 if
/// either is not positive).
pub fn rayleigh_omega2_with(u_k_u: f64, u_m_u: f64) -> f64 {
    if u_m_u > 0.0 && u_k_u > 0.0 {
        u_k_u / u_m_u
    } else {
        0.0
    }
}
