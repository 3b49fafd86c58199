//! The figures of an ensemble: `fs-histogram.png` (the members' FS with
//! FS = 1 and the mean marked), `convergence.png` (the mean FS and PF of
//! the first n members against n) and `pf-by-water.png` (PF in bins of the
//! water level); every estimate drawn with its 95 % interval, the one
//! `ensemble.md` prints, so that a bin of 6 members is not read as a
//! measurement.

use std::path::Path;

use plotters::prelude::*;

use super::plot::{init_fonts, plot_err};
use crate::drivers::ensemble::{EnsembleSummary, PfBin};

/// A vertical 95 % interval `[lo, hi]` at `x`, its caps from `caps.0` to
/// `caps.1` (x units).
fn interval(x: f64, [lo, hi]: [f64; 2], caps: (f64, f64)) -> [PathElement<(f64, f64)>; 3] {
    let style = RGBColor(31, 119, 180).mix(0.7).stroke_width(2);
    [
        PathElement::new(vec![(x, lo), (x, hi)], style),
        PathElement::new(vec![(caps.0, lo), (caps.1, lo)], style),
        PathElement::new(vec![(caps.0, hi), (caps.1, hi)], style),
    ]
}

/// Histogram of the members' FS, FS = 1 and the mean marked.
pub fn histogram(path: &Path, fs: &[f64], s: &EnsembleSummary) -> crate::Result<()> {
    init_fonts();
    let (lo, hi) = fs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let (lo, hi) = (lo.min(1.0), hi.max(1.0));
    let span = (hi - lo).max(1e-6);
    let bins = ((fs.len() as f64).sqrt().ceil() as usize).clamp(10, 60);
    let w = 1.1 * span / bins as f64;
    // FS = 1 on a bin edge: a bin is wholly failing or wholly not.
    let x0 = 1.0 - ((1.0 - (lo - 0.05 * span)) / w).ceil() * w;
    let bins = (((hi + 0.05 * span) - x0) / w).ceil() as usize;
    let x1 = x0 + bins as f64 * w;
    let mut counts = vec![0usize; bins];
    for &v in fs {
        counts[(((v - x0) / w) as usize).min(bins - 1)] += 1;
    }
    let ymax = *counts.iter().max().unwrap_or(&1) as f64 * 1.15;
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let r = s.reliability.as_ref();
    let caption = format!(
        "Factor of safety over {} members: mean {:.3}, PF = {:.3}",
        fs.len(),
        s.fs.as_ref().map_or(f64::NAN, |d| d.mean),
        r.map_or(f64::NAN, |r| r.probability_of_failure)
    );
    let mut chart = ChartBuilder::on(&root)
        .caption(caption, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, 0.0..ymax)
        .map_err(|e| plot_err(path, e))?;
    chart
        .configure_mesh()
        .x_desc("factor of safety")
        .y_desc("members")
        .y_label_formatter(&|v| format!("{v:.0}"))
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let fill = RGBColor(70, 130, 180);
    chart
        .draw_series(counts.iter().enumerate().map(|(k, &c)| {
            let a = x0 + k as f64 * w;
            let colour = if a + 0.5 * w < 1.0 { RGBColor(200, 60, 50) } else { fill };
            Rectangle::new([(a, 0.0), (a + w, c as f64)], colour.mix(0.85).filled())
        }))
        .map_err(|e| plot_err(path, e))?;
    chart
        .draw_series(std::iter::once(PathElement::new(vec![(1.0, 0.0), (1.0, ymax)], BLACK.stroke_width(2))))
        .map_err(|e| plot_err(path, e))?
        .label("FS = 1")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    if let Some(d) = &s.fs {
        let m = d.mean;
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(m, 0.0), (m, ymax)],
                RGBColor(255, 140, 0).stroke_width(2),
            )))
            .map_err(|e| plot_err(path, e))?
            .label("mean")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RGBColor(255, 140, 0).stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
}

/// Mean FS and PF of the first n members against n (log n), each point with
/// its 95 % interval.
pub fn convergence(path: &Path, s: &EnsembleSummary) -> crate::Result<()> {
    init_fonts();
    let pts = &s.convergence;
    if pts.is_empty() {
        return Ok(());
    }
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let panels = root.split_evenly((2, 1));
    let n1 = pts.last().map_or(10.0, |p| p.n as f64).max(10.0);
    let n0 = pts.first().map_or(1.0, |p| p.n as f64).min(n1 / 2.0);
    // (title, points, their 95 % intervals, the full ensemble's value)
    type Panel<'a> = (&'a str, Vec<(f64, f64)>, Vec<[f64; 2]>, Option<f64>);
    let series: [Panel; 2] = [
        (
            "mean FS of the first n members, 95 % interval",
            pts.iter().map(|p| (p.n as f64, p.mean)).collect(),
            pts.iter().map(|p| p.mean_ci95).collect(),
            s.fs.as_ref().map(|d| d.mean),
        ),
        (
            "P(FS < 1) of the first n members, 95 % Wilson interval",
            pts.iter().map(|p| (p.n as f64, p.probability_of_failure)).collect(),
            pts.iter().map(|p| p.pf_ci95).collect(),
            s.reliability.as_ref().map(|r| r.probability_of_failure),
        ),
    ];
    for (area, (title, line, ci, last)) in panels.iter().zip(series) {
        let (lo, hi) = ci
            .iter()
            .flatten()
            .chain(line.iter().map(|p| &p.1))
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        let pad = ((hi - lo) * 0.1).max(1e-3 * hi.abs().max(1e-3));
        let mut chart = ChartBuilder::on(area)
            .caption(title, ("sans-serif", 19))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            // A margin of 15 % either side on the log axis: the first and last
            // intervals' caps are not cut by the frame.
            .build_cartesian_2d((n0 / 1.15..n1 * 1.15).log_scale(), (lo - pad)..(hi + pad))
            .map_err(|e| plot_err(path, e))?;
        chart
            .configure_mesh()
            .x_desc("members n")
            .x_label_formatter(&|v| format!("{v:.0}"))
            .y_label_formatter(&|v| format!("{v:.3}"))
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| plot_err(path, e))?;
        let c = RGBColor(31, 119, 180);
        // Caps a fixed fraction of a decade wide on the log axis.
        for (p, b) in line.iter().zip(&ci) {
            chart.draw_series(interval(p.0, *b, (p.0 / 1.06, p.0 * 1.06))).map_err(|e| plot_err(path, e))?;
        }
        chart.draw_series(LineSeries::new(line.clone(), c.stroke_width(2))).map_err(|e| plot_err(path, e))?;
        chart.draw_series(line.iter().map(|&p| Circle::new(p, 4, c.filled()))).map_err(|e| plot_err(path, e))?;
        if let Some(v) = last {
            chart
                .draw_series(std::iter::once(PathElement::new(vec![(n0, v), (n1, v)], BLACK.mix(0.5).stroke_width(1))))
                .map_err(|e| plot_err(path, e))?;
        }
    }
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
}

/// An ensemble's figures in `dir` (none when no member has an FS), and
/// `pf-by-water.png` when a water key was drawn ([`pf_by_variable`]).
pub fn write_figures(
    dir: &Path,
    s: &EnsembleSummary,
    fs: &[f64],
    records: &[crate::drivers::ensemble::MemberRecord],
) -> crate::Result<()> {
    if !fs.is_empty() {
        histogram(&dir.join("fs-histogram.png"), fs, s)?;
        convergence(&dir.join("convergence.png"), s)?;
    }
    let water_key = records.first().and_then(|r| r.draws.iter().find(|d| d.key.starts_with("water.")));
    if let Some(key) = water_key.map(|d| d.key.clone()) {
        let bins = crate::drivers::ensemble::pf_by(records, &key, 8);
        pf_by_variable(&dir.join("pf-by-water.png"), &key, &bins)?;
    }
    Ok(())
}

/// P(FS < 1) in bins of one drawn variable, each with its members and its
/// 95 % Wilson interval.
pub fn pf_by_variable(path: &Path, key: &str, bins: &[PfBin]) -> crate::Result<()> {
    init_fonts();
    if bins.is_empty() {
        return Ok(());
    }
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let (x0, x1) = (bins[0].centre, bins[bins.len() - 1].centre);
    let pad = ((x1 - x0) * 0.08).max(1e-6);
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("P(FS < 1) against {key}: 95 % Wilson interval, members per bin beside each point"),
            ("sans-serif", 19),
        )
        .margin(14)
        .x_label_area_size(44)
        .y_label_area_size(60)
        .build_cartesian_2d((x0 - pad)..(x1 + pad), 0.0..1.05)
        .map_err(|e| plot_err(path, e))?;
    chart
        .configure_mesh()
        .x_desc(format!("{key} (m)"))
        .y_desc("P(FS < 1)")
        .x_label_formatter(&|v| format!("{v:.2}"))
        .y_label_formatter(&|v| format!("{v:.2}"))
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let c = RGBColor(31, 119, 180);
    let cap = 0.012 * (x1 - x0 + 2.0 * pad);
    for b in bins {
        chart
            .draw_series(interval(b.centre, b.ci95, (b.centre - cap, b.centre + cap)))
            .map_err(|e| plot_err(path, e))?;
    }
    let line: Vec<(f64, f64)> = bins.iter().map(|b| (b.centre, b.pf)).collect();
    chart.draw_series(LineSeries::new(line.clone(), c.stroke_width(2))).map_err(|e| plot_err(path, e))?;
    chart.draw_series(line.iter().map(|&p| Circle::new(p, 5, c.filled()))).map_err(|e| plot_err(path, e))?;
    // The member count beside the point, right of its interval.
    chart
        .draw_series(bins.iter().map(|b| {
            Text::new(format!("n {}", b.members), (b.centre + 1.5 * cap, b.pf + 0.01), ("sans-serif", 13).into_font())
        }))
        .map_err(|e| plot_err(path, e))?;
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
}
