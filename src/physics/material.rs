//! Element materials: elasticity, density and the constitutive law.
//!
//! The material-law seam: every element group has a [`MaterialLaw`], a
//! pure function from (stress, strain increment) to stress in the
//! strain-increment form of fenics-constitutive. Linear elasticity,
//! `sigma = lambda tr(eps) I + 2 G eps`, condenses to the element stiffness
//! `K_e` and the force stage takes the fast path `f_e = K_e u_e` (eq. 12)
//! without visiting its tetrahedra. The Mohr-Coulomb rock mass
//! ([`super::mohr_coulomb`]) does not condense once it yields: its elements
//! integrate per tetrahedron with a history the loop owns
//! ([`super::plastic`]); elastic (phase 1) they condense to their mixed
//! stiffness ([`super::element::mixed_stiffness`]).

pub use super::elasticity::{Lame, YoungPoisson};
pub use super::mohr_coulomb::RockStrength;

/// The constitutive law of an element group.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum MaterialLaw {
    /// `sigma = lambda tr(eps) I + 2 mu eps` ([`Lame::stress`]).
    #[default]
    LinearElastic,
    /// Elastic-perfectly-plastic Mohr-Coulomb with a tension cut-off and
    /// non-associated flow ([`super::mohr_coulomb`]), integrated per
    /// tetrahedron with the mixed volumetric strain ([`super::plastic`]).
    MohrCoulomb(RockStrength),
}

impl MaterialLaw {
    /// Whether an element of this law condenses to `f_e = K_e u_e` in every
    /// phase (a plastic element does so only while it is elastic, phase 1).
    pub fn condenses(self) -> bool {
        match self {
            MaterialLaw::LinearElastic => true,
            MaterialLaw::MohrCoulomb(_) => false,
        }
    }

    /// The strength, for a law that yields.
    pub fn strength(self) -> Option<RockStrength> {
        match self {
            MaterialLaw::LinearElastic => None,
            MaterialLaw::MohrCoulomb(s) => Some(s),
        }
    }

    /// The stress after the strain increment `d_eps` (Voigt xx yy zz yz xz
    /// xy, engineering shear) from the stress `sigma` (Pa, same order).
    pub fn stress_update(self, lame: Lame, sigma: [f64; 6], d_eps: [f64; 6]) -> [f64; 6] {
        let ds = lame.stress_voigt(d_eps);
        let trial = [0, 1, 2, 3, 4, 5].map(|i| sigma[i] + ds[i]);
        match self {
            MaterialLaw::LinearElastic => trial,
            MaterialLaw::MohrCoulomb(s) => super::mohr_coulomb::MohrCoulomb::of(&s).return_map(lame, trial).0,
        }
    }
}

/// An element material: elasticity, density (kg/m^3) and law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    pub lame: Lame,
    pub density: f64,
    pub law: MaterialLaw,
}
