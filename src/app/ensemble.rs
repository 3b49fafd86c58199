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
    /// `--resume`: keep the members already in the journal (see [`run`]).
    pub resume: bool,
}

/// What a resumed run found in its journal.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Resumed {
    /// Members read back and not run again.
    pub members: usize,
    /// Bytes of a torn last line (a record cut by a kill), dropped.
    pub torn_bytes: usize,
}

/// What was written.
pub enum Outcome {
    /// A shard of several: its records, to be merged.
    Shard { info: ShardInfo, resumed: Resumed },
    /// The whole ensemble, aggregated.
    Whole { summary: Box<EnsembleSummary>, resumed: Resumed },
}

/// The journal's companion: which ensemble its records belong to.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
struct JournalOf {
    digest: String,
    members: usize,
    seed: u64,
    shard: [usize; 2],
}

/// Reads the journal `path` back: the records of `range`'s first members,
/// in order, one JSON line each; a last line cut short (no newline, or not
/// a record) is torn and cut off the file. Any other line that is not the
/// next member's record refuses the journal.
fn read_journal(path: &Path, range: &std::ops::Range<usize>) -> crate::Result<(Vec<MemberRecord>, usize)> {
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok((Vec::new(), 0)),
        Err(e) => return Err(crate::Error::io(path, e)),
    };
    let refuse = |reason: String| crate::Error::Checkpoint {
        path: path.to_path_buf(),
        source: crate::error::CheckpointError::Content { offset: 0, reason },
    };
    let mut records = Vec::new();
    let mut good = 0;
    let mut rest = &bytes[..];
    while !rest.is_empty() {
        let Some(end) = rest.iter().position(|&b| b == b'\n') else { break };
        let line = &rest[..end];
        let record: MemberRecord = match serde_json::from_slice(line) {
            Ok(r) => r,
            // A whole line that is not a record: only the last may be torn.
            Err(_) if end + 1 == rest.len() => break,
            Err(e) => return Err(refuse(format!("line {}: not a member record: {e}", records.len() + 1))),
        };
        let want = range.start + records.len();
        if record.member != want || want >= range.end {
            return Err(refuse(format!("line {}: member {}, expected {want}", records.len() + 1, record.member)));
        }
        records.push(record);
        good += end + 1;
        rest = &rest[end + 1..];
    }
    let torn = bytes.len() - good;
    if torn > 0 {
        let f = std::fs::OpenOptions::new().write(true).open(path).map_err(|e| crate::Error::io(path, e))?;
        f.set_len(good as u64).and_then(|_| f.sync_all()).map_err(|e| crate::Error::io(path, e))?;
    }
    Ok((records, torn))
}

/// Appends `records` to the journal, one line each, synced.
fn append(path: &Path, records: &[MemberRecord]) -> crate::Result<()> {
    use std::io::Write;
    let text = crate::output::ensemble::members_jsonl(records);
    let mut f =
        std::fs::OpenOptions::new().append(true).create(true).open(path).map_err(|e| crate::Error::io(path, e))?;
    f.write_all(text.as_bytes()).and_then(|_| f.sync_data()).map_err(|e| crate::Error::io(path, e))
}

/// Runs the requested members; `progress(done, total)` after each batch.
///
/// The records are appended to a journal as each batch ends (synced): the
/// shard's `members-I-of-N.jsonl`, or `members.jsonl`, with `.journal.json`
/// saying which ensemble it is of (kept: resuming a finished run runs no
/// member and writes the same files again). With `req.resume` the members the journal
/// holds are kept and not run again (a torn last line, cut by a kill, is
/// dropped and reported), and the files are byte-identical to a run never
/// stopped (their wall times aside); a journal of another input, seed,
/// member count or shard is refused.
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
    // The journal: the records appended as each batch ends (the shard's
    // members file, or members.jsonl), with what it belongs to beside it.
    std::fs::create_dir_all(&req.out).map_err(|e| crate::Error::io(&req.out, e))?;
    let journal = req.out.join(if n > 1 { format!("members-{i}-of-{n}.jsonl") } else { "members.jsonl".into() });
    let of_path = req.out.join(".journal.json");
    let of = JournalOf { digest: ens::digest_hex(input.digest), members, seed, shard: [i, n] };
    let (done, torn_bytes) = if req.resume && journal.exists() {
        let found: Option<JournalOf> = std::fs::read(&of_path).ok().and_then(|b| serde_json::from_slice(&b).ok());
        if found.as_ref() != Some(&of) {
            return Err(crate::Error::Checkpoint {
                path: journal,
                source: crate::error::CheckpointError::Content {
                    offset: 0,
                    reason: format!(
                        "its records are of another ensemble (.journal.json says {found:?}, this run is {of:?})"
                    ),
                },
            });
        }
        read_journal(&journal, &range)?
    } else {
        crate::output::write_json(&of_path, &of)?;
        crate::output::write_atomic(&journal, b"")?;
        (Vec::new(), 0)
    };
    let resumed = Resumed { members: done.len(), torn_bytes };
    let records = ens::run_members_journaled(
        &input,
        seed,
        range.clone(),
        circle,
        done,
        &mut |done| progress(done, total),
        &mut |batch| append(&journal, batch),
    )?;
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
        // The journal is the shard's members file, whole now; the shard's
        // record, written last, says so.
        crate::output::write_json(&req.out.join(format!("shard-{i}-of-{n}.json")), &info)?;
        return Ok(Outcome::Shard { info, resumed });
    }
    let summary = ens::aggregate(&info.input, seed, &input.analyses, Some(input.spec.lem_surface), circle, &records);
    // members.jsonl repeats the journal's lines (those read back verbatim).
    let lines = std::fs::read_to_string(&journal).map_err(|e| crate::Error::io(&journal, e))?;
    finish(&req.out, &summary, &records, Some(&lines))?;
    crate::output::write_json(&req.out.join("run.json"), &info)?;
    Ok(Outcome::Whole { summary: Box::new(summary), resumed })
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
