//! All numerical settings of the solver, in one struct (scene key `[solver]`).

use serde::Deserialize;

use crate::error::SceneError;

/// Damping used by dynamic relaxation (see [`crate::physics::damping`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DampingKind {
    /// Cundall's local non-viscous damping, factor `local_damping`.
    Local,
    /// Mass-proportional viscous damping at the adaptive critical value.
    Viscous,
    /// Kinetic damping: velocities zeroed at every kinetic-energy peak.
    /// Plain resets (no displacement correction): it converges the column in
    /// fewer steps than viscous damping, but on the perturbed slope it grows
    /// slowly unstable after ~4000 steps (caught by the energy check).
    Kinetic,
}

/// The solver of the elastic phase (phase 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ElasticSolver {
    /// Dynamic relaxation (the paper's method, and the cross-check).
    Dr,
    /// Two-level preconditioned conjugate gradients ([`crate::solver::pcg`]):
    /// the default, 9 iterations where DR takes 806 steps on the paper slope,
    /// 1.2-1.6x the FEM solve against DR's 12-56x (references/performance.md).
    #[default]
    Pcg,
}

/// Dynamic-relaxation settings. Every field has a default.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SolverParams {
    /// Time step as a fraction of the Gershgorin bound on the critical step
    /// `2 / sqrt(max_i sum_j |K_ij| / m_i)`. Default 0.9; must be in (0, 1].
    pub safety: f64,
    /// Damping kind. Default `viscous` (adaptive critical): on the paper
    /// slope it reaches 1e-5 in 25x fewer steps than local damping.
    pub damping: DampingKind,
    /// Local damping factor alpha. Default 0.8 (FLAC's).
    pub local_damping: f64,
    /// Scale nodal masses so that every node has the same critical step
    /// (static problems only: the path to equilibrium is then fictitious).
    /// Default true. Gravity always uses the physical mass.
    pub mass_scaling: bool,
    /// With mass scaling, scale the mass by one dense block per mesh node
    /// (all its copies; see [`crate::solver::block_mass`]) instead of one
    /// number per copy, so that stiff joint springs no longer set the step
    /// count. This key is phase 1's (dynamic relaxation); phase 2 has its
    /// own (`[failure] block_mass`, default true). Either needs
    /// [`Self::block_masses`]: mass scaling and viscous damping. Default: on
    /// when they allow it (on the paper slope it converges in 14x fewer
    /// steps, references/performance.md).
    pub block_mass: Option<bool>,
    /// Convergence: `max |f_unbal| / max |f_ext|` below this. Default 1e-5.
    pub tolerance: f64,
    /// Stop (not converged) after this many steps. Default: the model's
    /// characteristic response time `N_r` ([`crate::solver::budget`]):
    /// `C n_c sqrt(kappa)` steps, `n_c` the elements across the model,
    /// `kappa` the joint-to-rock stiffness ratio with lumped masses (1 with
    /// node-block masses), `C` measured per damping kind (100 viscous, 1500
    /// local, 500 kinetic); at least 2000.
    pub max_steps: Option<usize>,
    /// Solver of the elastic phase: `"dr"` or `"pcg"` (an iteration is
    /// then a step of `max_steps` and of the history). Default `"pcg"`.
    pub elastic: ElasticSolver,
}

impl Default for SolverParams {
    fn default() -> Self {
        Self {
            safety: 0.9,
            damping: DampingKind::Viscous,
            local_damping: 0.8,
            mass_scaling: true,
            block_mass: None,
            tolerance: 1e-5,
            max_steps: None,
            elastic: ElasticSolver::Pcg,
        }
    }
}

impl SolverParams {
    /// The one rule for node-block masses, in both phases: a phase that
    /// asks for them (`wanted`) gets them when mass scaling is on and the
    /// damping is viscous. Local damping is not dissipative with a dense
    /// mass (Cundall's per-component damping force: on the paper's
    /// slip-surface case it blew up in 464 steps), and neither are kinetic
    /// resets (the column blew up at step 272, tests/solver_errors.rs).
    pub fn block_masses(&self, wanted: bool) -> bool {
        wanted && self.mass_scaling && self.damping == DampingKind::Viscous
    }

    /// Whether the elastic phase (dynamic relaxation) uses node-block masses.
    pub fn uses_block_mass(&self) -> bool {
        self.block_masses(self.block_mass.unwrap_or(true))
    }

    pub fn validate(&self) -> Result<(), SceneError> {
        let bad = |k: &str, r: String| Err(SceneError::invalid(format!("solver.{k}"), r));
        if !(self.safety > 0.0 && self.safety <= 1.0) {
            return bad("safety", format!("must be in (0, 1], got {}", self.safety));
        }
        if !(self.local_damping >= 0.0 && self.local_damping < 1.0) {
            return bad("local_damping", format!("must be in [0, 1), got {}", self.local_damping));
        }
        if !(self.tolerance > 0.0 && self.tolerance.is_finite()) {
            return bad("tolerance", format!("must be a finite positive number, got {}", self.tolerance));
        }
        if self.block_mass == Some(true) && !self.block_masses(true) {
            return bad("block_mass", "needs mass_scaling = true and damping = \"viscous\"".into());
        }
        if self.max_steps == Some(0) {
            return bad("max_steps", "must be at least 1".into());
        }
        Ok(())
    }
}
