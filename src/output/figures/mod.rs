//! The product's figures (feature `plot`): what `cdem run` and `cdem fem`
//! ([`analysis`], `analysis.png`), `cdem srm` ([`mechanism`],
//! `mechanism.png`) and `cdem ensemble` ([`ensemble`], `fs-histogram.png`,
//! `convergence.png`) write, on the generic plotting of [`plot`] and the
//! section patches of [`section`]. The harness's paper figures draw with the
//! same code.

pub mod analysis;
pub mod ensemble;
pub mod joints;
pub mod mechanism;
pub mod plot;
pub mod runout;
pub mod section;
pub mod stereonet;
pub mod water;

pub use plot::*;
