//! The machine's memory bandwidth, the yardstick of "fraction of stream":
//! the STREAM triad `a = b + s c` over three arrays of f64, timed on the
//! current rayon pool. [`triad`] and [`triad_par`] are also the loops
//! `benches/stream.rs` measures with criterion.

use std::time::Instant;

/// STREAM triad `a = b + s c` over three arrays of f64 on the current rayon
/// pool, kept for batches timed between other measurements
/// ([`Triad::batch`]): `cdem perf` interleaves them with the step's
/// batches, so that both see the same moments of a shared machine.
pub struct Triad {
    a: Vec<f64>,
    b: Vec<f64>,
    c: Vec<f64>,
}

impl Triad {
    /// Three arrays of `n` f64.
    pub fn new(n: usize) -> Self {
        Self { a: vec![0.0; n], b: (0..n).map(|i| i as f64).collect(), c: (0..n).map(|i| (n - i) as f64).collect() }
    }

    /// `passes` triads timed together, in GB/s (24 B per iteration; the
    /// write-allocate read is not counted, as in STREAM).
    pub fn batch(&mut self, passes: usize) -> f64 {
        let passes = passes.max(1);
        let t = Instant::now();
        for _ in 0..passes {
            triad_par(&mut self.a, &self.b, &self.c, 3.0);
        }
        let s = t.elapsed().as_secs_f64();
        std::hint::black_box(&self.a);
        24.0 * (self.a.len() * passes) as f64 / s / 1e9
    }
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
