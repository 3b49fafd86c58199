//! Shared by the element tests: reference cells, the rock material and a
//! seeded corner perturbation.
#![allow(dead_code)] // each test binary uses its own part

use cdem::mesh::perturb::SplitMix64;
use cdem::physics::material::{Material, MaterialLaw, YoungPoisson};

pub const UNIT_HEX: [[f64; 3]; 8] =
    [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.], [0., 0., 1.], [1., 0., 1.], [1., 1., 1.], [0., 1., 1.]];
pub const UNIT_PRISM: [[f64; 3]; 6] =
    [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.], [1., 0., 1.], [0., 1., 1.]];
pub const UNIT_TET: [[f64; 3]; 4] = [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]];

/// The paper's rock: E = 3e8 Pa, nu = 0.3, 2100 kg/m^3.
pub fn rock() -> Material {
    Material {
        lame: YoungPoisson { young: 3.0e8, poisson: 0.3 }.into(),
        density: 2100.0,
        law: MaterialLaw::LinearElastic,
    }
}

/// Corners of `base` scaled by `scale` and moved by up to `r` per axis (seeded).
pub fn perturbed(base: &[[f64; 3]], scale: f64, r: f64, seed: u64) -> Vec<[f64; 3]> {
    let mut rng = SplitMix64::new(seed);
    base.iter().map(|x| x.map(|v| scale * v + r * (2.0 * rng.next_f64() - 1.0))).collect()
}
