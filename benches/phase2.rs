//! Phase 2 of the paper's slip-surface case
//! (verification/cases/slope-slip/slope-slip.toml) from its precomputed
//! elastic state, node-block masses (the default), as `cdem run` runs it:
//!
//! - `phase2/slope_slip_block`: the phase-2 solver (time step, node-block
//!   masses) and its steps to the decision (GlobalSliding by the rate rule,
//!   2,160 steps when this bench was written; the count is printed and must not change
//!   between samples); 10 samples.
//!
//! The elastic phase is solved once, outside the measurement
//! (`harness::perf::failure::slip_surface_reduction`); each sample runs
//! `Reduction::trial(1.0, ..)` from a copy of it (a factor of 1 leaves the
//! strengths as they are). `cdem perf` reports the same steps against the
//! goal of 5,000 and against lumped masses (row `perf/phase2/*`).

use std::path::Path;
use std::time::Duration;

use cdem::drivers::Watch;
use cdem::harness::perf::failure::slip_surface_reduction;
use criterion::{criterion_group, criterion_main, Criterion};

struct Quiet;
impl Watch for Quiet {}

fn phase2(c: &mut Criterion) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (mut red, elastic_steps) = slip_surface_reduction(root, true).expect("the slip-surface case's elastic phase");
    let first = red.trial(1.0, &mut Quiet).expect("phase 2 runs").trial;
    eprintln!(
        "phase2/slope_slip_block: elastic {elastic_steps} steps; phase 2 {:?} after {} steps",
        first.outcome, first.steps
    );
    let mut group = c.benchmark_group("phase2");
    group.sample_size(10).warm_up_time(Duration::from_secs(2)).measurement_time(Duration::from_secs(15));
    group.bench_function("slope_slip_block", |b| {
        b.iter(|| {
            let t = red.trial(1.0, &mut Quiet).expect("phase 2 runs").trial;
            assert_eq!(t.steps, first.steps, "phase 2 is deterministic");
            t
        })
    });
    group.finish();
}

criterion_group!(benches, phase2);
criterion_main!(benches);
