//! The slab's front face as 2D patches (x, z) for contour figures: each
//! element contributes its corners on its lower-y side, ordered around their
//! centroid.

use super::figures::Patch;
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
