//! Scene (and LEM file) table `[ensemble]`: what `cdem ensemble` varies from
//! member to member and what it computes per member (docs/method.md section 4.7).
//!
//! ```toml
//! [ensemble]
//! members = 200                  # default of --members
//! seed = 1                       # default of --seed (BASE)
//! analyses = ["cdem", "lem"]     # default: "cdem" for a scene (+ "lem" with [lem]), "lem" for a LEM file;
//!                                # "srm": strength reduction per member (its FS is the headline FS);
//!                                # "cdem" with [analysis]: eq. 21 K per member on its circle
//! lem_surface = "critical"       # "critical": every member on the mean critical circle; "search": its own
//!
//! [[ensemble.random]]            # a strength drawn per member, as Slide's probabilistic analysis
//! key = "interface[0].strength.cohesion"   # any real number of the file, by its key
//!                                # (set on the typed member: drivers::ensemble::keys)
//! distribution = "normal"        # or "lognormal"
//! mean = 16e3                    # default: the file's value
//! std_dev = 2e3
//! min = 0.0                      # optional truncation (redrawn outside [min, max])
//! ```

use serde::Deserialize;

use crate::error::SceneError;

#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EnsembleSpec {
    /// Member count when `--members` is not given.
    pub members: Option<usize>,
    /// Base seed when `--seed` is not given. Default 1.
    pub seed: Option<u64>,
    /// What each member computes (default: see the module doc).
    pub analyses: Option<Vec<Analysis>>,
    /// How the LEM of a member finds its circle. Default `critical`.
    #[serde(default)]
    pub lem_surface: LemSurface,
    #[serde(default)]
    pub random: Vec<RandomVariable>,
}

/// A per-member analysis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Analysis {
    /// The CDEM run of the member's scene (phase 1, and phase 2 with `[failure]`).
    Cdem,
    /// The LEM of the member's `[lem]` table (or LEM file).
    Lem,
    /// Strength reduction of the member's scene (`cdem srm`): its FS is the
    /// member's headline FS.
    Srm,
}

/// Slide's two modes: the critical surface of the mean values, or a search per member.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LemSurface {
    #[default]
    Critical,
    Search,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Distribution {
    #[default]
    Normal,
    /// `ln X` normal, with the given mean and standard deviation of `X`.
    Lognormal,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomVariable {
    /// The key of a number in the file, as errors spell it: `interface[0].strength.cohesion`.
    pub key: String,
    #[serde(default)]
    pub distribution: Distribution,
    /// Default: the file's value at `key`.
    pub mean: Option<f64>,
    pub std_dev: f64,
    pub min: Option<f64>,
    pub max: Option<f64>,
}

impl EnsembleSpec {
    /// Checks what can be checked without the file's other values.
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.members == Some(0) {
            return Err(SceneError::invalid("ensemble.members", "must be at least 1"));
        }
        if self.analyses.as_ref().is_some_and(|a| a.is_empty()) {
            return Err(SceneError::invalid("ensemble.analyses", "must name at least one analysis"));
        }
        for (i, r) in self.random.iter().enumerate() {
            let key = |k: &str| format!("ensemble.random[{i}].{k}");
            if !(r.std_dev.is_finite() && r.std_dev >= 0.0) {
                return Err(SceneError::invalid(key("std_dev"), "must be finite and >= 0"));
            }
            if r.mean.is_some_and(|m| !m.is_finite()) {
                return Err(SceneError::invalid(key("mean"), "must be finite"));
            }
            if let (Some(lo), Some(hi)) = (r.min, r.max) {
                if !(lo < hi) {
                    return Err(SceneError::invalid(key("max"), format!("must exceed min ({lo}), got {hi}")));
                }
            }
            if r.distribution == Distribution::Lognormal && r.mean.is_some_and(|m| m <= 0.0) {
                return Err(SceneError::invalid(key("mean"), "a lognormal variable needs a positive mean"));
            }
        }
        Ok(())
    }
}
