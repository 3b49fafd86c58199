//! The scene's `[analysis]`: eq. 19-22 on its slip circle from a solved
//! state. The circle is the scene's or the Bishop critical circle of its
//! `[lem]`; the arc is found and sampled in the (perturbed) mesh by
//! [`crate::analysis::arc`], the tractions come from the cells'
//! stresses and, where the circle is an `[[interface]]`, from its springs.

use serde::Serialize;

use crate::analysis::arc::{from_cell_stresses, length_per_cell, Arc, Station};
use crate::analysis::safety::{safety_factors_with, sign_segments, Segment, SurfacePoint};
use crate::analysis::slip::from_springs;
use crate::error::{Error, SceneError};
use crate::mesh::locate::CellLocator;
use crate::mesh::Mesh;
use crate::model::Model;
use crate::physics::joint::{JointStrength, StrengthSection};
use crate::physics::spring::SpringState;
use crate::scene::Scene;

/// Eq. 21/22 on the scene's surface: `analysis.json`, with the stations in
/// `analysis.csv`.
#[derive(Debug, Clone, Serialize)]
pub struct AnalysisReport {
    /// Where the circle comes from: `"scene"` or `"lem critical (Bishop)"`.
    pub circle_from: String,
    /// The Bishop FS of the LEM critical circle, when the circle is that one.
    pub lem_fs: Option<f64>,
    pub arc: Arc,
    /// The state the tractions are taken from.
    pub state: &'static str,
    /// How the strength was chosen.
    pub strength_from: String,
    pub min_segment: f64,
    /// From the cells' stresses at the stations.
    pub stresses: Factors,
    /// From the springs of `analysis.interface` (`cdem run` only).
    pub springs: Option<Factors>,
}

/// K, its parts and the K_i of one traction source.
#[derive(Debug, Clone, Serialize)]
pub struct Factors {
    /// Eq. 21: `K = sum R_i / sum D_i`.
    pub k: f64,
    /// `sum R_i`, `sum D_i` (N per metre of width for stations, N for springs).
    pub resisting: f64,
    pub driving: f64,
    pub segments: Vec<Segment>,
    #[serde(skip)]
    pub points: Vec<SurfacePoint>,
    /// `(cohesion (Pa), friction angle (deg))` at each point.
    #[serde(skip)]
    pub strength: Vec<(f64, f64)>,
    #[serde(skip)]
    pub k_i: Vec<f64>,
}

/// The springs of a CDEM state, for a surface that is an interface.
pub struct SpringSource<'a> {
    pub model: &'a Model,
    pub u: &'a [f64],
    pub springs: &'a SpringState,
}

/// The scene's `[analysis]` on cell stresses `stress` (mesh cell order) at
/// the perturbed node positions `coords`, and on springs when given; None
/// for a scene without `[analysis]`. `state` names the state for the report.
pub fn run_analysis(
    scene: &Scene,
    mesh: &Mesh,
    coords: &[[f64; 3]],
    stress: &[[f64; 6]],
    springs: Option<SpringSource>,
    state: &'static str,
) -> Result<Option<AnalysisReport>, Error> {
    let Some(spec) = &scene.analysis else { return Ok(None) };
    let invalid = |key: &str, reason: String| Error::from(SceneError::invalid(key, reason));
    let (circle, circle_from, lem_fs) = match spec.circle {
        Some(c) => (c, "scene".to_string(), None),
        None => {
            let result = crate::lem::analyse(&super::scene_lem_input(scene)?)?;
            let c = result.critical.bishop.ok_or_else(|| {
                invalid("analysis.circle", "missing, and the [lem] search found no Bishop critical circle".into())
            })?;
            (c.circle, "lem critical (Bishop)".to_string(), Some(c.fs))
        }
    };
    let y = spec.y.unwrap_or_else(|| {
        let (lo, hi) = coords.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |m, p| (m.0.min(p[1]), m.1.max(p[1])));
        0.5 * (lo + hi)
    });
    let locator = CellLocator::new(coords, &mesh.cells);
    let key = if spec.circle.is_some() { "analysis.circle" } else { "analysis" };
    let arc = Arc::find(&locator, circle, y).map_err(|r| invalid(key, r))?;
    let stations = arc.stations(&locator, spec.stations);
    let min_segment = spec.min_segment.unwrap_or_else(|| length_per_cell(&arc, &stations));

    // The strength: the table's, else the interface's, else each station's material in [lem].
    let interface_strength = spec
        .interface
        .as_ref()
        .and_then(|name| scene.interface.iter().find(|i| &i.group == name).and_then(|i| i.strength.as_ref()));
    let uniform: Option<(PointStrength, String)> = match (spec.strength, interface_strength) {
        (Some(st), _) => Some((PointStrength::MohrCoulomb(st.cohesion, st.friction_angle), "analysis.strength".into())),
        (None, Some(st)) => {
            Some((PointStrength::of(st), format!("interface {:?}", spec.interface.as_deref().unwrap_or_default())))
        }
        (None, None) => None,
    };
    let (per_station, strength_from) = match &uniform {
        Some((strength, from)) => (vec![*strength; stations.len()], from.clone()),
        None => (
            material_strengths(scene, mesh, &stations)?
                .into_iter()
                .map(|(c, phi)| PointStrength::MohrCoulomb(c, phi))
                .collect(),
            "[[lem.material]] of each station's cell".into(),
        ),
    };
    let mut points = from_cell_stresses(&arc, &stations, stress);
    // With water the blocks carry the total stress: eq. 19 takes the effective
    // normal stress sigma_n' = sigma_n - u (the springs' is effective already).
    if let Some(surface) = scene.water.as_ref().map(|w| w.phreatic()).transpose()?.flatten() {
        for (p, st) in points.iter_mut().zip(&stations) {
            p.sigma_n -= surface.pressure(st.x[0], st.x[2]);
        }
    }
    let stresses = factors(points, per_station, min_segment);

    let springs = match (&spec.interface, springs) {
        (Some(name), Some(src)) => {
            let strength = uniform.as_ref().map(|u| u.0).ok_or_else(|| {
                invalid(
                    "analysis.strength",
                    format!("missing: interface {name:?} has no strength and the springs need one"),
                )
            })?;
            let pts = from_springs(src.model, src.u, src.springs, name, &arc.slip_circle())
                .ok_or_else(|| invalid("analysis.interface", format!("{name:?} has no springs in the model")))?;
            let n = pts.len();
            Some(factors(pts, vec![strength; n], min_segment))
        }
        _ => None,
    };
    Ok(Some(AnalysisReport { circle_from, lem_fs, arc, state, strength_from, min_segment, stresses, springs }))
}

/// The strength eq. 21 takes at a point: Mohr-Coulomb's `(c (Pa), phi
/// (deg))` (`[analysis].strength`, `[[lem.material]]`, a Coulomb interface)
/// or a joint law's envelope (an interface of another law).
#[derive(Debug, Clone, Copy)]
enum PointStrength {
    MohrCoulomb(f64, f64),
    Joint(JointStrength),
}

impl PointStrength {
    fn of(st: &StrengthSection) -> Self {
        match st.coulomb() {
            Some(c) => PointStrength::MohrCoulomb(c.cohesion, c.friction_angle),
            None => PointStrength::Joint(st.strength()),
        }
    }
    /// The shear strength (Pa) at the normal stress `sigma_n` (Pa).
    fn tau(&self, sigma_n: f64) -> f64 {
        match *self {
            PointStrength::MohrCoulomb(c, phi) => sigma_n * phi.to_radians().tan() + c,
            PointStrength::Joint(j) => j.shear_strength(sigma_n),
        }
    }
    /// As `analysis.csv` shows it, `(c, phi)`: a joint law's secant angle
    /// `atan(tau / sigma_n)` at the point (no cohesion).
    fn shown(&self, sigma_n: f64) -> (f64, f64) {
        match *self {
            PointStrength::MohrCoulomb(c, phi) => (c, phi),
            PointStrength::Joint(j) if sigma_n > 0.0 => {
                (0.0, (j.shear_strength(sigma_n) / sigma_n).atan().to_degrees())
            }
            PointStrength::Joint(_) => (0.0, 0.0),
        }
    }
}

fn factors(points: Vec<SurfacePoint>, strength: Vec<PointStrength>, min_segment: f64) -> Factors {
    let sf = safety_factors_with(&points, |i, sigma_n| strength[i].tau(sigma_n));
    let strength = points.iter().zip(&strength).map(|(p, st)| st.shown(p.sigma_n)).collect();
    let s: Vec<f64> = points.iter().map(|p| p.s).collect();
    let segments = sign_segments(&s, &sf.k_i, min_segment);
    Factors { k: sf.k, resisting: sf.resisting, driving: sf.driving, segments, points, strength, k_i: sf.k_i }
}

/// Each station's strength from the `[[lem.material]]` of its cell's volume group.
fn material_strengths(scene: &Scene, mesh: &Mesh, stations: &[Station]) -> Result<Vec<(f64, f64)>, Error> {
    let missing = || {
        Error::from(SceneError::invalid(
            "analysis.strength",
            "missing: give it, an interface with a strength, or [[lem.material]] for the groups the circle crosses",
        ))
    };
    let lem = scene.lem.as_ref().ok_or_else(missing)?;
    let mut group_of = vec![None; mesh.cells.len()];
    for g in mesh.groups.iter().filter(|g| g.dim == 3) {
        for &c in &g.cells {
            group_of[c] = Some(g.name.as_str());
        }
    }
    stations
        .iter()
        .map(|st| {
            let group = group_of[st.cell].unwrap_or("(none)");
            lem.strength_of(group).ok_or_else(|| {
                Error::from(SceneError::invalid(
                    "analysis.strength",
                    format!("missing: the circle crosses volume group {group:?}, which has no [[lem.material]]"),
                ))
            })
        })
        .collect()
}
