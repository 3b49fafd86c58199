//! The command line: `cdem run` writes summary.json, history.csv and VTK
//! frames; a bad scene exits non-zero with a message naming the key and
//! leaves no output behind.

use std::path::PathBuf;
use std::process::Command;

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cdem-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn run_writes_summary_history_and_vtk_frames() {
    let out = temp_dir("run");
    let scene = temp_dir("scene").with_extension("toml");
    let text = std::fs::read_to_string("verification/cases/column/column-merged.toml").unwrap();
    let text = text.replace(
        "file = \"column.msh\"",
        &format!("file = {:?}", std::fs::canonicalize("verification/cases/column/column.msh").unwrap()),
    );
    std::fs::write(&scene, format!("{text}\n[output]\nframe_every = 100\n")).unwrap();
    let st = Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .status()
        .unwrap();
    assert!(st.success());
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    for key in ["converged", "steps", "wall_s", "max_abs_uz", "min_uz", "min_szz", "failed_springs", "unbalanced_ratio"]
    {
        assert!(summary.get(key).is_some(), "summary.json lacks {key}");
    }
    assert_eq!(summary["converged"], true);
    let history = std::fs::read_to_string(out.join("history.csv")).unwrap();
    assert!(
        history.starts_with("step,time,kinetic_energy,external_work,strain_energy,unbalanced_ratio,max_displacement")
    );
    let pvd = std::fs::read_to_string(out.join("run.pvd")).unwrap();
    assert!(pvd.contains("step-00000100.vtu") && pvd.contains("final.vtu"));
    let vtu = std::fs::read_to_string(out.join("final.vtu")).unwrap();
    assert!(vtu.contains("Name=\"displacement\"") && vtu.contains("Name=\"szz\""));
    assert!(std::fs::read_dir(&out).unwrap().all(|e| !e.unwrap().file_name().to_string_lossy().ends_with(".partial")));
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_file(&scene);
}

#[test]
fn a_bad_scene_exits_non_zero_naming_the_key_and_writes_nothing() {
    let out = temp_dir("bad");
    let scene = temp_dir("bad-scene").with_extension("toml");
    let text = std::fs::read_to_string("verification/cases/column/column-merged.toml")
        .unwrap()
        .replace("poisson_ratio = 0.3", "poisson_ratio = 0.6");
    std::fs::write(&scene, text).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(msg.contains("material[0].poisson_ratio"), "{msg}");
    assert!(!out.exists(), "no output directory for a failed run");
    let _ = std::fs::remove_file(&scene);
}
