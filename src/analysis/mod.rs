//! Analyses of a solved state: the stress-based safety factor on a slip
//! surface (paper eq. 19-22, docs/method.md section 4) and the sign segments of the
//! per-point factors K_i, on a conforming interface ([`slip`]) or on any
//! circle of any mesh ([`surface`]).

pub mod compare;
pub mod safety;
pub mod slip;
pub mod stats;
pub mod surface;

pub use safety::{
    safety_factors, safety_factors_with, sign_segments, traction_from_stress, SafetyFactors, Segment, SurfacePoint,
};
