//! The block on an inclined plane (references/sliding-block.md).

#[allow(unused_imports)]
use super::super::*;

/// The contact's friction angle in tests/fixtures/block-on-plane.toml (deg).
pub const SLIDING_BLOCK_PHI_DEG: f64 = 20.0;

/// The acceleration of a cohesionless block sliding down a plane inclined at
/// theta with friction angle phi: g (sin theta - cos theta tan phi) (m/s^2).
pub fn sliding_block_acceleration(theta_deg: f64, phi_deg: f64) -> f64 {
    let (th, phi) = (theta_deg.to_radians(), phi_deg.to_radians());
    GRAVITY * (th.sin() - th.cos() * phi.tan())
}
