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
fn a_launched_block_under_water_stops_after_its_buoyant_weight_says() {
    let (r, rows) = runout::submerged_rows().unwrap();
    // Twice the dry distance: half the weight presses on the base.
    assert!(r.x_at(r.track.last().unwrap().0) > 8.0, "more than four base faces");
    assert_rows("runout_submerged", &rows);
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
fn the_paper_slope_runs_out_onto_the_toe_bench_and_stops_beyond_its_energy_line() {
    // Phases 1 and 2, then the runout to rest: about 2 minutes on 2 cores.
    let (r, rows) = runout::slope_rows().unwrap();
    let s = &r.summary;
    // The mass left the slope: its front beyond the toe (x = 20 m), the sliding
    // mass's volume moved (the circle's segment, 2 m wide).
    assert!(s.deposit_min[0] < 20.0 && s.moved_volume > 400.0, "{s:?}");
    // Gravity's work is M |g| times the centre of mass's drop (no other
    // external force works): the drop is the budget's, not a second estimate.
    let m = s.moved_volume * 2100.0;
    assert!((m * 9.81 * s.mass_drop / s.energy_gravity - 1.0).abs() < 0.01, "{s:?}");
    assert_rows("runout_slope", &rows);
}

#[test]
fn runout_is_bit_for_bit_the_same_on_one_and_two_threads() {
    assert_rows("runout_determinism", &[runout::determinism_row().unwrap()]);
}

#[test]
fn runout_with_water_is_bit_for_bit_the_same_on_one_and_two_threads() {
    assert_rows("runout_determinism_water", &[runout::determinism_water_row().unwrap()]);
}

/// A scene of `verification/runout/` with extra TOML, written to a temporary
/// directory (its mesh by absolute path).
fn scene_with(name: &str, extra: &str) -> std::path::PathBuf {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("verification/runout");
    let text = std::fs::read_to_string(root.join(format!("{name}.toml"))).unwrap();
    let mesh = root.join(format!("{name}.msh"));
    let text = text.replace(&format!("file = \"{name}.msh\""), &format!("file = {:?}", mesh.display().to_string()));
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("cdem-runout-{name}-{}-{k}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("scene.toml");
    std::fs::write(&path, format!("{text}\n{extra}")).unwrap();
    path
}

#[test]
fn cdem_run_with_runout_slides_the_block_and_writes_its_files() {
    // 3DEC's block (a) on its 40 degree plane, from the bonded elastic state.
    let g = reg::RUNOUT_GRAVITY;
    let th = reg::RUNOUT_DIP_DEG.to_radians();
    let extra = format!(
        "[loads]\ngravity = [{}, 0.0, {}]\n\n[runout]\nduration = 1.0\nstart = \"rest\"\nrest_time = 0.0\n",
        g * th.sin(),
        -g * th.cos()
    );
    let scene = scene_with("sliding", &extra);
    let out = scene.parent().unwrap().join("out");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .status()
        .unwrap();
    assert!(status.success(), "cdem run failed: {status}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let r = &summary["runout"];
    assert_eq!(r["ran"], true);
    // The front's travel in 1 s against a t^2 / 2 (1.820 m): the block's
    // nodes move alike, the bonded start's upslope tension released at once.
    let d = r["runout_distance"].as_f64().unwrap();
    let a = reg::block_acceleration(reg::RUNOUT_DIP_DEG, reg::RUNOUT_SLIDING_PHI_DEG, g);
    assert!((d - 0.5 * a).abs() < 0.03 * 0.5 * a, "runout distance {d} m, Coulomb {} m", 0.5 * a);
    assert!(r["energy_closure"].as_f64().unwrap() < reg::TOL_RUNOUT_ENERGY);
    let csv = std::fs::read_to_string(out.join("runout.csv")).unwrap();
    assert!(csv.starts_with("step,time,kinetic_energy"), "{}", &csv[..80.min(csv.len())]);
    assert!(csv.lines().count() > 10);
}

#[test]
fn runout_on_a_scene_that_does_not_slide_says_so_and_exits_3() {
    let scene = scene_with("at-rest", "[runout]\nduration = 1.0\n");
    let out = scene.parent().unwrap().join("out");
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert_eq!(run.status.code(), Some(3), "{stdout}");
    assert!(stdout.contains("runout: not run: the slope did not slide"), "{stdout}");
}

#[test]
fn a_bad_runout_key_is_refused_naming_it() {
    let scene = scene_with("at-rest", "[runout]\nduration = -1.0\n");
    let err = cdem::scene::Scene::load(&scene).unwrap_err().to_string();
    assert!(err.contains("runout.duration"), "{err}");
    let scene = scene_with("at-rest", "[runout]\nduration = 1.0\ndampign = \"local\"\n");
    assert!(cdem::scene::Scene::load(&scene).is_err());
    // A crack's water has no surface to follow once blocks move: refused, naming the key.
    let scene = scene_with(
        "at-rest",
        "[runout]\nduration = 1.0\n\n[water]\n[[water.crack]]\ngroup = \"contact\"\nlevel = 0.5\n",
    );
    let err = cdem::scene::Scene::load(&scene).unwrap_err().to_string();
    assert!(err.contains("water.crack[0]") && err.contains("runout"), "{err}");
}
