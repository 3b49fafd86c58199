//! The solver is usable as a library without the harness's and the CLI's
//! crates: `clap`, `indicatif`, `signal-hook` (the CLI's SIGINT/SIGTERM
//! checkpoints), `plotters` and `dejavu` are optional
//! dependencies enabled only by the default feature `harness` (`plotters`
//! and `dejavu` through the feature `plot` it enables: the product's figures
//! and the application layer), and the binary requires that feature. So
//! `cargo tree --no-default-features -e normal` lists none of them. The one
//! other optional crate, `gungraun`, is for the instruction-count benches
//! only (feature `iai`, in neither `default` nor `harness`).

#[test]
fn cli_and_plotting_crates_come_only_with_the_harness_feature() {
    let manifest: toml::Table = std::fs::read_to_string("Cargo.toml").unwrap().parse().unwrap();
    let deps = manifest["dependencies"].as_table().unwrap();
    let harness_only = ["clap", "indicatif", "signal-hook", "plotters", "dejavu"];
    for name in harness_only {
        let optional = deps[name].as_table().and_then(|t| t.get("optional")).and_then(|v| v.as_bool());
        assert_eq!(optional, Some(true), "{name} must be an optional dependency");
    }
    let bench_only = ["gungraun"];
    for (name, spec) in deps {
        let optional = spec.as_table().and_then(|t| t.get("optional")).and_then(|v| v.as_bool()).unwrap_or(false);
        assert!(
            !optional || harness_only.contains(&name.as_str()) || bench_only.contains(&name.as_str()),
            "{name}: optional but not a harness crate"
        );
    }
    let features = manifest["features"].as_table().unwrap();
    let iai: Vec<&str> = features["iai"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
    assert!(iai.contains(&"dep:gungraun"), "feature iai lacks dep:gungraun");
    let list = |f: &str| -> Vec<&str> { features[f].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect() };
    let (harness, plot) = (list("harness"), list("plot"));
    assert!(harness.contains(&"plot"), "feature harness lacks plot");
    assert_eq!(plot, ["dep:plotters", "dep:dejavu"], "feature plot is the plotting crates");
    for name in harness_only {
        let dep = format!("dep:{name}");
        assert!(harness.contains(&dep.as_str()) || plot.contains(&dep.as_str()), "feature harness lacks dep:{name}");
    }
    let default: Vec<&str> = features["default"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
    assert_eq!(default, ["harness"]);
    assert!(!harness.contains(&"dep:gungraun"), "gungraun must stay out of the harness feature");
    let bins = manifest["bin"].as_array().unwrap();
    assert!(bins
        .iter()
        .all(|b| b["required-features"].as_array().is_some_and(|f| f.iter().any(|v| v.as_str() == Some("harness")))));
}

/// What a library user writes: a scene relaxed and summarised through the
/// drivers, nothing from the harness.
#[test]
fn a_scene_runs_through_the_library_alone() {
    let scene = cdem::scene::Scene::load("verification/cases/column/column-merged.toml".as_ref()).unwrap();
    let run = cdem::drivers::run_scene(&scene, &mut |_, _| {}).unwrap();
    assert_eq!(run.summary.end_state, cdem::EndState::Equilibrium);
    assert!(run.failure.is_none() && run.summary.phase2.is_none());
    assert_eq!(run.summary.steps, run.elastic.steps);
}
