//! An ensemble's statistics, `ensemble.json` ([`EnsembleSummary`]), from
//! its member records ([`aggregate`]).

use serde::Serialize;

use super::MemberRecord;
use crate::analysis::stats::{self, ConvergencePoint, Distribution as Stats, Reliability};
use crate::lem;
use crate::scene::{Analysis, LemSurface};
use crate::summary::EndState;

/// What `ensemble.json` holds.
#[derive(Debug, Clone, Serialize)]
pub struct EnsembleSummary {
    pub input: String,
    pub members: usize,
    pub seed: u64,
    pub analyses: Vec<Analysis>,
    pub lem_surface: Option<LemSurface>,
    /// The mean critical circle (xc, zc, r) the members were evaluated on.
    pub lem_circle: Option<[f64; 3]>,
    pub fs_source: Option<&'static str>,
    /// Members without an FS (an inadmissible circle, no Bishop root).
    pub members_without_fs: usize,
    pub fs: Option<Stats>,
    pub reliability: Option<Reliability>,
    pub convergence: Vec<ConvergencePoint>,
    /// Statistics of each random variable's draws.
    pub draws: Vec<(String, Stats)>,
    pub elastic_max_abs_u: Option<Stats>,
    /// Eq. 21 K of the members with `[analysis]` (`CdemMember::eq21_k`).
    pub eq21_k: Option<Stats>,
    /// `P(K < 1)` and the reliability indices of eq. 21 K: a stress-based
    /// probability beside the FS's.
    pub eq21_reliability: Option<Reliability>,
    /// Members per phase-2 end state.
    pub end_states: Vec<(EndState, usize)>,
}

/// The statistics of complete records (member order).
pub fn aggregate(
    input: &str,
    seed: u64,
    analyses: &[Analysis],
    lem_surface: Option<LemSurface>,
    lem_circle: Option<lem::Circle>,
    records: &[MemberRecord],
) -> EnsembleSummary {
    let fs: Vec<f64> = records.iter().filter_map(|r| r.fs).collect();
    let keys: Vec<String> = records.first().map_or(Vec::new(), |r| r.draws.iter().map(|d| d.key.clone()).collect());
    let draws = keys
        .iter()
        .enumerate()
        .filter_map(|(i, k)| {
            let v: Vec<f64> = records.iter().map(|r| r.draws[i].value).collect();
            stats::distribution(&v).map(|d| (k.clone(), d))
        })
        .collect();
    let u: Vec<f64> = records.iter().filter_map(|r| r.cdem.as_ref().map(|c| c.elastic_max_abs_u)).collect();
    let k: Vec<f64> = records.iter().filter_map(|r| r.cdem.as_ref().and_then(|c| c.eq21_k)).collect();
    let mut end_states = Vec::new();
    for e in [EndState::Equilibrium, EndState::GlobalSliding, EndState::Undecided] {
        let n = records.iter().filter(|r| r.cdem.as_ref().and_then(|c| c.end_state) == Some(e)).count();
        if n > 0 {
            end_states.push((e, n));
        }
    }
    let has_lem = analyses.contains(&Analysis::Lem);
    EnsembleSummary {
        input: input.to_string(),
        members: records.len(),
        seed,
        analyses: analyses.to_vec(),
        lem_surface: lem_surface.filter(|_| has_lem),
        lem_circle: lem_circle.map(|c| [c.xc, c.zc, c.r]),
        fs_source: if analyses.contains(&Analysis::Srm) {
            Some("strength reduction (cdem srm)")
        } else {
            has_lem.then_some("LEM Bishop simplified (else Spencer, else ordinary)")
        },
        members_without_fs: records.len() - fs.len(),
        fs: stats::distribution(&fs),
        reliability: stats::reliability(&fs),
        convergence: if fs.is_empty() { Vec::new() } else { stats::convergence(&fs) },
        draws,
        elastic_max_abs_u: stats::distribution(&u),
        eq21_k: stats::distribution(&k),
        eq21_reliability: stats::reliability(&k),
        end_states,
    }
}
