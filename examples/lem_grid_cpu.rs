//! On-CPU time of `benches/lem_search.rs`'s `bishop_grid_only_1thread/grid_20x20x10`
//! (Bishop on the default 20 x 20 x 10 grid, one thread, no entry-exit, no
//! refinement), for a shared machine where wall-clock medians swing 2x with
//! other jobs: the time this thread spent on a CPU (Linux
//! `/proc/thread-self/schedstat`), per search, median of `ROUNDS` rounds.
//!
//! `cargo run --release --example lem_grid_cpu`

use std::path::Path;

use cdem::harness::perf::pyslope::{pyslope_grid_search, LEM_CASES};
use cdem::lem::{analyse, LemInput, Method};

const ROUNDS: usize = 15;
const PER_ROUND: usize = 40;

fn on_cpu_ns() -> u64 {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").expect("Linux schedstat");
    s.split_whitespace().next().and_then(|t| t.parse().ok()).expect("on-CPU ns")
}

fn main() {
    for (case, path) in LEM_CASES {
        let input = pyslope_grid_search(LemInput::load(Path::new(path)).expect("committed case loads"));
        let r = analyse(&input).expect("search succeeds");
        let mut cpu = Vec::with_capacity(ROUNDS);
        let mut wall = Vec::with_capacity(ROUNDS);
        for _ in 0..ROUNDS {
            let (c0, w0) = (on_cpu_ns(), std::time::Instant::now());
            for _ in 0..PER_ROUND {
                std::hint::black_box(analyse(std::hint::black_box(&input)).expect("search succeeds"));
            }
            cpu.push((on_cpu_ns() - c0) as f64 * 1e-6 / PER_ROUND as f64);
            wall.push(w0.elapsed().as_secs_f64() * 1e3 / PER_ROUND as f64);
        }
        cpu.sort_by(f64::total_cmp);
        wall.sort_by(f64::total_cmp);
        println!(
            "{case}: on-CPU {:.2} ms per search (median of {ROUNDS} x {PER_ROUND}; min {:.2}), wall {:.2} ms; \
             {} admissible circles, {} rejected; Bishop F {:.10}",
            cpu[ROUNDS / 2],
            cpu[0],
            wall[ROUNDS / 2],
            r.circles_evaluated,
            r.circles_rejected,
            r.fs.get(Method::Bishop).copied().unwrap_or(f64::NAN)
        );
    }
}
