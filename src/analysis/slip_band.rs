//! How finely a mesh resolves the slip band of a strength reduction with
//! plastic blocks (references/srm.md, "Discretisation error"): the band is
//! the largest face-connected set of elements whose plastic shear strain is
//! at least [`BAND_FRACTION`] of the largest; it crosses `along` elements
//! from end to end (the hop diameter of that set over shared faces, found by
//! two breadth-first sweeps) and is `across = elements / along` elements
//! thick.
//!
//! The thickness localises to one or two elements on every mesh (perfect
//! plasticity has no length of its own), so only `along` tells a coarse mesh
//! from a fine one; below [`MIN_ELEMENTS_ALONG`] the factor is likely
//! unconservative.

use std::collections::{HashMap, VecDeque};

use serde::Serialize;

use crate::model::Model;
use crate::physics::plastic::CellPlastic;

/// The band's elements carry at least this fraction of the largest plastic
/// shear strain (the toe's, as a rule: a quarter keeps the band to the toe's
/// side and to the crest).
pub const BAND_FRACTION: f64 = 0.25;
/// Fewer elements than this along the band: the factor is likely
/// unconservative (references/srm.md, "Discretisation error": on Griffiths &
/// Lane's hexahedra the bands of refine 0.5, 1, 1.5, 2 cross 13, 26, 40, 49
/// elements and their factors err +5.3, +2.5, +0.7, +0.5 % against the
/// extrapolated one: below 40, by more than 1 %).
pub const MIN_ELEMENTS_ALONG: usize = 40;

/// The slip band of one plastic state.
#[derive(Debug, Clone, Serialize)]
pub struct SlipBand {
    /// Elements in the band.
    pub elements: usize,
    /// Elements the band crosses from end to end.
    pub along: usize,
    /// Its mean thickness in elements (`elements / along`).
    pub across: f64,
    /// The smallest plastic shear strain counted in the band (-).
    pub threshold_strain: f64,
}

/// The slip band of `cells` (one per element of `model`); None if no element
/// has a plastic shear strain.
pub fn slip_band(model: &Model, cells: &[CellPlastic]) -> Option<SlipBand> {
    let max = cells.iter().map(|c| c.plastic_shear).fold(0.0, f64::max);
    if !(max > 0.0) {
        return None;
    }
    let threshold = BAND_FRACTION * max;
    let inside: Vec<bool> = cells.iter().map(|c| c.plastic_shear >= threshold).collect();
    let neighbours = face_neighbours(model, &inside);
    // The largest component, then its hop diameter by a double sweep.
    let mut seen = vec![false; cells.len()];
    let mut best: Vec<usize> = Vec::new();
    for e in (0..cells.len()).filter(|&e| inside[e]) {
        if !seen[e] {
            let (order, _) = sweep(e, &neighbours, &mut seen);
            if order.len() > best.len() {
                best = order;
            }
        }
    }
    let mut scratch = vec![false; cells.len()];
    let (order, _) = sweep(best[0], &neighbours, &mut scratch);
    let far = *order.last().unwrap_or(&best[0]);
    scratch.fill(false);
    let (_, hops) = sweep(far, &neighbours, &mut scratch);
    let along = hops + 1;
    Some(SlipBand {
        elements: best.len(),
        along,
        across: best.len() as f64 / along as f64,
        threshold_strain: threshold,
    })
}

/// Breadth-first from `start` over `neighbours`: the elements in the order
/// reached, and the hops to the last of them.
fn sweep(start: usize, neighbours: &[Vec<usize>], seen: &mut [bool]) -> (Vec<usize>, usize) {
    let mut order = vec![start];
    let mut depth = HashMap::from([(start, 0usize)]);
    let mut queue = VecDeque::from([start]);
    seen[start] = true;
    while let Some(u) = queue.pop_front() {
        for &v in &neighbours[u] {
            if !seen[v] {
                seen[v] = true;
                depth.insert(v, depth[&u] + 1);
                order.push(v);
                queue.push_back(v);
            }
        }
    }
    let last = *order.last().unwrap_or(&start);
    (order, depth[&last])
}

/// For each element with `inside`, its face neighbours with `inside` (faces
/// matched by their mesh nodes: the model's nodes are per element).
fn face_neighbours(model: &Model, inside: &[bool]) -> Vec<Vec<usize>> {
    let el = &model.elements;
    let mut faces: HashMap<[u32; 4], usize> = HashMap::new();
    let mut out = vec![Vec::new(); inside.len()];
    for e in (0..el.len()).filter(|&e| inside[e]) {
        let corners = el.corners(e);
        for face in el.kind[e].faces() {
            let mut key = [u32::MAX; 4];
            for (k, &i) in face.iter().enumerate() {
                key[k] = model.mesh_node[corners[i] as usize];
            }
            key.sort_unstable();
            if let Some(other) = faces.insert(key, e) {
                out[e].push(other);
                out[other].push(e);
            }
        }
    }
    out
}
