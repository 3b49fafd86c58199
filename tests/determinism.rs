//! Results for a given scene and seed are bit for bit the same across runs
//! and thread counts (forces are gathered per node in a fixed order).

use cdem::drivers::run_scene;

/// Summary (without wall time) and history of a 2000-step run of the
/// perturbed slope by dynamic relaxation, as raw bits (PCG's own check:
/// tests/pcg.rs).
fn fingerprint(threads: usize) -> Vec<u64> {
    let mut scene = cdem::harness::registry::SLOPE.scene().unwrap();
    scene.solver.max_steps = Some(2000);
    scene.solver.elastic = cdem::solver::ElasticSolver::Dr;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    let r = pool.install(|| run_scene(&scene, &mut |_, _| {})).unwrap();
    let s = &r.summary;
    let mut bits: Vec<u64> = vec![s.steps as u64, s.max_abs_uz.to_bits(), s.min_uz.to_bits(), s.max_abs_u.to_bits()];
    bits.push(s.min_szz.unwrap().to_bits());
    bits.push(s.unbalanced_ratio.to_bits());
    for h in &r.elastic.history {
        bits.extend(
            [h.kinetic_energy, h.external_work, h.strain_energy, h.unbalanced_ratio, h.max_displacement]
                .map(f64::to_bits),
        );
    }
    bits.extend(r.state.u.iter().map(|v| v.to_bits()));
    bits
}

#[test]
fn same_seed_same_bits_with_one_and_two_threads_and_across_runs() {
    let one = fingerprint(1);
    let two = fingerprint(2);
    let again = fingerprint(2);
    assert_eq!(one.len(), two.len());
    assert!(one == two, "1 and 2 threads differ");
    assert!(two == again, "two runs differ");
}
