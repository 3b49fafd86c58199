//! The rows of the performance goals (references/performance.md) that
//! `cdem perf`, `cdem reproduce` and the tests report: every timed figure
//! against its goal, measured side by side in one run.

use crate::harness::perf::bytes::FULL_KE_ELEMENT_BYTES;
use crate::harness::perf::ensemble::EnsembleFigures;
use crate::harness::perf::failure::{Phase2Figure, Phase2Run, SrmFigure};
use crate::harness::perf::headline::Headline;
use crate::harness::registry::{self as reg, row};
use crate::harness::report::Check;

/// LEM grid search at least this many times faster than pySlope (issue 28, item 3).
pub const GOAL_LEM_OVER_PYSLOPE: f64 = 300.0;
/// A plastic block's element step at most this many times the condensed
/// elastic one (issue 24, item 7).
pub const GOAL_PLASTIC_OVER_CONDENSED: f64 = 2.0;
/// The kernels' AVX2 version no slower than their baseline (`crate::simd`).
pub const GOAL_AVX2_SPEEDUP: f64 = 1.0;
/// Bytes per element-step at most this fraction of the full-`K_e` count (issue 28, item 2).
pub const GOAL_ELEMENT_BYTES_FRACTION: f64 = 0.6;

/// The performance goals (references/performance.md), reported.
pub fn perf_rows(h: &Headline) -> Vec<Check> {
    let mut rows = vec![
        row("perf/bandwidth").value(h.step_fraction_of_stream(), 0.5, h.step_block.step_s),
        row("perf/element-bytes")
            .value(h.element_pass.bytes_per_element, GOAL_ELEMENT_BYTES_FRACTION * FULL_KE_ELEMENT_BYTES, h.element_pass.pass_s)
            .with_note(format!(
                "{:.2} of the {FULL_KE_ELEMENT_BYTES:.0} B with the full K_e; the element pass alone {:.3} ms, {:.1} GB/s \
                 = {:.0} % of this run's triad ({:.1} GB/s)",
                h.element_pass.bytes_per_element / FULL_KE_ELEMENT_BYTES,
                1e3 * h.element_pass.pass_s,
                h.element_pass.gbs,
                100.0 * h.element_fraction_of_stream(),
                h.stream_gbs
            )),
        row("perf/plastic-over-condensed")
            .value(h.plastic_pass.screened_ratio(), GOAL_PLASTIC_OVER_CONDENSED, h.plastic_pass.screened_s)
            .with_note(format!(
                "plastic pass, every tetrahedron elastic: {:.3} ms behind armed screens, {:.3} ms with the return \
                 mappings run ({:.1}x); every one yielding {:.3} ms ({:.1}x: not met); condensed {:.3} ms; the 24 \
                 tetrahedra's strains alone, a floor under any yielding block, {:.3} ms ({:.1}x)",
                1e3 * h.plastic_pass.screened_s,
                1e3 * h.plastic_pass.elastic_s,
                h.plastic_pass.elastic_ratio(),
                1e3 * h.plastic_pass.yielding_s,
                h.plastic_pass.yielding_ratio(),
                1e3 * h.plastic_pass.condensed_s,
                1e3 * h.plastic_pass.strains_s,
                h.plastic_pass.strains_ratio()
            )),
        row("perf/avx2-speedup")
            .value(h.simd_step.speedup(), GOAL_AVX2_SPEEDUP, h.simd_step.avx2_s)
            .with_note(format!(
                "a phase-2 step with plastic blocks: {:.3} ms with the baseline kernels, {:.3} ms with AVX2 ({}); \
                 the plastic pass with every tetrahedron yielding, the case AVX2 helps least (its return mappings are \
                 scalar): {:.3} ms and {:.3} ms ({:.2}x){}",
                1e3 * h.simd_step.baseline_s,
                1e3 * h.simd_step.avx2_s,
                if h.simd_step.same_bits { "the same bits" } else { "DIFFERENT BITS" },
                1e3 * h.plastic_pass.yielding_baseline_s,
                1e3 * h.plastic_pass.yielding_avx2_s,
                h.plastic_pass.avx2_speedup(),
                if h.simd_step.avx2_cpu { "" } else { "; this CPU has no AVX2: both ran the baseline" }
            )),
        row("perf/dr-over-fem").value(h.dr_over_fem(), 3.0, h.dr_block.seconds),
        row("perf/pcg-over-fem").value(h.pcg_over_fem(), 3.0, h.pcg.seconds),
    ];
    for (case, ours, pyslope) in &h.lem {
        let id = format!("perf/lem/{case}");
        let spec = crate::harness::registry::rows().into_iter().find(|r| r.id == id);
        let c = match spec {
            Some(s) => s.value(pyslope / ours, GOAL_LEM_OVER_PYSLOPE, *ours),
            None => Check::new(
                &format!("performance: LEM grid, {case}"),
                "pySlope / ours time",
                pyslope / ours,
                GOAL_LEM_OVER_PYSLOPE,
                f64::NAN,
                reg::PERFORMANCE_MD,
                *ours,
            ),
        };
        rows.push(c.with_note(if h.pyslope_timed_now {
            "pySlope timed in this run"
        } else {
            "pySlope's time recorded in references/pyslope.json, not timed in this run"
        }));
    }
    rows
}

/// Phase 2 of the slip-surface slope, node-block against lumped masses in
/// one run ([`crate::harness::perf::failure::phase2_figure`]): the steps to a
/// decision against the goal and the paper-era baseline, and their ratio. A
/// phase 2 that ran to its step cap has no decision: its rows carry a defect.
pub fn phase2_rows(f: &Phase2Figure) -> Vec<Check> {
    let (b, l) = (&f.block, &f.lumped);
    let checked = |c: Check, runs: &[&Phase2Run]| match runs.iter().find(|r| !r.decided()) {
        Some(r) => c.with_defect(format!(
            "phase 2 with {} masses ran to its step cap ({} steps) without a decision",
            if r.block_mass { "node-block" } else { "lumped" },
            r.steps
        )),
        None => c,
    };
    vec![
        checked(row("perf/phase2/block-steps").value(b.steps as f64, reg::GOAL_PHASE2_STEPS, b.seconds), &[b])
            .with_note(format!("{:?}; lumped masses {} steps in this run", b.end, l.steps)),
        checked(row("perf/phase2/lumped-steps").value(l.steps as f64, reg::PHASE2_STEPS_BASELINE, l.seconds), &[l])
            .with_note(format!("{:?}; the baseline was decided by the 0.5 m bound, before the rate rule", l.end)),
        checked(row("perf/phase2/lumped-over-block").value(f.lumped_over_block(), 1.0, b.seconds + l.seconds), &[b, l])
            .with_note(format!("{} / {} steps", l.steps, b.steps)),
    ]
}

/// The ids of the rows of one timed strength reduction (`variant` of
/// [`crate::harness::perf::failure::SRM_VARIANTS`]): wall time, mean and
/// largest steps per trial.
pub fn srm_perf_ids(variant: &str) -> [String; 4] {
    ["wall", "trial-steps-mean", "trial-steps-max", "fs-change"].map(|q| format!("perf/srm/{variant}/{q}"))
}

/// The wall-time goal of a timed strength reduction: the ductile one 15 s
/// (issue 28, item 1), the brittle one 60 s ([`reg::GOAL_SRM_SECONDS`]).
pub fn srm_goal_seconds(variant: &str) -> f64 {
    match variant {
        "ductile" => reg::GOAL_SRM_DUCTILE_SECONDS,
        "plastic-gl1-hex" => reg::GOAL_PLASTIC_SRM_SECONDS,
        "plastic-paper-slope" => reg::GOAL_PLASTIC_PAPER_SRM_SECONDS,
        _ => reg::GOAL_SRM_SECONDS,
    }
}

/// `cdem srm` on the slip-surface slope ([`crate::harness::perf::failure::srm_figure`]),
/// trials warm-started (`f`) and from the elastic state (`e`, the same
/// variant, same run): the warm wall time against the goal, the mean and
/// largest steps per trial against 3DEC's default cap, and the change of FS
/// against the bracket width. A search without a bracket carries a defect.
pub fn srm_perf_rows(f: &SrmFigure, e: &SrmFigure) -> Vec<Check> {
    let [wall, mean, max, change] = srm_perf_ids(&f.variant);
    let width = crate::drivers::srm::BRACKET_WIDTH;
    let fmt = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.4}"));
    let fs_change = match (f.fs, e.fs) {
        (Some(a), Some(b)) => (a - b).abs(),
        _ => f64::INFINITY,
    };
    let cap = reg::THREEDEC_TRIAL_STEP_CAP;
    let budget = format!(
        "{} trials, {} Undecided (budget {} steps, 10 N_r{})",
        f.trials,
        f.undecided,
        f.trial_budget,
        if f.foresight { ", or foreseen" } else { "" }
    );
    // What `e` is: the same search from the elastic state, or without the
    // foresight rule.
    let other = if e.foresight != f.foresight { "without the foresight rule" } else { "from the elastic state" };
    // A comparison with the rule off says nothing where the rule ended no
    // trial: say how many it could have ended.
    let vacuous = match (e.foresight != f.foresight, f.undecided) {
        (true, 0) => "; no trial Undecided: the rule fired on none, so the two searches are the same",
        _ => "",
    };
    let rows = vec![
        row(&wall).value(f.seconds, srm_goal_seconds(&f.variant), f.seconds).with_note(format!(
            "FS {}; {budget}; {other} in the same run {:.1} s ({:.2}x), {:.0} steps per trial",
            f.fs.map_or("none (no bracket)".to_string(), |fs| format!("{fs:.3}")),
            e.seconds,
            e.seconds / f.seconds,
            e.mean_trial_steps
        )),
        row(&mean)
            .value(f.mean_trial_steps, cap, f.seconds)
            .with_note(format!("{:.2} of the cap; {budget}", f.mean_trial_steps / cap)),
        row(&max).value(f.max_trial_steps as f64, cap, f.seconds).with_note(format!(
            "{:.2} of the cap; our budget {} steps is {} it",
            f.max_trial_steps as f64 / cap,
            f.trial_budget,
            if (f.trial_budget as f64) < cap { "below" } else { "not below" }
        )),
        row(&change).value(fs_change, width, f.seconds + e.seconds).with_note(format!(
            "FS as cdem srm runs it / {other} {} / {}, bracket [{}, {}] / [{}, {}], {} / {} trials{vacuous}",
            fmt(f.fs),
            fmt(e.fs),
            fmt(f.bracket_lo),
            fmt(f.bracket_hi),
            fmt(e.bracket_lo),
            fmt(e.bracket_hi),
            f.trials,
            e.trials
        )),
    ];
    match f.fs {
        Some(_) => rows,
        None => rows.into_iter().map(|c| c.with_defect("the search found no bracket")).collect(),
    }
}

/// The rows of the timed strength reductions as skipped, with the reason
/// (they take 10 s to 4 min each: `cdem perf` measures them, the tests and
/// `cdem reproduce` do not).
pub fn srm_perf_skipped(reason: &str) -> Vec<Check> {
    use crate::harness::perf::failure::{PLASTIC_SRM_VARIANTS, SRM_VARIANTS};
    let variants = SRM_VARIANTS.iter().map(|v| v.0).chain(PLASTIC_SRM_VARIANTS.iter().map(|v| v.0));
    variants.flat_map(srm_perf_ids).chain([MESH_CHECK_ROW.to_string()]).map(|id| row(&id).skipped(reason)).collect()
}

/// The row of `cdem srm --mesh-check`'s cost (issue 61).
pub const MESH_CHECK_ROW: &str = "perf/srm/mesh-check-gl1-hex/cost-ratio";

/// The wall time of `cdem srm --mesh-check` on Griffiths & Lane's
/// hexahedra over that of the plain `cdem srm` of the same run (`plain`,
/// the foresight rule on as `cdem srm` runs), against
/// [`reg::GOAL_MESH_CHECK_COST_RATIO`]; a defect if either failed.
pub fn mesh_check_row(m: &crate::harness::perf::failure::MeshCheckFigure, plain: Option<&SrmFigure>) -> Check {
    let plain_s = plain.map_or(f64::NAN, |p| p.seconds);
    let c =
        row(MESH_CHECK_ROW).value(m.seconds / plain_s, reg::GOAL_MESH_CHECK_COST_RATIO, m.seconds).with_note(format!(
            "the check {:.1} s (refine 1 and 2, brackets 0.0025; {:.2}x its own reduction on the committed mesh), the \
             plain cdem srm {plain_s:.1} s in the same run; {}",
            m.seconds, m.over_own, m.line
        ));
    match (&m.error, plain) {
        (Some(why), _) => c.with_defect(format!("the mesh check failed: {why}")),
        (None, None) => c.with_defect("the plain reduction of Griffiths & Lane's hexahedra was not timed"),
        _ => c,
    }
}

/// The ids of the timed ensemble rows ([`ensemble_perf_rows`]).
pub const ENSEMBLE_PERF_IDS: [&str; 3] =
    ["perf/ensemble/members-per-hour", "perf/ensemble/srm-members-per-hour", "perf/ensemble/two-shards-speedup"];

/// Ensembles of the slip-surface slope ([`crate::harness::perf::ensemble`]):
/// members per hour without and with strength reduction, against the
/// goal of 600 with SRM (issue 28; issue 14 asked 100), and the speed-up of
/// two concurrent shards over one process. Merged shards that are not
/// byte-identical to the one process's `members.jsonl` carry a defect, as
/// SRM members without an FS do.
pub fn ensemble_perf_rows(f: &EnsembleFigures) -> Vec<Check> {
    let [members, srm, shards] = ENSEMBLE_PERF_IDS;
    let goal = reg::GOAL_SRM_MEMBERS_PER_HOUR;
    let (m, s, sh) = (&f.members, &f.srm, &f.shards);
    let ends = |m: &crate::harness::perf::ensemble::MembersFigure| {
        format!("phase 2: {} GlobalSliding, {} Equilibrium, {} Undecided", m.sliding, m.equilibrium, m.undecided)
    };
    let k = |m: &crate::harness::perf::ensemble::MembersFigure| m.mean_k.map_or("none".into(), |k| format!("{k:.3}"));
    let load = |l: Option<f64>| l.map_or("unknown".into(), |l| format!("{l:.2}"));
    let srm_row = row(srm).value(s.members_per_hour, goal, s.seconds).with_note(format!(
        "{} members in {:.1} s on {} threads ({:.1} s each); mean SRM FS {}, {:.1} trials; mean K {}; {}",
        s.members,
        s.seconds,
        s.threads,
        s.seconds / s.members as f64,
        s.mean_srm_fs.map_or("none".into(), |v| format!("{v:.3}")),
        s.mean_srm_trials.unwrap_or(f64::NAN),
        k(s),
        ends(s)
    ));
    let srm_row = match s.members_without_srm_fs {
        0 => srm_row,
        n => srm_row.with_defect(format!("{n} members' strength reduction found no bracket")),
    };
    let shards_row =
        row(shards).value(sh.speedup(), reg::GOAL_TWO_SHARDS_SPEEDUP, sh.one_process_s).with_note(format!(
            "{} members: one process {:.1} s on {} threads, {} members at once ({:.1} s on 1: threads gain \
             {:.2}x); 2 shards ({} thread(s) each) {:.1} s + merge {:.2} s, {:.2}x the one process on 1 thread; \
             members.jsonl {} ({} bytes); load average {} before, {} after",
            sh.members,
            sh.one_process_s,
            sh.threads,
            sh.members_at_once,
            sh.one_thread_s,
            sh.thread_speedup(),
            sh.threads_per_shard,
            sh.shards_s,
            sh.merge_s,
            sh.speedup_over_one_thread(),
            if sh.identical { "byte-identical" } else { "DIFFERENT" },
            sh.jsonl_bytes,
            load(sh.load_before),
            load(sh.load_after)
        ));
    let shards_row = match sh.identical {
        true => shards_row,
        false => {
            shards_row.with_defect("members.jsonl differs between the one process, one thread and the merged shards")
        }
    };
    vec![
        row(members).value(m.members_per_hour, goal, m.seconds).with_note(format!(
            "{} members in {:.1} s on {} threads ({:.2} s each); mean K {}; {}",
            m.members,
            m.seconds,
            m.threads,
            m.seconds / m.members as f64,
            k(m),
            ends(m)
        )),
        srm_row,
        shards_row,
    ]
}

/// The timed ensemble rows as skipped, with the reason.
pub fn ensemble_perf_skipped(reason: &str) -> Vec<Check> {
    ENSEMBLE_PERF_IDS.iter().map(|id| row(id).skipped(reason)).collect()
}
