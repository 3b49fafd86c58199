//! Pore water of a LEM section: the pore pressure `u` at a slice base (a
//! phreatic surface, or the pore-pressure ratio `r_u`) and a water-filled
//! tension crack (equations in the module docs of [`crate::lem`]).

use serde::Serialize;

use crate::error::SceneError;
use crate::physics::water::{Hu, Phreatic, DEFAULT_UNIT_WEIGHT};

/// Where the pore pressure at a slice base comes from.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Pore {
    /// `u = 0`.
    #[default]
    Dry,
    /// `u = gamma_w h H_u` at the middle of the base, `h` the vertical
    /// distance up to the surface ([`Phreatic::pressure`]).
    Surface(Phreatic),
    /// Slide's pore-pressure ratio: `u = r_u sigma_v`, `sigma_v = W / b` the
    /// slice's mean vertical overburden stress (`sum gamma_k h_k`).
    Ru(f64),
}

/// A tension crack as Slide draws one: a crack line `depth` below the ground
/// over `zone` (all of the ground if `None`); a slip circle that crosses the
/// crack line is cut there on its crest side and closed by a vertical crack
/// up to the ground, filled with water to `fill` of its depth.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TensionCrack {
    /// Depth of the crack line below the ground (m).
    pub depth: f64,
    /// Filled fraction, 0 (dry) to 1 (full): water depth `fill * depth`.
    pub fill: f64,
    /// `[x0, x1]` over which the crack line runs (user frame).
    pub zone: Option<[f64; 2]>,
}

/// The water of a section; [`Water::default`] is dry.
#[derive(Debug, Clone, PartialEq)]
pub struct Water {
    pub pore: Pore,
    pub crack: Option<TensionCrack>,
    /// `gamma_w` of the crack water (N/m^3).
    pub unit_weight: f64,
}

/// What a result says about the water model that ran.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WaterModel {
    /// "dry", "surface" or "ru".
    pub pore: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hu: Option<Hu>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ru: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tension_crack: Option<TensionCrack>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unit_weight: Option<f64>,
}

impl WaterModel {
    /// One line for the table.
    pub fn describe(&self) -> String {
        let mut s = match (self.pore, self.hu, self.ru) {
            ("surface", Some(Hu::Cos2), _) => "phreatic surface, H_u = cos^2(beta)".to_string(),
            ("surface", _, _) => "phreatic surface, H_u = 1 (vertical distance)".to_string(),
            ("ru", _, Some(r)) => format!("r_u = {r}"),
            _ => "dry".to_string(),
        };
        if let Some(c) = &self.tension_crack {
            s += &format!(", tension crack {} m deep, {:.0} % filled", c.depth, 100.0 * c.fill);
        }
        s
    }
}

impl Default for Water {
    fn default() -> Self {
        Water { pore: Pore::Dry, crack: None, unit_weight: DEFAULT_UNIT_WEIGHT }
    }
}

impl Water {
    pub fn is_dry(&self) -> bool {
        self.pore == Pore::Dry && self.crack.is_none()
    }

    /// The model as the results report it.
    pub fn model(&self) -> WaterModel {
        let (pore, hu, ru) = match &self.pore {
            Pore::Dry => ("dry", None, None),
            Pore::Surface(p) => ("surface", Some(p.hu), None),
            Pore::Ru(r) => ("ru", None, Some(*r)),
        };
        let wet = !matches!(self.pore, Pore::Dry | Pore::Ru(_)) || self.crack.is_some_and(|c| c.fill > 0.0);
        WaterModel { pore, hu, ru, tension_crack: self.crack, unit_weight: wet.then_some(self.unit_weight) }
    }

    /// Checks the water against the section's ground (user frame): the
    /// surface spans the ground and does not rise above it (ponded water
    /// is not modelled), the crack's zone lies on the ground.
    pub(crate) fn check(&self, ground: &[[f64; 2]]) -> Result<(), SceneError> {
        let (gx0, gx1) = (ground[0][0], ground[ground.len() - 1][0]);
        if let Pore::Surface(p) = &self.pore {
            let [x0, x1] = p.x_range();
            if x0 > gx0 || x1 < gx1 {
                return Err(SceneError::invalid(
                    "water.surface",
                    format!("must span the section's ground, x in [{gx0}, {gx1}]; it spans [{x0}, {x1}]"),
                ));
            }
            let tol = 1e-9 * (1.0 + (gx1 - gx0).abs());
            let xs =
                ground.iter().map(|g| g[0]).chain(p.points.iter().map(|q| q[0]).filter(|x| *x >= gx0 && *x <= gx1));
            for x in xs {
                let (zw, zg) = (p.level(x), ground_z(ground, x));
                if zw > zg + tol {
                    return Err(SceneError::invalid(
                        "water.surface",
                        format!("rises above the ground at x = {x} (z_w = {zw}, ground {zg}): ponded water is not modelled by the LEM"),
                    ));
                }
            }
        }
        if let Pore::Ru(r) = self.pore {
            if !(r.is_finite() && (0.0..1.0).contains(&r)) {
                return Err(SceneError::invalid("water.ru", format!("must be in [0, 1), got {r}")));
            }
        }
        if let Some(c) = &self.crack {
            if !(c.depth.is_finite() && c.depth > 0.0) {
                return Err(SceneError::invalid(
                    "water.crack_depth",
                    format!("must be finite and > 0 (m), got {}", c.depth),
                ));
            }
            if !(c.fill.is_finite() && (0.0..=1.0).contains(&c.fill)) {
                return Err(SceneError::invalid(
                    "water.crack_fill",
                    format!("the filled fraction must be in [0, 1] (0 dry, 1 full), got {}", c.fill),
                ));
            }
            if let Some([a, b]) = c.zone {
                if !(a.is_finite() && b.is_finite() && a < b && b > gx0 && a < gx1) {
                    return Err(SceneError::invalid(
                        "water.crack_zone",
                        format!("must be [x0, x1], x0 < x1, overlapping the ground x in [{gx0}, {gx1}]"),
                    ));
                }
            }
        }
        if !(self.unit_weight.is_finite() && self.unit_weight > 0.0) {
            return Err(SceneError::invalid("water.unit_weight", "must be finite and > 0 (N/m^3)"));
        }
        Ok(())
    }

    /// The same water in the mirrored frame (x -> -x).
    pub(crate) fn mirrored(&self) -> Water {
        let pore = match &self.pore {
            Pore::Surface(p) => {
                let points = p.points.iter().rev().map(|q| [-q[0], q[1]]).collect();
                Pore::Surface(Phreatic { points, ..p.clone() })
            }
            other => other.clone(),
        };
        let crack = self.crack.map(|c| TensionCrack { zone: c.zone.map(|[a, b]| [-b, -a]), ..c });
        Water { pore, crack, unit_weight: self.unit_weight }
    }
}

/// The ground's height at `x` inside its x-range (linear between points).
fn ground_z(g: &[[f64; 2]], x: f64) -> f64 {
    let k = g.windows(2).position(|w| x <= w[1][0]).unwrap_or(g.len() - 2);
    let (a, b) = (g[k], g[k + 1]);
    a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0])
}
