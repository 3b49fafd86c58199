//! Barton-Bandis joints (Barton 1973; Barton & Choubey 1977; Barton &
//! Bandis 1990): the peak shear strength of a rough joint falls with normal
//! stress,
//!
//! `tau = sigma_n tan(phi_r + JRC log10(JCS / sigma_n))`,
//!
//! `sigma_n` the effective normal stress (Pa, compression positive), `phi_r`
//! the residual friction angle, `JRC` the joint roughness coefficient and
//! `JCS` the joint wall compressive strength. Conventions, as RS2, Slide and
//! RocPlane state them:
//! - `sigma_n -> 0`: the total friction angle is capped at
//!   `max_friction_angle` (70 degrees by default);
//! - `sigma_n >= JCS`: the roughness term is taken as zero (`tau = sigma_n
//!   tan(phi_r)`), not negative;
//! - `sigma_n <= 0`: no shear strength; a tensile strength `T` (default 0)
//!   holds an intact joint in tension up to `F_n = T A` (an opening of a
//!   joint with `T = 0` breaks it: `F_n > 0`);
//! - post-peak: brittle (default) drops to the residual `sigma_n tan(phi_r)`
//!   at the first slip or opening, ductile keeps the peak. No dilation.
//!
//! Strength reduction by `F` divides the whole envelope, `tau(sigma_n) / F`,
//! and `T / F`: the factor of safety's own definition (available over
//! mobilised shear strength at each normal stress), which for Mohr-Coulomb
//! is the usual `c / F`, `tan(phi) / F`; RS2 reduces both the peak and the
//! residual strength by the SRF (Rocscience RS2 knowledge base, "SSR").
//!
//! Cost: the logarithm and the tangent are taken only when a spring's shear
//! force lies between its residual and its peak (a spring below the
//! residual strength holds whatever its roughness).

use serde::Deserialize;

use super::{JointLaw, Softening};
use crate::physics::spring::{spring_force, Spring, SpringStatus};

/// The law (a name; its parameters are [`BartonBandisStrength`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct BartonBandis;

/// The parameters in SI units, with the strength-reduction factor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BartonBandisStrength {
    /// Joint roughness coefficient (degrees per decade of `JCS / sigma_n`).
    pub jrc: f64,
    /// Joint wall compressive strength (Pa).
    pub jcs: f64,
    /// Residual friction angle (rad).
    pub phi_r: f64,
    /// Cap on the total friction angle (rad).
    pub phi_max: f64,
    /// `tan(phi_r)`, `tan(phi_max)`.
    pub tan_phi_r: f64,
    pub tan_phi_max: f64,
    /// Tensile strength `T` (Pa), already divided by `factor`.
    pub tensile: f64,
    /// Strength-reduction factor `F` (1 unreduced): the envelope is divided by it.
    pub factor: f64,
    pub softening: Softening,
}

impl BartonBandisStrength {
    /// The peak shear strength (Pa) at normal stress `sigma_n` (Pa,
    /// compression positive), reduced by the factor.
    #[inline]
    pub fn peak(&self, sigma_n: f64) -> f64 {
        if sigma_n <= 0.0 {
            return 0.0;
        }
        let roughness = (self.jrc * (self.jcs / sigma_n).log10()).max(0.0).to_radians();
        sigma_n * (self.phi_r + roughness).min(self.phi_max).tan() / self.factor
    }

    /// A lower bound of `peak(sigma_n) / sigma_n` without a logarithm or a
    /// tangent (the cheap test that most springs above their residual pass):
    /// `tan(phi_r + R) >= tan(phi_r) + R` for angles below 90 degrees, the
    /// roughness `R = JRC log10(JCS / sigma_n)` (rad) bounded below through
    /// `ln(x) >= floor(log2(x)) ln 2`, the exponent of `x` read from its bits;
    /// capped at `tan(phi_max)`.
    #[inline]
    fn lower_bound(&self, sigma_n: f64) -> f64 {
        let x = self.jcs / sigma_n;
        let octaves = if x >= 1.0 && x.is_finite() { ((x.to_bits() >> 52) & 0x7ff) as f64 - 1023.0 } else { 0.0 };
        let roughness = self.jrc * (octaves * std::f64::consts::LN_2 / std::f64::consts::LN_10).to_radians();
        (self.tan_phi_r + roughness).min(self.tan_phi_max) / self.factor
    }
}

fn seventy() -> f64 {
    70.0
}

/// The scene's `strength = { law = "barton_bandis", jrc, jcs,
/// residual_friction_angle, max_friction_angle, tensile, softening }`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BartonBandisSection {
    /// `JRC`, in [0, 20] (Barton & Choubey's profiles).
    pub jrc: f64,
    /// `JCS` (Pa), > 0.
    pub jcs: f64,
    /// `phi_r` (degrees), in [0, 90).
    pub residual_friction_angle: f64,
    /// Cap on `phi_r + JRC log10(JCS / sigma_n)` (degrees), default 70.
    #[serde(default = "seventy")]
    pub max_friction_angle: f64,
    /// Tensile strength (Pa), default 0.
    #[serde(default)]
    pub tensile: f64,
    /// `"brittle"` (default: the residual after the peak) or `"ductile"`.
    #[serde(default)]
    pub softening: Softening,
}

impl BartonBandisSection {
    /// The first bad field and why.
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        let ok = |v: f64, lo: f64, hi: f64| v.is_finite() && v >= lo && v <= hi;
        if !ok(self.jrc, 0.0, 20.0) {
            return Err(("jrc", format!("must be in [0, 20], got {}", self.jrc)));
        }
        if !(self.jcs.is_finite() && self.jcs > 0.0) {
            return Err(("jcs", format!("must be finite and > 0 (Pa), got {}", self.jcs)));
        }
        let phi_r = self.residual_friction_angle;
        if !(phi_r.is_finite() && (0.0..90.0).contains(&phi_r)) {
            return Err(("residual_friction_angle", format!("must be in [0, 90) degrees, got {phi_r}")));
        }
        let cap = self.max_friction_angle;
        if !(cap.is_finite() && cap > phi_r && cap < 90.0) {
            return Err((
                "max_friction_angle",
                format!("must be above residual_friction_angle ({phi_r}) and below 90 degrees, got {cap}"),
            ));
        }
        if !(self.tensile.is_finite() && self.tensile >= 0.0) {
            return Err(("tensile", format!("must be finite and >= 0, got {}", self.tensile)));
        }
        Ok(())
    }

    pub fn strength(&self) -> BartonBandisStrength {
        let phi_r = self.residual_friction_angle.to_radians();
        BartonBandisStrength {
            jrc: self.jrc,
            jcs: self.jcs,
            phi_r,
            phi_max: self.max_friction_angle.to_radians(),
            tan_phi_r: phi_r.tan(),
            tan_phi_max: self.max_friction_angle.to_radians().tan(),
            tensile: self.tensile,
            factor: 1.0,
            softening: self.softening,
        }
    }

    /// The number named `field` (ensemble keys).
    pub fn number_mut(&mut self, field: &str) -> Option<&mut f64> {
        match field {
            "jrc" => Some(&mut self.jrc),
            "jcs" => Some(&mut self.jcs),
            "residual_friction_angle" => Some(&mut self.residual_friction_angle),
            "max_friction_angle" => Some(&mut self.max_friction_angle),
            "tensile" => Some(&mut self.tensile),
            _ => None,
        }
    }

    /// The section as an inline TOML table's fields.
    pub fn toml_fields(&self) -> String {
        format!(
            "law = \"barton_bandis\", jrc = {:?}, jcs = {:?}, residual_friction_angle = {:?}, max_friction_angle = {:?}, tensile = {:?}, softening = \"{}\"",
            self.jrc,
            self.jcs,
            self.residual_friction_angle,
            self.max_friction_angle,
            self.tensile,
            self.softening.name()
        )
    }
}

impl JointLaw for BartonBandis {
    type Params = BartonBandisStrength;

    #[inline]
    fn force(
        p: &BartonBandisStrength,
        sp: &Spring,
        d: [f64; 3],
        slip: &mut [f64; 3],
        status: &mut SpringStatus,
    ) -> [f64; 3] {
        let (f_n, f_s) = spring_force(sp.kn, sp.ks, sp.normal, d, *slip);
        let brittle = p.softening == Softening::Brittle;
        let cap = p.tensile * sp.area;
        let open = |slip: &mut [f64; 3]| *slip = [0, 1, 2].map(|i| slip[i] + f_s[i] / sp.ks);
        let (f_n, peak) = match *status {
            SpringStatus::Intact if f_n > cap => {
                *status = SpringStatus::Tension;
                if brittle {
                    open(slip);
                    return [0.0; 3];
                }
                (cap, true)
            }
            SpringStatus::Intact => (f_n, true),
            _ if brittle && f_n > 0.0 => {
                open(slip);
                return [0.0; 3];
            }
            _ => (f_n.min(cap), !brittle),
        };
        let compression = (-f_n).max(0.0);
        let fs_abs = (f_s[0] * f_s[0] + f_s[1] * f_s[1] + f_s[2] * f_s[2]).sqrt();
        let residual = compression * p.tan_phi_r / p.factor;
        if fs_abs <= residual {
            return [0, 1, 2].map(|i| f_n * sp.normal[i] + f_s[i]);
        }
        if peak && fs_abs <= compression * p.lower_bound(compression / sp.area) {
            return [0, 1, 2].map(|i| f_n * sp.normal[i] + f_s[i]);
        }
        let limit = match peak {
            false => residual,
            // Past the cap's friction, a brittle joint slips whatever its roughness.
            true if brittle && fs_abs > compression * p.tan_phi_max / p.factor => residual,
            true => sp.area * p.peak(compression / sp.area),
        };
        if fs_abs <= limit {
            return [0, 1, 2].map(|i| f_n * sp.normal[i] + f_s[i]);
        }
        if *status == SpringStatus::Intact {
            *status = SpringStatus::Shear;
        }
        let kept_abs = if brittle { residual } else { limit };
        let kept = f_s.map(|v| v * kept_abs / fs_abs);
        *slip = [0, 1, 2].map(|i| slip[i] + (f_s[i] - kept[i]) / sp.ks);
        [0, 1, 2].map(|i| f_n * sp.normal[i] + kept[i])
    }

    fn reduced(p: &BartonBandisStrength, f: f64) -> BartonBandisStrength {
        BartonBandisStrength { tensile: p.tensile / f, factor: p.factor * f, ..*p }
    }

    #[inline]
    fn shear_strength(p: &BartonBandisStrength, sigma_n: f64) -> f64 {
        p.peak(sigma_n)
    }

    fn residual_tan_phi(p: &BartonBandisStrength) -> f64 {
        p.tan_phi_r / p.factor
    }

    fn bonds(p: &BartonBandisStrength) -> bool {
        p.tensile > 0.0
    }

    fn words(p: &BartonBandisStrength) -> Vec<f64> {
        vec![p.jrc, p.jcs, p.phi_r, p.phi_max, p.tan_phi_r, p.tan_phi_max, p.tensile, p.factor, p.softening.word()]
    }

    fn from_words(w: &[f64]) -> Option<BartonBandisStrength> {
        match *w {
            [jrc, jcs, phi_r, phi_max, tan_phi_r, tan_phi_max, tensile, factor, soft] => Some(BartonBandisStrength {
                jrc,
                jcs,
                phi_r,
                phi_max,
                tan_phi_r,
                tan_phi_max,
                tensile,
                factor,
                softening: Softening::from_word(soft)?,
            }),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn joint() -> BartonBandisStrength {
        BartonBandisSection {
            jrc: 10.0,
            jcs: 100e6,
            residual_friction_angle: 30.0,
            max_friction_angle: 70.0,
            tensile: 0.0,
            softening: Softening::Brittle,
        }
        .strength()
    }

    #[test]
    fn peak_follows_the_envelope_and_its_conventions() {
        let j = joint();
        // 1 MPa: 30 + 10 log10(100) = 50 degrees.
        assert!((j.peak(1e6) - 1e6 * 50f64.to_radians().tan()).abs() < 1e-6);
        // Low stress: capped at 70 degrees.
        assert!((j.peak(1.0) - 70f64.to_radians().tan()).abs() < 1e-12);
        // Above JCS: the residual.
        assert!((j.peak(200e6) - 200e6 * 30f64.to_radians().tan()).abs() < 1e-3);
        assert_eq!(j.peak(0.0), 0.0);
        assert_eq!(j.peak(-1.0), 0.0);
        // The cheap bound is below the envelope everywhere.
        for k in 0..400 {
            let s = 10f64.powf(-1.0 + 0.025 * k as f64) * 1e3;
            assert!(j.lower_bound(s) * s <= j.peak(s) * (1.0 + 1e-15), "{s}");
        }
        // Reduced by 2: half the envelope.
        let r = BartonBandis::reduced(&j, 2.0);
        assert!((r.peak(1e6) - 0.5 * j.peak(1e6)).abs() < 1e-6);
    }
}
