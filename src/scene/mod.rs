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
//! keep_flat = ["slip"]           # surface groups whose nodes stay on their plane
//!
//! [[material]]
//! group = "rock"                 # a volume physical group
//! youngs_modulus = 3.0e8
//! poisson_ratio = 0.3
//! density = 2100.0
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
//! ```

mod validate;

use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::error::SceneError;
use crate::solver::SolverParams;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    pub mesh: MeshSection,
    #[serde(default)]
    pub perturbation: Perturbation,
    pub material: Vec<MaterialSection>,
    #[serde(default)]
    pub joints: Joints,
    #[serde(default)]
    pub interface: Vec<InterfaceSection>,
    #[serde(default)]
    pub boundary: Vec<Boundary>,
    #[serde(default)]
    pub loads: Loads,
    #[serde(default)]
    pub solver: SolverParams,
    #[serde(default)]
    pub output: Output,
    /// Phase 2 (progressive failure), if present.
    pub failure: Option<crate::progressive::FailureParams>,
    /// Directory of the scene file: relative paths are resolved against it.
    #[serde(skip)]
    pub base_dir: PathBuf,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshSection {
    pub file: PathBuf,
}

#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Perturbation {
    /// Maximum offset per axis as a fraction of the local edge length (0 = off).
    #[serde(default)]
    pub ratio: f64,
    #[serde(default)]
    pub seed: u64,
    /// Surface groups whose nodes may move only within the group's plane.
    #[serde(default)]
    pub keep_flat: Vec<String>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSection {
    pub group: String,
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    pub density: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum JointMode {
    /// Node copies joined by springs (the CDEM default).
    #[default]
    Springs,
    /// Shared nodes, no springs: a continuous interface.
    Merged,
}

/// The default structural plane: every interface not listed in `[[interface]]`.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Joints {
    #[serde(default)]
    pub mode: JointMode,
    /// `E_j` (Pa).
    pub normal_modulus: Option<f64>,
    /// `G_j` (Pa).
    pub shear_modulus: Option<f64>,
    /// Equivalent thickness `L` (m).
    pub thickness: Option<f64>,
    /// Makes these joints breakable (eq. 17-18) in the failure phase.
    pub strength: Option<StrengthSection>,
}

/// Strength of a breakable structural plane.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StrengthSection {
    /// Tensile strength `T` (Pa), eq. 17.
    pub tensile: f64,
    /// Cohesion `c` (Pa), eq. 18.
    pub cohesion: f64,
    /// Friction angle `phi` (degrees, in [0, 90)), eq. 18.
    pub friction_angle: f64,
}

impl From<StrengthSection> for crate::physics::spring::Strength {
    fn from(s: StrengthSection) -> Self {
        Self { tensile: s.tensile, cohesion: s.cohesion, tan_phi: s.friction_angle.to_radians().tan() }
    }
}

/// An interface group (a surface physical group lying between elements).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InterfaceSection {
    pub group: String,
    #[serde(default)]
    pub mode: JointMode,
    pub normal_modulus: Option<f64>,
    pub shear_modulus: Option<f64>,
    pub thickness: Option<f64>,
    /// Makes this interface breakable (eq. 17-18) in the failure phase.
    pub strength: Option<StrengthSection>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    X,
    Y,
    Z,
}

impl Axis {
    /// Component index: x 0, y 1, z 2.
    pub fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
            Axis::Z => 2,
        }
    }
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Boundary {
    pub group: String,
    pub fix: Vec<Axis>,
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

    /// Reads, parses and validates a scene file.
    pub fn load(path: &Path) -> crate::Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| crate::Error::io(path, e))?;
        let base = path.parent().unwrap_or(Path::new("."));
        Ok(Self::from_toml(&text, base, path)?)
    }

    /// The mesh path, resolved against the scene's directory.
    pub fn mesh_path(&self) -> PathBuf {
        self.base_dir.join(&self.mesh.file)
    }
}
