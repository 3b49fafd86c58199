//! The kinematic analysis's stereonet (`cdem kinematics`): lower hemisphere,
//! equal area, north up, as Rocscience Dips draws it: the slope face's great
//! circle (thick black), the friction circle of the wedge test (the lines
//! plunging phi, dashed red) and the daylight envelope (the face's great
//! circle bounds the lines that daylight: the critical zone for wedges lies
//! between it and the friction circle, shaded), each set's great circle and
//! pole (coloured, labelled), and the sets' lines of intersection (crosses,
//! red where the pair passes the wedge test); for plane sliding, the poles'
//! friction cone and daylight envelope (dotted grey).

use std::path::Path;

use plotters::prelude::*;

use super::plot::{init_fonts, plot_err};
use crate::analysis::kinematics::{equal_area, great_circle, small_circle, Line, Orientation, PairTest};
use crate::error::Error;

const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
];

/// The stereonet of `sets` (their labels) on `face`, with the friction circle
/// at `friction` (deg) and the pairs' intersections, to a PNG.
pub fn stereonet(
    path: &Path,
    face: Orientation,
    sets: &[(String, Orientation)],
    friction: f64,
    pairs: &[PairTest],
) -> Result<(), Error> {
    init_fonts();
    let e = |e| plot_err(path, e);
    let tmp = crate::atomic::partial_path(path);
    let root = BitMapBackend::new(&tmp, (900, 980)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let (title, body) = root.split_vertically(80);
    title
        .draw(&Text::new(
            format!(
                "lower hemisphere, equal area; face {:.0}/{:03.0}, friction {:.0} deg",
                face.dip, face.dip_direction, friction
            ),
            (20, 15),
            ("sans-serif", 24).into_font(),
        ))
        .map_err(e)?;
    title
        .draw(&Text::new(
            "black: face; red dashed: friction circle; shaded: wedge critical zone; x: intersections;",
            (20, 46),
            ("sans-serif", 16).into_font(),
        ))
        .map_err(e)?;
    title
        .draw(&Text::new(
            "dots: poles; grey dotted: the poles' friction cone and daylight envelope (plane sliding)",
            (20, 64),
            ("sans-serif", 16).into_font(),
        ))
        .map_err(e)?;
    let mut chart = ChartBuilder::on(&body).margin(30).build_cartesian_2d(-1.12..1.12, -1.12..1.12).map_err(e)?;
    // The primitive circle and the cardinal ticks.
    chart.draw_series(std::iter::once(PathElement::new(small_circle(0.0, 360), BLACK.stroke_width(2)))).map_err(e)?;
    for (label, t) in [("N", 0.0), ("E", 90.0), ("S", 180.0), ("W", 270.0)] {
        let (x, y) = equal_area(Line { plunge: 0.0, trend: t });
        chart
            .draw_series(std::iter::once(PathElement::new(vec![(x, y), (1.04 * x, 1.04 * y)], BLACK.stroke_width(2))))
            .map_err(e)?;
        chart
            .draw_series(std::iter::once(Text::new(
                label.to_string(),
                (1.08 * x - 0.02, 1.08 * y + 0.03),
                ("sans-serif", 22).into_font(),
            )))
            .map_err(e)?;
    }
    // The wedge critical zone: lines that daylight (outside the face's great
    // circle, on the face side) and plunge more than phi (inside the friction
    // circle): sampled on a polar grid.
    let mut zone = Vec::new();
    for it in 0..180 {
        let trend = face.dip_direction - 90.0 + it as f64;
        let app = face.apparent_dip(trend);
        if app <= friction {
            continue;
        }
        for ip in 0..60 {
            let plunge = friction + (app - friction) * (ip as f64 + 0.5) / 60.0;
            zone.push(equal_area(Line { plunge, trend }));
        }
    }
    chart.draw_series(zone.iter().map(|&p| Circle::new(p, 2, RGBColor(255, 200, 200).filled()))).map_err(e)?;
    // The friction circle, dashed.
    let fc = small_circle(friction, 180);
    chart
        .draw_series(
            fc.chunks(2).step_by(2).map(|c| PathElement::new(c.to_vec(), RGBColor(214, 39, 40).stroke_width(2))),
        )
        .map_err(e)?;
    // For planar sliding, on the poles: the friction cone (poles of planes
    // dipping phi: plunge 90 - phi) and the daylight envelope (poles of the
    // planes dipping at the face's apparent dip in their dip direction),
    // dotted grey; a plane can slide when its pole lies inside the envelope and
    // outside the cone.
    let grey = RGBColor(110, 110, 110);
    let cone = small_circle(90.0 - friction, 180);
    chart.draw_series(cone.iter().step_by(3).map(|&p| Circle::new(p, 2, grey.filled()))).map_err(e)?;
    let envelope: Vec<(f64, f64)> = (0..=180)
        .filter_map(|k| {
            let t = face.dip_direction - 90.0 + k as f64;
            let app = face.apparent_dip(t);
            (app > 0.0).then(|| equal_area(Line { plunge: 90.0 - app, trend: t + 180.0 }))
        })
        .collect();
    chart.draw_series(envelope.iter().step_by(2).map(|&p| Circle::new(p, 2, grey.filled()))).map_err(e)?;
    // The face.
    chart.draw_series(std::iter::once(PathElement::new(great_circle(face, 180), BLACK.stroke_width(3)))).map_err(e)?;
    // The sets.
    for (k, (label, o)) in sets.iter().enumerate() {
        let c = COLOURS[k % COLOURS.len()];
        chart.draw_series(std::iter::once(PathElement::new(great_circle(*o, 180), c.stroke_width(2)))).map_err(e)?;
        let p = equal_area(o.pole());
        chart.draw_series(std::iter::once(Circle::new(p, 7, c.filled()))).map_err(e)?;
        // Labels above right of the pole, or below left of it near the east rim.
        let at = if p.0 > 0.55 { (p.0 - 0.42, p.1 - 0.03) } else { (p.0 + 0.03, p.1 + 0.06) };
        chart
            .draw_series(std::iter::once(Text::new(
                format!("{label} {:.0}/{:03.0}", o.dip, o.dip_direction),
                at,
                ("sans-serif", 18).into_font().color(&c),
            )))
            .map_err(e)?;
    }
    for pr in pairs {
        let Some(l) = pr.intersection else { continue };
        let (x, y) = equal_area(l);
        let style = if pr.wedge_sliding { RGBColor(214, 39, 40).stroke_width(4) } else { BLACK.stroke_width(2) };
        let d = 0.025;
        chart.draw_series(std::iter::once(PathElement::new(vec![(x - d, y - d), (x + d, y + d)], style))).map_err(e)?;
        chart.draw_series(std::iter::once(PathElement::new(vec![(x - d, y + d), (x + d, y - d)], style))).map_err(e)?;
        chart
            .draw_series(std::iter::once(Text::new(
                format!("I{}{} {:.0}->{:03.0}", pr.sets.0 + 1, pr.sets.1 + 1, l.plunge.abs(), l.trend),
                (x + 0.03, y - 0.02),
                ("sans-serif", 16).into_font(),
            )))
            .map_err(e)?;
    }
    root.present().map_err(e)?;
    crate::output::commit(&tmp, path)
}
