//! Progressive failure of the paper slope (Fig. 10): failure judged only on
//! the LEM critical circle (interface "slip" of verification/cases/slope-slip/),
//! c = 16 kPa, phi = 18 deg, T = 16 kPa, brittle loss of cohesion.
//!
//! Physics asserted: the first springs to fail are exactly those that violate
//! eq. 17-18 at the elastic state, where the elastic K_i (eq. 22) is lowest;
//! with the cohesion gone the friction-only eq. 21 of the elastic state is
//! below 1, so the mass must slide, and it does (global sliding), although
//! the LEM gives FS 1.089. The zones (the surface cut where the elastic K_i
//! crosses 1, lettered from the toe) and their first- and full-failure order
//! are [`cdem::harness::suite::slope_failure`] (shared with `cdem
//! reproduce`): the sequence is an insta snapshot, both orders of all five
//! zones are reported rows, and the paper's order as a reader takes it is
//! asserted (row `slope-failure/order-vs-paper`, references/paper.md).
//! Writes target/figures/fig10-*.png.

use std::path::Path;

use cdem::analysis::slip::spring_points;
use cdem::drivers::{run_watched, EndState, StageSnapshots};
use cdem::harness::registry::{self as reg, SLIP_CIRCLE};
use cdem::harness::reproduce::stage_figures;
use cdem::harness::suite::slope_failure::SlopeFailure;
use cdem::solver::State;

#[test]
fn slope_fails_progressively_from_the_low_ki_zones_and_slides() {
    let t0 = std::time::Instant::now();
    let scene = reg::SLOPE_SLIP.scene().unwrap();
    let mut snapshots = StageSnapshots::default();
    let run = run_watched(&scene, &mut snapshots).unwrap();
    let seconds = t0.elapsed().as_secs_f64();
    let r = run.failure.as_ref().expect("phase 2 ran");
    let tan_phi = reg::SLIP_FRICTION_DEG.to_radians().tan();
    let f = SlopeFailure::of(&run).expect("phase 2 on the interface slip");
    println!("elastic eq. 21: K = {:.4}; friction only (c lost): {:.4}", f.k, f.k_friction_only);
    assert!(f.k_friction_only < 1.0, "without cohesion the surface must be over-stressed");
    let first_step = f.first_step.expect("springs fail");

    // Exactly the springs that violate eq. 17-18 at the elastic state, in
    // their own frame (recomputed here from the spring law), fail at the
    // first phase-2 step.
    let sp = &run.model.springs;
    let iface = run.model.interfaces.iter().position(|i| i.name == "slip").unwrap() as u16;
    let (c, t_strength) = (reg::SLIP_COHESION, reg::SLIP_TENSILE);
    for s in (0..sp.len()).filter(|&s| sp.interface[s] == iface) {
        let (a, b) = (sp.a[s] as usize, sp.b[s] as usize);
        let n = sp.normal[s];
        let d: Vec<f64> = (0..3).map(|i| r.u_elastic[3 * b + i] - r.u_elastic[3 * a + i]).collect();
        let dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
        let f_n = sp.kn[s] * dn;
        let f_s = (0..3).map(|i| (sp.ks[s] * (d[i] - dn * n[i])).powi(2)).sum::<f64>().sqrt();
        let violated = f_n >= t_strength * sp.area[s] || f_s > (-f_n).max(0.0) * tan_phi + c * sp.area[s];
        assert_eq!(
            r.failed_at[s] == Some(first_step),
            violated,
            "spring {s}: failed at {:?}, eq. 17-18 violated {violated}",
            r.failed_at[s]
        );
    }
    // And they are where K_i (circle frame, eq. 22) is lowest.
    let mut elastic = State::new(&run.model);
    elastic.u = r.u_elastic.clone();
    let per_spring = spring_points(&run.model, &elastic.u, &elastic.springs, "slip", &SLIP_CIRCLE).unwrap();
    let ki = |p: &cdem::analysis::SurfacePoint| (p.sigma_n * tan_phi + c) / p.tau;
    let (mut first_k, mut later_k) = (Vec::new(), Vec::new());
    for (s, p) in &per_spring {
        if ki(p) > 0.0 {
            if r.failed_at[*s] == Some(first_step) {
                first_k.push(ki(p))
            } else {
                later_k.push(ki(p))
            }
        }
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    println!(
        "{} springs fail at step {first_step}: mean K_i {:.3} (max {:.3}); the others mean K_i {:.3}",
        first_k.len(),
        mean(&first_k),
        first_k.iter().cloned().fold(0.0, f64::max),
        mean(&later_k)
    );
    assert!(mean(&first_k) < 1.0 && mean(&first_k) < mean(&later_k), "the first failures are where K_i is lowest");
    assert_eq!(r.end, EndState::GlobalSliding, "the mass slides once the cohesion is lost");

    // The zones, both orders, the snapshot and the paper's order.
    let sequence = f.sequence();
    for line in &sequence {
        println!("{line}");
    }
    println!("{}", f.describe_start());
    let rows = f.rows(seconds);
    for row in &rows {
        println!("{}: {} ({:?})", row.id, row.ours_text, row.status());
    }
    cdem::harness::report::record("progressive_slope", &rows);
    assert!(
        f.paper_order(),
        "the paper's order: failure starts in the K_i < 1 zones, spreads to the K_i >= 1 zones, then the slide: {}",
        f.describe_start()
    );
    // The check can fail: with the zones' kinds swapped the failure would
    // start where K_i >= 1, and the row differs.
    let mut swapped = f.clone();
    swapped.zones.iter_mut().for_each(|z| z.weak = !z.weak);
    assert!(!swapped.paper_order(), "swapped zones must not match the paper's order");
    insta::assert_yaml_snapshot!("slope_failure_sequence", sequence);

    // Fig. 10: the displacement since phase 1 at four stages on one figure
    // (the figure of `cdem reproduce`).
    std::fs::create_dir_all("target/figures").unwrap();
    let files = stage_figures(&run, &snapshots, Path::new("target/figures"), "fig10").unwrap();
    assert_eq!(files.len(), 1);
}

/// A stable slope with a weak interface: the slip circle with phi = 35 deg
/// (LEM Bishop 1.93 on that circle, references/lem.md). The springs that
/// violate eq. 17-18 at the elastic state fail, the load they shed is carried,
/// and phase 2 ends in Equilibrium well inside its step budget.
#[test]
fn a_stable_slope_with_a_weak_interface_reaches_equilibrium_in_phase_2() {
    let scene = reg::SLOPE_SLIP_STABLE.scene().unwrap();
    let run = run_watched(&scene, &mut StageSnapshots::default()).unwrap();
    let r = run.failure.as_ref().expect("phase 2 ran");
    let p2 = run.summary.phase2.as_ref().unwrap();
    println!(
        "phase 2: {:?} after {} steps, {} shear / {} tension failures, {:.3e} m since phase 1",
        r.end, p2.steps, p2.failed_springs.shear, p2.failed_springs.tension, p2.max_displacement
    );
    assert_eq!(r.end, EndState::Equilibrium);
    assert!(p2.failed_springs.shear + p2.failed_springs.tension > 0, "some springs fail: the interface is weak");
    assert!(r.report.unbalanced_ratio < scene.solver.tolerance);
    // Settles: the displacement since phase 1 is a small fraction of the
    // elastic settlement (4.2e-2 m).
    assert!(p2.max_displacement < 5e-3, "{}", p2.max_displacement);
}
