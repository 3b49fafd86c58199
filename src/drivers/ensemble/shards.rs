//! Shards of an ensemble: what a shard ran ([`ShardInfo`]) and the merging
//! of shard directories into one complete ensemble ([`merge_shards`]).

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use super::MemberRecord;
use crate::error::SceneError;
use crate::Error;

/// `shard-I-of-N.json`: what a shard ran, for `cdem ensemble merge`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShardInfo {
    pub input: String,
    pub digest: String,
    pub members: usize,
    pub seed: u64,
    pub shard: [usize; 2],
    pub first: usize,
    pub end: usize,
    pub wall_s: f64,
    pub threads: usize,
}

/// Member records from shard directories, checked to be one complete
/// ensemble: same input and seed, every member exactly once; each with its
/// JSON line as the shard wrote it.
pub fn merge_shards(dirs: &[PathBuf]) -> crate::Result<(ShardInfo, Vec<(MemberRecord, String)>)> {
    let mut infos: Vec<ShardInfo> = Vec::new();
    // Each record with its line as written: the merged file repeats the lines.
    let mut records: Vec<(MemberRecord, String)> = Vec::new();
    let invalid = |key: &str, reason: String| Error::from(SceneError::invalid(key, reason));
    for dir in dirs {
        let entries = std::fs::read_dir(dir).map_err(|e| Error::io(dir, e))?;
        let mut names: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        names.sort();
        for p in names {
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if name.starts_with("shard-") && name.ends_with(".json") {
                let text = std::fs::read_to_string(&p).map_err(|e| Error::io(&p, e))?;
                let info: ShardInfo = serde_json::from_str(&text)
                    .map_err(|e| invalid("merge", format!("{}: not a shard record: {e}", p.display())))?;
                let jsonl = p.with_file_name(name.replace("shard-", "members-").replace(".json", ".jsonl"));
                let text = std::fs::read_to_string(&jsonl).map_err(|e| Error::io(&jsonl, e))?;
                for (line, l) in text.lines().enumerate() {
                    let r: MemberRecord = serde_json::from_str(l)
                        .map_err(|e| invalid("merge", format!("{} line {}: {e}", jsonl.display(), line + 1)))?;
                    records.push((r, l.to_string()));
                }
                infos.push(info);
            }
        }
    }
    let Some(first) = infos.first().cloned() else {
        return Err(invalid("merge", format!("no shard-*.json in {dirs:?}")));
    };
    for i in &infos {
        if (i.digest.as_str(), i.members, i.seed) != (first.digest.as_str(), first.members, first.seed) {
            return Err(invalid(
                "merge",
                format!(
                    "shard {}/{} ran {} (seed {}, {} members), shard {}/{} ran {} (seed {}, {} members)",
                    first.shard[0],
                    first.shard[1],
                    first.input,
                    first.seed,
                    first.members,
                    i.shard[0],
                    i.shard[1],
                    i.input,
                    i.seed,
                    i.members
                ),
            ));
        }
    }
    records.sort_by_key(|r| r.0.member);
    for (k, (r, _)) in records.iter().enumerate() {
        if r.member != k {
            let what = if r.member < k { "twice" } else { "missing" };
            let m = if r.member < k { r.member } else { k };
            return Err(invalid("merge", format!("member {m} is {what} (merging {} shards)", infos.len())));
        }
    }
    if records.len() != first.members {
        return Err(invalid("merge", format!("{} of {} members present", records.len(), first.members)));
    }
    let wall: f64 = infos.iter().map(|i| i.wall_s).sum();
    Ok((ShardInfo { shard: [0, 1], first: 0, end: first.members, wall_s: wall, ..first }, records))
}

/// The digest as text (JSON numbers lose bits above 2^53).
pub fn digest_hex(d: u64) -> String {
    format!("{d:016x}")
}
