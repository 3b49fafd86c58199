//! `summary.json`: the numbers a run is judged by. A CDEM run and the FEM
//! reference write the same keys, so this record sits at the bottom of the
//! layers beside [`crate::error`], plain data that every layer may fill in.
//!
//! A CDEM run has a `phase1` section (elastic) and, for a scene with
//! `[failure]`, a `phase2` section (breakable joints); the top-level
//! `end_state`, `converged`, `steps` (both phases), `unbalanced_ratio` and
//! field extremes describe the end of the whole run.

use serde::{Deserialize, Serialize};

/// How a run (or one phase of it) ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum EndState {
    /// Converged: the unbalanced-force ratio fell below the tolerance.
    Equilibrium,
    /// The mass kept moving: the displacement since phase 1 passed the
    /// sliding bound.
    GlobalSliding,
    /// Neither within the step budget.
    Undecided,
}

/// Number of failed springs by kind.
#[derive(Debug, Clone, Copy, Default, Serialize, PartialEq, Eq)]
pub struct FailedSprings {
    pub tension: usize,
    pub shear: usize,
}

impl FailedSprings {
    /// Failed either way.
    pub fn total(&self) -> usize {
        self.tension + self.shear
    }
}

/// One phase of a CDEM run.
#[derive(Debug, Clone, Serialize)]
pub struct PhaseSummary {
    pub end_state: EndState,
    pub steps: usize,
    /// The unbalanced-force ratio at the phase's last step.
    pub unbalanced_ratio: f64,
    pub failed_springs: FailedSprings,
    /// Largest nodal displacement since the start of the phase (m).
    pub max_displacement: f64,
}

/// `|d|` of a 3-vector: the one per-node magnitude formula.
#[inline]
pub fn magnitude(d: [f64; 3]) -> f64 {
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

/// Each node's displacement magnitude since `u0` (3 per node, like `u`).
pub fn distances<'a>(u: &'a [f64], u0: &'a [f64]) -> impl Iterator<Item = f64> + 'a {
    u.chunks(3).zip(u0.chunks(3)).map(|(a, b)| magnitude([a[0] - b[0], a[1] - b[1], a[2] - b[2]]))
}

/// Largest nodal displacement of `u` since `u0` (m).
pub fn max_displacement_since(u: &[f64], u0: &[f64]) -> f64 {
    distances(u, u0).fold(0.0, f64::max)
}

/// Largest nodal displacement magnitude of `u` (m).
pub fn max_displacement(u: &[f64]) -> f64 {
    u.chunks(3).map(|d| magnitude([d[0], d[1], d[2]])).fold(0.0, f64::max)
}

/// Extremes of a displacement field (3 per node) and of element stresses.
#[derive(Debug, Clone, Copy)]
pub struct FieldExtremes {
    pub max_abs_uz: f64,
    pub min_uz: f64,
    pub max_abs_u: f64,
    pub min_szz: Option<f64>,
}

impl FieldExtremes {
    pub fn of(u: &[f64], stress: Option<&[[f64; 6]]>) -> Self {
        let uz = u.chunks(3).map(|d| d[2]);
        Self {
            max_abs_uz: uz.clone().map(f64::abs).fold(0.0, f64::max),
            min_uz: uz.fold(0.0, f64::min),
            max_abs_u: max_displacement(u),
            min_szz: stress.map(|s| s.iter().map(|x| x[2]).fold(f64::INFINITY, f64::min)),
        }
    }
}

/// `summary.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    pub end_state: EndState,
    /// `end_state == Equilibrium`.
    pub converged: bool,
    /// Steps of all phases (1 for the FEM).
    pub steps: usize,
    pub wall_s: f64,
    /// Time step (s; 1 with mass scaling, a fictitious time; 0 for the FEM).
    pub dt: f64,
    /// At the last step (FEM: the relative residual).
    pub unbalanced_ratio: f64,
    /// Largest |u_z| over all nodes (m).
    pub max_abs_uz: f64,
    /// Most negative u_z (m).
    pub min_uz: f64,
    /// Largest displacement magnitude (m).
    pub max_abs_u: f64,
    /// Most compressive element sigma_zz (Pa), if stresses were computed.
    pub min_szz: Option<f64>,
    pub failed_springs: FailedSprings,
    pub elements: usize,
    pub nodes: usize,
    pub springs: usize,
    /// The elastic phase (CDEM runs).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub phase1: Option<PhaseSummary>,
    /// The failure phase (scenes with `[failure]`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub phase2: Option<PhaseSummary>,
    /// The plastic blocks at the end (scenes with a `[[material]] strength`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic: Option<PlasticSummary>,
    /// The pore water that ran (scenes with `[water]`); absent: dry.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub water: Option<WaterSummary>,
    /// The runout (`[runout]`), if the scene asks for one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout: Option<RunoutSummary>,
}

/// What a runout did (docs/method.md 2.9d; `runout.csv` has its course).
#[derive(Debug, Clone, Default, Serialize, PartialEq)]
pub struct RunoutSummary {
    /// Whether it ran; if not, why (the scene did not slide).
    pub ran: bool,
    pub reason: Option<String>,
    pub steps: usize,
    /// Time run (s) and the time step (s).
    pub time: f64,
    pub dt: f64,
    /// Springs whose stiffness `[runout] stiffness_limit` lowered.
    pub springs_limited: usize,
    /// When the moving mass came to rest (s since the runout's start), if it did.
    pub time_to_rest: Option<f64>,
    /// Largest speed of any node (m/s).
    pub peak_velocity: f64,
    /// Largest displacement of any node during the runout (m): the runout distance.
    pub runout_distance: f64,
    /// The box of the blocks that moved more than 1 % of the runout distance, at the end (m).
    pub deposit_min: [f64; 3],
    pub deposit_max: [f64; 3],
    /// Volume of those blocks (m^3).
    pub moved_volume: f64,
    /// Their centre of mass: its drop along gravity and its travel across it
    /// (m), and the angle of that path, `atan(drop / travel)` (degrees): the
    /// energy line's, which the sled model puts at the friction angle.
    pub mass_drop: f64,
    pub mass_travel: f64,
    pub travel_angle: f64,
    /// The energy budget (J): gravity + water = kinetic + elastic + friction + joints + damping.
    pub energy_gravity: f64,
    /// Work of the pore water's forces (0 without `[water]`).
    pub energy_water: f64,
    pub energy_kinetic: f64,
    pub energy_elastic: f64,
    pub energy_friction: f64,
    pub energy_joints: f64,
    pub energy_damping: f64,
    /// `|residual| / max(|gravity work|, kinetic energy at the start)`.
    pub energy_closure: f64,
}

/// Which water model ran, and on what.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WaterSummary {
    /// The model, in words (joint water: impermeable blocks).
    pub model: String,
    /// The phreatic surface `[x, z]` (m) as it ran (raised by `rise`), if any.
    pub surface: Option<Vec<[f64; 2]>>,
    /// `gamma_w` (N/m^3).
    pub unit_weight: f64,
    /// `"vertical"` or `"cos2"`.
    pub hu: String,
    /// `(interface group, level (m))` of each water-filled crack.
    pub cracks: Vec<(String, f64)>,
    /// Resultant of the water forces on the model (N).
    pub resultant: [f64; 3],
    /// Springs below the water (u > 0) of all springs.
    pub wet_springs: usize,
}

/// How much of the plastic blocks yields (m^3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PlasticSummary {
    /// Volume of the plastic blocks.
    pub volume: f64,
    /// Volume of their tetrahedra on the yield surface at the last step.
    pub yielding_volume: f64,
    /// Volume of their tetrahedra that have yielded at some step.
    pub yielded_volume: f64,
    /// Of `yielding_volume` and `yielded_volume`: the volume on a tension
    /// plane (the rest yields in shear alone).
    pub yielding_tension_volume: f64,
    pub yielded_tension_volume: f64,
    /// Largest element plastic shear strain (FLAC's measure).
    pub max_plastic_shear: f64,
}
