//! `cdem ensemble`: runs a shard (or all) of an ensemble's members and writes
//! its files (the figures through [`crate::output::figures::ensemble`]), and
//! merges shards.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::drivers::ensemble::{self as ens, EnsembleInput, EnsembleSummary, MemberRecord, ShardInfo};

/// What `cdem ensemble INPUT` was asked for.
#[derive(Debug, Clone)]
pub struct Request {
    pub input: PathBuf,
    pub out: PathBuf,
    /// `--members` (default: `[ensemble] members`, else 100).
    pub members: Option<usize>,
    /// `--seed` (default: `[ensemble] seed`, else 1).
    pub seed: Option<u64>,
    /// `--shard I/N` (default 0/1: the whole ensemble, merged at once).
    pub shard: (usize, usize),
}

/// What was written.
pub enum Outcome {
    /// A shard of several: its records, to be merged.
    Shard { info: ShardInfo },
    /// The whole ensemble, aggregated.
    Whole { summary: Box<EnsembleSummary> },
}

/// Runs the requested members; `progress(done, total)` after each batch.
pub fn run(req: &Request, progress: &mut dyn FnMut(usize, usize)) -> crate::Result<Outcome> {
    let t0 = Instant::now();
    let input = EnsembleInput::load(&req.input)?;
    let members = req.members.unwrap_or(input.default_members());
    let seed = req.seed.unwrap_or(input.default_seed());
    let (i, n) = req.shard;
    if n == 0 || i >= n || n > members.max(1) {
        return Err(crate::error::SceneError::invalid(
            "--shard",
            format!("I/N needs 0 <= I < N <= members ({members}), got {i}/{n}"),
        )
        .into());
    }
    let range = ens::shard_range(members, req.shard);
    let total = range.len();
    let circle = ens::mean_critical_circle(&input)?;
    let records = ens::run_members(&input, seed, range.clone(), circle, &mut |done| progress(done, total))?;
    let info = ShardInfo {
        input: req.input.display().to_string(),
        digest: ens::digest_hex(input.digest),
        members,
        seed,
        shard: [i, n],
        first: range.start,
        end: range.end,
        wall_s: t0.elapsed().as_secs_f64(),
        threads: rayon::current_num_threads(),
    };
    if n > 1 {
        crate::output::ensemble::write_shard(&req.out, &info, &records)?;
        return Ok(Outcome::Shard { info });
    }
    let summary = ens::aggregate(&info.input, seed, &input.analyses, Some(input.spec.lem_surface), circle, &records);
    finish(&req.out, &summary, &records, None)?;
    crate::output::write_json(&req.out.join("run.json"), &info)?;
    Ok(Outcome::Whole { summary: Box::new(summary) })
}

/// `cdem ensemble merge DIR... --out OUT`.
pub fn merge(dirs: &[PathBuf], out: &Path) -> crate::Result<EnsembleSummary> {
    let (info, lines) = ens::merge_shards(dirs)?;
    let records: Vec<MemberRecord> = lines.iter().map(|(r, _)| r.clone()).collect();
    let input = EnsembleInput::load(Path::new(&info.input))?;
    if ens::digest_hex(input.digest) != info.digest {
        return Err(crate::error::SceneError::invalid(
            "merge",
            format!(
                "{} changed since the shards ran (digest {} now, {} then)",
                info.input,
                ens::digest_hex(input.digest),
                info.digest
            ),
        )
        .into());
    }
    let circle = ens::mean_critical_circle(&input)?;
    let summary =
        ens::aggregate(&info.input, info.seed, &input.analyses, Some(input.spec.lem_surface), circle, &records);
    let text: String = lines.iter().map(|(_, l)| format!("{l}\n")).collect();
    finish(out, &summary, &records, Some(&text))?;
    crate::output::write_json(&out.join("run.json"), &info)?;
    Ok(summary)
}

/// Writes the ensemble's files; `lines`: the member lines as the shards wrote them.
fn finish(out: &Path, summary: &EnsembleSummary, records: &[MemberRecord], lines: Option<&str>) -> crate::Result<()> {
    crate::output::ensemble::write_ensemble(out, summary, records, lines)?;
    let fs: Vec<f64> = records.iter().filter_map(|r| r.fs).collect();
    crate::output::figures::ensemble::write_figures(out, summary, &fs, records)
}
