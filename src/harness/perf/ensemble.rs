//! Ensembles of the paper's slip-surface slope, timed (issue 14, item 6):
//!
//! - [`members_figure`]: members per hour on this machine, in one process
//!   with the default thread count, of [`PAPER_SLOPE_SLIP`] (each member: the
//!   elastic state, eq. 21 K from the slip springs, phase 2 to its end state)
//!   and of [`PAPER_SLOPE_SLIP_SRM`] (the same, plus `cdem srm` per member);
//! - [`shards_figure`]: the same members of [`PAPER_SLOPE_SLIP`] as two
//!   `cdem ensemble --shard I/2` processes run concurrently (half the threads
//!   each) and merged, against one `cdem ensemble` process (with the default
//!   threads, and with one): the speed-ups, and whether the merged
//!   `members.jsonl` is byte-identical to the one process's (it must be:
//!   references/ensemble.md, "Determinism").
//!
//! The processes are the given executable (`cdem perf` passes its own,
//! [`std::env::current_exe`]); they run in `root` and write under the
//! directory given. The goal is in the registry
//! ([`crate::harness::registry::GOAL_SRM_MEMBERS_PER_HOUR`]).

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Instant;

use serde::Serialize;

use crate::drivers::ensemble::{self as ens, EnsembleInput};
use crate::error::{Error, SceneError};
use crate::summary::EndState;

/// The paper slope's slip-surface scene as an ensemble (random cohesion on
/// the slip surface, `analyses = ["cdem"]`), relative to the repository root.
pub const PAPER_SLOPE_SLIP: &str = "verification/ensemble/paper-slope-slip.toml";
/// The same scene and draws with `analyses = ["cdem", "srm"]`.
pub const PAPER_SLOPE_SLIP_SRM: &str = "verification/ensemble/paper-slope-slip-srm.toml";
/// Members timed without strength reduction (the in-process rate and the shards).
pub const MEMBERS: usize = 8;
/// Members timed with strength reduction (about 20 s each).
pub const SRM_MEMBERS: usize = 4;
/// The base seed of the timed members.
pub const SEED: u64 = 1;

/// Members of one ensemble input run in this process.
#[derive(Debug, Clone, Serialize)]
pub struct MembersFigure {
    pub input: String,
    pub members: usize,
    pub threads: usize,
    /// The members' run, the input read (s).
    pub seconds: f64,
    pub members_per_hour: f64,
    /// Mean eq. 21 K of the members (from the slip springs).
    pub mean_k: Option<f64>,
    /// Members whose phase 2 ended GlobalSliding / Equilibrium / Undecided.
    pub sliding: usize,
    pub equilibrium: usize,
    pub undecided: usize,
    /// With strength reduction: the mean SRM FS, the members without one, the mean trials.
    pub mean_srm_fs: Option<f64>,
    pub members_without_srm_fs: usize,
    pub mean_srm_trials: Option<f64>,
}

/// Runs members `0..members` of `input` (relative to `root`) with base seed
/// [`SEED`] in this process, no files written.
pub fn members_figure(
    root: &Path,
    input: &str,
    members: usize,
    progress: &mut dyn FnMut(&str),
) -> Result<MembersFigure, Error> {
    let ens_input = EnsembleInput::load(&root.join(input))?;
    progress(&format!("ensemble: {members} members of {input} in one process"));
    let t = Instant::now();
    let circle = ens::mean_critical_circle(&ens_input)?;
    let records = ens::run_members(&ens_input, SEED, 0..members, circle, &mut |done| {
        progress(&format!("ensemble: {input}, {done} of {members} members"));
    })?;
    let seconds = t.elapsed().as_secs_f64();
    let mean = |v: Vec<f64>| (!v.is_empty()).then(|| v.iter().sum::<f64>() / v.len() as f64);
    let ends = |e: EndState| records.iter().filter(|r| r.cdem.as_ref().and_then(|c| c.end_state) == Some(e)).count();
    let srm: Vec<_> = records.iter().filter_map(|r| r.srm.as_ref()).collect();
    Ok(MembersFigure {
        input: input.to_string(),
        members,
        threads: rayon::current_num_threads(),
        seconds,
        members_per_hour: members as f64 * 3600.0 / seconds,
        mean_k: mean(records.iter().filter_map(|r| r.cdem.as_ref().and_then(|c| c.eq21_k)).collect()),
        sliding: ends(EndState::GlobalSliding),
        equilibrium: ends(EndState::Equilibrium),
        undecided: ends(EndState::Undecided),
        mean_srm_fs: mean(srm.iter().filter_map(|s| s.fs).collect()),
        members_without_srm_fs: srm.iter().filter(|s| s.fs.is_none()).count(),
        mean_srm_trials: mean(srm.iter().map(|s| s.trials as f64).collect()),
    })
}

/// One ensemble as one process and as two concurrent shards merged.
#[derive(Debug, Clone, Serialize)]
pub struct ShardsFigure {
    pub input: String,
    pub members: usize,
    /// Threads of the one process, and of each shard.
    pub threads: usize,
    pub threads_per_shard: usize,
    /// Members the one process runs at once
    /// ([`EnsembleInput::members_at_once`] on its threads).
    pub members_at_once: usize,
    /// `cdem ensemble INPUT` as one process (s).
    pub one_process_s: f64,
    /// The same with one thread (s): what two shards on one thread each
    /// would ideally halve.
    pub one_thread_s: f64,
    /// The two shard processes, started together, until both ended (s).
    pub shards_s: f64,
    /// `cdem ensemble merge` (s).
    pub merge_s: f64,
    /// The merged `members.jsonl` and the one thread's are byte-identical
    /// to the one process's.
    pub identical: bool,
    pub jsonl_bytes: usize,
    /// The 1-minute load average before the one process and after the merge
    /// (`/proc/loadavg`; None where there is none): on a shared machine the
    /// shards compete with the other jobs as well as with each other.
    pub load_before: Option<f64>,
    pub load_after: Option<f64>,
}

impl ShardsFigure {
    /// One process's wall time over the two shards' and the merge's. Both
    /// use the same cores (the one process through its threads), so this is
    /// what sharding gains over threading on one machine, not the 2 of two
    /// machines.
    pub fn speedup(&self) -> f64 {
        self.one_process_s / (self.shards_s + self.merge_s)
    }

    /// The one process on one thread over the two shards and the merge
    /// (ideally 2 on 2 free cores).
    pub fn speedup_over_one_thread(&self) -> f64 {
        self.one_thread_s / (self.shards_s + self.merge_s)
    }

    /// The one process on one thread over the one process on its threads.
    pub fn thread_speedup(&self) -> f64 {
        self.one_thread_s / self.one_process_s
    }
}

/// Rounds of the one process against the two shards ([`shards_figure`]),
/// in alternating order; the best time of each is kept.
pub const SHARD_ROUNDS: usize = 2;

/// The 1-minute load average (Linux).
pub fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg").ok()?.split_whitespace().next()?.parse().ok()
}

fn spawn(exe: &Path, root: &Path, threads: usize, args: &[&str]) -> Result<Child, Error> {
    Command::new(exe)
        .current_dir(root)
        .env("RAYON_NUM_THREADS", threads.to_string())
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| Error::io(exe, e))
}

fn wait(exe: &Path, child: Child, what: &str) -> Result<(), Error> {
    let out = child.wait_with_output().map_err(|e| Error::io(exe, e))?;
    if out.status.success() {
        return Ok(());
    }
    let stderr = String::from_utf8_lossy(&out.stderr);
    Err(SceneError::invalid("perf.ensemble", format!("{what} failed ({}): {}", out.status, stderr.trim())).into())
}

/// Runs members `0..members` of `input` (relative to `root`), base seed
/// [`SEED`], with `exe` (a `cdem` binary) under `dir`: in each of
/// [`SHARD_ROUNDS`] rounds (alternating which runs first) as one process with
/// this process's thread count (`dir/single-R`) and as shards 0/2 and 1/2
/// started together with half the threads each (`dir/shard-R-{0,1}`, merged
/// into `dir/merged-R`), the best time of each kept; once as one process on
/// one thread (`dir/single-1-thread`); compares every `members.jsonl`.
pub fn shards_figure(
    exe: &Path,
    root: &Path,
    input: &str,
    members: usize,
    dir: &Path,
    progress: &mut dyn FnMut(&str),
) -> Result<ShardsFigure, Error> {
    if dir.exists() {
        std::fs::remove_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    }
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let dir = dir.canonicalize().map_err(|e| Error::io(dir, e))?;
    let sub = |name: &str| -> PathBuf { dir.join(name) };
    let (m, seed) = (members.to_string(), SEED.to_string());
    let threads = rayon::current_num_threads();
    let per_shard = (threads / 2).max(1);
    let path_str = |p: &Path| p.display().to_string();

    // One process on `threads` threads against two shards on `per_shard`
    // each (the same cores in total), in SHARD_ROUNDS rounds of alternating
    // order, the best of each: on a shared machine the other jobs' load
    // swings from minute to minute, and the one that runs first in a round
    // would otherwise carry it alone.
    let load_before = load_average();
    let (mut one_process_s, mut shards_s) = (f64::INFINITY, f64::INFINITY);
    let mut outputs = Vec::new();
    for round in 0..SHARD_ROUNDS {
        let single = sub(&format!("single-{round}"));
        let shard_dirs = [path_str(&sub(&format!("shard-{round}-0"))), path_str(&sub(&format!("shard-{round}-1")))];
        let one = || -> Result<f64, Error> {
            let out = path_str(&single);
            let t = Instant::now();
            let child =
                spawn(exe, root, threads, &["ensemble", input, "--members", &m, "--seed", &seed, "--out", &out])?;
            wait(exe, child, "cdem ensemble (one process)")?;
            Ok(t.elapsed().as_secs_f64())
        };
        let two = || -> Result<f64, Error> {
            let t = Instant::now();
            let children = (0..2)
                .map(|i| {
                    let shard = format!("{i}/2");
                    let args = ["ensemble", input, "--members", &m, "--seed", &seed, "--shard", &shard, "--out"];
                    let mut all: Vec<&str> = args.to_vec();
                    all.push(&shard_dirs[i]);
                    spawn(exe, root, per_shard, &all)
                })
                .collect::<Result<Vec<_>, _>>()?;
            // Both waited for before an error is returned: no shard is left running.
            let ends: Vec<_> = children
                .into_iter()
                .enumerate()
                .map(|(i, c)| wait(exe, c, &format!("cdem ensemble --shard {i}/2")))
                .collect();
            ends.into_iter().collect::<Result<Vec<()>, _>>()?;
            Ok(t.elapsed().as_secs_f64())
        };
        progress(&format!(
            "ensemble: {members} members of {input}, one process ({threads} threads) and 2 concurrent shards \
             ({per_shard} thread(s) each), round {round} ({})",
            if round % 2 == 0 { "one process first" } else { "shards first" }
        ));
        let (a, b) = if round % 2 == 0 {
            let a = one()?;
            (a, two()?)
        } else {
            let b = two()?;
            (one()?, b)
        };
        one_process_s = one_process_s.min(a);
        shards_s = shards_s.min(b);
        outputs.push((single, shard_dirs));
    }

    progress("ensemble: the same members, one process on 1 thread");
    let single1 = path_str(&sub("single-1-thread"));
    let t = Instant::now();
    let child = spawn(exe, root, 1, &["ensemble", input, "--members", &m, "--seed", &seed, "--out", &single1])?;
    wait(exe, child, "cdem ensemble (one process, 1 thread)")?;
    let one_thread_s = t.elapsed().as_secs_f64();

    progress("ensemble: merging the two shards of each round");
    let mut merge_s = f64::INFINITY;
    for (round, (_, shard_dirs)) in outputs.iter().enumerate() {
        let merged = path_str(&sub(&format!("merged-{round}")));
        let t = Instant::now();
        let child =
            spawn(exe, root, threads, &["ensemble", "merge", &shard_dirs[0], &shard_dirs[1], "--out", &merged])?;
        wait(exe, child, "cdem ensemble merge")?;
        merge_s = merge_s.min(t.elapsed().as_secs_f64());
    }

    let read = |p: PathBuf| std::fs::read(&p).map_err(|e| Error::io(&p, e));
    let a = read(sub("single-0").join("members.jsonl"))?;
    let c = read(sub("single-1-thread").join("members.jsonl"))?;
    let mut identical = a == c;
    for round in 0..SHARD_ROUNDS {
        identical &= read(sub(&format!("single-{round}")).join("members.jsonl"))? == a;
        identical &= read(sub(&format!("merged-{round}")).join("members.jsonl"))? == a;
    }
    Ok(ShardsFigure {
        input: input.to_string(),
        members,
        threads,
        threads_per_shard: per_shard,
        members_at_once: EnsembleInput::load(&root.join(input))?.members_at_once()?,
        one_process_s,
        one_thread_s,
        shards_s,
        merge_s,
        identical,
        jsonl_bytes: a.len(),
        load_before,
        load_after: load_average(),
    })
}

/// What `cdem perf` measures on the ensembles (`--no-ensemble`: nothing).
#[derive(Debug, Clone, Serialize)]
pub struct EnsembleFigures {
    pub members: MembersFigure,
    pub srm: MembersFigure,
    pub shards: ShardsFigure,
}

/// [`members_figure`] of [`PAPER_SLOPE_SLIP`] ([`MEMBERS`]) and of
/// [`PAPER_SLOPE_SLIP_SRM`] ([`SRM_MEMBERS`]), and [`shards_figure`] of
/// [`PAPER_SLOPE_SLIP`] ([`MEMBERS`]) under `dir` with `exe`.
pub fn ensemble_figures(
    exe: &Path,
    root: &Path,
    dir: &Path,
    progress: &mut dyn FnMut(&str),
) -> Result<EnsembleFigures, Error> {
    let members = members_figure(root, PAPER_SLOPE_SLIP, MEMBERS, progress)?;
    let srm = members_figure(root, PAPER_SLOPE_SLIP_SRM, SRM_MEMBERS, progress)?;
    let shards = shards_figure(exe, root, PAPER_SLOPE_SLIP, MEMBERS, dir, progress)?;
    Ok(EnsembleFigures { members, srm, shards })
}
