//! Scene section `[runout]` (docs/scene.md): the blocks in real time after
//! the slope has failed ([`crate::solver::runout`], docs/method.md 2.9d).

use serde::Deserialize;

use crate::error::SceneError;
use crate::model::Model;
use crate::solver::runout::{ContactDefaults, RunoutDamping, RunoutParams};

/// When the runout starts.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RunoutStart {
    /// After phase 2 ends in global sliding; a scene that does not slide
    /// runs no runout and says so (`cdem run` exits 3).
    #[default]
    Sliding,
    /// From the end of the last phase whatever it ended in (a block released
    /// on a slope, a dropped block).
    Rest,
}

/// Damping of the runout: a physical choice.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RunoutDampingKind {
    #[default]
    None,
    Local,
    Rayleigh,
}

/// `[runout.contact]`: the contacts between blocks that never shared a face.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RunoutContactSection {
    /// Normal penalty stiffness per unit area (Pa/m). Default: `[joints]`'
    /// `normal_modulus / thickness` (merged: the first `[[interface]]` with springs).
    pub normal_stiffness: Option<f64>,
    /// Tangential stiffness per unit area (Pa/m). Default: `[joints]`'
    /// `shear_modulus / thickness`.
    pub shear_stiffness: Option<f64>,
    /// Friction angle (deg). Default: `[joints]`' `strength.friction_angle`,
    /// else the lowest of the `[[interface]]`s' (the weakest joint's).
    /// No cohesion and no tension, ever (a new contact).
    pub friction_angle: Option<f64>,
}

/// Scene section `[runout]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunoutSection {
    /// Time to run at most (s). Required.
    pub duration: f64,
    #[serde(default)]
    pub start: RunoutStart,
    #[serde(default)]
    pub damping: RunoutDampingKind,
    /// Local damping's `alpha` (default 0.8).
    #[serde(default = "default_alpha")]
    pub local_damping: f64,
    /// Rayleigh: the ratio of critical (default 0.05) at `rayleigh_frequency` (Hz, default 1).
    #[serde(default = "default_ratio")]
    pub rayleigh_ratio: f64,
    #[serde(default = "default_frequency")]
    pub rayleigh_frequency: f64,
    /// Fraction of the stable time step (default 0.5).
    #[serde(default = "default_safety")]
    pub safety: f64,
    /// Contact detection reach (m). Default 1 % of the smallest element's size
    /// (the cube root of its volume).
    pub tolerance: Option<f64>,
    /// Deeper than this inside another block is a missed contact (m).
    /// Default 20 % of the smallest element's size.
    pub max_penetration: Option<f64>,
    /// At rest when, over a window of `rest_time` (s, default 0.5; 0: run
    /// the whole duration), no node has moved more than `rest_velocity *
    /// rest_time` (m/s, default 0.01).
    #[serde(default = "default_rest_velocity")]
    pub rest_velocity: f64,
    #[serde(default = "default_rest_time")]
    pub rest_time: f64,
    /// A `runout.csv` row every this many steps (default 100).
    #[serde(default = "default_row_every")]
    pub row_every: usize,
    /// A `runout.pvd` frame every this many seconds (default: 20 frames over the duration).
    pub frame_every: Option<f64>,
    /// Limit every spring's and contact's stiffness to this many times the
    /// softer neighbouring element's `(K + 4G/3) / dz_min` (within the Itasca
    /// codes' rule for joints, at most 10 times the stiffer's). Default: none,
    /// the stiffnesses as given.
    pub stiffness_limit: Option<f64>,
    #[serde(default)]
    pub contact: RunoutContactSection,
}

fn default_alpha() -> f64 {
    0.8
}
fn default_ratio() -> f64 {
    0.05
}
fn default_frequency() -> f64 {
    1.0
}
fn default_safety() -> f64 {
    0.5
}
fn default_rest_velocity() -> f64 {
    0.01
}
fn default_rest_time() -> f64 {
    0.5
}
fn default_row_every() -> usize {
    100
}

fn positive(key: &str, v: f64) -> Result<(), SceneError> {
    match v.is_finite() && v > 0.0 {
        true => Ok(()),
        false => Err(SceneError::invalid(key, format!("must be a finite number above 0, not {v}"))),
    }
}

impl RunoutSection {
    /// The checks each key names.
    pub fn validate(&self) -> Result<(), SceneError> {
        positive("runout.duration", self.duration)?;
        if !(self.safety > 0.0 && self.safety <= 1.0) {
            return Err(SceneError::invalid("runout.safety", "must be in (0, 1]"));
        }
        if !(0.0..1.0).contains(&self.local_damping) {
            return Err(SceneError::invalid("runout.local_damping", "must be in [0, 1)"));
        }
        if !(self.rayleigh_ratio >= 0.0 && self.rayleigh_ratio.is_finite()) {
            return Err(SceneError::invalid("runout.rayleigh_ratio", "must be finite and not negative"));
        }
        positive("runout.rayleigh_frequency", self.rayleigh_frequency)?;
        for (key, v) in [("runout.tolerance", self.tolerance), ("runout.max_penetration", self.max_penetration)] {
            if let Some(v) = v {
                positive(key, v)?;
            }
        }
        positive("runout.rest_velocity", self.rest_velocity)?;
        if !(self.rest_time >= 0.0 && self.rest_time.is_finite()) {
            return Err(SceneError::invalid("runout.rest_time", "must be finite and not negative"));
        }
        if self.row_every == 0 {
            return Err(SceneError::invalid("runout.row_every", "must be at least 1"));
        }
        if let Some(f) = self.frame_every {
            positive("runout.frame_every", f)?;
        }
        if let Some(f) = self.stiffness_limit {
            positive("runout.stiffness_limit", f)?;
        }
        let c = &self.contact;
        for (key, v) in [
            ("runout.contact.normal_stiffness", c.normal_stiffness),
            ("runout.contact.shear_stiffness", c.shear_stiffness),
        ] {
            if let Some(v) = v {
                positive(key, v)?;
            }
        }
        if let Some(phi) = c.friction_angle {
            if !(0.0..90.0).contains(&phi) {
                return Err(SceneError::invalid("runout.contact.friction_angle", "must be in [0, 90) degrees"));
            }
        }
        Ok(())
    }

    /// The engine's settings for `model`: the defaults from its smallest
    /// element and its default joints (`[joints]`, interface 0).
    pub fn params(&self, model: &Model) -> Result<RunoutParams, SceneError> {
        let h = model.elements.volume.iter().fold(f64::INFINITY, |a, &v| a.min(v.cbrt()));
        // `[joints]` first (interface 0), then the `[[interface]]`s in scene order.
        let springs = || model.interfaces.iter().map(|i| i.props).filter(|p| p.normal_modulus.is_finite());
        let c = &self.contact;
        let normal = c
            .normal_stiffness
            .or_else(|| springs().next().map(|p| p.normal_modulus / p.thickness))
            .ok_or_else(|| {
                SceneError::invalid(
                    "runout.contact.normal_stiffness",
                    "is required: no interface of the scene has springs",
                )
            })?;
        let shear =
            c.shear_stiffness.or_else(|| springs().next().map(|p| p.shear_modulus / p.thickness)).unwrap_or(normal);
        // The weakest joint's friction: [joints]' if it has a strength, else the
        // lowest of the interfaces'.
        let joints = model.interfaces.first().and_then(|i| i.props.strength);
        let weakest =
            model.interfaces.iter().filter_map(|i| i.props.strength).map(|s| s.residual_tan_phi()).reduce(f64::min);
        let friction = c
            .friction_angle
            .or_else(|| joints.map(|s| s.residual_tan_phi()).or(weakest).map(|t| t.atan().to_degrees()))
            .ok_or_else(|| {
                SceneError::invalid(
                    "runout.contact.friction_angle",
                    "is required: no interface of the scene has a strength to take it from",
                )
            })?;
        let damping = match self.damping {
            RunoutDampingKind::None => RunoutDamping::None,
            RunoutDampingKind::Local => RunoutDamping::Local { alpha: self.local_damping },
            RunoutDampingKind::Rayleigh => RunoutDamping::Rayleigh {
                ratio: self.rayleigh_ratio,
                omega: 2.0 * std::f64::consts::PI * self.rayleigh_frequency,
            },
        };
        Ok(RunoutParams {
            duration: self.duration,
            damping,
            safety: self.safety,
            tolerance: self.tolerance.unwrap_or(0.01 * h),
            max_penetration: self.max_penetration.unwrap_or(0.2 * h),
            rest_velocity: self.rest_velocity,
            rest_time: self.rest_time,
            contact: ContactDefaults { normal_stiffness: normal, shear_stiffness: shear, friction_deg: friction },
            stiffness_limit: self.stiffness_limit,
        })
    }
}
