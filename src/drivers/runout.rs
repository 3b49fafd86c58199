//! The runout of a scene (`[runout]`, docs/method.md 2.9d): after phase 2
//! ends in global sliding (or from rest, `start = "rest"`), the blocks in
//! real time until the moving mass comes to rest or the duration ends.
//! Orchestration only: the step is [`crate::solver::runout`], the files are
//! written by `output`.

use std::ops::ControlFlow;

use serde::Serialize;

use super::phase::Frame;
use crate::error::Error;
use crate::model::Model;
use crate::scene::{RunoutSection, RunoutStart};
use crate::solver::runout::{moving_volume, Runout, RunoutState, RunoutStep};
use crate::solver::State;
use crate::summary::{EndState, RunoutSummary};

/// One row of `runout.csv`.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct RunoutRow {
    pub step: usize,
    /// Time since the runout's start (s).
    pub time: f64,
    pub kinetic_energy: f64,
    pub max_speed: f64,
    /// Largest displacement of any node since the runout's start (m): the front's travel.
    pub front_travel: f64,
    /// Volume of the blocks moving faster than the rest velocity (m^3).
    pub moving_volume: f64,
    pub contacts: usize,
    pub sliding_contacts: usize,
    pub gravity_work: f64,
    pub water_work: f64,
    pub friction_work: f64,
    pub damping_work: f64,
}

/// What a runout produced.
#[derive(Debug, Clone)]
pub struct RunoutResult {
    pub summary: RunoutSummary,
    pub rows: Vec<RunoutRow>,
    /// Displacement frames (from the model's rest coordinates).
    pub frames: Vec<Frame>,
    /// The displacement at the start of the runout.
    pub u_start: Vec<f64>,
}

/// Whether element `e` moved from `u0` to `u1` by more than 1 % of the
/// runout distance `distance` at some corner: a block of the deposit.
pub fn moved(model: &Model, u0: &[f64], u1: &[f64], distance: f64, e: usize) -> bool {
    distance > 0.0
        && model.elements.corners(e).iter().any(|&n| {
            let n = 3 * n as usize;
            (0..3).map(|d| (u1[n + d] - u0[n + d]).powi(2)).sum::<f64>().sqrt() > 0.01 * distance
        })
}

/// The path of the centre of mass of the blocks `deposit` (the lumped masses
/// of their nodes) from `u0` to `u1`: its drop along gravity and its travel
/// across it (m). The work of gravity on them is `M |g| drop`; `drop /
/// travel` is the slope of their energy line (the sled model's `tan(phi)`,
/// references/runout.md).
pub fn centre_of_mass_path(model: &Model, u0: &[f64], u1: &[f64], deposit: &[usize]) -> (f64, f64) {
    let el = &model.elements;
    let mut counted = vec![false; model.n_nodes()];
    let (mut m, mut shift) = (0.0, [0.0; 3]);
    for &e in deposit {
        for &n in el.corners(e) {
            let n = n as usize;
            if !std::mem::replace(&mut counted[n], true) {
                m += model.mass[n];
                for d in 0..3 {
                    shift[d] += model.mass[n] * (u1[3 * n + d] - u0[3 * n + d]);
                }
            }
        }
    }
    let g = model.gravity;
    let g_len = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    if m == 0.0 || g_len == 0.0 {
        return (0.0, 0.0);
    }
    let shift = shift.map(|v| v / m);
    let drop = (0..3).map(|d| shift[d] * g[d] / g_len).sum::<f64>();
    let across = (0..3).map(|d| (shift[d] - drop * g[d] / g_len).powi(2)).sum::<f64>().sqrt();
    (drop, across)
}

/// The runout of `model` from `state` (the end of the last phase, which
/// ended in `end`), or why it does not run.
pub fn run(section: &RunoutSection, model: &Model, state: &State, end: EndState) -> Result<RunoutResult, Error> {
    if section.start == RunoutStart::Sliding && end != EndState::GlobalSliding {
        let reason = format!(
            "the slope did not slide (the last phase ended in {end:?}); [runout] start = \"sliding\" runs only after global sliding (start = \"rest\" runs from any end)"
        );
        let summary = RunoutSummary { reason: Some(reason), ..Default::default() };
        return Ok(RunoutResult { summary, rows: Vec::new(), frames: Vec::new(), u_start: state.u.clone() });
    }
    let params = section.params(model)?;
    // The Itasca codes' stiffness rule, when the scene asks for it: the
    // springs of a model built for the static phases may be far stiffer
    // than their blocks, and in real time they set the step.
    let (limited, springs_limited) = match params.stiffness_limit {
        Some(f) => {
            let (m, k) = model.with_spring_limit(f);
            (Some(m), k)
        }
        None => (None, 0),
    };
    let model = limited.as_ref().unwrap_or(model);
    let mut engine = Runout::new(model, params.clone(), &state.springs, &state.joints, &state.u)?;
    // The failure phase's velocities are fictitious (mass scaling): the
    // runout starts from rest.
    let v = vec![0.0; state.u.len()];
    let mut st = RunoutState::new(state.u.clone(), v, state.springs.clone(), state.joints.clone());
    let u_start = state.u.clone();
    let frame_every = section.frame_every.unwrap_or(section.duration / 20.0);
    let mut frames = vec![Frame { step: 0, time: 0.0, u: u_start.clone() }];
    let mut rows = Vec::new();
    let mut travel: f64 = 0.0;
    let travel_of = |u: &[f64]| {
        (0..u.len() / 3)
            .map(|i| (0..3).map(|d| (u[3 * i + d] - u_start[3 * i + d]).powi(2)).sum::<f64>().sqrt())
            .fold(0.0, f64::max)
    };
    let mut next_frame = frame_every;
    let mut watch = |r: &RunoutStep, st: &RunoutState| {
        if r.step.is_multiple_of(section.row_every) || r.time >= next_frame {
            travel = travel.max(travel_of(&st.u));
        }
        if r.step.is_multiple_of(section.row_every) {
            rows.push(RunoutRow {
                step: r.step,
                time: r.time,
                kinetic_energy: r.kinetic,
                max_speed: r.max_speed,
                front_travel: travel_of(&st.u),
                moving_volume: moving_volume(model, &st.v, params.rest_velocity),
                contacts: r.contacts,
                sliding_contacts: r.sliding,
                gravity_work: r.energy.gravity,
                water_work: r.energy.water,
                friction_work: r.energy.friction,
                damping_work: r.energy.damping,
            });
        }
        if r.time >= next_frame {
            frames.push(Frame { step: r.step, time: r.time, u: st.u.clone() });
            next_frame += frame_every;
        }
        ControlFlow::Continue(())
    };
    let end = engine.run(model, &mut st, &mut watch)?;
    frames.push(Frame { step: st.step, time: st.time, u: st.u.clone() });
    let runout_distance = travel.max(travel_of(&st.u));
    // The deposit: the blocks that moved more than 1 % of the runout distance.
    let el = &model.elements;
    let deposit: Vec<usize> = (0..el.len()).filter(|&e| moved(model, &u_start, &st.u, runout_distance, e)).collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let mut moved_volume = 0.0;
    for &e in &deposit {
        moved_volume += el.volume[e];
        for &n in el.corners(e) {
            for d in 0..3 {
                let x = model.x0[n as usize][d] + st.u[3 * n as usize + d];
                lo[d] = lo[d].min(x);
                hi[d] = hi[d].max(x);
            }
        }
    }
    let (mass_drop, mass_travel) = centre_of_mass_path(model, &u_start, &st.u, &deposit);
    let e = end.energy;
    // The runout starts from rest: the budget is measured against gravity's work.
    let scale = e.gravity.abs();
    let summary = RunoutSummary {
        ran: true,
        reason: None,
        steps: end.steps,
        time: end.time,
        dt: engine.dt(),
        springs_limited,
        time_to_rest: end.rest_at,
        peak_velocity: end.peak_speed,
        runout_distance,
        deposit_min: if moved_volume > 0.0 { lo } else { [0.0; 3] },
        deposit_max: if moved_volume > 0.0 { hi } else { [0.0; 3] },
        moved_volume,
        mass_drop,
        mass_travel,
        travel_angle: if mass_travel > 0.0 { mass_drop.atan2(mass_travel).to_degrees() } else { 0.0 },
        energy_gravity: e.gravity,
        energy_water: e.water,
        energy_kinetic: e.kinetic,
        energy_elastic: e.elastic,
        energy_friction: e.friction,
        energy_joints: e.joints,
        energy_damping: e.damping,
        energy_closure: if scale > 0.0 { e.residual().abs() / scale } else { 0.0 },
    };
    Ok(RunoutResult { summary, rows, frames, u_start })
}
