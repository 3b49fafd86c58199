//! Circular slip-surface search (src/lem) on ACADS 1(a) and the paper's slope.
//!
//! - `<case>/full/grid_NXxNZxNR`: the whole search as `cdem lem` runs it:
//!   grid NX x NZ centres x NR radii, entry-exit NX x NZ pairs x NR radii,
//!   Nelder-Mead refinement, all three methods, rayon on.
//! - `<case>/bishop_grid_only_1thread/grid_20x20x10`: Bishop on the grid's
//!   4000 trial circles, no entry-exit, no refinement, one thread: the same
//!   work as `scripts/pyslope_check.py`'s timing of pySlope (references/pyslope.json).

use std::path::Path;

use cdem::harness::perf::pyslope::{pyslope_grid_search, LEM_CASES};
use cdem::lem::{analyse, EntryExitSpec, GridSpec, LemInput, Method, Mode, SearchSpec};
use criterion::{criterion_group, criterion_main, Criterion};

fn with_search(base: &LemInput, spec: SearchSpec, methods: &[Method]) -> LemInput {
    LemInput { mode: Mode::Search(spec), methods: methods.to_vec(), ..base.clone() }
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("lem_search");
    group.sample_size(10);
    for (case, path) in LEM_CASES {
        let base = LemInput::load(Path::new(path)).expect("committed case loads");
        for n in [10usize, 20, 40] {
            let spec = SearchSpec {
                grid: Some(GridSpec { x: None, z: None, nx: n, nz: n, radii: n / 2 }),
                entry_exit: Some(EntryExitSpec { exit: None, entry: None, n_exit: n, n_entry: n, radii: n / 2 }),
                ..SearchSpec::default()
            };
            let input = with_search(&base, spec, &Method::ALL);
            group.bench_function(format!("{case}/full/grid_{n}x{n}x{}", n / 2), |b| {
                b.iter(|| analyse(&input).expect("search succeeds"))
            });
        }
        let input = pyslope_grid_search(base);
        group.bench_function(format!("{case}/bishop_grid_only_1thread/grid_20x20x10"), |b| {
            b.iter(|| analyse(&input).expect("search succeeds"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
