//! Runout verification (references/runout.md, tests/runout.rs): blocks in
//! real time with large displacement and contacts found anew.
//!
//! - 3DEC's sliding and toppling blocks (Itasca's verification, after Wyllie
//!   & Mah 2004): rho 2000 kg/m^3, g = 10 m/s^2, a 10 m long block on a plane
//!   dipping 40 degrees: (a) 5 m high, phi 20 degrees, slides with
//!   `a = g (sin 40 - cos 40 tan 20)`; (b) 10 m high, phi 40.1: at rest;
//!   (c) 25 m high, phi 40: topples (`w / h = 0.4 < tan 40`).
//! - A block launched at `v0` along a level plane with friction `mu` stops
//!   after `v0^2 / (2 mu g)`.
//! - A block dropped from `h` touches the plane at `sqrt(2 h / g)`; with no
//!   damping it rebounds to `h`; with local damping it comes to rest.
//! - A free block turned 90 degrees keeps no stress (objectivity).
//!
//! The plane is level and gravity is tilted by the dip. Each block starts
//! at rest on its base, from the bonded static state (phase 1), so that the
//! contacts that take over from the frictional springs start loaded.

use std::ops::ControlFlow;

use crate::error::Error;
use crate::harness::registry::{self as reg, Case};
use crate::harness::report::Check;
use crate::model::Model;
use crate::physics::corotation::{best_rotation, local_deformation, rotation_angle};
use crate::physics::element::element_stress;
use crate::solver::runout::{ContactDefaults, Energy, Runout, RunoutDamping, RunoutParams, RunoutState, RunoutStep};
use crate::solver::{Solver, State};

/// Gravity of the 3DEC verification (m/s^2).
pub const G: f64 = reg::RUNOUT_GRAVITY;

/// One block run: the block's motion against time, and what the run measured.
#[derive(Debug, Clone)]
pub struct BlockRun {
    /// `(t, mean x displacement of the block, mean z, the block's rotation (rad))`.
    pub track: Vec<(f64, f64, f64, f64)>,
    pub energy: Energy,
    /// `|residual| / max(|gravity work|, kinetic energy at the start)` at the end.
    pub closure: f64,
    pub dt: f64,
    pub steps: usize,
    /// Time of the first step with a contact carrying load (s).
    pub first_contact: Option<f64>,
    pub remaps: usize,
    /// Largest count of contacts at once.
    pub max_contacts: usize,
    /// Largest speed of a free node in the last 0.1 s (m/s).
    pub final_speed: f64,
    /// The block's largest stress in its own frame at the end, over E.
    pub stress_over_e: f64,
    pub seconds: f64,
    /// The final displacement, 3 per node (for determinism checks).
    pub u: Vec<f64>,
}

impl BlockRun {
    /// The track's value `f` at time `t` (linear between steps).
    fn at(&self, t: f64, f: impl Fn(&(f64, f64, f64, f64)) -> f64) -> f64 {
        let k = self.track.partition_point(|r| r.0 < t);
        match k {
            0 => self.track.first().map_or(0.0, &f),
            k if k >= self.track.len() => self.track.last().map_or(0.0, &f),
            k => {
                let (a, b) = (&self.track[k - 1], &self.track[k]);
                f(a) + (f(b) - f(a)) * (t - a.0) / (b.0 - a.0)
            }
        }
    }
    /// The mean x displacement at time `t`.
    pub fn x_at(&self, t: f64) -> f64 {
        self.at(t, |r| r.1)
    }
    /// The block's rotation at time `t` (rad).
    pub fn rotation_at(&self, t: f64) -> f64 {
        self.at(t, |r| r.3)
    }
    /// The largest rise of the mean z after the first contact, within
    /// `window` s of it: the rebound height (m).
    pub fn rebound(&self, window: f64) -> f64 {
        let Some(t0) = self.first_contact else { return 0.0 };
        let z0 = self.at(t0, |r| r.2);
        self.track.iter().filter(|r| r.0 > t0 && r.0 < t0 + window).map(|r| r.2 - z0).fold(0.0, f64::max)
    }
}

/// How a case starts and runs.
#[derive(Debug, Clone, Copy)]
pub struct Setup {
    pub dip_deg: f64,
    pub duration: f64,
    /// Initial velocity of the block (m/s).
    pub v0: [f64; 3],
    pub damping: RunoutDamping,
    /// Relax the bonded state first (blocks resting on their base).
    pub static_start: bool,
    /// Gravity on (off: the objectivity spin).
    pub gravity: bool,
    /// Spin of the block about y through its centroid (rad/s).
    pub spin: f64,
    /// The stiffness of contacts between blocks that never shared a face (Pa/m).
    pub contact_stiffness: f64,
    /// A level water table at this height (m), `gamma_w = rho_w g` with the
    /// case's g (references/runout.md): the block under water.
    pub water_level: Option<f64>,
}

impl Setup {
    pub fn new(dip_deg: f64, duration: f64) -> Self {
        Self {
            dip_deg,
            duration,
            v0: [0.0; 3],
            damping: RunoutDamping::None,
            static_start: true,
            gravity: true,
            spin: 0.0,
            contact_stiffness: reg::RUNOUT_CONTACT_STIFFNESS,
            water_level: None,
        }
    }
}

/// The runout settings of the verification cases: contacts take the
/// scene's joint stiffness, the tolerance is 2 cm, a half of the stable step.
pub fn params(setup: &Setup, friction_deg: f64) -> RunoutParams {
    RunoutParams {
        duration: setup.duration,
        damping: setup.damping,
        safety: 0.5,
        tolerance: 0.02,
        max_penetration: 0.2,
        rest_velocity: 1e-3,
        rest_time: 0.0,
        contact: ContactDefaults {
            normal_stiffness: setup.contact_stiffness,
            shear_stiffness: setup.contact_stiffness,
            friction_deg,
        },
        stiffness_limit: None,
    }
}

/// The model of a case with gravity tilted by the dip, and its block's elements.
pub fn model(case: &Case, setup: &Setup) -> Result<(Model, Vec<usize>), Error> {
    let mut scene = case.scene()?;
    let th = setup.dip_deg.to_radians();
    scene.loads.gravity = match setup.gravity {
        true => [G * th.sin(), 0.0, -G * th.cos()],
        false => [0.0; 3],
    };
    if let Some(z) = setup.water_level {
        scene.water = Some(crate::model::spec::WaterSection {
            surface: vec![[-1e3, z], [1e3, z]],
            unit_weight: reg::RUNOUT_WATER_DENSITY * G,
            ..Default::default()
        });
    }
    let block_material = scene.material.iter().position(|m| m.group == "block").unwrap_or(1);
    let model = crate::drivers::build_model(&scene)?;
    let block = (0..model.elements.len()).filter(|&e| model.elements.material[e] as usize == block_material).collect();
    Ok((model, block))
}

/// Runs one case.
pub fn run(case: &Case, setup: &Setup, friction_deg: f64) -> Result<BlockRun, Error> {
    let t0 = std::time::Instant::now();
    let (model, block) = model(case, setup)?;
    let el = &model.elements;
    let mut block_nodes: Vec<usize> = block.iter().flat_map(|&e| el.corners(e).iter().map(|&c| c as usize)).collect();
    block_nodes.sort_unstable();
    block_nodes.dedup();
    let state = static_start(&model, setup.static_start)?;
    let x0: Vec<[f64; 3]> = block_nodes.iter().map(|&i| model.x0[i]).collect();
    let centroid = [0, 1, 2].map(|d| x0.iter().map(|p| p[d]).sum::<f64>() / x0.len() as f64);
    let mut v = vec![0.0; state.u.len()];
    for &i in &block_nodes {
        let r = [0, 1, 2].map(|d| model.x0[i][d] - centroid[d]);
        // omega about +y: v = omega x r = (omega r_z, 0, -omega r_x).
        let spin = [setup.spin * r[2], 0.0, -setup.spin * r[0]];
        for d in 0..3 {
            v[3 * i + d] = setup.v0[d] + spin[d];
        }
    }
    let kinetic0: f64 = (0..v.len()).map(|k| 0.5 * model.mass[k / 3] * v[k] * v[k]).sum();
    let u_start = state.u.clone();
    let mut engine = Runout::new(&model, params(setup, friction_deg), &state.springs, &state.joints, &state.u)?;
    let mut rs = RunoutState::new(state.u, v, state.springs, state.joints);
    let mean = |u: &[f64], d: usize| {
        block_nodes.iter().map(|&i| u[3 * i + d] - u_start[3 * i + d]).sum::<f64>() / block_nodes.len() as f64
    };
    let rotation = |u: &[f64]| {
        let x: Vec<[f64; 3]> = block_nodes.iter().map(|&i| [0, 1, 2].map(|d| model.x0[i][d] + u[3 * i + d])).collect();
        rotation_angle(&best_rotation(&x0, &x))
    };
    let mut track = vec![(0.0, 0.0, 0.0, 0.0)];
    let (mut first_contact, mut max_contacts, mut final_speed) = (None, 0, 0.0f64);
    let duration = setup.duration;
    let mut watch = |r: &RunoutStep, st: &RunoutState| {
        track.push((r.time, mean(&st.u, 0), mean(&st.u, 2), rotation(&st.u)));
        if r.contacts > 0 && first_contact.is_none() {
            first_contact = Some(r.time);
        }
        max_contacts = max_contacts.max(r.contacts);
        if r.time > duration - 0.1 {
            final_speed = final_speed.max(r.max_speed);
        }
        ControlFlow::Continue(())
    };
    let end = engine.run(&model, &mut rs, &mut watch)?;
    let scale = end.energy.gravity.abs().max(kinetic0);
    let closure = if scale > 0.0 { end.energy.residual().abs() / scale } else { 0.0 };
    let lame = model.materials[el.material[block[0]] as usize].lame;
    let young = lame.mu * (3.0 * lame.lambda + 2.0 * lame.mu) / (lame.lambda + lame.mu);
    let stress_over_e = block_stress(&model, &block, &rs.u, engine.rotations()) / young;
    Ok(BlockRun {
        track,
        energy: end.energy,
        closure,
        dt: engine.dt(),
        steps: end.steps,
        first_contact,
        remaps: engine.remaps,
        max_contacts,
        final_speed,
        stress_over_e,
        seconds: t0.elapsed().as_secs_f64(),
        u: rs.u,
    })
}

/// The state a block case starts from. The joints' own law (no tension,
/// Coulomb friction), relaxed quasi-statically: the block at rest as far as
/// its friction holds it, an upslope edge lifting where the weight's line
/// falls near the downslope edge. Where no such rest exists (the relaxation
/// does not converge: the block slides), the block is held instead (no
/// tension, no slip), and where that finds no rest either (the block
/// topples: its weight's line falls outside its base) it is held bonded
/// (the joints elastic); a held block is released at the runout's first
/// step, as a block placed on the plane and let go.
pub fn static_start(model: &Model, on: bool) -> Result<State, Error> {
    let mut state = State::new(model);
    if !on || model.springs.is_empty() {
        return Ok(state);
    }
    let relax = |state: &mut State, failure: bool| -> Result<bool, Error> {
        let params = crate::solver::SolverParams { tolerance: 1e-9, max_steps: Some(100_000), ..Default::default() };
        let mut solver = Solver::new(model, params)?;
        solver.set_failure(model, failure);
        Ok(solver.relax(model, state, 0)?.converged)
    };
    if relax(&mut state, true)? {
        return Ok(state);
    }
    let mut held = State::new(model);
    let given = held.joints.clone();
    for s in held.joints.strength.iter_mut().flatten().filter_map(|s| s.coulomb_mut()) {
        s.tan_phi = s.tan_phi.max(10.0);
    }
    if !relax(&mut held, true)? {
        held = State::new(model);
        relax(&mut held, false)?;
    }
    held.joints = given;
    Ok(held)
}

/// The largest stress of the block's elements in their own frame (Pa).
pub fn block_stress(model: &Model, block: &[usize], u: &[f64], rotations: &[crate::physics::corotation::Mat3]) -> f64 {
    let el = &model.elements;
    let mut worst: f64 = 0.0;
    for &e in block {
        let corners = el.corners(e);
        let x0: Vec<[f64; 3]> = corners.iter().map(|&c| model.x0[c as usize]).collect();
        let x: Vec<[f64; 3]> =
            corners.iter().map(|&c| [0, 1, 2].map(|d| model.x0[c as usize][d] + u[3 * c as usize + d])).collect();
        let mut local = vec![0.0; 3 * corners.len()];
        local_deformation(&rotations[e], &x0, &x, &mut local);
        let idx: Vec<u32> = (0..corners.len() as u32).collect();
        let r = el.offset[e]..el.offset[e + 1];
        let s = element_stress(&el.grad[r], &idx, &local, model.materials[el.material[e] as usize].lame);
        worst = worst.max(s.iter().fold(0.0, |a: f64, v| a.max(v.abs())));
    }
    worst
}

/// Rows `runout/3dec-sliding-1s`, `-2s` and its energy: 3DEC's sliding block.
pub fn sliding_rows() -> Result<(BlockRun, Vec<Check>), Error> {
    let r = run(&reg::RUNOUT_SLIDING, &Setup::new(reg::RUNOUT_DIP_DEG, 2.0), reg::RUNOUT_SLIDING_PHI_DEG)?;
    let a = reg::block_acceleration(reg::RUNOUT_DIP_DEG, reg::RUNOUT_SLIDING_PHI_DEG, G);
    let note =
        format!("{} steps of {:.2e} s, {} broad phases, up to {} contacts", r.steps, r.dt, r.remaps, r.max_contacts);
    let rows = vec![
        reg::row("runout/3dec-sliding-1s").value(r.x_at(1.0), 0.5 * a, r.seconds).with_note(note.clone()),
        reg::row("runout/3dec-sliding-2s").value(r.x_at(2.0), 2.0 * a, r.seconds).with_note(note),
        energy_row("runout/energy-3dec-sliding", &r),
    ];
    Ok((r, rows))
}

/// Row `runout/3dec-at-rest`: 3DEC's 10 m block at phi 40.1 on 40 degrees.
pub fn at_rest_row() -> Result<(BlockRun, Check), Error> {
    let r = run(&reg::RUNOUT_AT_REST, &Setup::new(reg::RUNOUT_DIP_DEG, 1.0), reg::RUNOUT_AT_REST_PHI_DEG)?;
    let travel = r.x_at(1.0);
    Ok((r.clone(), reg::row("runout/3dec-at-rest").value(travel, 0.0, r.seconds)))
}

/// Rows `runout/3dec-toppling`, `-angle` and its energy: the 25 m block.
pub fn toppling_rows() -> Result<(BlockRun, Vec<Check>), Error> {
    let r = run(&reg::RUNOUT_TOPPLING, &Setup::new(reg::RUNOUT_DIP_DEG, 3.0), reg::RUNOUT_TOPPLING_PHI_DEG)?;
    let past = r.track.iter().find(|q| q.3 > 30f64.to_radians()).map(|q| q.0);
    let ours = match past {
        Some(t) => format!("rotation past 30 deg at {t:.2} s, {:.1} deg at 3 s", r.rotation_at(3.0).to_degrees()),
        None => format!("rotation {:.1} deg at 3 s", r.rotation_at(3.0).to_degrees()),
    };
    let at2 = r.rotation_at(2.0).to_degrees();
    let rows = vec![
        reg::row("runout/3dec-toppling").compared(&ours, "topples (w / h = 0.4 < tan 40)", past.is_some(), r.seconds),
        reg::row("runout/3dec-toppling-angle").value(at2, 0.0, r.seconds).with_note("no published angle: reported"),
        energy_row("runout/energy-3dec-toppling", &r),
    ];
    Ok((r, rows))
}

/// Rows `runout/launched-stop` and its energy: 7 m/s along a level plane.
pub fn launched_rows() -> Result<(BlockRun, Vec<Check>), Error> {
    let v0 = reg::RUNOUT_LAUNCH_SPEED;
    let phi = reg::RUNOUT_LAUNCH_PHI_DEG;
    launch(None, reg::launch_distance(v0, phi, G), "runout/launched-stop", "runout/energy-launched")
}

/// Rows `runout/launched-submerged-stop` and its energy: the launched block
/// under water, its pore water following it (buoyancy: Archimedes).
pub fn submerged_rows() -> Result<(BlockRun, Vec<Check>), Error> {
    let v0 = reg::RUNOUT_LAUNCH_SPEED;
    let phi = reg::RUNOUT_LAUNCH_PHI_DEG;
    let stop = reg::submerged_launch_distance(v0, phi, G);
    launch(Some(reg::RUNOUT_WATER_LEVEL), stop, "runout/launched-submerged-stop", "runout/energy-launched-submerged")
}

/// The launched block (under a water table at `water_level`, if any), run
/// for its stopping time (from the reference distance `stop`: uniform
/// deceleration, `2 stop / v0`) and 0.4 s more; its travel and budget rows.
fn launch(
    water_level: Option<f64>,
    stop: f64,
    stop_id: &str,
    energy_id: &str,
) -> Result<(BlockRun, Vec<Check>), Error> {
    let v0 = reg::RUNOUT_LAUNCH_SPEED;
    let setup = Setup { v0: [v0, 0.0, 0.0], water_level, ..Setup::new(0.0, 2.0 * stop / v0 + 0.4) };
    let r = run(&reg::RUNOUT_LAUNCHED, &setup, reg::RUNOUT_LAUNCH_PHI_DEG)?;
    let d = r.x_at(setup.duration);
    let rows = vec![reg::row(stop_id).value(d, stop, r.seconds), energy_row(energy_id, &r)];
    Ok((r, rows))
}

/// Rows `runout/dropped-*` and its energy: a block dropped 1 m, undamped and
/// with local damping.
pub fn dropped_rows() -> Result<(BlockRun, BlockRun, Vec<Check>), Error> {
    let h = reg::RUNOUT_DROP_HEIGHT;
    // A soft contact (its period 11 times the block's own): the impact is
    // quasi-static and the block's vibration keeps little of its energy.
    let free = Setup { static_start: false, ..Setup::new(0.0, 1.2) };
    let soft = Setup { contact_stiffness: reg::RUNOUT_SOFT_CONTACT_STIFFNESS, ..free };
    let r = run(&reg::RUNOUT_DROPPED, &soft, 30.0)?;
    let t_ref = (2.0 * h / G).sqrt();
    let t = r.first_contact.unwrap_or(f64::NAN);
    let damped = Setup { damping: RunoutDamping::Local { alpha: 0.8 }, ..Setup { duration: 3.0, ..free } };
    let d = run(&reg::RUNOUT_DROPPED, &damped, 30.0)?;
    let rest = d.final_speed < 1e-3;
    let rows = vec![
        reg::row("runout/dropped-contact-time").value(t, t_ref, r.seconds).with_note(format!(
            "time step {:.2e} s: {:+.2} steps from sqrt(2 h / g)",
            r.dt,
            (t - t_ref) / r.dt
        )),
        reg::row("runout/dropped-rebound").value(r.rebound(0.9), h, r.seconds),
        reg::row("runout/dropped-rest").compared(
            &format!("largest speed in the last 0.1 s: {:.2e} m/s", d.final_speed),
            "at rest (below 1e-3 m/s)",
            rest,
            d.seconds,
        ),
        energy_row("runout/energy-dropped", &d),
    ];
    Ok((r, d, rows))
}

/// Row `runout/objectivity`: a free block spun a quarter turn, no load.
pub fn objectivity_row() -> Result<(BlockRun, Check), Error> {
    let spin = 0.5;
    let setup =
        Setup { static_start: false, gravity: false, spin, ..Setup::new(0.0, std::f64::consts::FRAC_PI_2 / spin) };
    let r = run(&reg::RUNOUT_DROPPED, &setup, 30.0)?;
    let note = format!(
        "turned {:.2} deg; the centripetal stress rho omega^2 r^2 ~ {:.1e} E is the physical part",
        r.rotation_at(setup.duration).to_degrees(),
        2000.0 * spin * spin * 2.0 / 1e10
    );
    Ok((r.clone(), reg::row("runout/objectivity").value(r.stress_over_e, 0.0, r.seconds).with_note(note)))
}

/// What the paper slope's runout gave: the summary of `cdem run` of
/// slope-slip-runout.toml.
#[derive(Debug, Clone)]
pub struct SlopeRun {
    pub summary: crate::summary::RunoutSummary,
    pub seconds: f64,
}

/// Rows `runout/slope-slip-*` and its energy: the paper's slip-surface slope
/// run through `cdem run`'s own path (phases 1 and 2, then the runout).
pub fn slope_rows() -> Result<(SlopeRun, Vec<Check>), Error> {
    let t0 = std::time::Instant::now();
    let scene = reg::RUNOUT_SLOPE.scene()?;
    let result = crate::drivers::run::run_scene(&scene, &mut |_, _| {})?;
    let summary = result.runout.map(|r| r.summary).ok_or_else(|| {
        Error::io("slope-slip-runout.toml", std::io::Error::other("the scene has no [runout]".to_string()))
    })?;
    let seconds = t0.elapsed().as_secs_f64();
    let s = &summary;
    let on_bench = s.ran && s.moved_volume > 0.0 && s.deposit_min[2] >= reg::RUNOUT_TOE_BENCH_Z - 0.5;
    let rest = s.time_to_rest.filter(|_| on_bench);
    let ours = match s.time_to_rest {
        Some(t) => format!(
            "at rest after {t:.1} s; deposit x {:.1} to {:.1} m, z {:.1} to {:.1} m; {:.0} m^3 moved, largest travel {:.2} m",
            s.deposit_min[0], s.deposit_max[0], s.deposit_min[2], s.deposit_max[2], s.moved_volume, s.runout_distance
        ),
        None => format!("still moving after {:.1} s (largest travel {:.2} m)", s.time, s.runout_distance),
    };
    let sled = reg::sled_travel_angle(reg::RUNOUT_SLOPE_PHI_DEG);
    let angle_text = format!(
        "{:.2} deg: the centre of mass {:.2} m down over {:.2} m (drop / travel {:.4} against tan(phi) {:.4}, {:+.1} %)",
        s.travel_angle,
        s.mass_drop,
        s.mass_travel,
        s.mass_drop / s.mass_travel,
        sled.to_radians().tan(),
        100.0 * (s.mass_drop / s.mass_travel / sled.to_radians().tan() - 1.0)
    );
    let note = format!("{} steps of {:.2e} s, {} springs limited", s.steps, s.dt, s.springs_limited);
    let rows = vec![
        reg::row("runout/slope-slip-rest")
            .compared(&ours, "at rest on the toe bench (z = 20 m)", rest.is_some(), seconds)
            .with_note(note.clone()),
        reg::row("runout/slope-slip-travel-angle")
            .compared(
                &angle_text,
                &format!("at least {sled:.0} deg (the sled model's energy line, tan(phi))"),
                s.ran && s.travel_angle >= sled,
                seconds,
            )
            .with_note("curvature, rotation and deformation only add friction work: the sled is the far bound"),
        reg::row("runout/energy-slope-slip").value(s.energy_closure, 0.0, seconds).with_note(format!(
            "gravity {:.4e} J = kinetic {:.4e} + elastic {:.4e} + friction {:.4e} + joints {:.4e} + damping {:.4e}",
            s.energy_gravity, s.energy_kinetic, s.energy_elastic, s.energy_friction, s.energy_joints, s.energy_damping
        )),
    ];
    Ok((SlopeRun { summary, seconds }, rows))
}

/// Row `runout/determinism`: the sliding block on 1 and on 2 threads.
pub fn determinism_row() -> Result<Check, Error> {
    let setup = Setup::new(reg::RUNOUT_DIP_DEG, 0.5);
    same_on_one_and_two_threads("runout/determinism", &reg::RUNOUT_SLIDING, &setup, reg::RUNOUT_SLIDING_PHI_DEG)
}

/// Row `runout/determinism-water`: the launched block under the water table
/// (its water forces follow it) for 0.5 s on one and on two threads.
pub fn determinism_water_row() -> Result<Check, Error> {
    let v0 = reg::RUNOUT_LAUNCH_SPEED;
    let setup = Setup { v0: [v0, 0.0, 0.0], water_level: Some(reg::RUNOUT_WATER_LEVEL), ..Setup::new(0.0, 0.5) };
    same_on_one_and_two_threads("runout/determinism-water", &reg::RUNOUT_LAUNCHED, &setup, reg::RUNOUT_LAUNCH_PHI_DEG)
}

/// Row `id`: `case` under `setup` run on one thread and on two, its
/// displacement compared bit for bit.
fn same_on_one_and_two_threads(id: &str, case: &Case, setup: &Setup, phi: f64) -> Result<Check, Error> {
    let t0 = std::time::Instant::now();
    let go = |threads: usize| -> Result<Vec<f64>, Error> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| Error::io("rayon thread pool", std::io::Error::other(e.to_string())))?;
        pool.install(|| run(case, setup, phi)).map(|r| r.u)
    };
    let (one, two) = (go(1)?, go(2)?);
    let same = one.len() == two.len() && one.iter().zip(&two).all(|(a, b)| a.to_bits() == b.to_bits());
    let ours = if same { "identical" } else { "differ" };
    Ok(reg::row(id).compared(ours, "identical", same, t0.elapsed().as_secs_f64()))
}

fn energy_row(id: &str, r: &BlockRun) -> Check {
    reg::row(id).value(r.closure, 0.0, r.seconds).with_note(format!(
        "gravity {:.4e} J + water {:.4e} = kinetic {:.4e} + elastic {:.4e} + friction {:.4e} + joints {:.4e} + damping {:.4e} (residual {:.3e} J)",
        r.energy.gravity,
        r.energy.water,
        r.energy.kinetic,
        r.energy.elastic,
        r.energy.friction,
        r.energy.joints,
        r.energy.damping,
        r.energy.residual()
    ))
}

/// Every runout row, in the registry's order.
pub fn rows() -> Result<Vec<Check>, Error> {
    let mut out = sliding_rows()?.1;
    out.push(at_rest_row()?.1);
    out.extend(toppling_rows()?.1);
    out.extend(launched_rows()?.1);
    out.extend(submerged_rows()?.1);
    out.extend(dropped_rows()?.2);
    out.push(objectivity_row()?.1);
    out.extend(slope_rows()?.1);
    out.push(determinism_row()?);
    out.push(determinism_water_row()?);
    Ok(out)
}
