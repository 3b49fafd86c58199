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
    // A frame every 2 steps: PCG (the default) takes 8 iterations on the column.
    let (scene, out) = edited_column("run", |t| format!("{t}\n[output]\nframe_every = 2\n"));
    assert!(cdem_run(&scene, &out).status.success());
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    for key in ["converged", "steps", "wall_s", "max_abs_uz", "min_uz", "min_szz", "failed_springs", "unbalanced_ratio"]
    {
        assert!(summary.get(key).is_some(), "summary.json lacks {key}");
    }
    assert_eq!(summary["converged"], true);
    let history = std::fs::read_to_string(out.join("history.csv")).unwrap();
    assert!(history
        .starts_with("phase,step,time,kinetic_energy,external_work,strain_energy,unbalanced_ratio,max_displacement"));
    let pvd = std::fs::read_to_string(out.join("run.pvd")).unwrap();
    assert!(pvd.contains("step-00000002.vtu") && pvd.contains("final.vtu"));
    let vtu = std::fs::read_to_string(out.join("final.vtu")).unwrap();
    assert!(vtu.contains("Name=\"displacement\"") && vtu.contains("Name=\"szz\""));
    assert!(std::fs::read_dir(&out).unwrap().all(|e| !e.unwrap().file_name().to_string_lossy().ends_with(".partial")));
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_file(&scene);
}

/// `cdem run` on a scene with `[failure]`: the paper slope whose slip circle
/// is breakable (c = 16 kPa, phi = 18 deg). The summary has both phases and
/// the end state at the top; the history covers both phases; the phase-2
/// tables agree with the summary; every file is in `--out`, none elsewhere.
#[test]
fn run_of_a_failure_scene_writes_both_phases_and_the_end_state() {
    let out = temp_dir("failure");
    let o = cdem_run(std::path::Path::new("verification/cases/slope-slip/slope-slip.toml"), &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(out.join("summary.json")).unwrap();
    assert!(text.trim_start().starts_with("{\n  \"end_state\": \"GlobalSliding\""), "end_state first:\n{text}");
    let s: serde_json::Value = serde_json::from_str(&text).unwrap();
    let (p1, p2) = (&s["phase1"], &s["phase2"]);
    assert_eq!(p1["end_state"], "Equilibrium");
    assert!(p1["unbalanced_ratio"].as_f64().unwrap() < 1e-5);
    assert_eq!(p2["end_state"], "GlobalSliding");
    assert_eq!(s["converged"], false);
    let steps = |v: &serde_json::Value| v["steps"].as_u64().unwrap();
    assert_eq!(steps(&s), steps(p1) + steps(p2), "top-level steps are both phases'");
    assert_eq!(s["unbalanced_ratio"], p2["unbalanced_ratio"], "the top-level ratio is the end's, not phase 1's");
    assert!(p2["unbalanced_ratio"].as_f64().unwrap() > 1e-5, "a sliding mass is out of balance");
    // Decided by the displacement rate (docs/method.md section 2.9): 2,160
    // phase-2 steps and 2e-2 m, well before the scene's 0.5 m bound.
    let moved = p2["max_displacement"].as_f64().unwrap();
    assert!(moved > 1e-3 && moved < 0.5 && steps(p2) <= 5000, "{moved} m after {} steps", steps(p2));
    let failed = |v: &serde_json::Value| {
        v["failed_springs"]["tension"].as_u64().unwrap() + v["failed_springs"]["shear"].as_u64().unwrap()
    };
    assert_eq!(failed(p1), 0, "no spring fails in the elastic phase");
    assert!(failed(p2) > 0);
    assert_eq!(s["failed_springs"], p2["failed_springs"]);

    // history.csv: phase 1 rows, then phase 2 rows with later steps.
    let history = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let rows: Vec<(u64, u64)> = history
        .lines()
        .skip(1)
        .map(|l| {
            let mut f = l.split(',');
            (f.next().unwrap().parse().unwrap(), f.next().unwrap().parse().unwrap())
        })
        .collect();
    let last1 = rows.iter().filter(|r| r.0 == 1).map(|r| r.1).max().unwrap();
    let first2 = rows.iter().filter(|r| r.0 == 2).map(|r| r.1).min().unwrap();
    assert_eq!(last1, steps(p1), "phase 1's history ends at its last step");
    assert!(first2 > last1 && rows.windows(2).all(|w| w[0].0 <= w[1].0 && w[0].1 < w[1].1));

    // stages.csv: the last stage is the last step of phase 2, with the summary's counts.
    let stages = std::fs::read_to_string(out.join("stages.csv")).unwrap();
    let mut lines = stages.lines();
    assert_eq!(
        lines.next().unwrap(),
        "step,failed_tension,failed_shear,max_displacement,kinetic_energy,unbalanced_ratio"
    );
    let last: Vec<&str> = lines.last().unwrap().split(',').collect();
    assert_eq!(last[0].parse::<u64>().unwrap(), steps(p2));
    assert_eq!(last[1].parse::<u64>().unwrap(), p2["failed_springs"]["tension"].as_u64().unwrap());
    assert_eq!(last[2].parse::<u64>().unwrap(), p2["failed_springs"]["shear"].as_u64().unwrap());

    // failed_springs.csv: one row per failed spring (a failed spring stays failed).
    let failed_csv = std::fs::read_to_string(out.join("failed_springs.csv")).unwrap();
    assert!(failed_csv.starts_with("spring,first_failure_step,kind,x,y,z\n"));
    assert_eq!(failed_csv.lines().count() as u64 - 1, failed(p2));

    // Frames where the failure state changed: fewer than the stages, the last one the end.
    let pvd = std::fs::read_to_string(out.join("failure.pvd")).unwrap();
    let frames = pvd.matches("<DataSet").count();
    assert!(frames >= 2 && frames < stages.lines().count() - 1, "{frames} frames");
    assert!(pvd.contains(&format!("stage-{:08}.vtu", steps(p2))));
    for f in ["run.pvd", "final.vtu"] {
        assert!(out.join(f).exists(), "{f}");
    }
    let parent = out.parent().unwrap();
    let stray = std::fs::read_dir(parent).unwrap().filter_map(|e| e.ok()).any(|e| {
        e.file_name().to_string_lossy().contains(&format!(".{}.partial", out.file_name().unwrap().to_string_lossy()))
    });
    assert!(!stray, "the staging directory is removed");
    let _ = std::fs::remove_dir_all(&out);
}

/// `stages.csv`'s kinetic energy is `v . M v / 2`, the value `history.csv`
/// has at the same step (with a row every step): not the estimate from the
/// node-block masses' diagonal that the stop rule compares from step to step,
/// which overstates it many times over on this scene.
#[test]
fn a_stage_records_the_kinetic_energy_of_the_history() {
    let scene = temp_dir("stage-kinetic-scene").with_extension("toml");
    let text = std::fs::read_to_string("verification/cases/slope-slip/slope-slip.toml").unwrap().replace(
        "file = \"slope-slip.msh\"",
        &format!("file = {:?}", std::fs::canonicalize("verification/cases/slope-slip/slope-slip.msh").unwrap()),
    );
    std::fs::write(&scene, format!("{text}\n[output]\nhistory_every = 1\nvtk = false\n")).unwrap();
    let out = temp_dir("stage-kinetic");
    assert!(cdem_run(&scene, &out).status.success());
    let csv = |name: &str| -> Vec<Vec<f64>> {
        let text = std::fs::read_to_string(out.join(name)).unwrap();
        text.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect()
    };
    let history = csv("history.csv"); // phase, step, time, kinetic_energy, ...
    let stages = csv("stages.csv"); // step (from the start of phase 2), ..., kinetic_energy, ratio
    let phase1_end = history.iter().filter(|r| r[0] == 1.0).map(|r| r[1]).fold(0.0, f64::max);
    let kinetic_at = |step: f64| history.iter().find(|r| r[0] == 2.0 && r[1] == step).map(|r| r[3]);
    let mut moving = 0;
    for stage in &stages {
        let exact = kinetic_at(phase1_end + stage[0]).expect("a history row every step");
        assert_eq!(stage[4], exact, "stage at phase-2 step {}", stage[0]);
        moving += (exact > 0.0) as usize;
    }
    assert!(moving >= 3, "{moving} stages with a moving mass");
    let _ = std::fs::remove_file(&scene);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn a_bad_scene_exits_non_zero_naming_the_key_and_writes_nothing() {
    let (scene, out) = edited_column("bad", |t| t.replace("poisson_ratio = 0.3", "poisson_ratio = 0.6"));
    let o = cdem_run(&scene, &out);
    assert_eq!(o.status.code(), Some(2), "invalid input");
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(msg.contains("material[0].poisson_ratio"), "{msg}");
    assert!(!out.exists(), "no output directory for a failed run");
    let _ = std::fs::remove_file(&scene);
}

/// The column scene with `edit` applied, written beside a temporary output
/// directory (the mesh path made absolute); returns (scene, out).
fn edited_column(name: &str, edit: impl Fn(String) -> String) -> (PathBuf, PathBuf) {
    let scene = temp_dir(&format!("{name}-scene")).with_extension("toml");
    let text = std::fs::read_to_string("verification/cases/column/column-merged.toml").unwrap().replace(
        "file = \"column.msh\"",
        &format!("file = {:?}", std::fs::canonicalize("verification/cases/column/column.msh").unwrap()),
    );
    std::fs::write(&scene, edit(text)).unwrap();
    (scene, temp_dir(name))
}

fn cdem_run(scene: &std::path::Path, out: &std::path::Path) -> std::process::Output {
    cdem("run", scene, out)
}

fn cdem_srm(scene: &std::path::Path, out: &std::path::Path) -> std::process::Output {
    cdem("srm", scene, out)
}

/// `cdem COMMAND SCENE --out OUT`.
fn cdem(command: &str, scene: &std::path::Path, out: &std::path::Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args([command, scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap()
}

/// Exit code 2 (invalid input) before the first step when the supports leave
/// a rigid motion free: here no `[[boundary]]` at all, so the whole column
/// translates; the message names the part and the motion.
#[test]
fn a_scene_without_supports_is_refused_before_the_first_step() {
    let (scene, out) = edited_column("free", |t| {
        let i = t.find("[[boundary]]").unwrap();
        let j = t.find("[loads]").unwrap();
        format!("{}{}", &t[..i], &t[j..])
    });
    let o = cdem_run(&scene, &out);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{msg}");
    assert!(msg.contains("part 0 of the model (40 elements") && msg.contains("is free to move"), "{msg}");
    assert!(msg.contains("translation"), "{msg}");
    assert!(!out.exists());

    // Only the bottom fixed in z: the column can still slide in x and y and spin about z.
    let (scene, out) = edited_column("slide", |t| {
        let i = t.find("[[boundary]]").unwrap();
        let j = t.find("[loads]").unwrap();
        format!("{}[[boundary]]\ngroup = \"bottom\"\nfix = [\"z\"]\n{}", &t[..i], &t[j..])
    });
    let o = cdem_run(&scene, &out);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    let _ = std::fs::remove_file(&scene);
}

/// Exit code 3 when the step budget runs out: the outputs are still written,
/// and say so. (PCG, the default, needs 8 iterations on the column, dynamic
/// relaxation 243 steps: 3 is short of both.)
#[test]
fn a_run_out_of_steps_exits_3_with_its_outputs_marked_undecided() {
    let (scene, out) = edited_column("budget", |t| t.replace("tolerance = 1e-7", "tolerance = 1e-7\nmax_steps = 3"));
    let o = cdem_run(&scene, &out);
    assert_eq!(o.status.code(), Some(3), "{}", String::from_utf8_lossy(&o.stderr));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(
        (s["end_state"].as_str(), s["converged"].as_bool(), s["steps"].as_u64()),
        (Some("Undecided"), Some(false), Some(3))
    );
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_file(&scene);
}

/// An `[[interface]]` must be an internal surface: naming an outer one (the
/// column's base) is refused, naming the item and counting the outer facets.
#[test]
fn an_interface_on_the_outer_surface_is_refused() {
    let (scene, out) = edited_column("outer", |t| {
        t.replace(
            "[[boundary]]\ngroup = \"bottom\"",
            "[[interface]]\ngroup = \"bottom\"\nmode = \"merged\"\n\n[[boundary]]\ngroup = \"bottom\"",
        )
    });
    let o = cdem_run(&scene, &out);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{msg}");
    assert!(
        msg.contains("interface[0].group") && msg.contains("\"bottom\" has 4 of its 4 facets on the outer surface"),
        "{msg}"
    );
    let _ = std::fs::remove_file(&scene);
}

/// An unknown group is answered with the groups of that kind the mesh has.
#[test]
fn an_unknown_group_lists_the_groups_there_are() {
    let (scene, out) = edited_column("unknown", |t| t.replacen("group = \"xmin\"", "group = \"x_min\"", 1));
    let o = cdem_run(&scene, &out);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{msg}");
    assert!(msg.contains("boundary[1].group") && msg.contains("\"x_min\""), "{msg}");
    assert!(msg.contains("its surface groups:") && msg.contains("\"xmin\"") && msg.contains("\"bottom\""), "{msg}");
    let _ = std::fs::remove_file(&scene);
}

/// `cdem lem` on a CDEM scene: the paper slope's scene carries a `[lem]`
/// table; the LEM of its mesh prints the paper's FS. A scene without one is
/// invalid input (2), and `--help` describes both formats.
#[test]
fn lem_runs_on_a_scene_and_refuses_one_without_a_lem_table() {
    let out = temp_dir("lem-scene").join("lem.json");
    let o = cdem("lem", "verification/cases/slope/slope.toml".as_ref(), &out);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(text.lines().any(|l| l.starts_with("bishop     1.0888")), "{text}");
    assert!(out.exists());

    let o = Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args(["lem", "verification/cases/column/column.toml"])
        .output()
        .unwrap();
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{msg}");
    assert!(msg.contains("`lem`") && msg.contains("[lem] table"), "{msg}");

    let o = Command::new(env!("CARGO_BIN_EXE_cdem")).args(["lem", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&o.stdout);
    for key in ["[lem]", "[[lem.material]]", "[section]", "ground_group", "z_min", "Exit codes"] {
        assert!(help.contains(key), "--help lacks {key}: {help}");
    }
}

/// `cdem srm` on the block on a plane with cohesion: exit 0, `srm.json` with
/// `fs`, `bracket` (width at most 0.01, holding the analytic FS 1.2630 of
/// references/srm.md) and the trials, `mechanism.vtu` and `mechanism.png`.
#[test]
fn srm_writes_fs_bracket_trials_and_the_mechanism() {
    let out = temp_dir("srm");
    let o = cdem_srm("verification/cases/block-srm/block-srm-cohesion.toml".as_ref(), &out);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("srm.json")).unwrap()).unwrap();
    let (lo, hi) = (j["bracket"][0].as_f64().unwrap(), j["bracket"][1].as_f64().unwrap());
    let analytic = cdem::harness::registry::BLOCK_SRM_COHESION_SET.fs();
    assert!(hi - lo <= 0.01 + 1e-12 && lo <= analytic && analytic <= hi, "[{lo}, {hi}] against {analytic}");
    assert!((j["fs"].as_f64().unwrap() - 0.5 * (lo + hi)).abs() < 1e-12);
    let trials = j["trials"].as_array().unwrap();
    assert!(trials.len() >= 3);
    for t in trials {
        for key in ["factor", "outcome", "steps", "max_displacement"] {
            assert!(!t[key].is_null(), "trial without {key}: {t}");
        }
    }
    assert!(out.join("mechanism.vtu").exists() && out.join("mechanism.png").exists());
    assert!(String::from_utf8_lossy(&o.stdout).contains("FS = 1.26"), "{}", String::from_utf8_lossy(&o.stdout));
}

/// `cdem srm` on a scene without a breakable interface: exit 2, naming the key.
#[test]
fn srm_without_a_breakable_interface_is_invalid_input() {
    let (scene, out) = edited_column("srm-none", |t| t);
    let o = cdem_srm(&scene, &out);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("scene key `interface`"));
    assert!(!out.exists());
}

/// `cdem run` on plastic blocks (Griffiths & Lane's hexahedra with a tenth
/// of their cohesion, 300 failure steps): `summary.json` has the plastic
/// volumes (yielding and yielded, and their parts in tension) and the VTK
/// frames the plastic cell fields of docs/method.md 2.9b.
#[test]
fn run_on_plastic_blocks_writes_their_yield_state() {
    let dir = temp_dir("plastic");
    std::fs::create_dir_all(&dir).unwrap();
    let src = std::path::Path::new("verification/plastic/griffiths-lane-1");
    let text = std::fs::read_to_string(src.join("gl1-hex.toml")).unwrap();
    let mesh = std::fs::canonicalize(src.join("gl1-hex.msh")).unwrap();
    let text = text.replace("file = \"gl1-hex.msh\"", &format!("file = {:?}", mesh.to_str().unwrap()));
    assert!(text.contains("cohesion = 10.0e3"), "the scene's cohesion moved");
    let text = format!("{}\n[failure]\nmax_steps = 300\n", text.replace("cohesion = 10.0e3", "cohesion = 1.0e3"));
    let scene = dir.join("weak.toml");
    std::fs::write(&scene, text).unwrap();
    let out = dir.join("out");
    let o = cdem_run(&scene, &out);
    assert!(out.join("summary.json").exists(), "{}", String::from_utf8_lossy(&o.stderr));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let plastic = &summary["plastic"];
    for key in ["volume", "yielding_volume", "yielded_volume", "yielding_tension_volume", "yielded_tension_volume"] {
        assert!(plastic[key].is_f64(), "summary.json's plastic lacks {key}: {plastic}");
    }
    assert!(plastic["yielded_volume"].as_f64().unwrap() > 0.0, "{plastic}");
    let vtu = std::fs::read_to_string(out.join("final.vtu")).unwrap();
    for field in ["plastic_shear", "yielding", "yielded", "yielding_tension", "yielded_tension"] {
        assert!(vtu.contains(&format!("Name=\"{field}\"")), "final.vtu lacks {field}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `cdem srm` on plastic blocks without tensile strength (Cheng et al.'s
/// problem 61 on its coarse hexahedra, T = 0): `mechanism.vtu` says which
/// elements yielded in tension at the mechanism (the crest's tension cracks:
/// some elements wholly, none more than wholly) and `slip-band.png` is drawn.
#[test]
fn srm_on_plastic_blocks_marks_the_tension_cracks() {
    let out = temp_dir("srm-plastic");
    let o = cdem_srm("verification/plastic/cheng-61/c61-hex.toml".as_ref(), &out);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let vtu = std::fs::read_to_string(out.join("mechanism.vtu")).unwrap();
    let field = |name: &str| -> Vec<f64> {
        let start = vtu.find(&format!("Name=\"{name}\"")).unwrap_or_else(|| panic!("no {name}"));
        let body = &vtu[start..];
        let body = &body[body.find('>').unwrap() + 1..body.find("</DataArray>").unwrap()];
        body.split_whitespace().map(|v| v.parse().unwrap()).collect()
    };
    let (tension, yielded) = (field("yielded_tension"), field("yielded"));
    assert_eq!(tension.len(), yielded.len());
    assert!(tension.iter().zip(&yielded).all(|(t, y)| (0.0..=1.0).contains(t) && t <= y), "tension within yielded");
    assert!(tension.iter().any(|&t| t >= 0.5), "no element yielded in tension at T = 0");
    assert!(out.join("slip-band.png").exists());
    // Each trial in srm.json: the volume that yielded in tension, within the yielded volume.
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("srm.json")).unwrap()).unwrap();
    let trials = j["trials"].as_array().unwrap();
    let volumes =
        |t: &serde_json::Value| (t["yielded_tension_volume"].as_f64().unwrap(), t["yielded_volume"].as_f64().unwrap());
    assert!(trials.iter().map(volumes).all(|(t, y)| (0.0..=y).contains(&t)), "{trials:?}");
    assert!(trials.iter().map(volumes).any(|(t, _)| t > 0.0), "{trials:?}");
    let _ = std::fs::remove_dir_all(&out);
}

/// `cdem run --mesh-check` on the confined column (its `.geo` takes no
/// `refine`: every hexahedron split into eight): the elastic run on 40 and
/// 320 elements, each mesh's min u_z within 1 % of the analytic top
/// displacement (references/column.md), the extrapolation of two meshes
/// with its order assumed, and the lines printed.
#[test]
fn run_mesh_check_refines_the_column_and_extrapolates_its_headline_values() {
    let out = temp_dir("run-mesh-check");
    let o = Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args(["run", "verification/cases/column/column.toml", "--out", out.to_str().unwrap(), "--mesh-check"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{stdout}{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("min u_z") && stdout.contains("converged (+/-") && stdout.contains("order 2.00 assumed"));
    let check: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("mesh-check.json")).unwrap()).unwrap();
    let meshes = check["meshes"].as_array().unwrap();
    let elements: Vec<u64> = meshes.iter().map(|m| m["elements"].as_u64().unwrap()).collect();
    assert_eq!(elements, [40, 320]);
    let analytic = cdem::harness::registry::column_uz(cdem::harness::registry::CONFINED_COLUMN.height);
    for m in meshes {
        let uz = m["min_uz"].as_f64().unwrap();
        assert!((uz / analytic - 1.0).abs() < 0.01, "min u_z {uz} against the analytic {analytic}");
    }
    assert_eq!(check["min_uz"]["order_source"], "assumed_two_meshes");
    assert!(check["min_szz"]["value"].as_f64().is_some());
    assert!(out.join("summary.json").exists() && out.join("mesh-check").is_dir());
    let _ = std::fs::remove_dir_all(&out);
}
