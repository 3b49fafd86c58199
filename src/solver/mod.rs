//! Explicit dynamic relaxation (paper section 3.4, eq. 8 and 14).
//!
//! One step is a short list of named stages:
//! 1. internal forces: elements (eq. 12) and springs (eq. 15), and the
//!    spring dashpots' forces where they are on (from the same passes);
//! 2. update: damping (eq. 13: the dashpots' forces, then the viscous or
//!    local damping) and explicit integration (eq. 14) with fixities;
//! 3. monitor: convergence ratio, energies, non-finite state and blow-up.
//!
//! [`relax`](relax::relax) steps until a stop rule fires; it is the one loop
//! every driver uses for dynamic relaxation. The elastic phase may instead
//! be solved as a linear system by two-level preconditioned conjugate
//! gradients ([`pcg`], coarse space [`coarse`]), with the same stop rules and
//! convergence measure.

pub mod block_mass;
pub mod budget;
pub mod coarse;
pub mod forces;
pub mod inertia;
pub mod integrate;
pub mod params;
pub mod pcg;
pub mod plan;
pub mod relax;
pub mod runout;
pub mod timestep;

pub use inertia::Inertia;
pub use params::{DampingKind, ElasticSolver, SolverParams};
pub use pcg::Pcg;
pub use plan::PhasePlan;
pub use relax::{relax, Foresight, Observer, RunReport, Sliding, StepView, Stop, StopRules};

use serde::Serialize;

use crate::error::SolveError;
use crate::model::Model;
use crate::model::ELEMENT_SLOT;
use crate::physics::damping::{dashpot_beta, rayleigh_omega2, rayleigh_omega2_with, tangent_numerator};
use crate::physics::joint::JointState;
use crate::physics::plastic::RockState;
use crate::physics::spring::SpringState;
use block_mass::BlockMass;
use integrate::{integrate, UpdateInput};

/// Whether `model`'s failure phase puts dashpots on its springs: breakable
/// springs and either plastic blocks or every mesh face breakable, the two
/// models in which yielding spreads through the whole mass (docs/method.md
/// 2.9b).
pub fn has_dashpots(model: &Model) -> bool {
    model.has_breakable_interface() && (model.has_plastic_blocks() || model.every_face_breakable())
}

/// What changes during a run, in flat arrays indexed `3 i + d`.
#[derive(Debug, Clone)]
pub struct State {
    pub u: Vec<f64>,
    pub v: Vec<f64>,
    pub f_int: Vec<f64>,
    pub springs: SpringState,
    /// What each spring can carry now (the joint law's strengths).
    pub joints: JointState,
    /// What each plastic block can carry now and its tetrahedra's history.
    pub rock: RockState,
    pub step: usize,
    pub time: f64,
}

impl State {
    pub fn new(model: &Model) -> Self {
        let n = 3 * model.n_nodes();
        Self {
            u: vec![0.0; n],
            v: vec![0.0; n],
            f_int: vec![0.0; n],
            springs: SpringState::new(model.springs.len()),
            joints: model.joint_state(),
            rock: model.rock_state(),
            step: 0,
            time: 0.0,
        }
    }
}

/// One row of the run history.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct HistoryRow {
    pub step: usize,
    pub time: f64,
    /// Kinetic energy with the inertial masses (J).
    pub kinetic_energy: f64,
    /// Work of the external loads `f_ext . u` (J).
    pub external_work: f64,
    /// Stored elastic energy `u . f_int / 2` (J).
    pub strain_energy: f64,
    pub unbalanced_ratio: f64,
    pub max_displacement: f64,
}

/// The solver owns its scratch: inertial masses, the step and damping
/// state. Its settings, masses and step are fixed at construction (they must
/// stay consistent with each other) and read through methods.
pub struct Solver {
    params: SolverParams,
    inertia: Inertia,
    dt: f64,
    f_ext_max: f64,
    viscous_c: f64,
    last_kinetic: f64,
    /// Scratch: element forces, `ELEMENT_SLOT` per element.
    f_elem: Vec<f64>,
    /// Scratch: spring forces on their node `a`.
    f_spring: Vec<[f64; 3]>,
    /// Scratch: one partial update report per chunk of the integration.
    partial: Vec<integrate::UpdateReport>,
    /// Failure phase on: breakable springs check eq. 17-18. Only true when
    /// the model has a breakable interface.
    failure: bool,
    /// Failure phase on for the blocks: plastic elements integrate per
    /// tetrahedron. Only true when the model has plastic blocks.
    plastic: bool,
    /// The spring dashpots' `beta` (s; 0: none): on in the failure phase of
    /// a model that [`has_dashpots`]
    /// ([`crate::physics::damping::dashpot_beta`]).
    dashpot_beta: f64,
    /// Scratch: each spring's dashpot force on its node `a`, and their sum
    /// per component (empty until the dashpots are on).
    f_dash_spring: Vec<[f64; 3]>,
    f_dash: Vec<f64>,
    /// Scratch of the tangent damping estimate (plastic failure phase).
    tangent: TangentProbe,
}

/// The state one step before a refresh of the tangent damping estimate:
/// `u` and `f_int` then, and the increment's scratch.
#[derive(Default)]
struct TangentProbe {
    u: Vec<f64>,
    f: Vec<f64>,
    du: Vec<f64>,
    armed: bool,
}

impl Solver {
    /// The solver of phase 1: node-block masses as `params` say
    /// ([`SolverParams::uses_block_mass`]).
    pub fn new(model: &Model, params: SolverParams) -> Result<Self, SolveError> {
        let block = params.uses_block_mass();
        Self::with_masses(model, params, block)
    }

    /// A solver with node-block masses if `block` and `params` allow them
    /// ([`SolverParams::block_masses`]), lumped masses otherwise.
    pub fn with_masses(model: &Model, params: SolverParams, block: bool) -> Result<Self, SolveError> {
        let rows = timestep::stiffness_row_sums(model);
        let amplification = if params.damping == DampingKind::Local { 1.0 + params.local_damping } else { 1.0 };
        let (mass, dt) = timestep::masses_and_step(model, &rows, params.safety, params.mass_scaling, amplification)
            .ok_or(SolveError::NoTimeStep)?;
        let inertia = match params.block_masses(block) {
            true => Inertia::block(mass, BlockMass::new(model, amplification / (4.0 * params.safety * params.safety))?),
            false => Inertia::lumped(mass),
        };
        let f_ext_max = f_ext_max(model);
        Ok(Self {
            params,
            inertia,
            dt,
            f_ext_max,
            viscous_c: 0.0,
            last_kinetic: 0.0,
            f_elem: vec![0.0; ELEMENT_SLOT * model.elements.len()],
            f_spring: vec![[0.0; 3]; model.springs.len()],
            partial: vec![integrate::UpdateReport::default(); (3 * model.n_nodes()).div_ceil(integrate::CHUNK)],
            failure: false,
            plastic: false,
            dashpot_beta: 0.0,
            f_dash_spring: Vec::new(),
            f_dash: Vec::new(),
            tangent: TangentProbe::default(),
        })
    }

    pub fn params(&self) -> &SolverParams {
        &self.params
    }

    /// The time step (s; 1 with mass scaling, a fictitious time).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Replaces the time step. For experiments only: a step beyond the
    /// stable bound is caught by the energy monitor as [`SolveError::Unstable`].
    pub fn set_time_step(&mut self, dt: f64) {
        self.dt = dt;
    }

    /// Relaxes `state` to this solver's own tolerance within its step budget
    /// (`params`), without an observer: [`relax()`] with those rules.
    pub fn relax(&mut self, model: &Model, state: &mut State, history_every: usize) -> Result<RunReport, SolveError> {
        let rules = StopRules::new(self.params.tolerance, self.step_budget(model), None, history_every);
        relax::relax(self, model, state, &rules, &mut relax::unobserved)
    }

    /// The step budget of one relaxation ([`budget::step_budget`]):
    /// `params.max_steps`, or one characteristic response time with this
    /// solver's damping and masses.
    pub fn step_budget(&self, model: &Model) -> usize {
        budget::step_budget(model, &self.params, self.inertia.is_block(), self.params.max_steps, 1)
    }

    /// Forgets the adaptive damping state, so that the next relaxation
    /// starts as with a new solver (masses and step are kept).
    pub fn restart(&mut self) {
        self.viscous_c = 0.0;
        self.last_kinetic = 0.0;
        self.tangent.armed = false;
    }

    pub fn inertia(&self) -> &Inertia {
        &self.inertia
    }

    /// Turns the failure phase (phase 2) on or off: breakable springs follow
    /// the joint law, plastic blocks the material law. Each stays off for a
    /// model without breakable interfaces or plastic blocks, which then does
    /// no failure work. The
    /// masses are kept: node-block masses stay stable when springs fail
    /// (see [`block_mass`]).
    pub fn set_failure(&mut self, model: &Model, on: bool) {
        self.failure = on && model.has_breakable_interface();
        self.plastic = on && model.has_plastic_blocks();
        self.dashpot_beta = if on && has_dashpots(model) { dashpot_beta(self.params.safety, self.dt) } else { 0.0 };
        if self.dashpots_on() && self.f_dash.is_empty() {
            self.f_dash_spring = vec![[0.0; 3]; model.springs.len()];
            self.f_dash = vec![0.0; 3 * model.n_nodes()];
        }
    }

    /// Whether the spring dashpots are on (see [`Self::set_failure`]).
    fn dashpots_on(&self) -> bool {
        self.dashpot_beta > 0.0
    }

    /// Kinetic energy `v . M v / 2` with the inertial masses (J).
    pub fn kinetic_energy(&mut self, state: &State) -> f64 {
        0.5 * self.inertia.quadratic(&state.v)
    }

    /// Stage 1: internal forces, eq. 12 (elements) and eq. 15 (springs),
    /// gathered per node (see [`forces`]); where the spring dashpots are on,
    /// their forces from the half-step velocities into `f_dash` too, from the
    /// same passes over the springs and the nodes.
    pub fn internal_forces(&mut self, model: &Model, state: &mut State) {
        match self.plastic {
            true => forces::element_forces_plastic(model, &mut state.rock, &state.u, &mut self.f_elem),
            false => forces::element_forces(model, &state.u, &mut self.f_elem),
        }
        let dashpots = self.dashpots_on();
        if self.failure {
            let dash = dashpots.then_some(forces::Dashpots {
                v: &state.v,
                beta: self.dashpot_beta,
                out: &mut self.f_dash_spring,
            });
            forces::spring_forces_with_failure(
                model,
                &state.joints,
                &mut state.springs,
                &state.u,
                dash,
                &mut self.f_spring,
            );
        } else {
            forces::spring_forces(model, &state.springs, &state.u, &mut self.f_spring);
        }
        match dashpots {
            true => forces::gather_with_dashpots(
                model,
                &self.f_elem,
                &self.f_spring,
                &self.f_dash_spring,
                &mut state.f_int,
                &mut self.f_dash,
            ),
            false => forces::gather(model, &self.f_elem, &self.f_spring, &mut state.f_int),
        }
    }

    /// One step. Returns `(max unbalanced force, kinetic-energy estimate)`:
    /// with node-block masses the estimate uses their diagonal, every step
    /// (`v . M v / 2` itself: [`Self::kinetic_energy`]).
    pub fn step(&mut self, model: &Model, state: &mut State) -> Result<(f64, f64), SolveError> {
        self.internal_forces(model, state);
        let dashpots = self.dashpots_on();
        self.update_damping(state);
        let f_dash = dashpots.then_some(&self.f_dash[..]);
        self.inertia.prepare(&model.fixed, &model.f_ext, &state.f_int, f_dash);
        let inp = UpdateInput {
            mass: self.inertia.masses(),
            fixed: &model.fixed,
            f_ext: &model.f_ext,
            f_int: &state.f_int,
            dt: self.dt,
            damping: self.params.damping,
            alpha: self.params.local_damping,
            c: self.viscous_c,
            f_dash,
        };
        let rep = integrate(&inp, &mut state.u, &mut state.v, &mut self.partial);
        state.step += 1;
        state.time += self.dt;
        let kinetic = self.kinetic_damping(state, rep.kinetic);
        if !kinetic.is_finite() {
            return Err(self.non_finite(state));
        }
        // The estimate is returned every step, so that rule 1 of `relax`
        // compares like with like; the energy check takes the exact value.
        if state.step.is_multiple_of(16) {
            let exact = self.exact_kinetic(state, kinetic);
            self.monitor(model, state, exact)?;
        }
        Ok((rep.max_unbalanced, kinetic))
    }

    /// Adaptive viscous damping: `c = 2 omega`, refreshed every 10 steps.
    /// `omega^2` is the Rayleigh quotient of the displacement (the secant),
    /// or with plastic blocks in the failure phase that of the increment of
    /// the step before the refresh (the tangent along the motion: a trial near
    /// its critical factor has a soft slowest mode, which the secant's
    /// `c` overdamps; docs/method.md 2.9b). A tangent that is not positive
    /// (softening) keeps the last `c`; the secant starts it.
    fn update_damping(&mut self, state: &State) {
        if self.params.damping != DampingKind::Viscous {
            return;
        }
        if self.plastic {
            if state.step % 10 == 9 {
                let t = &mut self.tangent;
                t.u.clone_from(&state.u);
                t.f.clone_from(&state.f_int);
                t.armed = true;
                return;
            }
            if state.step.is_multiple_of(10) && self.tangent.armed {
                let t = &mut self.tangent;
                t.armed = false;
                t.du.resize(state.u.len(), 0.0);
                let num = tangent_numerator(&state.u, &state.f_int, &t.u, &t.f, &mut t.du);
                let w2 = rayleigh_omega2_with(num, self.inertia.quadratic(&t.du));
                if w2 > 0.0 {
                    self.viscous_c = 2.0 * w2.sqrt();
                }
                if self.viscous_c > 0.0 {
                    return;
                }
            }
        }
        if state.step.is_multiple_of(10) {
            let w2 = match self.inertia.is_block() {
                true => rayleigh_omega2_with(dot(&state.u, &state.f_int), self.inertia.quadratic(&state.u)),
                false => rayleigh_omega2(&state.u, &state.f_int, self.inertia.lumped_masses()),
            };
            if w2 > 0.0 {
                self.viscous_c = 2.0 * w2.sqrt();
            }
        }
    }

    /// Kinetic damping: at a peak of kinetic energy, stop every node.
    fn kinetic_damping(&mut self, state: &mut State, kinetic: f64) -> f64 {
        if self.params.damping != DampingKind::Kinetic {
            return kinetic;
        }
        let peaked = kinetic < self.last_kinetic;
        self.last_kinetic = kinetic;
        if peaked {
            state.v.fill(0.0);
            self.last_kinetic = 0.0;
            return 0.0;
        }
        kinetic
    }

    fn non_finite(&self, state: &State) -> SolveError {
        let node = (0..state.u.len()).find(|&k| !state.u[k].is_finite() || !state.v[k].is_finite()).unwrap_or(0) / 3;
        SolveError::NonFinite { step: state.step, node }
    }

    /// Stage 3: non-finite state and energy blow-up are errors naming the node.
    fn monitor(&self, model: &Model, state: &State, kinetic: f64) -> Result<(), SolveError> {
        if !kinetic.is_finite() {
            return Err(self.non_finite(state));
        }
        if kinetic > 0.0 && state.step.is_multiple_of(16) {
            let work = external_work(model, state);
            // Energy balance: kinetic + strain = work - dissipated <= work.
            // The kinetic energy of central differences (half-step
            // velocities) overstates the true one by up to
            // 1 / (1 - (omega dt / 2)^2) <= 1 / (1 - safety^2); a real
            // instability grows geometrically and passes twice that in a few
            // steps.
            let s = self.params.safety.min(0.99);
            if kinetic > 2.0 * work.abs() / (1.0 - s * s) {
                let node = (0..model.n_nodes())
                    .max_by(|&a, &b| self.node_kinetic(state, a).total_cmp(&self.node_kinetic(state, b)))
                    .unwrap_or(0);
                return Err(SolveError::Unstable { step: state.step, node, kinetic, work });
            }
        }
        Ok(())
    }

    fn node_kinetic(&self, state: &State, i: usize) -> f64 {
        0.5 * self.inertia.lumped_masses()[i] * (0..3).map(|d| state.v[3 * i + d].powi(2)).sum::<f64>()
    }

    /// Unbalanced-force ratio `max |f_unbal| / max |f_ext|` (0 if unloaded and at rest).
    pub fn ratio(&self, max_unbalanced: f64) -> f64 {
        unbalanced_ratio(max_unbalanced, self.f_ext_max)
    }

    /// `v . M v / 2` of `state` given the step's estimate `kinetic`: with
    /// block masses a pass over them ([`Self::kinetic_energy`]); with lumped
    /// masses the estimate is that value already.
    pub fn exact_kinetic(&mut self, state: &State, kinetic: f64) -> f64 {
        if self.inertia.is_block() {
            self.kinetic_energy(state)
        } else {
            kinetic
        }
    }
}

impl HistoryRow {
    /// The row of `state` with the given kinetic energy and ratio.
    pub fn of(model: &Model, state: &State, kinetic: f64, ratio: f64) -> Self {
        let max_displacement = crate::summary::max_displacement(&state.u);
        HistoryRow {
            step: state.step,
            time: state.time,
            kinetic_energy: kinetic,
            external_work: dot(&model.f_ext, &state.u),
            strain_energy: 0.5 * dot(&state.u, &state.f_int),
            unbalanced_ratio: ratio,
            max_displacement,
        }
    }
}

/// The work of the loads and of the supports on `state.u` (J): `f_ext . u`
/// plus, on fixed components with a prescribed (nonzero) displacement, the
/// reaction's `(f_int - f_ext) u` (zero where supports hold nodes in place).
fn external_work(model: &Model, state: &State) -> f64 {
    let loads = dot(&model.f_ext, &state.u);
    let supports: f64 = (0..state.u.len())
        .filter(|&k| model.fixed[k] && state.u[k] != 0.0)
        .map(|k| (state.f_int[k] - model.f_ext[k]) * state.u[k])
        .sum();
    loads + supports
}

/// `max |f_ext|` over the free components (N).
pub fn f_ext_max(model: &Model) -> f64 {
    model.f_ext.iter().zip(&model.fixed).filter(|(_, &fx)| !fx).map(|(f, _)| f.abs()).fold(0.0, f64::max)
}

/// The convergence measure of both elastic solvers, `max |f_unbal| / max
/// |f_ext|` over free components (0 if unloaded and balanced, infinite if
/// unloaded and not).
pub fn unbalanced_ratio(max_unbalanced: f64, f_ext_max: f64) -> f64 {
    if f_ext_max > 0.0 {
        max_unbalanced / f_ext_max
    } else if max_unbalanced == 0.0 {
        0.0
    } else {
        f64::INFINITY
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
