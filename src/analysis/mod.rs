//! Analyses of a solved state: the stress-based safety factor on a slip
//! surface (paper eq. 19-22, docs/method.md section 2.10) and the sign
//! segments of the per-point factors K_i (section 4.3), on a conforming
//! interface ([`slip`]) or on the arc of any circle in any mesh ([`arc`],
//! section 4.3a).

pub mod arc;
pub mod compare;
pub mod kinematics;
pub mod richardson;
pub mod safety;
pub mod slip;
pub mod slip_band;
pub mod stats;

pub use safety::{
    safety_factors, safety_factors_with, sign_segments, traction_from_stress, SafetyFactors, Segment, SurfacePoint,
};
