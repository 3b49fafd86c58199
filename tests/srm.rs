//! Strength reduction (`cdem srm`, src/drivers/srm.rs) against the analytic
//! factor of safety of a block on a plane (references/srm.md):
//! `FS = (c A + W cos(theta) tan(phi)) / (W sin(theta))`, for two
//! (theta, phi, c) sets, within 1 %; the analytic FS must also lie inside
//! the final bracket, which is at most 0.01 wide.

use cdem::drivers::run_srm;
use cdem::harness::registry::{self as reg, BlockOnPlane, Case};
use cdem::harness::report::{record, Check};

fn check(case: Case, set: BlockOnPlane) -> Check {
    let t0 = std::time::Instant::now();
    let scene = case.scene().unwrap();
    let (r, _) = run_srm(&scene, &mut |_| {}).unwrap();
    let analytic = set.fs();
    let fs = r.fs.expect("a bracket");
    let [lo, hi] = r.bracket.map(Option::unwrap);
    println!("{}: FS {fs:.4} in [{lo:.4}, {hi:.4}], analytic {analytic:.4}, {} trials", case.name, r.trials.len());
    for t in &r.trials {
        println!("  F = {:.4}: {:?} after {} steps", t.factor, t.outcome, t.steps);
    }
    assert!(hi - lo <= 0.01 + 1e-12, "bracket width {}", hi - lo);
    assert!(lo <= analytic && analytic <= hi, "analytic {analytic} outside [{lo}, {hi}]");
    assert!(((fs - analytic) / analytic).abs() < reg::TOL_SRM_BLOCK);
    // The bracket's upper end is a trial that slid, not one out of steps.
    assert_eq!(r.hi_outcome, Some(cdem::EndState::GlobalSliding));
    assert!(r.sliding_from.is_some_and(|f| f >= hi), "{:?}", r.sliding_from);
    assert_eq!(r.undecided, r.trials.iter().filter(|t| t.outcome == cdem::EndState::Undecided).count());
    let id = if case.name == reg::BLOCK_SRM_FRICTION.name { "srm/block-friction" } else { "srm/block-cohesion" };
    reg::row(id).value(fs, analytic, t0.elapsed().as_secs_f64())
}

#[test]
fn block_on_a_plane_srm_fs_matches_the_analytic_fs() {
    let rows = vec![
        check(reg::BLOCK_SRM_FRICTION, reg::BLOCK_SRM_FRICTION_SET),
        check(reg::BLOCK_SRM_COHESION, reg::BLOCK_SRM_COHESION_SET),
    ];
    record("srm", &rows);
}

#[test]
fn srm_needs_a_breakable_interface() {
    let mut scene = reg::BLOCK_SRM_FRICTION.scene().unwrap();
    scene.interface.clear();
    let Err(err) = run_srm(&scene, &mut |_| {}) else { panic!("no breakable interface, yet a result") };
    assert!(err.is_input() && err.to_string().contains("breakable interface"), "{err}");
}
