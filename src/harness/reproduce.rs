//! `cdem reproduce --out DIR`: every paper case from the committed meshes (or
//! regenerated with gmsh first, `--regenerate`), run, checked and drawn:
//! `DIR/report.md` with the validation table and the figures (PNG, plotters).
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
use crate::harness::figures::{line_plot, section_contour, Patch, Scale, Series};
use crate::harness::registry::{self as reg, Case};
use crate::harness::report::{Check, Table};
use crate::harness::section::{element_mean_displacement, front_patches, front_patches_of_cells};
use crate::harness::validation;

/// Runs everything into `out` and writes `out/report.md`.
pub fn reproduce(out: &Path, regenerate: bool, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
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
    // 9. The rest of the validation table: the extreme suite, pySlope, the
    // performance goals.
    more_rows(&mut rep, progress)?;
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
        for (id, reason) in NOT_IN_REPRODUCE {
            self.checks.push(reg::row(id).skipped(reason));
        }
        let table = Table::assemble(&reg::rows(), std::mem::take(&mut self.checks), &[], &|spec| {
            format!("not computed by cdem reproduce (a step failed to make it); see {}", spec.test)
        });
        let failures = table.failures();
        let head = format!(
            "# cdem reproduce\n\n{}; {} failing; {:.0} s in all.\n\n## Validation\n\n{}{}\n",
            table.counts(),
            failures.len(),
            seconds,
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
        Ok(())
    }
}

/// The rows of the registry that `cdem reproduce` does not compute, with the
/// reason (they are computed by `cargo test`; the table shows them skipped).
const NOT_IN_REPRODUCE: &[(&str, &str)] = &[
    ("fem/skfem/column/max-abs-uz", SKFEM_ONLY),
    ("fem/skfem/column/min-szz", SKFEM_ONLY),
    ("fem/skfem/column/all", SKFEM_ONLY),
    ("fem/skfem/slope/max-abs-uz", SKFEM_ONLY),
    ("fem/skfem/slope/min-szz", SKFEM_ONLY),
    ("fem/skfem/slope/all", SKFEM_ONLY),
    ("fem/skfem/slope-perturbed/max-abs-uz", SKFEM_ONLY),
    ("fem/skfem/slope-perturbed/min-szz", SKFEM_ONLY),
    ("fem/skfem/slope-perturbed/all", SKFEM_ONLY),
    ("lem/taylor-60", "a section built in the test: cargo test --release --test lem"),
    ("srm/block-friction", "strength reduction of the block cases: cargo test --release --test srm"),
    ("srm/block-cohesion", "strength reduction of the block cases: cargo test --release --test srm"),
    ("ensemble/segment/mean", "the analytic ensemble: cargo test --release --test ensemble"),
    ("ensemble/segment/pf", "the analytic ensemble: cargo test --release --test ensemble"),
    ("slope-failure/snapshot", PROGRESSIVE_ONLY),
    ("slope-failure/order-vs-paper", PROGRESSIVE_ONLY),
    ("wulong/snapshot", WULONG_ONLY),
    ("wulong/toe-first", WULONG_ONLY),
    ("wulong/no-slide", WULONG_ONLY),
    ("block/at-rest-15", BLOCK_ONLY),
    ("block/acceleration-30", BLOCK_ONLY),
    ("meshes/regenerated", "gmsh against the committed meshes: cargo test --release --test gmsh_regen"),
];
const SKFEM_ONLY: &str = "the FEM against the recorded scikit-fem solution: cargo test --release --test fem";
const PROGRESSIVE_ONLY: &str =
    "the zones of the failure sequence are cut in the test: cargo test --release --test progressive_slope";
const WULONG_ONLY: &str = "the bands and cracks are found in the test: cargo test --release --test wulong";
const BLOCK_ONLY: &str = "physical-time run built in the test: cargo test --release --test sliding_block";

/// Step 9, the rows no figure needs: the extreme suite, our Bishop against
/// pySlope on the same circles, the study's column point, the performance
/// goals (measured in this run).
fn more_rows(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progress("extreme suite");
    for case in reg::extreme_cases() {
        let r = run_scene(&case.scene()?, &mut |_, _| {})?;
        rep.checks.push(validation::extreme_row(&case, &r));
    }
    rep.checks.extend(validation::pyslope_rows(Path::new("."))?);
    let (cdem, fem) = crate::harness::study::column_base_point()?;
    rep.checks.push(reg::row("study/column/cdem-l2").value(cdem, 0.0, 0.0));
    rep.checks.push(reg::row("study/column/fem-l2").value(fem, 0.0, 0.0));
    progress("performance goals");
    let (scene, model) = crate::harness::perf::headline::paper_slope(Path::new("."))?;
    let h = crate::harness::perf::headline::headline(Path::new("."), &scene, &model, progress)?;
    rep.checks.extend(validation::perf_rows(&h));
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

/// Figs. 6 (sigma_zz) and 7 (u_z) of the elastic slope, CDEM and FEM, on the front section.
fn figs6_7_contours(rep: &mut Report, r: &RunResult, fem: &FemSolution) -> Result<(), Error> {
    let stress = r.stress.clone().unwrap_or_default();
    let figs: [(&str, &str, Vec<Patch>); 4] = [
        ("fig6-szz-cdem.png", "CDEM sigma_zz (Pa)", front_patches(&r.model, |e| stress[e][2])),
        (
            "fig6-szz-fem.png",
            "FEM sigma_zz (Pa)",
            front_patches_of_cells(&fem.coords, &fem.cells, |e| fem.stress[e][2]),
        ),
        (
            "fig7-uz-cdem.png",
            "CDEM u_z (m)",
            front_patches(&r.model, |e| element_mean_displacement(&r.model, &r.state.u, e, 2)),
        ),
        (
            "fig7-uz-fem.png",
            "FEM u_z (m)",
            front_patches_of_cells(&fem.coords, &fem.cells, |e| {
                fem.cells[e].corners().iter().map(|&n| fem.u[3 * n + 2]).sum::<f64>()
                    / fem.cells[e].corners().len() as f64
            }),
        ),
    ];
    for (file, title, patches) in &figs {
        section_contour(&rep.path(file), title, title, patches, &[])?;
        rep.figure(title, file);
    }
    Ok(())
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
    rep.checks.push(validation::paper_lem_row(&paper));
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
    let on_circle = crate::lem::Circle { xc: circle.xc, zc: circle.zc, r: reg::slip_circle_radius() };
    let fs_circle =
        crate::lem::evaluate_circle(&lem.section, on_circle, 50).ok().and_then(|f| f.bishop).unwrap_or(f64::NAN);
    let cdem_stress = rs
        .stress
        .as_ref()
        .and_then(|st| from_stresses(&mesh, &rs.model.mesh_coords, "slip", &circle, st))
        .unwrap_or_default();
    let k_cdem = safety_factors(&cdem_stress, c, tan_phi);
    rep.checks.extend(validation::slip_rows(k_sp.k, k_cdem.k, k_fem.k, fs_circle, &seg, rs.summary.wall_s));
    let _ = writeln!(rep.md, "## Slip circle (Fig. 9)\n\nK_i sign segments (CDEM springs, toe to crest, runs under 2 m merged): {}. The paper: ab -, bc +, cd -, de +.\n", seg.iter().map(|g| format!("{} {:.0}-{:.0} m", if g.sign > 0 { "+" } else { "-" }, g.s0, g.s1)).collect::<Vec<_>>().join(", "));
    fig9(rep, &rs, (&pts_sp, &k_sp), (&pts_fem, &k_fem))
}

/// Fig. 9: the slip surface on the u_z contours of the section, and K_i
/// along it from toe to crest (CDEM springs, FEM stresses).
fn fig9(
    rep: &mut Report,
    rs: &RunResult,
    springs: (&[SurfacePoint], &SafetyFactors),
    fem: (&[SurfacePoint], &SafetyFactors),
) -> Result<(), Error> {
    let clamped = |(pts, k): (&[SurfacePoint], &SafetyFactors)| -> Vec<(f64, f64)> {
        pts.iter().zip(&k.k_i).map(|(p, &k)| (p.s, k.clamp(-5.0, 5.0))).collect()
    };
    let (ki_sp, ki_fem) = (clamped(springs), clamped(fem));
    line_plot(
        &rep.path("fig9-ki.png"),
        "K_i along the slip surface, toe (s = 0) to crest (clamped to +-5)",
        "s (m)",
        "K_i",
        &[Series { name: "CDEM springs", points: &ki_sp }, Series { name: "FEM stresses", points: &ki_fem }],
        Scale::Linear,
        Scale::Linear,
    )?;
    let p = front_patches(&rs.model, |e| element_mean_displacement(&rs.model, &rs.state.u, e, 2));
    let title = "Slip surface (LEM critical circle) on u_z";
    section_contour(&rep.path("fig9-surface.png"), title, "u_z (m)", &p, &[reg::slip_arc()])?;
    rep.figure("slip surface", "fig9-surface.png");
    rep.figure("K_i", "fig9-ki.png");
    Ok(())
}

/// Step 6, Fig. 10: progressive failure of the paper slope on its slip circle.
fn fig10_slope_failure(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progressive_failure(rep, "slope", reg::SLOPE_SLIP, "fig10", progress)
}

/// Step 7, Fig. 14: progressive failure of the Wulong slope.
fn fig14_wulong(rep: &mut Report, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    progressive_failure(rep, "Wulong", reg::WULONG, "fig14", progress)
}

/// Both phases of a scene with `[failure]` (skipped if the scene is absent or
/// has none): a summary paragraph and the displacement since phase 1 at three
/// stages ([`stage_figures`], files `<prefix>-*.png`).
fn progressive_failure(
    rep: &mut Report,
    name: &str,
    case: Case,
    prefix: &str,
    progress: &mut dyn FnMut(&str),
) -> Result<(), Error> {
    if !case.path().exists() {
        return Ok(());
    }
    progress(&format!("progressive failure: {name}"));
    let scene = case.scene()?;
    if scene.failure.is_none() {
        return Ok(());
    }
    let t0 = Instant::now();
    let mut snapshots = StageSnapshots::default();
    let pr = run_watched(&scene, &mut snapshots)?;
    let f = pr.failure.as_ref().expect("a [failure] scene has phase 2");
    let last = f.stages.last().copied();
    let _ = writeln!(
        rep.md,
        "## Progressive failure: {name} ({prefix})\n\nPhase 1: {} steps; phase 2: {:?} after {} steps ({:.1} s); failed springs: {} tension, {} shear; displacement since phase 1 {:.3} m.\n",
        pr.elastic.steps,
        f.end,
        f.report.steps,
        t0.elapsed().as_secs_f64(),
        last.map_or(0, |s| s.failed_tension),
        last.map_or(0, |s| s.failed_shear),
        last.map_or(0.0, |s| s.max_displacement)
    );
    for (title, file) in stage_figures(&pr, &snapshots, &rep.out, prefix)? {
        rep.figure(&title, &file);
    }
    Ok(())
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

/// Displacement (since `base`) contours of a progressive run at three stages.
pub fn stage_figures(
    r: &RunResult,
    snapshots: &StageSnapshots,
    out: &Path,
    prefix: &str,
) -> Result<Vec<(String, String)>, Error> {
    let Some(f) = &r.failure else { return Ok(Vec::new()) };
    let n = f.stages.len();
    let mut files = Vec::new();
    if n == 0 {
        return Ok(files);
    }
    for (tag, idx) in [("early", 0), ("middle", n / 2), ("end", n - 1)] {
        let du: Vec<f64> = snapshots.u[idx].iter().zip(&f.u_elastic).map(|(a, b)| a - b).collect();
        for (comp, name) in [(0, "u_x"), (2, "u_z")] {
            let p = front_patches(&r.model, |e| element_mean_displacement(&r.model, &du, e, comp));
            let file = format!("{prefix}-{tag}-{name}.png");
            let title = format!("Phase 2, step {}: {name} since phase 1", f.stages[idx].step);
            section_contour(&out.join(&file), &title, &format!("{name} (m)"), &p, &[])?;
            files.push((title, file));
        }
    }
    Ok(files)
}
