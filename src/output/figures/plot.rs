//! Figures drawn with plotters into PNG files: no Python, no system fonts
//! (DejaVu Sans is embedded and registered once).
//!
//! - [`line_plot`]: series on linear or log axes;
//! - [`contour_panels`]: a section's elements coloured by a field, several
//!   panels on one colour scale ([`ColourScale`]: sequential from the zero
//!   end for a one-signed field, diverging and centred on zero for a signed
//!   one; banded on request), in kPa/MPa or mm ([`Quantity`]), with overlay
//!   lines (joints); [`section_contour`] is its one-panel form;
//! - [`slip_profile`]: Fig. 9, the section and slip surface above a profile
//!   along x on one canvas.

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

pub(crate) fn plot_err(path: &Path, e: impl std::fmt::Display) -> Error {
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
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (900, 600)).into_drawing_area();
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
                        // Only 1, 2 and 5 of each decade: every minor tick
                        // labelled runs the labels of a decade together.
                        let m = v / 10f64.powf(v.log10().floor());
                        if [1.0, 2.0, 5.0, 10.0].iter().any(|k| (m - k).abs() < 1e-6 * k) {
                            format!("{v:.0e}")
                        } else {
                            String::new()
                        }
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
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
}

/// Interpolates a list of RGB stops at `t` in [0, 1].
fn ramp(stops: &[(f64, f64, f64)], t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let x = t * (stops.len() - 1) as f64;
    let i = (x.floor() as usize).min(stops.len() - 2);
    let f = x - i as f64;
    let (a, b) = (stops[i], stops[i + 1]);
    let mix = |p: f64, q: f64| (p + f * (q - p)).round().clamp(0.0, 255.0) as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Diverging blue-white-red map of `t` in [0, 1] ("coolwarm"-like): 0.5 is
/// the neutral light grey, so a field centred on zero shows zero there.
pub fn colormap(t: f64) -> RGBColor {
    ramp(
        &[(59.0, 76.0, 192.0), (141.0, 176.0, 254.0), (240.0, 240.0, 240.0), (244.0, 154.0, 123.0), (180.0, 4.0, 38.0)],
        t,
    )
}

/// Sequential map of `t` in [0, 1] (viridis stops): light yellow at 0, dark
/// violet at 1, lightness falling monotonically.
pub fn sequential(t: f64) -> RGBColor {
    ramp(
        &[
            (253.0, 231.0, 37.0),
            (122.0, 209.0, 81.0),
            (34.0, 168.0, 132.0),
            (42.0, 120.0, 142.0),
            (65.0, 68.0, 135.0),
            (68.0, 1.0, 84.0),
        ],
        t,
    )
}

/// What a field is, for its display unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Quantity<'a> {
    /// A stress (Pa): shown in kPa, or MPa from 1 MPa up.
    Stress,
    /// A displacement (m): shown in mm.
    Displacement,
    /// Anything else, shown as given with this unit (may be empty).
    Plain(&'a str),
}

impl Quantity<'_> {
    /// `(factor, unit)`: the displayed value is `factor * SI value`.
    pub fn display(&self, max_abs: f64) -> (f64, String) {
        match self {
            Quantity::Stress if max_abs >= 1e6 => (1e-6, "MPa".into()),
            Quantity::Stress => (1e-3, "kPa".into()),
            Quantity::Displacement => (1e3, "mm".into()),
            Quantity::Plain(u) => (1.0, u.to_string()),
        }
    }
}

/// How a scalar field becomes a colour: a sequential map from the zero end
/// for a one-signed field (the largest magnitude darkest), a diverging map
/// centred on zero with a symmetric range for a field of both signs; with
/// `bands`, the colour is constant on that many equal bands (a banded
/// contour plot).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ColourScale {
    /// Displayed range (display units).
    pub lo: f64,
    pub hi: f64,
    pub diverging: bool,
    pub bands: Option<usize>,
}

impl ColourScale {
    /// The scale of displayed values `v`.
    pub fn of(values: impl Iterator<Item = f64>, bands: Option<usize>) -> Self {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.filter(|v| v.is_finite()) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        if !lo.is_finite() {
            return Self { lo: 0.0, hi: 1.0, diverging: false, bands };
        }
        let m = lo.abs().max(hi.abs());
        // Both signs, the lesser beyond 5 % of the greater: diverging,
        // symmetric about zero. Otherwise sequential from the zero end (a
        // few values of the other sign, e.g. a crest element in slight
        // tension, stay on the bar past zero).
        if lo < 0.0 && hi > 0.0 && lo.abs().min(hi) > 0.05 * m {
            let mut sc = Self { lo: -m, hi: m, diverging: true, bands };
            sc.round_bands();
            return sc;
        }
        let (lo, hi) = if hi <= 0.05 * m { (lo, hi.max(0.0)) } else { (lo.min(0.0), hi) };
        let (lo, hi) = if hi > lo { (lo, hi) } else { (lo - 0.5 * m.max(1e-30), hi + 0.5 * m.max(1e-30)) };
        let mut sc = Self { lo, hi, diverging: false, bands };
        sc.round_bands();
        sc
    }
    /// Banded: bands of a round width (1, 2, 2.5 or 5 x 10^k) about
    /// `bands` of them across the range, which is widened to whole bands
    /// (a diverging scale keeps zero on a band edge).
    fn round_bands(&mut self) {
        let Some(b) = self.bands.filter(|&b| b > 0) else { return };
        let raw = (self.hi - self.lo) / b as f64;
        let p = 10f64.powf(raw.log10().floor());
        let w =
            [1.0, 2.0, 2.5, 5.0, 10.0].into_iter().map(|m| m * p).find(|&w| w >= raw * (1.0 - 1e-12)).unwrap_or(raw);
        let (lo, hi) = ((self.lo / w + 1e-9).floor() * w, (self.hi / w - 1e-9).ceil() * w);
        let (lo, hi) = if self.diverging { (-(hi.max(-lo)), hi.max(-lo)) } else { (lo, hi) };
        self.lo = lo;
        self.hi = hi;
        self.bands = Some(((hi - lo) / w).round().max(1.0) as usize);
    }
    /// Position of `v` on the bar, 0 at `lo`, 1 at `hi`, snapped to the
    /// middle of its band when banded.
    pub fn position(&self, v: f64) -> f64 {
        let t = ((v - self.lo) / (self.hi - self.lo)).clamp(0.0, 1.0);
        match self.bands {
            Some(b) if b > 0 => ((t * b as f64).floor().min(b as f64 - 1.0) + 0.5) / b as f64,
            _ => t,
        }
    }
    pub fn colour(&self, v: f64) -> RGBColor {
        let t = self.position(v);
        if self.diverging {
            colormap(t)
        } else if self.hi.abs() < self.lo.abs() {
            // A non-positive field: zero (hi) light, the most negative dark.
            sequential(1.0 - t)
        } else {
            sequential(t)
        }
    }
}

/// A tick label for ticks about `span / 6` apart: no exponent, as few
/// decimals as the spacing needs, and rounding residue of zero as 0.
pub fn tick_label(v: f64, span: f64) -> String {
    let step = (span.abs() / 6.0).max(1e-300);
    let decimals = (-step.log10().floor()).clamp(0.0, 6.0) as usize;
    let s = format!("{:.*}", decimals, snap_zero(v, span));
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// A filled polygon of the section (x, z) with its value.
pub struct Patch {
    pub corners: Vec<(f64, f64)>,
    pub value: f64,
}

/// A polyline drawn over a contour panel.
pub struct Line {
    pub points: Vec<(f64, f64)>,
    pub colour: RGBColor,
    pub width: u32,
}

impl Line {
    pub fn black(points: Vec<(f64, f64)>) -> Self {
        Self { points, colour: BLACK, width: 2 }
    }
}

/// One panel of a contour figure: its patches (SI values), its overlay
/// lines and its title.
pub struct Panel {
    pub title: String,
    pub patches: Vec<Patch>,
    pub lines: Vec<Line>,
}

/// Options of a contour figure.
#[derive(Debug, Clone, Default)]
pub struct ContourStyle {
    /// Constant colour on this many bands (None: continuous).
    pub bands: Option<usize>,
    /// Panels per row (0 or 1: one column).
    pub columns: usize,
    /// Width of each panel (px; 0: 950).
    pub panel_width: u32,
    /// Lines of text under the panels (a legend for the overlays).
    pub notes: Vec<String>,
    /// Draw the patches' edges (thin grey).
    pub edges: bool,
    /// The vertical axis of each panel, by panel (absent: "z (m)").
    pub y_desc: Vec<String>,
}

/// Filled-polygon contour of a section (e.g. element faces on the slab's front
/// face coloured by sigma_zz) with a colour bar, plus optional overlay lines.
/// The colour map follows the data ([`ColourScale`]), the values are shown as
/// given (`label` names them).
pub fn section_contour(
    path: &Path,
    title: &str,
    label: &str,
    patches: &[Patch],
    overlays: &[Vec<(f64, f64)>],
) -> Result<(), Error> {
    let panel = Panel {
        title: title.to_string(),
        patches: patches.iter().map(|p| Patch { corners: p.corners.clone(), value: p.value }).collect(),
        lines: overlays.iter().map(|l| Line::black(l.clone())).collect(),
    };
    contour_panels(path, "", label, Quantity::Plain(""), &[panel], &ContourStyle::default())
}

/// Contour panels of one field on one colour scale, with one colour bar:
/// `quantity` sets the display unit (kPa/MPa, mm), `label` names the field
/// on the bar (the unit is appended), `title` heads the figure.
pub fn contour_panels(
    path: &Path,
    title: &str,
    label: &str,
    quantity: Quantity,
    panels: &[Panel],
    style: &ContourStyle,
) -> Result<(), Error> {
    init_fonts();
    let max_abs = panels.iter().flat_map(|p| p.patches.iter().map(|q| q.value.abs())).filter(|v| v.is_finite());
    let (factor, unit) = quantity.display(max_abs.fold(0.0, f64::max));
    let scale = ColourScale::of(panels.iter().flat_map(|p| p.patches.iter().map(|q| q.value * factor)), style.bands);
    let all = || panels.iter().flat_map(|p| p.patches.iter().flat_map(|q| q.corners.iter()));
    let (x0, x1) = range(all().map(|c| c.0), false);
    let (z0, z1) = range(all().map(|c| c.1), false);
    // Panel size from the section's aspect ratio (equal scales on x and z).
    let cols = style.columns.max(1).min(panels.len().max(1));
    let rows = panels.len().div_ceil(cols).max(1);
    let pw = if style.panel_width == 0 { 950 } else { style.panel_width };
    let plot_w = pw as f64 - 75.0;
    let ph = ((plot_w * (z1 - z0) / (x1 - x0)) + 85.0).clamp(250.0, 1200.0) as u32;
    let head = if title.is_empty() { 0 } else { 45 };
    let foot = 10 + 24 * style.notes.len() as u32;
    let bar_w = 200;
    let (w, h) = (pw * cols as u32 + bar_w, head + ph * rows as u32 + foot);
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (w, h)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let (top, rest) = root.split_vertically(head);
    if head > 0 {
        top.titled(title, ("sans-serif", 24)).map_err(|e| plot_err(path, e))?;
    }
    let (body, foot_area) = rest.split_vertically(ph * rows as u32);
    let (grid, bar) = body.split_horizontally(pw * cols as u32);
    for (k, (area, panel)) in grid.split_evenly((rows, cols)).iter().zip(panels).enumerate() {
        let y_desc = style.y_desc.get(k).map_or("z (m)", String::as_str);
        let mut chart = ChartBuilder::on(area)
            .caption(&panel.title, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(45)
            .build_cartesian_2d(x0..x1, z0..z1)
            .map_err(|e| plot_err(path, e))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x (m)")
            .y_desc(y_desc)
            .x_label_formatter(&|v| tick_label(*v, x1 - x0))
            .y_label_formatter(&|v| tick_label(*v, z1 - z0))
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| plot_err(path, e))?;
        chart
            .draw_series(
                panel.patches.iter().map(|p| Polygon::new(p.corners.clone(), scale.colour(p.value * factor).filled())),
            )
            .map_err(|e| plot_err(path, e))?;
        if style.edges {
            let grey = RGBColor(120, 120, 120).mix(0.5);
            chart
                .draw_series(panel.patches.iter().map(|p| {
                    PathElement::new(p.corners.iter().chain(p.corners.first()).copied().collect::<Vec<_>>(), grey)
                }))
                .map_err(|e| plot_err(path, e))?;
        }
        for line in &panel.lines {
            chart
                .draw_series(LineSeries::new(line.points.clone(), line.colour.stroke_width(line.width)))
                .map_err(|e| plot_err(path, e))?;
        }
    }
    let bar_label = if unit.is_empty() { label.to_string() } else { format!("{label} ({unit})") };
    colour_bar(path, &bar, &bar_label, &scale)?;
    for (i, note) in style.notes.iter().enumerate() {
        foot_area
            .draw(&Text::new(note.clone(), (20, 4 + 24 * i as i32), ("sans-serif", 16).into_font()))
            .map_err(|e| plot_err(path, e))?;
    }
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
}

/// The colour bar of `scale` in `area`, with `label` above it.
fn colour_bar<DB: DrawingBackend>(
    path: &Path,
    area: &DrawingArea<DB, plotters::coord::Shift>,
    label: &str,
    scale: &ColourScale,
) -> Result<(), Error>
where
    DB::ErrorType: 'static,
{
    let (v0, v1) = (scale.lo, scale.hi);
    let mut cb = ChartBuilder::on(area)
        .margin_top(50)
        .margin_bottom(55)
        .margin_right(10)
        .margin_left(5)
        .y_label_area_size(75)
        .caption(label, ("sans-serif", 15))
        .build_cartesian_2d(0.0..1.0, v0..v1)
        .map_err(|e| plot_err(path, e))?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_label_formatter(&|v| tick_label(*v, v1 - v0))
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let n = scale.bands.unwrap_or(200).max(1);
    cb.draw_series((0..n).map(|k| {
        let (a, b) = (v0 + (v1 - v0) * k as f64 / n as f64, v0 + (v1 - v0) * (k + 1) as f64 / n as f64);
        Rectangle::new([(0.0, a), (1.0, b)], scale.colour(0.5 * (a + b)).filled())
    }))
    .map_err(|e| plot_err(path, e))?;
    Ok(())
}

/// An x interval of a profile, labelled.
#[derive(Debug, Clone)]
pub struct Span {
    pub x0: f64,
    pub x1: f64,
    pub label: String,
}

/// Fig. 9 as the paper draws it: the section with the slip surface above,
/// a profile along x below, on one canvas with a common x axis.
pub struct SlipProfile<'a> {
    pub title: &'a str,
    /// The section's elements, value 1 inside the sliding mass, 0 outside.
    pub section: &'a [Patch],
    /// The slip surface (x, z), toe to crest.
    pub surface: &'a [(f64, f64)],
    /// The profile's y label and series (x, y).
    pub y_label: &'a str,
    pub series: &'a [Series<'a>],
    /// The y range shown; points outside it are drawn as triangles at its edge.
    pub y_range: (f64, f64),
    /// Horizontal lines (y, label), e.g. K = 1 and K = 0.
    pub levels: &'a [(f64, &'a str)],
    /// Labelled intervals in a strip at the top of the profile (sign segments).
    pub strip: &'a [Span],
    /// Intervals shaded over the whole profile and lettered on the section
    /// (e.g. K_i < 1 zones).
    pub shaded: &'a [Span],
    /// Labelled intervals that are not shaded (the other zones).
    pub unshaded: &'a [Span],
    /// Lines of text under the profile.
    pub notes: &'a [String],
}

/// Draws a [`SlipProfile`] to a PNG.
pub fn slip_profile(path: &Path, fig: &SlipProfile) -> Result<(), Error> {
    init_fonts();
    let all = || fig.section.iter().flat_map(|p| p.corners.iter());
    let (x0, x1) = range(all().map(|c| c.0), false);
    let (z0, z1) = range(all().map(|c| c.1), false);
    let (w, margin, y_area) = (1150u32, 15u32, 70u32);
    let plot_w = (w - 2 * margin - y_area) as f64;
    let top_h = (plot_w * (z1 - z0) / (x1 - x0)) as u32 + 30 + 40 + margin;
    let (bottom_h, foot_h) = (520u32, 12 + 24 * fig.notes.len() as u32);
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (w, 50 + top_h + bottom_h + foot_h)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let (head, rest) = root.split_vertically(50);
    head.titled(fig.title, ("sans-serif", 24)).map_err(|e| plot_err(path, e))?;
    let (top, rest) = rest.split_vertically(top_h);
    let (bottom, foot) = rest.split_vertically(bottom_h);
    let mass = RGBColor(222, 184, 135);
    let ground = RGBColor(225, 225, 225);
    let weak = RGBColor(255, 205, 205);

    // The section and the slip surface.
    let mut sec = ChartBuilder::on(&top)
        .caption("Section and slip surface", ("sans-serif", 18))
        .margin(margin)
        .x_label_area_size(40)
        .y_label_area_size(y_area)
        .build_cartesian_2d(x0..x1, z0..z1)
        .map_err(|e| plot_err(path, e))?;
    sec.configure_mesh()
        .disable_mesh()
        .x_desc("x (m)")
        .y_desc("z (m)")
        .x_label_formatter(&|v| tick_label(*v, x1 - x0))
        .y_label_formatter(&|v| tick_label(*v, z1 - z0))
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    sec.draw_series(
        fig.section.iter().map(|p| Polygon::new(p.corners.clone(), if p.value > 0.5 { mass } else { ground }.filled())),
    )
    .map_err(|e| plot_err(path, e))?;
    let edge = RGBColor(150, 150, 150);
    sec.draw_series(
        fig.section
            .iter()
            .map(|p| PathElement::new(p.corners.iter().chain(p.corners.first()).copied().collect::<Vec<_>>(), edge)),
    )
    .map_err(|e| plot_err(path, e))?;
    sec.draw_series(LineSeries::new(fig.surface.iter().copied(), RED.stroke_width(3)))
        .map_err(|e| plot_err(path, e))?;
    // Zone letters on the surface, just below it, and their boundaries.
    let z_at = |x: f64| -> Option<f64> {
        fig.surface.windows(2).find(|w| (w[0].0 - x) * (w[1].0 - x) <= 0.0).map(|w| {
            let f = if w[1].0 != w[0].0 { (x - w[0].0) / (w[1].0 - w[0].0) } else { 0.0 };
            w[0].1 + f * (w[1].1 - w[0].1)
        })
    };
    for span in fig.shaded.iter().chain(fig.unshaded) {
        let xm = 0.5 * (span.x0 + span.x1);
        if let Some(z) = z_at(xm) {
            sec.draw_series(std::iter::once(Text::new(
                span.label.clone(),
                (xm, z - 0.04 * (z1 - z0)),
                ("sans-serif", 20).into_font().style(FontStyle::Bold),
            )))
            .map_err(|e| plot_err(path, e))?;
        }
        for x in [span.x0, span.x1] {
            if let Some(z) = z_at(x) {
                sec.draw_series(std::iter::once(Circle::new((x, z), 4, BLACK.filled())))
                    .map_err(|e| plot_err(path, e))?;
            }
        }
    }

    // The profile.
    let (y0, y1) = fig.y_range;
    let mut prof = ChartBuilder::on(&bottom)
        .margin(margin)
        .x_label_area_size(40)
        .y_label_area_size(y_area)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| plot_err(path, e))?;
    prof.configure_mesh()
        .x_desc("x (m)")
        .y_desc(fig.y_label)
        .x_label_formatter(&|v| tick_label(*v, x1 - x0))
        .y_label_formatter(&|v| tick_label(*v, y1 - y0))
        .light_line_style(WHITE)
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let strip_lo = y1 - 0.08 * (y1 - y0);
    prof.draw_series(fig.shaded.iter().map(|s| Rectangle::new([(s.x0, y0), (s.x1, strip_lo)], weak.filled())))
        .map_err(|e| plot_err(path, e))?;
    for span in fig.shaded.iter().chain(fig.unshaded) {
        prof.draw_series(std::iter::once(Text::new(
            span.label.clone(),
            (0.5 * (span.x0 + span.x1), strip_lo - 0.02 * (y1 - y0)),
            ("sans-serif", 18).into_font().style(FontStyle::Bold),
        )))
        .map_err(|e| plot_err(path, e))?;
    }
    for (k, span) in fig.strip.iter().enumerate() {
        let c = if k % 2 == 0 { RGBColor(200, 215, 240) } else { RGBColor(240, 225, 190) };
        prof.draw_series(std::iter::once(Rectangle::new([(span.x0, strip_lo), (span.x1, y1)], c.filled())))
            .map_err(|e| plot_err(path, e))?;
        prof.draw_series(std::iter::once(Text::new(
            span.label.clone(),
            (span.x0 + 0.005 * (x1 - x0), y1 - 0.015 * (y1 - y0)),
            ("sans-serif", 14).into_font(),
        )))
        .map_err(|e| plot_err(path, e))?;
    }
    for &(y, label) in fig.levels {
        let c = if y == 0.0 { BLACK } else { RED };
        prof.draw_series(LineSeries::new([(x0, y), (x1, y)], c.stroke_width(2))).map_err(|e| plot_err(path, e))?;
        prof.draw_series(std::iter::once(Text::new(
            label.to_string(),
            (x1 - 0.06 * (x1 - x0), y + 0.045 * (y1 - y0)),
            ("sans-serif", 15).into_font().color(&c),
        )))
        .map_err(|e| plot_err(path, e))?;
    }
    for (k, s) in fig.series.iter().enumerate() {
        let c = PALETTE[k % PALETTE.len()];
        let inside: Vec<(f64, f64)> = s.points.iter().copied().filter(|p| p.1 >= y0 && p.1 <= strip_lo).collect();
        let clipped: Vec<(f64, f64)> = s.points.iter().map(|&(x, y)| (x, y.clamp(y0, strip_lo))).collect();
        prof.draw_series(LineSeries::new(clipped.clone(), c.mix(0.6).stroke_width(1)))
            .map_err(|e| plot_err(path, e))?
            .label(s.name)
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.filled()));
        prof.draw_series(inside.iter().map(|&p| Circle::new(p, 3, c.filled()))).map_err(|e| plot_err(path, e))?;
        prof.draw_series(
            clipped
                .iter()
                .zip(s.points)
                .filter(|(q, p)| q.1 != p.1)
                .map(|(&q, _)| TriangleMarker::new(q, 6, c.filled())),
        )
        .map_err(|e| plot_err(path, e))?;
    }
    prof.configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    for (i, note) in fig.notes.iter().enumerate() {
        foot.draw(&Text::new(note.clone(), (20, 4 + 24 * i as i32), ("sans-serif", 16).into_font()))
            .map_err(|e| plot_err(path, e))?;
    }
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
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

    #[test]
    fn tick_labels_carry_the_decimals_their_spacing_needs() {
        use super::tick_label;
        assert_eq!(tick_label(-800.0, 800.0), "-800");
        assert_eq!(tick_label(20.0, 42.0), "20");
        assert_eq!(tick_label(-12.5, 4.2), "-12.5");
        assert_eq!(tick_label(0.2, 1.0), "0.2");
        assert_eq!(tick_label(-3.0e-17, 1.0), "0.0");
    }

    #[test]
    fn one_signed_fields_get_a_sequential_map_and_signed_ones_a_diverging_map_centred_on_zero() {
        use super::ColourScale;
        let neg = ColourScale::of([-780.0, -400.0, -5.0].into_iter(), None);
        assert!(!neg.diverging);
        assert_eq!((neg.lo, neg.hi), (-780.0, 0.0));
        // A little tension (under 5 %) keeps the map sequential.
        let nearly = ColourScale::of([-780.0, 30.0].into_iter(), Some(10));
        assert!(!nearly.diverging);
        assert_eq!((nearly.lo, nearly.hi, nearly.bands), (-800.0, 100.0, Some(9)));
        // The most compressive is the dark end, zero the light end.
        let lum = |c: plotters::style::RGBColor| 0.3 * c.0 as f64 + 0.59 * c.1 as f64 + 0.11 * c.2 as f64;
        assert!(lum(neg.colour(-780.0)) < lum(neg.colour(0.0)));
        let signed = ColourScale::of([-2.0, 0.5, 1.0].into_iter(), Some(9));
        assert!(signed.diverging);
        // Bands 0.5 wide from -2 to 2: zero on a band edge.
        assert_eq!((signed.lo, signed.hi, signed.bands), (-2.0, 2.0, Some(8)));
        assert_eq!(signed.position(0.0), 0.5625);
        assert_eq!(signed.position(-1e-9), 0.4375);
    }
}
