//! `cdem lem` on a CDEM scene: the section, its zones and unit weights taken
//! from the scene's own mesh and materials (`[lem]`, `lem::SceneLem`), checked
//! against the LEM input files that state the same section by hand.

use std::path::Path;

use cdem::drivers::load_lem_input;
use cdem::error::SceneError;
use cdem::harness::registry as reg;
use cdem::lem::{analyse, cut_mesh, evaluate_circle, LemInput, Method};
use cdem::scene::Scene;

fn lem_of_scene(path: &str, edit: impl Fn(String) -> String) -> cdem::Result<LemInput> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    let text = edit(std::fs::read_to_string(&path).unwrap());
    let scene = Scene::from_toml(&text, path.parent().unwrap(), &path)?;
    cdem::drivers::scene_lem_input(&scene)
}

/// Applies `edit` to the scene's `[lem]` part only (the joints above use the same keys).
fn in_lem(edit: impl Fn(String) -> String) -> impl Fn(String) -> String {
    move |t: String| {
        let at = t.find("[lem]").expect("the scene has a [lem] table");
        format!("{}{}", &t[..at], edit(t[at..].to_string()))
    }
}

fn invalid_key(r: cdem::Result<LemInput>) -> (String, String) {
    match r {
        Err(cdem::Error::Scene(SceneError::Invalid { key, reason })) => (key, reason),
        other => panic!("expected an invalid key, got {other:?}"),
    }
}

/// The paper slope's scene with `[lem]` (ground = the top of the section at
/// y = 0) and `verification/lem/paper-slope.toml` (ground = the "ground"
/// group) describe the same section: the same factors of safety.
#[test]
fn the_paper_slope_scene_gives_the_lem_file_s_factors_of_safety() {
    let from_scene = analyse(&load_lem_input(Path::new("verification/cases/slope/slope.toml")).unwrap()).unwrap();
    let from_file = analyse(&reg::LEM_PAPER_SLOPE.lem_input().unwrap()).unwrap();
    for m in Method::ALL {
        let (a, b) = (from_scene.fs.get(m).unwrap(), from_file.fs.get(m).unwrap());
        assert!((a - b).abs() <= 1e-12 * b, "{m:?}: scene {a}, LEM file {b}");
    }
    let bishop = from_scene.fs.get(Method::Bishop).unwrap();
    assert!((bishop - reg::PAPER_LEM_FS.value).abs() <= reg::TOL_PAPER_LEM_FS_ABSOLUTE, "{bishop}");
}

/// Wulong's front section is cut into its two volume groups: their outlines
/// tile the section's outline, the near-surface band lies along the ground.
#[test]
fn wulong_zones_tile_the_section() {
    let scene = Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join(reg::WULONG.input)).unwrap();
    let mesh = cdem::drivers::read_mesh(&scene).unwrap();
    let cut = cut_mesh(&mesh, 0.0).unwrap();
    let area = |p: &[[f64; 2]]| {
        0.5 * (0..p.len()).map(|i| p[i][0] * p[(i + 1) % p.len()][1] - p[(i + 1) % p.len()][0] * p[i][1]).sum::<f64>()
    };
    let names: Vec<&str> = cut.zones.iter().map(|(g, _)| g.as_str()).collect();
    assert_eq!(names.len(), 2, "{names:?}");
    assert!(names.contains(&"interior") && names.contains(&"nearsurface"), "{names:?}");
    let zones: f64 = cut.zones.iter().flat_map(|(_, l)| l.iter()).map(|p| area(p)).sum();
    assert_eq!(cut.outline.len(), 1, "one piece");
    let whole = area(&cut.outline[0]);
    assert!(whole > 0.0 && (zones - whole).abs() <= 1e-9 * whole, "zones {zones} m^2, section {whole} m^2");
    let ground = cut.ground().unwrap();
    assert!(ground.windows(2).all(|w| w[1][0] > w[0][0]), "x increases along the ground");
    let (lo, hi) = (ground[0][1], ground[ground.len() - 1][1]);
    assert!(hi > lo + 30.0, "the ground rises toward +x (the slope faces -x): {lo} -> {hi}");
}

/// The zoned section agrees with the homogeneous one when the zones are
/// (almost) equal in strength: the zone polygons cover the section exactly.
#[test]
fn zones_of_almost_one_strength_give_the_homogeneous_factor_of_safety() {
    let same =
        |t: String| t.replace("cohesion = 40.0e3\nfriction_angle = 33.0", "cohesion = 24.0e3\nfriction_angle = 30.0");
    let homogeneous = lem_of_scene(reg::WULONG.input, in_lem(same)).unwrap();
    assert!(homogeneous.section.zones().is_empty(), "equal strengths: one material");
    let nearly = |t: String| same(t).replacen("cohesion = 24.0e3", "cohesion = 24.000001e3", 1);
    let zoned = lem_of_scene(reg::WULONG.input, in_lem(nearly)).unwrap();
    assert_eq!(zoned.section.zones().len(), 2);
    // On the homogeneous critical circle, with slices fine enough that the
    // zoned weights (columns at slice centres) equal the exact areas.
    let circle = analyse(&homogeneous).unwrap().critical.get(Method::Bishop).unwrap().circle;
    let (a, b) = (
        evaluate_circle(&homogeneous.section, circle, 400).unwrap(),
        evaluate_circle(&zoned.section, circle, 400).unwrap(),
    );
    for m in Method::ALL {
        let (x, y) = (a.get(m).unwrap(), b.get(m).unwrap());
        assert!((x - y).abs() <= 1e-4 * x, "{m:?}: homogeneous {x}, zoned {y}");
    }
}

/// The weaker near-surface band governs Wulong: stronger interior rock
/// changes nothing the band alone decides, a weaker band lowers the FS.
#[test]
fn wulong_fs_follows_the_near_surface_band() {
    let base = analyse(&lem_of_scene(reg::WULONG.input, |t| t).unwrap()).unwrap();
    let weak = |t: String| t.replacen("cohesion = 24.0e3", "cohesion = 12.0e3", 1);
    let weaker = analyse(&lem_of_scene(reg::WULONG.input, in_lem(weak)).unwrap()).unwrap();
    let (f0, f1) = (base.fs.get(Method::Bishop).unwrap(), weaker.fs.get(Method::Bishop).unwrap());
    assert!(f1 < f0, "halving the band's cohesion: {f0} -> {f1}");
}

#[test]
fn scene_lem_errors_name_the_key_and_the_groups() {
    let (key, reason) = invalid_key(lem_of_scene(reg::WULONG.input, |t| {
        t.replace("group = \"interior\"\ncohesion", "group = \"inner\"\ncohesion")
    }));
    assert_eq!(key, "lem.material", "{reason}");
    assert!(reason.contains("\"interior\""), "{reason}");
    let (key, reason) = invalid_key(lem_of_scene(reg::WULONG.input, |t| {
        t + "\n[[lem.material]]\ngroup = \"nowhere\"\ncohesion = 1.0\nfriction_angle = 30.0\n"
    }));
    assert_eq!(key, "lem.material[2].group", "{reason}");
    assert!(reason.contains("\"nearsurface\""), "{reason}");
    let (key, reason) =
        invalid_key(lem_of_scene(reg::WULONG.input, |t| t.replace("[lem]\n", "[lem]\ny_plane = 5.0\n")));
    assert_eq!(key, "lem.y_plane", "{reason}");
    let (key, reason) = invalid_key(lem_of_scene(
        reg::WULONG.input,
        in_lem(|t| t.replace("friction_angle = 33.0", "friction_angle = 95.0")),
    ));
    assert_eq!(key, "lem.material[1].friction_angle", "{reason}");
    let (key, _) = invalid_key(lem_of_scene(reg::WULONG.input, |t| t.replace("[lem]\n", "[lem]\nslices = 1\n")));
    assert_eq!(key, "lem.slices");
    let (key, reason) =
        invalid_key(lem_of_scene(reg::SLOPE.input, |t| t.replace("[lem]\n", "[lem]\nground_group = \"bottom_\"\n")));
    assert_eq!(key, "lem.ground_group", "{reason}");
    let (key, reason) = invalid_key(lem_of_scene(reg::COLUMN.input, |t| t));
    assert_eq!(key, "lem", "{reason}");
}
