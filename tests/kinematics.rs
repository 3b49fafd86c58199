//! The kinematic tests (`cdem kinematics`, src/analysis/kinematics.rs) against
//! orientations computed by hand and one read off a published stereonet.

use cdem::analysis::kinematics::{
    analyse, equal_area, flexural_toppling, intersection, plane_sliding, Line, Orientation, SetInput,
};

fn plane(dip: f64, dip_direction: f64) -> Orientation {
    Orientation { dip, dip_direction }
}

fn close(l: Line, plunge: f64, trend: f64, tol: f64) {
    assert!((l.plunge - plunge).abs() < tol && (l.trend - trend).abs() < tol, "{l:?} vs {plunge} -> {trend}");
}

#[test]
fn lines_of_intersection_match_hand_computed_ones() {
    // Two planes dipping 45 deg east and south: the line bisects them, trending 135 deg,
    // its plunge the apparent dip of either along 135: atan(tan 45 cos 45) = 35.264 deg.
    close(
        intersection(plane(45.0, 90.0), plane(45.0, 180.0)).unwrap(),
        std::f64::consts::FRAC_1_SQRT_2.atan().to_degrees(),
        135.0,
        1e-9,
    );
    // The symmetric wedge of verification/joints: 55/215 and 55/325 meet along 270 at
    // atan(tan 55 cos 55) = 39.3227 deg.
    let psi = (55f64.to_radians().tan() * 55f64.to_radians().cos()).atan().to_degrees();
    close(intersection(plane(55.0, 215.0), plane(55.0, 325.0)).unwrap(), psi, 270.0, 1e-9);
    assert!((psi - 39.3227).abs() < 1e-4);
    // A vertical plane striking north and a horizontal one: a horizontal line along north-south.
    let l = intersection(plane(90.0, 90.0), plane(0.0, 0.0)).unwrap();
    assert!(l.plunge.abs() < 1e-9 && (l.trend.rem_euclid(180.0)).abs() < 1e-9, "{l:?}");
    // Hudson & Harrison, Engineering Rock Mechanics (1997), appendix B: the planes 266/36
    // and 146/59 (dip direction/dip) intersect in 219/26, read off the stereonet to the degree.
    close(intersection(plane(36.0, 266.0), plane(59.0, 146.0)).unwrap(), 26.0, 219.0, 1.0);
    // Parallel planes have none.
    assert_eq!(intersection(plane(40.0, 10.0), plane(40.0, 10.0)), None);
}

#[test]
fn markland_tests_on_a_face_dipping_60_west() {
    let face = plane(60.0, 270.0);
    let set = |dip, dd, friction| SetInput { orientation: plane(dip, dd), friction };
    // Plane sliding: daylights, steeper than phi, within 20 deg of the face.
    assert!(plane_sliding(set(40.0, 270.0, 30.0), face));
    assert!(plane_sliding(set(40.0, 289.0, 30.0), face));
    assert!(!plane_sliding(set(40.0, 291.0, 30.0), face), "outside the lateral limit");
    assert!(!plane_sliding(set(40.0, 270.0, 45.0), face), "flatter than phi");
    assert!(!plane_sliding(set(65.0, 270.0, 30.0), face), "does not daylight");
    // Flexural toppling: dips into the slope with (90 - dip) + phi < face dip.
    assert!(flexural_toppling(set(80.0, 90.0, 30.0), face));
    assert!(!flexural_toppling(set(60.0, 90.0, 30.0), face), "(90 - 60) + 30 = 60 is not < 60");
    assert!(!flexural_toppling(set(80.0, 270.0, 30.0), face), "dips out of the slope");
    // Wedge: the symmetric pair on a 75 deg face daylights (39.3 < 75) above phi = 35,
    // not above phi = 40.
    let face75 = plane(75.0, 270.0);
    let (_, pairs) = analyse(&[set(55.0, 215.0, 35.0), set(55.0, 325.0, 35.0)], face75);
    assert!(pairs[0].wedge_sliding && (pairs[0].face_apparent_dip - 75.0).abs() < 1e-9);
    let (_, pairs) = analyse(&[set(55.0, 215.0, 40.0), set(55.0, 325.0, 45.0)], face75);
    assert!(!pairs[0].wedge_sliding);
    // A line plunging into the slope does not daylight.
    let (_, pairs) = analyse(&[set(55.0, 35.0, 20.0), set(55.0, 145.0, 20.0)], face75);
    assert!((pairs[0].intersection.unwrap().trend - 90.0).abs() < 1e-9 && !pairs[0].wedge_sliding);
}

#[test]
fn the_equal_area_projection_puts_vertical_at_the_centre_and_horizontal_on_the_rim() {
    let c = equal_area(Line { plunge: 90.0, trend: 123.0 });
    assert!(c.0.abs() < 1e-12 && c.1.abs() < 1e-12);
    let e = equal_area(Line { plunge: 0.0, trend: 90.0 });
    assert!((e.0 - 1.0).abs() < 1e-12 && e.1.abs() < 1e-12);
    // Equal area: plunge 30 lies at sqrt(2) sin(30 deg) = 0.7071 of the radius.
    let p = equal_area(Line { plunge: 30.0, trend: 0.0 });
    assert!((p.1 - std::f64::consts::SQRT_2 * 0.5).abs() < 1e-12);
}

#[test]
fn cdem_kinematics_writes_the_table_and_the_stereonet() {
    let out = std::env::temp_dir().join(format!("cdem-kinematics-{}", std::process::id()));
    let geometry = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("verification/joints/wedge-geometry.toml");
    let k = cdem::app::kinematics::kinematics(&geometry, &out).unwrap();
    assert!(k.table.contains("| set1 x set2 | 39.32 -> 270.00 | 75.00 | 35.0 | possible |"), "{}", k.table);
    assert!(out.join("stereonet.png").is_file() && out.join("kinematics.md").is_file());
    let _ = std::fs::remove_dir_all(&out);
}
