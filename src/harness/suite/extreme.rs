//! The stiff and extreme suite (verification/extreme/, references/extreme.md)
//! under both elastic solvers: every case is run with dynamic relaxation and
//! with PCG, a row each ([`ExtremeCase::row_spec`]); each run is judged by
//! the convergence measure of its own solver ([`Convergence`]).

use crate::drivers::{run_scene, RunResult};
use crate::error::Error;
use crate::harness::registry::{self as reg, ExtremeCase};
use crate::harness::report::Check;
use crate::solver::{f_ext_max, unbalanced_ratio, ElasticSolver};

/// Dynamic relaxation: the last recorded kinetic energy of a converged case
/// is at most this fraction of its peak (references/extreme.md).
pub const KE_DECAY: f64 = 1e-10;

/// The two elastic solvers, in the order of the rows.
pub const SOLVERS: [ElasticSolver; 2] = reg::EXTREME_SOLVERS;

/// What a run's own solver produces, against its bound:
/// - dynamic relaxation: the kinetic energy decays (last recorded value over
///   the peak at most [`KE_DECAY`]) and the unbalanced-force ratio it
///   stopped on is below the tolerance;
/// - PCG (its history has no kinetic energy: `v` stays 0): the residual it
///   stops on, `max |f_ext - K u| / max |f_ext|` over the free components,
///   recomputed here from the final state's internal force, below the
///   tolerance.
///
/// Either way the run must have stopped `Converged`.
#[derive(Debug, Clone, PartialEq)]
pub struct Convergence {
    pub solver: ElasticSolver,
    pub converged: bool,
    /// DR: last / peak kinetic energy (0 without motion); PCG: NaN.
    pub ke_ratio: f64,
    /// DR: the unbalanced ratio of the last step; PCG: the recomputed residual ratio.
    pub ratio: f64,
    pub tolerance: f64,
}

impl Convergence {
    /// Measures run `r` of `solver` with tolerance `tolerance`.
    pub fn of(r: &RunResult, solver: ElasticSolver, tolerance: f64) -> Self {
        let (ke_ratio, ratio) = match solver {
            ElasticSolver::Dr => {
                let peak = r.elastic.history.iter().map(|h| h.kinetic_energy).fold(0.0, f64::max);
                let last = r.elastic.history.last().map_or(0.0, |h| h.kinetic_energy);
                (if peak > 0.0 { last / peak } else { 0.0 }, r.elastic.unbalanced_ratio)
            }
            ElasticSolver::Pcg => (f64::NAN, residual_ratio(r)),
        };
        Self { solver, converged: r.elastic.converged, ke_ratio, ratio, tolerance }
    }
    /// Whether the measure of its solver is within its bound.
    pub fn ok(&self) -> bool {
        self.converged
            && self.ratio < self.tolerance
            && (self.solver == ElasticSolver::Pcg || self.ke_ratio <= KE_DECAY)
    }
    /// The measure as text, e.g. "KE last/peak 0.0e0, ratio 3.1e-8 (< 1e-7)".
    pub fn describe(&self) -> String {
        match self.solver {
            ElasticSolver::Dr => format!(
                "KE last/peak {:.1e} (at most {KE_DECAY:.0e}), ratio {:.1e} (tolerance {:.0e})",
                self.ke_ratio, self.ratio, self.tolerance
            ),
            ElasticSolver::Pcg => format!("true residual {:.1e} (tolerance {:.0e})", self.ratio, self.tolerance),
        }
    }
    /// Why the run's numbers cannot be trusted (None if [`Self::ok`]).
    pub fn defect(&self) -> Option<String> {
        (!self.ok()).then(|| {
            format!(
                "{}: {}{}",
                solver_name(self.solver),
                self.describe(),
                if self.converged { "" } else { ", not converged" }
            )
        })
    }
}

/// "DR" or "PCG".
pub fn solver_name(s: ElasticSolver) -> &'static str {
    match s {
        ElasticSolver::Dr => "DR",
        ElasticSolver::Pcg => "PCG",
    }
}

/// `max |f_ext - f_int| / max |f_ext|` over the free components of the
/// final state (its internal force is `K u` after phase 1).
pub fn residual_ratio(r: &RunResult) -> f64 {
    let m = &r.model;
    let max = (0..m.f_ext.len())
        .filter(|&k| !m.fixed[k])
        .map(|k| (m.f_ext[k] - r.state.f_int[k]).abs())
        .fold(0.0, |a: f64, b| if a.is_nan() || b.is_nan() { f64::NAN } else { a.max(b) });
    unbalanced_ratio(max, f_ext_max(m))
}

/// One run of a case with one solver, its convergence and its row.
pub struct ExtremeRun {
    pub case: ExtremeCase,
    pub solver: ElasticSolver,
    pub result: RunResult,
    pub convergence: Convergence,
    pub row: Check,
}

/// Runs `case` with `solver` (the scene otherwise as committed).
pub fn run(case: &ExtremeCase, solver: ElasticSolver) -> Result<ExtremeRun, Error> {
    let mut scene = case.scene()?;
    scene.solver.elastic = solver;
    run_with(case, &scene)
}

/// Runs `case` on `scene` (a mutation of its scene, e.g. a smaller budget).
pub fn run_with(case: &ExtremeCase, scene: &crate::scene::Scene) -> Result<ExtremeRun, Error> {
    let solver = scene.solver.elastic;
    let result = run_scene(scene, &mut |_, _| {})?;
    let convergence = Convergence::of(&result, solver, scene.solver.tolerance);
    let row = row(case, solver, &result, &convergence);
    Ok(ExtremeRun { case: *case, solver, result, convergence, row })
}

/// The row of a run: top u_z against the analytic value; a run whose own
/// convergence measure misses its bound fails the row (with the reason).
pub fn row(case: &ExtremeCase, solver: ElasticSolver, r: &RunResult, c: &Convergence) -> Check {
    let check = case.row_spec_for(solver).value(reg::measured_top_uz(r), case.reference, r.summary.wall_s);
    match c.defect() {
        Some(d) => check.with_defect(d),
        None => check,
    }
}

/// Every case under both solvers ([`SOLVERS`]), in the table's order.
pub fn run_all() -> Result<Vec<ExtremeRun>, Error> {
    let mut runs = Vec::new();
    for case in reg::extreme_cases() {
        for solver in SOLVERS {
            runs.push(run(&case, solver)?);
        }
    }
    Ok(runs)
}
