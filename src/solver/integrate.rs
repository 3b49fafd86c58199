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

/// Components per parallel chunk of the update (a multiple of 3).
pub const CHUNK: usize = 3 * 1024;

/// The update over all components, in parallel chunks of [`CHUNK`]. Each
/// chunk's partial report goes to its own slot of `partial` (one per chunk,
/// owned by the solver), and the slots are combined in order, so the result
/// does not depend on the number of threads.
pub fn integrate(inp: &UpdateInput, u: &mut [f64], v: &mut [f64], partial: &mut [UpdateReport]) -> UpdateReport {
    use rayon::prelude::*;
    u.par_chunks_mut(CHUNK).zip(v.par_chunks_mut(CHUNK)).zip(partial.par_iter_mut()).enumerate().for_each(|(c, ((u, v), rep))| {
        *rep = integrate_range(inp, c * CHUNK, u, v);
    });
    partial.iter().fold(UpdateReport::default(), |a, b| UpdateReport { max_unbalanced: a.max_unbalanced.max(b.max_unbalanced), kinetic: a.kinetic + b.kinetic })
}

/// The update of the components `first..first + u.len()`.
fn integrate_range(inp: &UpdateInput, first: usize, u: &mut [f64], v: &mut [f64]) -> UpdateReport {
    let mut rep = UpdateReport::default();
    let dt = inp.dt;
    for (j, (u, v)) in u.iter_mut().zip(v.iter_mut()).enumerate() {
        let k = first + j;
        if inp.fixed[k] {
            *v = 0.0;
            continue;
        }
        let m = inp.mass[k / 3];
        let f = inp.f_ext[k] - inp.f_int[k];
        rep.max_unbalanced = rep.max_unbalanced.max(f.abs());
        *v = match inp.damping {
            DampingKind::Local => *v + dt * (f - local_damping(inp.alpha, f, *v)) / m,
            DampingKind::Viscous => {
                let h = 0.5 * inp.c * dt;
                ((1.0 - h) * *v + dt * f / m) / (1.0 + h)
            }
            DampingKind::Kinetic => *v + dt * f / m,
        };
        *u += dt * *v;
        rep.kinetic += 0.5 * m * *v * *v;
    }
    rep
}
