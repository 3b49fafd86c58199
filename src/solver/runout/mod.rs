//! Runout: the blocks in real time after the slope has failed (docs/method.md
//! 2.13), the paper's own future work (its section 6). Large displacement,
//! contacts found anew as blocks move, and an energy budget that must close.
//!
//! One step is a short list of named stages:
//! 1. **blocks**: each element's corotational force and rotation
//!    ([`corotated_force_from`], from its rotation at the last step), its strain energy;
//! 2. **joints**: the springs that still bond two parts of one intact body,
//!    by the joint law with the normal turned by the block's rotation;
//! 3. **contacts**: re-detect where a node has moved more than half the
//!    tolerance ([`contact`]'s broad phase); the narrow phase (where each
//!    candidate vertex touches its block, with the interpenetration check;
//!    a vertex clear of a body by more than it has moved is not looked at);
//!    then every vertex-face contact's penalty and Coulomb force
//!    ([`contact_force`]);
//! 4. **update**: damping (none, local or mass-proportional Rayleigh) and
//!    central differences with the physical masses (no mass scaling);
//! 5. **monitor**: the energy terms, non-finite state, the moving mass.
//!
//! Bodies: the elements joined by shared nodes or by bonded springs (intact,
//! with a strength above zero) form one intact body, found by union-find.
//! Contacts act only between different bodies. A spring between two bodies
//! (it has failed, or its joint is purely frictional: no tension, no
//! cohesion) hands over to the contact model, which carries its interface's
//! stiffness and friction; a pair of blocks that never shared a face takes
//! the `[runout]` contact's.

pub mod contact;

use std::collections::BTreeMap;

use rayon::prelude::*;

use crate::error::SolveError;
use crate::model::union_find::UnionFind;
use crate::model::Model;
use crate::physics::contact::{contact_force, ContactHistory, ContactLaw};
use crate::physics::corotation::{corotated_force_from, rotate, Mat3, IDENTITY};
use crate::physics::joint::JointState;
use crate::physics::spring::{Spring, SpringState, SpringStatus};
use contact::{block_box, sweep, vertex_face, Faces};

/// Above this many blocks the broad phase uses the uniform grid instead of
/// sort and sweep (measured, benches/broad_phase.rs: on a deposit 4 blocks
/// deep, sweep 2.1e-4 / 4.6e-3 / 1.16e-1 s and grid 8.0e-4 / 8.2e-3 /
/// 1.0e-1 s at 1e3 / 1e4 / 1e5 blocks: exponents 1.38 and 1.06).
const GRID_ABOVE: usize = 50_000;

/// Damping in runout: a physical choice, stated in the scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RunoutDamping {
    /// None: the only dissipation is friction and joint failure.
    None,
    /// Cundall's local damping, `f_d = alpha |f_unbal| sign(v)` per component.
    Local { alpha: f64 },
    /// Mass-proportional Rayleigh damping `f_d = 2 xi omega m v`: the ratio
    /// `xi` of critical at the angular frequency `omega` (rad/s).
    Rayleigh { ratio: f64, omega: f64 },
}

/// Stiffness and friction of the contacts between blocks that never shared
/// a face (per unit area: Pa/m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactDefaults {
    pub normal_stiffness: f64,
    pub shear_stiffness: f64,
    pub friction_deg: f64,
}

/// The settings of a runout.
#[derive(Debug, Clone, PartialEq)]
pub struct RunoutParams {
    /// Time to run at most (s).
    pub duration: f64,
    pub damping: RunoutDamping,
    /// Fraction of the stable time step (Gershgorin bound).
    pub safety: f64,
    /// Detection reach (m): vertices within it of a face are contacts-to-be;
    /// the broad phase runs again once a node has moved half of it.
    pub tolerance: f64,
    /// A vertex deeper than this inside another block is a missed contact (m).
    pub max_penetration: f64,
    /// The mass is at rest when no node's mean speed (m/s) over a window ...
    pub rest_velocity: f64,
    /// ... of this length (s) is above `rest_velocity`. Zero: run the whole duration.
    pub rest_time: f64,
    pub contact: ContactDefaults,
    /// Limit of every contact's stiffness: this many times the softer
    /// block's [`Model::zone_stiffness`] (within the Itasca codes' rule, at
    /// most 10 times the stiffer's); the
    /// driver limits the springs the same way ([`Model::with_spring_limit`]).
    pub stiffness_limit: Option<f64>,
}

/// The energy terms of a runout since its start (J). The budget:
/// `gravity + water = kinetic + elastic + friction + joints + damping`, each term
/// computed on its own (none as the remainder).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct Energy {
    /// Work of the external loads but the water, `f_ext . (u - u_0)`.
    pub gravity: f64,
    /// Work of the pore water's forces, which follow the blocks (their
    /// pressure where each node is now, their area turned with its block):
    /// not a potential, so summed step by step (trapezoid). 0 without water.
    pub water: f64,
    /// `sum m v^2 / 2` at the step (central-difference velocity), less the start's.
    pub kinetic: f64,
    /// Strain energy of the blocks, the bonded springs and the contacts, less the start's.
    pub elastic: f64,
    /// Slip work of the contacts.
    pub friction: f64,
    /// Work the bonded springs took and did not store (slip, failure).
    pub joints: f64,
    /// Work of the damping forces.
    pub damping: f64,
}

impl Energy {
    /// `gravity + water - (kinetic + elastic + friction + joints + damping)`.
    pub fn residual(&self) -> f64 {
        self.gravity + self.water - (self.kinetic + self.elastic + self.friction + self.joints + self.damping)
    }
    /// `|residual| / |gravity|` (0 if no work was done).
    pub fn closure(&self) -> f64 {
        if self.gravity.abs() > 0.0 {
            self.residual().abs() / self.gravity.abs()
        } else {
            0.0
        }
    }
}

/// What changes in a runout.
#[derive(Debug, Clone)]
pub struct RunoutState {
    /// Displacement from the model's rest coordinates (m), `3 i + d`.
    pub u: Vec<f64>,
    /// Velocity at the last half step (m/s).
    pub v: Vec<f64>,
    pub springs: SpringState,
    pub joints: JointState,
    pub step: usize,
    pub time: f64,
}

/// One step's measures.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct RunoutStep {
    pub step: usize,
    pub time: f64,
    /// Kinetic energy at the step (J).
    pub kinetic: f64,
    /// Largest speed of a free node (m/s).
    pub max_speed: f64,
    pub contacts: usize,
    pub sliding: usize,
    /// Whether the broad phase ran this step.
    pub remapped: bool,
    /// The energy terms up to this step.
    pub energy: Energy,
}

/// A contact-to-be of the last mapping: a vertex (node) against one block's
/// near triangles.
#[derive(Debug, Clone)]
struct Candidate {
    node: u32,
    /// The block the vertex belongs to (for the law).
    vertex_elem: u32,
    face_elem: u32,
    tris: std::ops::Range<usize>,
}

/// Pore water in a runout (docs/method.md 2.13): the joint water of the
/// static phases ([`crate::model::water`]), whose forces `-u a` at each node
/// copy are fixed there, made to follow the blocks: `u` is the phreatic
/// surface's pressure where the node is now and its vector area `a` turns
/// with the node's block. At the start it is the static phases' force; a
/// block that leaves the water table loses it, one that goes under gains it.
struct RunoutWater {
    surface: crate::physics::water::Phreatic,
    area: Vec<[f64; 3]>,
    /// The external forces less the static water forces: gravity and loads.
    f_dry: Vec<f64>,
    /// The water's force at the last step (N, `3 i + d`), empty before the
    /// first, and the buffer the next step's is built in.
    force: Vec<f64>,
    next: Vec<f64>,
}

impl RunoutWater {
    fn new(model: &Model) -> Option<Self> {
        let w = model.water.as_ref()?;
        let surface = w.surface.clone()?;
        let mut f_dry = model.f_ext.clone();
        for (i, a) in w.node_area.iter().enumerate() {
            let u = surface.pressure(model.x0[i][0], model.x0[i][2]);
            for d in 0..3 {
                f_dry[3 * i + d] += u * a[d];
            }
        }
        Some(Self { surface, area: w.node_area.clone(), f_dry, force: Vec::new(), next: Vec::new() })
    }

    /// The water's force at positions `x`, each node's area turned by
    /// `rotation(i)`; returns its work since the last call (trapezoid).
    fn update(&mut self, x: &[[f64; 3]], x_prev: &[[f64; 3]], rotation: impl Fn(usize) -> Mat3) -> f64 {
        let mut force = std::mem::take(&mut self.next);
        force.clear();
        force.resize(3 * x.len(), 0.0);
        for (i, p) in x.iter().enumerate() {
            let u = self.surface.pressure(p[0], p[2]);
            if u > 0.0 {
                let a = rotate(&rotation(i), self.area[i]);
                for d in 0..3 {
                    force[3 * i + d] = -u * a[d];
                }
            }
        }
        let mut work = 0.0;
        if !self.force.is_empty() && !x_prev.is_empty() {
            for (i, (p, q)) in x.iter().zip(x_prev).enumerate() {
                for d in 0..3 {
                    work += 0.5 * (self.force[3 * i + d] + force[3 * i + d]) * (p[d] - q[d]);
                }
            }
        }
        self.next = std::mem::replace(&mut self.force, force);
        work
    }
}

/// The runout engine: what is built once, and the scratch of a step.
pub struct Runout {
    params: RunoutParams,
    dt: f64,
    faces: Faces,
    /// Per node: the elements holding it and its local corner there.
    node_elems: Vec<Vec<(u32, u8)>>,
    /// Per node: its exterior face area (m^2), 0 for a node inside a body.
    exterior: Vec<bool>,
    /// The interface of each pair of elements that shared a face at the start.
    pair_interface: BTreeMap<(u32, u32), u16>,
    /// Body of each element (union-find over shared nodes and bonded springs).
    body: Vec<u32>,
    /// Whether spring `s` bonds (not handed over to the contacts).
    bonded: Vec<bool>,
    /// The last mapping: positions then, candidates and their triangles.
    x_map: Vec<[f64; 3]>,
    mapped: bool,
    candidates: Vec<Candidate>,
    cand_tris: Vec<u16>,
    /// The candidates of one vertex and one body: consecutive ranges.
    cand_groups: Vec<std::ops::Range<usize>>,
    /// Per candidate: how far (m) its vertex is at least from its block's
    /// box, less the relative motion since ([`Self::step`]'s 3a): while
    /// positive for every candidate of a vertex and body with no contact
    /// history, that vertex cannot touch that body and is not looked at.
    clearance: Vec<f64>,
    /// Node positions at the last step.
    x_prev: Vec<[f64; 3]>,
    /// Per candidate: its group (index into `cand_groups`); per group:
    /// whether its vertex and body are in contact (have a history).
    cand_group: Vec<u32>,
    touching: Vec<bool>,
    /// The blocks a candidate vertex may touch (sorted), where each one's
    /// triangles start in `placed` (`u32::MAX` for the others), and the
    /// triangles placed at this step.
    placed_elems: Vec<u32>,
    placed_at: Vec<u32>,
    placed: Vec<contact::Placed>,
    /// The forces a released spring left at a node (compression, N; shear on
    /// the node, N), taken up by that node's first new contact.
    pending: BTreeMap<u32, ContactHistory>,
    /// Contact history keyed by (node, body of the face).
    history: BTreeMap<(u32, u32), ContactHistory>,
    /// Scratch.
    f_elem: Vec<f64>,
    rotations: Vec<Mat3>,
    elem_energy: Vec<f64>,
    f_int: Vec<f64>,
    spring_force_prev: Vec<[f64; 3]>,
    spring_input: f64,
    spring_e0: Option<f64>,
    // Energy bookkeeping.
    energy: Energy,
    kinetic0: f64,
    elastic0: Option<f64>,
    u0: Vec<f64>,
    fixed_elem: Vec<bool>,
    /// Per element: the contact stiffness limit (Pa/m), empty for none.
    contact_limit: Vec<f64>,
    /// The pore water, if the model has a phreatic surface.
    water: Option<RunoutWater>,
    pub remaps: usize,
    /// Wall time spent in each stage of [`Runout::step`] so far (s), in the
    /// order of [`STAGES`]: what a profile of the runout reads first.
    pub stage_seconds: [f64; 6],
}

/// The stages of a runout step, as [`Runout::stage_seconds`] counts them.
pub const STAGES: [&str; 6] = ["blocks", "joints", "broad phase", "narrow phase", "contact forces", "update"];

/// The result of a runout.
#[derive(Debug, Clone)]
pub struct RunoutEnd {
    /// Steps taken, time run (s).
    pub steps: usize,
    pub time: f64,
    /// The time the mass came to rest (s), if it did.
    pub rest_at: Option<f64>,
    pub peak_speed: f64,
    pub energy: Energy,
}

impl Runout {
    /// The engine for `model` from the state the failure phase left (`springs`
    /// and `joints`: which springs have failed and what they can carry).
    pub fn new(
        model: &Model,
        params: RunoutParams,
        springs: &SpringState,
        joints: &JointState,
        u: &[f64],
    ) -> Result<Self, SolveError> {
        let el = &model.elements;
        let n = model.n_nodes();
        let mut node_elems: Vec<Vec<(u32, u8)>> = vec![Vec::new(); n];
        for e in 0..el.len() {
            for (c, &node) in el.corners(e).iter().enumerate() {
                node_elems[node as usize].push((e as u32, c as u8));
            }
        }
        let mut faces = Faces::build(model);
        // Exterior faces: those no other element holds with the same nodes.
        let mut count: BTreeMap<Vec<u32>, u32> = BTreeMap::new();
        let face_key = |e: usize, f: usize| {
            let corners = el.corners(e);
            let mut k: Vec<u32> = el.kind[e].faces()[f].iter().map(|&c| corners[c]).collect();
            k.sort_unstable();
            k
        };
        for e in 0..el.len() {
            for f in 0..el.kind[e].faces().len() {
                *count.entry(face_key(e, f)).or_default() += 1;
            }
        }
        let mut exterior = vec![false; n];
        for e in 0..el.len() {
            let fp = faces.face_ptr[e];
            for f in 0..el.kind[e].faces().len() {
                if count[&face_key(e, f)] > 1 {
                    faces.face_share[fp + f] = 0.0;
                } else {
                    for &c in el.kind[e].faces()[f] {
                        exterior[el.corners(e)[c] as usize] = true;
                    }
                }
            }
        }
        // Interior faces take no part in contact: drop their triangles.
        let mut tri = Vec::new();
        let mut tri_ptr = vec![0];
        for e in 0..el.len() {
            let fp = faces.face_ptr[e];
            tri.extend(faces.triangles(e).iter().filter(|t| faces.face_share[fp + t.face as usize] > 0.0).copied());
            tri_ptr.push(tri.len());
        }
        faces.tri = tri;
        faces.tri_ptr = tri_ptr;
        let elem_of = |node: u32| node_elems[node as usize].first().map(|&(e, _)| e).unwrap_or(0);
        let mut pair_interface = BTreeMap::new();
        for s in 0..model.springs.len() {
            let (a, b) = (elem_of(model.springs.a[s]), elem_of(model.springs.b[s]));
            pair_interface.entry((a.min(b), a.max(b))).or_insert(model.springs.interface[s]);
        }
        // Time step: Gershgorin's bound on each node's row of the stiffness
        // (docs/method.md 2.13): the elements', and on each exterior face at
        // the node either its spring (bonded: one body) or its contacts
        // (released, or a block met anew), whichever is stiffer, never both.
        let contact_limit: Vec<f64> = match params.stiffness_limit {
            Some(f) => model.zone_stiffness().iter().map(|k| f * k).collect(),
            None => Vec::new(),
        };
        let kn_max = contact_kn_max(model, &params.contact);
        let node_limit = |i: usize| match contact_limit.is_empty() {
            true => f64::INFINITY,
            false => node_elems[i].iter().map(|&(e, _)| contact_limit[e as usize]).fold(f64::INFINITY, f64::min),
        };
        let rows = face_row_bound(model, &faces, &node_elems, |i| kn_max.min(node_limit(i)));
        let lambda = rows.iter().zip(&model.mass).map(|(r, m)| r / m).fold(0.0, f64::max);
        let amplification = match params.damping {
            RunoutDamping::Local { alpha } => 1.0 + alpha,
            _ => 1.0,
        };
        if !(lambda > 0.0 && lambda.is_finite()) {
            return Err(SolveError::NoTimeStep);
        }
        let dt = params.safety * 2.0 / (amplification * lambda).sqrt();
        let fixed_elem = (0..el.len())
            .map(|e| el.corners(e).iter().all(|&c| (0..3).all(|d| model.fixed[3 * c as usize + d])))
            .collect();
        let mut me = Self {
            params,
            dt,
            faces,
            node_elems,
            exterior,
            pair_interface,
            body: Vec::new(),
            bonded: vec![true; model.springs.len()],
            x_map: Vec::new(),
            mapped: false,
            candidates: Vec::new(),
            cand_tris: Vec::new(),
            cand_groups: Vec::new(),
            clearance: Vec::new(),
            x_prev: Vec::new(),
            cand_group: Vec::new(),
            touching: Vec::new(),
            placed_elems: Vec::new(),
            placed_at: vec![u32::MAX; el.len()],
            placed: Vec::new(),
            history: BTreeMap::new(),
            pending: BTreeMap::new(),
            f_elem: vec![0.0; 24 * el.len()],
            rotations: vec![IDENTITY; el.len()],
            elem_energy: vec![0.0; el.len()],
            f_int: vec![0.0; 3 * n],
            spring_force_prev: vec![[0.0; 3]; model.springs.len()],
            spring_input: 0.0,
            spring_e0: None,
            energy: Energy::default(),
            kinetic0: 0.0,
            elastic0: None,
            u0: Vec::new(),
            fixed_elem,
            contact_limit,
            water: RunoutWater::new(model),
            remaps: 0,
            stage_seconds: [0.0; 6],
        };
        me.hand_over(model, springs, joints, u);
        Ok(me)
    }

    /// The time step (s).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// The rotation of each element now (from the last step).
    pub fn rotations(&self) -> &[Mat3] {
        &self.rotations
    }

    /// Decides which springs still bond and regroups the bodies: a spring
    /// bonds while it is intact and its joint has a tensile strength or a
    /// cohesion; bodies are the elements joined by shared nodes or bonds.
    /// Returns whether anything changed.
    fn hand_over(&mut self, model: &Model, springs: &SpringState, joints: &JointState, u: &[f64]) -> bool {
        let el = &model.elements;
        let mut changed = self.body.is_empty();
        for s in 0..model.springs.len() {
            let bonds = springs.status[s] == SpringStatus::Intact && joints.strength[s].is_none_or(|st| st.bonds());
            if self.bonded[s] && !bonds {
                self.release(model, springs, s, u);
                changed = true;
            }
        }
        if !changed {
            return false;
        }
        let mut parts = UnionFind::new(el.len());
        for list in &self.node_elems {
            for w in list.windows(2) {
                parts.union(w[0].0 as usize, w[1].0 as usize);
            }
        }
        for s in (0..model.springs.len()).filter(|&s| self.bonded[s]) {
            let a = self.node_elems[model.springs.a[s] as usize][0].0;
            let b = self.node_elems[model.springs.b[s] as usize][0].0;
            parts.union(a as usize, b as usize);
        }
        self.body = (0..el.len()).map(|e| parts.find(e) as u32).collect();
        // A spring between two bodies hands over even if it is intact.
        for s in 0..model.springs.len() {
            let a = self.node_elems[model.springs.a[s] as usize][0].0;
            let b = self.node_elems[model.springs.b[s] as usize][0].0;
            if self.bonded[s] && self.body[a as usize] != self.body[b as usize] {
                self.release(model, springs, s, u);
            }
        }
        self.mapped = false;
        true
    }

    /// Spring `s` stops bonding: its shear force is kept for the contacts its
    /// two nodes make next ([`Self::pending_shear`]), so that a joint that
    /// was holding a block by friction hands over without a jolt.
    fn release(&mut self, model: &Model, springs: &SpringState, s: usize, u: &[f64]) {
        self.bonded[s] = false;
        let sp = &model.springs;
        let (a, b) = (sp.a[s] as usize, sp.b[s] as usize);
        let d = [0, 1, 2].map(|k| u[3 * b + k] - u[3 * a + k]);
        let (f_n, f_s) = crate::physics::spring::spring_force(sp.kn[s], sp.ks[s], sp.normal[s], d, springs.slip[s]);
        let open = springs.status[s] != SpringStatus::Intact && f_n > 0.0;
        if open {
            return;
        }
        for (node, sign) in [(a, 1.0), (b, -1.0)] {
            let e = self.pending.entry(node as u32).or_default();
            e.normal += (-f_n).max(0.0);
            for k in 0..3 {
                e.shear[k] += sign * f_s[k];
            }
        }
    }

    /// The law of a contact between blocks `a` and `b` at a vertex of area `area`.
    fn law(&self, model: &Model, a: u32, b: u32, area: f64) -> ContactLaw {
        let d = &self.params.contact;
        let (kn, ks, tan_phi) = match self.pair_interface.get(&(a.min(b), a.max(b))) {
            Some(&i) => {
                let p = &model.interfaces[i as usize].props;
                let tan_phi = p.strength.map_or(d.friction_deg.to_radians().tan(), |s| s.residual_tan_phi());
                match p.normal_modulus.is_finite() {
                    true => (p.normal_modulus / p.thickness, p.shear_modulus / p.thickness, tan_phi),
                    false => (d.normal_stiffness, d.shear_stiffness, tan_phi),
                }
            }
            None => (d.normal_stiffness, d.shear_stiffness, d.friction_deg.to_radians().tan()),
        };
        let limit = match self.contact_limit.is_empty() {
            true => f64::INFINITY,
            false => self.contact_limit[a as usize].min(self.contact_limit[b as usize]),
        };
        let (kn, ks) = (kn.min(limit), ks.min(limit));
        ContactLaw { kn: kn * area, ks: ks * area, tan_phi, cohesion: 0.0 }
    }

    /// The broad phase and the candidates' near triangles, from positions `x`.
    fn map(&mut self, model: &Model, x: &[[f64; 3]]) {
        let el = &model.elements;
        let tol = self.params.tolerance;
        let boxes: Vec<_> =
            (0..el.len()).map(|e| block_box(el.corners(e).iter().map(|&c| x[c as usize]), 0.5 * tol)).collect();
        let body = &self.body;
        let fixed = &self.fixed_elem;
        let keep = |a: usize, b: usize| body[a] != body[b] && !(fixed[a] && fixed[b]);
        // The same pairs, sorted, either way (a unit test); which is faster
        // depends on the count (benches/broad_phase.rs: sort and sweep up to
        // about 5e4 blocks, the grid above, whose cost grows as n^1.06).
        let pairs = match boxes.len() > GRID_ABOVE {
            true => {
                let cell =
                    boxes.iter().map(|(lo, hi)| (0..3).map(|d| hi[d] - lo[d]).fold(0.0, f64::max)).fold(0.0, f64::max);
                contact::grid(&boxes, cell, keep)
            }
            false => sweep(&boxes, keep),
        };
        let mut candidates = Vec::new();
        let mut tris = Vec::new();
        let mut seen = std::collections::BTreeSet::new();
        for &(a, b) in &pairs {
            for (v_elem, f_elem) in [(a, b), (b, a)] {
                let (lo, hi) = boxes[f_elem as usize];
                let corners_f: Vec<[f64; 3]> = el.corners(f_elem as usize).iter().map(|&c| x[c as usize]).collect();
                for &node in el.corners(v_elem as usize) {
                    let p = x[node as usize];
                    if !self.exterior[node as usize]
                        || (0..3).any(|d| p[d] < lo[d] - 0.5 * tol || p[d] > hi[d] + 0.5 * tol)
                        || !seen.insert((node, f_elem))
                    {
                        continue;
                    }
                    let start = tris.len();
                    for (k, t) in self.faces.triangles(f_elem as usize).iter().enumerate() {
                        let face = self.faces.face_corners[self.faces.face_ptr[f_elem as usize] + t.face as usize];
                        let (tlo, thi) =
                            block_box(face.iter().map(|&c| corners_f[c]), tol + self.params.max_penetration);
                        if (0..3).all(|d| p[d] >= tlo[d] && p[d] <= thi[d]) {
                            tris.push(k as u16);
                        }
                    }
                    if tris.len() > start {
                        candidates.push(Candidate {
                            node,
                            vertex_elem: v_elem,
                            face_elem: f_elem,
                            tris: start..tris.len(),
                        });
                    }
                }
            }
        }
        let body = &self.body;
        candidates.sort_by_key(|c: &Candidate| (c.node, body[c.face_elem as usize], c.face_elem));
        let mut placed_elems: Vec<u32> = candidates.iter().map(|c| c.face_elem).collect();
        placed_elems.sort_unstable();
        placed_elems.dedup();
        self.placed_at.fill(u32::MAX);
        let mut at = 0;
        for &e in &placed_elems {
            self.placed_at[e as usize] = at as u32;
            at += self.faces.triangles(e as usize).len();
        }
        self.placed.resize(at, contact::Placed::default());
        self.placed_elems = placed_elems;
        let mut groups = Vec::new();
        let mut i = 0;
        while i < candidates.len() {
            let key = |c: &Candidate| (c.node, body[c.face_elem as usize]);
            let j = i + candidates[i..].iter().take_while(|c| key(c) == key(&candidates[i])).count();
            groups.push(i..j);
            i = j;
        }
        self.cand_group = groups.iter().enumerate().flat_map(|(g, r)| r.clone().map(move |_| g as u32)).collect();
        self.touching = groups
            .iter()
            .map(|r| {
                self.history.contains_key(&(candidates[r.start].node, body[candidates[r.start].face_elem as usize]))
            })
            .collect();
        self.cand_groups = groups;
        self.clearance = vec![0.0; candidates.len()];
        self.candidates = candidates;
        self.cand_tris = tris;
        self.x_map = x.to_vec();
        self.mapped = true;
        self.remaps += 1;
    }

    /// One step (see the module doc).
    pub fn step(&mut self, model: &Model, st: &mut RunoutState) -> Result<RunoutStep, SolveError> {
        let el = &model.elements;
        let n = model.n_nodes();
        if self.u0.is_empty() {
            self.u0 = st.u.clone();
            self.kinetic0 = (0..3 * n).map(|k| 0.5 * model.mass[k / 3] * st.v[k] * st.v[k]).sum();
        }
        let x: Vec<[f64; 3]> = (0..n).map(|i| [0, 1, 2].map(|d| model.x0[i][d] + st.u[3 * i + d])).collect();

        let mut clock = std::time::Instant::now();
        let mut lap = |stage: usize, seconds: &mut [f64; 6]| {
            let now = std::time::Instant::now();
            seconds[stage] += (now - clock).as_secs_f64();
            clock = now;
        };
        // 1. Blocks: corotational forces.
        let fe = &mut self.f_elem;
        let rot = &mut self.rotations;
        let en = &mut self.elem_energy;
        fe.par_chunks_mut(24).zip(rot.par_iter_mut()).zip(en.par_iter_mut()).enumerate().for_each(
            |(e, ((f, r), w))| {
                let corners = el.corners(e);
                let m = corners.len();
                let (mut x0, mut xe) = ([[0.0; 3]; 8], [[0.0; 3]; 8]);
                for (k, &c) in corners.iter().enumerate() {
                    (x0[k], xe[k]) = (model.x0[c as usize], x[c as usize]);
                }
                let c = corotated_force_from(r, el.stiffness(e), &x0[..m], &xe[..m], &mut f[..3 * m]);
                (*r, *w) = (c.rotation, c.energy);
            },
        );
        let mut f_int = std::mem::take(&mut self.f_int);
        f_int.resize(3 * n, 0.0);
        f_int.fill(0.0);
        for e in 0..el.len() {
            for (c, &node) in el.corners(e).iter().enumerate() {
                for d in 0..3 {
                    f_int[3 * node as usize + d] += self.f_elem[24 * e + 3 * c + d];
                }
            }
        }
        let mut elastic: f64 = self.elem_energy.iter().sum();

        lap(0, &mut self.stage_seconds);
        // 2. Joints: bonded springs, the normal turned with block a.
        let sp = &model.springs;
        let mut spring_energy = 0.0;
        let mut input = 0.0;
        // Each spring's force, the work put in over the step (trapezoid) and
        // what it stores now, in parallel; then summed in spring order.
        let (bonded, rotations, node_elems, dt) = (&self.bonded, &self.rotations, &self.node_elems, self.dt);
        let (u, v, joints) = (&st.u, &st.v, &st.joints);
        let per_spring: Vec<([f64; 3], f64, f64)> = st
            .springs
            .slip
            .par_iter_mut()
            .zip(st.springs.status.par_iter_mut())
            .zip(self.spring_force_prev.par_iter_mut())
            .enumerate()
            .map(|(s, ((slip, status), prev))| {
                if !bonded[s] {
                    return ([0.0; 3], 0.0, 0.0);
                }
                let (a, b) = (sp.a[s] as usize, sp.b[s] as usize);
                let normal = rotate(&rotations[node_elems[a][0].0 as usize], sp.normal[s]);
                let spring = Spring { kn: sp.kn[s], ks: sp.ks[s], normal, area: sp.area[s] };
                let d = [0, 1, 2].map(|k| u[3 * b + k] - u[3 * a + k]);
                let fa = joints.force(s, &spring, d, slip, status);
                let dd = [0, 1, 2].map(|k| (v[3 * b + k] - v[3 * a + k]) * dt);
                let input = (0..3).map(|k| 0.5 * (prev[k] + fa[k]) * dd[k]).sum::<f64>();
                *prev = fa;
                let fn_ = fa[0] * normal[0] + fa[1] * normal[1] + fa[2] * normal[2];
                let fs2 = (0..3).map(|k| (fa[k] - fn_ * normal[k]).powi(2)).sum::<f64>();
                let stored = 0.5 * fn_ * fn_ / sp.kn[s] + if sp.ks[s] > 0.0 { 0.5 * fs2 / sp.ks[s] } else { 0.0 };
                (fa, input, stored)
            })
            .collect();
        for (s, (fa, put_in, stored)) in per_spring.into_iter().enumerate().filter(|&(s, _)| self.bonded[s]) {
            let (a, b) = (sp.a[s] as usize, sp.b[s] as usize);
            for k in 0..3 {
                f_int[3 * a + k] -= fa[k];
                f_int[3 * b + k] += fa[k];
            }
            input += put_in;
            spring_energy += stored;
        }
        if st.step > 0 {
            self.spring_input += input;
        }
        elastic += spring_energy;
        // Springs that failed this step hand over from the next (and the
        // broad phase runs again: bodies may have split).
        self.hand_over(model, &st.springs, &st.joints, &st.u);

        lap(1, &mut self.stage_seconds);
        // 3. Contacts (the re-detection test and the broad phase, then the narrow phase and the forces).
        let half = 0.5 * self.params.tolerance;
        let remap = !self.mapped
            || (0..n).any(|i| (0..3).map(|d| (x[i][d] - self.x_map[i][d]).powi(2)).sum::<f64>() > half * half);
        if remap {
            self.map(model, &x);
        }
        lap(2, &mut self.stage_seconds);
        let dt = self.dt;
        // 3a. Narrow phase: where each candidate vertex touches its block.
        // An element's corners now, on the stack (at most 8).
        let corners_of = |e: usize| -> Corners {
            let mut out = Corners { p: [[0.0; 3]; 8], len: 0 };
            for &c in el.corners(e) {
                out.p[out.len] = x[c as usize];
                out.len += 1;
            }
            out
        };
        // Each candidate's clearance less the motion of its vertex relative
        // to its block's corners this step (the box of corners that each
        // moved at most m relative to the vertex is at most m nearer it):
        // `|dv - dq| <= |dv - d0| + max_q |dq - d0|` with `d0` the block's
        // first corner's step and the maximum taken once per block.
        let (x_prev, candidates) = (&self.x_prev, &self.candidates);
        if !x_prev.is_empty() {
            let step_of = |i: usize| [0, 1, 2].map(|d| x[i][d] - x_prev[i][d]);
            let dist = |a: [f64; 3], b: [f64; 3]| (0..3).map(|d| (a[d] - b[d]).powi(2)).sum::<f64>().sqrt();
            let spread: Vec<f64> = (0..el.len())
                .into_par_iter()
                .map(|e| {
                    let d0 = step_of(el.corners(e)[0] as usize);
                    el.corners(e).iter().map(|&q| dist(step_of(q as usize), d0)).fold(0.0, f64::max)
                })
                .collect();
            self.clearance.par_iter_mut().zip(candidates.par_iter()).for_each(|(clear, c)| {
                let fe = c.face_elem as usize;
                *clear -= dist(step_of(c.node as usize), step_of(el.corners(fe)[0] as usize)) + spread[fe];
            });
        }
        // A vertex and body are looked at if they are in contact or any of
        // their candidates may be within reach of touching.
        let clearance = &self.clearance;
        let awake: Vec<bool> = (self.cand_groups.par_iter().zip(self.touching.par_iter()))
            .map(|(r, &touching)| touching || r.clone().any(|k| clearance[k] <= 0.0))
            .collect();
        // The candidates looked at, group by group (`looked[o..]` for the
        // group at `o`), and where each one's vertex touches its block.
        let mut looked: Vec<u32> = Vec::new();
        let mut awake_groups: Vec<(usize, usize)> = Vec::new();
        for (g, r) in self.cand_groups.iter().enumerate().filter(|&(g, _)| awake[g]) {
            awake_groups.push((g, looked.len()));
            looked.extend(r.clone().map(|k| k as u32));
        }
        // The triangles of the blocks the looked-at vertices may touch, placed once.
        let mut need = vec![false; self.placed_elems.len()];
        for &k in &looked {
            let e = self.candidates[k as usize].face_elem as usize;
            need[self.placed_elems.binary_search(&(e as u32)).unwrap_or(0)] = true;
        }
        let mut chunks = Vec::with_capacity(self.placed_elems.len());
        let mut rest = &mut self.placed[..];
        for (&e, &need) in self.placed_elems.iter().zip(&need) {
            let (chunk, tail) = rest.split_at_mut(self.faces.triangles(e as usize).len());
            if need {
                chunks.push((e as usize, chunk));
            }
            rest = tail;
        }
        let faces = &self.faces;
        chunks.into_par_iter().for_each(|(e, out)| faces.place(e, &corners_of(e), out));
        let placed_of = |e: usize| -> &[contact::Placed] {
            let at = self.placed_at[e] as usize;
            &self.placed[at..at + self.faces.triangles(e).len()]
        };
        let found: Vec<(Option<contact::FacePoint>, f64, f64)> = looked
            .par_iter()
            .map_init(
                || Vec::with_capacity(24),
                |normals, &k| {
                    let c = &self.candidates[k as usize];
                    let fe = c.face_elem as usize;
                    let p = x[c.node as usize];
                    let (fp, inside) = self.near_face(fe, placed_of(fe), p, c, normals);
                    (fp, inside, box_clearance(&corners_of(fe), p))
                },
            )
            .collect();
        for (&k, f) in looked.iter().zip(&found) {
            self.clearance[k as usize] = f.2;
        }
        // A vertex inside every face plane of a block, deeper than the
        // allowed penetration: a missed contact.
        if let Some((&k, (_, inside, _))) = looked.iter().zip(&found).find(|(_, f)| f.1 < -self.params.max_penetration)
        {
            let c = &self.candidates[k as usize];
            let vertex_elem = self.node_elems[c.node as usize][0].0 as usize;
            return Err(SolveError::Interpenetration {
                step: st.step,
                a: el.tag[vertex_elem],
                b: el.tag[c.face_elem as usize],
                depth: -inside,
            });
        }
        let found: Vec<Option<contact::FacePoint>> = found.into_iter().map(|f| f.0).collect();
        // 3b. One contact per vertex and body (candidates are sorted so): the
        // face point of the largest gap, of equals the most squarely inside;
        // the shear history follows the vertex across the body's faces.
        // Each: the group's candidates, the chosen one's candidate and
        // `found` index, the group.
        let band = 1e-9 * self.params.tolerance;
        let mut groups: Vec<(std::ops::Range<usize>, usize, usize, usize)> = Vec::new();
        for &(g, o) in &awake_groups {
            let range = self.cand_groups[g].clone();
            let mut best: Option<usize> = None;
            for k in o..o + range.len() {
                let Some(fp) = &found[k] else { continue };
                let better = match best.and_then(|b| found[b].as_ref()) {
                    None => true,
                    Some(b) => fp.gap > b.gap + band || (fp.gap >= b.gap - band && fp.inside > b.inside),
                };
                if better {
                    best = Some(k);
                }
            }
            if let Some(b) = best {
                groups.push((range.clone(), range.start + b - o, b, g));
            }
        }
        lap(3, &mut self.stage_seconds);
        // 3c. Each contact's law (its area: the vertex's faces that face the
        // contact and whose share lies over the other body) and its relative
        // motion this step.
        let inputs: Vec<Option<(ContactLaw, [f64; 3])>> = groups
            .par_iter()
            .map(|(range, b, bf, g)| {
                let cand = &self.candidates[*b];
                let fp = found[*bf].as_ref()?;
                // Only a vertex inside, or one that was in contact, makes a contact (below).
                if fp.gap >= 0.0 && !self.touching[*g] {
                    return None;
                }
                let over = |point: [f64; 3]| {
                    range.clone().any(|k| {
                        let c = &self.candidates[k];
                        contact::covers(placed_of(c.face_elem as usize), point, fp.normal)
                    })
                };
                let mut area = 0.0;
                for &(e, c) in &self.node_elems[cand.node as usize] {
                    let corners = corners_of(e as usize);
                    area += self.faces.vertex_area(
                        e as usize,
                        c as usize,
                        &self.rotations[e as usize],
                        &corners,
                        fp.normal,
                        &over,
                    );
                }
                if area <= 0.0 {
                    return None;
                }
                // Half: where two faces meet, the vertices of both sides touch.
                let law = self.law(model, cand.vertex_elem, cand.face_elem, 0.5 * area);
                let fe = cand.face_elem as usize;
                let mut vq = [0.0; 3];
                for i in 0..fp.len as usize {
                    let node = el.corners(fe)[fp.corners[i] as usize] as usize;
                    for d in 0..3 {
                        vq[d] += fp.weights[i] * st.v[3 * node + d];
                    }
                }
                let ds = [0, 1, 2].map(|d| (st.v[3 * cand.node as usize + d] - vq[d]) * dt);
                Some((law, ds))
            })
            .collect();
        let chosen = groups.iter().zip(inputs).filter_map(|((_, b, bf, g), input)| {
            let (law, ds) = input?;
            let c = &self.candidates[*b];
            Some((c.node, c.face_elem, law, found[*bf]?, ds, *g))
        });
        let chosen: Vec<_> = chosen.collect();
        let mut history = BTreeMap::new();
        let (mut contacts, mut sliding) = (0, 0);
        let mut friction = 0.0;
        self.touching.fill(false);
        for (node, fe, law, fp, ds, g) in chosen {
            let key = (node, self.body[fe as usize]);
            // A new contact (only where the vertex is inside the face) takes
            // half (the other side's vertex takes the other half) of what a
            // released spring left at its node.
            let mut h = match self.history.get(&key) {
                Some(&h) => h,
                None if fp.gap < 0.0 => self.pending.remove(&node).map_or_else(ContactHistory::default, |p| {
                    ContactHistory { normal: 0.5 * p.normal, shear: p.shear.map(|v| 0.5 * v) }
                }),
                None => continue,
            };
            let r = contact_force(&law, fp.normal, ds, &mut h);
            if r.normal > 0.0 {
                contacts += 1;
                sliding += usize::from(r.slipping);
                history.insert(key, h);
                self.touching[g] = true;
            }
            friction += r.dissipated;
            elastic += r.energy;
            let k = 3 * node as usize;
            for d in 0..3 {
                f_int[k + d] -= r.force[d];
            }
            for i in 0..fp.len as usize {
                let q = 3 * el.corners(fe as usize)[fp.corners[i] as usize] as usize;
                for d in 0..3 {
                    f_int[q + d] += fp.weights[i] * r.force[d];
                }
            }
        }
        self.history = history;

        lap(4, &mut self.stage_seconds);
        // 4. Update: the water's forces where the blocks are now, damping and
        // central differences.
        let (rotations, node_elems) = (&self.rotations, &self.node_elems);
        let water_work = match &mut self.water {
            Some(w) => w.update(&x, &self.x_prev, |i| rotations[node_elems[i].first().map_or(0, |e| e.0 as usize)]),
            None => 0.0,
        };
        let f_dry = self.water.as_ref().map_or(&model.f_ext, |w| &w.f_dry);
        let f_water = self.water.as_ref().map(|w| &w.force);
        let mut damping_work = 0.0;
        let mut kinetic = 0.0;
        let mut max_speed: f64 = 0.0;
        for i in 0..n {
            let mut speed2 = 0.0;
            for d in 0..3 {
                let k = 3 * i + d;
                if model.fixed[k] {
                    st.v[k] = 0.0;
                    continue;
                }
                let f = f_dry[k] + f_water.map_or(0.0, |w| w[k]) - f_int[k];
                let v_old = st.v[k];
                let fd = match self.params.damping {
                    RunoutDamping::None => 0.0,
                    RunoutDamping::Local { alpha } => crate::physics::damping::local_damping(alpha, f, v_old),
                    RunoutDamping::Rayleigh { ratio, omega } => 2.0 * ratio * omega * model.mass[i] * v_old,
                };
                let v_new = v_old + dt * (f - fd) / model.mass[i];
                let v_mid = 0.5 * (v_old + v_new);
                damping_work += fd * v_mid * dt;
                kinetic += 0.5 * model.mass[i] * v_mid * v_mid;
                speed2 += v_mid * v_mid;
                st.v[k] = v_new;
                st.u[k] += dt * v_new;
            }
            max_speed = max_speed.max(speed2.sqrt());
        }
        self.f_int = f_int;
        self.x_prev = x;
        lap(5, &mut self.stage_seconds);
        // 5. Monitor: the energy terms at this step (positions x_n, velocity v_n).
        if !kinetic.is_finite() || !elastic.is_finite() {
            let node = (0..st.u.len()).find(|&k| !st.u[k].is_finite() || !st.v[k].is_finite()).unwrap_or(0) / 3;
            return Err(SolveError::NonFinite { step: st.step, node });
        }
        let elastic0 = *self.elastic0.get_or_insert(elastic);
        self.energy.damping += damping_work;
        self.energy.friction += friction;
        // Gravity's work up to x_n: f_ext . (u_n - u_0); u_n is before this step's update.
        let f_dry = self.water.as_ref().map_or(&model.f_ext, |w| &w.f_dry);
        self.energy.gravity = (0..3 * n).map(|k| f_dry[k] * (st.u[k] - dt * st.v[k] - self.u0[k])).sum();
        self.energy.water += water_work;
        self.energy.kinetic = kinetic - self.kinetic0;
        self.energy.elastic = elastic - elastic0;
        let spring_e0 = *self.spring_e0.get_or_insert(spring_energy);
        self.energy.joints = self.spring_input - (spring_energy - spring_e0);
        st.step += 1;
        st.time += dt;
        Ok(RunoutStep {
            step: st.step,
            time: st.time,
            kinetic,
            max_speed,
            contacts,
            sliding,
            remapped: remap,
            energy: self.energy,
        })
    }

    /// The triangle a candidate vertex touches now, among its near ones.
    fn near_face(
        &self,
        fe: usize,
        placed: &[contact::Placed],
        p: [f64; 3],
        cand: &Candidate,
        normals: &mut Vec<[f64; 3]>,
    ) -> (Option<contact::FacePoint>, f64) {
        normals.clear();
        for &(e, c) in &self.node_elems[cand.node as usize] {
            self.faces.vertex_normals(e as usize, c as usize, &self.rotations[e as usize], normals);
        }
        let reach = (self.params.tolerance, self.params.max_penetration);
        vertex_face(&self.faces, fe, placed, p, reach, &self.cand_tris[cand.tris.clone()], normals)
    }

    /// Steps until the mass is at rest or the duration ends; `watch` sees
    /// every step and may stop the run.
    pub fn run(
        &mut self,
        model: &Model,
        st: &mut RunoutState,
        watch: &mut dyn FnMut(&RunoutStep, &RunoutState) -> std::ops::ControlFlow<()>,
    ) -> Result<RunoutEnd, SolveError> {
        let t0 = st.time;
        let mut peak: f64 = 0.0;
        // Rest: over a window of rest_time no node has moved more than
        // rest_velocity * rest_time (its mean speed below rest_velocity):
        // elastic vibration about a deposit is not motion of the mass.
        let mut window = (t0, st.u.clone());
        let mut rest_at = None;
        let (mut steps, mut time) = (0, 0.0);
        while st.time - t0 < self.params.duration {
            let r = self.step(model, st)?;
            steps += 1;
            time = st.time - t0;
            peak = peak.max(r.max_speed);
            if watch(&r, st).is_break() {
                break;
            }
            if self.params.rest_time > 0.0 && st.time - window.0 >= self.params.rest_time {
                let reach = self.params.rest_velocity * (st.time - window.0);
                let moved =
                    st.u.chunks(3)
                        .zip(window.1.chunks(3))
                        .map(|(a, b)| (0..3).map(|d| (a[d] - b[d]).powi(2)).sum::<f64>())
                        .fold(0.0, f64::max)
                        .sqrt();
                if moved < reach && peak > self.params.rest_velocity {
                    rest_at = Some(window.0 - t0);
                    break;
                }
                window = (st.time, st.u.clone());
            }
        }
        Ok(RunoutEnd { steps, time, rest_at, peak_speed: peak, energy: self.energy })
    }
}

/// Volume of the elements whose mean corner velocity `v` is above
/// `rest_velocity` (m^3): the moving mass.
pub fn moving_volume(model: &Model, v: &[f64], rest_velocity: f64) -> f64 {
    let el = &model.elements;
    (0..el.len())
        .filter(|&e| {
            let c = el.corners(e);
            let m: [f64; 3] = [0, 1, 2].map(|d| c.iter().map(|&n| v[3 * n as usize + d]).sum::<f64>() / c.len() as f64);
            (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt() > rest_velocity
        })
        .map(|e| el.volume[e])
        .sum()
}

/// How far `p` is at least from a block with corners `corners`, less the
/// edge slack of a projection ([`contact::EDGE_SLACK`] of the block's size):
/// the distance to the corners' box, which holds the block; where it is
/// positive no face point of the block can lie behind the vertex.
fn box_clearance(corners: &[[f64; 3]], p: [f64; 3]) -> f64 {
    let (lo, hi) = block_box(corners.iter().copied(), 0.0);
    let out = (0..3).map(|d| (lo[d] - p[d]).max(p[d] - hi[d]).max(0.0).powi(2)).sum::<f64>().sqrt();
    let size = (0..3).map(|d| (hi[d] - lo[d]).powi(2)).sum::<f64>().sqrt();
    out - 2.0 * contact::EDGE_SLACK * size
}

/// An element's corner positions, without a heap allocation.
struct Corners {
    p: [[f64; 3]; 8],
    len: usize,
}

impl std::ops::Deref for Corners {
    type Target = [[f64; 3]];
    fn deref(&self) -> &[[f64; 3]] {
        &self.p[..self.len]
    }
}

/// Each node's bound on its row sums of the stiffness (N/m): its elements'
/// ([`element_row_sums`]) and, per exterior face `f` at the node, the larger
/// of the springs that leave the node through `f` (their blocks `K_aa` and
/// `K_ab = -K_aa`: twice `K_aa`'s row) and the contacts it can make there
/// with stiffness `kn(i)` per unit area: a vertex contact over the node's
/// share `A_f` takes half of it (the other side's vertices the other half),
/// and its row, with the face points' (weights summing to one), is at most
/// `2 * 1.37 * kn A_f / 2` (1.37 bounds `|n_i| sum_j |n_j|`, 1.37 =
/// (1 + sqrt 3)/2); the node as a face point of the other side's vertices
/// takes as much again: `CONTACT_ROW kn A_f`, rounded up from 2.73. A spring
/// belongs to the face of its node whose rest normal is nearest its own.
fn face_row_bound(model: &Model, faces: &Faces, node_elems: &[Vec<(u32, u8)>], kn: impl Fn(usize) -> f64) -> Vec<f64> {
    const CONTACT_ROW: f64 = 3.0;
    let mut rows = crate::solver::timestep::element_row_sums(model);
    // Per node: (face index into `faces.face_*`, its bound so far from springs).
    let mut node_faces: Vec<Vec<(usize, f64)>> = node_elems
        .iter()
        .map(|list| {
            let mut out = Vec::new();
            for &(e, c) in list {
                for f in faces.face_ptr[e as usize]..faces.face_ptr[e as usize + 1] {
                    if faces.face_share[f] > 0.0 && faces.face_corners[f].contains(&(c as usize)) {
                        out.push((f, 0.0));
                    }
                }
            }
            out
        })
        .collect();
    let mut loose = vec![0.0; rows.len()];
    let sp = &model.springs;
    for s in 0..sp.len() {
        let n = sp.normal[s];
        let row = crate::solver::timestep::spring_block_rows(sp.kn[s], sp.ks[s], n).into_iter().fold(0.0, f64::max);
        for (node, sign) in [(sp.a[s] as usize, 1.0), (sp.b[s] as usize, -1.0)] {
            let dot = |f: usize| (0..3).map(|d| sign * n[d] * faces.face_normal[f][d]).sum::<f64>();
            match node_faces[node].iter_mut().max_by(|x, y| dot(x.0).total_cmp(&dot(y.0))) {
                Some(face) => face.1 += 2.0 * row,
                None => loose[node] += 2.0 * row,
            }
        }
    }
    for (i, list) in node_faces.iter().enumerate() {
        let k = kn(i);
        rows[i] +=
            loose[i] + list.iter().map(|&(f, spring)| spring.max(CONTACT_ROW * k * faces.face_share[f])).sum::<f64>();
    }
    rows
}

/// The largest contact stiffness per unit area any pair can take (Pa/m).
fn contact_kn_max(model: &Model, d: &ContactDefaults) -> f64 {
    model
        .interfaces
        .iter()
        .filter(|i| i.props.normal_modulus.is_finite())
        .map(|i| i.props.normal_modulus / i.props.thickness)
        .fold(d.normal_stiffness, f64::max)
}

impl RunoutState {
    /// A runout from displacement `u` at rest (or with velocity `v`), the
    /// springs' and joints' state as the failure phase left them.
    pub fn new(u: Vec<f64>, v: Vec<f64>, springs: SpringState, joints: JointState) -> Self {
        Self { u, v, springs, joints, step: 0, time: 0.0 }
    }
}
