//! Constitutive laws (references/laws.md): Barton-Bandis joints. The
//! direct shear test against the envelope, the scene's keys and their
//! errors, and strength reduction of Hoek & Bray's plane failure with a
//! Barton-Bandis sliding plane against the closed form, dry and with the
//! tension crack full of water (the runs and rows are
//! [`cdem::harness::suite::laws`], shared with `cdem reproduce`).

use std::path::Path;

use cdem::harness::registry as reg;
use cdem::harness::report::record;
use cdem::harness::suite::laws;
use cdem::scene::Scene;
use cdem::SceneError;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The registry's envelope gives issue 58's quoted 1.192 MPa at 1 MPa, and
/// the plane-failure closed forms the numbers references/laws.md states
/// (computed there by an independent one-line script).
#[test]
fn the_closed_forms_equal_the_quoted_numbers() {
    let at_1 = reg::BB_SHEAR_JOINT.tau(1e6);
    assert!((at_1 - reg::BB_SHEAR_AT_1MPA_QUOTED).abs() < 0.5e3, "{at_1}");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    for (k, s) in reg::BB_SHEAR_STRESSES.into_iter().enumerate() {
        assert!(close(reg::BB_SHEAR_JOINT.tau(s), reg::BB_SHEAR_PEAKS[k]), "{s}");
    }
    assert!(close(1e6 * 30f64.to_radians().tan(), reg::BB_SHEAR_RESIDUAL_1MPA));
    let [dry, wet] = laws::plane_closed_forms();
    assert!(close(dry, reg::BB_PLANE_FS_DRY) && close(wet, reg::BB_PLANE_FS_WET), "{dry} {wet}");
    assert!((dry - 1.36960).abs() < 1e-5 && (wet - 0.73028).abs() < 1e-5, "{dry} {wet}");
    // The conventions: the cap at low stress, no negative roughness above JCS.
    let j = reg::BB_SHEAR_JOINT;
    assert!((j.tau(1.0) - 70f64.to_radians().tan()).abs() < 1e-12);
    assert!((j.tau(200e6) / 200e6 - 30f64.to_radians().tan()).abs() < 1e-15);
}

#[test]
fn direct_shear_peaks_and_residual_follow_the_envelope() {
    let rows = laws::shear_rows();
    record("laws-shear", &rows);
    for r in &rows {
        println!("{}: ours {:.6e}, reference {:.6e}", r.id, r.ours, r.reference);
        assert!(r.passed(), "{}: {:?} (ours {}, reference {})", r.id, r.defect, r.ours, r.reference);
    }
}

fn plane_scene_with(edit: &str, with: &str) -> Result<Scene, cdem::Error> {
    let path = root().join(reg::PLANE_BB.input);
    let text = std::fs::read_to_string(&path).unwrap();
    let edited = text.replacen(edit, with, 1);
    assert_ne!(edited, text, "{edit:?} is not in the scene");
    let dir = std::env::temp_dir().join(format!("cdem-laws-{}-{}", std::process::id(), with.len()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(root().join("verification/joints/plane.msh"), dir.join("plane.msh")).unwrap();
    let p = dir.join("scene.toml");
    std::fs::write(&p, edited.replace("../joints/plane.msh", "plane.msh")).unwrap();
    let scene = Scene::load(&p)?;
    cdem::drivers::build_model(&scene)?;
    Ok(scene)
}

/// Bad Barton-Bandis values are errors naming the key; an unknown law and
/// an unknown or missing key are syntax errors naming them.
#[test]
fn bad_barton_bandis_keys_are_errors_naming_them() {
    plane_scene_with("jrc = 6.0", "jrc = 6.00").unwrap();
    let cases = [
        ("jrc = 6.0", "jrc = 25.0", "interface[0].strength.jrc"),
        ("jcs = 40.0e6", "jcs = 0.0", "interface[0].strength.jcs"),
        (
            "residual_friction_angle = 25.0",
            "residual_friction_angle = 95.0",
            "interface[0].strength.residual_friction_angle",
        ),
        ("jrc = 6.0", "jrc = 6.0, max_friction_angle = 20.0", "interface[0].strength.max_friction_angle"),
        ("jrc = 6.0", "jrc = 6.0, tensile = -1.0", "interface[0].strength.tensile"),
    ];
    for (edit, with, key) in cases {
        match plane_scene_with(edit, with) {
            Err(cdem::Error::Scene(SceneError::Invalid { key: k, reason })) => assert_eq!(k, key, "{with}: {reason}"),
            other => panic!("{with}: expected an error naming {key}, got {other:?}"),
        }
    }
    for (edit, with, word) in [
        ("law = \"barton_bandis\"", "law = \"barton\"", "barton"),
        ("jrc = 6.0", "jcr = 6.0", "jcr"),
        ("jrc = 6.0, ", "", "jrc"),
        ("jrc = 6.0", "jrc = 6.0, cohesion = 1.0", "cohesion"),
    ] {
        match plane_scene_with(edit, with) {
            Err(cdem::Error::Scene(SceneError::Syntax { message, .. })) => {
                assert!(message.contains(word), "{with}: {message}")
            }
            other => panic!("{with}: expected a syntax error naming {word}, got {other:?}"),
        }
    }
}

fn run_plane(i: usize, test: &str) {
    let (case, closed, id) = laws::plane_cases()[i];
    let (row, r) = laws::plane(case, closed, id).unwrap();
    record(test, std::slice::from_ref(&row));
    let [lo, hi] = r.bracket.map(|b| b.unwrap_or(f64::NAN));
    println!(
        "{}: FS {:.4} in [{lo:.4}, {hi:.4}], closed form {closed:.4}, error {:+.2} %, {:.1} s",
        case.name,
        r.fs.unwrap_or(f64::NAN),
        100.0 * (r.fs.unwrap_or(f64::NAN) - closed) / closed,
        r.wall_s
    );
    for t in &r.trials {
        println!("  F = {:.4}: {:?} after {} steps", t.factor, t.outcome, t.steps);
    }
    assert!(row.passed(), "{:?}", row.defect);
}

#[test]
fn plane_failure_on_a_barton_bandis_joint_matches_the_closed_form() {
    run_plane(0, "laws-plane");
}

#[test]
fn plane_failure_on_a_barton_bandis_joint_with_a_full_crack_matches_the_closed_form() {
    run_plane(1, "laws-plane-wet");
}
