//! Plain geometry shared by the layers above: the one circle type.
//!
//! A [`Circle`] is a circle in the x-z section (x horizontal, z up, m): the
//! trial and critical circles of the limit equilibrium (`lem`), the slip
//! circles eq. 19-22 are evaluated on (`analysis`), the scene's
//! `[analysis] circle` and the ensembles' circles. Types that carry more
//! than the geometry (a critical circle with its FS, an arc with its ends,
//! a slip circle with its toe and sense) contain one.

use serde::{Deserialize, Serialize};

/// A circle in the x-z section (m): centre `(xc, zc)`, radius `r`. As a
/// table (a scene's `[analysis] circle`, a LEM file's `[circle]`) its keys
/// are `xc`, `zc` and `r`, no others.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Circle {
    pub xc: f64,
    pub zc: f64,
    pub r: f64,
}

impl Circle {
    /// The point `[x, z]` at polar angle `a` (rad, from +x toward +z).
    pub fn at(&self, a: f64) -> [f64; 2] {
        [self.xc + self.r * a.cos(), self.zc + self.r * a.sin()]
    }
}
