//! Constitutive laws (issue 58; references/laws.md; the runs:
//! `cdem::harness::suite::laws`): Barton-Bandis joints in a direct shear
//! test against their envelope, and in Hoek & Bray's plane failure against
//! its closed form, dry and with the tension crack full of water.

use super::{spec, Case, PlaneFailure, RowSpec, SpecKind::Asserted, SpecKind::Bounded};

/// The laws' reference values and their sources.
pub const LAWS_MD: &str = "references/laws.md";

/// A Barton-Bandis joint as the closed forms take it (degrees, Pa).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BartonBandisJoint {
    pub jrc: f64,
    /// Pa.
    pub jcs: f64,
    pub phi_r_deg: f64,
    /// The cap on the total friction angle (deg).
    pub cap_deg: f64,
}

impl BartonBandisJoint {
    /// Barton & Choubey (1977): `tau = sigma_n tan(phi_r + JRC log10(JCS /
    /// sigma_n))` (Pa), the total angle at most the cap and the roughness
    /// term at least zero (`sigma_n >= JCS`), zero for `sigma_n <= 0`.
    pub fn tau(&self, sigma_n: f64) -> f64 {
        if sigma_n <= 0.0 {
            return 0.0;
        }
        let angle = (self.phi_r_deg + (self.jrc * (self.jcs / sigma_n).log10()).max(0.0)).min(self.cap_deg);
        sigma_n * angle.to_radians().tan()
    }
}

/// Issue 58's direct-shear joint: JRC 10, JCS 100 MPa, phi_r 30 deg (the
/// default cap, 70 deg); at 1 MPa its peak is 1 MPa x tan(50 deg).
pub const BB_SHEAR_JOINT: BartonBandisJoint =
    BartonBandisJoint { jrc: 10.0, jcs: 100e6, phi_r_deg: 30.0, cap_deg: 70.0 };
/// The direct shear test's three normal stresses (Pa): the roughness term
/// is 30, 20 and 10 deg.
pub const BB_SHEAR_STRESSES: [f64; 3] = [0.1e6, 1e6, 10e6];
/// The envelope at [`BB_SHEAR_STRESSES`] (Pa): `python3
/// scripts/rock_slope_closed_forms.py` to the last digit (tests/laws.rs
/// checks [`BartonBandisJoint::tau`] against them to 1e-12).
pub const BB_SHEAR_PEAKS: [f64; 3] = [173205.08075688768, 1191753.59259421, 8390996.3117728];
/// The residual at 1 MPa, `1 MPa tan(30 deg)` (Pa).
pub const BB_SHEAR_RESIDUAL_1MPA: f64 = 577350.2691896257;
/// Issue 58's quoted value at 1 MPa (Pa, 4 figures).
pub const BB_SHEAR_AT_1MPA_QUOTED: f64 = 1.192e6;
/// The law's peak and residual against the envelope (relative): the
/// spring's force is the envelope times its area, to rounding.
pub const TOL_BB_SHEAR: f64 = 1e-12;

/// The plane-failure joint (verification/laws/plane-barton-bandis.toml):
/// JRC 6, JCS 40 MPa, phi_r 25 deg.
pub const BB_PLANE_JOINT: BartonBandisJoint = BartonBandisJoint { jrc: 6.0, jcs: 40e6, phi_r_deg: 25.0, cap_deg: 70.0 };

/// The plane-failure closed forms, dry and with the crack full
/// ([`plane_failure_bb_fs`]; `python3 scripts/rock_slope_closed_forms.py`
/// to the last digit, checked by tests/laws.rs to 1e-12).
pub const BB_PLANE_FS_DRY: f64 = 1.3696020424390578;
pub const BB_PLANE_FS_WET: f64 = 0.7302836580130894;

/// Hoek & Bray's plane failure on a Barton-Bandis joint, the block's normal
/// stress uniform: `FS = tau(sigma_n') A / (W sin(psi_p) + V cos(psi_p))`,
/// `sigma_n' = (W cos(psi_p) - U - V sin(psi_p)) / A`, the crack filled to
/// `z_w` (m; 0 dry) and the plane's uplift `U = gamma_w z_w A / 2`.
pub fn plane_failure_bb_fs(p: &PlaneFailure, j: &BartonBandisJoint, water_unit_weight: f64, z_w: f64) -> f64 {
    let (h, z) = (p.height, p.crack_depth());
    let (pf, pp) = (p.face_dip.to_radians(), p.plane_dip.to_radians());
    let area = (h - z) / pp.sin();
    let w = 0.5 * p.unit_weight * h * h * ((1.0 - (z / h).powi(2)) / pp.tan() - 1.0 / pf.tan());
    let u = 0.5 * water_unit_weight * z_w * area;
    let v = 0.5 * water_unit_weight * z_w * z_w;
    j.tau((w * pp.cos() - u - v * pp.sin()) / area) * area / (w * pp.sin() + v * pp.cos())
}

/// The dry plane failure on a Barton-Bandis joint.
pub const PLANE_BB: Case = Case {
    name: "plane failure on a Barton-Bandis joint, dry tension crack",
    input: "verification/laws/plane-barton-bandis.toml",
    checks: "`cdem srm` FS against the closed form with a uniform normal stress (tests/laws.rs)",
    source: LAWS_MD,
};

/// The same with the crack full of water.
pub const PLANE_BB_WET: Case = Case {
    name: "plane failure on a Barton-Bandis joint, tension crack full",
    input: "verification/laws/plane-barton-bandis-wet.toml",
    checks: "`cdem srm` FS against the closed form with a uniform normal stress (tests/laws.rs)",
    source: LAWS_MD,
};

/// The plane-failure rows' bounds (above, below the closed form). The
/// closed form takes the normal stress as uniform; the blocks' is not, and
/// the envelope is concave, so the mean of `tau` over the plane is below
/// `tau` of the mean stress (Jensen): strength reduction must lie below the
/// closed form, by at most `TOL_BB_PLANE_BELOW`, and above it by no more
/// than the Coulomb rows' bracket (references/laws.md gives the measured errors).
pub const TOL_BB_PLANE_ABOVE: f64 = 0.01;
pub const TOL_BB_PLANE_BELOW: f64 = 0.03;

const SHEAR_CASE: &str = "direct shear of one Barton-Bandis joint, JRC 10, JCS 100 MPa, phi_r 30";

/// The laws' rows (appended to the registry's).
#[rustfmt::skip]
pub const LAWS_ROWS: &[RowSpec] = &[
    spec("laws/bb-shear-peak-0.1mpa", SHEAR_CASE, "peak shear stress at sigma_n 0.1 MPa (Pa)", Asserted(TOL_BB_SHEAR), LAWS_MD, "tests/laws.rs").with_reference(BB_SHEAR_PEAKS[0]),
    spec("laws/bb-shear-peak-1mpa", SHEAR_CASE, "peak shear stress at sigma_n 1 MPa (Pa)", Asserted(TOL_BB_SHEAR), LAWS_MD, "tests/laws.rs").with_reference(BB_SHEAR_PEAKS[1]),
    spec("laws/bb-shear-peak-10mpa", SHEAR_CASE, "peak shear stress at sigma_n 10 MPa (Pa)", Asserted(TOL_BB_SHEAR), LAWS_MD, "tests/laws.rs").with_reference(BB_SHEAR_PEAKS[2]),
    spec("laws/bb-shear-residual-1mpa", SHEAR_CASE, "brittle: shear stress after the peak at sigma_n 1 MPa (Pa)", Asserted(TOL_BB_SHEAR), LAWS_MD, "tests/laws.rs").with_reference(BB_SHEAR_RESIDUAL_1MPA),
    spec("laws/bb-plane-srm", "plane failure on a Barton-Bandis joint, dry crack (Hoek & Bray's slope)", "FS (strength reduction) vs closed form, uniform normal stress", Bounded(TOL_BB_PLANE_ABOVE, TOL_BB_PLANE_BELOW), LAWS_MD, "tests/laws.rs").with_reference(BB_PLANE_FS_DRY),
    spec("laws/bb-plane-wet-srm", "plane failure on a Barton-Bandis joint, crack full of water", "FS (strength reduction) vs closed form, uniform normal stress", Bounded(TOL_BB_PLANE_ABOVE, TOL_BB_PLANE_BELOW), LAWS_MD, "tests/laws.rs").with_reference(BB_PLANE_FS_WET),
];
