//! Bad scenes are typed errors that name the key; nothing panics.

use std::path::Path;

use cdem::scene::Scene;
use cdem::{Error, ModelError, SceneError};

const GOOD: &str = r#"
[mesh]
file = "column.msh"
[[material]]
group = "rock"
youngs_modulus = 3.0e8
poisson_ratio = 0.3
density = 2100.0
[joints]
mode = "merged"
[[boundary]]
group = "bottom"
fix = ["x", "y", "z"]
"#;

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::from_toml(text, Path::new("verification/cases/column"), Path::new("test.toml"))
}

fn invalid_key(text: &str) -> String {
    match parse(text) {
        Err(SceneError::Invalid { key, .. }) => key,
        other => panic!("expected an Invalid error, got {other:?}"),
    }
}

#[test]
fn a_good_scene_parses() {
    parse(GOOD).unwrap();
}

#[test]
fn unknown_keys_are_rejected_with_their_name() {
    let err = parse(&GOOD.replace("density = 2100.0", "density = 2100.0\ndensty = 1.0")).unwrap_err();
    assert!(err.to_string().contains("densty"), "{err}");
    let err = parse(&format!("{GOOD}\n[solver]\ntolerence = 1e-5\n")).unwrap_err();
    assert!(err.to_string().contains("tolerence"), "{err}");
}

#[test]
fn bad_values_name_their_key() {
    assert_eq!(invalid_key(&GOOD.replace("poisson_ratio = 0.3", "poisson_ratio = 0.5")), "material[0].poisson_ratio");
    assert_eq!(
        invalid_key(&GOOD.replace("youngs_modulus = 3.0e8", "youngs_modulus = -1.0")),
        "material[0].youngs_modulus"
    );
    assert_eq!(
        invalid_key(&GOOD.replace("youngs_modulus = 3.0e8", "youngs_modulus = nan")),
        "material[0].youngs_modulus"
    );
    assert_eq!(invalid_key(&GOOD.replace("density = 2100.0", "density = 0.0")), "material[0].density");
    assert_eq!(invalid_key(&GOOD.replace("mode = \"merged\"", "mode = \"springs\"")), "joints.normal_modulus");
    assert_eq!(invalid_key(&format!("{GOOD}\n[perturbation]\nratio = 0.7\n")), "perturbation.ratio");
    assert_eq!(invalid_key(&format!("{GOOD}\n[solver]\nsafety = 1.5\n")), "solver.safety");
    assert_eq!(invalid_key(&format!("{GOOD}\n[solver]\ntolerance = 0.0\n")), "solver.tolerance");
    assert_eq!(invalid_key(&GOOD.replace("fix = [\"x\", \"y\", \"z\"]", "fix = []")), "boundary[0].fix");
}

#[test]
fn joint_strengths_are_checked_and_named() {
    let springs = GOOD.replace(
        "mode = \"merged\"",
        "mode = \"springs\"\nnormal_modulus = 1e10\nshear_modulus = 4e9\nthickness = 1.0\nstrength = { tensile = 0.0, cohesion = 16e3, friction_angle = 18.0 }",
    );
    parse(&springs).unwrap();
    assert_eq!(
        invalid_key(&springs.replace("friction_angle = 18.0", "friction_angle = 90.0")),
        "joints.strength.friction_angle"
    );
    assert_eq!(
        invalid_key(&springs.replace("friction_angle = 18.0", "friction_angle = -1.0")),
        "joints.strength.friction_angle"
    );
    assert_eq!(invalid_key(&springs.replace("cohesion = 16e3", "cohesion = -1.0")), "joints.strength.cohesion");
    assert_eq!(invalid_key(&springs.replace("tensile = 0.0", "tensile = nan")), "joints.strength.tensile");
    let iface = format!("{springs}\n[[interface]]\ngroup = \"top\"\nstrength = {{ tensile = 0.0, cohesion = -5.0, friction_angle = 30.0 }}\n");
    assert_eq!(invalid_key(&iface), "interface[0].strength.cohesion");
}

#[test]
fn rock_mass_strengths_are_checked_and_named() {
    let plastic = GOOD.replace(
        "density = 2100.0",
        "density = 2100.0\nstrength = { cohesion = 50e3, friction_angle = 35.0, tensile = 0.0, dilation_angle = 10.0 }",
    );
    parse(&plastic).unwrap();
    let bad = |from: &str, to: &str| invalid_key(&plastic.replace(from, to));
    assert_eq!(bad("cohesion = 50e3", "cohesion = -1.0"), "material[0].strength.cohesion");
    assert_eq!(bad("cohesion = 50e3", "cohesion = inf"), "material[0].strength.cohesion");
    assert_eq!(bad("tensile = 0.0", "tensile = -1.0"), "material[0].strength.tensile");
    assert_eq!(bad("friction_angle = 35.0", "friction_angle = 90.0"), "material[0].strength.friction_angle");
    assert_eq!(bad("friction_angle = 35.0", "friction_angle = nan"), "material[0].strength.friction_angle");
    // Non-associated flow: the dilation angle at most the friction angle.
    assert_eq!(bad("dilation_angle = 10.0", "dilation_angle = 40.0"), "material[0].strength.dilation_angle");
    assert_eq!(bad("dilation_angle = 10.0", "dilation_angle = -1.0"), "material[0].strength.dilation_angle");
    // A material that carries no shear at all.
    assert_eq!(
        bad(
            "cohesion = 50e3, friction_angle = 35.0, tensile = 0.0, dilation_angle = 10.0",
            "cohesion = 0.0, friction_angle = 0.0, tensile = 0.0, dilation_angle = 0.0"
        )
        .as_str(),
        "material[0].strength"
    );
    let missing = parse(&plastic.replace("cohesion = 50e3, ", "")).unwrap_err();
    assert!(missing.to_string().contains("cohesion"), "{missing}");
}

#[test]
fn failure_phase_settings_are_checked_and_named() {
    let with = |line: &str| invalid_key(&format!("{GOOD}\n[failure]\n{line}\n"));
    parse(&format!("{GOOD}\n[failure]\nmax_steps = 100\nsmoothing = 0.6\nsliding_travel = 0.0\n")).unwrap();
    assert_eq!(with("max_steps = 0"), "failure.max_steps");
    assert_eq!(with("stage_every = 0"), "failure.stage_every");
    assert_eq!(with("smoothing = 1.0"), "failure.smoothing");
    assert_eq!(with("smoothing = -0.1"), "failure.smoothing");
    assert_eq!(with("smoothing = nan"), "failure.smoothing");
    assert_eq!(with("sliding_displacement = 0.0"), "failure.sliding_displacement");
    assert_eq!(with("sliding_displacement = inf"), "failure.sliding_displacement");
    assert_eq!(with("sliding_travel = -1.0"), "failure.sliding_travel");
}

#[test]
fn a_group_the_mesh_lacks_is_named_with_its_key() {
    let scene = parse(&GOOD.replace("group = \"bottom\"", "group = \"floor\"")).unwrap();
    match cdem::drivers::build_model(&scene) {
        Err(Error::Model(ModelError::UnknownGroup { key, group, .. })) => {
            assert_eq!(key, "boundary[0].group");
            assert_eq!(group, "floor");
        }
        other => panic!("expected UnknownGroup, got {:?}", other.err()),
    }
}

#[test]
fn a_missing_mesh_file_names_the_path() {
    let scene = parse(&GOOD.replace("column.msh", "no-such.msh")).unwrap();
    let err = cdem::drivers::build_model(&scene).err().unwrap();
    assert!(matches!(err, Error::Io { .. }), "{err}");
    assert!(err.to_string().contains("no-such.msh"));
}

/// The slip slope's scene with its text edited.
fn slip_scene(edit: impl Fn(String) -> String) -> Scene {
    let text = std::fs::read_to_string("verification/cases/slope-slip/slope-slip.toml").unwrap();
    Scene::from_toml(&edit(text), Path::new("verification/cases/slope-slip"), Path::new("test.toml")).unwrap()
}

/// A cell whose volume group has no `[[material]]`: the error names the
/// element and its group (the slip slope's "rest", with only "mass" given).
#[test]
fn a_cell_without_material_names_its_volume_group() {
    let scene = slip_scene(|text| {
        let i = text.find("[[material]]\ngroup = \"rest\"").unwrap();
        let j = i + text[i..].find("[joints]").unwrap();
        format!("{}{}", &text[..i], &text[j..])
    });
    match cdem::drivers::build_model(&scene) {
        Err(e @ Error::Model(ModelError::NoMaterial { .. })) => {
            let msg = e.to_string();
            assert!(msg.contains("its volume group \"rest\" is not given a [[material]]"), "{msg}");
        }
        other => panic!("expected NoMaterial, got {:?}", other.err()),
    }
}

/// `keep_flat` needs a plane: the slip circle is refused, naming the key,
/// the group and how far it is from a plane; `keep_on` takes it.
#[test]
fn keep_flat_on_a_curved_group_is_refused_with_its_deviation() {
    let scene = slip_scene(|text| {
        assert!(text.contains("keep_on = [\"slip\"]"));
        text.replace("keep_on = [\"slip\"]", "keep_flat = [\"slip\"]")
    });
    match cdem::drivers::build_model(&scene) {
        Err(e @ Error::Model(ModelError::NotPlanar { deviation, extent, .. })) => {
            let msg = e.to_string();
            assert!(msg.contains("perturbation.keep_flat[0]") && msg.contains("\"slip\" is not one plane"), "{msg}");
            // A circular arc through (20, 20) and about (48, 40): it bows metres away from its chord plane.
            assert!(deviation > 1.0 && extent > 10.0, "deviation {deviation} m, extent {extent} m");
        }
        other => panic!("expected NotPlanar, got {:?}", other.err()),
    }
    // A plane group passes: the column's side faces.
    let column = std::fs::read_to_string("verification/cases/column/column-merged.toml")
        .unwrap()
        .replace("[[material]]", "[perturbation]\nratio = 0.1\nkeep_flat = [\"xmin\", \"bottom\"]\n\n[[material]]");
    let scene = Scene::from_toml(&column, Path::new("verification/cases/column"), Path::new("test.toml")).unwrap();
    cdem::drivers::build_model(&scene).unwrap();
}
