//! Drivers: a scene from its file to its results, in memory. They sit above
//! the solver, the FEM and the LEM and below `output` (which writes what they
//! return), and they relax only through [`solver::relax`](crate::solver::relax()).
//!
//! - [`input`]: a scene's mesh and model;
//! - [`phase`]: the vocabulary they share (phases, watchers, frames, stages);
//! - [`run`]: the CDEM run of a scene: phase 1 (elastic) and, for a scene
//!   with `[failure]`, phase 2 ([`failure`]: breakable joints, stages, end state);
//! - [`fem`]: the implicit FEM reference on the scene's continuous mesh;
//! - [`lem`]: the LEM input of a LEM file or of a scene's `[lem]` table;
//! - [`ensemble`]: Monte-Carlo members of a scene or LEM file, and their statistics;
//! - [`srm`]: strength reduction, the factor of safety (`cdem srm`);
//! - [`analysis`]: the scene's `[analysis]`, eq. 21/22 on its slip circle;
//! - [`checkpoint`]: checkpoints of `cdem srm` and their resume, bit for bit.

pub mod analysis;
pub mod checkpoint;
pub mod discretisation;
pub mod ensemble;
pub mod failure;
pub mod fem;
pub mod input;
pub mod lem;
pub mod mesh_check;
pub mod phase;
pub mod run;
pub mod runout;
pub mod srm;

pub use crate::summary::EndState;
pub use analysis::{run_analysis, AnalysisReport};
pub use failure::FailureResult;
pub use fem::{run_fem, solve_scene as solve_fem, FemRun};
pub use input::{build_model, read_mesh};
pub use lem::{load_lem_input, scene_lem_input};
pub use phase::{Frame, NoWatch, Phase, Progress, Stage, StageSnapshots, Watch};
pub use run::{run_scene, run_watched, RunResult};
pub use srm::{run_srm, SrmProgress, SrmResult, Trial};
