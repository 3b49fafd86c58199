//! `cdem reproduce --out DIR`: every paper case from the committed meshes (or
//! regenerated with gmsh first, `--regenerate`), run, checked and drawn:
//! `DIR/report.md` with the validation table and the figures (PNG, plotters).
//!
//! 1. meshes; 2. column (analytic); 3. elastic slope, CDEM and FEM (Figs. 6-7,
//! convergence history); 4. LEM (ACADS 1(a), paper slope); 5. eq. 21 and K_i
//! on the slip circle (Fig. 9); 6. progressive failure of the slope (Fig. 10);
//! 7. Wulong (Fig. 14); 8. error against run time.

use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::analysis::slip::{from_springs, from_stresses, SlipCircle};
use crate::analysis::{safety_factors, sign_segments};
use crate::drivers::run_scene;
use crate::drivers::{run_watched, RunResult, StageSnapshots};
use crate::error::Error;
use crate::harness::figures::{line_plot, section_contour, Scale, Series};
use crate::harness::report::{markdown_table, Check};
use crate::harness::section::{element_mean_displacement, front_patches, front_patches_of_cells};
use crate::scene::Scene;

/// The slip circle of verification/cases/slope-slip/slope-slip.geo.
pub const SLIP_CIRCLE: SlipCircle = SlipCircle { xc: 24.006, zc: 63.222, toe: [20.0, 20.0] };

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
}

fn analytic_column_top() -> f64 {
    // references/column.md
    let (h, rho, g, e, nu) = (40.0, 2100.0, 9.81, 3.0e8, 0.3);
    -rho * g * h * h / (2.0 * e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)))
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

/// Runs everything into `out` and writes `out/report.md`.
pub fn reproduce(out: &Path, regenerate: bool, progress: &mut dyn FnMut(&str)) -> Result<(), Error> {
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    let mut rep = Report { out: out.to_path_buf(), checks: Vec::new(), md: String::new() };
    let t_all = Instant::now();

    // 1. Meshes.
    if regenerate {
        let n = regenerate_meshes(progress)?;
        let _ = writeln!(rep.md, "Meshes regenerated from {n} .geo files with gmsh.\n");
    }

    // 2. Column.
    progress("column");
    let top = analytic_column_top();
    for (name, file, tol) in [("column, springs", "column.toml", 0.01), ("column, merged", "column-merged.toml", 1e-5)]
    {
        let scene = Scene::load(&Path::new("verification/cases/column").join(file))?;
        let r = run_scene(&scene, &mut |_, _| {})?;
        let top_nodes: Vec<usize> =
            (0..r.model.n_nodes()).filter(|&i| (r.model.x0[i][2] - 40.0).abs() < 1e-9).collect();
        let uz = top_nodes.iter().map(|&i| r.state.u[3 * i + 2]).sum::<f64>() / top_nodes.len() as f64;
        rep.checks.push(Check::new(name, "top u_z (m)", uz, top, tol, "references/column.md", r.summary.wall_s));
    }

    // 3. Elastic slope: CDEM and FEM on the same perturbed mesh.
    progress("elastic slope (CDEM, FEM)");
    let scene = Scene::load(Path::new("verification/cases/slope/slope.toml"))?;
    let r = run_scene(&scene, &mut |_, _| {})?;
    let fem = crate::drivers::solve_fem(&scene)?;
    let (c, f) = (&r.summary, &fem.summary);
    let l2 = crate::analysis::compare::relative_l2_displacement(&r.model, &r.state.u, &fem.u);
    let (cs, fs) = (c.min_szz.unwrap_or(f64::NAN), f.min_szz.unwrap_or(f64::NAN));
    rep.checks.extend([
        Check::new("paper slope, CDEM vs FEM", "max |u_z| (m)", c.max_abs_uz, f.max_abs_uz, 0.01, "cdem fem", c.wall_s),
        Check::new("paper slope, CDEM vs FEM", "min sigma_zz (Pa)", cs, fs, 0.01, "cdem fem", c.wall_s),
        Check::new("paper slope, CDEM vs FEM", "relative L2 error of u", l2, 0.0, 0.01, "cdem fem", c.wall_s),
        Check::new(
            "paper slope, CDEM vs paper",
            "max |u_z| (m)",
            c.max_abs_uz,
            4.18e-2,
            f64::NAN,
            "references/paper.md",
            c.wall_s,
        ),
        Check::new(
            "paper slope, FEM vs ANSYS (paper)",
            "max |u_z| (m)",
            f.max_abs_uz,
            4.16e-2,
            f64::NAN,
            "references/paper.md",
            f.wall_s,
        ),
        Check::new(
            "paper slope, CDEM vs paper",
            "min sigma_zz (Pa)",
            cs,
            -7.89e5,
            f64::NAN,
            "references/paper.md",
            c.wall_s,
        ),
        Check::new(
            "paper slope, FEM vs ANSYS (paper)",
            "min sigma_zz (Pa)",
            fs,
            -7.81e5,
            f64::NAN,
            "references/paper.md",
            f.wall_s,
        ),
    ]);
    let _ = writeln!(
        rep.md,
        "## Elastic slope (Figs. 6-7)\n\nCDEM: {} steps, {:.1} s; FEM: {:.2} s.\n",
        c.steps, c.wall_s, f.wall_s
    );
    let stress = r.stress.clone().unwrap_or_default();
    let figs: [(&str, &str, Vec<crate::harness::figures::Patch>); 4] = [
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
    let ratio: Vec<(f64, f64)> = r.elastic.history.iter().map(|h| (h.step as f64, h.unbalanced_ratio)).collect();
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
        "Elastic slope: convergence of dynamic relaxation",
        "step",
        "value",
        &[
            Series { name: "unbalanced-force ratio", points: &ratio },
            Series { name: "kinetic energy / max", points: &ke },
        ],
        Scale::Linear,
        Scale::Log,
    )?;
    rep.figure("convergence history", "history-slope.png");

    // 4. Limit equilibrium.
    progress("limit equilibrium");
    let acads = crate::lem::analyse(&crate::lem::LemInput::load(Path::new("verification/lem/acads-1a.toml"))?)?;
    let paper = crate::lem::analyse(&crate::lem::LemInput::load(Path::new("verification/lem/paper-slope.toml"))?)?;
    if let (Some(b), Some(s)) = (acads.fs.bishop, acads.fs.spencer) {
        rep.checks.extend([
            Check::new("ACADS 1(a)", "Bishop FS vs Slide", b, 0.987, 0.015, "references/lem.md", acads.wall_s),
            Check::new("ACADS 1(a)", "Bishop FS vs referee", b, 1.0, 0.015, "references/lem.md", acads.wall_s),
            Check::new("ACADS 1(a)", "Spencer FS vs Slide", s, 0.986, 0.015, "references/lem.md", acads.wall_s),
            Check::new("ACADS 1(a)", "Spencer FS vs referee", s, 1.0, f64::NAN, "references/lem.md", acads.wall_s),
        ]);
    }
    let fs_lem = paper.fs.bishop.unwrap_or(f64::NAN);
    rep.checks.push(Check::new(
        "paper slope LEM",
        "Bishop FS (0.01 absolute)",
        fs_lem,
        1.084,
        0.01 / 1.084,
        "references/paper.md",
        paper.wall_s,
    ));

    // 5. Eq. 21 and K_i on the slip circle (Fig. 9).
    progress("eq. 21 on the slip circle");
    let mut slip_scene = Scene::load(Path::new("verification/cases/slope-slip/slope-slip.toml"))?;
    slip_scene.failure = None; // the elastic state: phase 1 only
    let rs = run_scene(&slip_scene, &mut |_, _| {})?;
    let fem_s = crate::drivers::solve_fem(&slip_scene)?;
    let mesh = crate::mesh::gmsh::read_msh(&slip_scene.mesh_path())?;
    let tan_phi = 18f64.to_radians().tan();
    let pts_sp = from_springs(&rs.model, &rs.state.u, &rs.state.springs, "slip", &SLIP_CIRCLE).unwrap_or_default();
    let pts_fem = from_stresses(&mesh, &fem_s.coords, "slip", &SLIP_CIRCLE, &fem_s.stress).unwrap_or_default();
    let (k_sp, k_fem) = (safety_factors(&pts_sp, 16e3, tan_phi), safety_factors(&pts_fem, 16e3, tan_phi));
    rep.checks.extend([
        Check::new(
            "slip circle",
            "eq. 21 K, CDEM springs vs LEM",
            k_sp.k,
            fs_lem,
            0.02,
            "references/lem.md",
            rs.summary.wall_s,
        ),
        Check::new(
            "slip circle",
            "eq. 21 K, FEM stresses vs LEM",
            k_fem.k,
            fs_lem,
            f64::NAN,
            "references/lem.md",
            fem_s.summary.wall_s,
        ),
        Check::new(
            "slip circle",
            "eq. 21 K, CDEM springs vs paper's 1.086",
            k_sp.k,
            1.086,
            f64::NAN,
            "references/paper.md",
            rs.summary.wall_s,
        ),
    ]);
    let s: Vec<f64> = pts_sp.iter().map(|p| p.s).collect();
    let seg = sign_segments(&s, &k_sp.k_i, 2.0);
    let _ = writeln!(rep.md, "## Slip circle (Fig. 9)\n\nK_i sign segments (CDEM springs, toe to crest, runs under 2 m merged): {}. The paper: ab -, bc +, cd -, de +.\n", seg.iter().map(|g| format!("{} {:.0}-{:.0} m", if g.sign > 0 { "+" } else { "-" }, g.s0, g.s1)).collect::<Vec<_>>().join(", "));
    let ki_sp: Vec<(f64, f64)> = pts_sp.iter().zip(&k_sp.k_i).map(|(p, &k)| (p.s, k.clamp(-5.0, 5.0))).collect();
    let ki_fem: Vec<(f64, f64)> = pts_fem.iter().zip(&k_fem.k_i).map(|(p, &k)| (p.s, k.clamp(-5.0, 5.0))).collect();
    line_plot(
        &rep.path("fig9-ki.png"),
        "K_i along the slip surface, toe (s = 0) to crest (clamped to +-5)",
        "s (m)",
        "K_i",
        &[Series { name: "CDEM springs", points: &ki_sp }, Series { name: "FEM stresses", points: &ki_fem }],
        Scale::Linear,
        Scale::Linear,
    )?;
    let r_c = ((SLIP_CIRCLE.toe[0] - SLIP_CIRCLE.xc).powi(2) + (SLIP_CIRCLE.toe[1] - SLIP_CIRCLE.zc).powi(2)).sqrt();
    let a0 = (SLIP_CIRCLE.toe[1] - SLIP_CIRCLE.zc).atan2(SLIP_CIRCLE.toe[0] - SLIP_CIRCLE.xc);
    let a1 = (40.0 - SLIP_CIRCLE.zc).atan2((r_c * r_c - (40.0 - SLIP_CIRCLE.zc).powi(2)).sqrt());
    let arc: Vec<(f64, f64)> = (0..=100)
        .map(|k| a0 + (a1 - a0) * k as f64 / 100.0)
        .map(|a| (SLIP_CIRCLE.xc + r_c * a.cos(), SLIP_CIRCLE.zc + r_c * a.sin()))
        .collect();
    let p = front_patches(&rs.model, |e| element_mean_displacement(&rs.model, &rs.state.u, e, 2));
    section_contour(&rep.path("fig9-surface.png"), "Slip surface (LEM critical circle) on u_z", "u_z (m)", &p, &[arc])?;
    rep.figure("slip surface", "fig9-surface.png");
    rep.figure("K_i", "fig9-ki.png");

    // 6-7. Progressive failure: the slope (Fig. 10) and Wulong (Fig. 14).
    for (name, path, prefix) in [
        ("slope", "verification/cases/slope-slip/slope-slip.toml", "fig10"),
        ("Wulong", "verification/cases/wulong/wulong.toml", "fig14"),
    ] {
        if !Path::new(path).exists() {
            continue;
        }
        progress(&format!("progressive failure: {name}"));
        let scene = Scene::load(Path::new(path))?;
        if scene.failure.is_none() {
            continue;
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
        for (title, file) in stage_figures(&pr, &snapshots, out, prefix)? {
            rep.figure(&title, &file);
        }
    }

    // 8. Error against run time.
    progress("error against run time");
    let study_dir = out.join("study");
    crate::harness::study::run_study(&study_dir, progress)?;
    let table =
        std::fs::read_to_string(study_dir.join("study.md")).map_err(|e| Error::io(study_dir.join("study.md"), e))?;
    let _ = writeln!(rep.md, "## Error against run time\n\nRelative L2 error of the displacement field (column: analytic; slope: FEM on the 0.5 m mesh), one factor varied at a time.\n\n{table}");
    rep.figure("column", "study/study-column.png");
    rep.figure("slope", "study/study-slope.png");

    let failed = rep.checks.iter().filter(|c| !c.passed()).count();
    let head = format!(
        "# cdem reproduce\n\n{} checks, {} failed; {:.0} s in all.\n\n## Validation\n\n{}\n",
        rep.checks.len(),
        failed,
        t_all.elapsed().as_secs_f64(),
        markdown_table(&rep.checks)
    );
    crate::output::write_atomic(&out.join("report.md"), format!("{head}{}", rep.md).as_bytes())?;
    progress(&format!("wrote {}", out.join("report.md").display()));
    Ok(())
}
