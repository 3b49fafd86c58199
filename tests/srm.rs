//! Strength reduction (`cdem srm`, src/drivers/srm.rs) against the analytic
//! factor of safety of a block on a plane (references/srm.md):
//! `FS = (c A + W cos(theta) tan(phi)) / (W sin(theta))`, for two
//! (theta, phi, c) sets, within 1 %; the analytic FS must also lie inside
//! the final bracket, which is at most 0.01 wide. The runs and their rows are
//! [`cdem::harness::suite::srm`] (shared with `cdem reproduce`).

use cdem::drivers::run_srm;
use cdem::harness::registry as reg;
use cdem::harness::report::record;
use cdem::harness::suite::srm::{self, BRACKET_WIDTH};

#[test]
fn block_on_a_plane_srm_fs_matches_the_analytic_fs() {
    let cases = srm::run_all().unwrap();
    record("srm", &cases.iter().map(|c| c.row.clone()).collect::<Vec<_>>());
    for c in &cases {
        let (r, analytic) = (&c.result, c.analytic);
        let fs = r.fs.expect("a bracket");
        let [lo, hi] = r.bracket.map(Option::unwrap);
        println!(
            "{}: FS {fs:.4} in [{lo:.4}, {hi:.4}], analytic {analytic:.4}, {} trials",
            c.case.name,
            r.trials.len()
        );
        for t in &r.trials {
            println!("  F = {:.4}: {:?} after {} steps", t.factor, t.outcome, t.steps);
        }
        assert!(hi - lo <= BRACKET_WIDTH + 1e-12, "bracket width {}", hi - lo);
        assert!(lo <= analytic && analytic <= hi, "analytic {analytic} outside [{lo}, {hi}]");
        assert!(((fs - analytic) / analytic).abs() < reg::TOL_SRM_BLOCK);
        // The bracket's upper end is a trial that slid, not one out of steps.
        assert_eq!(r.hi_outcome, Some(cdem::EndState::GlobalSliding));
        assert!(r.sliding_from.is_some_and(|f| f >= hi), "{:?}", r.sliding_from);
        assert_eq!(r.undecided, r.trials.iter().filter(|t| t.outcome == cdem::EndState::Undecided).count());
        assert!(c.row.passed(), "{:?}", c.row.defect);
    }
}

/// The row of a reduction whose bracket misses the analytic FS fails, with the reason.
#[test]
fn a_bracket_that_misses_the_analytic_fs_fails_the_row() {
    let (case, set, _) = srm::CASES[0];
    let (r, _) = run_srm(&case.scene().unwrap(), &mut |_| {}).unwrap();
    assert_eq!(srm::defect(&r, set.fs()), None);
    let d = srm::defect(&r, 1.1 * set.fs()).expect("outside the bracket");
    assert!(d.contains("outside the bracket"), "{d}");
}

#[test]
fn srm_needs_a_breakable_interface() {
    let mut scene = reg::BLOCK_SRM_FRICTION.scene().unwrap();
    scene.interface.clear();
    let Err(err) = run_srm(&scene, &mut |_| {}) else { panic!("no breakable interface, yet a result") };
    assert!(err.is_input() && err.to_string().contains("breakable interface"), "{err}");
}

/// Which model answers: real joints between merged blocks (plane failure,
/// `[joints]` merged) carry no interlocking note; the mesh's own faces all
/// breakable between elastic blocks do; plastic blocks do not.
#[test]
fn the_interlocking_note_is_for_breakable_mesh_faces_only() {
    use cdem::drivers::srm::Answer;
    let answer = |path: &str| {
        let scene = cdem::scene::Scene::load(std::path::Path::new(path)).unwrap();
        Answer::of(&cdem::drivers::build_model(&scene).unwrap())
    };
    let plane = answer(reg::PLANE_FAILURE.input);
    assert_eq!((plane.kind, plane.note.is_some()), ("interfaces only", false));
    let joints = answer("verification/plastic/cheng-61/c61-hex-joints.toml");
    assert_eq!((joints.kind, joints.note.is_some()), ("every interface, elastic blocks", true));
    let plastic = answer("verification/plastic/cheng-61/c61-hex.toml");
    assert_eq!((plastic.kind, plastic.note.is_some()), ("plastic blocks", false));
    // Plastic prisms with breakable interfaces average across them (a note);
    // with springs that cannot break, not.
    let text = std::fs::read_to_string("verification/plastic/cheng-61/c61-prism.toml").unwrap();
    let dir = std::path::Path::new("verification/plastic/cheng-61");
    let breakable = text.replace(
        "thickness = 1.0",
        "thickness = 1.0\nstrength = { tensile = 0.0, cohesion = 5.0e3, friction_angle = 30.0, softening = \"ductile\" }",
    );
    let of = |text: &str| {
        Answer::of(&cdem::drivers::build_model(&cdem::scene::Scene::from_toml(text, dir, dir).unwrap()).unwrap())
    };
    assert_eq!(of(&text).note, None);
    assert_eq!(of(&breakable).note.as_deref(), Some(cdem::drivers::srm::NODAL_ACROSS_CRACKS_NOTE));
    // Spring dashpots (docs/method.md 2.9b): on where yielding spreads through the
    // mass (every mesh face breakable), off on real joints and on springs that
    // cannot break.
    assert_eq!((plane.dashpots, joints.dashpots, plastic.dashpots), (false, true, false));
}
