//! `runout.png`: the runout of `cdem run` with `[runout]`. Left, the section
//! (the slab's front face, x-z) with the blocks where they are at the start,
//! at a third and two thirds of the run, and at its end (outlines, one colour
//! each, the start and what stays put grey; what moved filled at the end); right, the
//! front's travel (the largest displacement of any node) against time.

use std::path::Path;

use plotters::prelude::*;

use super::plot::{init_fonts, plot_err};
use super::section::front_patches_deformed;
use crate::drivers::runout::{moved, RunoutResult};
use crate::error::Error;
use crate::model::Model;

/// Writes `runout.png`.
pub fn runout_png(model: &Model, r: &RunoutResult, path: &Path) -> Result<(), Error> {
    init_fonts();
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (1500, 650)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let (left, right) = root.split_horizontally(950);
    // The frames drawn: start, 1/3, 2/3, end.
    let n = r.frames.len();
    let picks: Vec<usize> = if n <= 1 { vec![0] } else { vec![0, (n - 1) / 3, 2 * (n - 1) / 3, n - 1] };
    let colours = [RGBColor(150, 150, 150), RGBColor(31, 119, 180), RGBColor(44, 160, 44), RGBColor(214, 39, 40)];
    let patches: Vec<_> = picks.iter().map(|&k| front_patches_deformed(model, &r.frames[k].u, 1.0, |_| 0.0)).collect();
    let (mut x0, mut x1, mut z0, mut z1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for p in patches.iter().flatten().flat_map(|p| &p.corners) {
        (x0, x1, z0, z1) = (x0.min(p.0), x1.max(p.0), z0.min(p.1), z1.max(p.1));
    }
    // Equal scales on both axes.
    let (w, h) = (x1 - x0, z1 - z0);
    let span = w.max(h * 880.0 / 560.0) * 1.04;
    let (cx, cz) = (0.5 * (x0 + x1), 0.5 * (z0 + z1));
    let (xr, zr) = (cx - span / 2.0..cx + span / 2.0, cz - span * 560.0 / 880.0 / 2.0..cz + span * 560.0 / 880.0 / 2.0);
    let mut chart = ChartBuilder::on(&left)
        .caption("runout: the blocks at four times (front face)", ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(xr, zr)
        .map_err(|e| plot_err(path, e))?;
    chart
        .configure_mesh()
        .x_desc("x (m)")
        .y_desc("z (m)")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let moved = |e: usize| moved(model, &r.frames[0].u, &r.frames[n - 1].u, r.summary.runout_distance, e);
    for (k, (&pick, ps)) in picks.iter().zip(&patches).enumerate() {
        let c = colours[k.min(3)];
        let last = k + 1 == picks.len();
        for (e, p) in ps.iter().enumerate() {
            // What stays put is drawn once, grey; what moves, at every time.
            if k > 0 && !moved(e) {
                continue;
            }
            let mut pts = p.corners.clone();
            if last && moved(e) {
                chart
                    .draw_series(std::iter::once(Polygon::new(pts.clone(), c.mix(0.25))))
                    .map_err(|e| plot_err(path, e))?;
            }
            pts.push(pts[0]);
            chart
                .draw_series(std::iter::once(PathElement::new(pts, c.stroke_width(1))))
                .map_err(|e| plot_err(path, e))?;
        }
        let t = r.frames[pick].time;
        chart
            .draw_series(std::iter::once(PathElement::new(vec![(cx, cz), (cx, cz)], c)))
            .map_err(|e| plot_err(path, e))?
            .label(format!("t = {t:.2} s"))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(3)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;

    let pts: Vec<(f64, f64)> = r.rows.iter().map(|q| (q.time, q.front_travel)).collect();
    let t1 = pts.last().map_or(1.0, |p| p.0).max(1e-9);
    let d1 = pts.iter().map(|p| p.1).fold(0.0, f64::max).max(1e-9) * 1.05;
    let mut chart = ChartBuilder::on(&right)
        .caption("the front's travel", ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..t1, 0.0..d1)
        .map_err(|e| plot_err(path, e))?;
    chart
        .configure_mesh()
        .x_desc("time since the runout began (s)")
        .y_desc("largest node displacement (m)")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    chart.draw_series(LineSeries::new(pts, colours[3].stroke_width(2))).map_err(|e| plot_err(path, e))?;
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
}
