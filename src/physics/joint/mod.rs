//! The joint-law seam (paper eq. 16-18): what a structural plane is
//! ([`JointProps`]: stiffness and strength, one type for `[joints]` and every
//! `[[interface]]`), what each spring can carry now ([`JointState`], owned by
//! the loop beside the springs' history), and the laws that turn a spring's
//! relative displacement into its force ([`JointLaw`]).
//!
//! The split is YADE's (geometry, physics, law) and fenics-constitutive's
//! (parameters and history in, force out): the model holds each spring's
//! geometry and stiffness ([`Spring`]), the state its strength and history,
//! and a law is a pure function of (spring, parameters, history, relative
//! displacement) that also owns its strength reduction and the shear
//! strength eq. 21 asks for. Strength reduction divides the state's
//! strengths ([`JointState::reduced`]) and never touches the model.
//!
//! The laws, one file each, registered below in [`JointStrength`] (the
//! parameters a spring carries) and [`StrengthSection`] (the scene's
//! `strength = { law = ..., ... }`):
//!
//! | `law` | file | shear strength |
//! |---|---|---|
//! | `"coulomb"` (default) | [`coulomb`] | eq. 17-18: `T`, `c + sigma_n tan(phi)`, the paper's |
//! | `"barton_bandis"` | [`barton_bandis`] | `sigma_n tan(phi_r + JRC log10(JCS / sigma_n))` |
//!
//! A new law is one more file here, one variant in each of the two enums
//! below (with its arms in their `match`es), and its keys in docs/scene.md.

pub mod barton_bandis;
pub mod coulomb;

use serde::{Deserialize, Serialize};

pub use barton_bandis::{BartonBandis, BartonBandisSection, BartonBandisStrength};
pub use coulomb::{Coulomb, CoulombSection, CoulombStrength};

use super::spring::{spring_contact_force, spring_stiffness, Spring, SpringStatus};

/// A joint law: the force a breakable spring exerts on its node `a` (node `b`
/// gets the opposite) for the relative displacement `d = u_b - u_a`, with
/// its history (plastic slip, status) updated; its strength reduction; and
/// the shear strength at a normal stress (eq. 21). The law is a name (a unit
/// type); its parameters are [`JointLaw::Params`].
pub trait JointLaw {
    /// The parameters one spring carries (SI units).
    type Params: Copy;
    /// The force on node `a` (N) and the updated history.
    fn force(
        p: &Self::Params,
        spring: &Spring,
        d: [f64; 3],
        slip: &mut [f64; 3],
        status: &mut SpringStatus,
    ) -> [f64; 3];
    /// The parameters of strength reduction by `f` (> 0).
    fn reduced(p: &Self::Params, f: f64) -> Self::Params;
    /// The intact joint's shear strength (Pa) at the effective normal stress
    /// `sigma_n` (Pa, compression positive): eq. 21's resistance per area.
    fn shear_strength(p: &Self::Params, sigma_n: f64) -> f64;
    /// The residual friction coefficient: what a new contact on this joint
    /// carries in runout.
    fn residual_tan_phi(p: &Self::Params) -> f64;
    /// Whether an intact spring of this joint holds its two blocks together
    /// (a tensile strength or a cohesion) in runout.
    fn bonds(p: &Self::Params) -> bool;
    /// The parameters as numbers (checkpoints), and back.
    fn words(p: &Self::Params) -> Vec<f64>;
    fn from_words(w: &[f64]) -> Option<Self::Params>;
}

/// The parameters one breakable spring carries: one variant per law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointStrength {
    Coulomb(CoulombStrength),
    BartonBandis(BartonBandisStrength),
}

/// `$body` with `L` the law of `$s`'s variant and `$p` its parameters.
macro_rules! per_law {
    ($s:expr, $p:ident, $body:expr) => {
        match $s {
            JointStrength::Coulomb($p) => {
                type L = Coulomb;
                $body
            }
            JointStrength::BartonBandis($p) => {
                type L = BartonBandis;
                $body
            }
        }
    };
}

impl JointStrength {
    /// [`JointLaw::force`] of this spring's law.
    #[inline]
    pub fn force(&self, spring: &Spring, d: [f64; 3], slip: &mut [f64; 3], status: &mut SpringStatus) -> [f64; 3] {
        per_law!(self, p, L::force(p, spring, d, slip, status))
    }
    /// [`JointLaw::reduced`].
    pub fn reduced(&self, f: f64) -> Self {
        match self {
            JointStrength::Coulomb(p) => JointStrength::Coulomb(Coulomb::reduced(p, f)),
            JointStrength::BartonBandis(p) => JointStrength::BartonBandis(BartonBandis::reduced(p, f)),
        }
    }
    /// [`JointLaw::shear_strength`].
    #[inline]
    pub fn shear_strength(&self, sigma_n: f64) -> f64 {
        per_law!(self, p, L::shear_strength(p, sigma_n))
    }
    /// [`JointLaw::residual_tan_phi`].
    pub fn residual_tan_phi(&self) -> f64 {
        per_law!(self, p, L::residual_tan_phi(p))
    }
    /// [`JointLaw::bonds`].
    pub fn bonds(&self) -> bool {
        per_law!(self, p, L::bonds(p))
    }
    /// The law's tag and [`JointLaw::words`] (checkpoints).
    pub fn words(&self) -> (u8, Vec<f64>) {
        match self {
            JointStrength::Coulomb(p) => (0, Coulomb::words(p)),
            JointStrength::BartonBandis(p) => (1, BartonBandis::words(p)),
        }
    }
    /// The inverse of [`Self::words`]; None for an unknown tag or a bad list.
    pub fn from_words(tag: u8, w: &[f64]) -> Option<Self> {
        match tag {
            0 => Coulomb::from_words(w).map(JointStrength::Coulomb),
            1 => BartonBandis::from_words(w).map(JointStrength::BartonBandis),
            _ => None,
        }
    }
    /// The Coulomb parameters, for the Coulomb law.
    pub fn coulomb_mut(&mut self) -> Option<&mut CoulombStrength> {
        match self {
            JointStrength::Coulomb(p) => Some(p),
            _ => None,
        }
    }
}

/// The scene's `strength` table of `[joints]`, an `[[interface]]` or a
/// joint set: `law` (default `"coulomb"`) and that law's keys.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StrengthSection {
    Coulomb(CoulombSection),
    BartonBandis(BartonBandisSection),
}

/// The laws' names as the scene spells them.
pub const LAW_NAMES: [&str; 2] = ["coulomb", "barton_bandis"];

impl<'de> Deserialize<'de> for StrengthSection {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let mut table = toml::Table::deserialize(d)?;
        let law = match table.remove("law") {
            None => "coulomb".to_string(),
            Some(toml::Value::String(s)) => s,
            Some(other) => return Err(D::Error::custom(format!("law: expected a string, got {other}"))),
        };
        let rest = toml::Value::Table(table);
        match law.as_str() {
            "coulomb" => rest.try_into().map(StrengthSection::Coulomb),
            "barton_bandis" => rest.try_into().map(StrengthSection::BartonBandis),
            other => {
                return Err(D::Error::custom(format!(
                    "law: unknown joint law {other:?}, expected one of {LAW_NAMES:?}"
                )))
            }
        }
        .map_err(|e| D::Error::custom(format!("law {law:?}: {}", e.message())))
    }
}

impl StrengthSection {
    /// The first bad field (its name in the table) and why.
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        match self {
            StrengthSection::Coulomb(s) => s.check(),
            StrengthSection::BartonBandis(s) => s.check(),
        }
    }
    /// The parameters a spring carries.
    pub fn strength(&self) -> JointStrength {
        match self {
            StrengthSection::Coulomb(s) => JointStrength::Coulomb(s.strength()),
            StrengthSection::BartonBandis(s) => JointStrength::BartonBandis(s.strength()),
        }
    }
    /// The number named `field` (ensemble keys).
    pub fn number_mut(&mut self, field: &str) -> Option<&mut f64> {
        match self {
            StrengthSection::Coulomb(s) => s.number_mut(field),
            StrengthSection::BartonBandis(s) => s.number_mut(field),
        }
    }
    /// The table as inline TOML, `{ ... }`.
    pub fn to_toml(&self) -> String {
        let fields = match self {
            StrengthSection::Coulomb(s) => s.toml_fields(),
            StrengthSection::BartonBandis(s) => s.toml_fields(),
        };
        format!("{{ {fields} }}")
    }
    /// The friction angle (degrees) the kinematic tests take: Coulomb's
    /// `phi`; Barton-Bandis' residual `phi_r` (the lower bound of its
    /// envelope's angle: a Markland test with it flags every set that can
    /// slide at some stress).
    pub fn friction_angle(&self) -> f64 {
        match self {
            StrengthSection::Coulomb(s) => s.friction_angle,
            StrengthSection::BartonBandis(s) => s.residual_friction_angle,
        }
    }
    /// The Coulomb table's cohesion, for the Coulomb law (None otherwise).
    pub fn coulomb(&self) -> Option<&CoulombSection> {
        match self {
            StrengthSection::Coulomb(s) => Some(s),
            _ => None,
        }
    }
    pub fn softening_mut(&mut self) -> &mut Softening {
        match self {
            StrengthSection::Coulomb(s) => &mut s.softening,
            StrengthSection::BartonBandis(s) => &mut s.softening,
        }
    }
}

/// What a spring keeps of its strength once it has failed.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Softening {
    /// Cohesion and tensile strength lost at failure (eq. 17-18 as in the paper).
    #[default]
    Brittle,
    /// Strength kept: perfectly plastic with a tension cap.
    Ductile,
}

impl Softening {
    /// The scene's spelling.
    pub fn name(self) -> &'static str {
        match self {
            Softening::Brittle => "brittle",
            Softening::Ductile => "ductile",
        }
    }
    /// As a number of a checkpoint's parameter list.
    fn word(self) -> f64 {
        match self {
            Softening::Brittle => 0.0,
            Softening::Ductile => 1.0,
        }
    }
    fn from_word(w: f64) -> Option<Self> {
        match w {
            0.0 => Some(Softening::Brittle),
            1.0 => Some(Softening::Ductile),
            _ => None,
        }
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

    /// Spring `s`'s force on its node `a`: its law's if it is breakable,
    /// eq. 15 (elastic) if not.
    #[inline]
    pub fn force(
        &self,
        s: usize,
        spring: &Spring,
        d: [f64; 3],
        slip: &mut [f64; 3],
        status: &mut SpringStatus,
    ) -> [f64; 3] {
        match &self.strength[s] {
            Some(st) => st.force(spring, d, slip, status),
            None => spring_contact_force(spring.kn, spring.ks, spring.normal, d, *slip, *status),
        }
    }

    /// Whether any spring can break.
    pub fn any_breakable(&self) -> bool {
        self.strength.iter().any(Option::is_some)
    }
}
