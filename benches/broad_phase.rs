//! The runout's broad phase, two ways side by side (issue 56, references/runout.md):
//! `contact::sweep` (sort and sweep along x) against `contact::grid` (a uniform
//! grid of cells one block wide, 3DEC's cell mapping), on a deposit of blocks:
//! a layer `k` blocks thick (k = 4), `n x n` in plan, unit blocks with a
//! deterministic jitter, from 1e3 to 1e5 blocks. Both find the same pairs
//! (a unit test in `solver::runout::contact`).
//!
//! Before criterion runs, each size is timed (best of 5) and the cost's
//! exponent against the block count is printed, `log(t2 / t1) / log(n2 / n1)`
//! over 1e3..1e5: the issue asks for at most 1.15.

use std::hint::black_box;
use std::time::Instant;

use cdem::solver::runout::contact::{grid, sweep};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

type Box3 = ([f64; 3], [f64; 3]);

/// `count` unit blocks (near enough) in a layer 4 deep, jittered by a fixed LCG.
fn deposit(count: usize) -> Vec<Box3> {
    let depth = 4;
    let side = ((count / depth) as f64).sqrt().round() as usize;
    let mut state: u64 = 2014;
    let mut jitter = || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.1
    };
    let mut out = Vec::with_capacity(side * side * depth);
    for i in 0..side {
        for j in 0..side {
            for k in 0..depth {
                let lo = [i as f64 + jitter(), j as f64 + jitter(), k as f64 + jitter()];
                out.push((lo, lo.map(|v| v + 1.0)));
            }
        }
    }
    out
}

const SIZES: [usize; 3] = [1_000, 10_000, 100_000];

fn best_of(reps: usize, mut f: impl FnMut() -> usize) -> (f64, usize) {
    let mut best = f64::INFINITY;
    let mut pairs = 0;
    for _ in 0..reps {
        let t = Instant::now();
        pairs = f();
        best = best.min(t.elapsed().as_secs_f64());
    }
    (best, pairs)
}

fn exponents() {
    let keep = |_: usize, _: usize| true;
    let mut rows = Vec::new();
    for &n in &SIZES {
        let boxes = deposit(n);
        let (ts, ps) = best_of(5, || sweep(black_box(&boxes), keep).len());
        let (tg, pg) = best_of(5, || grid(black_box(&boxes), 1.1, keep).len());
        assert_eq!(ps, pg, "sweep and grid disagree at {n} blocks");
        println!("broad phase, {} blocks, {ps} pairs: sweep {:.3e} s, grid {:.3e} s", boxes.len(), ts, tg);
        rows.push((boxes.len() as f64, ts, tg));
    }
    let (first, last) = (rows[0], rows[rows.len() - 1]);
    let slope = |a: f64, b: f64| (b / a).ln() / (last.0 / first.0).ln();
    println!(
        "broad phase exponent over {:.0}..{:.0} blocks: sweep {:.3}, grid {:.3} (issue 56: at most 1.15)",
        first.0,
        last.0,
        slope(first.1, last.1),
        slope(first.2, last.2)
    );
}

fn bench(c: &mut Criterion) {
    exponents();
    let mut g = c.benchmark_group("broad_phase");
    g.sample_size(10);
    for &n in &SIZES {
        let boxes = deposit(n);
        g.throughput(Throughput::Elements(boxes.len() as u64));
        g.bench_with_input(BenchmarkId::new("sweep", n), &boxes, |b, boxes| b.iter(|| sweep(boxes, |_, _| true)));
        g.bench_with_input(BenchmarkId::new("grid", n), &boxes, |b, boxes| b.iter(|| grid(boxes, 1.1, |_, _| true)));
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
