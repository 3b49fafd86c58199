//! Pore water: the pressure `u` (Pa, compression positive) at a point, from a
//! phreatic surface drawn in the section and from water-filled cracks.
//!
//! The phreatic surface is a polyline `z_w(x)` in the section (x horizontal,
//! z up), extruded along y. Below it the pressure is hydrostatic in the
//! vertical distance to it, as Slide's piezometric line gives it:
//!
//! `u = gamma_w h H_u`, `h = max(z_w(x) - z, 0)`,
//!
//! with `H_u = 1` (`hu = "vertical"`) or `H_u = cos^2(beta)` (`hu = "cos2"`),
//! `beta` the inclination of the surface's segment at `x`: the pressure under
//! a sloping surface with flow lines parallel to it (the equipotentials are
//! normal to the surface, so the head at depth `h` is `h cos^2 beta`).
//! Above the surface (and outside it: the surface spans the model) `u = 0`.
//! A 3D surface `z_w(x, y)` would replace [`Phreatic::level`] only.
//!
//! A water-filled crack (a tension crack above the surface, filled to a
//! `level`) has `u = gamma_w max(level - z, 0)` on its own faces, the larger
//! of that and the surface's pressure.

use crate::error::SceneError;

/// Unit weight of water used when a scene gives none (N/m^3).
pub const DEFAULT_UNIT_WEIGHT: f64 = 9810.0;

/// How the vertical distance to the phreatic surface becomes a head.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Hu {
    /// `H_u = 1`: the vertical distance (Slide's default).
    #[default]
    Vertical,
    /// `H_u = cos^2(beta)` of the surface's inclination at `x`.
    Cos2,
}

/// A phreatic surface `z_w(x)`: strictly increasing `x`, at least two points.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Phreatic {
    pub points: Vec<[f64; 2]>,
    /// `gamma_w` (N/m^3).
    pub unit_weight: f64,
    pub hu: Hu,
}

impl Phreatic {
    /// Checks the polyline and the unit weight; errors name `key`.
    pub fn new(key: &str, points: Vec<[f64; 2]>, unit_weight: f64, hu: Hu) -> Result<Self, SceneError> {
        if points.len() < 2 {
            return Err(SceneError::invalid(format!("{key}.surface"), "needs at least two points [x, z]"));
        }
        for (i, p) in points.iter().enumerate() {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err(SceneError::invalid(format!("{key}.surface[{i}]"), "must be finite"));
            }
            if i > 0 && !(p[0] > points[i - 1][0]) {
                return Err(SceneError::invalid(
                    format!("{key}.surface[{i}]"),
                    format!("x must increase along the surface: {} after {}", p[0], points[i - 1][0]),
                ));
            }
        }
        if !(unit_weight.is_finite() && unit_weight > 0.0) {
            return Err(SceneError::invalid(
                format!("{key}.unit_weight"),
                format!("must be a finite positive number, got {unit_weight}"),
            ));
        }
        Ok(Self { points, unit_weight, hu })
    }

    /// The x-range the surface is drawn over.
    pub fn x_range(&self) -> [f64; 2] {
        [self.points[0][0], self.points[self.points.len() - 1][0]]
    }

    /// The segment under `x` (clamped to the ends).
    fn segment(&self, x: f64) -> usize {
        let p = &self.points;
        p.windows(2).position(|w| x <= w[1][0]).unwrap_or(p.len() - 2)
    }

    /// `z_w(x)`, linear between points and constant beyond the ends.
    pub fn level(&self, x: f64) -> f64 {
        let p = &self.points;
        if x <= p[0][0] {
            return p[0][1];
        }
        if x >= p[p.len() - 1][0] {
            return p[p.len() - 1][1];
        }
        let i = self.segment(x);
        let (a, b) = (p[i], p[i + 1]);
        a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0])
    }

    /// `H_u` at `x`.
    pub fn hu_factor(&self, x: f64) -> f64 {
        match self.hu {
            Hu::Vertical => 1.0,
            Hu::Cos2 => {
                let i = self.segment(x);
                let (a, b) = (self.points[i], self.points[i + 1]);
                let (dx, dz) = (b[0] - a[0], b[1] - a[1]);
                dx * dx / (dx * dx + dz * dz)
            }
        }
    }

    /// The pore pressure `u = gamma_w max(z_w(x) - z, 0) H_u(x)` (Pa).
    pub fn pressure(&self, x: f64, z: f64) -> f64 {
        let h = self.level(x) - z;
        if h > 0.0 {
            self.unit_weight * h * self.hu_factor(x)
        } else {
            0.0
        }
    }
}

/// A crack's own pressure: `gamma_w max(level - z, 0)` (Pa).
pub fn crack_pressure(unit_weight: f64, level: f64, z: f64) -> f64 {
    unit_weight * (level - z).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn surface(hu: Hu) -> Phreatic {
        Phreatic::new("water", vec![[0.0, 10.0], [10.0, 10.0], [20.0, 0.0]], 10e3, hu).unwrap()
    }

    #[test]
    fn hydrostatic_below_the_surface_and_dry_above() {
        let w = surface(Hu::Vertical);
        assert_eq!(w.pressure(5.0, 4.0), 60e3);
        assert_eq!(w.pressure(15.0, 1.0), 40e3);
        assert_eq!(w.pressure(15.0, 6.0), 0.0);
        assert_eq!(w.pressure(-3.0, 0.0), 100e3); // constant beyond the ends
    }

    #[test]
    fn cos2_is_the_head_under_a_sloping_surface() {
        let w = surface(Hu::Cos2);
        // beta = 45 degrees on the second segment: H_u = 1/2.
        assert!((w.pressure(15.0, 1.0) - 20e3).abs() < 1e-9);
        assert_eq!(w.pressure(5.0, 4.0), 60e3);
    }

    #[test]
    fn bad_surfaces_are_named() {
        let e = Phreatic::new("water", vec![[0.0, 1.0], [0.0, 2.0]], 9810.0, Hu::Vertical).unwrap_err();
        assert!(e.to_string().contains("water.surface[1]"), "{e}");
        let e = Phreatic::new("water", vec![[0.0, 1.0]], 9810.0, Hu::Vertical).unwrap_err();
        assert!(e.to_string().contains("water.surface"), "{e}");
        let e = Phreatic::new("water", vec![[0.0, 1.0], [1.0, 1.0]], -1.0, Hu::Vertical).unwrap_err();
        assert!(e.to_string().contains("water.unit_weight"), "{e}");
    }
}
