//! Numerical failure is reported data: a step beyond the stability limit is an
//! energy blow-up error naming the step and node, a non-finite state is a
//! NonFinite error, and running out of steps is `converged: false`.

use cdem::scene::Scene;
use cdem::solver::{DampingKind, Solver, State};
use cdem::SolveError;

fn column() -> (Scene, cdem::model::Model) {
    let scene = cdem::harness::registry::COLUMN.scene().unwrap();
    let model = cdem::drivers::build_model(&scene).unwrap();
    (scene, model)
}

#[test]
fn a_step_past_the_stability_limit_is_caught_as_blow_up() {
    let (scene, model) = column();
    for damping in [DampingKind::Local, DampingKind::Viscous, DampingKind::Kinetic] {
        let mut params = scene.solver.clone();
        params.damping = damping;
        let mut solver = Solver::new(&model, params).unwrap();
        solver.set_time_step(solver.dt() * 1.5); // beyond 2 / omega_max for the automatic safety 0.9
        let mut state = State::new(&model);
        let err = solver.relax(&model, &mut state, 10).unwrap_err();
        match err {
            SolveError::Unstable { step, node, .. } => {
                assert!(step < 1000, "{damping:?}: caught late, at step {step}");
                assert!(node < model.n_nodes());
            }
            SolveError::NonFinite { step, .. } => {
                panic!("{damping:?}: blow-up reached NaN at step {step} before the energy check")
            }
            other => panic!("{damping:?}: {other}"),
        }
    }
}

#[test]
fn automatic_step_is_stable_with_every_damping_on_the_column() {
    let (scene, model) = column();
    for damping in [DampingKind::Local, DampingKind::Viscous, DampingKind::Kinetic] {
        let mut params = scene.solver.clone();
        params.damping = damping;
        params.max_steps = Some(3000);
        let mut solver = Solver::new(&model, params).unwrap();
        let mut state = State::new(&model);
        let rep = solver.relax(&model, &mut state, 10).unwrap();
        let ke = rep.history.iter().map(|h| h.kinetic_energy).collect::<Vec<_>>();
        assert!(ke.iter().all(|k| k.is_finite()));
    }
}

#[test]
fn non_finite_state_names_step_and_node() {
    let (scene, model) = column();
    let mut solver = Solver::new(&model, scene.solver.clone()).unwrap();
    let mut state = State::new(&model);
    state.u[3 * 17 + 1] = f64::NAN;
    let err = solver.relax(&model, &mut state, 10).unwrap_err();
    assert!(matches!(err, SolveError::NonFinite { step: 1, .. }), "{err}");
}

#[test]
fn running_out_of_steps_is_reported_not_converged() {
    let (scene, model) = column();
    let mut params = scene.solver.clone();
    params.max_steps = Some(50);
    let mut solver = Solver::new(&model, params).unwrap();
    let mut state = State::new(&model);
    let rep = solver.relax(&model, &mut state, 10).unwrap();
    assert!(!rep.converged);
    assert_eq!(rep.steps, 50);
    assert!(rep.unbalanced_ratio > 1e-7);
}
