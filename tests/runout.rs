//! Runout (references/runout.md): blocks in real time with large
//! displacement and contacts found anew, against 3DEC's sliding and toppling
//! blocks (Itasca, after Wyllie & Mah 2004) and closed forms. The runs and
//! their rows are [`cdem::harness::suite::runout`] (shared with `cdem reproduce`).

use cdem::harness::registry as reg;
use cdem::harness::report::{record, Check};
use cdem::harness::suite::runout;

fn assert_rows(name: &str, rows: &[Check]) {
    record(name, rows);
    for r in rows {
        println!("{}: ours {:.6e} reference {:.6e} {} {}", r.id, r.ours, r.reference, r.ours_text, r.note);
        assert!(r.passed(), "{} fails: ours {} reference {} {}", r.id, r.ours, r.reference, r.ours_text);
    }
}

#[test]
fn the_3dec_sliding_block_travels_as_coulomb_says_across_the_base_faces() {
    let (r, rows) = runout::sliding_rows().unwrap();
    // 7.28 m in 2 s: the block's front crosses four base faces, and the
    // broad phase ran again as it went.
    assert!(r.x_at(2.0) > 7.0 && r.remaps > 100, "travel {} m, {} broad phases", r.x_at(2.0), r.remaps);
    assert_rows("runout_sliding", &rows);
}

#[test]
fn the_3dec_block_at_phi_40_1_stays_at_rest() {
    let (_, row) = runout::at_rest_row().unwrap();
    assert_rows("runout_at_rest", &[row]);
}

#[test]
fn the_3dec_25_m_block_topples() {
    let (r, rows) = runout::toppling_rows().unwrap();
    // It turns over its toe: past 30 degrees within the 3 s run.
    assert!(r.rotation_at(3.0) > 30f64.to_radians());
    assert_rows("runout_toppling", &rows);
}

#[test]
fn a_launched_block_stops_after_v0_squared_over_2_mu_g() {
    let (r, rows) = runout::launched_rows().unwrap();
    assert!(r.x_at(r.track.last().unwrap().0) > 2.0, "more than one base face");
    assert_rows("runout_launched", &rows);
}

#[test]
fn a_dropped_block_lands_at_sqrt_2h_over_g_rebounds_and_comes_to_rest_when_damped() {
    let (r, _, rows) = runout::dropped_rows().unwrap();
    let t = r.first_contact.unwrap();
    let t_ref = (2.0 * reg::RUNOUT_DROP_HEIGHT / reg::RUNOUT_GRAVITY).sqrt();
    // Central differences from rest land within two steps of the exact time.
    assert!((t - t_ref).abs() <= 2.0 * r.dt, "contact at {t} s, exact {t_ref} s, dt {}", r.dt);
    assert_rows("runout_dropped", &rows);
}

#[test]
fn a_free_block_turned_90_degrees_keeps_no_stress() {
    let (r, row) = runout::objectivity_row().unwrap();
    assert!((r.rotation_at(r.track.last().unwrap().0).to_degrees() - 90.0).abs() < 0.5);
    assert_rows("runout_objectivity", &[row]);
}

#[test]
fn runout_is_bit_for_bit_the_same_on_one_and_two_threads() {
    assert_rows("runout_determinism", &[runout::determinism_row().unwrap()]);
}
