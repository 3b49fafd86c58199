//! The paper slope's slip circle.

#[allow(unused_imports)]
use super::super::*;

/// The Bishop critical circle of the paper slope (references/lem.md, "The
/// paper's slope": centre (24.006, 63.222) m, through the toe (20, 20); the
/// slope faces -x, so the mass turns clockwise), the interface "slip" of verification/cases/slope-slip/slope-slip.geo.
/// Its radius is the centre's distance from the toe (to the last bit:
/// `the_slip_arc_runs_from_the_toe_to_the_crest`).
pub const SLIP_CIRCLE: SlipCircle =
    SlipCircle { circle: Circle { xc: 24.006, zc: 63.222, r: 43.40724962491865 }, toe: [20.0, 20.0], clockwise: true };

/// The crest level of the paper slope (m): the section's ground is
/// (0,20) (20,20) (56,40) (80,40) (references/lem.md).
pub const PAPER_SLOPE_CREST_Z: f64 = 40.0;

/// Cohesion on the slip surface (Pa): the paper's c = 16 kPa (references/paper.md).
pub const SLIP_COHESION: f64 = 16e3;
/// Friction angle on the slip surface (deg): the paper's phi = 18 deg.
pub const SLIP_FRICTION_DEG: f64 = 18.0;
/// Tensile strength on the slip surface (Pa): not in the paper; ours T = c
/// (verification/cases/slope-slip/slope-slip.toml).
pub const SLIP_TENSILE: f64 = 16e3;

/// Minimum sign-segment length of K_i (m): about one element along the
/// surface; shorter runs merge into their neighbours.
pub const MIN_SEGMENT: f64 = 2.0;

/// The radius of [`SLIP_CIRCLE`] (m).
pub fn slip_circle_radius() -> f64 {
    SLIP_CIRCLE.circle.r
}

/// [`SLIP_CIRCLE`] on the section from the toe to the crest, 101 points
/// (x, z), for the figures.
pub fn slip_arc() -> Vec<(f64, f64)> {
    let (c, r) = (SLIP_CIRCLE, slip_circle_radius());
    let crest = PAPER_SLOPE_CREST_Z;
    let Circle { xc, zc, .. } = c.circle;
    let a0 = (c.toe[1] - zc).atan2(c.toe[0] - xc);
    let a1 = (crest - zc).atan2((r * r - (crest - zc).powi(2)).sqrt());
    (0..=100).map(|k| a0 + (a1 - a0) * k as f64 / 100.0).map(|a| (xc + r * a.cos(), zc + r * a.sin())).collect()
}
