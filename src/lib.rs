//! # cdem — the continuum–discontinuum element method for jointed rock slopes
//!
//! Every element is a linear-elastic polyhedron (24 constant-strain tetrahedra
//! for a hexahedron); neighbouring elements own separate copies of their shared
//! nodes, joined by normal and shear springs; the static state is found by
//! explicit dynamic relaxation. After Liu, Li & Liu (2014), restated in
//! `DESIGN.md`.
//!
//! The pipeline: [`mesh::gmsh::read_msh`] -> [`scene::Scene::load`] ->
//! [`model::build`] (perturbation, node copies, element operators, springs) ->
//! [`solver::Solver::relax`] -> [`output`].
//!
//! ```no_run
//! let scene = cdem::scene::Scene::load("verification/cases/column/column.toml".as_ref())?;
//! let result = cdem::run::run_scene(&scene, &mut |_, _| {})?;
//! println!("top displacement {:.4e} m", result.summary.min_uz);
//! # Ok::<(), cdem::Error>(())
//! ```

pub mod analysis;
pub mod error;
pub mod fem;
pub mod lem;
pub mod mesh;
pub mod model;
pub mod output;
pub mod perf;
pub mod physics;
pub mod progressive;
pub mod reproduce;
pub mod run;
pub mod scene;
pub mod solver;
pub mod study;
pub mod validation;

pub use error::{Error, MeshError, ModelError, Result, SceneError, SolveError};
