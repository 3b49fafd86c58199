//! Element materials: elasticity, density and the constitutive law.
//!
//! The material-law seam: every element group has a [`MaterialLaw`], a
//! pure function from (stress, strain increment) to stress in the
//! strain-increment form of fenics-constitutive. Today's one law is linear
//! elasticity, `sigma = lambda tr(eps) I + 2 G eps`; an element whose law is
//! linear condenses to its stiffness `K_e` and the force stage takes the fast
//! path `f_e = K_e u_e` (eq. 12) without visiting its tetrahedra. A law that
//! does not condense (the Mohr-Coulomb rock mass) would integrate the strain
//! increment per tetrahedron with a history the loop owns.

/// Young's modulus (Pa) and Poisson's ratio, as a user gives them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct YoungPoisson {
    pub young: f64,
    pub poisson: f64,
}

/// Lamé parameters (Pa).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lame {
    pub lambda: f64,
    pub mu: f64,
}

impl From<YoungPoisson> for Lame {
    fn from(m: YoungPoisson) -> Self {
        let (e, nu) = (m.young, m.poisson);
        Lame { lambda: e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu: e / (2.0 * (1.0 + nu)) }
    }
}

impl Lame {
    /// Constrained (P-wave) modulus `M = lambda + 2 mu`.
    pub fn p_modulus(&self) -> f64 {
        self.lambda + 2.0 * self.mu
    }

    /// Stress (Pa, Voigt xx yy zz yz xz xy) of a displacement gradient
    /// `h[i][j] = du_i/dx_j`: `sigma = lambda tr(eps) I + 2 mu eps`.
    pub fn stress(&self, h: &[[f64; 3]; 3]) -> [f64; 6] {
        let tr = h[0][0] + h[1][1] + h[2][2];
        let Lame { lambda, mu } = *self;
        [
            lambda * tr + 2.0 * mu * h[0][0],
            lambda * tr + 2.0 * mu * h[1][1],
            lambda * tr + 2.0 * mu * h[2][2],
            mu * (h[1][2] + h[2][1]),
            mu * (h[0][2] + h[2][0]),
            mu * (h[0][1] + h[1][0]),
        ]
    }
}

/// The constitutive law of an element group.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MaterialLaw {
    /// `sigma = lambda tr(eps) I + 2 mu eps` ([`Lame::stress`]).
    #[default]
    LinearElastic,
}

impl MaterialLaw {
    /// Whether an element of this law condenses to `f_e = K_e u_e`.
    pub fn condenses(self) -> bool {
        match self {
            MaterialLaw::LinearElastic => true,
        }
    }

    /// The stress after the strain increment `d_eps` (Voigt xx yy zz yz xz
    /// xy, engineering shear) from the stress `sigma` (Pa, same order).
    pub fn stress_update(self, lame: Lame, sigma: [f64; 6], d_eps: [f64; 6]) -> [f64; 6] {
        match self {
            MaterialLaw::LinearElastic => {
                let Lame { lambda, mu } = lame;
                let tr = d_eps[0] + d_eps[1] + d_eps[2];
                [0, 1, 2, 3, 4, 5].map(|i| match i {
                    0..=2 => sigma[i] + lambda * tr + 2.0 * mu * d_eps[i],
                    _ => sigma[i] + mu * d_eps[i],
                })
            }
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
