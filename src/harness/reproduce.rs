//! `cdem reproduce --out DIR`: every paper case from the committed meshes (or
//! regenerated with gmsh first, `--regenerate`), run, checked and drawn:
//! `DIR/report.md` with the validation table and the figures (PNG, plotters),
//! and the same as one self-contained web page, `DIR/report.html`
//! ([`crate::harness::report::html`]).
//!
//! [`reproduce`] is the list of steps; each step, and each paper figure, is a
//! function of its own below. The cases and their reference values come from
//! [`crate::harness::registry`].

use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::analysis::slip::{from_springs, from_stresses};
use crate::analysis::{safety_factors, sign_segments, SafetyFactors, SurfacePoint};
use crate::drivers::run_scene;
use crate::drivers::{run_watched, RunResult, StageSnapshots};
use crate::error::Error;
use crate::fem::FemSolution;
use crate::harness::registry::{self as reg, Case};
use crate::harness::report::header::RunHeader;
use crate::harness::report::html::{self, Page};
use crate::harness::report::{Check, Rules, Skips, Table};
use crate::harness::{suite, validation};
use crate::model::Model;
use crate::output::figures::analysis::weak_zones;
use crate::output::figures::section::{
    element_mean_displacement, front_joint_traces, front_patches, front_patches_deformed, front_patches_of_cells,
    spring_opening, spring_point,
};
use crate::output::figures::{
    contour_panels, line_plot, slip_profile, ContourStyle, Line, Panel, Patch, Quantity, Scale, Series, SlipProfile,
    Span,
};
use plotters::style::RGBColor;

/// Runs everything into `out` and writes `out/report.md` and `out/report.html`, the
/// published slopes of issue 24 item 4 whose keys `published_slopes` names among
/// them (on three element shapes; all five: about 14 minutes on 2 cores; the others'
/// rows are skipped with [`reg::SLOPES_SKIP`]). An unknown key is an error before any
/// run; a report with failing rows is written, then returned as
/// [`Error::Validation`].
pub fn reproduce(
    out: &Path,
    regenerate: bool,
    published_slopes: &[String],
    progress: &mut dyn FnMut(&str),
) -> Result<(), Error> {
    let known: Vec<&str> = suite::plastic::heavy_published_slopes().map(|s| s.key).collect();
    if let Some(k) = published_slopes.iter().find(|k| !known.contains(&k.as_str())) {
        return Err(crate::error::SceneError::invalid(
            "--published-slopes",
            format!("no published slope {k:?}: the keys are {}", known.join(", ")),
        )
        .into());
    }
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    let mut rep = Report { out: out.to_path_buf(), checks: Vec::new(), md: String::new() };
    let t_all = Instant::now();
    // 1. The meshes (Fig. 5), regenerated with gmsh if asked.
    if regenerate {
        fig5_meshes(&mut rep, progress)?;
    }
    // 2. The column against the analytic solution.
    column(&mut rep, progress)?;
    // 3. The elastic slope, CDEM and FEM (Figs. 6-7, convergence history).
    elastic_slope(&mut rep, progress)?;
    // 4. Limit equilibrium: ACADS 1(a) and the paper slope.
    let fs_lem = limit_equilibrium(&mut rep, progress)?;
    // 5. Eq. 21 and K_i on the slip circle (Fig. 9).
    slip_circle(&mut rep, fs_lem, progress)?;
    // 6. Progressive failure of the slope (Fig. 10).
    fig10_slope_failure(&mut rep, progress)?;
    // 7. Progressive failure of Wulong (Fig. 14).
    fig14_wulong(&mut rep, progress)?;
    // 8. Error against run time.
    error_against_run_time(&mut rep, progress)?;
    // 9. The rest of the validation table: the extreme suite (DR and PCG),
    // scikit-fem, the block on a plane, the ensemble, pySlope, the meshes
    // against gmsh, the performance goals (phase-2 steps included).
    more_rows(&mut rep, progress)?;
    // 10. The published slopes on three shapes (all but those skipped).
    published(&mut rep, published_slopes, progress)?;
    rep.write(t_all.elapsed().as_secs_f64(), progress)
}

/// The report being written: the validation rows and the Markdown after the table.
struct Report {
    out: PathBuf,
    checks: Vec<Check>,
    md: String,
}

impl Report {
    fn figure(&mut self, caption: &str, file: &str) {
        let _ = writeln!(self.md, "![{caption}]({file})\n");
    }
    fn path(&self, file: &str) -> PathBuf {
        self.out.join(file)
    }
    /// `out/report.md`: the head, the validation table (every row of the
    /// registry, as in `cargo test`'s report), then the sections.
    fn write(mut self, seconds: f64, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
        self.checks.extend(not_in_reproduce());
        // The registry's rules: a row is skipped only where its spec allows it.
        let stale = std::collections::BTreeMap::new();
        let absent = |spec: &crate::harness::report::RowSpec| {
            format!("not computed by cdem reproduce (a step failed to make it); see {}", spec.test)
        };
        let rules = Rules { stale: &stale, absent: &absent, skips: Skips::Registry { ci: false, also: &[] } };
        let table = Table::assemble_with(&reg::rows(), std::mem::take(&mut self.checks), &rules);
        let failures = table.failures();
        let header = RunHeader::of_this_process(Path::new("."));
        let summary = format!("{}; {} failing; {:.0} s in all.", table.counts(), failures.len(), seconds);
        let head = format!(
            "# cdem reproduce\n\n{}\n{summary}\n\n## Validation\n\n{}{}\n",
            header.markdown(),
            table.markdown(),
            if failures.is_empty() {
                String::new()
            } else {
                format!("\nFailing rows:\n\n- {}\n", failures.join("\n- "))
            }
        );
        let path = self.out.join("report.md");
        crate::output::write_atomic(&path, format!("{head}{}", self.md).as_bytes())?;
        progress(&format!("wrote {}", path.display()));
        let page = Page {
            title: "cdem reproduce",
            header: &header,
            table: &table,
            summary,
            failures: &failures,
            sections: &self.md,
            dir: &self.out,
            root: Path::new("."),
        };
        let path = self.out.join("report.html");
        crate::output::write_atomic(&path, html::page(&page).as_bytes())?;
        progress(&format!("wrote {}", path.display()));
        match failures.first() {
            None => Ok(()),
            Some(first) => Err(Error::Validation {
                count: failures.len(),
                report: self.out.join("report.md"),
                first: first.clone(),
            }),
        }
    }
}

/// The rows of the registry that `cdem reproduce` does not compute, with the
/// reason (the table shows them skipped): the timed rows that `cargo test`
/// skips too (with the same reasons, tests/performance.rs).
fn not_in_reproduce() -> Vec<Check> {
    let mut rows = crate::harness::perf::rows::srm_perf_skipped(SRM_PERF_ONLY);
    rows.extend(crate::harness::perf::rows::ensemble_perf_skipped(ENSEMBLE_PERF_ONLY));
    rows.extend(reg::FSERROR_ROWS.iter().map(|r| r.skipped(reg::FSERROR_SKIP)));
    rows
}
const SRM_PERF_ONLY: &str =
    "four strength reductions of 10 s to 4 min each, twice, measured by cargo run --release -- perf (references/performance.md)";
const ENSEMBLE_PERF_ONLY: &str = "timed ensembles (about 2 min, shard processes of the cdem binary), measured by \
                                  cargo run --release -- perf (references/performance.md)";

/// Step 9, the rows no figure needs: the extreme suite under both solvers,
/// the FEM against the committed scikit-fem values, the block on a plane
/// (physical time, strength reduction), the analytic ensemble, our Bishop
/// against pySlope on the same circles, the study's column point, the
/// committed meshes against gmsh (skipped without gmsh), the performance
/// goals (measured in this run; phase 2 of the slip-surface slope with both
/// masses too, not its strength reductions: [`not_in_reproduce`]).
fn more_rows(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    let root = Path::new(".");
    progress("extreme suite (DR and PCG)");
    for run in suite::extreme::run_all()? {
        rep.checks.push(run.row);
    }
    progress("FEM against scikit-fem (references/skfem.json)");
    for case in suite::skfem::cases(root)? {
        rep.checks.extend(case.rows);
    }
    progress("block on a plane: physical time, strength reduction");
    rep.checks.push(suite::block::at_rest()?.1);
    rep.checks.push(suite::block::sliding()?.1);
    for case in suite::srm::run_all()? {
        rep.checks.push(case.row);
    }
    progress("runout: 3DEC's sliding and toppling blocks, launched and dropped blocks, the paper slope run out to rest (about 3 min)");
    rep.checks.extend(suite::runout::rows()?);
    progress("plastic blocks: the Mohr-Coulomb limit of one hexahedron");
    rep.checks.push(suite::plastic::element_limit_row().0);
    progress("plastic blocks: the unconfined column in compression and tension");
    rep.checks.extend(suite::plastic::column_rows()?.into_iter().map(|r| r.0));
    progress("plastic blocks: Prandtl's strip footing (about 1 min)");
    rep.checks.push(suite::plastic::prandtl_row()?.0);
    progress("plastic blocks: Griffiths & Lane's slope by strength reduction (about 2 min)");
    let gl1 = suite::plastic::gl1_hex_row()?;
    let (gl1_prism, gl1_tet, gl1_spread) = suite::plastic::gl1_shape_rows(&gl1)?;
    rep.checks.extend([gl1.row, gl1_prism.row, gl1_tet.row, gl1_spread]);
    progress("plastic blocks: the paper slope with every interface breakable, by strength reduction (about 1 min)");
    rep.checks.push(suite::plastic::paper_slope_row()?.row);
    joint_sets(rep, progress)?;
    laws(rep, progress)?;
    water(rep, progress)?;
    progress("analytic ensemble");
    rep.checks.extend(suite::ensemble::segment(root)?.rows);
    rep.checks.extend(validation::pyslope_rows(root)?);
    let (cdem, fem) = crate::harness::study::column_base_point()?;
    rep.checks.push(reg::row("study/column/cdem-l2").value(cdem, 0.0, 0.0));
    rep.checks.push(reg::row("study/column/fem-l2").value(fem, 0.0, 0.0));
    progress("committed meshes against gmsh");
    rep.checks.push(suite::meshes::regenerated_row(root));
    progress("performance goals");
    let (scene, model) = crate::harness::perf::headline::paper_slope(root)?;
    let h = crate::harness::perf::headline::headline(root, &scene, &model, progress)?;
    rep.checks.extend(crate::harness::perf::rows::perf_rows(&h));
    let phase2 = crate::harness::perf::failure::phase2_figure(root, progress)?;
    rep.checks.extend(crate::harness::perf::rows::phase2_rows(&phase2));
    Ok(())
}

/// Issue 24 item 4 beyond Griffiths & Lane's slope (`more_rows` has its
/// rows): the five other published slopes, each on hexahedra, prisms and
/// tetrahedra, against the published FE strength reduction and the 3 %
/// spread ([`suite::plastic::PublishedSlopeRun`]); skipped unless `run`.
fn published(rep: &mut Report, keys: &[String], progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    let asked = |s: &reg::PublishedSlope| keys.iter().any(|k| k == s.key);
    for slope in suite::plastic::heavy_published_slopes().filter(|s| !asked(s)) {
        rep.checks.extend(suite::plastic::published_slope_skipped(slope, reg::SLOPES_SKIP));
    }
    if keys.is_empty() {
        return Ok(());
    }
    let _ = writeln!(rep.md, "## The published slopes on three element shapes (references/plastic.md)\n");
    let _ = writeln!(
        rep.md,
        "| slope | hexahedra | prisms | tetrahedra | spread | published FE-SRM | published LEM | our Bishop |"
    );
    let _ = writeln!(rep.md, "|---|---|---|---|---|---|---|---|");
    let slopes: Vec<&reg::PublishedSlope> = suite::plastic::heavy_published_slopes().filter(|s| asked(s)).collect();
    progress(&format!("the published slopes: {} strength reductions, two at a time", 3 * slopes.len()));
    let workers = std::thread::available_parallelism().map_or(1, |n| n.get());
    let runs = suite::plastic::PublishedSlopeRun::run_all(&slopes, workers, &|_| {})?;
    for (slope, r) in slopes.into_iter().zip(runs) {
        let fs = r.factors();
        let _ = writeln!(
            rep.md,
            "| {} | {:.4} | {:.4} | {:.4} | {:.1} % | {:.3} | {:.3} | {:.4} |",
            slope.name,
            fs[0],
            fs[1],
            fs[2],
            100.0 * suite::plastic::mesh_spread(&fs),
            slope.fe_srm,
            slope.lem,
            r.bishop
        );
        rep.checks.extend(r.rows(slope));
    }
    let _ = writeln!(rep.md);
    Ok(())
}

/// Pore water (no paper figure): the submerged column against Terzaghi's
/// effective stress, the infinite slope and Hoek & Bray's plane failure
/// with water by `cdem srm` against their closed forms.
fn water(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("water: submerged column, infinite slope, plane failure with a water-filled crack");
    let _ = writeln!(rep.md, "## Pore water: effective stress and the closed forms (references/water.md)\n");
    std::fs::create_dir_all(rep.path("water")).map_err(|e| Error::io(rep.path("water"), e))?;
    let (rows, runs) = suite::water::rows()?;
    rep.checks.extend(rows);
    for (id, result, model) in &runs {
        let name = id.trim_start_matches("water/").trim_end_matches("-srm");
        let file = format!("water/{name}-mechanism.png");
        if crate::output::figures::joints::mechanism_views(result, model, &rep.path(&file))? {
            rep.figure(&format!("{id}: the mechanism at the smallest unstable factor, the water in blue"), &file);
        }
    }
    progress("water: Wulong after rain, the water table's rise at which it first slides (about 2 min)");
    let (rows, level) = suite::wulong::wet_rows()?;
    rep.checks.extend(rows);
    let scene = reg::WULONG_WET.scene()?;
    let lem = suite::wulong::lem_fs_by_rise(&scene, &suite::wulong::figure_rises())?;
    let file = "water/wulong-fs-by-water.png";
    let verdicts: Vec<(f64, bool)> = level.2.iter().map(|t| (t.0, t.1)).collect();
    crate::output::figures::water::fs_by_rise(&rep.path(file), &lem, &verdicts)?;
    rep.figure("Wulong after rain: the LEM's FS against the water table's rise, and where CDEM first slides", file);
    let table: Vec<String> = lem.iter().map(|(r, b, s)| format!("| {r:.0} | {b:.3} | {s:.3} |")).collect();
    let _ = writeln!(
        rep.md,
        "Wulong after rain, the LEM of `wulong-wet.toml` against the rise (m):\n\n| rise | Bishop | Spencer |\n|---|---|---|\n{}\n",
        table.join("\n")
    );
    Ok(())
}

/// The joint-set cases (no paper figure): plane failure, the wedge and
/// toppling by `cdem srm` against their closed forms, each mechanism in
/// section and plan, and the stereonets of the two geometry files.
fn joint_sets(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("joint sets: plane failure, wedge, toppling (cdem srm against the closed forms)");
    std::fs::create_dir_all(rep.path("joints")).map_err(|e| Error::io(rep.path("joints"), e))?;
    let _ = writeln!(rep.md, "## Joint sets: plane, wedge and toppling failure (references/joints.md)\n");
    for case in suite::joints::run_all()? {
        let name = case.row.id.trim_start_matches("joints/").trim_end_matches("-srm").to_string();
        let file = format!("joints/{name}-mechanism.png");
        if crate::output::figures::joints::mechanism_views(&case.result, &case.model, &rep.path(&file))? {
            rep.figure(&format!("{}: the mechanism at the smallest unstable factor", case.case.name), &file);
        }
        rep.checks.push(case.row);
    }
    for (name, geometry) in
        [("plane", "verification/joints/plane-geometry.toml"), ("wedge", "verification/joints/wedge-geometry.toml")]
    {
        let dir = rep.path(&format!("joints/{name}-kinematics"));
        let k = crate::app::kinematics::kinematics(Path::new(geometry), &dir)?;
        let _ = writeln!(rep.md, "Kinematic analysis of `{geometry}`:\n\n{}", k.table);
        rep.figure(&format!("{name}: stereonet"), &format!("joints/{name}-kinematics/stereonet.png"));
    }
    Ok(())
}

/// The joint laws (no paper figure): a Barton-Bandis joint's direct shear
/// test against its envelope, and plane failure on one by `cdem srm` against
/// the closed form, dry and with the crack full.
fn laws(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("joint laws: Barton-Bandis direct shear and plane failure (cdem srm against the closed forms)");
    let _ = writeln!(rep.md, "## Joint laws: Barton-Bandis (references/laws.md)\n");
    rep.checks.extend(suite::laws::shear_rows());
    for (case, closed, id) in suite::laws::plane_cases() {
        rep.checks.push(suite::laws::plane(case, closed, id)?.0);
    }
    Ok(())
}

/// Step 1, the meshes of Fig. 5 (and every other committed mesh): regenerated
/// from their `.geo` files with gmsh.
fn fig5_meshes(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    let n = regenerate_meshes(progress)?;
    let _ = writeln!(rep.md, "Meshes regenerated from {n} .geo files with gmsh.\n");
    Ok(())
}

/// Step 2, the laterally confined column (no paper figure): top u_z with
/// springs and with merged interfaces against the analytic solution.
fn column(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("column");
    let springs = run_scene(&reg::COLUMN.scene()?, &mut |_, _| {})?;
    rep.checks.extend(validation::column_springs_rows(&springs));
    let merged = run_scene(&reg::COLUMN_MERGED.scene()?, &mut |_, _| {})?;
    rep.checks.push(validation::column_merged_row(&merged));
    Ok(())
}

/// Step 3, the elastic slope: CDEM and FEM on the same perturbed mesh, the
/// paper's and ANSYS values beside them; Figs. 6-7 and the convergence history.
fn elastic_slope(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("elastic slope (CDEM, FEM)");
    let scene = reg::SLOPE.scene()?;
    let r = run_scene(&scene, &mut |_, _| {})?;
    let fem = crate::drivers::solve_fem(&scene)?;
    let (c, f) = (&r.summary, &fem.summary);
    rep.checks.extend(validation::slope_rows(&r, &fem));
    let _ = writeln!(
        rep.md,
        "## Elastic slope (Figs. 6-7)\n\nCDEM: {} steps, {:.1} s; FEM: {:.2} s.\n",
        c.steps, c.wall_s, f.wall_s
    );
    figs6_7_contours(rep, &r, &fem)?;
    let mut dr_scene = scene.clone();
    dr_scene.solver.elastic = crate::solver::ElasticSolver::Dr;
    let dr = run_scene(&dr_scene, &mut |_, _| {})?;
    let pcg = (scene.solver.elastic == crate::solver::ElasticSolver::Pcg).then_some(&r);
    convergence_history(rep, &dr, pcg)
}

/// Figs. 6 (sigma_zz) and 7 (u_z) of the elastic slope on the front section:
/// CDEM above FEM on one banded colour scale (as the paper's ANSYS-style
/// plots), and CDEM - FEM per element on a diverging scale centred on zero
/// (the two share the perturbed mesh, cell for cell).
fn figs6_7_contours(rep: &mut Report, r: &RunResult, fem: &FemSolution) -> Result<(), Error> {
    let stress = r.stress.clone().unwrap_or_default();
    let n = r.model.elements.len();
    let cdem_szz: Vec<f64> = (0..n).map(|e| stress.get(e).map_or(f64::NAN, |s| s[2])).collect();
    let fem_szz: Vec<f64> = fem.stress.iter().map(|s| s[2]).collect();
    let cdem_uz: Vec<f64> = (0..n).map(|e| element_mean_displacement(&r.model, &r.state.u, e, 2)).collect();
    let fem_uz: Vec<f64> = fem
        .cells
        .iter()
        .map(|c| c.corners().iter().map(|&k| fem.u[3 * k + 2]).sum::<f64>() / c.corners().len() as f64)
        .collect();
    let same = same_cells(&r.model, fem);
    let banded = ContourStyle { bands: Some(10), ..ContourStyle::default() };
    for (fig, file, name, q, c, f) in [
        ("Fig. 6", "fig6-szz", "sigma_zz", Quantity::Stress, &cdem_szz, &fem_szz),
        ("Fig. 7", "fig7-uz", "u_z", Quantity::Displacement, &cdem_uz, &fem_uz),
    ] {
        let panels = [
            Panel { title: format!("CDEM {name}"), patches: front_patches(&r.model, |e| c[e]), lines: Vec::new() },
            Panel {
                title: format!("FEM {name} (same perturbed mesh, continuous)"),
                patches: front_patches_of_cells(&fem.coords, &fem.cells, |e| f[e]),
                lines: Vec::new(),
            },
        ];
        let png = format!("{file}.png");
        let title = format!("{fig}: elastic slope, {name} (bands of a round width)");
        contour_panels(&rep.path(&png), &title, name, q, &panels, &banded)?;
        rep.figure(&title, &png);
        if !same {
            continue;
        }
        let max_f = f.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let max_d = c.iter().zip(f.iter()).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        let (factor, unit) = q.display(max_f);
        let diff = [Panel {
            title: format!("CDEM - FEM, {name} per element"),
            patches: front_patches(&r.model, |e| c[e] - f[e]),
            lines: Vec::new(),
        }];
        let style = ContourStyle {
            notes: vec![format!(
                "largest |CDEM - FEM| {:.3} {unit} = {:.2} % of the largest |FEM {name}| ({:.1} {unit})",
                max_d * factor,
                100.0 * max_d / max_f,
                max_f * factor
            )],
            ..ContourStyle::default()
        };
        let png = format!("{file}-diff.png");
        let title = format!("{fig}: CDEM - FEM, {name}");
        contour_panels(&rep.path(&png), &title, &format!("CDEM - FEM {name}"), q, &diff, &style)?;
        rep.figure(&title, &png);
    }
    Ok(())
}

/// The CDEM elements are the FEM cells, in order (same corners' centroids).
fn same_cells(model: &Model, fem: &FemSolution) -> bool {
    let el = &model.elements;
    el.len() == fem.cells.len()
        && (0..el.len()).all(|e| {
            let (a, b) = (el.corners(e), fem.cells[e].corners());
            let mean = |pts: &mut dyn Iterator<Item = [f64; 3]>, n: usize| {
                pts.fold([0.0; 3], |m, p| [m[0] + p[0], m[1] + p[1], m[2] + p[2]]).map(|v| v / n as f64)
            };
            let ca = mean(&mut a.iter().map(|&i| model.x0[i as usize]), a.len());
            let cb = mean(&mut b.iter().map(|&i| fem.coords[i]), b.len());
            a.len() == b.len() && (0..3).all(|k| (ca[k] - cb[k]).abs() <= 1e-9 * (1.0 + cb[k].abs()))
        })
}

/// The convergence of the elastic slope (no paper figure): dynamic
/// relaxation's (`r`) unbalanced-force ratio and kinetic energy against
/// step, and PCG's ratio against iteration (`pcg`: a run whose phase 1 was PCG).
fn convergence_history(rep: &mut Report, r: &RunResult, pcg: Option<&RunResult>) -> Result<(), Error> {
    let ratio: Vec<(f64, f64)> = r.elastic.history.iter().map(|h| (h.step as f64, h.unbalanced_ratio)).collect();
    let pcg_ratio: Vec<(f64, f64)> =
        pcg.map_or(Vec::new(), |p| p.elastic.history.iter().map(|h| (h.step as f64, h.unbalanced_ratio)).collect());
    let ke: Vec<(f64, f64)> = r
        .elastic
        .history
        .iter()
        .map(|h| {
            (h.step as f64, h.kinetic_energy / r.elastic.history.iter().map(|h| h.kinetic_energy).fold(0.0, f64::max))
        })
        .collect();
    line_plot(
        &rep.path("history-slope.png"),
        "Elastic slope: convergence of dynamic relaxation and PCG",
        "step (DR) or iteration (PCG)",
        "value",
        &[
            Series { name: "DR: unbalanced-force ratio", points: &ratio },
            Series { name: "DR: kinetic energy / max", points: &ke },
            Series { name: "PCG: unbalanced-force ratio", points: &pcg_ratio },
        ],
        Scale::Linear,
        Scale::Log,
    )?;
    rep.figure("convergence history", "history-slope.png");
    Ok(())
}

/// Step 4, limit equilibrium (no paper figure): ACADS 1(a) against Slide and
/// the referee, the paper slope against the paper's LEM. Returns our Bishop
/// FS of the paper slope.
fn limit_equilibrium(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<f64, Error> {
    progress("limit equilibrium");
    let acads = crate::lem::analyse(&reg::LEM_ACADS_1A.lem_input()?)?;
    let paper = crate::lem::analyse(&reg::LEM_PAPER_SLOPE.lem_input()?)?;
    rep.checks.extend(validation::acads_rows(&acads));
    let (acads_1c, acads_1c_400) = crate::harness::suite::lem_layers::acads_1c()?;
    rep.checks.extend(validation::acads_1c_rows(&acads_1c, &acads_1c_400));
    rep.checks.push(validation::paper_lem_row(&paper));
    rep.checks.extend(crate::harness::suite::taylor::rows()?);
    rep.checks.extend(crate::harness::suite::lem_water::rows()?);
    Ok(paper.fs.bishop.unwrap_or(f64::NAN))
}

/// Step 5, eq. 21 and K_i on the LEM critical circle, from the CDEM springs
/// and the FEM stresses, against our LEM (`fs_lem`) and the paper's 1.086;
/// the K_i sign segments; Fig. 9.
fn slip_circle(rep: &mut Report, fs_lem: f64, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("eq. 21 on the slip circle");
    let slip_scene = reg::SLOPE_SLIP.elastic_scene()?;
    let rs = run_scene(&slip_scene, &mut |_, _| {})?;
    let fem_s = crate::drivers::solve_fem(&slip_scene)?;
    let mesh = crate::mesh::gmsh::read_msh(&slip_scene.mesh_path())?;
    let (circle, c) = (reg::SLIP_CIRCLE, reg::SLIP_COHESION);
    let tan_phi = reg::SLIP_FRICTION_DEG.to_radians().tan();
    let pts_sp = from_springs(&rs.model, &rs.state.u, &rs.state.springs, "slip", &circle).unwrap_or_default();
    let pts_fem = from_stresses(&mesh, &fem_s.coords, "slip", &circle, &fem_s.stress).unwrap_or_default();
    let (k_sp, k_fem) = (safety_factors(&pts_sp, c, tan_phi), safety_factors(&pts_fem, c, tan_phi));
    let s: Vec<f64> = pts_sp.iter().map(|p| p.s).collect();
    let seg = sign_segments(&s, &k_sp.k_i, reg::MIN_SEGMENT);
    // The table's rows: eq. 21 against our Bishop on the same circle (not
    // the search's minimum `fs_lem`, which is on a neighbouring circle).
    let _ = fs_lem;
    let lem = reg::LEM_PAPER_SLOPE.lem_input()?;
    let on_circle = circle.circle;
    let fs_circle =
        crate::lem::evaluate_circle(&lem.section, on_circle, 50).ok().and_then(|f| f.bishop).unwrap_or(f64::NAN);
    let cdem_stress = rs
        .stress
        .as_ref()
        .and_then(|st| from_stresses(&mesh, &rs.model.mesh_coords, "slip", &circle, st))
        .unwrap_or_default();
    let k_cdem = safety_factors(&cdem_stress, c, tan_phi);
    rep.checks.extend(validation::slip_rows(k_sp.k, k_cdem.k, k_fem.k, fs_circle, &seg, rs.summary.wall_s));
    // The same on circles no mesh face follows (`[analysis]`, references/analysis.md).
    let (rows, runs) = validation::surface_rows()?;
    rep.checks.extend(rows);
    let _ = writeln!(
        rep.md,
        "## Eq. 21 on circles no face follows (`[analysis]`)\n\nColumn circle: K = {:.4} (CDEM), {:.4} (FEM), closed form {:.4}. Paper slope mesh, LEM critical circle: K = {:.4} (CDEM), {:.4} (FEM), LEM Bishop {:.4}.\n",
        runs.column_cdem.stresses.k,
        runs.column_fem.stresses.k,
        reg::COLUMN_CIRCLE_K.value,
        runs.slope_cdem.stresses.k,
        runs.slope_fem.stresses.k,
        runs.slope_cdem.lem_fs.unwrap_or(f64::NAN)
    );
    let _ = writeln!(rep.md, "## Slip circle (Fig. 9)\n\nK_i sign segments (CDEM springs, toe to crest, runs under 2 m merged): {}. The paper: ab -, bc +, cd -, de +.\n", seg.iter().map(|g| format!("{} {:.0}-{:.0} m", if g.sign > 0 { "+" } else { "-" }, g.s0, g.s1)).collect::<Vec<_>>().join(", "));
    fig9(rep, &rs, (&pts_sp, &k_sp), (&pts_fem, &k_fem))
}

/// Fig. 9 as in the paper, on one canvas: the section with the sliding mass
/// and the slip surface above, K_i against x below (CDEM springs, FEM
/// stresses), with the K = 1 and K = 0 lines, the sign segments in a strip
/// and the K_i < 1 zones (lettered a, b, ... from the toe) shaded; the
/// paper's ab -, bc +, cd -, de + beside ours.
fn fig9(
    rep: &mut Report,
    rs: &RunResult,
    springs: (&[SurfacePoint], &SafetyFactors),
    fem: (&[SurfacePoint], &SafetyFactors),
) -> Result<(), Error> {
    let to_x = arc_x();
    let profile = |(pts, k): (&[SurfacePoint], &SafetyFactors)| -> Vec<(f64, f64)> {
        pts.iter().zip(&k.k_i).map(|(p, &k)| (to_x(p.s), k)).collect()
    };
    let (ki_sp, ki_fem) = (profile(springs), profile(fem));
    let s: Vec<f64> = springs.0.iter().map(|p| p.s).collect();
    let segs = sign_segments(&s, &springs.1.k_i, reg::MIN_SEGMENT);
    let sign = |g: i8| if g > 0 { "+" } else { "-" };
    let strip: Vec<Span> =
        segs.iter().map(|g| Span { x0: to_x(g.s0), x1: to_x(g.s1), label: format!("sign {}", sign(g.sign)) }).collect();
    let zones = weak_zones(springs.0, &springs.1.k_i);
    let (mut shaded, mut unshaded) = (Vec::new(), Vec::new());
    for (k, z) in zones.iter().enumerate() {
        let span = Span { x0: to_x(z.1), x1: to_x(z.2), label: ((b'a' + k as u8) as char).to_string() };
        if z.0 {
            shaded.push(span);
        } else {
            unshaded.push(span);
        }
    }
    // K_i is R_i / D_i and runs off where D_i changes sign: a fixed window.
    let y_range = (-3.0, 6.0);
    let beyond = ki_sp.iter().chain(&ki_fem).filter(|p| p.1 < y_range.0 || p.1 > y_range.1).count();
    let section: Vec<Patch> = front_patches(&rs.model, |e| {
        let c = rs.model.elements.corners(e);
        let (x, z) =
            c.iter().fold((0.0, 0.0), |m, &i| (m.0 + rs.model.x0[i as usize][0], m.1 + rs.model.x0[i as usize][2]));
        let (x, z) = (x / c.len() as f64, z / c.len() as f64);
        let circle = reg::SLIP_CIRCLE;
        f64::from((x - circle.circle.xc).hypot(z - circle.circle.zc) < reg::slip_circle_radius())
    });
    let zone_text = |want: bool| {
        zones
            .iter()
            .enumerate()
            .filter(|z| z.1 .0 == want)
            .map(|(k, z)| format!("{} x {:.0}-{:.0}", (b'a' + k as u8) as char, to_x(z.1), to_x(z.2)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let notes = vec![
        format!(
            "Ours (CDEM springs, elastic): sign segments {}; K_i < 1 zones (shaded) {}; K_i >= 1 zones {}.",
            segs.iter()
                .map(|g| format!("{} x {:.0}-{:.0}", sign(g.sign), to_x(g.s0), to_x(g.s1)))
                .collect::<Vec<_>>()
                .join(", "),
            zone_text(true),
            zone_text(false)
        ),
        "The paper (its Fig. 9): ab -, bc +, cd -, de + (sign of K_i, toe to crest). Ours alternate in K_i against 1, \
         not in sign."
            .to_string(),
        format!(
            "Eq. 21: K = {:.3} (CDEM springs), {:.3} (FEM stresses). {beyond} stations beyond the window are drawn as \
             triangles at its edge.",
            springs.1.k, fem.1.k
        ),
    ];
    let fig = SlipProfile {
        title: "Fig. 9: safety factor K_i along the slip surface (LEM critical circle)",
        section: &section,
        surface: &reg::slip_arc(),
        y_label: "K_i (eq. 22)",
        series: &[Series { name: "CDEM springs", points: &ki_sp }, Series { name: "FEM stresses", points: &ki_fem }],
        y_range,
        levels: &[(1.0, "K = 1"), (0.0, "K = 0")],
        strip: &strip,
        shaded: &shaded,
        unshaded: &unshaded,
        notes: &notes,
    };
    slip_profile(&rep.path("fig9.png"), &fig)?;
    rep.figure("Fig. 9: K_i along the slip surface", "fig9.png");
    Ok(())
}

/// The x of the point at arc length `s` from the toe on the slip circle.
fn arc_x() -> impl Fn(f64) -> f64 {
    let (c, r) = (reg::SLIP_CIRCLE, reg::slip_circle_radius());
    let (xc, zc) = (c.circle.xc, c.circle.zc);
    let a0 = (c.toe[1] - zc).atan2(c.toe[0] - xc);
    let end = *reg::slip_arc().last().expect("the arc has points");
    let dir = ((end.1 - zc).atan2(end.0 - xc) - a0).signum();
    move |s| xc + r * (a0 + dir * s / r).cos()
}

/// Step 6, Fig. 10: progressive failure of the paper slope on its slip
/// circle, and its rows (the failure order, [`suite::slope_failure`]).
fn fig10_slope_failure(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    let Some((run, seconds)) = progressive_failure(rep, "slope", reg::SLOPE_SLIP, "fig10", progress)? else {
        return Ok(());
    };
    if let Some(f) = suite::slope_failure::SlopeFailure::of(&run) {
        let _ = writeln!(
            rep.md,
            "Zones of the slip circle (elastic K_i against 1), from the toe: {}.\n",
            f.describe_start()
        );
        rep.checks.extend(f.rows(seconds));
    }
    Ok(())
}

/// Step 7, Fig. 14: progressive failure of the Wulong slope, and its rows
/// ([`suite::wulong`]).
fn fig14_wulong(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    let Some(((run, snapshots), seconds)) = progressive_run(rep, "Wulong", reg::WULONG, "fig14", progress)? else {
        return Ok(());
    };
    let scene = reg::WULONG.scene()?;
    if let Some(r) = suite::wulong::from_run(run, snapshots) {
        rep.checks.extend(suite::wulong::analyse(&r, &scene, seconds)?.rows);
    }
    Ok(())
}

/// A run with phase 2, its stage snapshots, and its wall time (s).
type ProgressiveRun = ((RunResult, StageSnapshots), f64);

/// [`progressive_run`] without the stage snapshots: the run and its wall time.
fn progressive_failure(
    rep: &mut Report,
    name: &str,
    case: Case,
    prefix: &str,
    progress: &mut dyn FnMut(&str),
) -> Result<Option<(RunResult, f64)>, Error> {
    Ok(progressive_run(rep, name, case, prefix, progress)?.map(|((run, _), t)| (run, t)))
}

/// Both phases of a scene with `[failure]` (None if the scene is absent or
/// has none): a summary paragraph and the displacement since phase 1 at
/// four stages ([`stage_figures`], files `<prefix>-*.png`); returns the run,
/// its stage snapshots and its wall time.
fn progressive_run(
    rep: &mut Report,
    name: &str,
    case: Case,
    prefix: &str,
    progress: &mut dyn FnMut(&str),
) -> Result<Option<ProgressiveRun>, Error> {
    if !case.path().exists() {
        return Ok(None);
    }
    progress(&format!("progressive failure: {name}"));
    let scene = case.scene()?;
    if scene.failure.is_none() {
        return Ok(None);
    }
    let t0 = Instant::now();
    let mut snapshots = StageSnapshots::default();
    let pr = run_watched(&scene, &mut snapshots)?;
    let seconds = t0.elapsed().as_secs_f64();
    let f = pr.failure.as_ref().expect("a [failure] scene has phase 2");
    let last = f.stages.last().copied();
    let _ = writeln!(
        rep.md,
        "## Progressive failure: {name} ({prefix})\n\nPhase 1: {} steps; phase 2: {:?} after {} steps ({:.1} s); failed springs: {} tension, {} shear; displacement since phase 1 {:.3} m.\n",
        pr.elastic.steps,
        f.end,
        f.report.steps,
        seconds,
        last.map_or(0, |s| s.failed_tension),
        last.map_or(0, |s| s.failed_shear),
        last.map_or(0.0, |s| s.max_displacement)
    );
    for (title, file) in stage_figures(&pr, &snapshots, &rep.out, prefix)? {
        rep.figure(&title, &file);
    }
    Ok(Some(((pr, snapshots), seconds)))
}

/// Step 8, error against run time (no paper figure): the study
/// ([`crate::harness::study`]) into `out/study/`, its table and figures.
fn error_against_run_time(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("error against run time");
    let study_dir = rep.out.join("study");
    crate::harness::study::run_study(&study_dir, progress)?;
    let table =
        std::fs::read_to_string(study_dir.join("study.md")).map_err(|e| Error::io(study_dir.join("study.md"), e))?;
    let _ = writeln!(rep.md, "## Error against run time\n\nRelative L2 error of the displacement field (column: analytic; slope: FEM on the 0.5 m mesh), one factor varied at a time.\n\n{table}");
    rep.figure("column", "study/study-column.png");
    rep.figure("slope", "study/study-slope.png");
    rep.figure("factor of safety", "study/study-fs.png");
    Ok(())
}

/// Regenerates every committed mesh from its `.geo` with gmsh.
pub fn regenerate_meshes(progress: &mut dyn FnMut(&str)) -> Result<usize, Error> {
    let mut dirs: Vec<PathBuf> = vec!["verification/extreme".into(), "verification/study".into()];
    for e in std::fs::read_dir("verification/cases").map_err(|e| Error::io("verification/cases", e))?.flatten() {
        dirs.push(e.path());
    }
    let mut n = 0;
    for dir in dirs {
        for f in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
            let geo = f.path();
            if geo.extension().is_some_and(|e| e == "geo") && geo.with_extension("msh").exists() {
                progress(&format!("gmsh {}", geo.display()));
                crate::mesh::gmsh::regenerate(&geo, &geo.with_extension("msh"))?;
                n += 1;
            }
        }
    }
    Ok(n)
}

/// A failed joint opening more than this is drawn as open (m): the crack
/// threshold of docs/method.md 4.4.
const OPEN: f64 = 2e-3;

/// Four stages of phase 2 chosen from its failure sequence: the first stage
/// with a failed spring, the one where the failures are halfway from there
/// to their final number, the first with the final number, and the last.
/// Indices into the stages, increasing (fewer if there are fewer stages).
pub fn chosen_stages(stages: &[crate::drivers::Stage]) -> Vec<usize> {
    let n = stages.len();
    if n <= 4 {
        return (0..n).collect();
    }
    let failed = |k: usize| stages[k].failed_tension + stages[k].failed_shear;
    let last = failed(n - 1);
    let first = (0..n).find(|&k| failed(k) > 0).unwrap_or(0);
    let f0 = failed(first);
    let half = (0..n).find(|&k| 2 * failed(k) >= f0 + last).unwrap_or(n / 2);
    let full = (0..n).find(|&k| failed(k) >= last).unwrap_or(n - 1);
    let mut idx = vec![first, half, full, n - 1];
    idx.dedup();
    // Fewer than four: add where the displacement since phase 1 reaches half
    // its final value, then the middle of the widest gap.
    if idx.len() < 4 {
        let d_end = stages[n - 1].max_displacement;
        let moved = (0..n).find(|&k| stages[k].max_displacement >= 0.5 * d_end).unwrap_or(n / 2);
        if !idx.contains(&moved) {
            idx.push(moved);
            idx.sort_unstable();
        }
    }
    while idx.len() < 4 {
        let (g, _) = idx.windows(2).enumerate().max_by_key(|(_, w)| w[1] - w[0]).expect("two stages");
        if idx[g + 1] - idx[g] < 2 {
            break;
        }
        idx.insert(g + 1, (idx[g] + idx[g + 1]) / 2);
    }
    idx
}

/// A deformation scale of 1, 2 or 5 x 10^k that draws `max_u` as about 4 %
/// of `width` (at least 1).
fn deformation_scale(width: f64, max_u: f64) -> f64 {
    if max_u <= 0.0 || !max_u.is_finite() {
        return 1.0;
    }
    let target = 0.04 * width / max_u;
    if target <= 1.0 {
        return 1.0;
    }
    let p = 10f64.powf(target.log10().floor());
    [5.0, 2.0, 1.0].into_iter().map(|m| m * p).find(|&v| v <= target).unwrap_or(p)
}

/// Fig. 10 / Fig. 14: the displacement since phase 1 (|u|, mm) at four
/// stages of the failure sequence ([`chosen_stages`]), on the deformed shape
/// (one scale for all four), with the failed joints drawn: open (more than
/// 2 mm) in red, failed and closed (slipped) in black; one colour scale for
/// the figure. Returns `(title, file)`: one file `<prefix>-stages.png`.
pub fn stage_figures(
    r: &RunResult,
    snapshots: &StageSnapshots,
    out: &Path,
    prefix: &str,
) -> Result<Vec<(String, String)>, Error> {
    let Some(f) = &r.failure else { return Ok(Vec::new()) };
    let idx = chosen_stages(&f.stages);
    if idx.is_empty() || snapshots.u.len() < f.stages.len() {
        return Ok(Vec::new());
    }
    let model = &r.model;
    let traces = front_joint_traces(model);
    let width = model.x0.iter().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max)
        - model.x0.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
    let max_u = idx.iter().flat_map(|&k| snapshots.u[k].chunks(3).map(|d| d[0].hypot(d[2]))).fold(0.0, f64::max);
    let scale = deformation_scale(width, max_u);
    let (open_c, slip_c) = (RGBColor(230, 20, 20), RGBColor(0, 0, 0));
    let mut panels = Vec::new();
    for &k in &idx {
        let (st, u) = (&f.stages[k], &snapshots.u[k]);
        let du: Vec<f64> = u.iter().zip(&f.u_elastic).map(|(a, b)| a - b).collect();
        let patches = front_patches_deformed(model, u, scale, |e| {
            element_mean_displacement(model, &du, e, 0).hypot(element_mean_displacement(model, &du, e, 2))
        });
        let mut lines = Vec::new();
        for t in &traces {
            let failed = t.springs.iter().any(|&s| f.failed_at[s].is_some_and(|at| at <= st.step));
            if !failed {
                continue;
            }
            let open = t.springs.iter().any(|&s| spring_opening(model, u, s) > OPEN);
            let pts = t.springs.iter().map(|&s| spring_point(model, u, scale, s)).collect();
            lines.push(Line {
                points: pts,
                colour: if open { open_c } else { slip_c },
                width: if open { 3 } else { 2 },
            });
        }
        let title = format!(
            "step {}: {} failed ({} tension, {} shear); max |u| since phase 1: {:.0} mm",
            st.step,
            st.failed_tension + st.failed_shear,
            st.failed_tension,
            st.failed_shear,
            1e3 * st.max_displacement
        );
        panels.push(Panel { title, patches, lines });
    }
    let name = if prefix == "fig10" { "Fig. 10: paper slope" } else { "Fig. 14: Wulong" };
    let title = format!("{name}, progressive failure at four stages of phase 2");
    let style = ContourStyle {
        columns: 2,
        panel_width: 760,
        notes: vec![format!(
            "Deformed shape, displacement x {scale}. Failed joints on the front face: red = open (> 2 mm), \
             black = failed and closed (slipped). Colour: |u| since the end of phase 1, one scale for all panels."
        )],
        ..ContourStyle::default()
    };
    let file = format!("{prefix}-stages.png");
    contour_panels(&out.join(&file), &title, "|u| since phase 1", Quantity::Displacement, &panels, &style)?;
    Ok(vec![(title, file)])
}
