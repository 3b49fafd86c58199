//! The validation table: every row it must contain.
//!
//! To add a row: add one `RowSpec` to `ROWS` below (an extreme case: to
//! `extreme_cases` and `EXTREME_ROWS`), with a unique id, its kind (asserted
//! with its tolerance, reported with its goal, compared with a snapshot or the
//! paper), the file under references/ that gives the reference and the reason
//! for the tolerance, and the test that records it; then make the row in that
//! test with `reg::row("id").value(ours, reference, seconds)` (or
//! `.compared(..)`, `.skipped(..)`) and `cdem::harness::report::record`. The
//! report (`tests/zz_validation_report.rs`, `cdem reproduce`) fails while a
//! listed row is missing and while a recorded row is not listed. The spec is
//! what the report enforces: a recorded row of another kind, tolerance, goal,
//! source or (where the spec holds it, `.with_reference(value)`) reference
//! fails as a spec mismatch; a row may be skipped only if its spec says so
//! (`.may_skip(reason)`), and an asserted one never under CI=true. The files a
//! row is computed from are declared by id prefix in
//! `cdem::harness::report::inputs::DECLARED` (a new prefix needs an entry).

#[allow(unused_imports)]
use super::*;

pub(crate) const fn spec(
    id: &'static str,
    case: &'static str,
    quantity: &'static str,
    kind: SpecKind,
    source: &'static str,
    test: &'static str,
) -> RowSpec {
    RowSpec { id, case, quantity, kind, source, test, reference: None, skip: None }
}

use SpecKind::{Asserted, Bounded, Compared, Reported};

/// Why `meshes/regenerated` may be skipped (never under `CI=true`: it is asserted).
const GMSH_SKIP: &str = "gmsh is not on PATH (outside CI)";
/// Why the timed strength reductions may be skipped: 10 s to 4 min each, measured by `cdem perf`.
const SRM_PERF_SKIP: &str = "timed strength reductions, measured by cdem perf (references/performance.md)";
/// Why the timed ensembles may be skipped: about 2 min with the `cdem` binary, measured by `cdem perf`.
const ENSEMBLE_PERF_SKIP: &str = "timed ensembles, measured by cdem perf (references/performance.md)";

const COLUMN_SPRINGS_CASE: &str = "column, springs E_j/L=1e11";
const ACADS_CASE: &str = "ACADS 1(a)";
const ACADS_1C_CASE: &str = "ACADS 1(c), three soils";
const SLOPE_VS_FEM: &str = "paper slope, CDEM vs FEM";
const SLIP_CASE: &str = "paper slope, slip circle";
const PHASE2_CASE: &str = "performance: slip-surface slope, phase 2";
const SRM_BRITTLE_CASE: &str = "performance: cdem srm, slip-surface slope, brittle";
const SRM_DUCTILE_CASE: &str = "performance: cdem srm, slip-surface slope, ductile";
const ENSEMBLE_CASE: &str = "performance: ensemble of the slip-surface slope";
const SRM_PLASTIC_GL1_CASE: &str = "performance: cdem srm, Griffiths & Lane, plastic blocks, 384 hexahedra";
const SRM_PLASTIC_PAPER_CASE: &str = "performance: cdem srm, paper slope, plastic blocks and breakable interfaces";

/// Every row of the validation table but the extreme suite's (see [`rows`]).
#[rustfmt::skip]
pub const ROWS: &[RowSpec] = &[
    // The column (tests/column.rs, tests/study_point.rs).
    spec("column/springs/top-uz", COLUMN_SPRINGS_CASE, "top u_z (m) vs the joints in series", Asserted(TOL_COLUMN_SERIES_JOINTS), COLUMN_MD, "tests/column.rs"),
    spec("column/springs/base-szz", COLUMN_SPRINGS_CASE, "base sigma_zz from reactions (Pa)", Asserted(TOL_COLUMN_REACTION), COLUMN_MD, "tests/column.rs"),
    spec("column/springs/element-szz", COLUMN_SPRINGS_CASE, "max element sigma_zz error vs centroid value", Asserted(TOL_COLUMN_STRESS), COLUMN_MD, "tests/column.rs").with_reference(0.0),
    spec("column/merged/top-uz", "column, merged", "top u_z (m)", Asserted(TOL_COLUMN_MERGED), COLUMN_MD, "tests/column.rs"),
    spec("study/column/cdem-l2", "study: column 10 layers", "CDEM relative L2 error of u", Asserted(TOL_COLUMN_SPRINGS), COLUMN_MD, "tests/study_point.rs").with_reference(0.0),
    spec("study/column/fem-l2", "study: column 10 layers", "FEM relative L2 error of u", Asserted(TOL_STUDY_FEM_L2), COLUMN_MD, "tests/study_point.rs").with_reference(0.0),
    // The FEM reference against scikit-fem (tests/fem.rs).
    spec("fem/skfem/column/max-abs-uz", "FEM vs scikit-fem, column", "max |u_z| (m)", Asserted(TOL_SKFEM), SKFEM_MD, "tests/fem.rs"),
    spec("fem/skfem/column/min-szz", "FEM vs scikit-fem, column", "min element sigma_zz (Pa)", Asserted(TOL_SKFEM), SKFEM_MD, "tests/fem.rs"),
    spec("fem/skfem/column/all", "FEM vs scikit-fem, column", "largest difference of all compared values", Asserted(TOL_SKFEM), SKFEM_MD, "tests/fem.rs").with_reference(0.0),
    spec("fem/skfem/slope/max-abs-uz", "FEM vs scikit-fem, slope unperturbed", "max |u_z| (m)", Asserted(TOL_SKFEM), SKFEM_MD, "tests/fem.rs"),
    spec("fem/skfem/slope/min-szz", "FEM vs scikit-fem, slope unperturbed", "min element sigma_zz (Pa)", Asserted(TOL_SKFEM), SKFEM_MD, "tests/fem.rs"),
    spec("fem/skfem/slope/all", "FEM vs scikit-fem, slope unperturbed", "largest difference of all compared values", Asserted(TOL_SKFEM_SLOPE_ALL), SKFEM_MD, "tests/fem.rs").with_reference(0.0),
    spec("fem/skfem/slope-perturbed/max-abs-uz", "FEM vs scikit-fem, slope perturbed", "max |u_z| (m)", Asserted(TOL_SKFEM), SKFEM_MD, "tests/fem.rs"),
    spec("fem/skfem/slope-perturbed/min-szz", "FEM vs scikit-fem, slope perturbed", "min element sigma_zz (Pa)", Asserted(TOL_SKFEM), SKFEM_MD, "tests/fem.rs"),
    spec("fem/skfem/slope-perturbed/all", "FEM vs scikit-fem, slope perturbed", "largest difference of all compared values", Asserted(TOL_SKFEM_PERTURBED_ALL), SKFEM_MD, "tests/fem.rs").with_reference(0.0),
    // The elastic slope (tests/slope_elastic.rs).
    spec("slope/cdem-vs-fem/max-abs-uz", SLOPE_VS_FEM, "max |u_z| (m)", Asserted(TOL_CDEM_VS_FEM), FEM_SAME_MESH_CROSS_CHECKED, "tests/slope_elastic.rs"),
    spec("slope/cdem-vs-fem/min-szz", SLOPE_VS_FEM, "min sigma_zz (Pa)", Asserted(TOL_CDEM_VS_FEM_STRESS), FEM_SAME_MESH_CROSS_CHECKED, "tests/slope_elastic.rs"),
    spec("slope/cdem-vs-fem/l2-u", SLOPE_VS_FEM, "relative L2 error of u", Asserted(TOL_CDEM_VS_FEM), FEM_SAME_MESH_CROSS_CHECKED, "tests/slope_elastic.rs").with_reference(0.0),
    spec("slope/cdem-vs-paper/max-abs-uz", "paper slope, CDEM vs paper", "max |u_z| (m)", Reported(Goal::Within(GOAL_VS_PAPER)), PAPER_MD, "tests/slope_elastic.rs").with_reference(PAPER_MAX_ABS_UZ.value),
    spec("slope/cdem-vs-paper/min-szz", "paper slope, CDEM vs paper", "min sigma_zz (Pa)", Reported(Goal::Within(GOAL_VS_PAPER)), PAPER_MD, "tests/slope_elastic.rs").with_reference(PAPER_MIN_SZZ.value),
    spec("slope/fem-vs-ansys/max-abs-uz", "paper slope, FEM vs ANSYS (paper)", "max |u_z| (m)", Reported(Goal::Within(GOAL_VS_PAPER)), PAPER_MD, "tests/slope_elastic.rs").with_reference(ANSYS_MAX_ABS_UZ.value),
    spec("slope/fem-vs-ansys/min-szz", "paper slope, FEM vs ANSYS (paper)", "min sigma_zz (Pa)", Reported(Goal::Within(GOAL_VS_PAPER)), PAPER_MD, "tests/slope_elastic.rs").with_reference(ANSYS_MIN_SZZ.value),
    // Limit equilibrium (tests/lem.rs).
    spec("lem/acads-1c/bishop-vs-slide", ACADS_1C_CASE, "Bishop FS (search, 50 slices) vs Slide", Asserted(TOL_ACADS), LEM_MD, "tests/lem.rs").with_reference(ACADS_1C_SLIDE_BISHOP.value),
    spec("lem/acads-1c/spencer-vs-slide", ACADS_1C_CASE, "Spencer FS (search, 50 slices) vs Slide", Asserted(TOL_ACADS), LEM_MD, "tests/lem.rs").with_reference(ACADS_1C_SLIDE_SPENCER.value),
    spec("lem/acads-1c/bishop-vs-referee", ACADS_1C_CASE, "Bishop FS (search, 50 slices) vs the ACADS referee", Reported(Goal::Within(TOL_ACADS)), LEM_MD, "tests/lem.rs").with_reference(ACADS_1C_REFEREE.value),
    spec("lem/acads-1c/slices-50-vs-400", ACADS_1C_CASE, "Bishop FS of the search with 50 slices vs 400 (consistency: our own code; slice ends at the layers)", Asserted(TOL_LEM_SLICES), LEM_MD, "tests/lem.rs"),
    spec("lem/acads/bishop-vs-slide", ACADS_CASE, "Bishop FS vs Slide", Asserted(TOL_ACADS), LEM_MD, "tests/lem.rs").with_reference(ACADS_SLIDE_BISHOP.value),
    spec("lem/acads/bishop-vs-referee", ACADS_CASE, "Bishop FS vs referee", Asserted(TOL_ACADS), LEM_MD, "tests/lem.rs").with_reference(ACADS_REFEREE.value),
    spec("lem/acads/spencer-vs-slide", ACADS_CASE, "Spencer FS vs Slide", Asserted(TOL_ACADS), LEM_MD, "tests/lem.rs").with_reference(ACADS_SLIDE_SPENCER.value),
    spec("lem/acads/spencer-vs-referee", ACADS_CASE, "Spencer FS vs referee (published band 1.5 %)", Reported(Goal::Within(TOL_ACADS)), LEM_MD, "tests/lem.rs").with_reference(ACADS_REFEREE.value),
    spec("lem/acads/pyslope", ACADS_CASE, "Bishop FS on our circle vs pySlope 1.4.0", Asserted(TOL_PYSLOPE_SAME_CIRCLE), PYSLOPE_JSON, "tests/lem.rs"),
    spec("lem/paper/bishop", "paper slope LEM", "Bishop FS vs the paper's LEM (0.01 absolute)", Asserted(TOL_PAPER_LEM_FS_ABSOLUTE / 1.084), PAPER_MD, "tests/lem.rs").with_reference(PAPER_LEM_FS.value),
    spec("lem/paper/pyslope", "paper slope LEM", "Bishop FS on our circle vs pySlope 1.4.0", Asserted(TOL_PYSLOPE_SAME_CIRCLE), PYSLOPE_JSON, "tests/lem.rs"),
    spec("lem/taylor-60", "Taylor 60 deg, base at toe level", "Bishop FS", Asserted(TOL_TAYLOR), LEM_MD, "tests/lem.rs"),
    spec("lem/taylor-75", "Taylor 75 deg, base at toe level", "Bishop FS", Asserted(TOL_TAYLOR), LEM_MD, "tests/lem.rs"),
    spec("lem/taylor-90", "Taylor 90 deg, base at toe level", "Bishop FS", Asserted(TOL_TAYLOR), LEM_MD, "tests/lem.rs"),
    // Eq. 21-22 on the slip circle (tests/slip_surface.rs).
    spec("slip/eq21-springs-vs-lem", SLIP_CASE, "eq. 21 K from CDEM springs vs LEM Bishop", Asserted(TOL_EQ21_VS_LEM), LEM_MD, "tests/slip_surface.rs"),
    spec("slip/eq21-cdem-vs-fem", SLIP_CASE, "eq. 21 K from CDEM stresses vs FEM stresses", Asserted(TOL_EQ21_CDEM_VS_FEM), LEM_MD, "tests/slip_surface.rs"),
    spec("slip/eq21-fem-vs-lem", SLIP_CASE, "eq. 21 K from FEM stresses vs LEM Bishop", Reported(Goal::Within(TOL_EQ21_VS_LEM)), LEM_MD, "tests/slip_surface.rs"),
    spec("slip/eq21-springs-vs-paper", SLIP_CASE, "eq. 21 K from CDEM springs vs the paper's 1.086", Reported(Goal::Within(TOL_EQ21_VS_LEM)), PAPER_MD, "tests/slip_surface.rs").with_reference(PAPER_EQ21_K.value),
    spec("slip/lem-vs-paper", SLIP_CASE, "LEM Bishop on the circle vs the paper's LEM (0.01 absolute)", Asserted(TOL_PAPER_LEM_FS_ABSOLUTE / 1.084), PAPER_MD, "tests/slip_surface.rs").with_reference(PAPER_LEM_FS.value),
    spec("slip/ki-segments-snapshot", SLIP_CASE, "K_i sign segments (springs) vs snapshot", Compared(true), PAPER_MD, "tests/slip_surface.rs"),
    spec("slip/ki-signs-vs-paper", SLIP_CASE, "K_i sign segments vs the paper's Fig. 9", Compared(false), PAPER_MD, "tests/slip_surface.rs"),
    // Progressive failure (tests/progressive_slope.rs, tests/wulong.rs).
    spec("slope-failure/snapshot", "paper slope, progressive failure", "failure sequence vs snapshot", Compared(true), PAPER_MD, "tests/progressive_slope.rs"),
    spec("slope-failure/order-vs-paper", "paper slope, progressive failure", "failure starts in the K_i < 1 zones (most first-step failures there, no K_i >= 1 zone half failed then), every zone fails, then the mass slides (paper Fig. 10)", Compared(true), PAPER_MD, "tests/progressive_slope.rs"),
    spec("slope-failure/first-failure-order", "paper slope, progressive failure", "zones by first failure: every K_i < 1 zone before every K_i >= 1 zone (paper Fig. 10)", Compared(false), PAPER_MD, "tests/progressive_slope.rs"),
    spec("slope-failure/full-failure-order", "paper slope, progressive failure", "zones by full failure: every K_i < 1 zone before every K_i >= 1 zone, then the slide (paper Fig. 10)", Compared(false), PAPER_MD, "tests/progressive_slope.rs"),
    spec("wulong/snapshot", "Wulong", "failure sequence vs snapshot", Compared(true), WULONG_MD, "tests/wulong.rs"),
    spec("wulong/toe-first", "Wulong", "cracks open at the toe first, later ones higher (observed 2000-2001)", Compared(true), WULONG_MD, "tests/wulong.rs"),
    spec("wulong/no-slide", "Wulong", "no global slide without water", Compared(true), WULONG_MD, "tests/wulong.rs"),
    spec("wulong/wet-slides", "Wulong after rain", "slides with the water table 1 m below the ground", Compared(true), WATER_MD, "tests/water.rs"),
    spec("wulong/wet-level", "Wulong after rain", "the water table's rise at which it first slides (bisection to 1 m)", Compared(false), WATER_MD, "tests/water.rs"),
    // The sliding block (tests/sliding_block.rs).
    spec("block/at-rest-15", "block on plane, theta 15, phi 20", "displacement in 0.5 s (m)", Asserted(TOL_BLOCK_AT_REST), SLIDING_BLOCK_MD, "tests/sliding_block.rs").with_reference(0.0),
    spec("block/acceleration-30", "block on plane, theta 30, phi 20", "acceleration (m/s^2)", Asserted(TOL_SLIDING_BLOCK), SLIDING_BLOCK_MD, "tests/sliding_block.rs"),
    // Strength reduction on the block on a plane (tests/srm.rs).
    spec("srm/block-friction", "SRM block on plane, theta 30, phi 35, c 0", "FS (strength reduction)", Asserted(TOL_SRM_BLOCK), SRM_MD, "tests/srm.rs"),
    spec("srm/block-cohesion", "SRM block on plane, theta 25, phi 20, c 5 kPa", "FS (strength reduction)", Asserted(TOL_SRM_BLOCK), SRM_MD, "tests/srm.rs"),
    // The plastic blocks' Mohr-Coulomb limit (tests/plasticity.rs).
    spec("plastic/element-limit", "one plastic hexahedron, plane-strain compression, c 100 kPa, phi 30, sigma_3 0 / 100 kPa / 1 MPa", "axial stress at the limit vs sigma_3 N_phi + 2 c sqrt(N_phi) (largest error)", Asserted(TOL_PLASTIC_ELEMENT), PLASTIC_MD, "tests/plasticity.rs").with_reference(0.0),
    spec("plastic/column-compression", "plastic column 1 x 1 x 4 m (8 hexahedra), free sides, c 100 kPa, phi 30, T 50 kPa, top pushed down at a constant rate", "plateau of the axial stress (Pa) vs the uniaxial strength 2 c sqrt(N_phi)", Asserted(TOL_PLASTIC_COLUMN_COMPRESSION), PLASTIC_MD, "tests/plasticity.rs"),
    spec("plastic/column-tension", "plastic column 1 x 1 x 4 m (8 hexahedra), free sides, c 100 kPa, phi 30, T 50 kPa, top pulled up at a constant rate", "plateau of the axial stress (Pa) vs the tension cut-off T", Asserted(TOL_PLASTIC_COLUMN_TENSION), PLASTIC_MD, "tests/plasticity.rs"),
    spec("plastic/prandtl", "Prandtl's rough strip footing, half model, 2310 hexahedra graded to 0.06 m at the footing edge, Tresca c 0.1 MPa, pushed 60 mm at a constant rate and held", "footing pressure after the hold (Pa) vs (2 + pi) c", Asserted(GOAL_PRANDTL), PLASTIC_MD, "tests/plasticity.rs"),
    spec("plastic/gl1-hex-srm", "Griffiths & Lane 1999 ex. 1, plastic blocks, 384 structured hexahedra", "FS (strength reduction) vs Bishop & Morgenstern's chart", Bounded(0.016, FS_SAFE_SIDE), PLASTIC_MD, "tests/plasticity.rs"),
    spec("plastic/gl1-prism-srm", "Griffiths & Lane 1999 ex. 1, plastic blocks, 277 unstructured prisms", "FS (strength reduction) vs Bishop & Morgenstern's chart", Bounded(0.031, FS_SAFE_SIDE), PLASTIC_MD, "tests/plasticity.rs"),
    spec("plastic/gl1-tet-srm", "Griffiths & Lane 1999 ex. 1, plastic blocks, 999 unstructured tetrahedra", "FS (strength reduction) vs Bishop & Morgenstern's chart", Bounded(0.045, FS_SAFE_SIDE), PLASTIC_MD, "tests/plasticity.rs"),
    spec("plastic/paper-slope-srm", "paper slope, plastic blocks and every interface breakable at the rock mass strength, 1000 hexahedra", "FS (strength reduction) vs Liu, Li & Liu's LEM", Bounded(0.013, FS_SAFE_SIDE), PLASTIC_MD, "tests/plasticity.rs").with_reference(PAPER_LEM_FS.value),
    spec("plastic/gl1-mesh-spread", "Griffiths & Lane 1999 ex. 1, plastic blocks, hexahedra, prisms and tetrahedra", "(max - min) / min of the three shapes' FS (issue 24 item 4: 3 %)", Asserted(GOAL_MESH_SPREAD), PLASTIC_MD, "tests/plasticity.rs").with_reference(0.0),
    // The other five published slopes of issue 24 item 4 on three shapes (PUBLISHED_SLOPES):
    // computed by `cargo test` (tests/plastic_slopes.rs) and by `cdem reproduce`, whose
    // `--skip-published-slopes` alone may skip them (never under CI=true).
    spec("plastic/slopes/at/hex-srm", "Arai & Tagyo 1985 ex. 1, plastic blocks, hexahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.037, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(AT_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/at/prism-srm", "Arai & Tagyo 1985 ex. 1, plastic blocks, prisms", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.030, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(AT_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/at/tet-srm", "Arai & Tagyo 1985 ex. 1, plastic blocks, tetrahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.030, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(AT_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/at/mesh-spread", "Arai & Tagyo 1985 ex. 1, plastic blocks, hexahedra, prisms and tetrahedra", "(max - min) / min of the three shapes' FS (issue 24 item 4: at most 3 %)", Asserted(GOAL_MESH_SPREAD), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(0.0).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/yu/hex-srm", "Yamagami & Ueta 1988, plastic blocks, hexahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.040, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(YU_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/yu/prism-srm", "Yamagami & Ueta 1988, plastic blocks, prisms", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.018, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(YU_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/yu/tet-srm", "Yamagami & Ueta 1988, plastic blocks, tetrahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.025, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(YU_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/yu/mesh-spread", "Yamagami & Ueta 1988, plastic blocks, hexahedra, prisms and tetrahedra", "(max - min) / min of the three shapes' FS (issue 24 item 4: at most 3 %)", Asserted(GOAL_MESH_SPREAD), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(0.0).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c63/hex-srm", "Cheng et al. 2007, RS2 #63, plastic blocks, hexahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.016, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(C63_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c63/prism-srm", "Cheng et al. 2007, RS2 #63, plastic blocks, prisms", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.016, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(C63_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c63/tet-srm", "Cheng et al. 2007, RS2 #63, plastic blocks, tetrahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.023, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(C63_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c63/mesh-spread", "Cheng et al. 2007, RS2 #63, plastic blocks, hexahedra, prisms and tetrahedra", "(max - min) / min of the three shapes' FS (issue 24 item 4: at most 3 %)", Asserted(GOAL_MESH_SPREAD), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(0.0).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c61/hex-srm", "Cheng et al. 2007, RS2 #61 case 1, plastic blocks, hexahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.008, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(C61_RS2_FS.value).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c61/prism-srm", "Cheng et al. 2007, RS2 #61 case 1, plastic blocks, prisms", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.008, 0.035), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(C61_RS2_FS.value).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c61/tet-srm", "Cheng et al. 2007, RS2 #61 case 1, plastic blocks, tetrahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.008, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(C61_RS2_FS.value).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/c61/mesh-spread", "Cheng et al. 2007, RS2 #61 case 1, plastic blocks, hexahedra, prisms and tetrahedra", "(max - min) / min of the three shapes' FS (issue 24 item 4: at most 3 %)", Asserted(GOAL_MESH_SPREAD), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(0.0).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/acads/hex-srm", "ACADS 1(a), plastic blocks, hexahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.008, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(ACADS_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/acads/prism-srm", "ACADS 1(a), plastic blocks, prisms", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.008, 0.033), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(ACADS_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/acads/tet-srm", "ACADS 1(a), plastic blocks, tetrahedra", "FS (strength reduction) vs the published FE strength reduction", Bounded(0.008, FS_SAFE_SIDE), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(ACADS_FE_FS).may_skip(SLOPES_SKIP),
    spec("plastic/slopes/acads/mesh-spread", "ACADS 1(a), plastic blocks, hexahedra, prisms and tetrahedra", "(max - min) / min of the three shapes' FS (issue 24 item 4: at most 3 %)", Asserted(GOAL_MESH_SPREAD), PLASTIC_MD, "tests/plastic_slopes.rs").with_reference(0.0).may_skip(SLOPES_SKIP),
    // Joint sets: the rock-slope mechanisms against their closed forms (tests/joints.rs).
    spec("joints/plane-srm", "plane failure, dry tension crack (Hoek & Bray)", "FS (strength reduction) vs closed form", Asserted(TOL_JOINTS_SRM), JOINTS_MD, "tests/joints.rs"),
    spec("joints/wedge-srm", "symmetric wedge, 3D (Hoek & Bray wedge factor)", "FS (strength reduction) vs closed form", Asserted(TOL_JOINTS_SRM), JOINTS_MD, "tests/joints.rs"),
    spec("joints/wedge-general-srm", "general wedge with cohesion, 3D (vector solution)", "FS (strength reduction) vs closed form", Asserted(TOL_JOINTS_WEDGE_GENERAL), JOINTS_MD, "tests/joints.rs"),
    spec("joints/toppling-srm", "block toppling, 16 blocks (Goodman & Bray 1976)", "FS (strength reduction) vs the Goodman-Bray recursion", Asserted(TOL_JOINTS_TOPPLING), JOINTS_MD, "tests/joints.rs"),
    // Eq. 21 on any circle, `[analysis]` (tests/surface_analysis.rs).
    spec("analysis/column/cdem-vs-analytic", "column, circle (-1.5, 26) r 5", "eq. 21 K from CDEM element stresses vs closed form", Asserted(TOL_EQ21_ANALYTIC), ANALYSIS_MD, "tests/surface_analysis.rs").with_reference(COLUMN_CIRCLE_K.value),
    spec("analysis/column/fem-vs-analytic", "column, circle (-1.5, 26) r 5", "eq. 21 K from FEM cell stresses vs closed form", Asserted(TOL_EQ21_ANALYTIC), ANALYSIS_MD, "tests/surface_analysis.rs").with_reference(COLUMN_CIRCLE_K.value),
    spec("analysis/slope/cdem-vs-fem", "paper slope, LEM critical circle, no conforming interface", "eq. 21 K from CDEM vs FEM stresses", Asserted(TOL_EQ21_CDEM_VS_FEM), ANALYSIS_MD, "tests/surface_analysis.rs"),
    spec("analysis/slope/cdem-vs-lem", "paper slope, LEM critical circle, no conforming interface", "eq. 21 K from CDEM stresses vs LEM Bishop", Reported(Goal::Within(TOL_EQ21_VS_LEM)), ANALYSIS_MD, "tests/surface_analysis.rs"),
    // Pore water against Terzaghi and the closed forms (tests/water.rs).
    spec("water/column-effective", "confined column, springs, water table at the top", "mean spring normal stress, mid-height interface, vs -(gamma - gamma_w)(H - z)", Asserted(TOL_WATER_COLUMN), WATER_MD, "tests/water.rs"),
    spec("water/column-base", "confined column, springs, water table at the top", "base reaction / area vs (gamma - gamma_w) H", Asserted(TOL_WATER_COLUMN), WATER_MD, "tests/water.rs"),
    spec("water/column-total", "confined column, springs, water table at the top", "element sigma_zz of the largest error vs -gamma (H - z) (total)", Asserted(TOL_WATER_COLUMN), WATER_MD, "tests/water.rs"),
    spec("water/infinite-half-srm", "infinite slope, water table parallel, m = 0.5", "FS (strength reduction) vs closed form", Asserted(TOL_WATER_SRM), WATER_MD, "tests/water.rs"),
    spec("water/infinite-full-srm", "infinite slope, water table parallel, m = 1", "FS (strength reduction) vs closed form", Asserted(TOL_WATER_SRM), WATER_MD, "tests/water.rs"),
    spec("water/plane-half-srm", "plane failure, tension crack half full (Hoek & Bray)", "FS (strength reduction) vs closed form", Asserted(TOL_WATER_SRM), WATER_MD, "tests/water.rs"),
    spec("water/plane-full-srm", "plane failure, tension crack full (Hoek & Bray)", "FS (strength reduction) vs closed form", Asserted(TOL_WATER_SRM), WATER_MD, "tests/water.rs"),
    spec("water/plane-crack-srm", "plane failure, crack full, plane drained (Hoek & Bray, U = 0)", "FS (strength reduction) vs closed form", Asserted(TOL_WATER_SRM), WATER_MD, "tests/water.rs"),
    // Ensembles against an exactly normal FS (tests/ensemble.rs).
    spec("ensemble/segment/mean", "ensemble: cohesive segment, c normal, 4000 members", "mean FS vs exact 1.2", Asserted(TOL_ENSEMBLE_MEAN), ENSEMBLE_MD, "tests/ensemble.rs"),
    spec("ensemble/segment/pf", "ensemble: cohesive segment, c normal, 4000 members", "P(FS < 1) vs exact Phi(-4/3)", Asserted(TOL_ENSEMBLE_PF), ENSEMBLE_MD, "tests/ensemble.rs"),
    // The committed meshes (tests/gmsh_regen.rs).
    spec("meshes/regenerated", "committed meshes", "equal to what gmsh makes of their .geo", Compared(true), GEO_FILES, "tests/gmsh_regen.rs").may_skip(GMSH_SKIP),
    // Performance, reported against the goals (tests/performance.rs).
    spec("perf/bandwidth", "performance: paper slope step", "bandwidth / stream triad (goal >= 0.5)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/element-bytes", "performance: paper slope element pass", "bytes per element-step (goal <= 0.6 x 4992 B of the full K_e)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/plastic-over-condensed", "performance: paper slope element pass, plastic blocks", "plastic / condensed element pass time, every tetrahedron elastic, behind the elastic screen (goal <= 2)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/avx2-speedup", "performance: paper slope step, plastic blocks", "baseline (SSE2) / AVX2 kernels, a phase-2 step with plastic blocks, 300 steps from the elastic state in alternating batches, the same bits (goal >= 1)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/dr-over-fem", "performance: paper slope", "DR to 1e-5 / FEM solve time (goal <= 3)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/pcg-over-fem", "performance: paper slope", "PCG to 1e-5 / FEM solve time (goal <= 3)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/lem/paper_slope", "performance: LEM grid, paper_slope", "pySlope / ours time (goal >= 300)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/lem/acads_1a", "performance: LEM grid, acads_1a", "pySlope / ours time (goal >= 300)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/laws/bb-over-coulomb-springs", "performance: paper slope springs, failure phase", "Barton-Bandis / Coulomb spring pass time, one thread, alternating batches (goal <= 1.2)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/checkpoint/srm-write", "performance: cdem srm checkpoint, Griffiths & Lane hexahedra, plastic blocks", "one checkpoint write (encode, fsync, rename) / the default --checkpoint-every 300 s (goal <= 0.02)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    // Phase 2 and strength reduction on the slip-surface slope (tests/performance.rs; the SRM rows
    // are measured by `cdem perf` only, skipped in the tests and in `cdem reproduce`).
    spec("perf/phase2/block-steps", PHASE2_CASE, "phase-2 steps to a decision, node-block masses (goal <= 5,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/phase2/lumped-steps", PHASE2_CASE, "phase-2 steps to a decision, lumped masses, same run (paper-era baseline 58,580)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/phase2/lumped-over-block", PHASE2_CASE, "phase-2 steps, lumped / node-block masses, same run (goal >= 1)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs"),
    spec("perf/srm/brittle/wall", SRM_BRITTLE_CASE, "cdem srm wall time (s) (goal <= 60)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/brittle/trial-steps-mean", SRM_BRITTLE_CASE, "mean steps per trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/brittle/trial-steps-max", SRM_BRITTLE_CASE, "largest steps of a trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/brittle/fs-change", SRM_BRITTLE_CASE, "change of FS, trials warm-started against from the elastic state (goal <= the bracket width 0.01)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/ductile/wall", SRM_DUCTILE_CASE, "cdem srm wall time (s) (goal <= 15)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/ductile/trial-steps-mean", SRM_DUCTILE_CASE, "mean steps per trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/ductile/trial-steps-max", SRM_DUCTILE_CASE, "largest steps of a trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/ductile/fs-change", SRM_DUCTILE_CASE, "change of FS, trials warm-started against from the elastic state (goal <= the bracket width 0.01)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-gl1-hex/wall", SRM_PLASTIC_GL1_CASE, "cdem srm wall time (s) (goal <= 30)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-gl1-hex/trial-steps-mean", SRM_PLASTIC_GL1_CASE, "mean steps per trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-gl1-hex/trial-steps-max", SRM_PLASTIC_GL1_CASE, "largest steps of a trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-gl1-hex/fs-change", SRM_PLASTIC_GL1_CASE, "change of FS, with the foresight rule against without it (goal <= the bracket width 0.01)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/mesh-check-gl1-hex/cost-ratio", SRM_PLASTIC_GL1_CASE, "cdem srm --mesh-check (refine 2) wall time / plain cdem srm's, same run (goal <= 4)", Reported(Goal::AtMost), SRM_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-paper-slope/wall", SRM_PLASTIC_PAPER_CASE, "cdem srm wall time (s) (goal <= 30)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-paper-slope/trial-steps-mean", SRM_PLASTIC_PAPER_CASE, "mean steps per trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-paper-slope/trial-steps-max", SRM_PLASTIC_PAPER_CASE, "largest steps of a trial (3DEC's default cap 50,000)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    spec("perf/srm/plastic-paper-slope/fs-change", SRM_PLASTIC_PAPER_CASE, "change of FS, with the foresight rule against without it (goal <= the bracket width 0.01)", Reported(Goal::AtMost), PERFORMANCE_MD, "tests/performance.rs").may_skip(SRM_PERF_SKIP),
    // Ensembles of the slip-surface slope (verification/ensemble/paper-slope-slip*.toml): measured by
    // `cdem perf` only, skipped in the tests and in `cdem reproduce`.
    spec("perf/ensemble/members-per-hour", ENSEMBLE_CASE, "members per hour, elastic + eq. 21 K + phase-2 end state, one process (against the SRM goal of 600)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs").may_skip(ENSEMBLE_PERF_SKIP),
    spec("perf/ensemble/srm-members-per-hour", ENSEMBLE_CASE, "members per hour with cdem srm per member, one process (goal >= 600)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs").may_skip(ENSEMBLE_PERF_SKIP),
    spec("perf/ensemble/two-shards-speedup", ENSEMBLE_CASE, "one process (its threads) / 2 concurrent shards + merge on the same cores, wall time (goal >= 1)", Reported(Goal::AtLeast), PERFORMANCE_MD, "tests/performance.rs").may_skip(ENSEMBLE_PERF_SKIP),
    // LEM with pore water (tests/lem_water.rs; harness::suite::lem_water; references/lem.md, "With water").
    spec("lem/water-fk-ru/ordinary-vs-fk", FK_RU_CASE, "ordinary FS on the F&K circle vs Fredlund & Krahn", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(FK_RU_ORDINARY.value),
    spec("lem/water-fk-ru/bishop-vs-fk", FK_RU_CASE, "Bishop FS on the F&K circle vs Fredlund & Krahn", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(FK_RU_BISHOP.value),
    spec("lem/water-fk-ru/spencer-vs-fk", FK_RU_CASE, "Spencer FS on the F&K circle vs Fredlund & Krahn", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(FK_RU_SPENCER.value),
    spec("lem/water-fk-ru/bishop-vs-slide", FK_RU_CASE, "Bishop FS on the F&K circle vs Slide", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(FK_RU_SLIDE_BISHOP.value),
    spec("lem/water-fk-ru/spencer-vs-slide", FK_RU_CASE, "Spencer FS on the F&K circle vs Slide", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(FK_RU_SLIDE_SPENCER.value),
    spec("lem/water-arai-tagyo/bishop-vs-slide", ARAI_TAGYO_CASE, "Bishop FS (search) vs Slide", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(ARAI_TAGYO_SLIDE_BISHOP.value),
    spec("lem/water-arai-tagyo/spencer-vs-slide", ARAI_TAGYO_CASE, "Spencer FS (search) vs Slide", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(ARAI_TAGYO_SLIDE_SPENCER.value),
    spec("lem/water-arai-tagyo/bishop-vs-paper", ARAI_TAGYO_CASE, "Bishop FS (search) vs Arai & Tagyo's own", Reported(Goal::Within(TOL_LEM_WATER)), LEM_MD, "tests/lem_water.rs").with_reference(ARAI_TAGYO_PAPER.value),
    spec("lem/water-acads-1b/bishop-vs-slide", ACADS_1B_CASE, "Bishop FS (search) vs Slide", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(ACADS_1B_SLIDE_BISHOP.value),
    spec("lem/water-acads-1b/spencer-vs-slide", ACADS_1B_CASE, "Spencer FS (search) vs Slide", Asserted(TOL_LEM_WATER), LEM_MD, "tests/lem_water.rs").with_reference(ACADS_1B_SLIDE_SPENCER.value),
    spec("lem/water-acads-1b/bishop-vs-referee", ACADS_1B_CASE, "Bishop FS (search) vs the ACADS referee", Reported(Goal::Within(TOL_LEM_WATER)), LEM_MD, "tests/lem_water.rs").with_reference(ACADS_1B_REFEREE.value),
];

/// Every row of the validation table, in its order: [`ROWS`] with the
/// extreme suite's rows after the column's.
pub fn rows() -> Vec<RowSpec> {
    let mut all: Vec<RowSpec> = ROWS[..6].to_vec();
    all.extend(extreme_cases().iter().flat_map(|c| EXTREME_SOLVERS.map(|s| c.row_spec_for(s))));
    all.extend_from_slice(&ROWS[6..]);
    all.extend_from_slice(RUNOUT_ROWS);
    all.extend_from_slice(FSERROR_ROWS);
    all.extend_from_slice(LAWS_ROWS);
    all
}

/// The spec of row `id` (a test naming an id the registry does not list is
/// a bug of that test: it panics with the id).
pub fn row(id: &str) -> RowSpec {
    rows().into_iter().find(|r| r.id == id).unwrap_or_else(|| panic!("no row {id:?} in registry::ROWS"))
}
