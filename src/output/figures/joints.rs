//! The mechanism of a 3D strength reduction (the joint-set cases): the
//! displacement since the elastic state at the smallest unstable factor, on
//! two views, a section (x, z, seen from -y) and a plan (x, y, seen from
//! above). Each element is the outline of its corners' projection, drawn in
//! the order of its displacement, so that the moving blocks show over the
//! rock around them. `mechanism-views.png`.

use std::path::Path;

use super::plot::{contour_panels, ContourStyle, Panel, Patch, Quantity};
use super::section::{element_mean_displacement, water_lines, water_notes};
use crate::drivers::SrmResult;
use crate::error::Error;
use crate::model::Model;

/// The convex hull of points (x, y), counter-clockwise (monotone chain).
fn hull(mut p: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    let mut h: Vec<(f64, f64)> = Vec::new();
    for pass in 0..2 {
        let start = h.len();
        let pts: Vec<(f64, f64)> = if pass == 0 { p.clone() } else { p.iter().rev().copied().collect() };
        for q in pts {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

/// Writes `path` (PNG) if the reduction found an unstable factor; returns
/// whether it did.
pub fn mechanism_views(result: &SrmResult, model: &Model, path: &Path) -> Result<bool, Error> {
    let Some(u) = &result.mechanism else { return Ok(false) };
    let el = &model.elements;
    let magnitude: Vec<f64> = (0..el.len())
        .map(|e| {
            let c = [0, 1, 2].map(|d| element_mean_displacement(model, u, e, d));
            (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt()
        })
        .collect();
    let mut order: Vec<usize> = (0..el.len()).collect();
    order.sort_by(|&a, &b| magnitude[a].total_cmp(&magnitude[b]));
    let view = |axes: (usize, usize)| -> Vec<Patch> {
        order
            .iter()
            .map(|&e| {
                let pts = el.corners(e).iter().map(|&i| model.x0[i as usize]).map(|p| (p[axes.0], p[axes.1])).collect();
                Patch { corners: hull(pts), value: magnitude[e] }
            })
            .collect()
    };
    let title = match (result.fs, result.bracket[1]) {
        (Some(fs), Some(hi)) => format!("strength reduction: FS = {fs:.3}; mechanism at F = {hi:.3}"),
        (_, Some(hi)) => format!("strength reduction: no bracket; mechanism at F = {hi:.3}"),
        _ => "strength reduction".to_string(),
    };
    let panels = [
        Panel { title: "section: x (m) east, z (m) up".into(), patches: view((0, 2)), lines: water_lines(model) },
        Panel { title: "plan: x (m) east, y (m) north".into(), patches: view((0, 1)), lines: Vec::new() },
    ];
    let style = ContourStyle {
        notes: water_notes(model),
        columns: 2,
        panel_width: 700,
        y_desc: vec!["z (m)".into(), "y (m)".into()],
        ..ContourStyle::default()
    };
    contour_panels(path, &title, "|u - u_elastic|", Quantity::Displacement, &panels, &style)?;
    Ok(true)
}
