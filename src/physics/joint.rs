//! The joint-law seam (paper eq. 16-18): what a structural plane is
//! ([`JointProps`]: stiffness and strength, one type for `[joints]` and every
//! `[[interface]]`), what each spring can carry now ([`JointState`], owned by
//! the loop beside the springs' history), and the law that turns a spring's
//! relative displacement into its force ([`JointLaw`]; the paper's is
//! [`CoulombJoint`]: tension cut-off and Mohr–Coulomb, brittle or ductile).
//!
//! The split is YADE's (geometry, physics, law) and fenics-constitutive's
//! (parameters and history in, force out): the model holds each spring's
//! geometry and stiffness ([`Spring`]), the state its strength and history,
//! and the law is a pure function of (spring, strength, history, relative
//! displacement). Strength reduction divides the state's strengths
//! ([`JointState::reduced`]) and never touches the model; a pore pressure
//! would be one more per-spring field of [`JointState`] that the law
//! subtracts from the normal stress.

use serde::{Deserialize, Serialize};

use super::spring::{mohr_coulomb, spring_force, spring_stiffness, tension_cutoff, Spring, SpringStatus};

/// What a spring keeps of its strength once it has failed.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Softening {
    /// Cohesion and tensile strength lost at failure (eq. 17-18 as in the paper).
    #[default]
    Brittle,
    /// Strength kept: perfectly plastic Mohr-Coulomb with a tension cap.
    Ductile,
}

/// Strength of a breakable structural plane (SI: Pa, Pa, dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointStrength {
    /// Tensile strength `T` (Pa), eq. 17.
    pub tensile: f64,
    /// Cohesion `c` (Pa), eq. 18.
    pub cohesion: f64,
    /// `tan(phi)`, eq. 18.
    pub tan_phi: f64,
    pub softening: Softening,
}

impl JointStrength {
    /// The strength reduced by a factor `f` (strength reduction):
    /// `T / f`, `c / f`, `tan(phi) / f`.
    pub fn reduced(&self, f: f64) -> Self {
        Self { tensile: self.tensile / f, cohesion: self.cohesion / f, tan_phi: self.tan_phi / f, ..*self }
    }
}

/// One structural plane: eq. 16's moduli and thickness, and its strength if
/// it is breakable. The moduli are NaN on a merged interface (no springs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointProps {
    /// `E_j` (Pa).
    pub normal_modulus: f64,
    /// `G_j` (Pa).
    pub shear_modulus: f64,
    /// Equivalent thickness `L` (m).
    pub thickness: f64,
    /// Breakable (eq. 17-18) in the failure phase if given.
    pub strength: Option<JointStrength>,
}

impl JointProps {
    /// Eq. 16: `(K_n, K_s)` of a spring with area share `area` (m^2).
    pub fn stiffness(&self, area: f64) -> (f64, f64) {
        spring_stiffness(self.normal_modulus, self.shear_modulus, area, self.thickness)
    }
}

/// What each spring can carry now, indexed by spring: its strength (None: an
/// unbreakable spring, elastic in every phase). Built from the interfaces'
/// strengths; the failure phase reads it, strength reduction rescales it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct JointState {
    pub strength: Vec<Option<JointStrength>>,
}

impl JointState {
    /// Spring `s` gets the strength of its interface `interface_of[s]`.
    pub fn new(interface_of: &[u16], strengths: &[Option<JointStrength>]) -> Self {
        Self { strength: interface_of.iter().map(|&i| strengths[i as usize]).collect() }
    }

    /// Every strength divided by `f` ([`JointStrength::reduced`]).
    pub fn reduced(&self, f: f64) -> Self {
        Self { strength: self.strength.iter().map(|s| s.map(|s| s.reduced(f))).collect() }
    }

    /// Whether any spring can break.
    pub fn any_breakable(&self) -> bool {
        self.strength.iter().any(Option::is_some)
    }
}

/// A joint law: the force a breakable spring exerts on its node `a` (node `b`
/// gets the opposite) for the relative displacement `d = u_b - u_a`, with
/// its history (plastic slip, status) updated. A pure function of its
/// inputs; the force stage calls it per spring.
pub trait JointLaw: Sync {
    fn force(
        &self,
        spring: &Spring,
        d: [f64; 3],
        strength: &JointStrength,
        slip: &mut [f64; 3],
        status: &mut SpringStatus,
    ) -> [f64; 3];
}

/// The paper's joint law (eq. 15 with eq. 17-18), in two softenings:
///
/// - brittle (the paper's): an intact spring breaks in tension (eq. 17; force
///   zero now) or slips when Mohr–Coulomb with cohesion (eq. 18) is
///   exceeded, and then keeps only friction `P tan(phi)`; a broken spring
///   that is open (`F_n > 0`) carries nothing and its shear reference
///   follows the motion (it recloses with zero shear force);
/// - ductile: failure changes the status (for the record) but not the
///   strength. The normal force is capped at `T A` (no normal plastic
///   displacement is kept: the cap is a limit on the force, not a memory),
///   and the shear force at `P tan(phi) + c A` at every step,
///   `P = max(-F_n, 0)`.
///
/// Plastic slip is updated so that `K_s (d_s - d_s^p)` equals the returned
/// shear force.
#[derive(Debug, Clone, Copy, Default)]
pub struct CoulombJoint;

impl JointLaw for CoulombJoint {
    #[inline]
    fn force(
        &self,
        spring: &Spring,
        d: [f64; 3],
        strength: &JointStrength,
        slip: &mut [f64; 3],
        status: &mut SpringStatus,
    ) -> [f64; 3] {
        match strength.softening {
            Softening::Brittle => brittle_force(spring, d, strength, slip, status),
            Softening::Ductile => ductile_force(spring, d, strength, slip, status),
        }
    }
}

/// The brittle branch of [`CoulombJoint`].
#[inline]
fn brittle_force(
    sp: &Spring,
    d: [f64; 3],
    strength: &JointStrength,
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

/// The ductile branch of [`CoulombJoint`].
#[inline]
fn ductile_force(
    sp: &Spring,
    d: [f64; 3],
    strength: &JointStrength,
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
