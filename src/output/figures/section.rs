//! The slab's front face as 2D patches (x, z) for contour figures: each
//! element contributes its corners on its lower-y side, ordered around their
//! centroid.

use plotters::style::RGBColor;

use super::plot::{Line, Patch};
use crate::model::Model;

/// The patch of one element from its corner positions.
pub fn front_patch(corners: &[[f64; 3]], value: f64) -> Patch {
    let ymid = corners.iter().map(|p| p[1]).sum::<f64>() / corners.len() as f64;
    let mut front: Vec<(f64, f64)> = corners.iter().filter(|p| p[1] < ymid).map(|p| (p[0], p[2])).collect();
    let n = front.len().max(1) as f64;
    let (cx, cz) = (front.iter().map(|p| p.0).sum::<f64>() / n, front.iter().map(|p| p.1).sum::<f64>() / n);
    front.sort_by(|a, b| (a.1 - cz).atan2(a.0 - cx).total_cmp(&(b.1 - cz).atan2(b.0 - cx)));
    Patch { corners: front, value }
}

/// One patch per CDEM element (reference positions of its node copies).
pub fn front_patches(model: &Model, value: impl Fn(usize) -> f64) -> Vec<Patch> {
    let el = &model.elements;
    (0..el.len())
        .map(|e| {
            let pts: Vec<[f64; 3]> = el.corners(e).iter().map(|&i| model.x0[i as usize]).collect();
            front_patch(&pts, value(e))
        })
        .collect()
}

/// One patch per mesh cell of a continuous mesh (e.g. the FEM's).
pub fn front_patches_of_cells(
    coords: &[[f64; 3]],
    cells: &[crate::mesh::Cell],
    value: impl Fn(usize) -> f64,
) -> Vec<Patch> {
    cells
        .iter()
        .enumerate()
        .map(|(c, cell)| {
            let pts: Vec<[f64; 3]> = cell.corners().iter().map(|&n| coords[n]).collect();
            front_patch(&pts, value(c))
        })
        .collect()
}

/// Mean of a displacement component over an element's corners.
pub fn element_mean_displacement(model: &Model, u: &[f64], e: usize, component: usize) -> f64 {
    let c = model.elements.corners(e);
    c.iter().map(|&i| u[3 * i as usize + component]).sum::<f64>() / c.len() as f64
}

/// One patch per CDEM element at its deformed position `x0 + scale u`.
pub fn front_patches_deformed(model: &Model, u: &[f64], scale: f64, value: impl Fn(usize) -> f64) -> Vec<Patch> {
    let el = &model.elements;
    (0..el.len())
        .map(|e| {
            let pts: Vec<[f64; 3]> = el.corners(e).iter().map(|&i| model.x0[i as usize]).collect();
            let mut patch = front_patch(&pts, value(e));
            // Same corners, moved: front_patch keeps (x, z) of the front
            // corners, so move each by the displacement of the copy there.
            let ymid = pts.iter().map(|p| p[1]).sum::<f64>() / pts.len() as f64;
            let front: Vec<usize> =
                el.corners(e).iter().map(|&i| i as usize).filter(|&i| model.x0[i][1] < ymid).collect();
            for c in patch.corners.iter_mut() {
                if let Some(&i) = front.iter().find(|&&i| model.x0[i][0] == c.0 && model.x0[i][2] == c.1) {
                    *c = (c.0 + scale * u[3 * i], c.1 + scale * u[3 * i + 2]);
                }
            }
            patch
        })
        .collect()
}

/// A joint's trace on the front face: the two springs of one shared element
/// face whose node copies lie on the front (lowest y) face.
#[derive(Debug, Clone, Copy)]
pub struct JointTrace {
    pub springs: [usize; 2],
}

/// The joint traces on the front face, one per element face shared by two
/// elements, in spring order.
pub fn front_joint_traces(model: &Model) -> Vec<JointTrace> {
    let el = &model.elements;
    let mut owner = vec![usize::MAX; model.n_nodes()];
    for e in 0..el.len() {
        for &i in el.corners(e) {
            owner[i as usize] = e;
        }
    }
    let y_front = model.x0.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
    let tol = 1e-6 * (1.0 + y_front.abs());
    let mut by_face: std::collections::BTreeMap<(usize, usize), Vec<usize>> = std::collections::BTreeMap::new();
    let sp = &model.springs;
    for s in 0..sp.len() {
        let (a, b) = (sp.a[s] as usize, sp.b[s] as usize);
        if (model.x0[a][1] - y_front).abs() <= tol {
            by_face.entry((owner[a], owner[b])).or_default().push(s);
        }
    }
    let mut traces: Vec<JointTrace> =
        by_face.into_values().filter(|v| v.len() == 2).map(|v| JointTrace { springs: [v[0], v[1]] }).collect();
    traces.sort_by_key(|t| t.springs[0]);
    traces
}

/// Normal opening `(u_b - u_a) . n` of spring `s` (m, positive open).
pub fn spring_opening(model: &Model, u: &[f64], s: usize) -> f64 {
    let sp = &model.springs;
    let (a, b, n) = (sp.a[s] as usize, sp.b[s] as usize, sp.normal[s]);
    (0..3).map(|k| (u[3 * b + k] - u[3 * a + k]) * n[k]).sum()
}

/// The (x, z) of spring `s` at `x0 + scale u`, midway between its two copies.
pub fn spring_point(model: &Model, u: &[f64], scale: f64, s: usize) -> (f64, f64) {
    let sp = &model.springs;
    let (a, b) = (sp.a[s] as usize, sp.b[s] as usize);
    let p = |i: usize, k: usize| model.x0[i][k] + scale * u[3 * i + k];
    (0.5 * (p(a, 0) + p(b, 0)), 0.5 * (p(a, 2) + p(b, 2)))
}

/// The water a model carries, drawn over its section in blue: the phreatic
/// surface over the model's x-range, and each water-filled crack's level as a
/// short horizontal stroke across the crack (its springs' x-range, widened so
/// that a vertical crack shows). Empty without water.
pub fn water_lines(model: &Model) -> Vec<Line> {
    let Some(w) = &model.water else { return Vec::new() };
    let blue = |points| Line { points, colour: WATER_BLUE, width: 3 };
    let (lo, hi) = crate::model::point_bounds(model.x0.iter().copied());
    let (x0, x1) = (lo[0], hi[0]);
    let mut lines = Vec::new();
    if let Some(s) = &w.surface {
        let mut xs = vec![x0];
        xs.extend(s.points.iter().map(|p| p[0]).filter(|&x| x > x0 && x < x1));
        xs.push(x1);
        lines.push(blue(xs.into_iter().map(|x| (x, s.level(x))).collect()));
    }
    let margin = 0.01 * (x1 - x0);
    for (group, level) in &w.cracks {
        let Some(k) = model.interfaces.iter().position(|i| &i.name == group) else { continue };
        let sp = &model.springs;
        let xs = (0..sp.len()).filter(|&s| sp.interface[s] as usize == k).map(|s| model.x0[sp.a[s] as usize][0]);
        let (a, b) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
        if a.is_finite() {
            lines.push(blue(vec![(a - margin, *level), (b + margin, *level)]));
        }
    }
    lines
}

/// The colour of water over a section (on the sequential map's light end
/// and its dark end alike).
pub const WATER_BLUE: RGBColor = RGBColor(0, 90, 220);

/// The legend of [`water_lines`] under a figure: one line, or none without
/// water.
pub fn water_notes(model: &Model) -> Vec<String> {
    match model.water {
        Some(_) => vec!["blue, in the section: the water table (and the water level in each crack)".to_string()],
        None => Vec::new(),
    }
}
