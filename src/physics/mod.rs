//! Pure kernels over flat slices, one physics concept per module. They know
//! nothing of files, scenes or the CLI. Paper equations (Liu, Li & Liu 2014):
//!
//! | eq. | kernel |
//! |-----|--------|
//! | 12  | [`element::element_force`]: deformation force `f = K_e u_e` |
//! | 13  | [`damping`]: damping force (local / viscous) |
//! | 14  | [`crate::solver::integrate`]: `a = (f_ext - f - f_d)/m`, `v += a dt`, `u += v dt` |
//! | 15  | [`spring::spring_force`] (per spring: [`spring::spring_contact_force`]): `F_n = K_n d_n`, `F_s = K_s (d_s - d_s^p)` |
//! | 16  | [`spring::spring_stiffness`]: `K_n = E_j A / L`, `K_s = G_j A / L` |
//! | 17  | [`spring::tension_cutoff`]: `F_n >= T A` -> `F_n = F_s = 0` |
//! | 18  | [`spring::mohr_coulomb`]: `|F_s| > P tan(phi) + c A` -> `|F_s| = P tan(phi)` |
//! | 15, 17-18 | [`joint::Coulomb`]: one breakable spring with its history (brittle or ductile); [`joint::BartonBandis`] the Barton-Bandis joint |
//! | runout | [`corotation::corotated_force`]: `f = R K_e u'`, a block's rotation taken out |
//! | runout | [`contact::contact_force`]: a vertex-face penalty and Coulomb slider |
//!
//! The two constitutive seams: [`joint`] (a [`joint::JointLaw`] reads a
//! spring, its strength in [`joint::JointState`] and its history) and
//! [`material`] (a [`material::MaterialLaw`] per element group; linear
//! elastic condenses to `K_e`).

pub mod contact;
pub mod corotation;
pub mod damping;
pub mod elasticity;
pub mod element;
pub mod joint;
pub mod material;
pub mod mohr_coulomb;
pub mod plastic;
pub mod spring;
pub mod tet_operator;
pub mod water;
