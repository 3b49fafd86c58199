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
    assert_eq!(invalid_key(&GOOD.replace("youngs_modulus = 3.0e8", "youngs_modulus = -1.0")), "material[0].youngs_modulus");
    assert_eq!(invalid_key(&GOOD.replace("youngs_modulus = 3.0e8", "youngs_modulus = nan")), "material[0].youngs_modulus");
    assert_eq!(invalid_key(&GOOD.replace("density = 2100.0", "density = 0.0")), "material[0].density");
    assert_eq!(invalid_key(&GOOD.replace("mode = \"merged\"", "mode = \"springs\"")), "joints.normal_modulus");
    assert_eq!(invalid_key(&format!("{GOOD}\n[perturbation]\nratio = 0.7\n")), "perturbation.ratio");
    assert_eq!(invalid_key(&format!("{GOOD}\n[solver]\nsafety = 1.5\n")), "solver.safety");
    assert_eq!(invalid_key(&format!("{GOOD}\n[solver]\ntolerance = 0.0\n")), "solver.tolerance");
    assert_eq!(invalid_key(&GOOD.replace("fix = [\"x\", \"y\", \"z\"]", "fix = []")), "boundary[0].fix");
}

#[test]
fn a_group_the_mesh_lacks_is_named_with_its_key() {
    let scene = parse(&GOOD.replace("group = \"bottom\"", "group = \"floor\"")).unwrap();
    match cdem::run::build_model(&scene) {
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
    let err = cdem::run::build_model(&scene).err().unwrap();
    assert!(matches!(err, Error::Io { .. }), "{err}");
    assert!(err.to_string().contains("no-such.msh"));
}
