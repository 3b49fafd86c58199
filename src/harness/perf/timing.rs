//! The timers of the solvers, on a built model or a scene: one explicit step
//! ([`time_steps`]: the median of 5 batches after a warm-up), dynamic
//! relaxation from rest to the scene's tolerance ([`time_dr`]: one run),
//! conjugate gradients to the same tolerance ([`time_pcg`]: one run), and
//! the implicit FEM solve of the same mesh ([`time_fem`]: the best of a few
//! end-to-end solves). Wall-clock times on whatever else the machine is
//! doing.

use std::time::Instant;

use rayon::prelude::*;
use serde::Serialize;

use super::bytes::step_bytes;
use crate::error::Error;
use crate::model::Model;
use crate::scene::Scene;
use crate::solver::relax::unobserved;
use crate::solver::{ElasticSolver, Pcg, Solver, SolverParams, State, StopRules};

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
/// median batch gives the time per step, [`step_bytes`] the bytes.
pub fn time_steps(model: &Model, params: &SolverParams, steps: usize) -> Result<StepFigure, Error> {
    time_steps_between(model, params, steps, &mut || {})
}

/// [`time_steps`] with `between` run before each batch (untimed): `cdem
/// perf` times a triad batch there, so that the step and the triad are
/// measured side by side.
pub fn time_steps_between(
    model: &Model,
    params: &SolverParams,
    steps: usize,
    between: &mut dyn FnMut(),
) -> Result<StepFigure, Error> {
    let mut solver = Solver::new(model, params.clone())?;
    let mut state = State::new(model);
    for _ in 0..20 {
        solver.step(model, &mut state)?;
    }
    let per_batch = steps.div_ceil(5).max(1);
    let mut batches = Vec::with_capacity(5);
    for _ in 0..5 {
        between();
        let t = Instant::now();
        for _ in 0..per_batch {
            solver.step(model, &mut state)?;
        }
        batches.push(t.elapsed().as_secs_f64() / per_batch as f64);
    }
    let step_s = median(&mut batches);
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

/// A phase-2 step of a model with plastic blocks with the kernels' AVX2
/// and baseline (SSE2) versions ([`crate::simd`]).
#[derive(Debug, Clone, Serialize)]
pub struct SimdStepFigure {
    /// Seconds per step, medians of 5 batches each.
    pub avx2_s: f64,
    pub baseline_s: f64,
    /// Whether this CPU has AVX2 (without it both run the baseline).
    pub avx2_cpu: bool,
    /// Whether the two runs ended in the same displacement, bit for bit.
    pub same_bits: bool,
}

impl SimdStepFigure {
    /// Baseline time over AVX2 time.
    pub fn speedup(&self) -> f64 {
        self.baseline_s / self.avx2_s
    }
}

/// Times `steps` phase-2 steps of `model` from its elastic state (failure
/// on, the phase's node-block masses) twice, with the AVX2 kernels and with
/// the baseline ones, in alternating batches on two copies of the same
/// trajectory: the two give the same bits, so each pair of batches does the
/// same work. Restores what the environment asks for afterwards.
pub fn time_failure_steps_simd(model: &Model, params: &SolverParams, steps: usize) -> Result<SimdStepFigure, Error> {
    let (elastic, _) = crate::drivers::run::relax_elastic(model, params, 1000)?;
    let phase2 = || -> Result<(Solver, State), Error> {
        let mut solver = Solver::with_masses(model, params.clone(), params.block_masses(true))?;
        solver.set_failure(model, true);
        Ok((solver, elastic.clone()))
    };
    // [AVX2, baseline], indexed by `baseline`.
    let mut run = [phase2()?, phase2()?];
    let mut error = None;
    let (avx2_s, baseline_s) = median_alternating(steps, |baseline| {
        crate::simd::set_baseline(baseline);
        let (solver, state) = &mut run[baseline as usize];
        if let Err(e) = solver.step(model, state) {
            error.get_or_insert(e);
        }
    });
    crate::simd::set_from_env();
    if let Some(e) = error {
        return Err(e.into());
    }
    let same_bits = run[0].1.u == run[1].1.u;
    Ok(SimdStepFigure { avx2_s, baseline_s, avx2_cpu: crate::simd::cpu_has_avx2(), same_bits })
}

/// The median of `x` (the middle value; of an even count, the upper one).
pub fn median(x: &mut [f64]) -> f64 {
    x.sort_by(f64::total_cmp);
    x[x.len() / 2]
}

/// The element pass alone (`forces::element_forces`, eq. 12) on a model.
#[derive(Debug, Clone, Serialize)]
pub struct ElementPassFigure {
    /// Seconds per pass (median of 5 batches).
    pub pass_s: f64,
    /// Bytes per element-step ([`super::bytes::element_bytes`]).
    pub bytes_per_element: f64,
    /// `bytes / pass_s` (GB/s).
    pub gbs: f64,
}

/// Times `passes` element passes in 5 batches on a smooth displacement field.
pub fn time_element_pass(model: &Model, passes: usize) -> ElementPassFigure {
    let u: Vec<f64> = (0..3 * model.n_nodes()).map(|k| 1e-3 * ((k % 7) as f64 - 3.0)).collect();
    let mut f = vec![0.0; crate::model::ELEMENT_SLOT * model.elements.len()];
    let pass_s = median_pass(passes, || {
        crate::solver::forces::element_forces(model, std::hint::black_box(&u), &mut f);
    });
    let bytes = super::bytes::element_bytes(model);
    ElementPassFigure { pass_s, bytes_per_element: bytes / model.elements.len() as f64, gbs: bytes / pass_s / 1e9 }
}

/// The element pass of plastic blocks (`forces::element_forces_plastic`)
/// against the condensed pass of the same mesh with elastic blocks
/// (issue 24, item 7: at most 2x per element).
#[derive(Debug, Clone, Serialize)]
pub struct PlasticPassFigure {
    /// Seconds per condensed pass (elastic blocks); per plastic pass with
    /// every tetrahedron elastic (a field of 1e-9 m) as a step takes it
    /// (`screened_s`: every screen armed and holding, the fast path) and
    /// with the return mappings run (`elastic_s`: the screens disarmed each
    /// pass); and with every tetrahedron yielding (1e-3 m: each return
    /// mapping runs); medians of 5 batches.
    pub condensed_s: f64,
    pub screened_s: f64,
    pub elastic_s: f64,
    pub yielding_s: f64,
    /// Seconds per pass that only computes every cell's tetrahedra's strains
    /// from its corners (no stress, no return mapping, no force): a floor
    /// under any pass that integrates each of the 24 tetrahedra, so a
    /// yielding block cannot be cheaper than `strains_s` plus the forces'
    /// pass back to the corners (about as many operations).
    pub strains_s: f64,
    /// The yielding pass with the kernels' AVX2 and baseline (SSE2)
    /// versions ([`crate::simd`]), timed in alternating batches (medians of
    /// 5 each; without AVX2 on the CPU both run the baseline).
    pub yielding_avx2_s: f64,
    pub yielding_baseline_s: f64,
}

impl PlasticPassFigure {
    /// The yielding pass's baseline time over its AVX2 time.
    pub fn avx2_speedup(&self) -> f64 {
        self.yielding_baseline_s / self.yielding_avx2_s
    }
    pub fn screened_ratio(&self) -> f64 {
        self.screened_s / self.condensed_s
    }
    pub fn elastic_ratio(&self) -> f64 {
        self.elastic_s / self.condensed_s
    }
    pub fn yielding_ratio(&self) -> f64 {
        self.yielding_s / self.condensed_s
    }
    pub fn strains_ratio(&self) -> f64 {
        self.strains_s / self.condensed_s
    }
}

/// The median of 5 batches of `passes / 5` calls of `pass` (s per call).
fn median_pass(passes: usize, mut pass: impl FnMut()) -> f64 {
    let per_batch = passes.div_ceil(5).max(1);
    pass();
    let mut batches: Vec<f64> = (0..5)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..per_batch {
                pass();
            }
            t.elapsed().as_secs_f64() / per_batch as f64
        })
        .collect();
    median(&mut batches)
}

/// `pass(false)` and `pass(true)` in alternating batches of `passes / 5`
/// calls each: the median of each's 5 batches (s per call).
fn median_alternating(passes: usize, mut pass: impl FnMut(bool)) -> (f64, f64) {
    let per_batch = passes.div_ceil(5).max(1);
    let mut batch = |which: bool| {
        let t = Instant::now();
        for _ in 0..per_batch {
            pass(which);
        }
        t.elapsed().as_secs_f64() / per_batch as f64
    };
    let (mut first, mut second) = (Vec::with_capacity(5), Vec::with_capacity(5));
    for _ in 0..5 {
        first.push(batch(false));
        second.push(batch(true));
    }
    (median(&mut first), median(&mut second))
}

/// Times the element passes of [`PlasticPassFigure`]: `elastic` and
/// `plastic` are the same mesh with elastic and with plastic blocks.
pub fn time_plastic_pass(elastic: &Model, plastic: &Model, passes: usize) -> PlasticPassFigure {
    let field =
        |scale: f64| -> Vec<f64> { (0..3 * plastic.n_nodes()).map(|k| scale * ((k % 7) as f64 - 3.0)).collect() };
    let mut f = vec![0.0; crate::model::ELEMENT_SLOT * plastic.elements.len()];
    let u = field(1e-3);
    let condensed_s = median_pass(passes, || {
        crate::solver::forces::element_forces(elastic, std::hint::black_box(&u), &mut f);
    });
    let timed = |scale: f64, f: &mut Vec<f64>| {
        let u = field(scale);
        let mut rock = plastic.rock_state();
        median_pass(passes, || {
            // The history is reset (and the screens disarmed) each pass: every
            // pass does the same work, the return mappings of every cell.
            rock.reset_history();
            crate::solver::forces::element_forces_plastic(plastic, &mut rock, std::hint::black_box(&u), f);
        })
    };
    let elastic_s = timed(1e-9, &mut f);
    let screened_s = {
        let u = field(1e-9);
        let mut rock = plastic.rock_state();
        // The first pass arms the screens; the timed ones hold.
        crate::solver::forces::element_forces_plastic(plastic, &mut rock, &u, &mut f);
        median_pass(passes, || {
            crate::solver::forces::element_forces_plastic(plastic, &mut rock, std::hint::black_box(&u), &mut f);
        })
    };
    let strains_s = {
        let u = field(1e-3);
        median_pass(passes, || {
            std::hint::black_box(strains_pass(plastic, std::hint::black_box(&u)));
        })
    };
    // The yielding pass with both instruction sets (the history reset each
    // pass, as `timed` does); `yielding_s` is the one the environment asks for.
    let (yielding_avx2_s, yielding_baseline_s) = {
        let u = field(1e-3);
        let mut rock = plastic.rock_state();
        median_alternating(passes, |baseline| {
            crate::simd::set_baseline(baseline);
            rock.reset_history();
            crate::solver::forces::element_forces_plastic(plastic, &mut rock, std::hint::black_box(&u), &mut f);
        })
    };
    crate::simd::set_from_env();
    let yielding_s = if crate::simd::avx2_on() { yielding_avx2_s } else { yielding_baseline_s };
    PlasticPassFigure {
        condensed_s,
        screened_s,
        elastic_s,
        yielding_s,
        strains_s,
        yielding_avx2_s,
        yielding_baseline_s,
    }
}

/// The floor pass of [`PlasticPassFigure::strains_s`]: every plastic cell's
/// tetrahedra's strains from the displacement `u`, nothing else, on rayon's
/// pool as the passes it is compared with. Returns the sum of the cells'
/// volumetric strains, a sink for the timing (its order does not matter).
pub fn strains_pass(plastic: &Model, u: &[f64]) -> f64 {
    let cells = &plastic.plastic;
    (0..plastic.elements.len())
        .into_par_iter()
        .filter(|&e| !cells.tets(e).is_empty())
        .map(|e| {
            let (topo, tets) = (cells.topology(plastic.elements.kind[e]), cells.tets(e));
            crate::physics::plastic::cell_volumetric_strain(topo, tets, plastic.elements.corners(e), u)
        })
        .sum()
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

/// Relaxes `model` from rest with `params` once by dynamic relaxation
/// (whatever `params.elastic` says), as phase 1 of a run does (to the
/// tolerance or `params.max_steps`), without history rows.
pub fn time_dr(model: &Model, params: &SolverParams) -> Result<DrFigure, Error> {
    let params = SolverParams { elastic: ElasticSolver::Dr, ..params.clone() };
    let t = Instant::now();
    let (state, report) = crate::drivers::run::relax_elastic(model, &params, usize::MAX)?;
    let seconds = t.elapsed().as_secs_f64();
    let max_abs_uz = state.u.chunks(3).map(|d| d[2].abs()).fold(0.0, f64::max);
    Ok(DrFigure { converged: report.converged, steps: report.steps, seconds, max_abs_uz })
}

/// The elastic phase by two-level PCG from rest to the scene's tolerance.
#[derive(Debug, Clone, Serialize)]
pub struct PcgFigure {
    pub converged: bool,
    pub iterations: usize,
    /// Both levels built: node blocks, coarse assembly and factorisation (s).
    pub setup_s: f64,
    /// `setup_s` plus the iterations; the model is built (s).
    pub seconds: f64,
    pub max_abs_uz: f64,
    /// Coarse unknowns (free components of the merged mesh).
    pub coarse_dofs: usize,
}

/// Solves the elastic phase of `model` from rest with PCG once (to
/// `params.tolerance` or `params.max_steps` iterations), without history rows.
pub fn time_pcg(model: &Model, params: &SolverParams) -> Result<PcgFigure, Error> {
    let t = Instant::now();
    let mut pcg = Pcg::new(model)?;
    let setup_s = t.elapsed().as_secs_f64();
    let mut state = State::new(model);
    let budget = crate::solver::budget::step_budget(model, params, true, params.max_steps, 1);
    let rules = StopRules::new(params.tolerance, budget, None, usize::MAX);
    let report = pcg.solve(model, &mut state, &rules, &mut unobserved)?;
    let seconds = t.elapsed().as_secs_f64();
    let max_abs_uz = state.u.chunks(3).map(|d| d[2].abs()).fold(0.0, f64::max);
    Ok(PcgFigure {
        converged: report.converged,
        iterations: report.steps,
        setup_s,
        seconds,
        max_abs_uz,
        coarse_dofs: pcg.coarse_unknowns(),
    })
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
