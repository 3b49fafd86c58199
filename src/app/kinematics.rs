//! `cdem kinematics GEOMETRY.toml --out DIR`: the Markland / Hoek-Bray
//! kinematic tests of a geometry file's joint sets on its slope face
//! ([`crate::analysis::kinematics`]), as a table (`kinematics.md`, returned
//! for printing) and a stereonet (`stereonet.png`).

use std::fmt::Write as _;
use std::path::Path;

use crate::analysis::kinematics::{analyse, Orientation, PairTest, SetInput, SetTests, LATERAL_LIMIT};
use crate::error::{Error, SceneError};
use crate::output::figures::stereonet::stereonet;
use crate::scene::joint_sets::Geometry;

/// The tests and the table.
pub struct Kinematics {
    pub face: Orientation,
    pub sets: Vec<SetInput>,
    pub singles: Vec<SetTests>,
    pub pairs: Vec<PairTest>,
    pub table: String,
}

/// The face and the sets of a geometry file; each set's friction angle is
/// its strength's (a set without a strength is an error naming it).
pub fn inputs(g: &Geometry) -> Result<(Orientation, Vec<SetInput>), SceneError> {
    let face = Orientation { dip: g.slope.face_dip, dip_direction: g.slope.face_dip_direction.rem_euclid(360.0) };
    let sets = g
        .joint_set
        .iter()
        .enumerate()
        .map(|(i, j)| {
            let friction = j.strength.map(|s| s.friction_angle()).ok_or_else(|| {
                SceneError::invalid(
                    format!("joint_set[{i}].strength"),
                    "the kinematic tests need the set's friction angle",
                )
            })?;
            Ok(SetInput {
                orientation: Orientation { dip: j.dip, dip_direction: j.dip_direction.rem_euclid(360.0) },
                friction,
            })
        })
        .collect::<Result<Vec<_>, SceneError>>()?;
    Ok((face, sets))
}

/// The table of the tests (Markdown).
pub fn table(face: Orientation, sets: &[SetInput], singles: &[SetTests], pairs: &[PairTest]) -> String {
    let yes = |b: bool| if b { "possible" } else { "-" };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Slope face {:.1}/{:05.1} (dip/dip direction); lateral limits +-{LATERAL_LIMIT} deg.\n",
        face.dip, face.dip_direction
    );
    let _ = writeln!(
        t,
        "| set | dip/dip direction | friction | plane sliding | flexural toppling |\n|---|---|---|---|---|"
    );
    for s in singles {
        let o = sets[s.set].orientation;
        let _ = writeln!(
            t,
            "| set{} | {:.1}/{:05.1} | {:.1} | {} | {} |",
            s.set + 1,
            o.dip,
            o.dip_direction,
            sets[s.set].friction,
            yes(s.plane_sliding),
            yes(s.flexural_toppling)
        );
    }
    if !pairs.is_empty() {
        let _ = writeln!(t, "\n| pair | intersection plunge -> trend | face apparent dip along it | friction | wedge sliding |\n|---|---|---|---|---|");
        for p in pairs {
            let (a, b) = p.sets;
            let line =
                p.intersection.map_or("parallel".to_string(), |l| format!("{:.2} -> {:06.2}", l.plunge.abs(), l.trend));
            let friction = sets[a].friction.min(sets[b].friction);
            let _ = writeln!(
                t,
                "| set{} x set{} | {line} | {:.2} | {friction:.1} | {} |",
                a + 1,
                b + 1,
                p.face_apparent_dip,
                yes(p.wedge_sliding)
            );
        }
    }
    t
}

/// Loads, tests, writes `DIR/kinematics.md` and `DIR/stereonet.png`.
pub fn kinematics(path: &Path, out: &Path) -> crate::Result<Kinematics> {
    let g = Geometry::load(path)?;
    let (face, sets) = inputs(&g)?;
    let (singles, pairs) = analyse(&sets, face);
    let table = table(face, &sets, &singles, &pairs);
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    let md = out.join("kinematics.md");
    crate::output::write_atomic(&md, format!("# Kinematic analysis of {}\n\n{table}", path.display()).as_bytes())?;
    let labelled: Vec<(String, Orientation)> =
        sets.iter().enumerate().map(|(i, s)| (format!("set{}", i + 1), s.orientation)).collect();
    // The figure's friction circle and cone: the largest friction angle of
    // the sets (a set without friction, like an open tension crack, would put
    // them on the rim and at the centre); the table uses each set's own.
    let friction = sets.iter().map(|s| s.friction).fold(f64::NEG_INFINITY, f64::max);
    let friction = if friction.is_finite() { friction } else { 30.0 };
    stereonet(&out.join("stereonet.png"), face, &labelled, friction, &pairs)?;
    Ok(Kinematics { face, sets, singles, pairs, table })
}
