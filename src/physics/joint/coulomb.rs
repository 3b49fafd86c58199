//! The paper's joint law (eq. 17-18): tension cut-off and Mohr-Coulomb with
//! cohesion, brittle (the paper's) or ductile.
//!
//! - brittle: an intact spring breaks in tension (eq. 17; force zero now) or
//!   slips when Mohr-Coulomb with cohesion (eq. 18) is exceeded, and then
//!   keeps only friction `P tan(phi)`; a broken spring that is open
//!   (`F_n > 0`) carries nothing and its shear reference follows the motion
//!   (it recloses with zero shear force);
//! - ductile: failure changes the status (for the record) but not the
//!   strength. The normal force is capped at `T A` (no normal plastic
//!   displacement is kept: the cap is a limit on the force, not a memory),
//!   and the shear force at `P tan(phi) + c A` at every step,
//!   `P = max(-F_n, 0)`.
//!
//! Plastic slip is updated so that `K_s (d_s - d_s^p)` equals the returned
//! shear force. Strength reduction: `T / F`, `c / F`, `tan(phi) / F`.

use serde::Deserialize;

use super::{JointLaw, Softening};
use crate::physics::spring::{mohr_coulomb, spring_force, tension_cutoff, Spring, SpringStatus};

/// The law (a name; its parameters are [`CoulombStrength`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Coulomb;

/// Strength of a Coulomb joint (SI: Pa, Pa, dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoulombStrength {
    /// Tensile strength `T` (Pa), eq. 17.
    pub tensile: f64,
    /// Cohesion `c` (Pa), eq. 18.
    pub cohesion: f64,
    /// `tan(phi)`, eq. 18.
    pub tan_phi: f64,
    pub softening: Softening,
}

/// The scene's `strength = { tensile, cohesion, friction_angle, softening }`
/// (the default law: `law = "coulomb"` may be given or left out).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CoulombSection {
    /// Tensile strength `T` (Pa), eq. 17.
    pub tensile: f64,
    /// Cohesion `c` (Pa), eq. 18.
    pub cohesion: f64,
    /// Friction angle `phi` (degrees, in [0, 90)), eq. 18.
    pub friction_angle: f64,
    /// What failure does to the strength: `"brittle"` (default, the paper's:
    /// cohesion and tensile strength lost) or `"ductile"` (kept).
    #[serde(default)]
    pub softening: Softening,
}

impl CoulombSection {
    /// The first bad field and why.
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        for (name, v) in [("tensile", self.tensile), ("cohesion", self.cohesion)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err((name, format!("must be finite and >= 0, got {v}")));
            }
        }
        let phi = self.friction_angle;
        if !(phi.is_finite() && (0.0..90.0).contains(&phi)) {
            return Err(("friction_angle", format!("must be in [0, 90) degrees, got {phi}")));
        }
        Ok(())
    }

    pub fn strength(&self) -> CoulombStrength {
        CoulombStrength {
            tensile: self.tensile,
            cohesion: self.cohesion,
            tan_phi: self.friction_angle.to_radians().tan(),
            softening: self.softening,
        }
    }

    /// The number named `field` (ensemble keys).
    pub fn number_mut(&mut self, field: &str) -> Option<&mut f64> {
        match field {
            "tensile" => Some(&mut self.tensile),
            "cohesion" => Some(&mut self.cohesion),
            "friction_angle" => Some(&mut self.friction_angle),
            _ => None,
        }
    }

    /// The section as an inline TOML table's fields.
    pub fn toml_fields(&self) -> String {
        format!(
            "tensile = {:?}, cohesion = {:?}, friction_angle = {:?}, softening = \"{}\"",
            self.tensile,
            self.cohesion,
            self.friction_angle,
            self.softening.name()
        )
    }
}

impl JointLaw for Coulomb {
    type Params = CoulombStrength;

    #[inline]
    fn force(
        p: &CoulombStrength,
        sp: &Spring,
        d: [f64; 3],
        slip: &mut [f64; 3],
        status: &mut SpringStatus,
    ) -> [f64; 3] {
        match p.softening {
            Softening::Brittle => brittle_force(sp, d, p, slip, status),
            Softening::Ductile => ductile_force(sp, d, p, slip, status),
        }
    }

    fn reduced(p: &CoulombStrength, f: f64) -> CoulombStrength {
        CoulombStrength { tensile: p.tensile / f, cohesion: p.cohesion / f, tan_phi: p.tan_phi / f, ..*p }
    }

    /// Eq. 21's `sigma_n tan(phi) + c` (no cut-off: a point in tension
    /// resists less, as the paper writes it).
    #[inline]
    fn shear_strength(p: &CoulombStrength, sigma_n: f64) -> f64 {
        sigma_n * p.tan_phi + p.cohesion
    }

    fn residual_tan_phi(p: &CoulombStrength) -> f64 {
        p.tan_phi
    }

    fn bonds(p: &CoulombStrength) -> bool {
        p.tensile > 0.0 || p.cohesion > 0.0
    }

    fn words(p: &CoulombStrength) -> Vec<f64> {
        vec![p.tensile, p.cohesion, p.tan_phi, p.softening.word()]
    }

    fn from_words(w: &[f64]) -> Option<CoulombStrength> {
        match *w {
            [tensile, cohesion, tan_phi, soft] => {
                Some(CoulombStrength { tensile, cohesion, tan_phi, softening: Softening::from_word(soft)? })
            }
            _ => None,
        }
    }
}

/// The brittle branch of [`Coulomb`].
#[inline]
fn brittle_force(
    sp: &Spring,
    d: [f64; 3],
    strength: &CoulombStrength,
    slip: &mut [f64; 3],
    status: &mut SpringStatus,
) -> [f64; 3] {
    let (f_n, f_s) = spring_force(sp.kn, sp.ks, sp.normal, d, *slip);
    let cohesion = match *status {
        SpringStatus::Intact => {
            if tension_cutoff(f_n, strength.tensile, sp.area) {
                *status = SpringStatus::Tension;
                *slip = [0, 1, 2].map(|i| slip[i] + f_s[i] / sp.ks);
                return [0.0; 3];
            }
            strength.cohesion
        }
        SpringStatus::Tension | SpringStatus::Shear => {
            if f_n > 0.0 {
                *slip = [0, 1, 2].map(|i| slip[i] + f_s[i] / sp.ks);
                return [0.0; 3];
            }
            0.0
        }
    };
    let fs_abs = (f_s[0] * f_s[0] + f_s[1] * f_s[1] + f_s[2] * f_s[2]).sqrt();
    let f_s = match mohr_coulomb(f_n, fs_abs, strength.tan_phi, cohesion, sp.area) {
        None => f_s,
        Some(limit) => {
            *status = SpringStatus::Shear;
            let scale = limit / fs_abs;
            let kept = f_s.map(|v| v * scale);
            *slip = [0, 1, 2].map(|i| slip[i] + (f_s[i] - kept[i]) / sp.ks);
            kept
        }
    };
    [0, 1, 2].map(|i| f_n * sp.normal[i] + f_s[i])
}

/// The ductile branch of [`Coulomb`].
#[inline]
fn ductile_force(
    sp: &Spring,
    d: [f64; 3],
    strength: &CoulombStrength,
    slip: &mut [f64; 3],
    status: &mut SpringStatus,
) -> [f64; 3] {
    let (f_n, f_s) = spring_force(sp.kn, sp.ks, sp.normal, d, *slip);
    let cap = strength.tensile * sp.area;
    let f_n = if f_n > cap {
        if *status == SpringStatus::Intact {
            *status = SpringStatus::Tension;
        }
        cap
    } else {
        f_n
    };
    let fs_abs = (f_s[0] * f_s[0] + f_s[1] * f_s[1] + f_s[2] * f_s[2]).sqrt();
    let f_s = match mohr_coulomb(f_n, fs_abs, strength.tan_phi, strength.cohesion, sp.area) {
        None => f_s,
        Some(_) => {
            if *status == SpringStatus::Intact {
                *status = SpringStatus::Shear;
            }
            let limit = (-f_n).max(0.0) * strength.tan_phi + strength.cohesion * sp.area;
            let kept = f_s.map(|v| v * limit / fs_abs);
            *slip = [0, 1, 2].map(|i| slip[i] + (f_s[i] - kept[i]) / sp.ks);
            kept
        }
    };
    [0, 1, 2].map(|i| f_n * sp.normal[i] + f_s[i])
}
