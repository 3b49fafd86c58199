//! What `cdem perf` writes: the Markdown tables of the headline figures, of
//! phase 2 and the strength reductions on the slip-surface slope, of the
//! timed ensembles of it, of the
//! validation rows `perf/*` these figures make, the damping table and the
//! scaling study (with its fitted exponents), the rows as CSV, the
//! cost-against-size figure, and `perf.md` made of the tables. Formatting
//! only: the numbers come from the other modules.

use std::fmt::Write as _;
use std::path::Path;

use serde::Serialize;

use super::damping::DampingRow;
use super::ensemble::EnsembleFigures;
use super::failure::FailureFigures;
use super::headline::Headline;
use super::scaling::{exponents, ScalingRow};
use crate::error::Error;
use crate::harness::registry as reg;
use crate::harness::report::{Check, Table};

impl Headline {
    /// The figures as a Markdown table, each with its goal.
    pub fn markdown(&self) -> String {
        let mut md = String::new();
        let _ = writeln!(md, "| figure | measured | goal |\n|---|---|---|");
        let _ = writeln!(md, "| stream triad (this pool) | {:.1} GB/s | - |", self.stream_gbs);
        for (name, s) in [("block masses (default)", &self.step_block), ("lumped masses", &self.step_lumped)] {
            let _ = writeln!(
                md,
                "| step, {name}, {} elements | {:.3} ms, {:.2} M element-steps/s, {:.0} B/element, \
                 {:.1} GB/s = {:.0} % of stream | >= 50 % |",
                s.elements,
                1e3 * s.step_s,
                s.mega_element_steps_per_s,
                s.bytes_per_step / s.elements as f64,
                s.gbs,
                100.0 * s.gbs / self.stream_gbs
            );
        }
        let e = &self.element_pass;
        let _ = writeln!(
            md,
            "| element pass (eq. 12) alone, {} elements | {:.3} ms, {:.0} B per element-step ({:.2} of {:.0} B with the \
             full K_e), {:.1} GB/s = {:.0} % of stream | <= 0.6 of the bytes |",
            self.step_block.elements,
            1e3 * e.pass_s,
            e.bytes_per_element,
            e.bytes_per_element / super::bytes::FULL_KE_ELEMENT_BYTES,
            super::bytes::FULL_KE_ELEMENT_BYTES,
            e.gbs,
            100.0 * self.element_fraction_of_stream()
        );
        let _ = writeln!(
            md,
            "| DR to 1e-5 / FEM solve (paper slope) | {:.3} s ({} steps) / {:.4} s ({} dofs) = {:.1}x | <= 3x |",
            self.dr_block.seconds,
            self.dr_block.steps,
            self.fem_s,
            self.fem_dofs,
            self.dr_over_fem()
        );
        let _ = writeln!(
            md,
            "| PCG to 1e-5 / FEM solve (paper slope) | {:.3} s ({} iterations) / {:.4} s = {:.2}x | <= 3x |",
            self.pcg.seconds,
            self.pcg.iterations,
            self.fem_s,
            self.pcg_over_fem()
        );
        let when = if self.pyslope_timed_now {
            "pySlope timed in this run"
        } else {
            "pySlope's recorded time (references/pyslope.json, another day): `--pyslope PYTHON` times it now"
        };
        for (case, ours, py) in &self.lem {
            let _ = writeln!(
                md,
                "| LEM Bishop grid 20x20x10, {case}: pySlope / ours ({when}) | {py:.3} s / {:.2} ms = {:.0}x | >= 300x |",
                1e3 * ours,
                py / ours
            );
        }
        md
    }
}

impl FailureFigures {
    /// The figures as a Markdown table, each with its goal or reference.
    pub fn markdown(&self) -> String {
        let mut md = String::new();
        let _ = writeln!(md, "| figure | measured | goal / reference |\n|---|---|---|");
        let (b, l) = (&self.phase2.block, &self.phase2.lumped);
        let _ = writeln!(
            md,
            "| phase 2 to a decision, node-block masses (default) | {} steps ({:?}, {:.1e} m, {} springs failed), \
             {:.2} s = {:.2} of the goal | <= {} steps |",
            b.steps,
            b.end,
            b.max_displacement,
            b.failed_springs,
            b.seconds,
            b.steps as f64 / reg::GOAL_PHASE2_STEPS,
            reg::GOAL_PHASE2_STEPS
        );
        let _ = writeln!(
            md,
            "| phase 2 to a decision, lumped masses (same elastic state) | {} steps ({:?}, {:.1e} m, {} springs \
             failed), {:.2} s; lumped / block = {:.2}x | paper-era baseline {} steps |",
            l.steps,
            l.end,
            l.max_displacement,
            l.failed_springs,
            l.seconds,
            self.phase2.lumped_over_block(),
            reg::PHASE2_STEPS_BASELINE
        );
        let cap = reg::THREEDEC_TRIAL_STEP_CAP;
        let plastic = self.plastic_plain.iter().chain(&self.plastic);
        for f in self.srm_elastic.iter().chain(&self.srm).chain(plastic) {
            let fs = f.fs.map_or("no bracket".to_string(), |fs| format!("FS {fs:.3}"));
            let bracket = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.4}"));
            let _ = writeln!(
                md,
                "| cdem srm, {}, {}, trials from the {} state, foresight {} | {:.1} s, bracket [{}, {}], {fs}, {} trials; steps per trial mean {:.0} / max {} \
                 = {:.3} / {:.3} of 3DEC's cap; {} trials Undecided (budget {} steps); a trial {:.3} s of which \
                 setup {:.1e} s, the phase-2 plan built once in {:.1e} s (before: once per trial, {:.1e} s in all) \
                 | <= {} s; cap {} steps |",
                f.case,
                f.variant,
                if f.start == crate::drivers::srm::TrialStart::Warm { "last stable" } else { "elastic" },
                if f.foresight { "on" } else { "off" },
                f.seconds,
                bracket(f.bracket_lo),
                bracket(f.bracket_hi),
                f.trials,
                f.mean_trial_steps,
                f.max_trial_steps,
                f.mean_trial_steps / cap,
                f.max_trial_steps as f64 / cap,
                f.undecided,
                f.trial_budget,
                f.mean_trial_s,
                f.mean_trial_setup_s,
                f.plan_setup_s,
                f.plan_setup_s * f.trials as f64,
                crate::harness::perf::rows::srm_goal_seconds(&f.variant),
                cap
            );
        }
        if self.srm.is_empty() {
            let _ = writeln!(
                md,
                "| cdem srm, slip-surface slope | not run (`--no-srm`) | <= {} s |",
                reg::GOAL_SRM_SECONDS
            );
        }
        md
    }
}

impl EnsembleFigures {
    /// The figures as a Markdown table, each with its goal.
    pub fn markdown(&self) -> String {
        let mut md = String::new();
        let _ = writeln!(md, "| figure | measured | goal / reference |\n|---|---|---|");
        let goal = reg::GOAL_SRM_MEMBERS_PER_HOUR;
        for (what, m) in [("elastic + eq. 21 K + phase 2", &self.members), ("with cdem srm per member", &self.srm)] {
            let srm = match m.mean_srm_fs {
                Some(fs) => format!(", mean SRM FS {fs:.3} ({:.1} trials)", m.mean_srm_trials.unwrap_or(f64::NAN)),
                None => String::new(),
            };
            let _ = writeln!(
                md,
                "| `{}`, {what}: {} members, one process, {} threads | {:.0} members per hour ({:.1} s, {:.2} s \
                 per member); mean K {}{srm}; phase 2: {} GlobalSliding, {} Equilibrium, {} Undecided | >= {goal} \
                 per hour (with SRM) |",
                m.input,
                m.members,
                m.threads,
                m.members_per_hour,
                m.seconds,
                m.seconds / m.members as f64,
                m.mean_k.map_or("none".into(), |k| format!("{k:.3}")),
                m.sliding,
                m.equilibrium,
                m.undecided
            );
        }
        let s = &self.shards;
        let load = |l: Option<f64>| l.map_or("unknown".into(), |l| format!("{l:.2}"));
        let _ = writeln!(
            md,
            "| `{}`, {} members: 2 concurrent shard processes ({} thread(s) each) + merge against one process ({} \
             threads, {} members at once; and 1 thread) | {:.1} s + {:.2} s against {:.1} s (1 thread: {:.1} s): \
             speed-up {:.2} ({:.2} over 1 thread; the threads alone {:.2}); members.jsonl {} ({} bytes); 1-min load \
             average {} before, {} after on {} cores | >= {} |",
            s.input,
            s.members,
            s.threads_per_shard,
            s.threads,
            s.members_at_once,
            s.shards_s,
            s.merge_s,
            s.one_process_s,
            s.one_thread_s,
            s.speedup(),
            s.speedup_over_one_thread(),
            s.thread_speedup(),
            if s.identical { "byte-identical" } else { "**DIFFERENT**" },
            s.jsonl_bytes,
            load(s.load_before),
            load(s.load_after),
            std::thread::available_parallelism().map_or(0, |n| n.get()),
            reg::GOAL_TWO_SHARDS_SPEEDUP
        );
        md
    }

    /// The figures as CSV rows (`ensemble.csv`).
    pub fn csv_rows(&self) -> Vec<EnsembleCsvRow> {
        let m = |what: &str, f: &super::ensemble::MembersFigure| EnsembleCsvRow {
            what: what.to_string(),
            input: f.input.clone(),
            members: f.members,
            threads: f.threads,
            seconds: f.seconds,
            members_per_hour: f.members_per_hour,
        };
        let s = &self.shards;
        let per_hour = |t: f64| s.members as f64 * 3600.0 / t;
        vec![
            m("in-process", &self.members),
            m("in-process-srm", &self.srm),
            EnsembleCsvRow {
                what: "one-process".into(),
                input: s.input.clone(),
                members: s.members,
                threads: s.threads,
                seconds: s.one_process_s,
                members_per_hour: per_hour(s.one_process_s),
            },
            EnsembleCsvRow {
                what: "one-process-1-thread".into(),
                input: s.input.clone(),
                members: s.members,
                threads: 1,
                seconds: s.one_thread_s,
                members_per_hour: per_hour(s.one_thread_s),
            },
            EnsembleCsvRow {
                what: "two-shards-and-merge".into(),
                input: s.input.clone(),
                members: s.members,
                threads: s.threads_per_shard,
                seconds: s.shards_s + s.merge_s,
                members_per_hour: per_hour(s.shards_s + s.merge_s),
            },
        ]
    }
}

/// One row of `ensemble.csv`.
#[derive(Debug, Clone, Serialize)]
pub struct EnsembleCsvRow {
    pub what: String,
    pub input: String,
    pub members: usize,
    /// Threads of the process (of each shard for the two shards).
    pub threads: usize,
    pub seconds: f64,
    pub members_per_hour: f64,
}

/// The validation rows `perf/*` of a `cdem perf` run: the headline's, phase
/// 2's, the strength reductions' and the ensembles' (skipped if not run).
pub fn perf_checks(head: &Headline, failure: &FailureFigures, ensemble: Option<&EnsembleFigures>) -> Vec<Check> {
    let mut rows = crate::harness::perf::rows::perf_rows(head);
    rows.extend(crate::harness::perf::rows::phase2_rows(&failure.phase2));
    if failure.srm.is_empty() {
        rows.extend(crate::harness::perf::rows::srm_perf_skipped("not run: cdem perf --no-srm"));
    }
    for (f, e) in failure.srm.iter().zip(&failure.srm_elastic).chain(failure.plastic.iter().zip(&failure.plastic_plain))
    {
        rows.extend(crate::harness::perf::rows::srm_perf_rows(f, e));
    }
    if let Some(m) = &failure.mesh_check {
        let plain = failure.plastic.iter().find(|f| f.variant == "plastic-gl1-hex");
        rows.push(crate::harness::perf::rows::mesh_check_row(m, plain));
    }
    match ensemble {
        Some(e) => rows.extend(crate::harness::perf::rows::ensemble_perf_rows(e)),
        None => rows.extend(crate::harness::perf::rows::ensemble_perf_skipped("not run: cdem perf --no-ensemble")),
    }
    rows
}

/// The rows of [`perf_checks`] as the validation table shows them (the
/// registry's rows `perf/*`, each with its result).
pub fn perf_rows_markdown(head: &Headline, failure: &FailureFigures, ensemble: Option<&EnsembleFigures>) -> String {
    let specs: Vec<_> = reg::rows().into_iter().filter(|r| r.id.starts_with("perf/")).collect();
    let table = Table::assemble(&specs, perf_checks(head, failure, ensemble), &[], &|spec| {
        format!("not measured by cdem perf; see {}", spec.test)
    });
    format!("{}.\n\n{}", table.counts(), table.markdown())
}

/// The damping rows as a Markdown table.
pub fn damping_markdown(damping: &[DampingRow]) -> String {
    let mut md = String::new();
    if !damping.is_empty() {
        md.push_str(
            "| damping | mass scaling | block masses | outcome | steps | wall (s) | max abs u_z (m) |\n\
             |---|---|---|---|---|---|---|\n",
        );
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
        md.push_str(
            "\n| refine | elements | node copies | springs | build (s) | step (ms) | M element-steps/s | step GB/s \
             | DR steps | DR steps, lumped | DR (s) | PCG iterations | PCG setup (s) | PCG (s) | FEM dofs | FEM (s) \
             | DR / FEM | PCG / FEM | PCG peak (MB) | FEM peak (MB) |\n\
             |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
        );
        let opt = |v: Option<String>| v.unwrap_or_else(|| "-".to_string());
        for r in scaling {
            let dr_steps = r
                .dr_steps
                .map(|s| format!("{s}{}", if r.dr_converged == Some(false) { " (not converged)" } else { "" }));
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {:.2} | {:.3} | {:.2} | {:.1} | {} | {} | {} | {}{} | {:.3} | {:.3} | {} \
                 | {:.3} | {} | {:.2} | {} | {} |",
                r.refine,
                r.elements,
                r.node_copies,
                r.springs,
                r.build_s,
                1e3 * r.step_s,
                r.mega_element_steps_per_s,
                r.gbs,
                opt(dr_steps),
                opt(r.lumped_steps.map(|s| s.to_string())),
                opt(r.dr_s.map(|s| format!("{s:.2}"))),
                r.pcg_iterations,
                if r.pcg_converged { "" } else { " (not converged)" },
                r.pcg_setup_s,
                r.pcg_s,
                r.fem_dofs,
                r.fem_s,
                opt(r.dr_s.map(|s| format!("{:.1}", s / r.fem_s))),
                r.pcg_s / r.fem_s,
                opt(r.pcg_peak_mb.map(|m| format!("{m:.0}"))),
                opt(r.fem_peak_mb.map(|m| format!("{m:.0}"))),
            );
        }
        if scaling.len() >= 2 {
            let e = exponents(scaling);
            let _ = writeln!(
                md,
                "\nFitted exponents against the element count N (least squares on logs): time per step N^{:.2}, \
                 DR steps N^{:.2}, DR time N^{:.2}, PCG iterations N^{:.2}, PCG time N^{:.2}, FEM time N^{:.2}. \
                 PCG and DR times include their setup (block masses; PCG's coarse factorisation), not the model \
                 build; the FEM time is its whole solve from the scene file. A peak is the largest resident size \
                 while the stage ran (PCG's includes the built model).",
                e.step_s, e.dr_steps, e.dr_s, e.pcg_iterations, e.pcg_s, e.fem_s
            );
        }
    }
    md
}

/// `perf.md`: the headline, phase-2 and strength-reduction, ensemble,
/// validation-row, damping and scaling tables under their headings.
pub fn perf_markdown(
    head: &Headline,
    failure: &FailureFigures,
    ensemble: Option<&EnsembleFigures>,
    damping: &[DampingRow],
    scaling: &[ScalingRow],
) -> String {
    format!(
        "# Performance (cdem perf)\n\n## Headline (paper slope, {} threads)\n\n{}\n\
         ## Phase 2 and strength reduction (slip-surface slope)\n\n{}\n\
         ## Ensembles (slip-surface slope)\n\n{}\n\
         ## Validation rows of this run\n\n{}\n\
         ## Damping (paper slope, to 1e-5)\n\n{}\n## Growth with size\n\n{}",
        rayon::current_num_threads(),
        head.markdown(),
        failure.markdown(),
        ensemble.map_or("Not run (`--no-ensemble`).\n".to_string(), |e| e.markdown()),
        perf_rows_markdown(head, failure, ensemble),
        damping_markdown(damping),
        scaling_markdown(scaling)
    )
}

/// The scaling figure: time per step, DR, PCG and FEM times against the
/// element count, log-log; nothing for fewer than two rows.
pub fn scaling_figure(path: &Path, scaling: &[ScalingRow]) -> Result<(), Error> {
    if scaling.len() < 2 {
        return Ok(());
    }
    use crate::output::figures::{line_plot, Scale, Series};
    let pts = |f: &dyn Fn(&ScalingRow) -> f64| scaling.iter().map(|r| (r.elements as f64, f(r))).collect::<Vec<_>>();
    let (step, pcg, fem) = (pts(&|r| r.step_s), pts(&|r| r.pcg_s), pts(&|r| r.fem_s));
    let dr: Vec<(f64, f64)> = scaling.iter().filter_map(|r| r.dr_s.map(|s| (r.elements as f64, s))).collect();
    let series = [
        Series { name: "time per step", points: &step },
        Series { name: "DR to 1e-5", points: &dr },
        Series { name: "PCG to 1e-5", points: &pcg },
        Series { name: "FEM solve", points: &fem },
    ];
    line_plot(path, "Paper slope: cost against size", "elements", "wall time (s)", &series, Scale::Log, Scale::Log)
}

/// Rows as CSV (a header from the field names), written atomically.
pub fn write_csv<T: Serialize>(path: &Path, rows: &[T]) -> Result<(), Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r).map_err(|e| Error::io(path, std::io::Error::other(e)))?;
    }
    let bytes = w.into_inner().map_err(|e| Error::io(path, std::io::Error::other(e.to_string())))?;
    crate::output::write_atomic(path, &bytes)
}

/// Writes `phase2.csv`, `srm.csv`, `ensemble.csv` (with the ensembles),
/// `damping.csv`, `scaling.csv`,
/// `scaling.png` (two rows or more) and `perf.md` to `out`; returns the
/// Markdown.
pub fn write_report(
    out: &Path,
    head: &Headline,
    failure: &FailureFigures,
    ensemble: Option<&EnsembleFigures>,
    damping: &[DampingRow],
    scaling: &[ScalingRow],
) -> Result<String, Error> {
    write_csv(&out.join("phase2.csv"), &[&failure.phase2.block, &failure.phase2.lumped])?;
    let srm =
        [failure.srm_elastic.clone(), failure.srm.clone(), failure.plastic_plain.clone(), failure.plastic.clone()];
    write_csv(&out.join("srm.csv"), &srm.concat())?;
    if let Some(e) = ensemble {
        write_csv(&out.join("ensemble.csv"), &e.csv_rows())?;
    }
    write_csv(&out.join("damping.csv"), damping)?;
    write_csv(&out.join("scaling.csv"), scaling)?;
    scaling_figure(&out.join("scaling.png"), scaling)?;
    let md = perf_markdown(head, failure, ensemble, damping, scaling);
    crate::output::write_atomic(&out.join("perf.md"), md.as_bytes())?;
    Ok(md)
}
