//! The verification harness, and only it: the paper's cases and their
//! reference values ([`registry`]), the validation table ([`report`],
//! [`validation`]), `cdem reproduce` ([`reproduce`], the paper's figures),
//! the error-against-run-time study ([`study`]) and the performance figures
//! ([`perf`]). The product's own figures (what `cdem run`, `srm`, `fem` and
//! `ensemble` write) are [`crate::output::figures`], on whose plotting the
//! harness draws too; the product commands are [`crate::app`].
//!
//! It depends on the library and the library never on it; it is compiled
//! with the default feature `harness` (which also brings `plot` and the
//! command-line crates). A library user takes `cdem` with
//! `default-features = false` and gets the solver alone.

pub mod perf;
pub mod registry;
pub mod report;
pub mod reproduce;
pub mod study;
pub mod suite;
pub mod validation;
