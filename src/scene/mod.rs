//! Scene files (TOML). Unknown keys are rejected; every bad value is a
//! [`SceneError::Invalid`] naming its key. Units are SI throughout.
//!
//! ```toml
//! [mesh]
//! file = "column.msh"            # relative to the scene file
//!
//! [perturbation]                 # optional: stochastic structural planes
//! ratio = 0.1                    # max offset per axis / local edge length
//! seed = 1
//! keep_flat = ["xmin"]           # plane surface groups whose nodes stay on their plane
//! keep_on = ["slip"]             # surface groups (curved too) whose nodes stay on them
//!
//! [[material]]
//! group = "rock"                 # a volume physical group
//! youngs_modulus = 3.0e8
//! poisson_ratio = 0.3
//! density = 2100.0
//! strength = { cohesion = 50e3, friction_angle = 35.0, tensile = 0.0, dilation_angle = 0.0 }
//!                                # optional: a Mohr-Coulomb rock mass that yields in the
//!                                # failure phase: c (Pa), phi (deg), T (Pa; default: the
//!                                # apex c / tan(phi)), psi (deg, default 0, at most phi)
//!
//! [joints]                       # every element interface not listed below
//! mode = "springs"               # or "merged": shared nodes, no springs
//! normal_modulus = 3.0e10        # E_j (Pa), eq. 16
//! shear_modulus = 1.15e10        # G_j (Pa)
//! thickness = 1.0                # L (m)
//!
//! [[interface]]                  # a surface group between elements
//! group = "slip"
//! mode = "springs"               # moduli default to [joints]'
//! strength = { tensile = 0.0, cohesion = 16e3, friction_angle = 18.0 }
//!                                # breakable (failure phase only): T, c (Pa), phi (deg)
//!
//! [[boundary]]
//! group = "bottom"
//! fix = ["x", "y", "z"]
//!
//! [loads]
//! gravity = [0.0, 0.0, -9.81]
//!
//! [solver]                       # see SolverParams for every field
//! tolerance = 1e-5
//!
//! [output]
//! vtk = true
//!
//! [ensemble]                     # optional: `cdem ensemble` (see EnsembleSpec)
//! members = 100
//! [[ensemble.random]]
//! key = "interface[0].strength.cohesion"
//! std_dev = 2e3
//!
//! [water]                        # optional: pore water (physics::water, model::water)
//! surface = [[0.0, 30.0], [40.0, 30.0], [80.0, 22.0]]   # phreatic surface [x, z] (m), x increasing
//! rise = 0.0                     # raises the whole surface (m): the water level as one number
//! unit_weight = 9810.0           # gamma_w (N/m^3)
//! hu = "vertical"                # or "cos2" (Slide's correction under a sloping surface)
//! [[water.crack]]                # an [[interface]] group filled to a level (m)
//! group = "crack"
//! level = 32.0
//!
//! [analysis]                     # optional: eq. 21/22 on a slip circle (see AnalysisSpec)
//! circle = { xc = 24.006, zc = 63.222, r = 43.41 }   # absent: the critical circle of [lem]
//!
//! [lem]                          # optional: `cdem lem` on this scene (see lem::SceneLem)
//! ground_group = "ground"
//! [[lem.material]]
//! group = "rock"
//! cohesion = 16e3
//! friction_angle = 18.0          # unit_weight defaults to density x |gravity|
//! ```

mod analysis;
mod ensemble;
pub mod joint_sets;
mod runout;
mod validate;

use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::error::SceneError;
pub use crate::model::spec::{
    Axis, Boundary, CrackSection, JointMode, JointSection, MaterialSection, ModelSpec, Perturbation,
    RockStrengthSection, StrengthSection, WaterSection,
};
use crate::solver::SolverParams;
pub use analysis::{AnalysisSpec, SurfaceStrength};
pub use ensemble::{Analysis, Distribution, EnsembleSpec, LemSurface, RandomVariable};
pub use runout::{RunoutSection, RunoutStart};

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    pub mesh: MeshSection,
    #[serde(default)]
    pub perturbation: Perturbation,
    pub material: Vec<MaterialSection>,
    #[serde(default)]
    pub joints: JointSection,
    #[serde(default)]
    pub interface: Vec<JointSection>,
    #[serde(default)]
    pub boundary: Vec<Boundary>,
    #[serde(default)]
    pub loads: Loads,
    #[serde(default)]
    pub solver: SolverParams,
    #[serde(default)]
    pub output: Output,
    /// Phase 2 (progressive failure), if present.
    pub failure: Option<FailureParams>,
    /// The limit-equilibrium analysis of this mesh (`cdem lem SCENE.toml`), if present.
    pub lem: Option<crate::lem::SceneLem>,
    /// The Monte-Carlo ensemble of this scene (`cdem ensemble`), if present.
    pub ensemble: Option<EnsembleSpec>,
    /// Eq. 21/22 on a slip circle (`cdem run`, `cdem fem`), if present.
    pub analysis: Option<AnalysisSpec>,
    /// Pore water (a phreatic surface, water-filled cracks), if present.
    pub water: Option<WaterSection>,
    /// The blocks in real time after the slope fails (`cdem run`), if present.
    pub runout: Option<RunoutSection>,
    /// Directory of the scene file: relative paths are resolved against it.
    #[serde(skip)]
    pub base_dir: PathBuf,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshSection {
    pub file: PathBuf,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Loads {
    /// Gravitational acceleration (m/s^2). Default `[0, 0, -9.81]`.
    #[serde(default = "default_gravity")]
    pub gravity: [f64; 3],
}

fn default_gravity() -> [f64; 3] {
    [0.0, 0.0, -9.81]
}

impl Default for Loads {
    fn default() -> Self {
        Self { gravity: default_gravity() }
    }
}

/// What a run writes. A scene computes only what it asks for.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Output {
    /// Write VTK frames (`.vtu` + `.pvd`). Default true.
    #[serde(default = "yes")]
    pub vtk: bool,
    /// Also write a VTK frame every this many steps (0: final state only).
    #[serde(default)]
    pub frame_every: usize,
    /// Record a history row every this many steps. Default 10.
    #[serde(default = "ten")]
    pub history_every: usize,
    /// Compute element stresses (needed for `min_szz` and VTK stress). Default true.
    #[serde(default = "yes")]
    pub stress: bool,
}

/// Scene section `[failure]`: present = run phase 2 (breakable joints).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FailureParams {
    /// Step limit of phase 2 (and of each `cdem srm` trial). Default: 10
    /// times the model's characteristic response time `N_r` with the phase-2
    /// masses (`solver::budget`; `drivers::failure::PHASE2_RESPONSE_TIMES`).
    pub max_steps: Option<usize>,
    /// Record a stage row every this many steps. Default 500.
    pub stage_every: usize,
    /// Also global sliding when the largest displacement since the end of
    /// phase 1 passes this bound (m). Default: none (the displacement rate
    /// decides, see [`crate::solver::Sliding`]).
    pub sliding_displacement: Option<f64>,
    /// The displacement-rate rule decides sliding only once the largest
    /// displacement since the end of phase 1 has reached this (m). Default:
    /// 1e-3 of the model's height with plastic blocks
    /// (`drivers::failure::PLASTIC_SLIDING_TRAVEL`), none (0) otherwise.
    /// Equal to `sliding_displacement`, a slide is that displacement reached.
    pub sliding_travel: Option<f64>,
    /// Node-block masses in phase 2 (default true; only where
    /// [`SolverParams::block_masses`] allows them: mass scaling and viscous
    /// damping, lumped masses otherwise). On the paper's
    /// slip-surface case they decide in 2,160 steps where lumped masses take
    /// 4,752 (58,580 before the displacement-rate rule; references/performance.md,
    /// rows `perf/phase2/*`).
    pub block_mass: bool,
    /// Plastic prisms and tetrahedra: the weight `alpha` of the
    /// node-smoothed deviatoric strain in their tetrahedra's strain
    /// ([`crate::physics::plastic::Volumetric::Smoothed`]), in [0, 1).
    /// Default [`crate::physics::plastic::NODE_SMOOTHING`] (0.6); 0: each
    /// cell's own deviatoric strain (their volumetric strain is the nodal
    /// average either way). Hexahedra do not use it.
    pub smoothing: f64,
}

impl Default for FailureParams {
    fn default() -> Self {
        Self {
            max_steps: None,
            stage_every: 500,
            sliding_displacement: None,
            sliding_travel: None,
            block_mass: true,
            smoothing: crate::physics::plastic::NODE_SMOOTHING,
        }
    }
}

impl FailureParams {
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.max_steps == Some(0) {
            return Err(SceneError::invalid("failure.max_steps", "must be at least 1"));
        }
        if self.stage_every == 0 {
            return Err(SceneError::invalid("failure.stage_every", "must be at least 1"));
        }
        if !(0.0..1.0).contains(&self.smoothing) {
            return Err(SceneError::invalid("failure.smoothing", "must be in [0, 1)"));
        }
        if let Some(d) = self.sliding_displacement {
            if !(d.is_finite() && d > 0.0) {
                return Err(SceneError::invalid("failure.sliding_displacement", "must be a finite positive length"));
            }
        }
        if let Some(d) = self.sliding_travel {
            if !(d.is_finite() && d >= 0.0) {
                return Err(SceneError::invalid("failure.sliding_travel", "must be a finite length >= 0"));
            }
        }
        Ok(())
    }
}

fn yes() -> bool {
    true
}
fn ten() -> usize {
    10
}

impl Default for Output {
    fn default() -> Self {
        Self { vtk: true, frame_every: 0, history_every: 10, stress: true }
    }
}

impl Scene {
    /// Parses and validates a scene from TOML text.
    pub fn from_toml(text: &str, base_dir: &Path, path_for_errors: &Path) -> Result<Self, SceneError> {
        let mut scene: Scene = toml::from_str(text)
            .map_err(|e| SceneError::Syntax { path: path_for_errors.to_path_buf(), message: e.to_string() })?;
        scene.base_dir = base_dir.to_path_buf();
        validate::validate(&scene)?;
        Ok(scene)
    }

    /// Checks a scene as [`Scene::from_toml`] checks a file's: for a scene
    /// changed in code (an ensemble member's drawn values).
    pub fn validate(&self) -> Result<(), SceneError> {
        validate::validate(self)
    }

    /// Reads, parses and validates a scene file.
    pub fn load(path: &Path) -> crate::Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| crate::Error::io(path, e))?;
        let base = path.parent().unwrap_or(Path::new("."));
        Ok(Self::from_toml(&text, base, path)?)
    }

    /// The model sections, for [`crate::model::build`] and the FEM.
    pub fn model_spec(&self) -> ModelSpec<'_> {
        ModelSpec {
            perturbation: &self.perturbation,
            material: &self.material,
            joints: &self.joints,
            interface: &self.interface,
            boundary: &self.boundary,
            gravity: self.loads.gravity,
            water: self.water.as_ref(),
            smoothing: self.failure.as_ref().map_or(crate::physics::plastic::NODE_SMOOTHING, |f| f.smoothing),
        }
    }

    /// The mesh path, resolved against the scene's directory.
    pub fn mesh_path(&self) -> PathBuf {
        self.base_dir.join(&self.mesh.file)
    }
}
