//! # cdem — the continuum–discontinuum element method for jointed rock slopes
//!
//! Every element of a gmsh mesh (hexahedron, prism, tetrahedron; split into
//! 24, 18 or 1 constant-strain tetrahedra) is a block of its material's law:
//! linear elastic (its stiffness condensed to the corners), or an
//! elastic-plastic Mohr-Coulomb rock mass where the scene gives the material a
//! strength (a history per tetrahedron). Neighbouring elements own separate
//! copies of their shared nodes, joined by normal and shear springs that break
//! in tension or slip by Mohr-Coulomb, on the effective stress where the scene
//! has `[water]`. The static state: phase 1 (elastic) by two-level
//! preconditioned conjugate gradients or dynamic relaxation, phase 2
//! (progressive failure) by explicit dynamic relaxation; `[runout]` follows the
//! failed blocks in real time with large displacements and contacts found
//! anew. After Liu, Li & Liu (2014), restated in `docs/method.md`.
//!
//! The pipeline: [`scene::Scene::load`] -> [`mesh::gmsh::read_msh`] ->
//! [`model::build`] (perturbation, node copies, element operators, springs) ->
//! [`solver::relax()`] (phase 1, then phase 2 for a scene with `[failure]`),
//! driven by [`drivers::run_scene`] -> [`output::write_run`]. Beside the
//! solver: [`fem`] (the implicit reference on the same mesh), [`lem`] (Bishop,
//! Spencer), [`analysis`] (eq. 21 on a surface, kinematics, ensemble
//! statistics); strength reduction and ensembles are drivers.
//!
//! ```no_run
//! let scene = cdem::scene::Scene::load("verification/cases/column/column.toml".as_ref())?;
//! let result = cdem::drivers::run_scene(&scene, &mut |_, _| {})?;
//! println!("top displacement {:.4e} m", result.summary.min_uz);
//! # Ok::<(), cdem::Error>(())
//! ```

// `!(x > 0.0)` is this crate's way to say "not a positive number, NaN
// included"; the partial_cmp form clippy suggests hides that.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Component loops (`for d in 0..3 { u[d] += ... }`) read as the equations
// they implement; iterator chains over zipped arrays would not.
#![allow(clippy::needless_range_loop)]

// The layers, bottom up; a module imports only from layers below its own
// (tests/layering.rs checks it):
//   error, summary, atomic -> mesh, geometry -> physics -> model -> solver | fem | lem | analysis
//   -> scene -> drivers -> output (its figures with feature `plot`) -> app
//   (feature `plot`: one function per product command) -> harness (feature
//   `harness`: verification only) -> the CLI.
pub mod atomic;
pub mod error;
pub mod simd;
pub mod summary;

pub mod geometry;
pub mod mesh;
pub mod physics;

pub mod model;

pub mod analysis;
pub mod fem;
pub mod lem;
pub mod solver;

pub mod scene;

pub mod drivers;

pub mod output;

#[cfg(feature = "plot")]
pub mod app;

#[cfg(feature = "harness")]
pub mod harness;

pub use error::{Error, MeshError, ModelError, Result, SceneError, SolveError};
pub use summary::{EndState, Summary};
