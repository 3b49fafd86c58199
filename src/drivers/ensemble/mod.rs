//! Monte-Carlo ensembles over the stochastic structural planes (docs/method.md
//! section 4.7): member `k` of an ensemble with base seed `BASE` is the input
//! file's typed input (its [`Scene`], or a LEM file's [`LemInput`]) with
//! - its `perturbation.seed` set to [`member_seed`]`(BASE, k)` (a scene with
//!   `[perturbation]`): another realisation of the random joint geometry;
//! - each `[[ensemble.random]]` number drawn from its distribution with the
//!   member's own stream ([`draw`]) and set on the number its key names
//!   ([`keys`]);
//!
//! and is run by the analyses of `[ensemble] analyses`. A member depends on
//! `(file, BASE, k)` only, so members are the same whatever the sharding
//! (`--shard I/N` runs members `[I M / N, (I + 1) M / N)`) and thread count, and
//! their records ([`MemberRecord`], one JSON line each, no timings) are
//! byte-identical. [`aggregate`] turns the records into the statistics of
//! [`crate::analysis::stats`].

pub mod keys;
mod shards;
mod summary;

use std::path::{Path, PathBuf};

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::srm::Phase2Run;
use crate::error::SceneError;
use crate::lem::{self, LemInput, Method, Mode};
use crate::mesh::perturb::SplitMix64;
use crate::scene::{Analysis, Distribution, EnsembleSpec, LemSurface, Scene};
use crate::summary::EndState;
use crate::Error;

pub use shards::{digest_hex, merge_shards, ShardInfo};
pub use summary::{aggregate, EnsembleSummary};

/// The golden-ratio increment of SplitMix64.
const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;
/// Separates a member's strength stream from its perturbation seed.
const STRENGTH_STREAM: u64 = 0x5EED_57E4_6770_0001;
/// Draws outside `[min, max]` are redrawn at most this often.
const MAX_REDRAWS: usize = 10_000;

/// Member `k`'s perturbation seed: the `(k + 1)`-th output of a SplitMix64
/// stream started at `base`, shifted right by one bit so that it is a TOML
/// integer (`0 <= seed < 2^63`).
pub fn member_seed(base: u64, k: usize) -> u64 {
    SplitMix64::new(base.wrapping_add((k as u64).wrapping_mul(GOLDEN))).next_u64() >> 1
}

/// An input file ready to be varied.
#[derive(Debug, Clone)]
pub struct EnsembleInput {
    pub path: PathBuf,
    pub base_dir: PathBuf,
    /// The mean input: the file's own values.
    source: Source,
    /// True for a CDEM scene (a `[mesh]` table), false for a LEM file.
    pub is_scene: bool,
    pub spec: EnsembleSpec,
    pub analyses: Vec<Analysis>,
    /// The mean value of every random variable (its `mean`, or the file's value).
    pub means: Vec<f64>,
    /// FNV-1a 64 of the file's bytes: shards of different inputs do not merge.
    pub digest: u64,
}

/// The elements of the members [`run_members`] keeps in memory at once:
/// a model with its solver takes about 20 kB per element at its peak (2 GB
/// at 100,000 elements, references/perf/full-2026-12-06-tenth/scaling.csv),
/// so about 2 GB.
pub const ELEMENTS_AT_ONCE: usize = 100_000;

/// Members of `elements` elements run at once on `threads` threads: twice
/// the threads, within [`ELEMENTS_AT_ONCE`], at least one.
fn models_at_once(elements: usize, threads: usize) -> usize {
    (2 * threads.max(1)).min(ELEMENTS_AT_ONCE / elements.max(1)).max(1)
}

/// A drawn value.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Draw {
    pub key: String,
    pub value: f64,
}

/// The LEM of one member.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LemMember {
    pub ordinary: Option<f64>,
    pub bishop: Option<f64>,
    pub spencer: Option<f64>,
    /// The circle (xc, zc, r) of the headline method.
    pub circle: [f64; 3],
}

/// The CDEM run of one member.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CdemMember {
    /// Largest displacement magnitude at the end of phase 1 (m).
    pub elastic_max_abs_u: f64,
    pub elastic_converged: bool,
    pub elastic_steps: usize,
    /// Phase 2's end state (with `[failure]`).
    pub end_state: Option<EndState>,
    pub failed_tension: usize,
    pub failed_shear: usize,
    /// Phase-2 step of the first spring failure and the mean position of the
    /// springs that failed then (m).
    pub first_failure_step: Option<usize>,
    pub first_failure_at: Option<[f64; 3]>,
    /// Eq. 21 K on the scene's `[analysis]` circle at the elastic state: from
    /// the interface's springs when it names one, else from the element
    /// stresses. None without `[analysis]`.
    #[serde(default)]
    pub eq21_k: Option<f64>,
}

/// One member's record: one JSON line of `members.jsonl`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MemberRecord {
    pub member: usize,
    /// The perturbation seed (a scene with `[perturbation]`), else the seed of its draws.
    pub seed: u64,
    pub draws: Vec<Draw>,
    /// The headline factor of safety: the strength-reduction FS with `"srm"`,
    /// else the LEM's Bishop FS (else Spencer's, else ordinary).
    pub fs: Option<f64>,
    pub lem: Option<LemMember>,
    pub cdem: Option<CdemMember>,
    /// Strength reduction (`analyses` with `"srm"`).
    pub srm: Option<SrmMember>,
}

/// The strength reduction of one member.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SrmMember {
    /// Midpoint of the final bracket; None without one.
    pub fs: Option<f64>,
    pub bracket: [Option<f64>; 2],
    pub trials: usize,
}

/// The mean input of an ensemble, typed.
#[derive(Debug, Clone)]
enum Source {
    Scene {
        /// The scene as the file gives it, without its `[ensemble]`.
        scene: Box<Scene>,
        /// Whether the file has a `[perturbation]` table (members then get their seeds).
        perturbed: bool,
    },
    Lem(Box<keys::LemParts>),
}

/// A member's input: the mean input with its drawn values (and seed) set.
#[derive(Debug, Clone)]
pub enum MemberInput {
    Scene(Box<Scene>),
    Lem(Box<LemInput>),
}

impl MemberInput {
    /// The member's LEM input: a LEM file's, or that of the scene's `[lem]`.
    pub fn lem_input(&self) -> crate::Result<LemInput> {
        match self {
            MemberInput::Scene(scene) => super::lem::scene_lem_input(scene),
            MemberInput::Lem(input) => Ok((**input).clone()),
        }
    }
}

fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ b as u64).wrapping_mul(0x100_0000_01b3))
}

impl EnsembleInput {
    /// Reads a scene or LEM file with an `[ensemble]` table (or none: the
    /// members then differ only by their perturbation seeds).
    pub fn load(path: &Path) -> crate::Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let base_dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        let syntax = |e: String| SceneError::Syntax { path: path.to_path_buf(), message: e };
        let mut table: toml::Table = text.parse().map_err(|e: toml::de::Error| syntax(e.to_string()))?;
        let is_scene = table.contains_key("mesh");
        // The file as a whole must be valid as it stands (the mean member).
        let source = if is_scene {
            let mut scene = Scene::from_toml(&text, &base_dir, path)?;
            if scene.lem.is_none() && scene.perturbation.ratio == 0.0 && scene.ensemble.is_none() {
                return Err(SceneError::invalid(
                    "ensemble",
                    "nothing varies: the scene has no perturbation, no [ensemble] random variables and no [lem]",
                )
                .into());
            }
            scene.ensemble = None;
            Source::Scene { scene: Box::new(scene), perturbed: table.contains_key("perturbation") }
        } else {
            let input = LemInput::from_toml(&text, &base_dir, path)?;
            let materials = table.get("material").and_then(toml::Value::as_array);
            let zoned: Vec<bool> = materials
                .map_or(&[][..], Vec::as_slice)
                .iter()
                .map(|m| m.as_table().is_some_and(|m| m.contains_key("zone")))
                .collect();
            Source::Lem(Box::new(keys::LemParts::new(&input, &zoned)))
        };
        let spec: EnsembleSpec = match table.remove("ensemble") {
            None => EnsembleSpec::default(),
            Some(v) => v.try_into().map_err(|e: toml::de::Error| syntax(format!("[ensemble]: {e}")))?,
        };
        spec.validate()?;
        let has_lem = !is_scene || table.contains_key("lem");
        let analyses = match &spec.analyses {
            Some(a) => a.clone(),
            None if !is_scene => vec![Analysis::Lem],
            None if has_lem => vec![Analysis::Cdem, Analysis::Lem],
            None => vec![Analysis::Cdem],
        };
        if (analyses.contains(&Analysis::Cdem) || analyses.contains(&Analysis::Srm)) && !is_scene {
            return Err(SceneError::invalid(
                "ensemble.analyses",
                "\"cdem\" and \"srm\" need a scene (a file with [mesh])",
            )
            .into());
        }
        if analyses.contains(&Analysis::Lem) && !has_lem {
            return Err(SceneError::invalid("ensemble.analyses", "\"lem\" needs a [lem] table in the scene").into());
        }
        let mut means = Vec::with_capacity(spec.random.len());
        let mut probe = source.clone();
        for (i, r) in spec.random.iter().enumerate() {
            let bad_key = |e: keys::UnknownKey| SceneError::invalid(format!("ensemble.random[{i}].key"), e.to_string());
            let v = *probe.number(&r.key).map_err(bad_key)?;
            let mean = r.mean.unwrap_or(v);
            if r.distribution == Distribution::Lognormal && mean <= 0.0 {
                return Err(SceneError::invalid(
                    format!("ensemble.random[{i}].mean"),
                    format!("a lognormal variable needs a positive mean, got {mean}"),
                )
                .into());
            }
            means.push(mean);
        }
        Ok(EnsembleInput {
            path: path.to_path_buf(),
            base_dir,
            source,
            is_scene,
            spec,
            analyses,
            means,
            digest: fnv1a(text.as_bytes()),
        })
    }

    /// The `[ensemble] members` default, else 100.
    pub fn default_members(&self) -> usize {
        self.spec.members.unwrap_or(100)
    }

    /// The `[ensemble] seed` default, else 1.
    pub fn default_seed(&self) -> u64 {
        self.spec.seed.unwrap_or(1)
    }

    /// Member `k`'s seed and draws.
    pub fn draws(&self, base: u64, k: usize) -> crate::Result<(u64, Vec<Draw>)> {
        let seed = member_seed(base, k);
        let mut rng = SplitMix64::new(seed ^ STRENGTH_STREAM);
        let mut draws = Vec::with_capacity(self.spec.random.len());
        for (i, (r, &mean)) in self.spec.random.iter().zip(&self.means).enumerate() {
            let value = draw(&mut rng, r.distribution, mean, r.std_dev, r.min, r.max).ok_or_else(|| {
                SceneError::invalid(
                    format!("ensemble.random[{i}]"),
                    format!("no draw within [min, max] in {MAX_REDRAWS} tries: the bounds exclude the distribution"),
                )
            })?;
            draws.push(Draw { key: r.key.clone(), value });
        }
        Ok((seed, draws))
    }

    /// How many members [`run_members`] runs at once. LEM-only members:
    /// 256. Members with a model: twice the thread count, so that each
    /// thread mostly runs a member of its own (on a model of a thousand
    /// elements one member per core is faster than one member on all of
    /// them: references/performance.md, "2026-12-06 (tenth)"), but no more
    /// than keep [`ELEMENTS_AT_ONCE`] elements in memory together (at least
    /// one member). Reads the mesh for its element count.
    pub fn members_at_once(&self) -> crate::Result<usize> {
        match &self.source {
            Source::Scene { scene, .. } if self.analyses != [Analysis::Lem] => {
                Ok(models_at_once(super::input::read_mesh(scene)?.cells.len(), rayon::current_num_threads()))
            }
            _ => Ok(256),
        }
    }

    /// The input of the member with perturbation seed `seed` and `draws`:
    /// the mean input with the seed and every drawn value set on it, checked
    /// as the file would be.
    pub fn member_input(&self, seed: u64, draws: &[Draw]) -> crate::Result<MemberInput> {
        let mut source = self.source.clone();
        let unknown = |e: keys::UnknownKey| SceneError::invalid("ensemble.random", e.to_string());
        for d in draws {
            *source.number(&d.key).map_err(unknown)? = d.value;
        }
        match source {
            Source::Scene { mut scene, perturbed } => {
                // A drawn perturbation.ratio perturbs with the member's seed too.
                if perturbed || draws.iter().any(|d| d.key.starts_with("perturbation.")) {
                    scene.perturbation.seed = seed;
                }
                scene.validate()?;
                Ok(MemberInput::Scene(scene))
            }
            Source::Lem(parts) => Ok(MemberInput::Lem(Box::new(parts.input()?))),
        }
    }
}

impl Source {
    /// The number of the mean input that a key names.
    fn number(&mut self, key: &str) -> Result<&mut f64, keys::UnknownKey> {
        match self {
            Source::Scene { scene, .. } => keys::scene_number(scene, key),
            Source::Lem(parts) => parts.number(key),
        }
    }
}

/// A standard normal variate (Box-Muller, the cosine branch; two uniforms per draw).
fn standard_normal(rng: &mut SplitMix64) -> f64 {
    let u1 = 1.0 - rng.next_f64(); // (0, 1]
    let u2 = rng.next_f64();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// One draw of a normal or lognormal variable with mean `mean` and standard
/// deviation `sd` (of the variable itself: for the lognormal,
/// `s^2 = ln(1 + sd^2 / mean^2)`, `ln X ~ N(ln mean - s^2 / 2, s^2)`),
/// redrawn while outside `[min, max]`; `None` if that never succeeds.
pub fn draw(
    rng: &mut SplitMix64,
    d: Distribution,
    mean: f64,
    sd: f64,
    min: Option<f64>,
    max: Option<f64>,
) -> Option<f64> {
    (0..MAX_REDRAWS)
        .map(|_| {
            let z = standard_normal(rng);
            match d {
                Distribution::Normal => mean + sd * z,
                Distribution::Lognormal => {
                    let s2 = (1.0 + (sd / mean).powi(2)).ln();
                    (mean.ln() - 0.5 * s2 + s2.sqrt() * z).exp()
                }
            }
        })
        .find(|v| min.is_none_or(|lo| *v >= lo) && max.is_none_or(|hi| *v <= hi))
}

/// Which members a shard runs: `[I M / N, (I + 1) M / N)`.
pub fn shard_range(members: usize, shard: (usize, usize)) -> std::ops::Range<usize> {
    let (i, n) = shard;
    (i * members / n)..((i + 1) * members / n)
}

fn headline(fs: &lem::PerMethod<f64>) -> Option<(Method, f64)> {
    [Method::Bishop, Method::Spencer, Method::Ordinary].into_iter().find_map(|m| fs.get(m).map(|&f| (m, f)))
}

/// The critical circle of the mean input, for `lem_surface = "critical"`.
pub fn mean_critical_circle(input: &EnsembleInput) -> crate::Result<Option<lem::Circle>> {
    if !input.analyses.contains(&Analysis::Lem) || input.spec.lem_surface == LemSurface::Search {
        return Ok(None);
    }
    let lem_input = match &input.source {
        Source::Scene { scene, .. } => super::lem::scene_lem_input(scene)?,
        Source::Lem(parts) => parts.input()?,
    };
    if let Mode::Circle(c) = lem_input.mode {
        return Ok(Some(c));
    }
    let result = lem::analyse(&lem_input)?;
    let (m, _) = headline(&result.fs).ok_or_else(|| {
        SceneError::invalid("lem", "the mean input has no admissible slip circle: no critical circle to sample on")
    })?;
    let c = result.critical.get(m).expect("a method with an FS has a circle");
    Ok(Some(c.circle))
}

/// Runs member `k`. `circle`: the mean critical circle (LEM on it), or None (a search).
pub fn run_member(
    input: &EnsembleInput,
    base: u64,
    k: usize,
    circle: Option<lem::Circle>,
) -> crate::Result<MemberRecord> {
    let (seed, draws) = input.draws(base, k)?;
    let member_error = |e: Error| match e {
        Error::Scene(SceneError::Invalid { key, reason }) => {
            Error::Scene(SceneError::invalid(key, format!("{reason} (ensemble member {k}, draws {draws:?})")))
        }
        other => other,
    };
    let mut record = MemberRecord { member: k, seed, draws: draws.clone(), fs: None, lem: None, cdem: None, srm: None };
    let member = input.member_input(seed, &draws).map_err(member_error)?;
    if input.analyses.contains(&Analysis::Lem) {
        let mut lem_input = member.lem_input().map_err(member_error)?;
        if let Some(c) = circle {
            lem_input.mode = Mode::Circle(c);
        }
        // On a fixed circle a member may have no FS (e.g. m_alpha <= 0): recorded as none.
        let result = match lem::analyse(&lem_input) {
            Ok(r) => Some(r),
            Err(_) if circle.is_some() => None,
            Err(e) => return Err(member_error(e)),
        };
        if let Some(r) = result {
            let h = headline(&r.fs);
            let c = h.and_then(|(m, _)| r.critical.get(m)).map(|c| c.circle);
            record.fs = h.map(|(_, f)| f);
            record.lem = Some(LemMember {
                ordinary: r.fs.get(Method::Ordinary).copied(),
                bishop: r.fs.get(Method::Bishop).copied(),
                spencer: r.fs.get(Method::Spencer).copied(),
                circle: c.map_or([f64::NAN; 3], |c| [c.xc, c.zc, c.r]),
            });
        }
    }
    let scene = match &member {
        MemberInput::Scene(scene) if input.analyses.iter().any(|a| matches!(a, Analysis::Cdem | Analysis::Srm)) => {
            Some(scene)
        }
        _ => None,
    };
    // The CDEM run, kept for the strength reduction: its phase 2 is the
    // search's trial at F = 1 (`srm::Phase2Run`).
    let mut cdem_run = None;
    if let (true, Some(scene)) = (input.analyses.contains(&Analysis::Cdem), &scene) {
        // Eq. 21 on the mean critical circle, as the LEM (`lem_surface = "critical"`),
        // unless the scene names its own circle.
        let mut scene = (**scene).clone();
        if let (Some(a), Some(c)) = (scene.analysis.as_mut(), circle) {
            a.circle.get_or_insert(c);
        }
        let run = super::run_scene(&scene, &mut |_, _| {}).map_err(member_error)?;
        let s = &run.summary;
        let phase1 = s.phase1.as_ref();
        let mut m = CdemMember {
            elastic_max_abs_u: phase1.map_or(s.max_abs_u, |p| p.max_displacement),
            elastic_converged: run.elastic.converged,
            elastic_steps: run.elastic.steps,
            end_state: s.phase2.as_ref().map(|p| p.end_state),
            failed_tension: s.failed_springs.tension,
            failed_shear: s.failed_springs.shear,
            first_failure_step: None,
            first_failure_at: None,
            eq21_k: run.surface.as_ref().map(|r| r.springs.as_ref().unwrap_or(&r.stresses).k),
        };
        if let Some(f) = &run.failure {
            if let Some(first) = f.failed_at.iter().flatten().min().copied() {
                let (mut sum, mut n) = ([0.0; 3], 0.0);
                for (i, _) in f.failed_at.iter().enumerate().filter(|(_, s)| **s == Some(first)) {
                    let (a, b) = (run.model.springs.a[i] as usize, run.model.springs.b[i] as usize);
                    for c in 0..3 {
                        sum[c] += 0.5 * (run.model.x0[a][c] + run.model.x0[b][c]);
                    }
                    n += 1.0;
                }
                m.first_failure_step = Some(first);
                m.first_failure_at = Some(sum.map(|v| v / n));
            }
        }
        record.cdem = Some(m);
        cdem_run = Some(run);
    }
    if let (true, Some(scene)) = (input.analyses.contains(&Analysis::Srm), &scene) {
        let phase2 =
            cdem_run.as_ref().and_then(|run| Some(Phase2Run { failure: run.failure.as_ref()?, state: &run.state }));
        let (r, _) = match phase2 {
            Some(run) => super::srm::run_srm_after(scene, run, &mut |_| {}),
            None => super::run_srm(scene, &mut |_| {}),
        }
        .map_err(member_error)?;
        record.fs = r.fs;
        record.srm = Some(SrmMember { fs: r.fs, bracket: r.bracket, trials: r.trials.len() });
    }
    Ok(record)
}

/// Runs the members `range`, [`EnsembleInput::members_at_once`] at a time
/// (results in member order, independent of the thread count: each
/// member's run is, references/ensemble.md "Determinism"). `circle`: the
/// mean critical circle ([`mean_critical_circle`], computed once by the
/// caller, which also reports it). `progress(done)` after each batch.
pub fn run_members(
    input: &EnsembleInput,
    base: u64,
    range: std::ops::Range<usize>,
    circle: Option<lem::Circle>,
    progress: &mut dyn FnMut(usize),
) -> crate::Result<Vec<MemberRecord>> {
    run_members_journaled(input, base, range, circle, Vec::new(), progress, &mut |_| Ok(()))
}

/// [`run_members`] going on after the members `done` (the first of
/// `range`, in order: a journal read back), with `journal` called on each
/// batch's new records, in member order, before the next batch starts.
pub fn run_members_journaled(
    input: &EnsembleInput,
    base: u64,
    range: std::ops::Range<usize>,
    circle: Option<lem::Circle>,
    done: Vec<MemberRecord>,
    progress: &mut dyn FnMut(usize),
    journal: &mut dyn FnMut(&[MemberRecord]) -> crate::Result<()>,
) -> crate::Result<Vec<MemberRecord>> {
    let batch = input.members_at_once()?;
    let mut out = done;
    out.reserve(range.len().saturating_sub(out.len()));
    let ks: Vec<usize> = range.skip(out.len()).collect();
    progress(out.len());
    for chunk in ks.chunks(batch) {
        let records: Vec<crate::Result<MemberRecord>> =
            chunk.par_iter().with_max_len(1).map(|&k| run_member(input, base, k, circle)).collect();
        let start = out.len();
        for r in records {
            out.push(r?);
        }
        journal(&out[start..])?;
        progress(out.len());
    }
    Ok(out)
}

/// One bin of [`pf_by`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PfBin {
    /// The bin's centre (the drawn variable's unit).
    pub centre: f64,
    /// P(FS < 1) of its members.
    pub pf: f64,
    pub members: usize,
    /// The 95 % Wilson interval of `pf` (the one `ensemble.md` prints for
    /// the whole ensemble, [`crate::analysis::stats::wilson95`]).
    pub ci95: [f64; 2],
}

/// P(FS < 1) against a drawn variable: the members (those with an FS) in
/// `bins` equal bins of the value drawn for `key`, each bin with its
/// members and its 95 % interval; empty if no member drew `key`. For the
/// water level of an ensemble (`water.rise`), the probability of failure
/// against the level from one ensemble.
pub fn pf_by(records: &[MemberRecord], key: &str, bins: usize) -> Vec<PfBin> {
    let pairs: Vec<(f64, f64)> =
        records.iter().filter_map(|r| Some((r.draws.iter().find(|d| d.key == key)?.value, r.fs?))).collect();
    let (lo, hi) = pairs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
    if pairs.is_empty() || bins == 0 || !(hi > lo) {
        return Vec::new();
    }
    let width = (hi - lo) / bins as f64;
    let mut count = vec![(0usize, 0usize); bins];
    for (v, fs) in pairs {
        let k = (((v - lo) / width) as usize).min(bins - 1);
        count[k].0 += 1;
        count[k].1 += usize::from(fs < 1.0);
    }
    count
        .iter()
        .enumerate()
        .filter(|(_, c)| c.0 > 0)
        .map(|(k, &(n, failed))| PfBin {
            centre: lo + (k as f64 + 0.5) * width,
            pf: failed as f64 / n as f64,
            members: n,
            ci95: crate::analysis::stats::wilson95(failed, n),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Small models: twice the threads; large ones: no more than
    /// `ELEMENTS_AT_ONCE` elements together, and never fewer than one member.
    #[test]
    fn members_at_once_are_bounded_by_threads_and_elements() {
        assert_eq!(models_at_once(1000, 2), 4);
        assert_eq!(models_at_once(1000, 64), 100);
        assert_eq!(models_at_once(30_000, 8), 3);
        assert_eq!(models_at_once(60_000, 2), 1);
        assert_eq!(models_at_once(250_000, 2), 1);
        assert_eq!(models_at_once(0, 0), 2);
    }
}
