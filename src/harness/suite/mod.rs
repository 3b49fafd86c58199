//! The cases of the validation table whose rows need more than one run's
//! numbers (a failure sequence, a physical-time run, an ensemble, a strength
//! reduction, a cross-check against committed values): one function per case
//! that runs it and returns its rows and what its test asserts on, called by
//! both its test (`tests/*.rs`) and `cdem reproduce`
//! ([`crate::harness::reproduce`]), so the two cannot disagree.

pub mod block;
pub mod ensemble;
pub mod extreme;
pub mod fserror;
pub mod joints;
pub mod laws;
pub mod lem_layers;
pub mod lem_water;
pub mod meshes;
pub mod plastic;
pub mod runout;
pub mod skfem;
pub mod slope_failure;
pub mod srm;
pub mod taylor;
pub mod water;
pub mod wulong;
