//! The runout cases, their reference values and tolerances, and their rows
//! (references/runout.md; the runs: `cdem::harness::suite::runout`).

use super::{spec, Case, RowSpec, SpecKind::Asserted, SpecKind::Compared, SpecKind::Reported};
use crate::harness::report::Goal;

/// Large displacement, contacts and runout: 3DEC's sliding and toppling
/// blocks, the launched and the dropped block, objectivity, the energy budget.
pub const RUNOUT_MD: &str = "references/runout.md";

/// Gravity of the 3DEC verification and of every runout block case (m/s^2).
pub const RUNOUT_GRAVITY: f64 = 10.0;
/// The plane's dip in 3DEC's three block cases (deg).
pub const RUNOUT_DIP_DEG: f64 = 40.0;
/// Case (a)'s friction angle (deg): slides.
pub const RUNOUT_SLIDING_PHI_DEG: f64 = 20.0;
/// Case (b)'s (deg): just above the dip, at rest.
pub const RUNOUT_AT_REST_PHI_DEG: f64 = 40.1;
/// Case (c)'s (deg): equal to the dip; the 25 m block topples.
pub const RUNOUT_TOPPLING_PHI_DEG: f64 = 40.0;
/// The launched block: friction angle (deg) and launch speed (m/s).
pub const RUNOUT_LAUNCH_PHI_DEG: f64 = 30.0;
pub const RUNOUT_LAUNCH_SPEED: f64 = 7.0;
/// The contact stiffness of blocks that never shared a face, per unit area
/// (Pa/m): the joints' own (`verification/runout/*.toml`, 1e10 / 1 m).
pub const RUNOUT_CONTACT_STIFFNESS: f64 = 1e10;
/// The dropped block's soft contact (Pa/m): its contact period, pi sqrt(m / k)
/// = 20 ms, is 11 times the block's own (2 L / c = 1.8 ms), so the impact
/// is quasi-static and the rebound tests the contact's elasticity; with the
/// stiff contact the blocks' vibration keeps a quarter of the energy
/// (references/runout.md).
pub const RUNOUT_SOFT_CONTACT_STIFFNESS: f64 = 1e8;
/// The dropped block's fall height (m): the gap under it in dropped.geo.
pub const RUNOUT_DROP_HEIGHT: f64 = 1.0;

/// 3DEC's sliding block, 10 m x 5 m, phi 20 deg (verification/runout/sliding.toml).
pub const RUNOUT_SLIDING: Case = Case {
    name: "3DEC sliding block",
    input: "verification/runout/sliding.toml",
    checks: "travel at 1 s and 2 s against g (sin 40 - cos 40 tan 20) t^2 / 2 (tests/runout.rs)",
    source: RUNOUT_MD,
};
/// 3DEC's block at rest, 10 m x 10 m, phi 40.1 deg.
pub const RUNOUT_AT_REST: Case = Case {
    name: "3DEC block at rest",
    input: "verification/runout/at-rest.toml",
    checks: "travel in 1 s below 1 mm (tests/runout.rs)",
    source: RUNOUT_MD,
};
/// 3DEC's toppling block, 10 m x 25 m, phi 40 deg.
pub const RUNOUT_TOPPLING: Case = Case {
    name: "3DEC toppling block",
    input: "verification/runout/toppling.toml",
    checks: "topples (w / h = 0.4 < tan 40): the rotation (tests/runout.rs)",
    source: RUNOUT_MD,
};
/// A 2 m block launched along a level plane, phi 30 deg.
pub const RUNOUT_LAUNCHED: Case = Case {
    name: "launched block",
    input: "verification/runout/launched.toml",
    checks: "stopping distance v0^2 / (2 mu g) (tests/runout.rs)",
    source: RUNOUT_MD,
};
/// A 2 m block dropped 1 m onto a level plane.
pub const RUNOUT_DROPPED: Case = Case {
    name: "dropped block",
    input: "verification/runout/dropped.toml",
    checks: "first contact at sqrt(2 h / g), rebound to h undamped, rest when damped; a free spin keeps no stress (tests/runout.rs)",
    source: RUNOUT_MD,
};

/// The acceleration of a cohesionless block on a plane dipping theta with
/// friction angle phi under gravity `g`: `g (sin theta - cos theta tan phi)`.
pub fn block_acceleration(theta_deg: f64, phi_deg: f64, g: f64) -> f64 {
    let (th, phi) = (theta_deg.to_radians(), phi_deg.to_radians());
    g * (th.sin() - th.cos() * phi.tan())
}

/// The blocks' density (kg/m^3, every `verification/runout/*.toml`) and the
/// water's, for the submerged launched block.
pub const RUNOUT_ROCK_DENSITY: f64 = 2000.0;
pub const RUNOUT_WATER_DENSITY: f64 = 1000.0;
/// The submerged block's water table (m): 8 m above the block's top (z = 2).
pub const RUNOUT_WATER_LEVEL: f64 = 10.0;

/// The submerged launched block's stopping distance: its weight less its
/// buoyancy (Archimedes) presses it on the base, `v0^2 / (2 tan(phi) g (1 -
/// rho_w / rho))` (m); the water's push on its faces is level, so it neither
/// drives nor brakes it.
pub fn submerged_launch_distance(v0: f64, phi_deg: f64, g: f64) -> f64 {
    launch_distance(v0, phi_deg, g) / (1.0 - RUNOUT_WATER_DENSITY / RUNOUT_ROCK_DENSITY)
}

/// The launched block's stopping distance `v0^2 / (2 tan(phi) g)` (m).
pub fn launch_distance(v0: f64, phi_deg: f64, g: f64) -> f64 {
    v0 * v0 / (2.0 * phi_deg.to_radians().tan() * g)
}

/// The sliding block's travel against Coulomb's: 1 % (the band; the
/// block starts from its bonded static state, so no settling enters).
pub const TOL_RUNOUT_TRAVEL: f64 = 0.01;
/// The block at rest: less than 1 mm in 1 s.
pub const TOL_RUNOUT_AT_REST: f64 = 1e-3;
/// The launched block's stopping distance: 1 %.
pub const TOL_RUNOUT_STOP: f64 = 0.01;
/// The dropped block's rebound height against its fall: 5 % (the band:
/// the blocks' own vibration keeps part of the impact's energy).
pub const TOL_RUNOUT_REBOUND: f64 = 0.05;
/// The free spin's largest stress over E (a unit strain): 1e-6.
pub const TOL_RUNOUT_OBJECTIVITY: f64 = 1e-6;
/// Every runout's energy budget: closes within 1 % of the work of gravity.
pub const TOL_RUNOUT_ENERGY: f64 = 0.01;

/// The paper's slip-surface slope run out (verification/runout/slope-slip-runout.toml).
pub const RUNOUT_SLOPE: Case = Case {
    name: "paper slope run out",
    input: "verification/runout/slope-slip-runout.toml",
    checks: "after global sliding on the slip circle, the mass comes to rest on the toe bench; its centre of mass's energy line against the sled model; the energy budget (tests/runout.rs)",
    source: RUNOUT_MD,
};
/// The toe bench's level (m): z = 20 in verification/cases/slope-slip/slope-slip.geo
/// (the slip circle dips 0.19 m below it just behind the toe).
pub const RUNOUT_TOE_BENCH_Z: f64 = 20.0;
/// The sliding mass's friction angle (deg): the slip interface's and the new
/// contacts' in slope-slip-runout.toml (the paper's phi = 18 deg).
pub const RUNOUT_SLOPE_PHI_DEG: f64 = 18.0;
/// The sled model's travel angle (Heim 1932; Hsu 1975; Hungr 2005): a mass
/// sliding from rest to rest with friction `tan(phi)` stops on its energy
/// line, centre-of-mass drop / travel = `tan(phi)`, exactly for a sled on a
/// path of small curvature. Curvature, rotation and internal deformation add
/// friction work, so a deformable mass on a concave path stops short of it:
/// its travel angle is at least phi (references/runout.md).
pub fn sled_travel_angle(phi_deg: f64) -> f64 {
    phi_deg
}

const SLIDING_CASE: &str = "3DEC sliding block, 10 x 5 m, dip 40, phi 20";
const SLOPE_CASE: &str = "the paper's slip-surface slope run out, phi 18 (stiffness_limit 10)";

/// The runout rows (appended to the registry's).
#[rustfmt::skip]
pub const RUNOUT_ROWS: &[RowSpec] = &[
    spec("runout/3dec-sliding-1s", SLIDING_CASE, "travel at 1 s (m)", Asserted(TOL_RUNOUT_TRAVEL), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/3dec-sliding-2s", SLIDING_CASE, "travel at 2 s (m), across four base faces", Asserted(TOL_RUNOUT_TRAVEL), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/3dec-at-rest", "3DEC block at rest, 10 x 10 m, dip 40, phi 40.1", "travel in 1 s (m)", Asserted(TOL_RUNOUT_AT_REST), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/3dec-toppling", "3DEC toppling block, 10 x 25 m, dip 40, phi 40", "topples: rotation past 30 deg within 4 s", Compared(true), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/3dec-toppling-angle", "3DEC toppling block, 10 x 25 m, dip 40, phi 40", "rotation at 2 s (deg; no published value: reported)", Reported(Goal::AtLeast), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/launched-stop", "block launched at 7 m/s on a level plane, phi 30", "stopping distance (m)", Asserted(TOL_RUNOUT_STOP), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/launched-submerged-stop", "block launched at 7 m/s on a level plane under 8 m of water, phi 30", "stopping distance (m), buoyancy by the water following the block", Asserted(TOL_RUNOUT_STOP), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/energy-launched-submerged", "block launched at 7 m/s on a level plane under 8 m of water, phi 30", "energy budget: |residual| / kinetic energy at launch", Asserted(TOL_RUNOUT_ENERGY), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/dropped-contact-time", "block dropped 1 m, no damping", "time of first contact (s), to the time step", Asserted(TOL_RUNOUT_STOP), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/dropped-rebound", "block dropped 1 m, no damping, soft contact 1e8 Pa/m", "rebound height (m)", Asserted(TOL_RUNOUT_REBOUND), RUNOUT_MD, "tests/runout.rs").with_reference(RUNOUT_DROP_HEIGHT),
    spec("runout/dropped-rest", "block dropped 1 m, local damping 0.8", "comes to rest: speed below 1 mm/s within 3 s", Compared(true), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/objectivity", "free block spun 90 deg, no load", "largest stress / E", Asserted(TOL_RUNOUT_OBJECTIVITY), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/energy-3dec-sliding", SLIDING_CASE, "energy budget: |residual| / gravity work", Asserted(TOL_RUNOUT_ENERGY), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/energy-3dec-toppling", "3DEC toppling block, 10 x 25 m, dip 40, phi 40", "energy budget: |residual| / gravity work", Asserted(TOL_RUNOUT_ENERGY), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/energy-launched", "block launched at 7 m/s on a level plane, phi 30", "energy budget: |residual| / kinetic energy at launch", Asserted(TOL_RUNOUT_ENERGY), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/energy-dropped", "block dropped 1 m, local damping 0.8", "energy budget: |residual| / gravity work", Asserted(TOL_RUNOUT_ENERGY), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/slope-slip-rest", SLOPE_CASE, "comes to rest on the toe bench (deposit above z = 20 - 0.5 m, at rest within 20 s)", Compared(true), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/slope-slip-travel-angle", SLOPE_CASE, "travel angle of the moved mass's centre of mass (deg): at least the sled model's phi", Compared(true), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/energy-slope-slip", SLOPE_CASE, "energy budget: |residual| / gravity work", Asserted(TOL_RUNOUT_ENERGY), RUNOUT_MD, "tests/runout.rs").with_reference(0.0),
    spec("runout/determinism", SLIDING_CASE, "1 and 2 threads: identical displacement, bit for bit", Compared(true), RUNOUT_MD, "tests/runout.rs"),
    spec("runout/determinism-water", "block launched at 7 m/s on a level plane under 8 m of water, phi 30, 0.5 s", "1 and 2 threads: identical displacement, bit for bit, the water forces following the block", Compared(true), RUNOUT_MD, "tests/runout.rs"),
];
