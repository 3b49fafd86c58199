//! The phase plan: how one phase relaxes, decided once and reused by every
//! relaxation of that phase (each strength-reduction trial, each ensemble
//! member). It holds:
//! - the method: dynamic relaxation ([`Solver`], with its masses and time
//!   step) or, for the elastic phase, two-level PCG ([`Pcg`]); the one place
//!   that chooses between them is [`PhasePlan::elastic`];
//! - the step budget ([`budget::step_budget`], the one formula);
//! - the stop rules' tolerance and history interval ([`PhasePlan::rules`]
//!   builds the [`StopRules`]; a phase adds its sliding rule).

use super::budget::{self, PHASE2_RESPONSE_TIMES};
use super::relax::{relax, Foresight, Observer, RunReport, Sliding, StopRules};
use super::{ElasticSolver, Pcg, Solver, SolverParams, State};
use crate::error::SolveError;
use crate::model::Model;

/// How a phase steps (both boxed: a plan is moved around whole).
pub enum Method {
    /// Dynamic relaxation (eq. 14) with this solver's masses and step.
    Dr(Box<Solver>),
    /// Two-level preconditioned conjugate gradients (elastic phase only).
    Pcg(Box<Pcg>),
}

/// One phase's method, budget and stop rules (see the module doc).
pub struct PhasePlan {
    method: Method,
    /// Step (or PCG iteration) budget of one relaxation.
    pub budget: usize,
    /// Converged: `max |f_unbal| / max |f_ext|` below this.
    pub tolerance: f64,
    /// A history row every this many steps.
    pub history_every: usize,
    /// The foresight rule of its relaxations (strength-reduction trials).
    pub foresight: Option<Foresight>,
    /// Phase 2 took phase 1's solver over, its damping state included
    /// ([`Self::failure`]); false for a newly built solver.
    pub continued: bool,
}

impl PhasePlan {
    /// Phase 1: the solver `params.elastic` names, its budget `N_r` (with
    /// node-block masses for PCG) unless `params.max_steps` gives one.
    pub fn elastic(model: &Model, params: &SolverParams, history_every: usize) -> Result<Self, SolveError> {
        let (method, block) = match params.elastic {
            ElasticSolver::Dr => {
                let solver = Solver::new(model, params.clone())?;
                let block = solver.inertia().is_block();
                (Method::Dr(Box::new(solver)), block)
            }
            ElasticSolver::Pcg => (Method::Pcg(Box::new(Pcg::new(model)?)), true),
        };
        let budget = budget::step_budget(model, params, block, params.max_steps, 1);
        Ok(Self { method, budget, tolerance: params.tolerance, history_every, foresight: None, continued: false })
    }

    /// Phase 2 (and each strength-reduction trial): dynamic relaxation with
    /// node-block masses if `block_mass` asks for them and `params` allow
    /// them ([`SolverParams::block_masses`]); the budget `max_steps`, else
    /// [`PHASE2_RESPONSE_TIMES`] `N_r`. A phase-1 `solver` with those masses
    /// is taken over as it is (its damping state goes on).
    pub fn failure(
        model: &Model,
        params: &SolverParams,
        block_mass: bool,
        max_steps: Option<usize>,
        history_every: usize,
        solver: Option<Solver>,
    ) -> Result<Self, SolveError> {
        let block = params.block_masses(block_mass);
        let (solver, continued) = match solver {
            Some(s) if s.inertia().is_block() == block => (s, true),
            _ => (Solver::with_masses(model, params.clone(), block)?, false),
        };
        let budget = budget::step_budget(model, params, block, max_steps, PHASE2_RESPONSE_TIMES);
        Ok(Self {
            method: Method::Dr(Box::new(solver)),
            budget,
            tolerance: params.tolerance,
            history_every,
            foresight: None,
            continued,
        })
    }

    /// The stop rules of one relaxation of this phase.
    pub fn rules<'a>(&self, sliding: Option<Sliding<'a>>) -> StopRules<'a> {
        StopRules {
            foresight: self.foresight,
            ..StopRules::new(self.tolerance, self.budget, sliding, self.history_every)
        }
    }

    /// Takes the dynamic-relaxation solver out (phase 2 goes on with it).
    pub fn into_solver(self) -> Option<Solver> {
        match self.method {
            Method::Dr(s) => Some(*s),
            Method::Pcg(_) => None,
        }
    }

    /// Relaxes `state` under this plan's rules plus `sliding`. With
    /// `failure`, breakable springs follow the joint law. The solver's
    /// damping state is not reset: see [`Self::restart`].
    pub fn run(
        &mut self,
        model: &Model,
        state: &mut State,
        failure: bool,
        sliding: Option<Sliding>,
        observer: &mut dyn Observer,
    ) -> Result<RunReport, SolveError> {
        let rules = self.rules(sliding);
        match &mut self.method {
            Method::Dr(solver) => {
                solver.set_failure(model, failure);
                relax(solver, model, state, &rules, observer)
            }
            Method::Pcg(pcg) => pcg.solve(model, state, &rules, observer),
        }
    }

    /// Makes the next [`Self::run`] start as a newly built plan would (the
    /// adaptive damping forgotten): a strength-reduction trial or ensemble
    /// member does not inherit the previous one's.
    pub fn restart(&mut self) {
        if let Method::Dr(solver) = &mut self.method {
            solver.restart();
        }
    }
}
