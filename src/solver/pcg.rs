//! The elastic phase as a linear solve: preconditioned conjugate gradients
//! (`[solver] elastic = "pcg"`), beside dynamic relaxation.
//!
//! With intact springs (phase 1) the equilibrium `K u = f_ext` over the node
//! copies is linear, with `K` symmetric positive definite on the free
//! components (elements, eq. 11, and springs, eq. 15-16). `K p` is the same
//! matrix-free internal force as a step of dynamic relaxation
//! ([`super::forces`]). The preconditioner has two levels, added:
//!
//! `z = S r + P A_c^-1 P^T r`
//!
//! - the smoother `S = (B + D)^-1`, one dense block per mesh node over its
//!   copies ([`BlockMass`] at scale 1: the blocks the node-block masses of
//!   dynamic relaxation hold). It contains the stiff joint springs between
//!   the copies exactly, so the joints do not set the iteration count;
//! - the coarse correction on the continuous mesh ([`CoarseSpace`]): the
//!   Galerkin operator `A_c = P^T K P` (the elements assembled on the merged
//!   mesh) factored once. It removes the continuum's own ill-conditioning,
//!   which grows with the mesh (the auxiliary-space idea for discontinuous
//!   systems, Dobrev, Lazarov, Vassilevski & Zikatanov 2006).
//!
//! Fixed components: zero rows in both levels, and `p`, `r`, `z` stay zero
//! there. An iteration is one step of the history. The stop rules are those
//! of [`super::relax`] (tolerance, budget, caller; no sliding in phase 1),
//! with the same convergence measure: the ratio `max |f_ext - K u| /
//! max |f_ext|` over free components ([`super::unbalanced_ratio`]). The
//! ratio that stops the solve is the true one, from `K u` recomputed (the
//! recurrence's residual only proposes the stop). `p . K p <= 0` is
//! [`SolveError::NotPositiveDefiniteCg`], a non-finite value
//! [`SolveError::NonFinite`].
//!
//! Every dot product sums fixed chunks in order, so the iterates do not
//! depend on the number of threads.

use rayon::prelude::*;

use super::block_mass::BlockMass;
use super::coarse::CoarseSpace;
use super::relax::{Observer, RunReport, StepView, Stop, StopRules};
use super::{f_ext_max, forces, unbalanced_ratio, HistoryRow, State};
use crate::error::SolveError;
use crate::model::{Model, ELEMENT_SLOT};
use crate::physics::spring::SpringState;

/// Components per chunk of a dot product.
const CHUNK: usize = 4096;

/// The operator, the preconditioner and their scratch.
pub struct Pcg {
    smoother: BlockMass,
    coarse: CoarseSpace,
    /// The intact springs of the elastic phase.
    springs: SpringState,
    f_elem: Vec<f64>,
    f_spring: Vec<[f64; 3]>,
    slot_force: Vec<f64>,
    slot_acc: Vec<f64>,
    partial: Vec<f64>,
    f_ext_max: f64,
}

impl Pcg {
    /// Builds both levels: the node blocks and the factored coarse operator.
    pub fn new(model: &Model) -> Result<Self, SolveError> {
        let n = 3 * model.n_nodes();
        Ok(Self {
            smoother: BlockMass::new(model, 1.0)?,
            coarse: CoarseSpace::new(model)?,
            springs: SpringState::new(model.springs.len()),
            f_elem: vec![0.0; ELEMENT_SLOT * model.elements.len()],
            f_spring: vec![[0.0; 3]; model.springs.len()],
            slot_force: vec![0.0; n],
            slot_acc: vec![0.0; n],
            partial: vec![0.0; n.div_ceil(CHUNK)],
            f_ext_max: f_ext_max(model),
        })
    }

    /// Coarse unknowns (free components of the merged mesh).
    pub fn coarse_unknowns(&self) -> usize {
        self.coarse.len()
    }

    /// `out = K x` (all components; at fixed ones the reaction to `x`).
    fn apply(&mut self, model: &Model, x: &[f64], out: &mut [f64]) {
        forces::element_forces(model, x, &mut self.f_elem);
        forces::spring_forces(model, &self.springs, x, &mut self.f_spring);
        forces::gather(model, &self.f_elem, &self.f_spring, out);
    }

    /// `z = S r + P A_c^-1 P^T r` (`r` zero on fixed components, so is `z`).
    fn precondition(&mut self, r: &[f64], z: &mut [f64]) {
        self.smoother.accelerations(
            |i| [r[3 * i], r[3 * i + 1], r[3 * i + 2]],
            &mut self.slot_force,
            &mut self.slot_acc,
        );
        let (s, acc) = (&self.smoother, &self.slot_acc);
        z.par_chunks_mut(3).with_min_len(512).enumerate().for_each(|(i, z)| z.copy_from_slice(&s.acceleration(acc, i)));
        self.coarse.add_correction(r, z);
    }

    fn dot(&mut self, a: &[f64], b: &[f64]) -> f64 {
        self.partial
            .par_iter_mut()
            .zip(a.par_chunks(CHUNK).zip(b.par_chunks(CHUNK)))
            .for_each(|(p, (a, b))| *p = a.iter().zip(b).map(|(x, y)| x * y).sum());
        self.partial.iter().sum()
    }

    /// Solves `K u = f_ext` from `state.u` (usually zero) until a rule of
    /// `rules` fires; `state.u` and `state.f_int = K u` hold the result and
    /// `state.step` counts the iterations. `state.v` stays zero: the history's
    /// kinetic energy is 0.
    pub fn solve(
        &mut self,
        model: &Model,
        state: &mut State,
        rules: &StopRules,
        observer: &mut dyn Observer,
    ) -> Result<RunReport, SolveError> {
        let n = 3 * model.n_nodes();
        let fixed = &model.fixed;
        state.v.fill(0.0);
        let (mut r, mut z, mut q) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut f_int = std::mem::take(&mut state.f_int);
        let residual = |f_int: &[f64], r: &mut [f64]| {
            r.par_iter_mut().enumerate().for_each(|(k, r)| *r = if fixed[k] { 0.0 } else { model.f_ext[k] - f_int[k] });
        };
        self.apply(model, &state.u, &mut f_int);
        residual(&f_int, &mut r);
        let mut ratio = unbalanced_ratio(max_abs(&r), self.f_ext_max);
        let mut history = Vec::new();
        let first = state.step;
        let mut stop = (ratio < rules.tolerance).then_some(Stop::Converged);
        if stop.is_some() {
            state.f_int.clone_from(&f_int);
            history.push(HistoryRow::of(model, state, 0.0, ratio));
        }
        self.precondition(&r, &mut z);
        let mut p = z.clone();
        let mut rz = self.dot(&r, &z);
        while stop.is_none() {
            self.apply(model, &p, &mut q);
            let pq = self.dot(&p, &q);
            let step = state.step + 1;
            if !pq.is_finite() || !rz.is_finite() {
                return Err(non_finite(step, &q));
            }
            if pq <= 0.0 {
                return Err(SolveError::NotPositiveDefiniteCg { iteration: step - first, pkp: pq });
            }
            let alpha = rz / pq;
            let u = &mut state.u;
            u.par_iter_mut().zip(&p).for_each(|(u, p)| *u += alpha * p);
            f_int.par_iter_mut().zip(&q).for_each(|(f, q)| *f += alpha * q);
            r.par_iter_mut().zip(&q).enumerate().for_each(|(k, (r, q))| {
                if !fixed[k] {
                    *r -= alpha * q
                }
            });
            state.step = step;
            let steps = step - first;
            ratio = unbalanced_ratio(max_abs(&r), self.f_ext_max);
            if ratio.is_nan() {
                return Err(non_finite(step, &state.u));
            }
            let mut restart = false;
            if ratio < rules.tolerance {
                // The recurrence proposes the stop; the true residual decides.
                self.apply(model, &state.u, &mut f_int);
                residual(&f_int, &mut r);
                ratio = unbalanced_ratio(max_abs(&r), self.f_ext_max);
                restart = ratio >= rules.tolerance;
                stop = (!restart).then_some(Stop::Converged);
            }
            if stop.is_none() && steps >= rules.max_steps {
                stop = Some(Stop::Budget);
            }
            state.f_int.clone_from(&f_int);
            if state.step.is_multiple_of(rules.history_every) || stop == Some(Stop::Converged) {
                history.push(HistoryRow::of(model, state, 0.0, ratio));
            }
            let view = StepView { state, steps, ratio, kinetic: 0.0, kinetic_exact: Some(0.0), stop };
            if observer.step(&view).is_break() && stop.is_none() {
                stop = Some(Stop::Caller);
            }
            if stop.is_some() {
                break;
            }
            self.precondition(&r, &mut z);
            let rz_new = self.dot(&r, &z);
            if restart {
                p.copy_from_slice(&z);
            } else {
                let beta = rz_new / rz;
                p.par_iter_mut().zip(&z).for_each(|(p, z)| *p = z + beta * *p);
            }
            rz = rz_new;
        }
        if stop != Some(Stop::Converged) {
            // The state leaves with its true internal force.
            self.apply(model, &state.u, &mut f_int);
            residual(&f_int, &mut r);
            ratio = unbalanced_ratio(max_abs(&r), self.f_ext_max);
        }
        state.f_int = f_int;
        let stop = stop.expect("the loop ends with a stop");
        Ok(RunReport {
            stop,
            converged: stop == Stop::Converged,
            steps: state.step - first,
            dt: 0.0,
            unbalanced_ratio: ratio,
            history,
        })
    }
}

/// `max |x_k|`, NaN if any component is (so a non-finite residual never converges).
fn max_abs(x: &[f64]) -> f64 {
    let max = |a: f64, b: f64| if a.is_nan() || b.is_nan() { f64::NAN } else { a.max(b) };
    x.par_iter().with_min_len(CHUNK).map(|v| v.abs()).reduce(|| 0.0, max)
}

fn non_finite(step: usize, x: &[f64]) -> SolveError {
    SolveError::NonFinite { step, node: x.iter().position(|v| !v.is_finite()).unwrap_or(0) / 3 }
}
