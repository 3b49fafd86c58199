//! Bad input through the command line: each is a typed error naming the
//! place (line, element, key), a non-zero exit code, and no output left behind.

use std::path::PathBuf;
use std::process::Command;

fn run(scene: &str) -> (bool, String, PathBuf) {
    let out = std::env::temp_dir().join(format!("cdem-bad-{}-{}", scene.replace('/', "_"), std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o =
        Command::new(env!("CARGO_BIN_EXE_cdem")).args(["run", scene, "--out", out.to_str().unwrap()]).output().unwrap();
    (o.status.success(), String::from_utf8_lossy(&o.stderr).into_owned(), out)
}

fn assert_fails_naming(scene: &str, needles: &[&str]) {
    let (ok, msg, out) = run(scene);
    assert!(!ok, "{scene}: should fail");
    for n in needles {
        assert!(msg.contains(n), "{scene}: message lacks {n:?}: {msg}");
    }
    assert!(!msg.contains("panicked"), "{scene}: panicked: {msg}");
    assert!(!out.exists(), "{scene}: left output behind");
    let staging = cdem::output::staging_dir(&out);
    assert!(!staging.exists());
}

#[test]
fn truncated_msh_names_the_file_and_where_it_ended() {
    assert_fails_naming("tests/fixtures/bad/truncated.toml", &["truncated.msh", "MSH parse error at line"]);
}

#[test]
fn unknown_element_type_names_the_element() {
    assert_fails_naming("tests/fixtures/bad/unknown-element.toml", &["unknown-element.msh", "gmsh element type 7"]);
}

#[test]
fn inverted_element_names_the_element() {
    assert_fails_naming("tests/fixtures/bad/inverted.toml", &["inverted.msh", "inverted"]);
}

#[test]
fn a_non_numeric_coordinate_names_the_line() {
    assert_fails_naming("tests/fixtures/bad/bad-number.toml", &["bad-number.msh", "line"]);
}

#[test]
fn missing_scene_file_names_it() {
    assert_fails_naming("tests/fixtures/bad/no-such-scene.toml", &["no-such-scene.toml"]);
}
