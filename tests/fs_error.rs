//! A factor of safety that states its own discretisation error (issue 61;
//! references/srm.md, "Discretisation error"). Plastic blocks converge to
//! their factor from the unsafe side as the mesh is refined: Griffiths &
//! Lane's committed hexahedra (384) and gmsh's refinements of their `.geo`
//! (864, 1536), each reduction bisected to 0.0025, extrapolate by
//! Richardson to a factor below the committed mesh's; the committed mesh
//! errs on the unsafe side; and what the two-mesh check tells a user (first
//! order assumed, Roache's safety factor 3) covers what the third mesh
//! finds. Needs gmsh on PATH (as CI installs it). About 5 minutes on 2
//! cores.

use cdem::harness::report::record;
use cdem::harness::suite::fserror::gl1_rows;

#[test]
fn griffiths_and_lanes_factor_states_its_discretisation_error_and_side() {
    let run = gl1_rows(&mut |what| println!("{what}")).expect("the check");
    let three = run.three();
    for m in &three.meshes {
        println!(
            "refine {}: {} elements, FS {:?} {:?} ({:?}), {} trials, {:.1} s",
            m.refine, m.elements, m.fs, m.bracket, m.hi_outcome, m.trials, m.wall_s
        );
    }
    println!("three meshes: {}", three.line);
    println!("two meshes: {}", run.two.line);
    for row in &run.rows {
        println!("{}: {} vs {} ({:?}) {}", row.id, row.ours, row.reference, row.status(), row.note);
    }
    // Every mesh found a factor, its bracket at most the check's width.
    for m in &three.meshes {
        let [Some(lo), Some(hi)] = m.bracket else { panic!("refine {}: no bracket {:?}", m.refine, m.bracket) };
        assert!(hi - lo <= three.bracket_width + 1e-12, "refine {}: [{lo}, {hi}]", m.refine);
    }
    assert!(three.meshes.windows(2).all(|w| w[1].elements > w[0].elements), "the meshes grow");
    let band = run.result.slip_band.as_ref().expect("a slip band on the committed mesh");
    println!("committed mesh's slip band: {} elements along, {:.2} across", band.along, band.across);
    assert!(run.rows.iter().all(|r| r.passed()), "{:?}", run.rows.iter().filter(|r| !r.passed()).collect::<Vec<_>>());
    record("fs_error", &run.rows);
}
