//! The cost of a `cdem srm` checkpoint ([`crate::drivers::checkpoint`]): the
//! warm-start state of Griffiths & Lane's slope with plastic blocks
//! (hexahedra: every tetrahedron's history, the largest state per element)
//! encoded, framed and written as a checkpoint is (temporary file, fsync,
//! rename), against the default interval `--checkpoint-every 300`: the
//! share of wall time the checkpoints take (goal <= 2 %, issue 57).

use std::path::Path;
use std::time::Instant;

use crate::drivers::checkpoint::{frame, Checkpointing, Codec, Enc, DEFAULT_EVERY_S};
use crate::error::Error;
use crate::harness::report::Check;
use crate::solver::State;

/// The scene whose state is written.
pub const CHECKPOINT_SCENE: &str = "verification/plastic/griffiths-lane-1/gl1-hex.toml";

/// What [`checkpoint_cost`] measured.
#[derive(Debug, Clone, Copy)]
pub struct CheckpointCost {
    pub elements: usize,
    pub bytes: usize,
    /// The median of the writes (s).
    pub write_s: f64,
    /// `write_s` / the default interval.
    pub share: f64,
}

/// Writes the checkpoint of the scene's state `writes` times into `dir`
/// (the median write kept).
pub fn checkpoint_cost(root: &Path, dir: &Path, writes: usize) -> Result<CheckpointCost, Error> {
    let scene = crate::scene::Scene::load(&root.join(CHECKPOINT_SCENE))?;
    let mesh = crate::drivers::read_mesh(&scene)?;
    let model = crate::model::build(&mesh, &scene.model_spec())?;
    let state = State::new(&model);
    let ck = Checkpointing::new(dir, 0.0, None);
    let mut times = Vec::new();
    let mut bytes = 0;
    for _ in 0..writes.max(1) {
        let t = Instant::now();
        let mut w = Enc::default();
        state.put(&mut w);
        bytes = frame("srm", 0, &w.0).len();
        ck.write("srm", 0, &w.0)?;
        times.push(t.elapsed().as_secs_f64());
    }
    ck.remove();
    times.sort_by(f64::total_cmp);
    let write_s = times[times.len() / 2];
    Ok(CheckpointCost { elements: mesh.cells.len(), bytes, write_s, share: write_s / DEFAULT_EVERY_S })
}

/// The row `perf/checkpoint/srm-write`.
pub fn checkpoint_row(c: &CheckpointCost) -> Check {
    crate::harness::registry::row("perf/checkpoint/srm-write").value(c.share, 0.02, c.write_s).with_note(format!(
        "{} elements, {:.2} MB written in {:.1} ms (median), against --checkpoint-every {DEFAULT_EVERY_S} s",
        c.elements,
        c.bytes as f64 / 1e6,
        c.write_s * 1e3
    ))
}
