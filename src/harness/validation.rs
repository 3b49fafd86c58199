//! The rows of the validation table that `cargo test` and `cdem reproduce`
//! both compute, made here once from a run's results: each function takes
//! what a test (or a step of [`crate::harness::reproduce`]) has computed and
//! returns its rows, built from the registry's specs
//! ([`crate::harness::registry::row`]). The tests then assert on them; the
//! table ([`crate::harness::report::Table`]) shows them.
//!
//! Measurements that only a row needs (the column's base stress from the
//! reactions, the largest element-stress error) are here too, so that a test
//! and `cdem reproduce` measure the same thing.

use std::path::Path;

use crate::analysis::Segment;
use crate::drivers::RunResult;
use crate::error::Error;
use crate::fem::FemSolution;
use crate::harness::registry::{self as reg, row, ExtremeCase};
use crate::harness::report::Check;
use crate::lem::{evaluate_circle, Circle, LemResult};

/// The insta snapshot of the K_i sign segments (tests/slip_surface.rs).
pub const KI_SNAPSHOT: &str = "tests/snapshots/slip_surface__ki_segments_cdem_springs.snap";
/// The insta snapshot of the slope's failure sequence (tests/progressive_slope.rs).
pub const SLOPE_FAILURE_SNAPSHOT: &str = "tests/snapshots/progressive_slope__slope_failure_sequence.snap";
/// The insta snapshot of Wulong's failure sequence (tests/wulong.rs).
pub const WULONG_SNAPSHOT: &str = "tests/snapshots/wulong__wulong_failure_sequence.snap";
/// The paper's K_i signs along its slip surface from the toe (Fig. 9: ab -, bc +, cd -, de +).
pub const PAPER_KI_SIGNS: [i8; 4] = [-1, 1, -1, 1];

/// Base stress of a column run from the bottom reactions: `sum (f_int - f_ext)_z / area` (Pa).
pub fn column_base_stress(r: &RunResult) -> f64 {
    let m = &r.model;
    let mut rz = 0.0;
    for i in 0..m.n_nodes() {
        if m.x0[i][2].abs() < 1e-9 && m.fixed[3 * i + 2] {
            rz += r.state.f_int[3 * i + 2] - m.f_ext[3 * i + 2];
        }
    }
    -rz / reg::CONFINED_COLUMN.area
}

/// Largest relative error of the element sigma_zz of a column run against
/// the analytic value at the element centroid (NaN without stresses).
pub fn column_element_stress_error(r: &RunResult) -> f64 {
    let m = &r.model;
    let Some(stress) = r.stress.as_ref() else { return f64::NAN };
    (0..m.elements.len())
        .map(|e| {
            let c = m.elements.corners(e);
            let zc = c.iter().map(|&i| m.x0[i as usize][2]).sum::<f64>() / c.len() as f64;
            ((stress[e][2] - reg::column_szz(zc)) / reg::column_szz(zc)).abs()
        })
        .fold(0.0, f64::max)
}

/// The defect of a run that did not converge (its numbers are not a result).
fn convergence(r: &RunResult) -> Option<String> {
    (!r.summary.converged).then(|| {
        format!(
            "not converged: {:?} after {} steps, ratio {:.1e}",
            r.summary.end_state, r.summary.steps, r.summary.unbalanced_ratio
        )
    })
}

fn with_convergence(c: Check, r: &RunResult) -> Check {
    match convergence(r) {
        Some(d) => c.with_defect(d),
        None => c,
    }
}

/// `E_j / L` of the default joints of a run (Pa/m).
pub fn joint_stiffness(r: &RunResult) -> f64 {
    let j = &r.model.interfaces[0].props;
    j.normal_modulus / j.thickness
}

/// The column with springs: top u_z (against the joints in series with the
/// rock), base stress, element stresses.
pub fn column_springs_rows(r: &RunResult) -> Vec<Check> {
    let t = r.summary.wall_s;
    [
        row("column/springs/top-uz").value(reg::measured_top_uz(r), reg::column_top_uz_jointed(joint_stiffness(r)), t),
        row("column/springs/base-szz").value(column_base_stress(r), reg::column_szz(0.0), t),
        row("column/springs/element-szz").value(column_element_stress_error(r), 0.0, t),
    ]
    .into_iter()
    .map(|c| with_convergence(c, r))
    .collect()
}

/// The column with merged interfaces: top u_z.
pub fn column_merged_row(r: &RunResult) -> Check {
    with_convergence(
        row("column/merged/top-uz").value(reg::measured_top_uz(r), reg::column_top_uz(), r.summary.wall_s),
        r,
    )
}

/// A case of the extreme suite: top u_z against the analytic value; a run
/// that did not converge fails its row.
pub fn extreme_row(case: &ExtremeCase, r: &RunResult) -> Check {
    with_convergence(case.row_spec().value(reg::measured_top_uz(r), case.reference, r.summary.wall_s), r)
}

/// The elastic slope: CDEM against the FEM on the same perturbed mesh, and
/// both beside the paper's figures.
pub fn slope_rows(r: &RunResult, fem: &FemSolution) -> Vec<Check> {
    let (c, f) = (&r.summary, &fem.summary);
    let l2 = crate::analysis::compare::relative_l2_displacement(&r.model, &r.state.u, &fem.u);
    let (cs, fs) = (c.min_szz.unwrap_or(f64::NAN), f.min_szz.unwrap_or(f64::NAN));
    let (t, tf) = (c.wall_s, f.wall_s);
    let mut rows = vec![
        row("slope/cdem-vs-fem/max-abs-uz").value(c.max_abs_uz, f.max_abs_uz, t),
        row("slope/cdem-vs-fem/min-szz").value(cs, fs, t),
        row("slope/cdem-vs-fem/l2-u").value(l2, 0.0, t),
        row("slope/cdem-vs-paper/max-abs-uz").value(c.max_abs_uz, reg::PAPER_MAX_ABS_UZ.value, t),
        row("slope/cdem-vs-paper/min-szz").value(cs, reg::PAPER_MIN_SZZ.value, t),
    ];
    rows = rows.into_iter().map(|x| with_convergence(x, r)).collect();
    rows.push(row("slope/fem-vs-ansys/max-abs-uz").value(f.max_abs_uz, reg::ANSYS_MAX_ABS_UZ.value, tf));
    rows.push(row("slope/fem-vs-ansys/min-szz").value(fs, reg::ANSYS_MIN_SZZ.value, tf));
    rows
}

/// ACADS 1(a): Bishop and Spencer against Slide and the referee.
pub fn acads_rows(r: &LemResult) -> Vec<Check> {
    let (b, s, t) = (r.fs.bishop.unwrap_or(f64::NAN), r.fs.spencer.unwrap_or(f64::NAN), r.wall_s);
    vec![
        row("lem/acads/bishop-vs-slide").value(b, reg::ACADS_SLIDE_BISHOP.value, t),
        row("lem/acads/bishop-vs-referee").value(b, reg::ACADS_REFEREE.value, t),
        row("lem/acads/spencer-vs-slide").value(s, reg::ACADS_SLIDE_SPENCER.value, t),
        row("lem/acads/spencer-vs-referee")
            .value(s, reg::ACADS_REFEREE.value, t)
            .with_note("see references/lem.md, ACADS 1(a)"),
    ]
}

/// ACADS 1(c)'s rows from its search with the default 50 slices and with 400.
pub fn acads_1c_rows(r50: &LemResult, r400: &LemResult) -> Vec<Check> {
    let (b, s, t) = (r50.fs.bishop.unwrap_or(f64::NAN), r50.fs.spencer.unwrap_or(f64::NAN), r50.wall_s);
    vec![
        row("lem/acads-1c/bishop-vs-slide").value(b, reg::ACADS_1C_SLIDE_BISHOP.value, t),
        row("lem/acads-1c/spencer-vs-slide").value(s, reg::ACADS_1C_SLIDE_SPENCER.value, t),
        row("lem/acads-1c/bishop-vs-referee").value(b, reg::ACADS_1C_REFEREE.value, t),
        row("lem/acads-1c/slices-50-vs-400").value(b, r400.fs.bishop.unwrap_or(f64::NAN), t + r400.wall_s),
    ]
}

/// The paper slope's Bishop minimum against the paper's LEM.
pub fn paper_lem_row(r: &LemResult) -> Check {
    row("lem/paper/bishop").value(r.fs.bishop.unwrap_or(f64::NAN), reg::PAPER_LEM_FS.value, r.wall_s)
}

/// Our Bishop on the critical circles pySlope was run on, against
/// pySlope's FS with the same 50 slices (references/pyslope.json).
pub fn pyslope_rows(root: &Path) -> Result<Vec<Check>, Error> {
    let path = root.join(reg::PYSLOPE_JSON);
    let text = std::fs::read_to_string(&path).map_err(|e| Error::io(&path, e))?;
    let json: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| Error::io(&path, std::io::Error::other(e)))?;
    let mut rows = Vec::new();
    for (key, id, case) in [
        ("acads_1a", "lem/acads/pyslope", reg::LEM_ACADS_1A),
        ("paper_slope", "lem/paper/pyslope", reg::LEM_PAPER_SLOPE),
    ] {
        let c = &json["cases"][key];
        let num = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
        let circle = Circle {
            xc: num(&c["our_bishop_circle"]["xc"]),
            zc: num(&c["our_bishop_circle"]["zc"]),
            r: num(&c["our_bishop_circle"]["r"]),
        };
        let pyslope = num(&c["pyslope_on_our_circle"]["slices_50"]);
        let t0 = std::time::Instant::now();
        let input = case.lem_input()?;
        let ours = evaluate_circle(&input.section, circle, 50).ok().and_then(|f| f.bishop).unwrap_or(f64::NAN);
        rows.push(row(id).value(ours, pyslope, t0.elapsed().as_secs_f64()));
    }
    Ok(rows)
}

/// Eq. 21 on the slip circle and what K_i shows there. `k_springs`,
/// `k_cdem`, `k_fem`: eq. 21 from the CDEM springs, CDEM stresses, FEM
/// stresses; `fs_lem`: our Bishop on the same circle; `segments`: the K_i
/// sign segments from the springs.
pub fn slip_rows(k_springs: f64, k_cdem: f64, k_fem: f64, fs_lem: f64, segments: &[Segment], t: f64) -> Vec<Check> {
    let ours = describe_segments(segments);
    let signs: Vec<i8> = segments.iter().map(|g| g.sign).collect();
    vec![
        row("slip/eq21-springs-vs-lem").value(k_springs, fs_lem, t),
        row("slip/eq21-cdem-vs-fem").value(k_cdem, k_fem, t),
        row("slip/eq21-fem-vs-lem").value(k_fem, fs_lem, t).with_note("see references/lem.md, eq. 21"),
        row("slip/eq21-springs-vs-paper").value(k_springs, reg::PAPER_EQ21_K.value, t),
        row("slip/lem-vs-paper").value(fs_lem, reg::PAPER_LEM_FS.value, t),
        snapshot_row("slip/ki-segments-snapshot", &ours, KI_SNAPSHOT, t),
        row("slip/ki-signs-vs-paper")
            .compared(&ours.join(", "), "ab -, bc +, cd -, de +", signs == PAPER_KI_SIGNS, t)
            .with_note("see references/paper.md, Fig. 9"),
    ]
}

/// The sign segments as the snapshot lists them: "+ from 0 m to 45 m".
pub fn describe_segments(seg: &[Segment]) -> Vec<String> {
    seg.iter().map(|g| format!("{} from {:.0} m to {:.0} m", if g.sign > 0 { "+" } else { "-" }, g.s0, g.s1)).collect()
}

/// The items of an insta YAML snapshot of a list of strings (None if the
/// file cannot be read).
pub fn snapshot_lines(path: &Path) -> Option<Vec<String>> {
    let text = std::fs::read_to_string(path).ok()?;
    let body = text.splitn(3, "---\n").nth(2)?;
    Some(
        body.lines()
            .filter_map(|l| l.strip_prefix("- "))
            .map(|l| {
                let l = l.trim();
                match l.strip_prefix('"').and_then(|l| l.strip_suffix('"')) {
                    Some(q) => q.replace("\\\"", "\""),
                    None => l.to_string(),
                }
            })
            .collect(),
    )
}

/// A compared row: `ours` against the committed snapshot `snap` (relative
/// to the repository root).
pub fn snapshot_row(id: &str, ours: &[String], snap: &str, seconds: f64) -> Check {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(snap);
    let spec = row(id);
    match snapshot_lines(&path) {
        Some(reference) => spec.compared(&ours.join("; "), &reference.join("; "), reference == ours, seconds),
        None => {
            spec.compared(&ours.join("; "), "no snapshot", false, seconds).with_defect(format!("cannot read {snap}"))
        }
    }
}

/// Eq. 21 from the scene's `[analysis]` on the column circle and on the
/// paper slope's critical circle, CDEM (elastic) and FEM.
#[derive(Debug, Clone)]
pub struct SurfaceRuns {
    pub column_cdem: crate::drivers::AnalysisReport,
    pub column_fem: crate::drivers::AnalysisReport,
    pub slope_cdem: crate::drivers::AnalysisReport,
    pub slope_fem: crate::drivers::AnalysisReport,
    pub seconds: f64,
}

/// Runs the two `[analysis]` cases (elastic CDEM and FEM of each) and makes
/// their rows (references/analysis.md).
pub fn surface_rows() -> Result<(Vec<Check>, SurfaceRuns), Error> {
    let t0 = std::time::Instant::now();
    let both = |case: &reg::Case| -> Result<_, Error> {
        let scene = case.elastic_scene()?;
        let cdem = crate::drivers::run_scene(&scene, &mut |_, _| {})?.surface;
        let fem = crate::drivers::run_fem(&scene)?.surface;
        let missing = || Error::from(crate::error::SceneError::invalid("analysis", format!("{}: none", case.input)));
        Ok((cdem.ok_or_else(missing)?, fem.ok_or_else(missing)?))
    };
    let (column_cdem, column_fem) = both(&reg::COLUMN_CIRCLE)?;
    let (slope_cdem, slope_fem) = both(&reg::SLOPE)?;
    let t = t0.elapsed().as_secs_f64();
    let k_ref = reg::COLUMN_CIRCLE_K.value;
    let lem = slope_cdem.lem_fs.unwrap_or(f64::NAN);
    let rows = vec![
        row("analysis/column/cdem-vs-analytic").value(column_cdem.stresses.k, k_ref, t),
        row("analysis/column/fem-vs-analytic").value(column_fem.stresses.k, k_ref, t),
        row("analysis/slope/cdem-vs-fem").value(slope_cdem.stresses.k, slope_fem.stresses.k, t),
        row("analysis/slope/cdem-vs-lem")
            .value(slope_cdem.stresses.k, lem, t)
            .with_note("see references/analysis.md: the mesh does not follow the circle"),
    ];
    Ok((rows, SurfaceRuns { column_cdem, column_fem, slope_cdem, slope_fem, seconds: t }))
}
