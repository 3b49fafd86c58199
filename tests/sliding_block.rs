//! Physical-time runs obey Coulomb friction (references/sliding-block.md):
//! a block on a plane inclined at theta with friction angle phi and no
//! cohesion stays at rest if theta < phi and otherwise slides with
//! acceleration g (sin theta - cos theta tan phi). The runs and their rows
//! are [`cdem::harness::suite::block`] (shared with `cdem reproduce`).

use cdem::harness::registry as reg;
use cdem::harness::suite::block;

#[test]
fn block_below_the_friction_angle_stays_at_rest() {
    let (s, row) = block::at_rest().unwrap();
    println!("theta 15 deg, phi 20 deg: block moved {:.3e} m in {:.3} s", s.x, s.t);
    cdem::harness::report::record("sliding_block_15", std::slice::from_ref(&row));
    assert!(s.phase1_converged, "the bonded block reaches equilibrium");
    // At rest: only elastic wobble. The static shear-spring displacement is
    // W sin(theta) / K_s = 24525 N x 0.259 / 4e9 N/m = 1.6e-6 m; sliding at
    // even 1 % of g would move 0.5 x 0.098 x 0.25 = 1.2e-2 m.
    assert!(s.x.abs() < reg::TOL_BLOCK_AT_REST, "block moved {} m", s.x);
    assert!(row.passed());
}

#[test]
fn block_above_the_friction_angle_slides_with_the_coulomb_acceleration() {
    let (s, row) = block::sliding().unwrap();
    println!("theta 30 deg, phi 20 deg: a = {:.4} m/s^2 (analytic {:.4})", row.ours, row.reference);
    cdem::harness::report::record("sliding_block_30", std::slice::from_ref(&row));
    assert!(s.phase1_converged, "the bonded block reaches equilibrium");
    assert!(row.rel_error() < reg::TOL_SLIDING_BLOCK, "a = {}, analytic {}", row.ours, row.reference);
    assert!(row.passed());
}
