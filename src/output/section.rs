//! The slab's front face as 2D patches (x, z) for contour figures: each
//! element contributes its corners on its lower-y side, ordered around their
//! centroid.

use super::figures::Patch;
use crate::model::Model;

/// One patch per element with the given value. Corners are the element's
/// nodes with `y` below the element's mid-`y`, in reference position.
pub fn front_patches(model: &Model, value: impl Fn(usize) -> f64) -> Vec<Patch> {
    let el = &model.elements;
    (0..el.len())
        .map(|e| {
            let pts: Vec<[f64; 3]> = el.corners(e).iter().map(|&i| model.x0[i as usize]).collect();
            let ymid = pts.iter().map(|p| p[1]).sum::<f64>() / pts.len() as f64;
            let mut front: Vec<(f64, f64)> = pts.iter().filter(|p| p[1] < ymid).map(|p| (p[0], p[2])).collect();
            let n = front.len().max(1) as f64;
            let (cx, cz) = (front.iter().map(|p| p.0).sum::<f64>() / n, front.iter().map(|p| p.1).sum::<f64>() / n);
            front.sort_by(|a, b| (a.1 - cz).atan2(a.0 - cx).total_cmp(&(b.1 - cz).atan2(b.0 - cx)));
            Patch { corners: front, value: value(e) }
        })
        .collect()
}

/// Mean of a displacement component over an element's corners.
pub fn element_mean_displacement(model: &Model, u: &[f64], e: usize, component: usize) -> f64 {
    let c = model.elements.corners(e);
    c.iter().map(|&i| u[3 * i as usize + component]).sum::<f64>() / c.len() as f64
}
