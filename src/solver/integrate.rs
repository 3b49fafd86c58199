//! Eq. 13-14: damping force and the explicit update, per component:
//! `a = (f_ext - f_int - f_d) / m`, `v += a dt`, `u += v dt`; fixed components
//! keep `v = 0`. With node-block masses `a = (M^-1 f)_k` (viscous and
//! kinetic damping only). Returns the largest unbalanced force on a free
//! component (the residual used for convergence) and the kinetic energy.

use crate::physics::damping::local_damping;
use crate::solver::block_mass::BlockMass;
use crate::solver::params::DampingKind;

/// The inertial masses of the update.
#[derive(Clone, Copy)]
pub enum Masses<'a> {
    /// One mass per node.
    Lumped(&'a [f64]),
    /// One dense block per mesh node ([`BlockMass`]), with the
    /// accelerations `M^-1 (f_ext - f_int)` of this step already computed
    /// ([`BlockMass::accelerations`]).
    Block(&'a BlockMass, &'a [f64]),
}

/// What one update measured.
#[derive(Debug, Clone, Copy, Default)]
pub struct UpdateReport {
    /// `max |f_ext - f_int|` over free components (N).
    pub max_unbalanced: f64,
    /// `sum m v^2 / 2` with the inertial masses (J); with block masses, with
    /// their diagonal (an estimate, used to detect non-finite state).
    pub kinetic: f64,
}

/// Everything the update reads that does not change in a step.
pub struct UpdateInput<'a> {
    pub mass: Masses<'a>,
    pub fixed: &'a [bool],
    pub f_ext: &'a [f64],
    pub f_int: &'a [f64],
    pub dt: f64,
    pub damping: DampingKind,
    pub alpha: f64,
    /// Viscous damping coefficient `c` (1/s), used by `Viscous`.
    pub c: f64,
    /// The spring dashpots' forces per component, if any: they drive the
    /// update (`a = M^-1 (f_ext - f_int - f_dash)`) but are not part of the
    /// unbalanced force the ratio measures (a mass creeping at the
    /// dashpots' terminal velocity is not at rest).
    pub f_dash: Option<&'a [f64]>,
}

/// The forces that accelerate node `i`'s three components: the unbalanced
/// force `f_ext - f_int` less the dashpots' (0 where a component is fixed).
#[inline]
pub fn driving_node(fixed: &[bool], f_ext: &[f64], f_int: &[f64], f_dash: Option<&[f64]>, i: usize) -> [f64; 3] {
    let k = 3 * i;
    let (fixed, f_ext, f_int) = (&fixed[k..k + 3], &f_ext[k..k + 3], &f_int[k..k + 3]);
    match f_dash {
        Some(d) => {
            let d = &d[k..k + 3];
            std::array::from_fn(|a| if fixed[a] { 0.0 } else { f_ext[a] - f_int[a] - d[a] })
        }
        None => std::array::from_fn(|a| if fixed[a] { 0.0 } else { f_ext[a] - f_int[a] }),
    }
}

/// Components per parallel chunk of the update (a multiple of 3).
pub const CHUNK: usize = 3 * 1024;

/// The update over all components, in parallel chunks of [`CHUNK`]. Each
/// chunk's partial report goes to its own slot of `partial` (one per chunk,
/// owned by the solver), and the slots are combined in order, so the result
/// does not depend on the number of threads.
pub fn integrate(inp: &UpdateInput, u: &mut [f64], v: &mut [f64], partial: &mut [UpdateReport]) -> UpdateReport {
    use rayon::prelude::*;
    u.par_chunks_mut(CHUNK).zip(v.par_chunks_mut(CHUNK)).zip(partial.par_iter_mut()).enumerate().for_each(
        |(c, ((u, v), rep))| {
            *rep = integrate_range(inp, c * CHUNK, u, v);
        },
    );
    partial.iter().fold(UpdateReport::default(), |a, b| UpdateReport {
        max_unbalanced: a.max_unbalanced.max(b.max_unbalanced),
        kinetic: a.kinetic + b.kinetic,
    })
}

/// The update of the nodes `first / 3..(first + u.len()) / 3`.
fn integrate_range(inp: &UpdateInput, first: usize, u: &mut [f64], v: &mut [f64]) -> UpdateReport {
    let mut rep = UpdateReport::default();
    let dt = inp.dt;
    let h = 0.5 * inp.c * dt;
    for (j, (u, v)) in u.chunks_exact_mut(3).zip(v.chunks_exact_mut(3)).enumerate() {
        let i = first / 3 + j;
        let k = 3 * i;
        let (fixed, f_ext, f_int) = (&inp.fixed[k..k + 3], &inp.f_ext[k..k + 3], &inp.f_int[k..k + 3]);
        // Per component: the mass and the velocity change `dt M^-1 f`.
        let (m, dv) = match inp.mass {
            Masses::Lumped(m) => {
                let f = driving_node(inp.fixed, inp.f_ext, inp.f_int, inp.f_dash, i);
                ([m[i]; 3], f.map(|f| dt * f / m[i]))
            }
            Masses::Block(b, acc) => (b.diagonal[i], b.acceleration(acc, i).map(|a| dt * a)),
        };
        for d in 0..3 {
            if fixed[d] {
                v[d] = 0.0;
                continue;
            }
            let f = f_ext[d] - f_int[d];
            rep.max_unbalanced = rep.max_unbalanced.max(f.abs());
            v[d] = match inp.damping {
                DampingKind::Local => {
                    let f = driving_node(inp.fixed, inp.f_ext, inp.f_int, inp.f_dash, i)[d];
                    v[d] + dt * (f - local_damping(inp.alpha, f, v[d])) / m[d]
                }
                DampingKind::Viscous => ((1.0 - h) * v[d] + dv[d]) / (1.0 + h),
                DampingKind::Kinetic => v[d] + dv[d],
            };
            u[d] += dt * v[d];
            rep.kinetic += 0.5 * m[d] * v[d] * v[d];
        }
    }
    rep
}

#[cfg(test)]
mod tests {
    use super::{integrate, Masses, UpdateInput, UpdateReport, CHUNK};
    use crate::solver::params::DampingKind;

    /// The dashpots' forces accelerate the nodes, but the unbalanced force
    /// the ratio is measured on is `f_ext - f_int` alone: a node moving at
    /// its dashpot's terminal velocity (the two forces cancel) keeps its
    /// velocity and still reports its unbalanced force.
    #[test]
    fn dashpot_forces_drive_the_update_but_are_not_unbalanced_force() {
        let (mass, fixed) = (vec![2.0], vec![false; 3]);
        let (f_ext, f_int) = (vec![3.0, 0.0, -1.0], vec![1.0, 0.0, 0.0]);
        let f_dash = vec![2.0, 0.0, 0.0];
        let step = |f_dash: Option<&[f64]>, damping: DampingKind| {
            let inp = UpdateInput {
                mass: Masses::Lumped(&mass),
                fixed: &fixed,
                f_ext: &f_ext,
                f_int: &f_int,
                dt: 1.0,
                damping,
                alpha: 0.8,
                c: 0.0,
                f_dash,
            };
            let (mut u, mut v) = (vec![0.0; 3], vec![0.5, 0.0, 0.0]);
            let mut partial = vec![UpdateReport::default(); 3usize.div_ceil(CHUNK)];
            let rep = integrate(&inp, &mut u, &mut v, &mut partial);
            (rep.max_unbalanced, v)
        };
        for damping in [DampingKind::Viscous, DampingKind::Kinetic, DampingKind::Local] {
            let (unbalanced, v) = step(Some(&f_dash), damping);
            assert_eq!(unbalanced, 2.0, "{damping:?}: |f_ext - f_int| on x, the dashpot left out");
            if damping != DampingKind::Local {
                assert_eq!(v[0], 0.5, "{damping:?}: the dashpot cancels the unbalanced force on x");
                assert_eq!(v[2], -0.5, "{damping:?}: z has no dashpot force");
            }
            let (unbalanced, v) = step(None, damping);
            assert_eq!(unbalanced, 2.0);
            if damping != DampingKind::Local {
                assert_eq!(v[0], 1.5, "{damping:?}: without dashpots x accelerates by 2 / 2");
            }
        }
    }
}
