//! Isotropic linear elasticity: the moduli as a user gives them and as the
//! kernels use them.

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
    /// Stress (Pa, Voigt) of a strain (Voigt xx yy zz yz xz xy, engineering
    /// shear): `sigma = lambda tr(eps) I + 2 mu eps`.
    #[inline(always)]
    pub fn stress_voigt(&self, eps: [f64; 6]) -> [f64; 6] {
        let Lame { lambda, mu } = *self;
        let tr = eps[0] + eps[1] + eps[2];
        let l = lambda * tr;
        [l + 2.0 * mu * eps[0], l + 2.0 * mu * eps[1], l + 2.0 * mu * eps[2], mu * eps[3], mu * eps[4], mu * eps[5]]
    }

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
