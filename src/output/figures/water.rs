//! The figure of a slope against its water table: the LEM's factor of
//! safety against the table's rise, with the CDEM runs' verdicts (slides or
//! stands within their step budget) at the rises they were run at,
//! `wulong-fs-by-water.png`.

use std::path::Path;

use plotters::prelude::*;

use super::plot::{init_fonts, plot_err};

/// Writes `path` (PNG): `lem` as `(rise, Bishop, Spencer)`, `cdem` as
/// `(rise, slid)`, both rises in m.
pub fn fs_by_rise(path: &Path, lem: &[(f64, f64, f64)], cdem: &[(f64, bool)]) -> crate::Result<()> {
    init_fonts();
    let rises = lem.iter().map(|p| p.0).chain(cdem.iter().map(|p| p.0));
    let (x0, x1) = rises.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    let fs = lem.iter().flat_map(|p| [p.1, p.2]).filter(|v| v.is_finite());
    let (y0, y1) = fs.fold((1.0_f64, 1.0_f64), |(a, b), v| (a.min(v), b.max(v)));
    let (pad_x, pad_y) = (0.04 * (x1 - x0).max(1.0), 0.08 * (y1 - y0).max(0.1));
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(path, e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption("Factor of safety against the water table's rise", ("sans-serif", 21))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((x0 - pad_x)..(x1 + pad_x), (y0 - pad_y)..(y1 + pad_y))
        .map_err(|e| plot_err(path, e))?;
    chart
        .configure_mesh()
        .x_desc("rise of the water table (m)")
        .y_desc("factor of safety")
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.2}"))
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    let one = vec![(x0 - pad_x, 1.0), (x1 + pad_x, 1.0)];
    chart.draw_series(LineSeries::new(one, BLACK.stroke_width(1))).map_err(|e| plot_err(path, e))?;
    for (k, (name, colour)) in
        [("LEM, Bishop (circular search)", RGBColor(31, 119, 180)), ("LEM, Spencer", RGBColor(255, 127, 14))]
            .into_iter()
            .enumerate()
    {
        let pts: Vec<(f64, f64)> =
            lem.iter().map(|p| (p.0, if k == 0 { p.1 } else { p.2 })).filter(|p| p.1.is_finite()).collect();
        chart
            .draw_series(LineSeries::new(pts.clone(), colour.stroke_width(2)))
            .map_err(|e| plot_err(path, e))?
            .label(name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
        chart.draw_series(pts.iter().map(|&p| Circle::new(p, 3, colour.filled()))).map_err(|e| plot_err(path, e))?;
    }
    // The CDEM verdicts sit on FS = 1: stands (hollow green) or slides (red).
    let (green, red) = (RGBColor(44, 160, 44), RGBColor(214, 39, 40));
    chart
        .draw_series(cdem.iter().filter(|p| !p.1).map(|p| Circle::new((p.0, 1.0), 7, green.stroke_width(3))))
        .map_err(|e| plot_err(path, e))?
        .label("CDEM: stands within its 30,000 steps")
        .legend(move |(x, y)| Circle::new((x + 10, y), 6, green.stroke_width(3)));
    chart
        .draw_series(cdem.iter().filter(|p| p.1).map(|p| Cross::new((p.0, 1.0), 8, red.stroke_width(3))))
        .map_err(|e| plot_err(path, e))?
        .label("CDEM: slides (a node moved more than 1 m)")
        .legend(move |(x, y)| Cross::new((x + 10, y), 6, red.stroke_width(3)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|e| plot_err(path, e))?;
    root.present().map_err(|e| plot_err(path, e))?;
    crate::output::commit(&tmp, path)
}
