//! The runout step's cost, side by side in one run (issue 56, references/runout.md):
//!
//! 1. **Contact's share of a step on a 1e4-block runout.** A deposit of
//!    100 x 100 unit blocks (each a separate block, 5 mm apart) resting on a
//!    base, launched at 2 m/s down a 30 degree slope with friction 20 degrees:
//!    every block touches the base and is within the contact tolerance of its
//!    neighbours, and the broad phase runs again as they slide. The engine's
//!    stage clock (`Runout::stage_seconds`) gives the share of contact
//!    detection (the broad and the narrow phase) in the step (the issue: at
//!    most 25 %), and with the contact forces (area, law, force).
//! 2. **A quiet model's step against the static step.** The paper's
//!    slope (verification/cases/slope, unbreakable springs) at its elastic state, where nothing moves: the runout
//!    step (corotational blocks, springs, the contact test that finds nothing
//!    to redo) against the failure phase's dynamic-relaxation step on the same
//!    model (the issue: at most 5 % more).
//!
//! Each is timed as the best of 3 runs of a fixed number of steps; the ratios
//! are printed. No criterion: the runs are long and the ratios are the result.

use std::path::Path;
use std::time::Instant;

use cdem::mesh::{Cell, CellKind, Facet, Mesh, PhysicalGroup};
use cdem::scene::Scene;
use cdem::solver::runout::{ContactDefaults, Runout, RunoutDamping, RunoutParams, RunoutState, STAGES};
use cdem::solver::{Solver, SolverParams, State};

/// `side x side` unit blocks `gap` apart on a base slab one element thick.
fn deposit_mesh(side: usize, gap: f64) -> Mesh {
    let mut mesh = Mesh::default();
    let hex = |mesh: &mut Mesh, lo: [f64; 3], hi: [f64; 3]| {
        let first = mesh.nodes.len();
        for &(x, y, z) in &[(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)] {
            let pick = |k: i32, d: usize| if k == 0 { lo[d] } else { hi[d] };
            mesh.nodes.push([pick(x, 0), pick(y, 1), pick(z, 2)]);
            mesh.node_tags.push(mesh.nodes.len() as u64);
        }
        let nodes = [0, 1, 2, 3, 4, 5, 6, 7].map(|k| first + k);
        mesh.cells.push(Cell { kind: CellKind::Hex8, nodes, tag: mesh.cells.len() as u64 + 1 });
        nodes
    };
    let pitch = 1.0 + gap;
    let width = side as f64 * pitch + 2.0;
    let base = hex(&mut mesh, [-1.0, -1.0, -1.0], [width, width, 0.0]);
    for i in 0..side {
        for j in 0..side {
            let lo = [i as f64 * pitch, j as f64 * pitch, 0.0];
            hex(&mut mesh, lo, [lo[0] + 1.0, lo[1] + 1.0, 1.0]);
        }
    }
    let n = mesh.cells.len();
    mesh.groups = vec![
        PhysicalGroup { dim: 3, tag: 1, name: "base".into(), cells: vec![0], facets: Vec::new() },
        PhysicalGroup { dim: 3, tag: 2, name: "block".into(), cells: (1..n).collect(), facets: Vec::new() },
        PhysicalGroup {
            dim: 2,
            tag: 3,
            name: "bottom".into(),
            cells: Vec::new(),
            facets: vec![Facet { nodes: [base[0], base[3], base[2], base[1]], n: 4 }],
        },
    ];
    mesh
}

const DEPOSIT_SCENE: &str = r#"
[mesh]
file = "built-in-code.msh"

[[material]]
group = "base"
youngs_modulus = 1.0e10
poisson_ratio = 0.25
density = 2000.0

[[material]]
group = "block"
youngs_modulus = 1.0e10
poisson_ratio = 0.25
density = 2000.0

[joints]
mode = "merged"
normal_modulus = 1.0e10
shear_modulus = 1.0e10
thickness = 1.0

[[boundary]]
group = "bottom"
fix = ["x", "y", "z"]

[loads]
gravity = [5.0, 0.0, -8.660254037844386]
"#;

fn params() -> RunoutParams {
    RunoutParams {
        duration: 1.0,
        damping: RunoutDamping::None,
        safety: 0.5,
        tolerance: 0.01,
        max_penetration: 0.2,
        rest_velocity: 1e-3,
        rest_time: 0.0,
        contact: ContactDefaults { normal_stiffness: 1e10, shear_stiffness: 1e10, friction_deg: 20.0 },
        stiffness_limit: None,
    }
}

/// Best of `reps` runs of `steps` runout steps from `start`: (seconds per step,
/// the stage seconds of that run, broad phases, contacts at the end).
fn runout_steps(
    model: &cdem::model::Model,
    start: &State,
    v: &[f64],
    steps: usize,
    reps: usize,
) -> (f64, [f64; 6], usize, usize) {
    let mut best = (f64::INFINITY, [0.0; 6], 0, 0);
    for _ in 0..reps {
        let mut engine = Runout::new(model, params(), &start.springs, &start.joints, &start.u).unwrap();
        let mut st = RunoutState::new(start.u.clone(), v.to_vec(), start.springs.clone(), start.joints.clone());
        let t = Instant::now();
        let mut contacts = 0;
        for _ in 0..steps {
            contacts = engine.step(model, &mut st).unwrap().contacts;
        }
        let per = t.elapsed().as_secs_f64() / steps as f64;
        if per < best.0 {
            best = (per, engine.stage_seconds, engine.remaps, contacts);
        }
    }
    best
}

fn stage_table(stages: &[f64; 6]) -> String {
    let total: f64 = stages.iter().sum();
    STAGES.iter().zip(stages).map(|(n, s)| format!("{n} {:.1} %", 100.0 * s / total)).collect::<Vec<_>>().join(", ")
}

fn contact_share() {
    let mesh = deposit_mesh(100, 0.005);
    let scene = Scene::from_toml(DEPOSIT_SCENE, Path::new("."), Path::new("deposit.toml")).unwrap();
    let model = cdem::model::build(&mesh, &scene.model_spec()).unwrap();
    let start = State::new(&model);
    // The blocks (material 1) launched at 2 m/s down the slope; the base at rest.
    let mut v = vec![0.0; start.u.len()];
    let el = &model.elements;
    for e in (0..el.len()).filter(|&e| el.material[e] == 1) {
        for &c in el.corners(e) {
            v[3 * c as usize] = 2.0;
        }
    }
    let steps = 200;
    let (per, stages, remaps, contacts) = runout_steps(&model, &start, &v, steps, 3);
    let total = stages.iter().sum::<f64>();
    let detection = (stages[2] + stages[3]) / total;
    let share = (stages[2] + stages[3] + stages[4]) / total;
    println!(
        "runout, {} blocks: {:.3e} s per step, {remaps} broad phases in {steps} steps, {contacts} contacts; {}",
        model.elements.len() - 1,
        per,
        stage_table(&stages)
    );
    println!(
        "contact detection (broad and narrow phase): {:.1} % of a step (issue 56: at most 25 %); with the contact forces: {:.1} %",
        100.0 * detection,
        100.0 * share
    );
}

fn quiet_overhead() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = Scene::load(&root.join("verification/cases/slope/slope.toml")).unwrap();
    let model = cdem::drivers::build_model(&scene).unwrap();
    // The elastic state: phase 1 (PCG) to 1e-10.
    let params = SolverParams { tolerance: 1e-10, ..scene.solver.clone() };
    let (elastic, _) = cdem::drivers::run::relax_elastic(&model, &params, 0).unwrap();
    let steps = 2000;
    let still = vec![0.0; elastic.u.len()];
    let (runout, stages, remaps, _) = runout_steps(&model, &elastic, &still, steps, 3);
    // The failure phase's step on the same model and state: dynamic relaxation
    // with the failure rules, a fixed number of steps (tolerance 0: never stops early).
    let mut dr = f64::INFINITY;
    for _ in 0..3 {
        let mut st = elastic.clone();
        let p = SolverParams { tolerance: 0.0, max_steps: Some(steps), ..scene.solver.clone() };
        let mut solver = Solver::new(&model, p).unwrap();
        solver.set_failure(&model, true);
        let t = Instant::now();
        let r = solver.relax(&model, &mut st, 0).unwrap();
        dr = dr.min(t.elapsed().as_secs_f64() / r.steps.max(1) as f64);
    }
    println!(
        "quiet model ({} elements, nothing moving): runout step {:.3e} s, failure-phase step {:.3e} s: {:.2} x (issue 56: at most 1.05); {remaps} broad phases in {steps} steps; {}",
        model.elements.len(),
        runout,
        dr,
        runout / dr,
        stage_table(&stages)
    );
}

fn main() {
    contact_share();
    quiet_overhead();
}
