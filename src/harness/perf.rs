//! Performance figures (issue: performance), measured in-process so that one
//! run puts every ratio side by side: the criterion benches measure the same
//! things more carefully; this module gives them to the validation report
//! (`tests/performance.rs`) and to `cdem perf`, which adds the damping table
//! and the growth with size (references/performance.md).
//!
//! - [`stream_triad`]: the machine's memory bandwidth (STREAM triad);
//! - [`step_bytes`]: the bytes one step must move (counted as in
//!   references/performance.md), so `bytes / step time` is the step's
//!   effective bandwidth;
//! - [`time_steps`], [`time_dr`], [`time_fem`]: a step, dynamic relaxation to
//!   the scene's tolerance, the implicit FEM solve of the same mesh;
//! - [`damping_table`]: damping kind x mass scaling x block masses on one scene;
//! - [`scaling_study`] and [`fit_power`]: cost against size, fitted exponents.
//!
//! Times are wall-clock on whatever else the machine is doing: they are
//! reported, never asserted.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Serialize;

use crate::error::Error;
use crate::model::Model;
use crate::scene::Scene;
use crate::solver::{DampingKind, Solver, SolverParams, State};

/// STREAM triad `a = b + s c` over three arrays of `n` f64 on the current
/// rayon pool: the best of `repeats` passes, in GB/s (24 B per iteration;
/// the write-allocate read is not counted, as in STREAM).
pub fn stream_triad(n: usize, repeats: usize) -> f64 {
    let mut a = vec![0.0; n];
    let b: Vec<f64> = (0..n).map(|i| i as f64).collect();
    let c: Vec<f64> = (0..n).map(|i| (n - i) as f64).collect();
    let mut best = f64::INFINITY;
    for _ in 0..repeats.max(1) {
        let t = Instant::now();
        triad_par(&mut a, &b, &c, 3.0);
        best = best.min(t.elapsed().as_secs_f64());
    }
    std::hint::black_box(&a);
    24.0 * n as f64 / best / 1e9
}

/// STREAM's triad `a[i] = b[i] + s c[i]`, one thread.
pub fn triad(a: &mut [f64], b: &[f64], c: &[f64], s: f64) {
    for ((a, b), c) in a.iter_mut().zip(b).zip(c) {
        *a = b + s * c;
    }
}

/// The triad over the current rayon pool, in chunks of 64 Ki elements.
pub fn triad_par(a: &mut [f64], b: &[f64], c: &[f64], s: f64) {
    use rayon::prelude::*;
    const CHUNK: usize = 1 << 16;
    a.par_chunks_mut(CHUNK).zip(b.par_chunks(CHUNK)).zip(c.par_chunks(CHUNK)).for_each(|((a, b), c)| triad(a, b, c, s));
}

/// Bytes one elastic step moves (references/performance.md, "Bytes per unit
/// of work"): per element `K_e` (24 x 24 f64), the corner gather and the
/// slot write (4992 B); per spring 145 B; per node copy the gather (60 B +
/// 28 B per spring end) and the update (164 B); with block masses each copy
/// also reads its block rows, `3 x 3 n_c` f64 for a mesh node of `n_c`
/// copies, and the two slot-order passes move 151 B more per copy (the
/// force gather reads `f_ext`, `f_int`, fixity and the slot's node, 55 B,
/// and writes 24 B; the product writes 24 B of acceleration that the update
/// reads, 24 B, through `slot_of`, 4 B; the cluster range, 8 B, and the
/// row offset, 8 B; the cluster's forces are re-read from cache).
pub fn step_bytes(model: &Model, block: bool) -> f64 {
    let (n_e, n_s, n_n) = (model.elements.len() as f64, model.springs.len() as f64, model.n_nodes() as f64);
    let ends = if n_n > 0.0 { 2.0 * n_s / n_n } else { 0.0 };
    let mut bytes = 4992.0 * n_e + 145.0 * n_s + (60.0 + 28.0 * ends + 164.0) * n_n;
    if block {
        let mut copies = std::collections::HashMap::<u32, f64>::new();
        for &m in &model.mesh_node {
            *copies.entry(m).or_default() += 1.0;
        }
        // Sum over copies of 72 n_c B = sum over mesh nodes of 72 n_c^2 B.
        bytes += copies.values().map(|n_c| 72.0 * n_c * n_c).sum::<f64>() + 151.0 * n_n;
    }
    bytes
}

/// One step's cost on a model.
#[derive(Debug, Clone, Serialize)]
pub struct StepFigure {
    pub elements: usize,
    pub block_mass: bool,
    /// Seconds per step (median of 5 batches).
    pub step_s: f64,
    /// Elements times steps per second (millions).
    pub mega_element_steps_per_s: f64,
    pub bytes_per_step: f64,
    /// `bytes_per_step / step_s` (GB/s).
    pub gbs: f64,
}

/// Times `steps` steps in 5 batches after 20 warm-up steps from rest; the
/// median batch gives the time per step.
pub fn time_steps(model: &Model, params: &SolverParams, steps: usize) -> Result<StepFigure, Error> {
    let mut solver = Solver::new(model, params.clone())?;
    let mut state = State::new(model);
    for _ in 0..20 {
        solver.step(model, &mut state)?;
    }
    let per_batch = steps.div_ceil(5).max(1);
    let mut batches = Vec::with_capacity(5);
    for _ in 0..5 {
        let t = Instant::now();
        for _ in 0..per_batch {
            solver.step(model, &mut state)?;
        }
        batches.push(t.elapsed().as_secs_f64() / per_batch as f64);
    }
    batches.sort_by(f64::total_cmp);
    let step_s = batches[2];
    let block = params.uses_block_mass();
    let bytes = step_bytes(model, block);
    Ok(StepFigure {
        elements: model.elements.len(),
        block_mass: block,
        step_s,
        mega_element_steps_per_s: model.elements.len() as f64 / step_s / 1e6,
        bytes_per_step: bytes,
        gbs: bytes / step_s / 1e9,
    })
}

/// Dynamic relaxation from rest to the scene's tolerance.
#[derive(Debug, Clone, Serialize)]
pub struct DrFigure {
    pub converged: bool,
    pub steps: usize,
    /// `Solver::new` (time step, block masses) plus `relax`; the model is built.
    pub seconds: f64,
    pub max_abs_uz: f64,
}

pub fn time_dr(model: &Model, params: &SolverParams) -> Result<DrFigure, Error> {
    let t = Instant::now();
    let (state, report) = crate::drivers::run::relax_elastic(model, params, usize::MAX)?;
    let seconds = t.elapsed().as_secs_f64();
    let max_abs_uz = state.u.chunks(3).map(|d| d[2].abs()).fold(0.0, f64::max);
    Ok(DrFigure { converged: report.converged, steps: report.steps, seconds, max_abs_uz })
}

/// The FEM solve of the scene end to end (`fem::solve_scene`: read, perturb,
/// assemble, factor, solve, stresses): the best of `repeats`, and the free
/// unknowns.
pub fn time_fem(scene: &Scene, repeats: usize) -> Result<(f64, usize), Error> {
    let mut best = f64::INFINITY;
    let mut dofs = 0;
    for _ in 0..repeats.max(1) {
        let t = Instant::now();
        let sol = crate::drivers::solve_fem(scene)?;
        best = best.min(t.elapsed().as_secs_f64());
        dofs = sol.free_dofs;
    }
    Ok((best, dofs))
}

/// Least-squares fit of `y = a x^p` on logarithms: `(p, a)`.
pub fn fit_power(x: &[f64], y: &[f64]) -> (f64, f64) {
    let n = x.len().min(y.len()) as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = x.iter().zip(y).map(|(x, y)| (x.ln(), y.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
    let p = sxy / sxx;
    (p, (my - p * mx).exp())
}

/// One row of the damping table.
#[derive(Debug, Clone, Serialize)]
pub struct DampingRow {
    pub damping: String,
    pub mass_scaling: bool,
    pub block_mass: bool,
    /// "converged", "max_steps" or the solver's error.
    pub outcome: String,
    pub steps: usize,
    pub seconds: f64,
    pub max_abs_uz: f64,
}

/// Every damping kind with and without mass scaling, plus viscous damping
/// with node-block masses, on one model, each from rest to the tolerance
/// (at most `max_steps`).
pub fn damping_table(
    model: &Model,
    base: &SolverParams,
    max_steps: usize,
    progress: &mut dyn FnMut(&str),
) -> Vec<DampingRow> {
    let mut variants = Vec::new();
    for damping in [DampingKind::Local, DampingKind::Viscous, DampingKind::Kinetic] {
        for mass_scaling in [true, false] {
            variants.push(SolverParams { damping, mass_scaling, block_mass: Some(false), max_steps, ..base.clone() });
        }
    }
    variants.push(SolverParams {
        damping: DampingKind::Viscous,
        mass_scaling: true,
        block_mass: Some(true),
        max_steps,
        ..base.clone()
    });
    variants
        .into_iter()
        .map(|p| {
            let name = format!("{:?}", p.damping).to_lowercase();
            progress(&format!(
                "damping: {name}, mass scaling {}, block masses {}",
                p.mass_scaling,
                p.uses_block_mass()
            ));
            let t = Instant::now();
            let (outcome, steps, max_abs_uz) = match time_dr(model, &p) {
                Ok(f) => ((if f.converged { "converged" } else { "max_steps" }).to_string(), f.steps, f.max_abs_uz),
                Err(e) => (e.to_string(), 0, f64::NAN),
            };
            DampingRow {
                damping: name,
                mass_scaling: p.mass_scaling,
                block_mass: p.uses_block_mass(),
                outcome,
                steps,
                seconds: t.elapsed().as_secs_f64(),
                max_abs_uz,
            }
        })
        .collect()
}

/// One resolution of the scaling study.
#[derive(Debug, Clone, Serialize)]
pub struct ScalingRow {
    /// The `.geo`'s `refine` (elements = 1000 refine^2 for the paper slope).
    pub refine: f64,
    pub elements: usize,
    pub node_copies: usize,
    pub springs: usize,
    pub build_s: f64,
    /// Per step, with the scene's solver (block masses).
    pub step_s: f64,
    pub mega_element_steps_per_s: f64,
    pub gbs: f64,
    pub dr_steps: usize,
    pub dr_converged: bool,
    pub dr_s: f64,
    /// DR steps with lumped masses, measured only up to `lumped_up_to` elements.
    pub lumped_steps: Option<usize>,
    pub fem_s: f64,
    pub fem_dofs: usize,
}

/// Cost against size on `scene` with the meshes given as `(refine, mesh)`.
pub fn scaling_study(
    scene: &Scene,
    meshes: &[(f64, PathBuf)],
    lumped_up_to: usize,
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<ScalingRow>, Error> {
    let mut rows = Vec::new();
    for (refine, mesh) in meshes {
        let mut s = scene.clone();
        s.mesh.file = mesh.clone();
        progress(&format!("scaling: refine {refine}: build"));
        let t = Instant::now();
        let model = crate::drivers::build_model(&s)?;
        let build_s = t.elapsed().as_secs_f64();
        let n = model.elements.len();
        progress(&format!("scaling: {n} elements: steps"));
        let steps = (2_000_000 / n.max(1)).clamp(20, 500);
        let step = time_steps(&model, &s.solver, steps)?;
        progress(&format!("scaling: {n} elements: DR ({:.1} ms per step)", 1e3 * step.step_s));
        let dr = time_dr(&model, &s.solver)?;
        let lumped_steps = if n <= lumped_up_to {
            progress(&format!("scaling: {n} elements: DR with lumped masses"));
            Some(time_dr(&model, &SolverParams { block_mass: Some(false), ..s.solver.clone() })?.steps)
        } else {
            None
        };
        let (node_copies, springs) = (model.n_nodes(), model.springs.len());
        drop(model); // the FEM solve of the largest meshes needs the memory
        progress(&format!("scaling: {n} elements: FEM"));
        let (fem_s, fem_dofs) = time_fem(&s, 1)?;
        rows.push(ScalingRow {
            refine: *refine,
            elements: n,
            node_copies,
            springs,
            build_s,
            step_s: step.step_s,
            mega_element_steps_per_s: step.mega_element_steps_per_s,
            gbs: step.gbs,
            dr_steps: dr.steps,
            dr_converged: dr.converged,
            dr_s: dr.seconds,
            lumped_steps,
            fem_s,
            fem_dofs,
        });
    }
    Ok(rows)
}

/// The fitted exponents of the scaling study against the element count.
#[derive(Debug, Clone, Serialize)]
pub struct Exponents {
    pub step_s: f64,
    pub dr_steps: f64,
    pub dr_s: f64,
    pub fem_s: f64,
}

pub fn exponents(rows: &[ScalingRow]) -> Exponents {
    let n: Vec<f64> = rows.iter().map(|r| r.elements as f64).collect();
    let fit = |f: &dyn Fn(&ScalingRow) -> f64| fit_power(&n, &rows.iter().map(f).collect::<Vec<_>>()).0;
    Exponents {
        step_s: fit(&|r| r.step_s),
        dr_steps: fit(&|r| r.dr_steps as f64),
        dr_s: fit(&|r| r.dr_s),
        fem_s: fit(&|r| r.fem_s),
    }
}

/// The paper slope's `.geo` at `refine`, meshed with gmsh into `dir`
/// (`slope-r<refine>.msh`); the existing file is reused.
pub fn slope_mesh(slope_geo: &Path, refine: u32, dir: &Path) -> Result<PathBuf, Error> {
    let msh = dir.join(format!("slope-r{refine}.msh"));
    if msh.is_file() {
        return Ok(msh);
    }
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let geo = dir.join(format!("slope-r{refine}.geo"));
    let include = slope_geo.canonicalize().map_err(|e| Error::io(slope_geo, e))?;
    let text = format!(
        "// The paper slope at refine = {refine} (cdem perf).\nrefine = {refine};\nInclude \"{}\";\n",
        include.display()
    );
    std::fs::write(&geo, text).map_err(|e| Error::io(&geo, e))?;
    crate::mesh::gmsh::regenerate(&geo, &msh)?;
    Ok(msh)
}

/// The damping rows as a Markdown table.
pub fn damping_markdown(damping: &[DampingRow]) -> String {
    let mut md = String::new();
    if !damping.is_empty() {
        md.push_str("| damping | mass scaling | block masses | outcome | steps | wall (s) | max abs u_z (m) |\n|---|---|---|---|---|---|---|\n");
        for r in damping {
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {:.2} | {:.4e} |",
                r.damping, r.mass_scaling, r.block_mass, r.outcome, r.steps, r.seconds, r.max_abs_uz
            );
        }
    }
    md
}

/// The scaling rows as a Markdown table, with the fitted exponents.
pub fn scaling_markdown(scaling: &[ScalingRow]) -> String {
    let mut md = String::new();
    if !scaling.is_empty() {
        md.push_str("\n| refine | elements | node copies | springs | build (s) | step (ms) | M element-steps/s | step GB/s | DR steps | DR steps, lumped | DR (s) | FEM dofs | FEM (s) | DR / FEM |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        for r in scaling {
            let lumped = r.lumped_steps.map_or("-".to_string(), |s| s.to_string());
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {:.2} | {:.3} | {:.2} | {:.1} | {}{} | {} | {:.2} | {} | {:.3} | {:.1} |",
                r.refine,
                r.elements,
                r.node_copies,
                r.springs,
                r.build_s,
                1e3 * r.step_s,
                r.mega_element_steps_per_s,
                r.gbs,
                r.dr_steps,
                if r.dr_converged { "" } else { " (not converged)" },
                lumped,
                r.dr_s,
                r.fem_dofs,
                r.fem_s,
                r.dr_s / r.fem_s
            );
        }
        if scaling.len() >= 2 {
            let e = exponents(scaling);
            let _ = writeln!(
                md,
                "\nFitted exponents against the element count N (least squares on logs): time per step N^{:.2}, DR steps N^{:.2}, DR time N^{:.2}, FEM time N^{:.2}.",
                e.step_s, e.dr_steps, e.dr_s, e.fem_s
            );
        }
    }
    md
}

/// The four figures the issue asks for, on the paper slope, side by side.
#[derive(Debug, Clone, Serialize)]
pub struct Headline {
    /// STREAM triad on the current rayon pool (GB/s).
    pub stream_gbs: f64,
    /// The scene's step (block masses) and the lumped-mass step.
    pub step_block: StepFigure,
    pub step_lumped: StepFigure,
    pub dr_block: DrFigure,
    pub fem_s: f64,
    pub fem_dofs: usize,
    /// `(case, ours (s), pySlope (s))`: Bishop on the 20 x 20 x 10 grid,
    /// one thread; pySlope's time from references/pyslope.json.
    pub lem: Vec<(String, f64, f64)>,
}

impl Headline {
    pub fn step_fraction_of_stream(&self) -> f64 {
        self.step_block.gbs / self.stream_gbs
    }
    pub fn dr_over_fem(&self) -> f64 {
        self.dr_block.seconds / self.fem_s
    }

    /// The figures as a Markdown table, each with its goal.
    pub fn markdown(&self) -> String {
        let mut md = String::new();
        let _ = writeln!(md, "| figure | measured | goal |\n|---|---|---|");
        let _ = writeln!(md, "| stream triad (this pool) | {:.1} GB/s | - |", self.stream_gbs);
        for (name, s) in [("block masses (default)", &self.step_block), ("lumped masses", &self.step_lumped)] {
            let _ = writeln!(
                md,
                "| step, {name}, {} elements | {:.3} ms, {:.2} M element-steps/s, {:.0} B/element, {:.1} GB/s = {:.0} % of stream | >= 50 % |",
                s.elements,
                1e3 * s.step_s,
                s.mega_element_steps_per_s,
                s.bytes_per_step / s.elements as f64,
                s.gbs,
                100.0 * s.gbs / self.stream_gbs
            );
        }
        let _ = writeln!(
            md,
            "| DR to 1e-5 / FEM solve (paper slope) | {:.3} s ({} steps) / {:.4} s ({} dofs) = {:.1}x | <= 3x |",
            self.dr_block.seconds,
            self.dr_block.steps,
            self.fem_s,
            self.fem_dofs,
            self.dr_over_fem()
        );
        for (case, ours, py) in &self.lem {
            let _ = writeln!(
                md,
                "| LEM Bishop grid 20x20x10, {case}: pySlope / ours | {py:.3} s / {:.2} ms = {:.0}x | >= 100x |",
                1e3 * ours,
                py / ours
            );
        }
        md
    }
}

/// LEM cases timed against pySlope: (name in references/pyslope.json, input).
pub const LEM_CASES: [(&str, &str); 2] =
    [("paper_slope", "verification/lem/paper-slope-explicit.toml"), ("acads_1a", "verification/lem/acads-1a.toml")];

/// `base` with the search pySlope's timing repeats (scripts/pyslope_check.py):
/// Bishop on the default 20 x 20 x 10 grid only, no entry-exit search, no
/// refinement, one thread.
pub fn pyslope_grid_search(base: crate::lem::LemInput) -> crate::lem::LemInput {
    use crate::lem::{LemInput, Method, Mode, SearchSpec};
    let spec = SearchSpec { entry_exit: None, refine: false, parallel: false, ..SearchSpec::default() };
    LemInput { mode: Mode::Search(spec), methods: vec![Method::Bishop], ..base }
}

/// The time of [`pyslope_grid_search`] on the LEM input at `input`: best of
/// `repeats` (s).
pub fn time_lem_grid(input: &Path, repeats: usize) -> Result<f64, Error> {
    let input = pyslope_grid_search(crate::lem::LemInput::load(input)?);
    let mut best = f64::INFINITY;
    for _ in 0..repeats.max(1) {
        let t = Instant::now();
        crate::lem::analyse(&input)?;
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok(best)
}

/// pySlope's recorded time for our grid (`cases.<case>.timing_our_grid.total_s`).
pub fn pyslope_seconds(json: &Path, case: &str) -> Result<f64, Error> {
    let text = std::fs::read_to_string(json).map_err(|e| Error::io(json, e))?;
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| Error::io(json, std::io::Error::other(e)))?;
    v["cases"][case]["timing_our_grid"]["total_s"]
        .as_f64()
        .ok_or_else(|| Error::io(json, std::io::Error::other(format!("no cases.{case}.timing_our_grid.total_s"))))
}

/// The paper slope's scene and model (paths relative to the repository root).
pub fn paper_slope(root: &Path) -> Result<(Scene, Model), Error> {
    let scene = Scene::load(&root.join("verification/cases/slope/slope.toml"))?;
    let model = crate::drivers::build_model(&scene)?;
    Ok((scene, model))
}

/// Measures the headline figures on the paper slope's `scene` and `model`
/// ([`paper_slope`]) and the repository's LEM inputs under `root`.
pub fn headline(root: &Path, scene: &Scene, model: &Model, progress: &mut dyn FnMut(&str)) -> Result<Headline, Error> {
    progress("stream triad");
    let stream_gbs = stream_triad(8 << 20, 10);
    progress("paper slope: step");
    let step_block = time_steps(model, &scene.solver, 500)?;
    let step_lumped = time_steps(model, &SolverParams { block_mass: Some(false), ..scene.solver.clone() }, 500)?;
    progress("paper slope: dynamic relaxation");
    let dr_block = time_dr(model, &scene.solver)?;
    progress("paper slope: FEM");
    let (fem_s, fem_dofs) = time_fem(scene, 5)?;
    let mut lem = Vec::new();
    for (case, input) in LEM_CASES {
        progress(&format!("LEM grid: {case}"));
        let ours = time_lem_grid(&root.join(input), 5)?;
        lem.push((case.to_string(), ours, pyslope_seconds(&root.join("references/pyslope.json"), case)?));
    }
    Ok(Headline { stream_gbs, step_block, step_lumped, dr_block, fem_s, fem_dofs, lem })
}

/// What `cdem perf` runs.
#[derive(Debug, Clone)]
pub struct PerfOptions {
    /// Run the damping table (about 3 minutes: local damping is slow).
    pub damping: bool,
    /// Resolutions of the scaling study (`refine` of slope.geo); those
    /// without a committed mesh need gmsh on PATH.
    pub refine: Vec<f64>,
    /// Lumped-mass DR is also run up to this many elements.
    pub lumped_up_to: usize,
}

impl Default for PerfOptions {
    fn default() -> Self {
        Self { damping: true, refine: vec![0.5, 1.0, 2.0, 4.0, 7.0, 10.0], lumped_up_to: 4000 }
    }
}

/// The committed meshes of the paper slope, coarse to fine: `refine` of
/// slope.geo (1000 refine^2 hexahedra) and the path from the repository root.
pub const SLOPE_MESHES: [(f64, &str); 4] = [
    (0.5, "verification/study/slope-h4.msh"),
    (1.0, "verification/cases/slope/slope.msh"),
    (2.0, "verification/study/slope-h1.msh"),
    (4.0, "verification/study/slope-h05.msh"),
];

/// `cdem perf`: headline figures, damping table and scaling study; writes
/// `perf.md`, `damping.csv`, `scaling.csv` and `scaling.png` to `out`.
pub fn run_perf(root: &Path, out: &Path, opts: &PerfOptions, progress: &mut dyn FnMut(&str)) -> Result<String, Error> {
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    let (scene, model) = paper_slope(root)?;
    let head = headline(root, &scene, &model, progress)?;
    let damping = if opts.damping { damping_table(&model, &scene.solver, 400_000, progress) } else { Vec::new() };
    let mut meshes = Vec::new();
    for &r in &opts.refine {
        let committed = SLOPE_MESHES.iter().find(|(c, _)| *c == r).map(|(_, p)| root.join(p));
        let mesh = match committed {
            Some(p) => p,
            None if r.fract() == 0.0 && r >= 1.0 => {
                progress(&format!("gmsh: slope at refine {r}"));
                slope_mesh(&root.join("verification/cases/slope/slope.geo"), r as u32, &out.join("meshes"))?
            }
            None => {
                return Err(Error::Gmsh(format!(
                    "refine {r}: only the committed 0.5, 1, 2, 4 or a whole number can be meshed"
                )))
            }
        };
        meshes.push((r, mesh.canonicalize().map_err(|e| Error::io(&mesh, e))?));
    }
    let scaling = scaling_study(&scene, &meshes, opts.lumped_up_to, progress)?;

    write_csv(&out.join("damping.csv"), &damping)?;
    write_csv(&out.join("scaling.csv"), &scaling)?;
    if scaling.len() >= 2 {
        use crate::harness::figures::{line_plot, Scale, Series};
        let pts =
            |f: &dyn Fn(&ScalingRow) -> f64| scaling.iter().map(|r| (r.elements as f64, f(r))).collect::<Vec<_>>();
        let (step, dr, fem) = (pts(&|r| r.step_s), pts(&|r| r.dr_s), pts(&|r| r.fem_s));
        let series = [
            Series { name: "time per step", points: &step },
            Series { name: "DR to 1e-5", points: &dr },
            Series { name: "FEM solve", points: &fem },
        ];
        line_plot(
            &out.join("scaling.png"),
            "Paper slope: cost against size",
            "elements",
            "wall time (s)",
            &series,
            Scale::Log,
            Scale::Log,
        )?;
    }
    let md = format!(
        "# Performance (cdem perf)\n\n## Headline (paper slope, {} threads)\n\n{}\n## Damping (paper slope, to 1e-5)\n\n{}\n## Growth with size\n\n{}",
        rayon::current_num_threads(),
        head.markdown(),
        damping_markdown(&damping),
        scaling_markdown(&scaling)
    );
    crate::output::write_atomic(&out.join("perf.md"), md.as_bytes())?;
    Ok(md)
}

fn write_csv<T: Serialize>(path: &Path, rows: &[T]) -> Result<(), Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r).map_err(|e| Error::io(path, std::io::Error::other(e)))?;
    }
    let bytes = w.into_inner().map_err(|e| Error::io(path, std::io::Error::other(e.to_string())))?;
    crate::output::write_atomic(path, &bytes)
}
