//! What a model is built from besides its mesh: the model sections of a
//! scene file (`[perturbation]`, `[[material]]`, `[joints]` and `[[interface]]`,
//! `[[boundary]]`) and gravity. The scene parses them; [`build`](super::build)
//! reads them through a [`ModelSpec`]. Keys and defaults are documented in
//! the `scene` module.

use serde::Deserialize;

use crate::physics::joint::JointProps;
pub use crate::physics::joint::Softening;
pub use crate::physics::joint::StrengthSection;
use crate::physics::material::RockStrength;

/// The model's inputs, borrowed from a scene (or made by hand in a test).
#[derive(Debug, Clone, Copy)]
pub struct ModelSpec<'a> {
    pub perturbation: &'a Perturbation,
    /// One per volume group, in scene order: material `i` is `material[i]`.
    pub material: &'a [MaterialSection],
    /// The default interface (index 0).
    pub joints: &'a JointSection,
    /// Interfaces overriding the default (index `i + 1`).
    pub interface: &'a [JointSection],
    pub boundary: &'a [Boundary],
    /// Gravitational acceleration (m/s^2).
    pub gravity: [f64; 3],
    /// Pore water, if any.
    pub water: Option<&'a WaterSection>,
    /// `[failure] smoothing` (the plastic prisms' and tetrahedra's `alpha`).
    pub smoothing: f64,
}

#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Perturbation {
    /// Maximum offset per axis as a fraction of the local edge length (0 = off).
    #[serde(default)]
    pub ratio: f64,
    #[serde(default)]
    pub seed: u64,
    /// Plane surface groups whose nodes may move only within the group's
    /// plane. A group that is not one plane (within [`PLANE_TOLERANCE`] of
    /// its size) is an error: use `keep_on`.
    #[serde(default)]
    pub keep_flat: Vec<String>,
    /// Surface groups whose nodes stay on the surface: each node moves only
    /// within the planes of its facets, so on a curved group (a slip circle)
    /// a node where facets meet at an angle does not move.
    #[serde(default)]
    pub keep_on: Vec<String>,
}

/// How far (relative to the group's extent) a `keep_flat` group's nodes may
/// lie from its plane.
pub const PLANE_TOLERANCE: f64 = 1e-9;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSection {
    pub group: String,
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    pub density: f64,
    /// Makes the blocks of this group a Mohr-Coulomb rock mass that yields
    /// in the failure phase; absent: linear elastic in every phase.
    pub strength: Option<RockStrengthSection>,
}

/// Strength of a Mohr-Coulomb rock mass (`[[material]] strength`).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RockStrengthSection {
    /// Cohesion `c` (Pa).
    pub cohesion: f64,
    /// Friction angle `phi` (degrees, in [0, 90)).
    pub friction_angle: f64,
    /// Tension cut-off `T` (Pa, >= 0). Default: none beyond the
    /// Mohr-Coulomb apex `c / tan(phi)` (a larger value is capped there).
    pub tensile: Option<f64>,
    /// Dilation angle `psi` (degrees, in [0, phi]). Default 0: plastic
    /// shear flow without volume change, FLAC's default.
    #[serde(default)]
    pub dilation_angle: f64,
}

impl From<RockStrengthSection> for RockStrength {
    fn from(s: RockStrengthSection) -> Self {
        Self {
            cohesion: s.cohesion,
            tan_phi: s.friction_angle.to_radians().tan(),
            tensile: s.tensile.unwrap_or(f64::INFINITY),
            tan_psi: s.dilation_angle.to_radians().tan(),
        }
    }
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

/// A structural plane's table, one shape for `[joints]` (the default: every
/// element interface not listed in `[[interface]]`) and each `[[interface]]`
/// (a surface physical group lying between elements, whose absent moduli
/// default to `[joints]`'). The model reads it as a [`JointProps`] through
/// [`JointSection::props`].
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointSection {
    /// `[[interface]]` only (required there, refused in `[joints]`): the
    /// surface physical group.
    #[serde(default)]
    pub group: String,
    #[serde(default)]
    pub mode: JointMode,
    /// `E_j` (Pa).
    pub normal_modulus: Option<f64>,
    /// `G_j` (Pa).
    pub shear_modulus: Option<f64>,
    /// Equivalent thickness `L` (m).
    pub thickness: Option<f64>,
    /// Makes the plane breakable (eq. 17-18) in the failure phase.
    pub strength: Option<StrengthSection>,
}

impl JointSection {
    /// `(E_j, G_j, L)`, each falling back to `default`'s (`[joints]`).
    pub fn moduli(&self, default: &JointSection) -> [Option<f64>; 3] {
        [
            self.normal_modulus.or(default.normal_modulus),
            self.shear_modulus.or(default.shear_modulus),
            self.thickness.or(default.thickness),
        ]
    }

    /// The plane's properties, moduli falling back to `default`'s (NaN where
    /// neither gives one: a merged interface, which has no springs).
    pub fn props(&self, default: &JointSection) -> JointProps {
        let [e, g, l] = self.moduli(default).map(|v| v.unwrap_or(f64::NAN));
        JointProps { normal_modulus: e, shear_modulus: g, thickness: l, strength: self.strength.map(|s| s.strength()) }
    }
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

/// Scene section `[water]`: a phreatic surface in the section and
/// water-filled cracks ([`crate::physics::water`] gives the pressure). The
/// blocks are impermeable and the water acts in the joints (UDEC's model):
/// its pressure pushes on both faces of every spring interface below it and
/// on the model's outer faces below it, so that the springs carry the
/// effective stress.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WaterSection {
    /// The phreatic surface `[[x, z], ...]` (m), x increasing, spanning the
    /// model's x-range. Empty: no surface (cracks only).
    #[serde(default)]
    pub surface: Vec<[f64; 2]>,
    /// Raises the whole surface by this much (m, default 0): the water level
    /// as one number, for an ensemble's `[[ensemble.random]]` and for
    /// `cdem srm`'s bisection on the level.
    #[serde(default)]
    pub rise: f64,
    /// `gamma_w` (N/m^3). Default 9810.
    #[serde(default = "default_water_unit_weight")]
    pub unit_weight: f64,
    /// `"vertical"` (default) or `"cos2"`: the head from the vertical
    /// distance to the surface, or with Slide's cos^2 correction.
    #[serde(default)]
    pub hu: crate::physics::water::Hu,
    /// Water-filled open joints.
    #[serde(default)]
    pub crack: Vec<CrackSection>,
}

fn default_water_unit_weight() -> f64 {
    crate::physics::water::DEFAULT_UNIT_WEIGHT
}

/// `[[water.crack]]`: an `[[interface]]` group filled with water to `level` (m).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CrackSection {
    pub group: String,
    pub level: f64,
}

impl WaterSection {
    /// The phreatic surface (raised by `rise`), if one is drawn; errors name their key.
    pub fn phreatic(&self) -> Result<Option<crate::physics::water::Phreatic>, crate::error::SceneError> {
        use crate::error::SceneError;
        use crate::physics::water::Phreatic;
        if !self.rise.is_finite() {
            return Err(SceneError::invalid("water.rise", "must be finite"));
        }
        if self.surface.is_empty() {
            if self.crack.is_empty() {
                return Err(SceneError::invalid("water", "gives neither a surface nor a [[water.crack]]"));
            }
            // The cracks' gamma_w (Phreatic::new checks a surface's).
            if !(self.unit_weight.is_finite() && self.unit_weight > 0.0) {
                return Err(SceneError::invalid(
                    "water.unit_weight",
                    format!("must be a finite positive number, got {}", self.unit_weight),
                ));
            }
            return Ok(None);
        }
        let points = self.surface.iter().map(|p| [p[0], p[1] + self.rise]).collect();
        Phreatic::new("water", points, self.unit_weight, self.hu).map(Some)
    }

    /// Checks what can be checked without the mesh.
    pub fn validate(&self) -> Result<(), crate::error::SceneError> {
        self.phreatic()?;
        for (i, c) in self.crack.iter().enumerate() {
            if c.group.is_empty() {
                return Err(crate::error::SceneError::invalid(format!("water.crack[{i}].group"), "missing"));
            }
            if !c.level.is_finite() {
                return Err(crate::error::SceneError::invalid(format!("water.crack[{i}].level"), "must be finite"));
            }
        }
        Ok(())
    }
}
