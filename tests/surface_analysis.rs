//! Eq. 21/22 on any circle of any mesh: a scene's `[analysis]` table
//! (docs/method.md section 4.3a, references/analysis.md).
//!
//! - A circle in the laterally confined column, which no mesh face follows:
//!   K from the CDEM element stresses and from the FEM cell stresses against
//!   the closed-form uniaxial-strain field.
//! - The paper slope's mesh (no slip interface), on the Bishop critical
//!   circle its `[lem]` finds: CDEM against FEM, and against the LEM.
//! - On the conforming slip mesh, the springs of the interface give the same K
//!   as the interface sampling of tests/slip_surface.rs.
//! - `cdem run` and `cdem fem` write analysis.json, analysis.csv and analysis.png; bad
//!   tables are errors naming their key.

use std::path::Path;
use std::process::Command;

use cdem::analysis::safety_factors;
use cdem::analysis::slip::from_springs;
use cdem::error::SceneError;
use cdem::harness::registry as reg;
use cdem::scene::Scene;

/// Eq. 21 on the column circle from the closed-form stresses
/// (references/analysis.md), by the midpoint rule, with cohesion 20 kPa.
fn column_circle_k(intervals: usize) -> f64 {
    column_circle_k_with(intervals, 20e3)
}

/// The same with cohesion `c` (Pa).
fn column_circle_k_with(intervals: usize, c: f64) -> f64 {
    let (gamma, k0) = (2100.0 * 9.81, 0.3 / 0.7);
    let tan_phi = 30f64.to_radians().tan();
    let (xc, zc, r) = (-1.5f64, 26.0, 5.0);
    let a1 = (-xc / r).acos();
    let (mut resisting, mut driving) = (0.0, 0.0);
    for k in 0..intervals {
        let a = -a1 + (k as f64 + 0.5) * 2.0 * a1 / intervals as f64;
        let szz = -gamma * (40.0 - (zc + r * a.sin()));
        let sxx = k0 * szz;
        let sigma_n = -(sxx * a.cos().powi(2) + szz * a.sin().powi(2));
        let tau = -(sxx - szz) * a.sin() * a.cos();
        resisting += sigma_n * tan_phi + c;
        driving += tau;
    }
    resisting / driving
}

#[test]
fn eq21_on_circles_no_face_follows_against_the_closed_form_and_the_lem() {
    // The registry's reference is the closed form, recomputed here.
    let exact = column_circle_k(200_000);
    assert!((exact / reg::COLUMN_CIRCLE_K.value - 1.0).abs() < 1e-5, "closed form {exact}");
    assert!((column_circle_k(400_000) / exact - 1.0).abs() < 1e-9, "midpoint rule converged");

    let (rows, runs) = cdem::harness::validation::surface_rows().unwrap();
    cdem::harness::report::record("surface_analysis", &rows);
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    let (col, col_fem) = (&runs.column_cdem, &runs.column_fem);
    println!("column circle: K CDEM {:.5}, FEM {:.5}, closed form {exact:.5}", col.stresses.k, col_fem.stresses.k);
    assert!(rel(col.stresses.k, exact) < reg::TOL_EQ21_ANALYTIC, "CDEM {} vs {exact}", col.stresses.k);
    assert!(rel(col_fem.stresses.k, exact) < reg::TOL_EQ21_ANALYTIC, "FEM {} vs {exact}", col_fem.stresses.k);
    // The arc's ends are where the circle leaves the face x = 0, to the
    // locator's tolerance (1e-9 of the 40 m extent: 4e-8 m).
    let a1 = (1.5f64 / 5.0).acos();
    assert!((col.arc.length - 2.0 * a1 * 5.0).abs() < 2.0 * 4e-8 * 5.0 / 1.5, "arc {}", col.arc.length);
    assert!(col.arc.toe[0].abs() < 1e-7 && (col.arc.toe[1] - (26.0 - 5.0 * a1.sin())).abs() < 1e-7, "{:?}", col.arc);
    assert_eq!(col.stresses.points.len(), 400);

    let (slope, slope_fem) = (&runs.slope_cdem, &runs.slope_fem);
    let lem = slope.lem_fs.unwrap();
    println!(
        "paper slope, critical circle ({:.3}, {:.3}) r {:.3}: K CDEM {:.4}, FEM {:.4}, LEM Bishop {lem:.4}",
        slope.arc.circle.xc, slope.arc.circle.zc, slope.arc.circle.r, slope.stresses.k, slope_fem.stresses.k
    );
    assert_eq!(slope.circle_from, "lem critical (Bishop)");
    // The search finds the registry's critical circle.
    let (arc, slip) = (slope.arc.circle, reg::SLIP_CIRCLE.circle);
    assert!((arc.xc - slip.xc).abs() < 0.01 && (arc.zc - slip.zc).abs() < 0.01);
    assert!(rel(slope.stresses.k, slope_fem.stresses.k) < reg::TOL_EQ21_CDEM_VS_FEM);
    // Reported, not asserted (references/analysis.md): the row shows whether it is met.
    let seg = |r: &cdem::drivers::AnalysisReport| r.stresses.segments.iter().map(|g| g.sign).collect::<Vec<_>>();
    assert_eq!(seg(slope), seg(slope_fem), "CDEM and FEM give the same sign segments");
}

#[test]
fn springs_of_the_interface_give_the_slip_surface_sampling() {
    let text = std::fs::read_to_string(reg::SLOPE_SLIP.input).unwrap()
        + "\n[analysis]\ncircle = { xc = 24.006, zc = 63.222, r = 43.40725 }\ninterface = \"slip\"\n";
    let dir = Path::new(reg::SLOPE_SLIP.input).parent().unwrap();
    let mut scene = Scene::from_toml(&text, dir, Path::new(reg::SLOPE_SLIP.input)).unwrap();
    scene.failure = None;
    let run = cdem::drivers::run_scene(&scene, &mut |_, _| {}).unwrap();
    let report = run.surface.unwrap();
    let springs = report.springs.unwrap();
    let pts = from_springs(&run.model, &run.state.u, &run.state.springs, "slip", &reg::SLIP_CIRCLE).unwrap();
    let k = safety_factors(&pts, reg::SLIP_COHESION, reg::SLIP_FRICTION_DEG.to_radians().tan()).k;
    assert!((springs.k - k).abs() < 1e-12 * k, "{} vs {k}", springs.k);
    assert_eq!(report.strength_from, "interface \"slip\"");
    // The stations in the element stresses on the same mesh: within a per cent.
    assert!((report.stresses.k / springs.k - 1.0).abs() < 0.01, "{} vs {}", report.stresses.k, springs.k);
}

#[test]
fn cdem_run_and_cdem_fem_write_the_analysis_files() {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("surface-analysis-cli");
    for (command, name) in [("run", "cdem"), ("fem", "fem")] {
        let dir = out.join(name);
        let status = Command::new(env!("CARGO_BIN_EXE_cdem"))
            .args([command, reg::COLUMN_CIRCLE.input, "--out"])
            .arg(&dir)
            .output()
            .unwrap();
        assert!(status.status.success(), "{}", String::from_utf8_lossy(&status.stderr));
        let stdout = String::from_utf8_lossy(&status.stdout);
        assert!(stdout.contains("K = 9.52"), "{stdout}");
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("analysis.json")).unwrap()).unwrap();
        let k = json["stresses"]["k"].as_f64().unwrap();
        assert!((k / reg::COLUMN_CIRCLE_K.value - 1.0).abs() < reg::TOL_EQ21_ANALYTIC, "{k}");
        let csv = std::fs::read_to_string(dir.join("analysis.csv")).unwrap();
        let mut lines = csv.lines();
        assert_eq!(lines.next().unwrap(), "source,s,x,z,area,sigma_n,tau,cohesion,friction_angle,k_i");
        assert_eq!(lines.count(), 400);
        assert!(dir.join("analysis.png").is_file(), "the K_i figure");
    }
}

/// `cdem ensemble`: each member's eq. 21 K on the scene's circle; with the
/// cohesion drawn and the stresses fixed, each is the closed form with the
/// member's own cohesion.
#[test]
fn each_ensemble_member_gets_eq21_on_the_scene_circle() {
    use cdem::drivers::ensemble::{aggregate, run_members, EnsembleInput};
    let input = EnsembleInput::load(Path::new("verification/ensemble/column-circle-cohesion.toml")).unwrap();
    let n = input.default_members();
    let records = run_members(&input, input.default_seed(), 0..n, None, &mut |_| {}).unwrap();
    let mut ks = Vec::new();
    for r in &records {
        let c = r.draws[0].value;
        let k = r.cdem.as_ref().unwrap().eq21_k.unwrap();
        let exact = column_circle_k_with(200_000, c);
        println!("member {}: c {c:.0} Pa, K {k:.5}, closed form {exact:.5}", r.member);
        assert!((k / exact - 1.0).abs() < reg::TOL_EQ21_ANALYTIC, "member {}: {k} vs {exact}", r.member);
        ks.push(k);
    }
    // The cohesions differ, and so do the K.
    assert!(ks.iter().any(|&k| (k - ks[0]).abs() > 0.05), "{ks:?}");
    let s = aggregate("column-circle-cohesion", input.default_seed(), &input.analyses, None, None, &records);
    let mean = ks.iter().sum::<f64>() / ks.len() as f64;
    assert!((s.eq21_k.unwrap().mean - mean).abs() < 1e-12 * mean);
    assert_eq!(s.eq21_reliability.unwrap().probability_of_failure, 0.0);
}

fn error_key(edit: &str) -> String {
    let path = Path::new(reg::COLUMN_CIRCLE.input);
    let text = std::fs::read_to_string(path).unwrap();
    let i = text.find("[analysis]").unwrap();
    let text = format!("{}{edit}", &text[..i]);
    let parsed = Scene::from_toml(&text, path.parent().unwrap(), path);
    let scene = match parsed {
        Err(SceneError::Invalid { key, .. }) => return key,
        Err(e) => panic!("{e}"),
        Ok(s) => s,
    };
    match cdem::drivers::run_scene(&scene, &mut |_, _| {}) {
        Err(cdem::Error::Scene(SceneError::Invalid { key, .. })) => key,
        Err(e) => panic!("{e}"),
        Ok(_) => panic!("accepted: {edit}"),
    }
}

#[test]
fn bad_analysis_tables_name_their_key() {
    let strength = "strength = { cohesion = 1e4, friction_angle = 30.0 }\n";
    // No circle and no [lem] to take one from.
    assert_eq!(error_key(&format!("[analysis]\n{strength}")), "analysis.circle");
    assert_eq!(
        error_key(&format!("[analysis]\ncircle = {{ xc = 0.0, zc = 20.0, r = -1.0 }}\n{strength}")),
        "analysis.circle.r"
    );
    // A circle that misses the column, one wholly inside it.
    assert_eq!(
        error_key(&format!("[analysis]\ncircle = {{ xc = 50.0, zc = 20.0, r = 5.0 }}\n{strength}")),
        "analysis.circle"
    );
    assert_eq!(
        error_key(&format!("[analysis]\ncircle = {{ xc = 2.0, zc = 20.0, r = 1.0 }}\n{strength}")),
        "analysis.circle"
    );
    // No strength anywhere: no interface, no [lem].
    assert_eq!(error_key("[analysis]\ncircle = { xc = -1.5, zc = 26.0, r = 5.0 }\n"), "analysis.strength");
    assert_eq!(
        error_key(&format!(
            "[analysis]\ncircle = {{ xc = -1.5, zc = 26.0, r = 5.0 }}\ninterface = \"slip\"\n{strength}"
        )),
        "analysis.interface"
    );
    assert_eq!(
        error_key(&format!("[analysis]\ncircle = {{ xc = -1.5, zc = 26.0, r = 5.0 }}\nstations = 1\n{strength}")),
        "analysis.stations"
    );
    assert_eq!(
        error_key("[analysis]\ncircle = { xc = -1.5, zc = 26.0, r = 5.0 }\nstrength = { cohesion = 1e4, friction_angle = 95.0 }\n"),
        "analysis.strength.friction_angle"
    );
}
