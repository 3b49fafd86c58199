//! Joint sets (references/joints.md): the geometry files of
//! verification/joints become the committed `.geo` files (`cdem mesh
//! GEOMETRY.toml`; tests/gmsh_regen.rs checks the `.msh` against the `.geo`),
//! bad geometry is a typed error naming its key, and `cdem srm` on the plane
//! failure and the symmetric wedge lands within 1 % of the closed forms, on
//! the general wedge within 3 % of the vector solution, on
//! Goodman & Bray's toppling within 5 % of their recursion (the
//! runs and rows are [`cdem::harness::suite::joints`], shared with
//! `cdem reproduce`).

use std::path::Path;

use cdem::harness::registry as reg;
use cdem::harness::report::record;
use cdem::harness::suite::joints;
use cdem::scene::joint_sets::Geometry;
use cdem::scene::Scene;
use cdem::SceneError;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

const GEOMETRIES: [&str; 3] = [
    "verification/joints/plane-geometry.toml",
    "verification/joints/wedge-geometry.toml",
    "verification/joints/wedge-general-geometry.toml",
];

/// The closed forms of the registry against the numbers of the independent
/// script (`python3 scripts/rock_slope_closed_forms.py`, references/joints.md).
#[test]
fn the_registry_closed_forms_equal_the_reference_script() {
    let plane = reg::PLANE_FAILURE_SET;
    assert!((plane.crack_depth() - 14.8038).abs() < 1e-4, "{}", plane.crack_depth());
    assert!((plane.fs() - 1.3469).abs() < 1e-4, "{}", plane.fs());
    let (k, psi_i) = reg::WEDGE_SYMMETRIC_SET.factor();
    assert!((k - 1.34871).abs() < 1e-5 && (psi_i - 39.3227).abs() < 1e-4, "{k} {psi_i}");
    assert!((reg::WEDGE_SYMMETRIC_SET.fs() - 1.15287).abs() < 1e-5, "{}", reg::WEDGE_SYMMETRIC_SET.fs());
    // Hoek & Bray's general wedge (45/105, 70/235), friction 30 on both: the
    // wedge factor equals the script's vector solution, 1.43530.
    let hb = reg::WedgeFactor { plane_a: (45.0, 105.0), plane_b: (70.0, 235.0), friction_deg: 30.0 };
    assert!((hb.fs() - 1.43530).abs() < 1e-5, "{}", hb.fs());
    // The general wedge: the script's vector solution.
    let (w, a1, a2, n1, n2, fs) = reg::WEDGE_GENERAL_SET.solve();
    assert!(
        (w - 4993458.234).abs() < 1e-2 && (a1 - 84.597).abs() < 1e-3 && (a2 - 59.999).abs() < 1e-3,
        "{w} {a1} {a2}"
    );
    assert!((n1 - 2846515.708).abs() < 1e-2 && (n2 - 1337059.880).abs() < 1e-2, "{n1} {n2}");
    assert!((fs - 1.117519).abs() < 1e-6, "{fs}");
    // With the symmetric wedge's planes and friction, the vector solution is the wedge factor's.
    let sym = reg::VectorWedge {
        planes: [(55.0, 215.0), (55.0, 325.0), (0.0, 270.0), (75.0, 270.0)],
        height: 12.0,
        unit_weight: 2600.0 * 9.81,
        strengths: [(0.0, 35.0), (0.0, 35.0)],
    };
    assert!((sym.fs() - reg::WEDGE_SYMMETRIC_SET.fs()).abs() < 1e-12);
    // Goodman & Bray: heights 4, 8, ..., 40, 34, ..., 4 m; the limit friction
    // angle 38.1512 deg (the script; published 38.15).
    let heights: Vec<f64> = reg::TOPPLING_SET.blocks().iter().map(|b| b.0).collect();
    assert_eq!(heights[9], 40.0);
    assert_eq!(heights[15], 4.0);
    let phi = reg::TOPPLING_SET.limit_friction();
    assert!((phi - 38.1512).abs() < 1e-4, "{phi}");
}

#[test]
fn committed_geo_files_are_what_cdem_mesh_writes() {
    for g in GEOMETRIES {
        let path = root().join(g);
        let geometry = Geometry::load(&path).unwrap();
        let name = geometry.name.clone().unwrap();
        let source = path.file_name().unwrap().to_string_lossy().into_owned();
        let committed = std::fs::read_to_string(path.with_file_name(format!("{name}.geo"))).unwrap();
        assert_eq!(
            geometry.geo(&source).unwrap(),
            committed,
            "{g}: regenerate with cdem mesh {g} --out verification/joints"
        );
        // The skeleton is a scene that loads and validates.
        let skeleton = geometry.scene_skeleton(&format!("{name}.msh"), &source);
        let scene = Scene::from_toml(&skeleton, path.parent().unwrap(), &path).unwrap();
        assert_eq!(scene.interface.len(), geometry.joint_set.len());
    }
}

fn plane_geometry_with(edit: &str, with: &str) -> Result<Geometry, SceneError> {
    let text = std::fs::read_to_string(root().join(GEOMETRIES[0])).unwrap();
    assert!(text.contains(edit), "{edit}");
    Geometry::from_toml(&text.replacen(edit, with, 1), Path::new("plane-geometry.toml"))
}

#[test]
fn bad_geometry_is_an_error_naming_its_key() {
    let cases = [
        ("face_dip = 60.0", "face_dip = 0.0", "slope.face_dip"),
        ("width = 4.0", "width = -4.0", "slope.width"),
        ("mesh_size = 4.0", "mesh_size = nan", "mesh_size"),
        ("dip = 30.0", "dip = 95.0", "joint_set[0].dip"),
        ("offset = 0.0", "offset = 0.0\nspacing = 0.0", "joint_set[0].spacing"),
        ("offset = 0.0", "offset = 0.0\nspacing = 0.01", "joint_set[0].spacing"),
        ("offset = 0.0", "offset = 0.0\nextent = \"finite\"", "joint_set[0].extent"),
        ("offset = -26.320508075688775", "offset = -100.0", "joint_set[1].offset"),
        ("friction_angle = 30.0", "friction_angle = 90.0", "joint_set[0].strength.friction_angle"),
        ("poisson_ratio = 0.25", "poisson_ratio = 0.5", "rock.poisson_ratio"),
    ];
    for (edit, with, key) in cases {
        match plane_geometry_with(edit, with) {
            Err(SceneError::Invalid { key: k, reason }) => assert_eq!(k, key, "{with}: {reason}"),
            other => panic!("{with}: expected an error naming {key}, got {other:?}"),
        }
    }
    // An unknown key and a missing one are syntax errors naming them.
    for (edit, with, word) in [("width = 4.0", "widht = 4.0", "widht"), ("height = 30.0", "", "height")] {
        match plane_geometry_with(edit, with) {
            Err(SceneError::Syntax { message, .. }) => assert!(message.contains(word), "{message}"),
            other => panic!("{with}: expected a syntax error, got {other:?}"),
        }
    }
}

/// A set with a spacing: its planes are `offset + k spacing` inside the volume, no more.
#[test]
fn a_spaced_set_has_every_plane_that_cuts_the_volume() {
    let g = plane_geometry_with("offset = 0.0", "offset = 0.0\nspacing = 10.0").unwrap();
    let planes = g.set_planes(0).unwrap();
    // n = (-1/2, 0, sqrt(3)/2): n . p over the plane case's corners spans
    // [-26.49, 17.32] (the back's foot (44.32, -5), the crest (17.32, 30)).
    let ds: Vec<f64> = planes.iter().map(|p| p.d).collect();
    assert_eq!(ds, vec![-20.0, -10.0, 0.0, 10.0]);
}

fn run_case(i: usize, test: &str) {
    let (case, closed, id) = joints::cases()[i];
    let run = joints::run(case, closed, id).unwrap();
    record(test, std::slice::from_ref(&run.row));
    let r = &run.result;
    let [lo, hi] = r.bracket.map(|b| b.unwrap_or(f64::NAN));
    println!(
        "{}: FS {:.4} in [{lo:.4}, {hi:.4}], closed form {closed:.4}, error {:+.2} %, {} tetrahedra, {:.1} s",
        case.name,
        r.fs.unwrap_or(f64::NAN),
        100.0 * (r.fs.unwrap_or(f64::NAN) - closed) / closed,
        run.cells,
        r.wall_s
    );
    for t in &r.trials {
        println!("  F = {:.4}: {:?} after {} steps", t.factor, t.outcome, t.steps);
    }
    assert!(run.row.passed(), "{:?}", run.row.defect);
    // The mechanism's figure (as `cdem reproduce` draws it).
    let png = std::env::temp_dir().join(format!("cdem-{test}-{}.png", std::process::id()));
    assert!(cdem::output::figures::joints::mechanism_views(r, &run.model, &png).unwrap());
    println!("mechanism: {}", png.display());
}

#[test]
fn plane_failure_srm_matches_hoek_and_bray() {
    run_case(0, "joints-plane");
}

#[test]
fn symmetric_wedge_srm_matches_the_wedge_factor() {
    run_case(1, "joints-wedge");
}

#[test]
fn general_wedge_srm_matches_the_vector_solution() {
    run_case(2, "joints-wedge-general");
}

#[test]
fn block_toppling_srm_matches_goodman_and_bray() {
    run_case(3, "joints-toppling");
}

/// The command line: a bad geometry file is exit code 2 naming the key, for
/// `cdem mesh` and `cdem kinematics` alike; `cdem kinematics` prints the table.
#[test]
fn the_commands_exit_2_on_bad_geometry_and_print_the_table() {
    let dir = std::env::temp_dir().join(format!("cdem-joints-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(root().join(GEOMETRIES[0])).unwrap();
    let bad = dir.join("bad-geometry.toml");
    std::fs::write(&bad, text.replacen("face_dip = 60.0", "face_dip = 100.0", 1)).unwrap();
    for command in ["mesh", "kinematics"] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_cdem"))
            .args([command, bad.to_str().unwrap(), "--out", dir.join("out").to_str().unwrap()])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{command}: {stderr}");
        assert!(stderr.contains("slope.face_dip"), "{command}: {stderr}");
    }
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cdem"))
        .args(["kinematics", root().join(GEOMETRIES[1]).to_str().unwrap(), "--out", dir.join("kin").to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("| set1 x set2 | 39.32 -> 270.00 | 75.00 | 35.0 | possible |")
    );
    let _ = std::fs::remove_dir_all(&dir);
}
