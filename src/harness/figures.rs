//! Figures drawn with plotters into PNG files: no Python, no system fonts
//! (DejaVu Sans is embedded and registered once).

use std::path::Path;
use std::sync::Once;

use plotters::prelude::*;

use crate::error::Error;

static FONTS: Once = Once::new();

/// Registers the embedded font as plotters' "sans-serif" (once per process).
pub fn init_fonts() {
    FONTS.call_once(|| {
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular());
        let _ = plotters::style::register_font("sans-serif", FontStyle::Bold, dejavu::sans::bold());
    });
}

fn plot_err(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::io(path, std::io::Error::other(format!("drawing the figure: {e}")))
}

/// Axis scales of a line plot.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    Linear,
    Log,
}

/// One named series of (x, y) points, drawn as a line with markers.
pub struct Series<'a> {
    pub name: &'a str,
    pub points: &'a [(f64, f64)],
}

const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
];

fn range(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite() && (!log || *v > 0.0)) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (if log { 1e-3 } else { 0.0 }, 1.0);
    }
    if log {
        (lo / 1.5, hi * 1.5)
    } else {
        let pad = 0.05 * (hi - lo).max(1e-12 * hi.abs().max(1.0));
        (lo - pad, hi + pad)
    }
}

/// A line plot (linear or log axes) to a PNG.
pub fn line_plot(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    x: Scale,
    y: Scale,
) -> Result<(), Error> {
    init_fonts();
    let root = BitMapBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let (x0, x1) = range(series.iter().flat_map(|s| s.points.iter().map(|p| p.0)), x == Scale::Log);
    let (y0, y1) = range(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)), y == Scale::Log);
    let mut builder = ChartBuilder::on(&root);
    builder.caption(title, ("sans-serif", 22)).margin(15).x_label_area_size(45).y_label_area_size(80);
    macro_rules! draw {
        ($chart:expr) => {{
            let mut chart = $chart.map_err(|e| plot_err(path, e))?;
            let fmt = |log: bool| {
                move |v: &f64| {
                    if log {
                        format!("{v:.0e}")
                    } else {
                        format!("{v:.6}").trim_end_matches('0').trim_end_matches('.').to_string()
                    }
                }
            };
            chart
                .configure_mesh()
                .x_desc(x_label)
                .y_desc(y_label)
                .x_label_formatter(&fmt(x == Scale::Log))
                .y_label_formatter(&fmt(y == Scale::Log))
                .label_style(("sans-serif", 15))
                .draw()
                .map_err(|e| plot_err(path, e))?;
            for (k, s) in series.iter().enumerate() {
                let c = PALETTE[k % PALETTE.len()];
                let pts: Vec<(f64, f64)> =
                    s.points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
                chart
                    .draw_series(LineSeries::new(pts.clone(), c.stroke_width(2)))
                    .map_err(|e| plot_err(path, e))?
                    .label(s.name)
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
                if pts.len() <= 200 {
                    chart
                        .draw_series(pts.iter().map(|&p| Circle::new(p, 3, c.filled())))
                        .map_err(|e| plot_err(path, e))?;
                }
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperLeft)
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .label_font(("sans-serif", 15))
                .draw()
                .map_err(|e| plot_err(path, e))?;
        }};
    }
    match (x, y) {
        (Scale::Linear, Scale::Linear) => draw!(builder.build_cartesian_2d(x0..x1, y0..y1)),
        (Scale::Log, Scale::Linear) => draw!(builder.build_cartesian_2d((x0..x1).log_scale(), y0..y1)),
        (Scale::Linear, Scale::Log) => draw!(builder.build_cartesian_2d(x0..x1, (y0..y1).log_scale())),
        (Scale::Log, Scale::Log) => draw!(builder.build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())),
    }
    root.present().map_err(|e| plot_err(path, e))
}

/// Blue-white-red style map of `t` in [0, 1] (a perceptually ordered
/// "coolwarm"-like ramp).
pub fn colormap(t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let stops =
        [(59.0, 76.0, 192.0), (141.0, 176.0, 254.0), (221.0, 221.0, 221.0), (244.0, 154.0, 123.0), (180.0, 4.0, 38.0)];
    let x = t * (stops.len() - 1) as f64;
    let i = (x.floor() as usize).min(stops.len() - 2);
    let f = x - i as f64;
    let (a, b) = (stops[i], stops[i + 1]);
    RGBColor((a.0 + f * (b.0 - a.0)) as u8, (a.1 + f * (b.1 - a.1)) as u8, (a.2 + f * (b.2 - a.2)) as u8)
}

/// A filled polygon of the section (x, z) with its value.
pub struct Patch {
    pub corners: Vec<(f64, f64)>,
    pub value: f64,
}

/// Filled-polygon contour of a section (e.g. element faces on the slab's front
/// face coloured by sigma_zz) with a colour bar, plus optional overlay lines.
pub fn section_contour(
    path: &Path,
    title: &str,
    label: &str,
    patches: &[Patch],
    overlays: &[Vec<(f64, f64)>],
) -> Result<(), Error> {
    init_fonts();
    let root = BitMapBackend::new(path, (1100, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let (main, bar) = root.split_horizontally(950);
    let (x0, x1) = range(patches.iter().flat_map(|p| p.corners.iter().map(|c| c.0)), false);
    let (z0, z1) = range(patches.iter().flat_map(|p| p.corners.iter().map(|c| c.1)), false);
    let (v0, v1) = range(patches.iter().map(|p| p.value), false);
    let mut chart = ChartBuilder::on(&main)
        .caption(title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(55)
        .build_cartesian_2d(x0..x1, z0..z1)
        .map_err(|e| plot_err(path, e))?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("x (m)")
        .y_desc("z (m)")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let t = |v: f64| if v1 > v0 { (v - v0) / (v1 - v0) } else { 0.5 };
    chart
        .draw_series(patches.iter().map(|p| Polygon::new(p.corners.clone(), colormap(t(p.value)).filled())))
        .map_err(|e| plot_err(path, e))?;
    for line in overlays {
        chart.draw_series(LineSeries::new(line.clone(), BLACK.stroke_width(2))).map_err(|e| plot_err(path, e))?;
    }
    let mut cb = ChartBuilder::on(&bar)
        .margin_top(60)
        .margin_bottom(55)
        .margin_right(5)
        .y_label_area_size(85)
        .caption(label, ("sans-serif", 14))
        .build_cartesian_2d(0.0..1.0, v0..v1)
        .map_err(|e| plot_err(path, e))?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_label_formatter(&|v| format!("{:.3e}", snap_zero(*v, v1 - v0)))
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let n = 100;
    cb.draw_series((0..n).map(|k| {
        let (a, b) = (v0 + (v1 - v0) * k as f64 / n as f64, v0 + (v1 - v0) * (k + 1) as f64 / n as f64);
        Rectangle::new([(0.0, a), (1.0, b)], colormap((k as f64 + 0.5) / n as f64).filled())
    }))
    .map_err(|e| plot_err(path, e))?;
    root.present().map_err(|e| plot_err(path, e))
}

/// A tick within rounding of zero (plotters steps ticks by repeated addition,
/// so a zero crossing can land on 3e-18) is printed as 0.
fn snap_zero(v: f64, span: f64) -> f64 {
    if v.abs() <= 1e-9 * span.abs() {
        0.0
    } else {
        v
    }
}

#[cfg(test)]
mod tick_tests {
    use super::snap_zero;

    #[test]
    fn a_rounding_residue_tick_prints_as_zero() {
        assert_eq!(format!("{:.3e}", snap_zero(3.469e-18, 2.0e-3)), "0.000e0");
        assert_eq!(format!("{:.3e}", snap_zero(-1.0e-4, 2.0e-3)), "-1.000e-4");
    }
}
