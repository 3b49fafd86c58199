//! The verification harness: the paper's cases and their reference values
//! ([`registry`]), the validation table ([`report`]), `cdem reproduce`
//! ([`reproduce`]), the error-against-run-time study ([`study`]), the
//! performance figures ([`perf`]) and the figures ([`figures`], [`section`]).
//!
//! It depends on the library and the library never on it; it is compiled
//! with the default feature `harness` (which also brings the plotting and
//! command-line crates). A library user takes `cdem` with
//! `default-features = false` and gets the solver alone.

pub mod ensemble;
pub mod figures;
pub mod perf;
pub mod registry;
pub mod report;
pub mod reproduce;
pub mod section;
pub mod srm;
pub mod study;
pub mod surface;
pub mod validation;
