//! Scene table `[analysis]`: the stress-based safety factor (eq. 19-22) on a
//! slip circle, written by `cdem run` (on the elastic state, the end of
//! phase 1) and `cdem fem` as `analysis.json` and `analysis.csv`
//! (docs/method.md section 4.3a).
//!
//! ```toml
//! [analysis]
//! circle = { xc = 24.006, zc = 63.222, r = 43.41 }  # m; absent: the Bishop critical
//!                                # circle of the scene's [lem] (found by its search)
//! y = 0.5                        # section plane (m); default: the middle of the mesh in y
//! stations = 200                 # sample points along the arc (default 200)
//! interface = "slip"             # also from the springs of this [[interface]] (cdem run)
//! strength = { cohesion = 16e3, friction_angle = 18.0 }
//!                                # default: the interface's strength, else the
//!                                # [[lem.material]] of the cell at each station
//! min_segment = 2.0              # m: shorter K_i sign runs merge (default: arc length per cell)
//! ```

use serde::Deserialize;

use crate::error::SceneError;
use crate::geometry::Circle;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalysisSpec {
    /// The slip circle; absent: the LEM critical circle of `[lem]`.
    pub circle: Option<Circle>,
    /// The section plane (m). Default: the middle of the mesh's y extent.
    pub y: Option<f64>,
    /// Stations along the arc. Default 200.
    #[serde(default = "default_stations")]
    pub stations: usize,
    /// An `[[interface]]` on the circle: K from its springs too (`cdem run`).
    pub interface: Option<String>,
    /// The strength on the surface (see the module doc for the default).
    pub strength: Option<SurfaceStrength>,
    /// Minimum length of a K_i sign segment (m).
    pub min_segment: Option<f64>,
}

/// Mohr-Coulomb strength on the surface.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceStrength {
    /// Cohesion (Pa).
    pub cohesion: f64,
    /// Friction angle (degrees, in [0, 90)).
    pub friction_angle: f64,
}

fn default_stations() -> usize {
    200
}

impl AnalysisSpec {
    /// Checks the values; `interfaces` are the groups of the scene's
    /// `[[interface]]` tables and `has_lem` whether it has `[lem]`.
    pub fn validate(&self, interfaces: &[&str], has_lem: bool) -> Result<(), SceneError> {
        match &self.circle {
            Some(c) => {
                for (k, v) in [("xc", c.xc), ("zc", c.zc)] {
                    if !v.is_finite() {
                        return Err(SceneError::invalid(
                            format!("analysis.circle.{k}"),
                            format!("must be finite, got {v}"),
                        ));
                    }
                }
                if !(c.r.is_finite() && c.r > 0.0) {
                    return Err(SceneError::invalid(
                        "analysis.circle.r",
                        format!("must be a finite positive radius, got {}", c.r),
                    ));
                }
            }
            None if !has_lem => {
                return Err(SceneError::invalid(
                    "analysis.circle",
                    "missing: give a circle, or a [lem] table whose critical circle is taken",
                ))
            }
            None => {}
        }
        if let Some(y) = self.y {
            if !y.is_finite() {
                return Err(SceneError::invalid("analysis.y", format!("must be finite, got {y}")));
            }
        }
        if !(2..=100_000).contains(&self.stations) {
            return Err(SceneError::invalid(
                "analysis.stations",
                format!("must be in 2..=100000, got {}", self.stations),
            ));
        }
        if let Some(name) = &self.interface {
            if !interfaces.contains(&name.as_str()) {
                return Err(SceneError::invalid(
                    "analysis.interface",
                    format!("{name:?} is not an [[interface]] of the scene (interfaces: {interfaces:?})"),
                ));
            }
        }
        if let Some(st) = &self.strength {
            if !(st.cohesion.is_finite() && st.cohesion >= 0.0) {
                return Err(SceneError::invalid(
                    "analysis.strength.cohesion",
                    format!("must be finite and >= 0, got {}", st.cohesion),
                ));
            }
            if !(st.friction_angle.is_finite() && (0.0..90.0).contains(&st.friction_angle)) {
                return Err(SceneError::invalid(
                    "analysis.strength.friction_angle",
                    format!("must be in [0, 90) degrees, got {}", st.friction_angle),
                ));
            }
        }
        if let Some(m) = self.min_segment {
            if !(m.is_finite() && m >= 0.0) {
                return Err(SceneError::invalid("analysis.min_segment", format!("must be finite and >= 0, got {m}")));
            }
        }
        Ok(())
    }
}
