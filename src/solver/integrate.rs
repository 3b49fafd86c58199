//! Eq. 13-14: damping force and the explicit update, per component:
//! `a = (f_ext - f_int - f_d) / m`, `v += a dt`, `u += v dt`; fixed components
//! keep `v = 0`. Returns the largest unbalanced force on a free component
//! (the residual used for convergence) and the kinetic energy.

use crate::physics::damping::local_damping;
use crate::solver::params::DampingKind;

/// What one update measured.
#[derive(Debug, Clone, Copy, Default)]
pub struct UpdateReport {
    /// `max |f_ext - f_int|` over free components (N).
    pub max_unbalanced: f64,
    /// `sum m v^2 / 2` with the inertial masses (J).
    pub kinetic: f64,
}

/// Everything the update reads that does not change in a step.
pub struct UpdateInput<'a> {
    pub mass: &'a [f64],
    pub fixed: &'a [bool],
    pub f_ext: &'a [f64],
    pub f_int: &'a [f64],
    pub dt: f64,
    pub damping: DampingKind,
    pub alpha: f64,
    /// Viscous damping coefficient `c` (1/s), used by `Viscous`.
    pub c: f64,
}

pub fn integrate(inp: &UpdateInput, u: &mut [f64], v: &mut [f64]) -> UpdateReport {
    let mut rep = UpdateReport::default();
    let dt = inp.dt;
    for k in 0..u.len() {
        if inp.fixed[k] {
            v[k] = 0.0;
            continue;
        }
        let m = inp.mass[k / 3];
        let f = inp.f_ext[k] - inp.f_int[k];
        rep.max_unbalanced = rep.max_unbalanced.max(f.abs());
        v[k] = match inp.damping {
            DampingKind::Local => v[k] + dt * (f - local_damping(inp.alpha, f, v[k])) / m,
            DampingKind::Viscous => {
                let h = 0.5 * inp.c * dt;
                ((1.0 - h) * v[k] + dt * f / m) / (1.0 + h)
            }
            DampingKind::Kinetic => v[k] + dt * f / m,
        };
        u[k] += dt * v[k];
        rep.kinetic += 0.5 * m * v[k] * v[k];
    }
    rep
}
