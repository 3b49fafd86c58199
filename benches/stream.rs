//! The machine's memory bandwidth, STREAM-style, as the yardstick for the
//! "fraction of stream" of the step kernels (references/performance.md).
//!
//! - `stream/triad_1thread/64MiB`: `a[i] = b[i] + s c[i]` over three arrays of
//!   8 Mi f64 (64 MiB each, far larger than the caches), one thread; the
//!   loops are `cdem::harness::perf::stream::{triad, triad_par}`, the ones `cdem perf` times;
//! - `stream/triad_2threads/64MiB`: the same split over a 2-thread rayon pool;
//! - `stream/read_1thread/64MiB`, `read_2threads`: `sum b[i]` (reads only),
//!   the fairer yardstick for a read-dominated kernel such as `K_e u_e`.
//!
//! Throughput counts STREAM's bytes: 3 x 8 B per triad iteration (two reads,
//! one write; the write-allocate read is not counted), 8 B per read.

use std::hint::black_box;

use cdem::harness::perf::stream::{triad, triad_par};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rayon::prelude::*;

/// Elements per array: 8 Mi f64 = 64 MiB.
const N: usize = 8 << 20;
/// Chunk per rayon task for the read loop (1 Mi elements, 8 MiB).
const CHUNK: usize = 1 << 20;

fn sum(b: &[f64]) -> f64 {
    // Four accumulators so that the add latency does not bound the loop.
    let mut acc = [0.0; 4];
    for x in b.chunks_exact(4) {
        for k in 0..4 {
            acc[k] += x[k];
        }
    }
    acc.iter().sum()
}

fn sum_par(b: &[f64]) -> f64 {
    b.par_chunks(CHUNK).map(sum).sum()
}

fn bench(c: &mut Criterion) {
    let pool = |n| rayon::ThreadPoolBuilder::new().num_threads(n).build().expect("rayon pool");
    let (one, two) = (pool(1), pool(2));
    // One socket (no NUMA placement to care about): initialise serially.
    let mut a = vec![0.0; N];
    let b: Vec<f64> = (0..N).map(|i| i as f64).collect();
    let cc: Vec<f64> = (0..N).map(|i| (N - i) as f64).collect();
    let s = 3.0;
    let size = format!("{}MiB", (N * 8) >> 20);

    let mut group = c.benchmark_group("stream");
    group.sample_size(20);
    group.throughput(Throughput::Bytes((3 * 8 * N) as u64));
    group.bench_function(BenchmarkId::new("triad_1thread", &size), |bn| bn.iter(|| triad(&mut a, &b, &cc, s)));
    group.bench_function(BenchmarkId::new("triad_2threads", &size), |bn| {
        two.install(|| bn.iter(|| triad_par(&mut a, &b, &cc, s)))
    });
    group.throughput(Throughput::Bytes((8 * N) as u64));
    group.bench_function(BenchmarkId::new("read_1thread", &size), |bn| one.install(|| bn.iter(|| sum(black_box(&b)))));
    group.bench_function(BenchmarkId::new("read_2threads", &size), |bn| {
        two.install(|| bn.iter(|| sum_par(black_box(&b))))
    });
    group.finish();
    assert_eq!(a[1], b[1] + s * cc[1]);
}

criterion_group!(benches, bench);
criterion_main!(benches);
