//! The plasticity itself against closed forms (references/plastic.md):
//!
//! 1. one plastic hexahedron in plane-strain compression at a confining
//!    stress: the axial stress it carries (its top face's nodal forces over
//!    the face area) rises to the Mohr-Coulomb limit
//!    `sigma_1 = sigma_3 N_phi + 2 c sqrt(N_phi)` and stays there;
//! 2. the mixed element elastic: it is the condensed element of the same
//!    cell with the volumetric strain averaged, no more (its forces equal
//!    `K_mixed u` to round-off, and its stiffness differs from today's
//!    condensed `K_e` only in the volumetric part).

use crate::mesh::shape::CellKind;
use crate::physics::element::element_operators;
use crate::physics::material::{Lame, Material, MaterialLaw, RockStrength, YoungPoisson};
use crate::physics::mohr_coulomb::MohrCoulomb;
use crate::physics::plastic::{plastic_element_force, plastic_operator, TetPlastic, MAX_TETS};
use crate::physics::tet_operator::TetTopology;

/// The unit cube's corners in gmsh's hexahedron order.
pub const UNIT_HEX: [[f64; 3]; 8] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
    [1.0, 0.0, 1.0],
    [1.0, 1.0, 1.0],
    [0.0, 1.0, 1.0],
];

/// One point of the compression test: the confining stress and the axial
/// stress the element carries at the end of the loading (both Pa,
/// compression positive), and the Mohr-Coulomb limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompressionLimit {
    pub confinement: f64,
    pub axial: f64,
    pub limit: f64,
}

impl CompressionLimit {
    /// `|axial - limit| / limit`.
    pub fn error(&self) -> f64 {
        (self.axial - self.limit).abs() / self.limit
    }
}

/// The material of the compression test: E 1 GPa, nu 0.25.
fn elasticity() -> Lame {
    YoungPoisson { young: 1e9, poisson: 0.25 }.into()
}

/// Plane-strain compression (`eps_yy = 0`) of the unit hexahedron with the
/// lateral stress held at `-confinement` and the axial strain driven to
/// `steps x d_axial` (homogeneous displacement field, the element's own
/// kernel each step, its history carried). The axial stress is the top
/// face's nodal force sum over its area.
pub fn compression(strength: RockStrength, confinement: f64, steps: usize, d_axial: f64) -> CompressionLimit {
    let lame = elasticity();
    let material = Material { lame, density: 1.0, law: MaterialLaw::MohrCoulomb(strength) };
    let ops = element_operators(CellKind::Hex8, &UNIT_HEX, &material).expect("the unit cube is a valid cell");
    let tets = plastic_operator(CellKind::Hex8, &UNIT_HEX);
    let topo = TetTopology::of(CellKind::Hex8);
    let surface = MohrCoulomb::of(&strength);
    let nodes: Vec<u32> = (0..8).collect();
    let mut hist = [TetPlastic::default(); MAX_TETS];
    let (mut exx, mut ezz) = (-confinement * (1.0 - 0.25 * 0.25) / 1e9, 0.0);
    let mut f = [0.0; 24];
    let mut forces = |exx: f64, ezz: f64, hist: &mut [TetPlastic]| {
        let u: Vec<f64> = UNIT_HEX.iter().flat_map(|x| [exx * x[0], 0.0, ezz * x[2]]).collect();
        plastic_element_force(&topo, &tets, &ops.grad, lame, &surface, &nodes, &u, hist, &mut f);
        // Top face (z = 1, corners 4-7): sigma_zz = sum f_z; the face x = 1
        // (corners 1, 2, 5, 6): sigma_xx = sum f_x.
        let szz: f64 = (4..8).map(|c| f[3 * c + 2]).sum();
        let sxx: f64 = [1, 2, 5, 6].iter().map(|&c| f[3 * c]).sum();
        (sxx, szz)
    };
    let mut szz = 0.0;
    for _ in 0..steps {
        ezz -= d_axial;
        // Hold sigma_xx at -confinement: secant iterations on eps_xx with the
        // elastic P-modulus, each from the step's starting history (the
        // iterations' return mappings must not accumulate).
        let start = hist;
        for _ in 0..200 {
            let mut h = start;
            let (sxx, s) = forces(exx, ezz, &mut h);
            szz = s;
            hist = h;
            let miss = sxx + confinement;
            if miss.abs() <= 1e-10 * confinement.max(1.0) {
                break;
            }
            exx -= miss / lame.p_modulus();
        }
    }
    let n_phi = {
        let s = strength.tan_phi.atan().sin();
        (1.0 + s) / (1.0 - s)
    };
    CompressionLimit {
        confinement,
        axial: -szz,
        limit: confinement * n_phi + 2.0 * strength.cohesion * n_phi.sqrt(),
    }
}
