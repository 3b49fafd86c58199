//! Progressive failure of the paper slope (Fig. 10; tests/progressive_slope.rs,
//! `cdem reproduce` step 6): failure judged only on the LEM critical circle
//! (interface "slip" of verification/cases/slope-slip/), brittle loss of
//! cohesion.
//!
//! Zones: the surface cut where the elastic (end of phase 1) K_i of the
//! spring stations crosses 1, lettered from the toe (docs/method.md 4.3).
//! Each zone gets the phase-2 step of its first failed spring and of its
//! last (fully failed); both orders are ranked and reported side by side for
//! all zones (rows `slope-failure/first-failure-order`,
//! `slope-failure/full-failure-order`, reported against the paper's order
//! taken strictly), the sequence is an insta snapshot
//! (`slope-failure/snapshot`), and what the paper states is asserted as a
//! reader takes it (`slope-failure/order-vs-paper`,
//! [`SlopeFailure::paper_order`]).

use crate::analysis::safety_factors;
use crate::analysis::slip::from_springs;
use crate::drivers::{EndState, RunResult};
use crate::harness::registry::{self as reg, SLIP_CIRCLE};
use crate::harness::report::Check;
use crate::harness::validation::{snapshot_row, SLOPE_FAILURE_SNAPSHOT};
use crate::solver::State;

/// A zone of the slip surface.
#[derive(Debug, Clone, PartialEq)]
pub struct Zone {
    /// `a`, `b`, ... from the toe.
    pub letter: char,
    /// Elastic K_i < 1 over it.
    pub weak: bool,
    /// Arc length from the toe (m).
    pub s0: f64,
    pub s1: f64,
    /// Its springs, and how many fail at all.
    pub springs: usize,
    pub failed: usize,
    /// Phase-2 step of its first and its last failure (None: none failed).
    pub first: Option<usize>,
    pub last: Option<usize>,
    /// The step by which half of its springs have failed (None: never).
    pub half: Option<usize>,
    /// Every spring failed.
    pub all_failed: bool,
    /// Its springs failed at the first failure step of the run.
    pub at_first_step: usize,
}

impl Zone {
    /// "K_i < 1" or "K_i >= 1".
    pub fn kind(&self) -> &'static str {
        if self.weak {
            "K_i < 1"
        } else {
            "K_i >= 1"
        }
    }
}

/// The zones and what happened to them.
#[derive(Debug, Clone)]
pub struct SlopeFailure {
    pub zones: Vec<Zone>,
    /// The run's first failure step.
    pub first_step: Option<usize>,
    /// Phase 2's end.
    pub end: EndState,
    /// Elastic eq. 21 K, and friction only (the cohesion lost).
    pub k: f64,
    pub k_friction_only: f64,
}

/// Rank (1 = earliest; equal steps share a rank) of `v[z]` among `v`; a zone
/// that never failed ranks after every zone that did.
fn rank(v: &[Option<usize>], z: usize) -> usize {
    let key = |x: Option<usize>| x.unwrap_or(usize::MAX);
    v.iter().filter(|&&x| key(x) < key(v[z])).count() + 1
}

impl SlopeFailure {
    /// Analyses phase 2 of a run of [`reg::SLOPE_SLIP`] (None without phase 2
    /// or without the interface "slip").
    pub fn of(run: &RunResult) -> Option<Self> {
        let r = run.failure.as_ref()?;
        let tan_phi = reg::SLIP_FRICTION_DEG.to_radians().tan();
        let mut elastic = State::new(&run.model);
        elastic.u = r.u_elastic.clone();
        let pts = from_springs(&run.model, &elastic.u, &elastic.springs, "slip", &SLIP_CIRCLE)?;
        let k = safety_factors(&pts, reg::SLIP_COHESION, tan_phi);
        let friction_only = safety_factors(&pts, 0.0, tan_phi);
        // Zones where K_i < 1 or >= 1, from the toe: (weak, s0, s1).
        let mut cut: Vec<(bool, f64, f64)> = Vec::new();
        for (i, p) in pts.iter().enumerate() {
            let weak = k.k_i[i] < 1.0;
            let edge = if i == 0 { 0.0 } else { 0.5 * (pts[i - 1].s + p.s) };
            match cut.last_mut() {
                Some(z) if z.0 == weak => z.2 = p.s,
                _ => cut.push((weak, edge, p.s)),
            }
        }
        let zone_of = |s: f64| cut.iter().position(|z| s <= z.2 + 1e-9).unwrap_or(cut.len() - 1);
        let sp = &run.model.springs;
        let iface = run.model.interfaces.iter().position(|i| i.name == "slip")? as u16;
        let on_slip: Vec<usize> = (0..sp.len()).filter(|&s| sp.interface[s] == iface).collect();
        let first_step = on_slip.iter().filter_map(|&s| r.failed_at[s]).min();
        let mut steps: Vec<Vec<Option<usize>>> = vec![Vec::new(); cut.len()];
        for &s in &on_slip {
            steps[zone_of(SLIP_CIRCLE.frame(run.model.x0[sp.a[s] as usize]).0)].push(r.failed_at[s]);
        }
        let zones = cut
            .iter()
            .zip(&steps)
            .enumerate()
            .map(|(z, (&(weak, s0, s1), st))| {
                let mut failed: Vec<usize> = st.iter().flatten().copied().collect();
                failed.sort_unstable();
                let half =
                    (2 * failed.len() >= st.len() && !st.is_empty()).then(|| failed[st.len().div_ceil(2).max(1) - 1]);
                Zone {
                    letter: (b'a' + z as u8) as char,
                    weak,
                    s0,
                    s1,
                    springs: st.len(),
                    failed: failed.len(),
                    first: failed.first().copied(),
                    last: (failed.len() == st.len()).then(|| failed.last().copied()).flatten(),
                    half,
                    all_failed: failed.len() == st.len(),
                    at_first_step: failed.iter().filter(|&&x| Some(x) == first_step).count(),
                }
            })
            .collect();
        Some(Self { zones, first_step, end: r.end, k: k.k, k_friction_only: friction_only.k })
    }

    fn ranks(&self, by: impl Fn(&Zone) -> Option<usize>) -> Vec<usize> {
        let v: Vec<Option<usize>> = self.zones.iter().map(by).collect();
        (0..v.len()).map(|z| rank(&v, z)).collect()
    }
    /// Ranks of the first failure of each zone.
    pub fn first_ranks(&self) -> Vec<usize> {
        self.ranks(|z| z.first)
    }
    /// Ranks of the full failure (last spring) of each zone.
    pub fn full_ranks(&self) -> Vec<usize> {
        self.ranks(|z| z.last)
    }

    /// The sequence of the snapshot: per zone its extent, kind, first-failure
    /// rank, whether and when (rank) it is fully failed; then the end state.
    pub fn sequence(&self) -> Vec<String> {
        let (first, full) = (self.first_ranks(), self.full_ranks());
        self.zones
            .iter()
            .enumerate()
            .map(|(i, z)| {
                format!(
                    "{} {:.0}-{:.0} m {}: first failure rank {}, fully failed {} (rank {})",
                    z.letter,
                    z.s0,
                    z.s1,
                    z.kind(),
                    first[i],
                    z.all_failed,
                    full[i]
                )
            })
            .chain(std::iter::once(format!("end: {:?}", self.end)))
            .collect()
    }

    /// The zones in the order of `ranks`, grouped by equal rank:
    /// "a, b, c (K_i < 1, >= 1, < 1); d (>= 1); e (< 1)".
    fn order(&self, ranks: &[usize]) -> String {
        let mut idx: Vec<usize> = (0..self.zones.len()).collect();
        idx.sort_by_key(|&z| (ranks[z], z));
        let mut groups: Vec<Vec<usize>> = Vec::new();
        for z in idx {
            match groups.last_mut() {
                Some(g) if ranks[g[0]] == ranks[z] => g.push(z),
                _ => groups.push(vec![z]),
            }
        }
        groups
            .iter()
            .map(|g| {
                g.iter()
                    .map(|&z| format!("{} ({})", self.zones[z].letter, self.zones[z].kind()))
                    .collect::<Vec<_>>()
                    .join(" with ")
            })
            .collect::<Vec<_>>()
            .join(", then ")
    }

    /// Every K_i < 1 zone ranks strictly before every K_i >= 1 zone.
    fn weak_before_strong(&self, ranks: &[usize]) -> bool {
        let weak = self.zones.iter().zip(ranks).filter(|(z, _)| z.weak).map(|(_, &r)| r).max();
        let strong = self.zones.iter().zip(ranks).filter(|(z, _)| !z.weak).map(|(_, &r)| r).min();
        matches!((weak, strong), (Some(w), Some(s)) if w < s)
    }

    /// The paper (Fig. 10): "discontinuities in ab and cd first, then in bc
    /// and de, then the whole mass slides"; its ab, cd are where K_i < 1,
    /// its bc, de where K_i >= 1 (docs/method.md 4.3). As a reader of the
    /// figure takes it, over all our zones:
    /// - the failure starts in the K_i < 1 zones: most of the springs that
    ///   fail at the run's first failure step lie in K_i < 1 zones
    ///   ([`Self::starts_where_weak`]), and no K_i >= 1 zone is half failed
    ///   then (its discontinuity appears later);
    /// - it spreads to the K_i >= 1 zones: every zone fails completely;
    /// - then the mass slides: phase 2 ends in `GlobalSliding`.
    ///
    /// It does not say that every K_i < 1 zone fails before every K_i >= 1
    /// zone: that is the strict order of the two reported rows (first and
    /// full failure), where our crest zone e (K_i < 1) fails last.
    pub fn paper_order(&self) -> bool {
        let later = |z: &Zone| z.half.zip(self.first_step).is_some_and(|(h, f)| h > f);
        self.starts_where_weak()
            && self.zones.iter().filter(|z| !z.weak).all(later)
            && self.zones.iter().all(|z| z.all_failed)
            && self.end == EndState::GlobalSliding
    }

    /// The springs that fail at the first failure step lie mostly in K_i < 1 zones.
    pub fn starts_where_weak(&self) -> bool {
        let (weak, strong) = self.at_first_step();
        weak > strong
    }

    /// Springs failed at the first failure step in K_i < 1 and in K_i >= 1 zones.
    pub fn at_first_step(&self) -> (usize, usize) {
        self.zones
            .iter()
            .fold((0, 0), |(w, s), z| if z.weak { (w + z.at_first_step, s) } else { (w, s + z.at_first_step) })
    }

    /// The rows: the snapshot, both orders reported against the paper's
    /// statement (strictly: every K_i < 1 zone before every K_i >= 1 zone),
    /// and the paper's statement asserted as a reader takes it
    /// ([`Self::paper_order`]).
    pub fn rows(&self, seconds: f64) -> Vec<Check> {
        let (first, full) = (self.first_ranks(), self.full_ranks());
        let paper = "ab and cd (K_i < 1) first, then bc and de (K_i >= 1), then the mass slides";
        let note = "all five zones; see references/paper.md, Fig. 10";
        vec![
            snapshot_row("slope-failure/snapshot", &self.sequence(), SLOPE_FAILURE_SNAPSHOT, seconds),
            reg::row("slope-failure/first-failure-order")
                .compared(
                    &format!("first failure: {}", self.order(&first)),
                    paper,
                    self.weak_before_strong(&first),
                    seconds,
                )
                .with_note(note),
            reg::row("slope-failure/full-failure-order")
                .compared(
                    &format!("fully failed: {}; then {:?}", self.order(&full), self.end),
                    paper,
                    self.weak_before_strong(&full) && self.end == EndState::GlobalSliding,
                    seconds,
                )
                .with_note(note),
            reg::row("slope-failure/order-vs-paper")
                .compared(&self.describe_start(), paper, self.paper_order(), seconds)
                .with_note("as a reader takes it; the strict orders are the two rows above, see references/paper.md"),
        ]
    }

    /// Where the failure starts and how it spreads, per zone: "first failure
    /// step 1: 45 of 47 failed springs in K_i < 1 zones (a 6/6, ...); half
    /// failed: a 1, ...; fully failed: a 1, ...; then GlobalSliding".
    pub fn describe_start(&self) -> String {
        let (weak, strong) = self.at_first_step();
        let step = |s: Option<usize>| s.map_or("never".to_string(), |s| s.to_string());
        let list = |f: &dyn Fn(&Zone) -> String| {
            self.zones.iter().map(|z| format!("{} {}", z.letter, f(z))).collect::<Vec<_>>().join(", ")
        };
        format!(
            "first failure step {}: {weak} of {} failed springs in K_i < 1 zones ({}); half failed at step: {}; \
             fully failed at step: {}; then {:?}",
            step(self.first_step),
            weak + strong,
            list(&|z| format!("({}) {}/{}", if z.weak { "< 1" } else { ">= 1" }, z.at_first_step, z.springs)),
            list(&|z| step(z.half)),
            list(&|z| step(z.last)),
            self.end
        )
    }
}
