//! The relax driver's stop rules (src/solver/relax.rs), each made to fire on
//! the merged column: tolerance, budget, the caller's stop, and sliding; the
//! order of the rules; history rows at the cadence and at convergence.

use std::ops::ControlFlow;
use std::path::Path;

use cdem::drivers::build_model;
use cdem::model::Model;
use cdem::scene::Scene;
use cdem::solver::relax::unobserved;
use cdem::solver::{relax, RunReport, Sliding, Solver, State, StepView, Stop, StopRules};

fn column() -> (cdem::model::Model, Solver, State, f64) {
    let scene = Scene::load(Path::new("verification/cases/column/column-merged.toml")).unwrap();
    let model = build_model(&scene).unwrap();
    let solver = Solver::new(&model, scene.solver.clone()).unwrap();
    let state = State::new(&model);
    (model, solver, state, scene.solver.tolerance)
}

fn rules(tolerance: f64, max_steps: usize) -> StopRules<'static> {
    StopRules { tolerance, max_steps, sliding: None, foresight: None, history_every: 10 }
}

#[test]
fn tolerance_stops_with_converged_and_a_last_history_row() {
    let (model, mut solver, mut state, tol) = column();
    let r = relax(&mut solver, &model, &mut state, &rules(tol, 100_000), &mut unobserved).unwrap();
    assert_eq!(r.stop, Stop::Converged);
    assert!(r.converged && r.unbalanced_ratio < tol);
    assert_eq!(state.step, r.steps);
    let last = r.history.last().unwrap();
    assert_eq!(last.step, r.steps, "a row at convergence");
    assert!(r.history.iter().rev().skip(1).all(|h| h.step % 10 == 0), "the other rows on the cadence");
}

#[test]
fn budget_stops_after_exactly_max_steps() {
    let (model, mut solver, mut state, tol) = column();
    let r = relax(&mut solver, &model, &mut state, &rules(tol, 50), &mut unobserved).unwrap();
    assert_eq!((r.stop, r.steps, r.converged), (Stop::Budget, 50, false));
    assert!(r.unbalanced_ratio > tol);
    assert_eq!(r.history.len(), 5, "rows at steps 10..50");
}

#[test]
fn the_callers_stop_ends_on_the_step_it_is_asked() {
    let (model, mut solver, mut state, tol) = column();
    let mut seen = Vec::new();
    let mut stop_at_30 = |v: &StepView| {
        seen.push((v.steps, v.stop));
        if v.steps == 30 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    let r = relax(&mut solver, &model, &mut state, &rules(tol, 1000), &mut stop_at_30).unwrap();
    assert_eq!((r.stop, r.steps), (Stop::Caller, 30));
    assert_eq!(seen.len(), 30, "the observer sees every step");
    assert!(seen.iter().enumerate().all(|(k, &(s, stop))| s == k + 1 && stop.is_none()));
}

#[test]
fn sliding_is_checked_on_its_cadence_and_after_the_tolerance() {
    let (model, mut solver, mut state, tol) = column();
    // A reference 1 m away from the rest state: the displacement "since" it
    // is 1 m from the first step, so the rule fires at its first check.
    let reference = vec![1.0; 3 * model.n_nodes()];
    let weights = model.mass.clone();
    // The fixed bound alone (the rate rule needs more windows than the run has).
    let sliding = Sliding {
        reference: &reference,
        weights: &weights,
        window: 7,
        windows: 1000,
        floor: 0.0,
        displacement: 0.5,
        travel: 0.0,
        steady: false,
    };
    let r = relax(
        &mut solver,
        &model,
        &mut state,
        &StopRules { sliding: Some(sliding), ..rules(tol, 1000) },
        &mut unobserved,
    )
    .unwrap();
    assert_eq!((r.stop, r.steps), (Stop::Sliding, 7));

    // With a tolerance the first step meets, converged wins over sliding.
    let (model, mut solver, mut state, _) = column();
    let r = relax(
        &mut solver,
        &model,
        &mut state,
        &StopRules { sliding: Some(Sliding { window: 1, ..sliding }), ..rules(f64::INFINITY, 1000) },
        &mut unobserved,
    )
    .unwrap();
    assert_eq!((r.stop, r.steps), (Stop::Converged, 1));
}

/// Relaxes under the sliding-rate rule alone (rest state as reference, mass
/// weights, windows of 20 steps, three growing windows, no floor, no bound).
fn relax_with_rate_rule(solver: &mut Solver, model: &Model, state: &mut State, tol: f64) -> RunReport {
    relax_with_travel(solver, model, state, tol, 0.0)
}

/// [`relax_with_rate_rule`] with the rate rule waiting for `travel` (m) of
/// the largest displacement.
fn relax_with_travel(solver: &mut Solver, model: &Model, state: &mut State, tol: f64, travel: f64) -> RunReport {
    let reference = vec![0.0; 3 * model.n_nodes()];
    let weights = model.mass.clone();
    let rule = Sliding {
        reference: &reference,
        weights: &weights,
        window: 20,
        windows: 3,
        floor: 0.0,
        displacement: f64::INFINITY,
        travel,
        steady: false,
    };
    relax(solver, model, state, &StopRules { sliding: Some(rule), ..rules(tol, 100_000) }, &mut unobserved).unwrap()
}

#[test]
fn sliding_by_rate_fires_when_the_mean_displacement_grows_without_decay_and_not_when_it_relaxes() {
    // A reference that recedes: the model relaxes from rest toward its
    // gravity settlement, so its mean displacement since the rest state
    // grows at first and then stops; a decaying rate never meets the rule.
    let (model, mut solver, mut state, tol) = column();
    let r = relax_with_rate_rule(&mut solver, &model, &mut state, tol);
    assert_eq!(r.stop, Stop::Converged, "a relaxing model is not sliding");

    // Pulled by a load that never balances (no fixities): a rigid motion that
    // accelerates, so each window's increment is larger than the last.
    let (mut model, _, _, _) = column();
    model.fixed.fill(false);
    let mut solver =
        Solver::new(&model, cdem::solver::SolverParams { block_mass: Some(false), ..Default::default() }).unwrap();
    let mut state = State::new(&model);
    let r = relax_with_rate_rule(&mut solver, &model, &mut state, tol);
    // Windows 2, 3 and 4 are the first three that can be compared with a previous one.
    assert_eq!((r.stop, r.steps), (Stop::Sliding, 80));
}

#[test]
fn the_rate_rule_waits_for_its_travel() {
    // The accelerating pull of the test above slides at step 80; with a
    // travel floor the rule fires at the first window past it, later, and
    // the largest displacement then is at least the floor.
    let pulled = || {
        let (mut model, _, _, tol) = column();
        model.fixed.fill(false);
        let solver =
            Solver::new(&model, cdem::solver::SolverParams { block_mass: Some(false), ..Default::default() }).unwrap();
        (model, solver, tol)
    };
    let (model, mut solver, tol) = pulled();
    let mut state = State::new(&model);
    let at_80 = relax_with_travel(&mut solver, &model, &mut state, tol, 0.0);
    let moved_at_80 = state.u.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert_eq!((at_80.stop, at_80.steps), (Stop::Sliding, 80));
    let (model, mut solver, tol) = pulled();
    let mut state = State::new(&model);
    let r = relax_with_travel(&mut solver, &model, &mut state, tol, 10.0 * moved_at_80);
    let moved = state.u.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert_eq!(r.stop, Stop::Sliding);
    assert!(r.steps > 80 && r.steps.is_multiple_of(20), "{} steps", r.steps);
    assert!(moved >= 10.0 * moved_at_80, "{moved} < {}", 10.0 * moved_at_80);
}
