//! The verification cases and every reference value, each stated once, with
//! its provenance: the tests (`tests/*.rs`), `cdem reproduce`
//! ([`crate::harness::reproduce`]) and the study ([`crate::harness::study`])
//! take them from here.
//!
//! Provenance: every [`Reference`] names the file under `references/` that
//! gives the value and where it comes from (a paper, a verification manual, a
//! derivation); `references/README.md` lists which item of this registry each
//! file backs. A value changed here must be changed there too.
//!
//! Contents:
//! - the cases: [`Case`] constants ([`COLUMN`], [`SLOPE`], [`SLOPE_SLIP`], ...),
//!   all in [`CASES`], and the stiff and extreme suite ([`extreme_cases`]);
//! - the analytic solutions as functions: the confined column
//!   ([`column_uz`], [`column_szz`], ...), the layered column
//!   ([`layered_top_uz`]), the block on a plane ([`sliding_block_acceleration`]);
//! - the published values ([`PAPER_MAX_ABS_UZ`], [`ACADS_SLIDE_BISHOP`], ...);
//! - the paper slope's slip circle ([`SLIP_CIRCLE`]) and its strength;
//! - the tolerances that a test and `cdem reproduce` both apply;
//! - the committed meshes of the paper slope by refinement ([`SLOPE_MESHES`]),
//!   which the performance figures ([`crate::harness::perf`]) and the benches
//!   use; perf's LEM cases and paper slope are [`LEM_PAPER_SLOPE_EXPLICIT`],
//!   [`LEM_ACADS_1A`] and [`SLOPE`].

use std::path::Path;

use crate::analysis::slip::SlipCircle;
use crate::error::Error;
use crate::harness::report::Check;
use crate::lem::LemInput;
use crate::scene::Scene;

// ---------------------------------------------------------------------------
// Provenance: the files under references/.

/// The laterally confined column under gravity (analytic).
pub const COLUMN_MD: &str = "references/column.md";
/// The paper's published figures (Liu, Li & Liu 2014).
pub const PAPER_MD: &str = "references/paper.md";
/// Limit equilibrium: ACADS 1(a), the paper slope, pySlope.
pub const LEM_MD: &str = "references/lem.md";
/// The stiff and extreme suite (analytic, layered columns).
pub const EXTREME_MD: &str = "references/extreme.md";
/// The block on an inclined plane (analytic).
pub const SLIDING_BLOCK_MD: &str = "references/sliding-block.md";
/// The scikit-fem cross-check of the FEM reference.
pub const SKFEM_MD: &str = "references/skfem.md";
/// The scikit-fem solution itself (read by tests/fem.rs).
pub const SKFEM_JSON: &str = "references/skfem.json";
/// Strength reduction: the block on a plane (analytic) and the slopes.
pub const SRM_MD: &str = "references/srm.md";
/// The Wulong landslide: the paper's and ours.
pub const WULONG_MD: &str = "references/wulong.md";
/// The source of a row whose reference is the implicit FEM on the same mesh.
pub const FEM_SAME_MESH: &str = "cdem fem";
/// The same, naming the cross-check of that FEM (the tests' rows).
pub const FEM_SAME_MESH_CROSS_CHECKED: &str = "cdem fem (references/skfem.md)";

// ---------------------------------------------------------------------------
// Cases.

/// A verification case: its input file and what is checked on it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Case {
    /// Short name.
    pub name: &'static str,
    /// The input, relative to the repository root: a scene, or for the LEM
    /// cases an LEM input.
    pub input: &'static str,
    /// What it checks, and where.
    pub checks: &'static str,
    /// The file under references/ with its reference values.
    pub source: &'static str,
}

/// The committed meshes of the paper slope, coarse to fine: `refine` of
/// slope.geo (1000 refine^2 hexahedra) and the path from the repository root
/// (the refine-1 mesh is [`SLOPE`]'s).
pub const SLOPE_MESHES: [(f64, &str); 4] = [
    (0.5, "verification/study/slope-h4.msh"),
    (1.0, "verification/cases/slope/slope.msh"),
    (2.0, "verification/study/slope-h1.msh"),
    (4.0, "verification/study/slope-h05.msh"),
];

impl Case {
    /// The input file.
    pub fn path(&self) -> &'static Path {
        Path::new(self.input)
    }
    /// The scene.
    pub fn scene(&self) -> Result<Scene, Error> {
        Scene::load(self.path())
    }
    /// The scene with phase 1 only (its `[failure]` dropped): the elastic
    /// state, e.g. for eq. 21 on the slip circle of [`SLOPE_SLIP`].
    pub fn elastic_scene(&self) -> Result<Scene, Error> {
        let mut scene = self.scene()?;
        scene.failure = None;
        Ok(scene)
    }
    /// The LEM input (for the LEM cases).
    pub fn lem_input(&self) -> Result<LemInput, Error> {
        LemInput::load(self.path())
    }
}

/// The 10-layer column with springs on every interface (E_j/L = 1e11 Pa/m).
pub const COLUMN: Case = Case {
    name: "column",
    input: "verification/cases/column/column.toml",
    checks: "top u_z, base and element sigma_zz against the analytic column within 1 %; the spring compliance \
             error falling as 1/E_j (tests/column.rs); the base point of the study (tests/study_point.rs); \
             `cdem reproduce` step 2",
    source: COLUMN_MD,
};

/// The same column with merged interfaces (no springs).
pub const COLUMN_MERGED: Case = Case {
    name: "column, merged",
    input: "verification/cases/column/column-merged.toml",
    checks: "top u_z against the analytic column to solver tolerance (tests/column.rs); the FEM reference \
             nodally exact (tests/fem.rs); `cdem reproduce` step 2",
    source: COLUMN_MD,
};

/// The paper's elastic slope (Figs. 5-7), perturbed, springs on every interface.
pub const SLOPE: Case = Case {
    name: "paper slope",
    input: "verification/cases/slope/slope.toml",
    checks: "CDEM against the FEM on the same perturbed mesh (max |u_z|, min sigma_zz, relative L2 error of u), \
             the paper's and ANSYS values reported (tests/slope_elastic.rs; `cdem reproduce` step 3, Figs. 6-7); \
             the slope of the study",
    source: PAPER_MD,
};

/// The paper slope with the LEM critical circle as the conforming interface "slip".
pub const SLOPE_SLIP: Case = Case {
    name: "paper slope, slip circle",
    input: "verification/cases/slope-slip/slope-slip.toml",
    checks: "eq. 21 and K_i on the slip circle against the LEM (tests/slip_surface.rs; `cdem reproduce` step 5, \
             Fig. 9); progressive failure on it (tests/progressive_slope.rs; step 6, Fig. 10)",
    source: LEM_MD,
};

/// The paper slope and slip circle with a stronger slip surface (phi = 35 deg):
/// a stable slope with a weak interface.
pub const SLOPE_SLIP_STABLE: Case = Case {
    name: "paper slope, slip circle, phi 35 deg",
    input: "verification/cases/slope-slip/slope-slip-stable.toml",
    checks: "phase 2 ends in Equilibrium although springs fail (tests/progressive_slope.rs); the stable slope of \
             `cdem srm` (tests/srm.rs)",
    source: LEM_MD,
};

/// The Wulong landslide (Figs. 11-14).
pub const WULONG: Case = Case {
    name: "Wulong",
    input: "verification/cases/wulong/wulong.toml",
    checks: "progressive failure: cracks at the toe first, blocks detach, no global slide (tests/wulong.rs; \
             `cdem reproduce` step 7, Fig. 14)",
    source: WULONG_MD,
};

/// ACADS (1989) problem 1(a), an LEM input.
pub const LEM_ACADS_1A: Case = Case {
    name: "ACADS 1(a)",
    input: "verification/lem/acads-1a.toml",
    checks: "Bishop and Spencer FS against Slide and the referee (tests/lem.rs; `cdem reproduce` step 4)",
    source: LEM_MD,
};

/// The paper slope's section (read from the slope mesh), an LEM input.
pub const LEM_PAPER_SLOPE: Case = Case {
    name: "paper slope LEM",
    input: "verification/lem/paper-slope.toml",
    checks: "Bishop FS against the paper's LEM (tests/lem.rs; `cdem reproduce` step 4); the LEM FS on the slip \
             circle (tests/slip_surface.rs)",
    source: PAPER_MD,
};

/// The same section written out, an LEM input.
pub const LEM_PAPER_SLOPE_EXPLICIT: Case = Case {
    name: "paper slope LEM, explicit section",
    input: "verification/lem/paper-slope-explicit.toml",
    checks: "the same FS as the section read from the mesh (tests/lem.rs)",
    source: LEM_MD,
};

/// A block on a frictional plane, gravity tilted by theta in the test.
pub const SLIDING_BLOCK: Case = Case {
    name: "block on plane",
    input: "tests/fixtures/block-on-plane.toml",
    checks: "at rest below the friction angle, the Coulomb acceleration above it (tests/sliding_block.rs)",
    source: SLIDING_BLOCK_MD,
};

/// Strength reduction of a block on a plane, friction only (theta 30, phi 35).
pub const BLOCK_SRM_FRICTION: Case = Case {
    name: "block on plane SRM, theta 30, phi 35, c 0",
    input: "verification/cases/block-srm/block-srm-friction.toml",
    checks: "`cdem srm` FS against the analytic block on a plane within 1 % (tests/srm.rs)",
    source: SRM_MD,
};

/// Strength reduction of a block on a plane with cohesion (theta 25, phi 20, c 5 kPa, ductile).
pub const BLOCK_SRM_COHESION: Case = Case {
    name: "block on plane SRM, theta 25, phi 20, c 5 kPa",
    input: "verification/cases/block-srm/block-srm-cohesion.toml",
    checks: "`cdem srm` FS against the analytic block on a plane within 1 % (tests/srm.rs, tests/cli.rs)",
    source: SRM_MD,
};

/// Every case above (the extreme suite is [`extreme_cases`]).
pub const CASES: [Case; 12] = [
    COLUMN,
    COLUMN_MERGED,
    SLOPE,
    SLOPE_SLIP,
    SLOPE_SLIP_STABLE,
    WULONG,
    LEM_ACADS_1A,
    LEM_PAPER_SLOPE,
    LEM_PAPER_SLOPE_EXPLICIT,
    SLIDING_BLOCK,
    BLOCK_SRM_FRICTION,
    BLOCK_SRM_COHESION,
];

// ---------------------------------------------------------------------------
// Reference values.

/// A reference value and the file that states where it comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    pub value: f64,
    /// The file under references/ that gives it (and its origin).
    pub source: &'static str,
    /// What it is, and where that file says it comes from.
    pub what: &'static str,
}

impl Reference {
    /// The validation row comparing `ours` with this value; a NaN
    /// `tolerance` makes a reported-only row.
    pub fn check(&self, case: &str, quantity: &str, ours: f64, tolerance: f64, seconds: f64) -> Check {
        Check::new(case, quantity, ours, self.value, tolerance, self.source, seconds)
    }
}

/// Standard gravity (m/s^2), as in the scenes.
pub const GRAVITY: f64 = 9.81;

/// The paper's CDEM: max vertical displacement of the elastic slope (Figs. 6-7), as a magnitude.
pub const PAPER_MAX_ABS_UZ: Reference = Reference {
    value: 4.18e-2,
    source: PAPER_MD,
    what: "max |u_z| (m) of the elastic slope, the paper's program (Liu, Li & Liu 2014, Figs. 6-7)",
};
/// ANSYS in the paper: max vertical displacement of the elastic slope, as a magnitude.
pub const ANSYS_MAX_ABS_UZ: Reference = Reference {
    value: 4.16e-2,
    source: PAPER_MD,
    what: "max |u_z| (m) of the elastic slope, ANSYS (Liu, Li & Liu 2014, Figs. 6-7)",
};
/// The paper's CDEM: max vertical (compressive) stress of the elastic slope (Figs. 6-7).
pub const PAPER_MIN_SZZ: Reference = Reference {
    value: -7.89e5,
    source: PAPER_MD,
    what: "min sigma_zz (Pa) of the elastic slope, the paper's program (Liu, Li & Liu 2014, Figs. 6-7)",
};
/// ANSYS in the paper: max vertical (compressive) stress of the elastic slope.
pub const ANSYS_MIN_SZZ: Reference = Reference {
    value: -7.81e5,
    source: PAPER_MD,
    what: "min sigma_zz (Pa) of the elastic slope, ANSYS (Liu, Li & Liu 2014, Figs. 6-7)",
};
/// The paper's LEM safety factor of its slope (c = 16 kPa, phi = 18 deg).
pub const PAPER_LEM_FS: Reference = Reference {
    value: 1.084,
    source: PAPER_MD,
    what: "LEM safety factor of the paper slope (Liu, Li & Liu 2014, their LEM software)",
};
/// The paper's eq. 21 on the same surface, from its CDEM.
pub const PAPER_EQ21_K: Reference = Reference {
    value: 1.086,
    source: PAPER_MD,
    what: "eq. 21 safety factor on the LEM surface from the paper's CDEM (Liu, Li & Liu 2014)",
};
/// ACADS 1(a): the referee's safety factor.
pub const ACADS_REFEREE: Reference =
    Reference { value: 1.00, source: LEM_MD, what: "ACADS (1989) problem 1(a), referee FS" };
/// ACADS 1(a): Slide's Bishop simplified.
pub const ACADS_SLIDE_BISHOP: Reference = Reference {
    value: 0.987,
    source: LEM_MD,
    what: "ACADS 1(a), Bishop simplified in Rocscience Slide (verification manual, problem 1)",
};
/// ACADS 1(a): Slide's Spencer.
pub const ACADS_SLIDE_SPENCER: Reference = Reference {
    value: 0.986,
    source: LEM_MD,
    what: "ACADS 1(a), Spencer in Rocscience Slide (verification manual, problem 1)",
};

// ---------------------------------------------------------------------------
// Tolerances a test and `cdem reproduce` both apply.

/// Column with springs against the analytic column: 1 % (references/column.md).
pub const TOL_COLUMN_SPRINGS: f64 = 0.01;
/// Column with merged interfaces against the analytic column: solver tolerance.
pub const TOL_COLUMN_MERGED: f64 = 1e-5;
/// CDEM against the FEM on the same mesh: 1 %.
pub const TOL_CDEM_VS_FEM: f64 = 0.01;
/// ACADS 1(a) against Slide and the referee: 1.5 % (references/lem.md).
pub const TOL_ACADS: f64 = 0.015;
/// The paper slope's Bishop FS against the paper's LEM: 0.01 absolute
/// (references/lem.md); relative in a validation row: `0.01 / 1.084`.
pub const TOL_PAPER_LEM_FS_ABSOLUTE: f64 = 0.01;
/// Eq. 21 from the CDEM springs against the LEM on the slip circle: 2 %.
pub const TOL_EQ21_VS_LEM: f64 = 0.02;

// ---------------------------------------------------------------------------
// The laterally confined column (references/column.md).

/// A laterally confined elastic column under gravity: base fixed, sides on
/// rollers, so the only strain is eps_zz.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConfinedColumn {
    /// H (m).
    pub height: f64,
    /// rho (kg/m^3).
    pub density: f64,
    /// g (m/s^2).
    pub gravity: f64,
    /// E (Pa).
    pub young: f64,
    /// nu.
    pub poisson: f64,
    /// Cross-section (m^2): 4 m x 4 m.
    pub area: f64,
}

/// The column of `verification/cases/column/` (references/column.md).
pub const CONFINED_COLUMN: ConfinedColumn =
    ConfinedColumn { height: 40.0, density: 2100.0, gravity: GRAVITY, young: 3.0e8, poisson: 0.3, area: 16.0 };

/// The oedometric (constrained) modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
pub fn oedometric_modulus(e: f64, nu: f64) -> f64 {
    e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))
}

/// M of the column (Pa).
pub fn column_m() -> f64 {
    oedometric_modulus(CONFINED_COLUMN.young, CONFINED_COLUMN.poisson)
}

/// u_z(z) = -rho g (H z - z^2 / 2) / M (m).
pub fn column_uz(z: f64) -> f64 {
    let c = CONFINED_COLUMN;
    -c.density * c.gravity * (c.height * z - 0.5 * z * z) / column_m()
}

/// sigma_zz(z) = -rho g (H - z) (Pa).
pub fn column_szz(z: f64) -> f64 {
    let c = CONFINED_COLUMN;
    -c.density * c.gravity * (c.height - z)
}

/// The lateral stress ratio sigma_xx / sigma_zz = nu / (1 - nu).
pub fn column_k0() -> f64 {
    CONFINED_COLUMN.poisson / (1.0 - CONFINED_COLUMN.poisson)
}

/// The top settlement u_z(H) = -rho g H^2 / (2 M) (m).
pub fn column_top_uz() -> f64 {
    column_uz(CONFINED_COLUMN.height)
}

/// What the column cases measure: the mean u_z of the node copies at the
/// top (z = H) of a CDEM run (m).
pub fn measured_top_uz(r: &crate::drivers::RunResult) -> f64 {
    let top: Vec<usize> =
        (0..r.model.n_nodes()).filter(|&i| (r.model.x0[i][2] - CONFINED_COLUMN.height).abs() < 1e-9).collect();
    top.iter().map(|&i| r.state.u[3 * i + 2]).sum::<f64>() / top.len() as f64
}

/// Top settlement of a laterally confined column of layers `(z0, z1, rho, M)`
/// from the bottom up (references/extreme.md):
/// `u(H) = -int_0^H W(z) / M(z) dz` with `W(z)` the weight per area above z.
pub fn layered_top_uz(layers: &[(f64, f64, f64, f64)]) -> f64 {
    let g = CONFINED_COLUMN.gravity;
    let mut u = 0.0;
    for (k, &(z0, z1, rho, m)) in layers.iter().enumerate() {
        let above: f64 = layers[k + 1..].iter().map(|&(a, b, r, _)| r * g * (b - a)).sum();
        // int_z0^z1 [above + rho g (z1 - z)] dz
        u -= (above * (z1 - z0) + 0.5 * rho * g * (z1 - z0).powi(2)) / m;
    }
    u
}

/// A case of the stiff and extreme suite (`verification/extreme/<name>.toml`,
/// references/extreme.md): the analytic top u_z and its tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExtremeCase {
    pub name: &'static str,
    pub what: &'static str,
    /// Analytic top u_z (m).
    pub reference: f64,
    /// Allowed relative error of a converged run (0: exactly).
    pub tolerance: f64,
}

impl ExtremeCase {
    /// The scene file.
    pub fn scene(&self) -> Result<Scene, Error> {
        Scene::load(&Path::new("verification/extreme").join(format!("{}.toml", self.name)))
    }
}

/// The stiff and extreme suite, in the order of references/extreme.md.
pub fn extreme_cases() -> [ExtremeCase; 8] {
    // The rock of the column (E = 3e8 Pa, nu = 0.3, rho = 2100 kg/m^3), H = 40 m.
    let c = CONFINED_COLUMN;
    let (h, g, rho) = (c.height, c.gravity, c.density);
    let m = oedometric_modulus(c.young, c.poisson);
    let column = layered_top_uz(&[(0.0, h, rho, m)]);
    // Soft joints, one element wide (column-single.msh): each horizontal
    // interface (z = 4, 8, ..., 36) adds the settlement W(z_i) L / E_j in
    // series, and there is no other interface; E_j = E (K_n L/(E A) = 1).
    let e_j = c.young;
    let soft = column - (1..10).map(|i| rho * g * (h - 4.0 * i as f64)).sum::<f64>() * 1.0 / e_j;
    let case = |name, what, reference, tolerance| ExtremeCase { name, what, reference, tolerance };
    [
        case("joints-soft", "soft joints, K_n L/(E A) = 1: column + series joints", soft, 1e-5),
        case("joints-stiff", "stiff joints, K_n L/(E A) = 1e6: column (if converged)", column, 1e-3),
        case(
            "poisson-0499",
            "nu = 0.499: column with M(nu = 0.499)",
            layered_top_uz(&[(0.0, h, rho, oedometric_modulus(c.young, 0.499))]),
            1e-5,
        ),
        case("perturbation-near-limit", "perturbation 0.49: column", column, 2e-3),
        case("aspect-1-50", "aspect ratio 1:50: column", column, 1e-5),
        case(
            "contrast-modulus-1e4",
            "E contrast 1e4: layered",
            layered_top_uz(&[(0.0, 20.0, rho, m), (20.0, h, rho, 1e4 * m)]),
            1e-5,
        ),
        case(
            "contrast-density-1e3",
            "density contrast 1e3: layered",
            layered_top_uz(&[(0.0, 20.0, 2.1, m), (20.0, h, rho, m)]),
            1e-5,
        ),
        case("zero-gravity", "zero gravity: u = 0 exactly", 0.0, 0.0),
    ]
}

// ---------------------------------------------------------------------------
// The block on an inclined plane (references/sliding-block.md).

/// The contact's friction angle in tests/fixtures/block-on-plane.toml (deg).
pub const SLIDING_BLOCK_PHI_DEG: f64 = 20.0;

/// The acceleration of a cohesionless block sliding down a plane inclined at
/// theta with friction angle phi: g (sin theta - cos theta tan phi) (m/s^2).
pub fn sliding_block_acceleration(theta_deg: f64, phi_deg: f64) -> f64 {
    let (th, phi) = (theta_deg.to_radians(), phi_deg.to_radians());
    GRAVITY * (th.sin() - th.cos() * phi.tan())
}

// ---------------------------------------------------------------------------
// The paper slope's slip circle.

/// The Bishop critical circle of the paper slope (references/lem.md, "The
/// paper's slope": centre (24.006, 63.222) m, through the toe (20, 20)), the
/// interface "slip" of verification/cases/slope-slip/slope-slip.geo.
pub const SLIP_CIRCLE: SlipCircle = SlipCircle { xc: 24.006, zc: 63.222, toe: [20.0, 20.0] };

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
    let c = SLIP_CIRCLE;
    ((c.toe[0] - c.xc).powi(2) + (c.toe[1] - c.zc).powi(2)).sqrt()
}

/// [`SLIP_CIRCLE`] on the section from the toe to the crest, 101 points
/// (x, z), for the figures.
pub fn slip_arc() -> Vec<(f64, f64)> {
    let (c, r) = (SLIP_CIRCLE, slip_circle_radius());
    let crest = PAPER_SLOPE_CREST_Z;
    let a0 = (c.toe[1] - c.zc).atan2(c.toe[0] - c.xc);
    let a1 = (crest - c.zc).atan2((r * r - (crest - c.zc).powi(2)).sqrt());
    (0..=100).map(|k| a0 + (a1 - a0) * k as f64 / 100.0).map(|a| (c.xc + r * a.cos(), c.zc + r * a.sin())).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn root() -> &'static Path {
        Path::new(env!("CARGO_MANIFEST_DIR"))
    }

    #[test]
    fn every_case_input_and_every_source_exists() {
        for c in CASES {
            assert!(root().join(c.input).is_file(), "{}: no {}", c.name, c.input);
            assert!(root().join(c.source).is_file(), "{}: no {}", c.name, c.source);
        }
        for c in extreme_cases() {
            assert!(root().join(format!("verification/extreme/{}.toml", c.name)).is_file(), "{}", c.name);
        }
        for r in [
            PAPER_MAX_ABS_UZ,
            ANSYS_MAX_ABS_UZ,
            PAPER_MIN_SZZ,
            ANSYS_MIN_SZZ,
            PAPER_LEM_FS,
            PAPER_EQ21_K,
            ACADS_REFEREE,
            ACADS_SLIDE_BISHOP,
            ACADS_SLIDE_SPENCER,
        ] {
            assert!(root().join(r.source).is_file(), "{}: no {}", r.what, r.source);
        }
        for f in [EXTREME_MD, SKFEM_MD, SKFEM_JSON] {
            assert!(root().join(f).is_file(), "no {f}");
        }
    }

    #[test]
    fn the_column_values_are_those_of_column_md() {
        // references/column.md: M = 4.03846e8 Pa, u_z(H) = -4.0809e-2 m, sigma_zz(0) = -8.2404e5 Pa.
        assert!((column_m() / 4.03846e8 - 1.0).abs() < 1e-5);
        assert!((column_top_uz() / -4.0809e-2 - 1.0).abs() < 1e-4);
        assert!((column_szz(0.0) / -8.2404e5 - 1.0).abs() < 1e-5);
        assert_eq!(column_szz(CONFINED_COLUMN.height), 0.0);
        assert_eq!(layered_top_uz(&[(0.0, 40.0, 2100.0, column_m())]).to_bits(), column_top_uz().to_bits());
    }

    #[test]
    fn the_slip_arc_runs_from_the_toe_to_the_crest() {
        let arc = slip_arc();
        let (first, last) = (arc[0], arc[arc.len() - 1]);
        assert!((first.0 - 20.0).abs() < 1e-9 && (first.1 - 20.0).abs() < 1e-9, "{first:?}");
        assert!((last.1 - PAPER_SLOPE_CREST_Z).abs() < 1e-9, "{last:?}");
        // references/lem.md: r = 43.408 m.
        assert!((slip_circle_radius() - 43.408).abs() < 1e-3);
    }
}

// ---------------------------------------------------------------------------
// Strength reduction of a block on a plane (references/srm.md).

/// A block of weight `W` on a plane inclined at `theta`, contact area `A`,
/// cohesion `c` and friction angle `phi`.
#[derive(Debug, Clone, Copy)]
pub struct BlockOnPlane {
    pub theta_deg: f64,
    pub phi_deg: f64,
    /// Pa.
    pub cohesion: f64,
    /// N.
    pub weight: f64,
    /// m^2.
    pub area: f64,
}

impl BlockOnPlane {
    /// The factor of safety `(c A + W cos(theta) tan(phi)) / (W sin(theta))`.
    pub fn fs(&self) -> f64 {
        let (th, phi) = (self.theta_deg.to_radians(), self.phi_deg.to_radians());
        (self.cohesion * self.area + self.weight * th.cos() * phi.tan()) / (self.weight * th.sin())
    }
}

/// The block of the SRM cases: 1 m^3 at 2500 kg/m^3 (W = 24525 N), A = 1 m^2.
const SRM_BLOCK_WEIGHT: f64 = 2500.0 * GRAVITY;

/// [`BLOCK_SRM_FRICTION`]: FS = tan 35 / tan 30 = 1.2128.
pub const BLOCK_SRM_FRICTION_SET: BlockOnPlane =
    BlockOnPlane { theta_deg: 30.0, phi_deg: 35.0, cohesion: 0.0, weight: SRM_BLOCK_WEIGHT, area: 1.0 };
/// [`BLOCK_SRM_COHESION`]: FS = 1.2630.
pub const BLOCK_SRM_COHESION_SET: BlockOnPlane =
    BlockOnPlane { theta_deg: 25.0, phi_deg: 20.0, cohesion: 5000.0, weight: SRM_BLOCK_WEIGHT, area: 1.0 };
/// `cdem srm` on the block against the analytic FS: 1 % (the bracket is
/// 0.01 wide, so its midpoint is within 0.4 % of any FS inside it).
pub const TOL_SRM_BLOCK: f64 = 0.01;
