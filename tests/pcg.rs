//! The elastic phase by two-level preconditioned conjugate gradients
//! (`[solver] elastic = "pcg"`, src/solver/pcg.rs): it reaches the state
//! dynamic relaxation reaches, on every case of the paper and of the stiff
//! and extreme suite; its iteration count stays bounded under refinement;
//! loss of positive definiteness and non-finite values are typed errors;
//! phase 2 starts from its state; results do not depend on the thread count.

use std::path::Path;

use cdem::analysis::compare::relative_l2_between_copies;
use cdem::drivers::run::relax_elastic;
use cdem::drivers::{build_model, run_scene};
use cdem::harness::registry::{self as reg, extreme_cases, measured_top_uz, SLOPE_MESHES};
use cdem::model::Model;
use cdem::scene::Scene;
use cdem::solver::relax::unobserved;
use cdem::solver::{ElasticSolver, Pcg, SolverParams, State, StopRules};
use cdem::{Error, SceneError, SolveError};

/// Agreement of the two solvers, as a multiple of the scene's tolerance on
/// the unbalanced-force ratio: the relative L2 difference of the
/// displacements (section 4.2 of docs/method.md) may be at most this many
/// tolerances. Measured at the time of writing: at most 1.9 (Wulong);
/// both solvers stop at a ratio below the tolerance, and a residual of
/// that size moves the displacement by about as much, relative.
const AGREEMENT: f64 = 5.0;

fn with_elastic(scene: &Scene, elastic: ElasticSolver) -> Scene {
    let mut s = scene.clone();
    s.solver.elastic = elastic;
    s
}

/// Phase 1 of `scene` by both solvers: `(relative L2 difference, tolerance,
/// PCG iterations, DR steps)`; both must converge.
fn compare(name: &str, scene: &Scene) -> (f64, f64, usize, usize) {
    let model = build_model(scene).unwrap();
    let run = |e| {
        let params = SolverParams { elastic: e, ..scene.solver.clone() };
        let (state, report) = relax_elastic(&model, &params, 10).unwrap_or_else(|err| panic!("{name}: {err}"));
        assert!(report.converged, "{name}: {e:?} did not converge ({} steps)", report.steps);
        assert!(report.unbalanced_ratio < scene.solver.tolerance);
        (state, report.steps)
    };
    let (pcg, iterations) = run(ElasticSolver::Pcg);
    let (dr, steps) = run(ElasticSolver::Dr);
    let diff = if dr.u.iter().all(|&v| v == 0.0) {
        pcg.u.iter().fold(0.0f64, |a, v| a.max(v.abs()))
    } else {
        relative_l2_between_copies(&model, &pcg.u, &dr.u)
    };
    println!("{name}: PCG {iterations} iterations, DR {steps} steps, relative L2 difference {diff:.2e}");
    (diff, scene.solver.tolerance, iterations, steps)
}

/// The column, the paper slope, the slip-surface slope and Wulong's phase 1.
#[test]
fn pcg_and_dr_agree_on_the_paper_cases() {
    for case in [reg::COLUMN, reg::COLUMN_MERGED, reg::SLOPE, reg::SLOPE_SLIP, reg::WULONG] {
        let scene = case.elastic_scene().unwrap();
        let (diff, tol, iterations, steps) = compare(case.name, &scene);
        assert!(diff <= AGREEMENT * tol, "{}: difference {diff:.2e} > {AGREEMENT} x {tol:.0e}", case.name);
        assert!(iterations < steps / 10, "{}: {iterations} iterations against {steps} steps", case.name);
    }
}

/// Every case of the stiff and extreme suite: the two solvers agree, and
/// PCG's top u_z matches the analytic answer within the case's tolerance
/// (references/extreme.md).
#[test]
fn pcg_and_dr_agree_on_the_stiff_and_extreme_suite() {
    for case in extreme_cases() {
        let scene = case.scene().unwrap();
        let (diff, tol, _, _) = compare(case.name, &scene);
        assert!(diff <= AGREEMENT * tol, "{}: difference {diff:.2e} > {AGREEMENT} x {tol:.0e}", case.name);
        let run = run_scene(&with_elastic(&scene, ElasticSolver::Pcg), &mut |_, _| {}).unwrap();
        assert!(run.summary.converged, "{}", case.name);
        let ours = measured_top_uz(&run);
        let err = if case.reference == 0.0 { ours.abs() } else { ((ours - case.reference) / case.reference).abs() };
        assert!(err <= case.tolerance, "{}: top u_z {ours:.6e}, analytic {:.6e}", case.name, case.reference);
        if case.name == "zero-gravity" {
            assert!(run.state.u.iter().all(|&v| v == 0.0), "zero load must stay exactly at rest");
        }
    }
}

/// The paper slope at 250, 1000, 4000 and 16,000 hexahedra (the committed
/// meshes of [`SLOPE_MESHES`], refine 0.5 to 4): PCG converges at every size
/// in at most twice the iterations of the coarsest (at the time of
/// writing 8, 9, 9, 11), where dynamic relaxation needs about 4x more steps
/// from the smallest to the largest (405 to 3226, references/performance.md).
#[test]
fn pcg_iterations_stay_bounded_under_refinement() {
    let base = reg::SLOPE.elastic_scene().unwrap();
    let mut iterations = Vec::new();
    for (refine, mesh) in SLOPE_MESHES {
        let mut scene = with_elastic(&base, ElasticSolver::Pcg);
        scene.mesh.file = Path::new(mesh).canonicalize().unwrap();
        let model = build_model(&scene).unwrap();
        let (_, report) = relax_elastic(&model, &scene.solver, 10).unwrap();
        println!("refine {refine}: {} hexahedra, {} iterations", model.elements.len(), report.steps);
        assert!(report.converged, "refine {refine}");
        iterations.push((model.elements.len(), report.steps));
    }
    let (first, last) = (iterations[0], iterations[iterations.len() - 1]);
    assert_eq!((first.0, last.0), (250, 16_000));
    assert!(last.1 <= 2 * first.1, "{iterations:?}");
}

/// The same bits with one and two threads, on the paper slope and on its
/// 16,000-hex mesh (where faer's parallel Cholesky, which the coarse space
/// therefore does not use, gave different bits).
#[test]
fn pcg_is_thread_count_independent() {
    for mesh in [SLOPE_MESHES[1].1, SLOPE_MESHES[3].1] {
        let mut scene = with_elastic(&reg::SLOPE.elastic_scene().unwrap(), ElasticSolver::Pcg);
        scene.mesh.file = Path::new(mesh).canonicalize().unwrap();
        let model = build_model(&scene).unwrap();
        let bits = |threads| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            let (state, report) = pool.install(|| relax_elastic(&model, &scene.solver, 1)).unwrap();
            let mut b: Vec<u64> = state.u.iter().chain(&state.f_int).map(|v| v.to_bits()).collect();
            b.extend(report.history.iter().map(|h| h.unbalanced_ratio.to_bits()));
            b
        };
        assert!(bits(1) == bits(2), "{mesh}: 1 and 2 threads differ");
    }
}

fn column_model() -> Model {
    build_model(&reg::COLUMN.elastic_scene().unwrap()).unwrap()
}

fn rules() -> StopRules<'static> {
    StopRules { tolerance: 1e-8, max_steps: 100, sliding: None, foresight: None, history_every: 1 }
}

/// A stiffness that is not positive definite: the preconditioner of the
/// column with the element and spring stiffnesses of the solved model
/// negated, so the first search direction has `p . K p < 0`.
#[test]
fn loss_of_positive_definiteness_is_a_typed_error() {
    let model = column_model();
    let mut pcg = Pcg::new(&model).unwrap();
    let mut negative = model.clone();
    negative.elements.k.iter_mut().for_each(|k| *k = -*k);
    negative.springs.kn.iter_mut().for_each(|k| *k = -*k);
    negative.springs.ks.iter_mut().for_each(|k| *k = -*k);
    let mut state = State::new(&negative);
    match pcg.solve(&negative, &mut state, &rules(), &mut unobserved) {
        Err(SolveError::NotPositiveDefiniteCg { iteration: 1, pkp }) => assert!(pkp < 0.0),
        other => panic!("expected NotPositiveDefiniteCg at iteration 1, got {:?}", other.map(|r| r.steps)),
    }
}

/// A non-finite load is a typed error, never a converged state.
#[test]
fn non_finite_values_are_a_typed_error() {
    let mut model = column_model();
    let k = (0..model.fixed.len()).find(|&k| !model.fixed[k]).unwrap();
    model.f_ext[k] = f64::NAN;
    let mut pcg = Pcg::new(&model).unwrap();
    let mut state = State::new(&model);
    match pcg.solve(&model, &mut state, &rules(), &mut unobserved) {
        Err(SolveError::NonFinite { step: 1, .. }) => {}
        other => panic!("expected NonFinite at step 1, got {:?}", other.map(|r| r.steps)),
    }
}

/// An unsupported model fails in the coarse factorisation, typed.
#[test]
fn an_unsupported_model_is_a_typed_error() {
    let mut model = column_model();
    model.fixed.iter_mut().for_each(|f| *f = false);
    assert!(matches!(Pcg::new(&model), Err(SolveError::NotPositiveDefinite { .. })));
}

/// `elastic` takes "dr" or "pcg"; anything else is refused naming the key.
#[test]
fn an_unknown_elastic_solver_is_refused_naming_the_key() {
    let path = Path::new("verification/cases/column/column-merged.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let parse = |t: &str| Scene::from_toml(t, Path::new("verification/cases/column"), path);
    assert!(text.contains("[solver]\n"));
    let with = |v: &str| text.replace("[solver]\n", &format!("[solver]\nelastic = \"{v}\"\n"));
    assert_eq!(parse(&with("pcg")).unwrap().solver.elastic, ElasticSolver::Pcg);
    assert_eq!(parse(&with("dr")).unwrap().solver.elastic, ElasticSolver::Dr);
    match parse(&with("cg")) {
        Err(e @ SceneError::Syntax { .. }) => {
            let m = e.to_string();
            assert!(m.contains("elastic") && m.contains("`dr`") && m.contains("`pcg`"), "{m}");
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
}

/// Phase 2 starts from the state PCG left: the slip-surface slope with
/// one phase-2 step. Its elastic state is PCG's bit for bit, and the
/// springs that fail at that first step (those that violate eq. 17-18 at
/// the elastic state) are the same as from dynamic relaxation's state.
#[test]
fn phase_two_starts_from_the_pcg_state() {
    let mut scene = reg::SLOPE_SLIP.scene().unwrap();
    let failure = scene.failure.as_mut().expect("the slip scene has [failure]");
    failure.max_steps = Some(1);
    failure.stage_every = 1;
    scene.output.vtk = false;
    let pcg = run_scene(&with_elastic(&scene, ElasticSolver::Pcg), &mut |_, _| {}).map_err(|e: Error| e).unwrap();
    let model = build_model(&scene).unwrap();
    let params = SolverParams { elastic: ElasticSolver::Pcg, ..scene.solver.clone() };
    let (state, report) = relax_elastic(&model, &params, usize::MAX).unwrap();
    let f = pcg.failure.as_ref().unwrap();
    assert!(f.u_elastic == state.u, "phase 2 did not start from the PCG state");
    assert_eq!(pcg.summary.phase1.as_ref().unwrap().steps, report.steps);
    assert_eq!(pcg.summary.phase2.as_ref().unwrap().steps, 1);
    let dr = run_scene(&with_elastic(&scene, ElasticSolver::Dr), &mut |_, _| {}).unwrap();
    let failed = |r: &cdem::drivers::RunResult| r.failure.as_ref().unwrap().failed_at.clone();
    let (a, b) = (failed(&pcg), failed(&dr));
    println!("failed at the first phase-2 step: PCG {}, DR {}", a.iter().flatten().count(), b.iter().flatten().count());
    assert!(a.iter().flatten().count() > 0);
    assert_eq!(a, b);
}
