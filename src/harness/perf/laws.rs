//! The cost of a joint law in the force stage (issue 58: Barton-Bandis
//! springs at most 1.2 times Coulomb springs): the failure-phase spring pass
//! ([`crate::solver::forces::spring_forces_with_failure`]) over every spring
//! of the paper slope, once with every spring a Coulomb joint and once a
//! Barton-Bandis joint, at the same displacement field (every spring's
//! history reset before each pass), in alternating batches on one thread;
//! the medians' ratio. Two fields: the slope's elastic state under gravity
//! (the row: springs in compression, most below their residual strength, as
//! in a slope before it fails) and a rough field of 1 mm that loads springs
//! in tension and far past their peak (the note: the worst case, where
//! every compressed spring evaluates its envelope).

use std::path::Path;
use std::time::Instant;

use crate::error::Error;
use crate::harness::report::Check;
use crate::physics::joint::{BartonBandisSection, CoulombSection, JointState, JointStrength, Softening};
use crate::physics::spring::SpringState;
use crate::solver::forces::spring_forces_with_failure;

/// What [`spring_law_cost`] measured.
#[derive(Debug, Clone, Copy)]
pub struct SpringLawCost {
    pub springs: usize,
    /// Median pass times (s) at the elastic state under gravity.
    pub coulomb_s: f64,
    pub barton_bandis_s: f64,
    /// The same at the rough field.
    pub rough_coulomb_s: f64,
    pub rough_barton_bandis_s: f64,
}

/// Times `batches` alternating batches of 20 passes of each law (one
/// thread, the paper slope's springs; a smooth displacement field of 1 mm
/// that loads springs in tension, in compression below and above their
/// residual strength).
pub fn spring_law_cost(root: &Path, batches: usize) -> Result<SpringLawCost, Error> {
    let scene = crate::scene::Scene::load(&root.join(crate::harness::registry::SLOPE.input))?;
    let run = crate::drivers::run_scene(&scene, &mut |_, _| {})?;
    let model = run.model;
    let n = model.springs.len();
    let rough: Vec<f64> = (0..3 * model.n_nodes()).map(|k| 1e-3 * (0.37 * k as f64).sin()).collect();
    let coulomb =
        CoulombSection { tensile: 0.0, cohesion: 10e3, friction_angle: 30.0, softening: Softening::Brittle }.strength();
    let bb = BartonBandisSection {
        jrc: 10.0,
        jcs: 50e6,
        residual_friction_angle: 28.0,
        max_friction_angle: 70.0,
        tensile: 0.0,
        softening: Softening::Brittle,
    }
    .strength();
    let states = [
        JointState { strength: vec![Some(JointStrength::Coulomb(coulomb)); n] },
        JointState { strength: vec![Some(JointStrength::BartonBandis(bb)); n] },
    ];
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .map_err(|e| Error::io("rayon thread pool", std::io::Error::other(e.to_string())))?;
    let mut f = vec![[0.0; 3]; n];
    let mut time = |u: &[f64]| {
        let mut times = [Vec::new(), Vec::new()];
        pool.install(|| {
            for _ in 0..batches.max(1) {
                for (joints, t) in states.iter().zip(times.iter_mut()) {
                    for _ in 0..20 {
                        let mut springs = SpringState::new(n);
                        let t0 = Instant::now();
                        spring_forces_with_failure(&model, joints, &mut springs, u, None, &mut f);
                        t.push(t0.elapsed().as_secs_f64());
                        std::hint::black_box(&f);
                    }
                }
            }
        });
        times.map(|mut t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2]
        })
    };
    let [coulomb_s, barton_bandis_s] = time(&run.state.u);
    let [rough_coulomb_s, rough_barton_bandis_s] = time(&rough);
    Ok(SpringLawCost { springs: n, coulomb_s, barton_bandis_s, rough_coulomb_s, rough_barton_bandis_s })
}

/// The row `perf/laws/bb-over-coulomb-springs`.
pub fn spring_law_row(c: &SpringLawCost) -> Check {
    crate::harness::registry::row("perf/laws/bb-over-coulomb-springs")
        .value(c.barton_bandis_s / c.coulomb_s, 1.2, c.barton_bandis_s)
        .with_note(format!(
            "{} springs of the paper slope's elastic state, one thread: Coulomb {:.3} ms, Barton-Bandis {:.3} ms a \
             pass (medians); a rough 1 mm field that takes every compressed spring past its residual: {:.2} times",
            c.springs,
            c.coulomb_s * 1e3,
            c.barton_bandis_s * 1e3,
            c.rough_barton_bandis_s / c.rough_coulomb_s
        ))
}
