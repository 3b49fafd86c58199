//! The Wulong landslide (paper Figs. 11-14; verification/cases/wulong/,
//! references/wulong.md): both phases, and what tests/wulong.rs asserts and
//! `cdem reproduce` (step 7) reports, computed once ([`analyse`]): the loss
//! of cohesion by band, the failure sequence by height band (an insta
//! snapshot), where the cracks open first and whether they climb, the
//! detached blocks, the motion of the band at the end; rows `wulong/*`.

use std::collections::BTreeMap;

use crate::drivers::{run_watched, EndState, RunResult, Stage, StageSnapshots};
use crate::error::{Error, SceneError};
use crate::harness::registry as reg;
use crate::harness::report::Check;
use crate::harness::validation::{snapshot_row, WULONG_SNAPSHOT};
use crate::model::Model;
use crate::physics::spring::SpringStatus;
use crate::scene::Scene;
use crate::solver::{RunReport, State};

/// The toe and the slope height of wulong.geo (the lattice crest is at z = 85.3 m).
pub const Z_TOE: f64 = 20.0;
pub const HEIGHT: f64 = 65.0;
/// A failed joint face is an open crack when its mean normal opening passes this (m).
pub const OPEN: f64 = 2e-3;

/// Height bands of the slope, by a joint face's reference z.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Band {
    /// Below 20 % of the slope height (the lower cut, and the rock under the platform).
    Toe,
    /// 20-50 %: the upper cut and the foot of the natural slope.
    Lower,
    /// 50-80 %.
    Middle,
    /// Above 80 %: the upper slope, the crest and the dip slope behind it.
    Upper,
}

/// The bands from the toe up.
pub const BANDS: [Band; 4] = [Band::Toe, Band::Lower, Band::Middle, Band::Upper];

/// The band of a reference height z.
pub fn band(z: f64) -> Band {
    match (z - Z_TOE) / HEIGHT {
        h if h < 0.2 => Band::Toe,
        h if h < 0.5 => Band::Lower,
        h if h < 0.8 => Band::Middle,
        _ => Band::Upper,
    }
}

/// The bands' names, lower case, comma-separated.
pub fn names(bands: &[Band]) -> String {
    bands.iter().map(|b| format!("{b:?}").to_lowercase()).collect::<Vec<_>>().join(", ")
}

/// A joint face: the springs between two elements on a breakable interface.
pub struct Face {
    pub springs: Vec<usize>,
    pub elements: [usize; 2],
    /// Reference position of its front (y = 0) springs: (x, z).
    pub front: Vec<(f64, f64)>,
    pub z: f64,
    pub near_surface: bool,
}

/// The joint faces of the breakable interfaces.
pub fn joint_faces(model: &Model) -> Vec<Face> {
    let el = &model.elements;
    let mut element_of = vec![0; model.n_nodes()];
    for e in 0..el.len() {
        for &n in el.corners(e) {
            element_of[n as usize] = e;
        }
    }
    let sp = &model.springs;
    let near =
        model.interfaces.iter().position(|i| i.name == "nearsurface_joints").expect("group nearsurface_joints") as u16;
    let mut by_pair: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
    for s in (0..sp.len()).filter(|&s| model.interfaces[sp.interface[s] as usize].props.strength.is_some()) {
        let (a, b) = (element_of[sp.a[s] as usize], element_of[sp.b[s] as usize]);
        by_pair.entry((a.min(b), a.max(b))).or_default().push(s);
    }
    by_pair
        .into_iter()
        .map(|((a, b), springs)| {
            let z = springs.iter().map(|&s| model.x0[sp.a[s] as usize][2]).sum::<f64>() / springs.len() as f64;
            let front = springs
                .iter()
                .map(|&s| model.x0[sp.a[s] as usize])
                .filter(|x| x[1] < 1e-6)
                .map(|x| (x[0], x[2]))
                .collect();
            let near_surface = sp.interface[springs[0]] == near;
            Face { springs, elements: [a, b], front, z, near_surface }
        })
        .collect()
}

/// Mean normal opening of a face (m; positive = open).
pub fn opening(model: &Model, u: &[f64], face: &Face) -> f64 {
    let sp = &model.springs;
    face.springs
        .iter()
        .map(|&s| {
            let (a, b, n) = (sp.a[s] as usize, sp.b[s] as usize, sp.normal[s]);
            (0..3).map(|d| (u[3 * b + d] - u[3 * a + d]) * n[d]).sum::<f64>()
        })
        .sum::<f64>()
        / face.springs.len() as f64
}

/// Both phases, with the displacement kept at every stage.
pub struct ProgressiveResult {
    pub model: Model,
    pub elastic: RunReport,
    pub u_elastic: Vec<f64>,
    pub state: State,
    pub stages: Vec<Stage>,
    pub stage_u: Vec<Vec<f64>>,
    pub failed_at: Vec<Option<usize>>,
    pub end: EndState,
    pub phase2_steps: usize,
}

/// Both phases of `scene` (an error without `[failure]`).
pub fn run_progressive(scene: &Scene) -> Result<ProgressiveResult, Error> {
    let mut snapshots = StageSnapshots::default();
    let run = run_watched(scene, &mut snapshots)?;
    from_run(run, snapshots).ok_or_else(|| SceneError::invalid("failure", "the Wulong scene has no phase 2").into())
}

/// A run with phase 2 and its stage snapshots (None without phase 2).
pub fn from_run(run: RunResult, snapshots: StageSnapshots) -> Option<ProgressiveResult> {
    let f = run.failure?;
    Some(ProgressiveResult {
        model: run.model,
        elastic: run.elastic,
        u_elastic: f.u_elastic,
        state: run.state,
        stages: f.stages,
        stage_u: snapshots.u,
        failed_at: f.failed_at,
        end: f.end,
        phase2_steps: f.report.steps,
    })
}

/// Every spring of the face failed by `step`.
pub fn failed_by(r: &ProgressiveResult, face: &Face, step: usize) -> bool {
    face.springs.iter().all(|&s| r.failed_at[s].is_some_and(|at| at <= step))
}

/// Per stage: which faces are open cracks, which elements are detached blocks.
pub struct StageState {
    pub open: Vec<bool>,
    pub detached: Vec<bool>,
}

/// The open cracks and detached blocks at stage `k`.
pub fn stage_state(r: &ProgressiveResult, faces: &[Face], k: usize) -> StageState {
    let (step, u) = (r.stages[k].step, &r.stage_u[k]);
    let open: Vec<bool> = faces.iter().map(|f| failed_by(r, f, step) && opening(&r.model, u, f) > OPEN).collect();
    // (joint faces, failed, open) per element
    let mut count = vec![(0, 0, 0); r.model.elements.len()];
    for (f, face) in faces.iter().enumerate() {
        let failed = failed_by(r, face, step);
        for e in face.elements {
            count[e].0 += 1;
            count[e].1 += failed as usize;
            count[e].2 += open[f] as usize;
        }
    }
    let detached = count.iter().map(|&(n, failed, open)| n > 0 && failed == n && 2 * open >= n).collect();
    StageState { open, detached }
}

/// Mean reference z of an element's corners.
pub fn element_z(model: &Model, e: usize) -> f64 {
    let c = model.elements.corners(e);
    c.iter().map(|&i| model.x0[i as usize][2]).sum::<f64>() / c.len() as f64
}

/// Mean motion of an element's corners from `u0` to `u` (m).
pub fn element_motion(model: &Model, u: &[f64], u0: &[f64], e: usize) -> f64 {
    let c = model.elements.corners(e);
    c.iter()
        .map(|&i| (0..3).map(|d| (u[3 * i as usize + d] - u0[3 * i as usize + d]).powi(2)).sum::<f64>().sqrt())
        .sum::<f64>()
        / c.len() as f64
}

/// What the Wulong run shows.
pub struct Wulong {
    pub faces: Vec<Face>,
    /// Per stage.
    pub states: Vec<StageState>,
    /// Shares of failed joint faces at the end: near-surface, interior.
    pub near_failed: f64,
    pub interior_failed: f64,
    /// The snapshot's sequence: per ranked stage the bands where each kind of
    /// event first appears, then the end state.
    pub sequence: Vec<String>,
    /// (stage, step, events) of the sequence.
    pub events: Vec<(usize, usize, Vec<String>)>,
    /// The bands of the first open cracks, and the mean z of the cracks
    /// opening at the first crack stage and later.
    pub first_bands: Vec<Band>,
    pub z_first: Vec<f64>,
    pub z_later: Vec<f64>,
    /// Cracks open first below mid-height and the later ones lie higher.
    pub toe_first: bool,
    /// The run ended in a global slide.
    pub slid: bool,
    /// Detached elements at the end.
    pub detached: Vec<usize>,
    /// The element that moved most in phase 2 (m, element) and the largest outward bulge (-u_x).
    pub moved: (f64, usize),
    pub bulge: (f64, usize),
    /// Median, 90 % and largest motion of the near-surface blocks in the last quarter (m).
    pub late_motion: [f64; 3],
    /// Widest failed joint per band at the first stage and at the end (m).
    pub widest_first: [f64; 4],
    pub widest_end: [f64; 4],
    /// Open cracks per band at the end.
    pub open_by_band: [usize; 4],
    pub rows: Vec<Check>,
}

impl Wulong {
    /// The mean of `v` (0 if empty).
    pub fn mean(v: &[f64]) -> f64 {
        v.iter().sum::<f64>() / v.len().max(1) as f64
    }
}

/// Analyses a run of [`reg::WULONG`]; `seconds`: its wall time (the rows' time).
pub fn analyse(r: &ProgressiveResult, scene: &Scene, seconds: f64) -> Result<Wulong, Error> {
    let (model, sp) = (&r.model, &r.model.springs);
    let faces = joint_faces(model);
    let last = r.stages.len().checked_sub(1).ok_or_else(|| SceneError::invalid("failure", "no stage"))?;
    let end_step = r.stages[last].step;
    let share = |near: bool| {
        let set: Vec<&Face> = faces.iter().filter(|f| f.near_surface == near).collect();
        set.iter().filter(|f| failed_by(r, f, end_step)).count() as f64 / set.len().max(1) as f64
    };
    let (near_failed, interior_failed) = (share(true), share(false));

    // The sequence: per stage, the bands where each kind of event first appears.
    let mut first_shear = BTreeMap::new();
    let mut first_tension = BTreeMap::new();
    let mut first_open = BTreeMap::new();
    let mut first_detached = BTreeMap::new();
    let mut states = Vec::with_capacity(r.stages.len());
    for (k, stage) in r.stages.iter().enumerate() {
        for s in 0..sp.len() {
            if r.failed_at[s].is_some_and(|at| at <= stage.step) {
                let b = band(model.x0[sp.a[s] as usize][2]);
                let map = if r.state.springs.status[s] == SpringStatus::Tension {
                    &mut first_tension
                } else {
                    &mut first_shear
                };
                map.entry(b).or_insert(k);
            }
        }
        let st = stage_state(r, &faces, k);
        for face in faces.iter().zip(&st.open).filter(|(_, o)| **o).map(|(f, _)| f) {
            first_open.entry(band(face.z)).or_insert(k);
        }
        for e in (0..model.elements.len()).filter(|&e| st.detached[e]) {
            first_detached.entry(band(element_z(model, e))).or_insert(k);
        }
        states.push(st);
    }
    let mut by_stage_events: BTreeMap<usize, Vec<String>> = BTreeMap::new();
    for (what, map) in [
        ("shear failures", &first_shear),
        ("tension failures", &first_tension),
        ("cracks open", &first_open),
        ("blocks detach", &first_detached),
    ] {
        let mut by_stage: BTreeMap<usize, Vec<Band>> = BTreeMap::new();
        for (&b, &k) in map.iter() {
            by_stage.entry(k).or_default().push(b);
        }
        for (k, bands) in by_stage {
            by_stage_events.entry(k).or_default().push(format!("{what}: {}", names(&bands)));
        }
    }
    let events: Vec<(usize, usize, Vec<String>)> =
        by_stage_events.into_iter().map(|(k, what)| (k, r.stages[k].step, what)).collect();
    let mut sequence: Vec<String> =
        events.iter().enumerate().map(|(rank, (_, _, what))| format!("{}: {}", rank + 1, what.join("; "))).collect();
    let tension = if first_tension.is_empty() { "none" } else { "some" };
    sequence.push(format!("end: {:?}; tension failures: {tension}", r.end));
    let open_by_band =
        BANDS.map(|b| faces.iter().zip(&states[last].open).filter(|(f, o)| **o && band(f.z) == b).count());
    let widest = |k: usize| {
        BANDS.map(|b| {
            faces
                .iter()
                .filter(|f| band(f.z) == b && failed_by(r, f, r.stages[k].step))
                .map(|f| opening(model, &r.stage_u[k], f))
                .fold(0.0, f64::max)
        })
    };

    // Mean z of the cracks that open at the first crack stage and of those opening later.
    let first_crack_stage = first_open.values().min().copied();
    let (mut z_first, mut z_later) = (Vec::new(), Vec::new());
    for (f, face) in faces.iter().enumerate() {
        if let Some(k) = (0..states.len()).find(|&k| states[k].open[f]) {
            if Some(k) == first_crack_stage {
                z_first.push(face.z)
            } else {
                z_later.push(face.z)
            }
        }
    }
    // Cracks open first below mid-height, then climb: the ones opening later lie higher.
    let first_bands: Vec<Band> =
        first_open.iter().filter(|(_, k)| Some(**k) == first_crack_stage).map(|(b, _)| *b).collect();
    let toe_first = !first_bands.is_empty()
        && first_bands.iter().all(|b| *b <= Band::Lower)
        && !z_later.is_empty()
        && Wulong::mean(&z_later) > Wulong::mean(&z_first);
    let slid = r.end == EndState::GlobalSliding;

    // Blocks detach; the most moved block and the largest bulge.
    let u_end = &r.stage_u[last];
    let detached: Vec<usize> = (0..model.elements.len()).filter(|&e| states[last].detached[e]).collect();
    let moved = (0..model.elements.len())
        .map(|e| (element_motion(model, u_end, &r.u_elastic, e), e))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap_or((0.0, 0));
    let mean_x = |u: &[f64], e: usize| crate::output::figures::section::element_mean_displacement(model, u, e, 0);
    let bulge = (0..model.elements.len())
        .map(|e| (-(mean_x(u_end, e) - mean_x(&r.u_elastic, e)), e))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap_or((0.0, 0));
    // No slide: the band as a whole barely moves in the last quarter of the run.
    let u_q = &r.stage_u[3 * last / 4];
    let ns = scene
        .material
        .iter()
        .position(|m| m.group == "nearsurface")
        .ok_or_else(|| SceneError::invalid("material", "no volume group nearsurface"))?;
    let mut late: Vec<f64> = (0..model.elements.len())
        .filter(|&e| model.elements.material[e] as usize == ns)
        .map(|e| element_motion(model, u_end, u_q, e))
        .collect();
    late.sort_by(f64::total_cmp);
    let late_motion = if late.is_empty() {
        [f64::NAN; 3]
    } else {
        [late[late.len() / 2], late[9 * late.len() / 10], late[late.len() - 1]]
    };

    let (widest_first, widest_end) = (widest(0), widest(last));
    let rows = vec![
        snapshot_row("wulong/snapshot", &sequence, WULONG_SNAPSHOT, seconds),
        reg::row("wulong/toe-first").compared(
            &format!(
                "first cracks in {}, mean z {:.1} m; later ones mean z {:.1} m",
                names(&first_bands),
                Wulong::mean(&z_first),
                Wulong::mean(&z_later)
            ),
            "cracks at the lower slope first, then more cracks higher (stages 1-2)",
            toe_first,
            seconds,
        ),
        reg::row("wulong/no-slide").compared(
            &format!("{:?}", r.end),
            "no global slide: the slide needed the rain, which the model has not",
            !slid,
            seconds,
        ),
    ];
    Ok(Wulong {
        faces,
        states,
        near_failed,
        interior_failed,
        sequence,
        events,
        first_bands,
        z_first,
        z_later,
        toe_first,
        slid,
        detached,
        moved,
        bulge,
        late_motion,
        widest_first,
        widest_end,
        open_by_band,
        rows,
    })
}

/// The Wulong model after rain ([`reg::WULONG_WET`]): does it slide (some
/// node more than 1 m from its phase-1 position within the step budget) at
/// the water table's `rise` (m)?
pub fn slides_at(scene: &Scene, rise: f64) -> Result<(bool, f64), Error> {
    let mut s = scene.clone();
    s.output.vtk = false;
    let w = s.water.as_mut().ok_or_else(|| SceneError::invalid("water", "the wet Wulong case needs [water]"))?;
    w.rise = rise;
    let r = crate::drivers::run_scene(&s, &mut |_, _| {})?;
    let moved = r.summary.phase2.as_ref().map_or(0.0, |p| p.max_displacement);
    Ok((r.summary.end_state == EndState::GlobalSliding, moved))
}

/// The rise at which the wet Wulong model first slides, by bisection in
/// `[0, top]` to [`WET_LEVEL_RESOLUTION`], as strength reduction bisects on
/// F: `(the highest rise that stood, the lowest that slid, every (rise, slid,
/// displacement) tried)`. None at either end if the top does not slide or
/// the bottom does.
pub type WetLevel = (Option<f64>, Option<f64>, Vec<(f64, bool, f64)>);

/// The depth of wulong-wet.toml's water table below the ground at rise 0 (m):
/// its surface is the ground's vertices 20 m down.
pub const WET_TABLE_DEPTH: f64 = 20.0;

/// Resolution of the bisection on the water table's rise (m).
pub const WET_LEVEL_RESOLUTION: f64 = 1.0;

pub fn wet_level(scene: &Scene, top: f64) -> Result<WetLevel, Error> {
    let mut tried = Vec::new();
    let run = |rise: f64, tried: &mut Vec<(f64, bool, f64)>| -> Result<bool, Error> {
        let (slid, moved) = slides_at(scene, rise)?;
        tried.push((rise, slid, moved));
        Ok(slid)
    };
    if !run(top, &mut tried)? {
        return Ok((Some(top), None, tried));
    }
    if run(0.0, &mut tried)? {
        return Ok((None, Some(0.0), tried));
    }
    let (mut lo, mut hi) = (0.0, top);
    while hi - lo > WET_LEVEL_RESOLUTION {
        let mid = 0.5 * (lo + hi);
        if run(mid, &mut tried)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok((Some(lo), Some(hi), tried))
}

/// The rows of the wet Wulong case: it slides with the water table 1 m
/// below the ground (`wulong/wet-slides`), and the rise at which it first
/// slides (`wulong/wet-level`, reported: ours, the paper gives no level).
pub fn wet_rows() -> Result<(Vec<Check>, WetLevel), Error> {
    let t0 = std::time::Instant::now();
    let scene = reg::WULONG_WET.scene()?;
    let top = scene.water.as_ref().map_or(0.0, |w| w.rise);
    let level = wet_level(&scene, top)?;
    let seconds = t0.elapsed().as_secs_f64();
    let (lo, hi, tried) = (&level.0, &level.1, &level.2);
    let slid_at_top = tried.first().is_some_and(|t| t.1);
    let describe = |t: &[(f64, bool, f64)]| {
        t.iter()
            .map(|(r, s, m)| format!("rise {r:.2} m: {} ({m:.3} m)", if *s { "slides" } else { "stands" }))
            .collect::<Vec<_>>()
            .join("; ")
    };
    let slides = reg::row("wulong/wet-slides")
        .compared(
            &format!("{} at rise {top} m (table 1 m below the ground)", if slid_at_top { "slides" } else { "stands" }),
            "slides (the observed slide after rain)",
            slid_at_top,
            seconds,
        )
        .with_note(describe(tried));
    let found = matches!((lo, hi), (Some(_), Some(_)));
    let ours = match (lo, hi) {
        (Some(l), Some(h)) => format!(
            "stands at rise {l:.2} m, slides at {h:.2} m: the table {:.2}-{:.2} m below the ground",
            WET_TABLE_DEPTH - h,
            WET_TABLE_DEPTH - l
        ),
        _ => format!("no bracket: stands at {lo:?}, slides at {hi:?}"),
    };
    let level_row = reg::row("wulong/wet-level").compared(
        &ours,
        "slid after a day of rain; the paper gives no water level",
        found,
        seconds,
    );
    Ok((vec![slides, level_row], level))
}

/// The LEM's factor of safety of the wet Wulong scene against the water
/// table's rise: `(rise, Bishop, Spencer)` at each rise of `rises` (m),
/// from the scene's `[lem]` (the joints' strengths as the rock mass's) with
/// the raised surface; the critical circle searched again at each rise.
/// A rise whose LEM fails (the table above the ground) is an error.
pub fn lem_fs_by_rise(scene: &Scene, rises: &[f64]) -> Result<Vec<(f64, f64, f64)>, Error> {
    use crate::lem::Method;
    rises
        .iter()
        .map(|&rise| {
            let mut s = scene.clone();
            let w =
                s.water.as_mut().ok_or_else(|| SceneError::invalid("water", "the wet Wulong case needs [water]"))?;
            w.rise = rise;
            let r = crate::lem::analyse(&crate::drivers::lem::scene_lem_input(&s)?)?;
            let fs = |m| r.fs.get(m).copied().unwrap_or(f64::NAN);
            Ok((rise, fs(Method::Bishop), fs(Method::Spencer)))
        })
        .collect()
}

/// The rises of the FS-by-water figure: 0 to 19 m in steps of 1 m (at 20 m the
/// table would reach the ground at the crest).
pub fn figure_rises() -> Vec<f64> {
    (0..=19).map(f64::from).collect()
}
