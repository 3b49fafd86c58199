//! An ensemble's files: `members.jsonl` (or `members-I-of-N.jsonl` with
//! `shard-I-of-N.json` for a shard), `ensemble.json` and `ensemble.md`.

use std::fmt::Write as _;
use std::path::Path;

use crate::drivers::ensemble::{EnsembleSummary, MemberRecord, ShardInfo};
use crate::error::Error;

/// One JSON object per line, in member order.
pub fn members_jsonl(records: &[MemberRecord]) -> String {
    records.iter().map(|r| serde_json::to_string(r).expect("records serialise") + "\n").collect()
}

/// A shard's records and what it ran.
pub fn write_shard(dir: &Path, info: &ShardInfo, records: &[MemberRecord]) -> Result<(), Error> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let [i, n] = info.shard;
    super::write_atomic(&dir.join(format!("members-{i}-of-{n}.jsonl")), members_jsonl(records).as_bytes())?;
    super::write_json(&dir.join(format!("shard-{i}-of-{n}.json")), info)
}

/// The records and their statistics; `lines`: the records as already written
/// (merged shards), repeated verbatim.
pub fn write_ensemble(
    dir: &Path,
    summary: &EnsembleSummary,
    records: &[MemberRecord],
    lines: Option<&str>,
) -> Result<(), Error> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let text = lines.map_or_else(|| members_jsonl(records), str::to_string);
    super::write_atomic(&dir.join("members.jsonl"), text.as_bytes())?;
    super::write_json(&dir.join("ensemble.json"), summary)?;
    super::write_atomic(&dir.join("ensemble.md"), markdown(summary).as_bytes())
}

fn g(v: f64) -> String {
    format!("{v:.4}")
}

/// `ensemble.md`: the statistics a rock engineer reads first.
pub fn markdown(s: &EnsembleSummary) -> String {
    let mut m = String::new();
    let _ = writeln!(m, "# Ensemble of `{}`\n", s.input);
    let _ = writeln!(m, "{} members, base seed {}, analyses {:?}.", s.members, s.seed, s.analyses);
    if let (Some(surface), Some(c)) = (s.lem_surface, s.lem_circle) {
        let _ = writeln!(m, "LEM on {surface:?} surface: circle xc {}, zc {}, r {}.", g(c[0]), g(c[1]), g(c[2]));
    }
    if let Some(src) = s.fs_source {
        let _ = writeln!(m, "FS: {src}; {} members without an FS.", s.members_without_fs);
    }
    if let (Some(fs), Some(r)) = (&s.fs, &s.reliability) {
        let _ = writeln!(m, "\n| quantity | value |\n|---|---|");
        let _ = writeln!(m, "| mean FS | {} (95 % CI {} to {}) |", g(fs.mean), g(fs.mean_ci95[0]), g(fs.mean_ci95[1]));
        let _ = writeln!(m, "| standard deviation | {} |", g(fs.std_dev));
        let _ = writeln!(
            m,
            "| min / 5 % / median / 95 % / max | {} / {} / {} / {} / {} |",
            g(fs.min),
            g(fs.p05),
            g(fs.p50),
            g(fs.p95),
            g(fs.max)
        );
        let _ = writeln!(
            m,
            "| probability of failure P(FS < 1) | {} (95 % CI {} to {}) |",
            g(r.probability_of_failure),
            g(r.pf_ci95[0]),
            g(r.pf_ci95[1])
        );
        let _ = writeln!(m, "| reliability index, normal | {} |", g(r.beta_normal));
        let _ = writeln!(m, "| reliability index, lognormal | {} |", g(r.beta_lognormal));
        let _ = writeln!(m, "\n| members | mean FS | 95 % CI | PF | 95 % CI |\n|---|---|---|---|---|");
        for c in &s.convergence {
            let _ = writeln!(
                m,
                "| {} | {} | {} to {} | {} | {} to {} |",
                c.n,
                g(c.mean),
                g(c.mean_ci95[0]),
                g(c.mean_ci95[1]),
                g(c.probability_of_failure),
                g(c.pf_ci95[0]),
                g(c.pf_ci95[1])
            );
        }
    }
    if !s.draws.is_empty() {
        let _ = writeln!(m, "\n| random variable | mean | standard deviation | min | max |\n|---|---|---|---|---|");
        for (k, d) in &s.draws {
            let _ = writeln!(m, "| `{k}` | {:.6e} | {:.6e} | {:.6e} | {:.6e} |", d.mean, d.std_dev, d.min, d.max);
        }
    }
    if let Some(u) = &s.elastic_max_abs_u {
        let _ = writeln!(
            m,
            "\nElastic max |u|: mean {:.4} mm, standard deviation {:.4} mm, from {:.4} to {:.4} mm.",
            1e3 * u.mean,
            1e3 * u.std_dev,
            1e3 * u.min,
            1e3 * u.max
        );
    }
    if let (Some(k), Some(r)) = (&s.eq21_k, &s.eq21_reliability) {
        let _ = writeln!(
            m,
            "\nEq. 21 K on the `[analysis]` circle (elastic state): mean {} (95 % CI {} to {}), standard deviation {}, \
             from {} to {}; P(K < 1) {} (95 % CI {} to {}).",
            g(k.mean),
            g(k.mean_ci95[0]),
            g(k.mean_ci95[1]),
            g(k.std_dev),
            g(k.min),
            g(k.max),
            g(r.probability_of_failure),
            g(r.pf_ci95[0]),
            g(r.pf_ci95[1])
        );
    }
    for (e, n) in &s.end_states {
        let _ = writeln!(m, "- phase 2 ended {e:?}: {n} members");
    }
    m
}
