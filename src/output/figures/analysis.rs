//! The figure of a scene's `[analysis]`, `analysis.png`, drawn as the paper's
//! Fig. 9: the section with the sliding mass and the arc above, K_i (eq. 22)
//! against x below, from the stresses and (with `interface`) the springs,
//! with the K = 1 and K = 0 lines, the sign segments in a strip and the
//! K_i < 1 zones shaded and lettered from the toe.

use std::path::Path;

use super::plot::{slip_profile, Patch, Series, SlipProfile, Span};
use super::section::{front_patches, front_patches_of_cells};
use crate::analysis::SurfacePoint;
use crate::drivers::analysis::Factors;
use crate::drivers::{AnalysisReport, FemRun, RunResult};
use crate::error::Error;

/// The window of K_i shown: K_i = R_i / D_i runs off where D_i changes sign.
const K_WINDOW: (f64, f64) = (-3.0, 6.0);

/// Runs of `K_i < 1` (true) and `K_i >= 1` along the points, as
/// `(weak, s0, s1)`, each point owning the interval halfway to its neighbours.
pub fn weak_zones(pts: &[SurfacePoint], k_i: &[f64]) -> Vec<(bool, f64, f64)> {
    let mut zones: Vec<(bool, f64, f64)> = Vec::new();
    for (i, p) in pts.iter().enumerate() {
        let weak = k_i[i] < 1.0;
        let edge = if i == 0 { p.s } else { 0.5 * (pts[i - 1].s + p.s) };
        match zones.last_mut() {
            Some(z) if z.0 == weak => z.2 = p.s,
            Some(z) => {
                z.2 = edge;
                zones.push((weak, edge, p.s));
            }
            None => zones.push((weak, edge, p.s)),
        }
    }
    zones
}

/// `analysis.png` of a CDEM run with `[analysis]`; false without one.
pub fn run_png(result: &RunResult, path: &Path) -> Result<bool, Error> {
    let Some(report) = &result.surface else { return Ok(false) };
    let m = &result.model;
    let section = front_patches(m, |e| in_mass(report, m.elements.corners(e).iter().map(|&i| m.x0[i as usize])));
    draw(report, &section, path)?;
    Ok(true)
}

/// `analysis.png` of a FEM solution with `[analysis]`; false without one.
pub fn fem_png(run: &FemRun, path: &Path) -> Result<bool, Error> {
    let Some(report) = &run.surface else { return Ok(false) };
    let sol = &run.solution;
    let section = front_patches_of_cells(&sol.coords, &sol.cells, |c| {
        in_mass(report, sol.cells[c].corners().iter().map(|&n| sol.coords[n]))
    });
    draw(report, &section, path)?;
    Ok(true)
}

/// 1 for a cell whose corners' centroid lies inside the circle (the sliding
/// mass), else 0.
fn in_mass(r: &AnalysisReport, corners: impl Iterator<Item = [f64; 3]>) -> f64 {
    let (mut x, mut z, mut n) = (0.0, 0.0, 0.0);
    for p in corners {
        (x, z, n) = (x + p[0], z + p[2], n + 1.0);
    }
    f64::from((x / n - r.arc.circle.xc).hypot(z / n - r.arc.circle.zc) < r.arc.circle.r)
}

fn draw(r: &AnalysisReport, section: &[Patch], path: &Path) -> Result<(), Error> {
    let x_of = |s: f64| r.arc.point_at(s)[0];
    let profile =
        |f: &Factors| -> Vec<(f64, f64)> { f.points.iter().zip(&f.k_i).map(|(p, &k)| (x_of(p.s), k)).collect() };
    let (ki_st, ki_sp) = (profile(&r.stresses), r.springs.as_ref().map(profile));
    // Segments and zones from the springs when there are, as the paper does.
    let main = r.springs.as_ref().unwrap_or(&r.stresses);
    let sign = |g: i8| if g > 0 { "+" } else { "-" };
    let strip: Vec<Span> = main
        .segments
        .iter()
        .map(|g| Span { x0: x_of(g.s0.max(0.0)), x1: x_of(g.s1), label: format!("sign {}", sign(g.sign)) })
        .collect();
    let zones = weak_zones(&main.points, &main.k_i);
    let (mut shaded, mut unshaded) = (Vec::new(), Vec::new());
    for (k, z) in zones.iter().enumerate() {
        let span = Span { x0: x_of(z.1), x1: x_of(z.2), label: ((b'a' + (k % 26) as u8) as char).to_string() };
        if z.0 {
            shaded.push(span);
        } else {
            unshaded.push(span);
        }
    }
    let arc: Vec<(f64, f64)> = (0..=100)
        .map(|k| {
            let p = r.arc.point_at(r.arc.length * k as f64 / 100.0);
            (p[0], p[1])
        })
        .collect();
    let mut series = vec![Series { name: "element stresses", points: &ki_st }];
    if let Some(sp) = &ki_sp {
        series.push(Series { name: "interface springs", points: sp });
    }
    let beyond = series.iter().flat_map(|s| s.points).filter(|p| p.1 < K_WINDOW.0 || p.1 > K_WINDOW.1).count();
    let springs_k = r.springs.as_ref().map_or(String::new(), |f| format!(", {:.3} (springs)", f.k));
    let lem = r.lem_fs.map_or(String::new(), |f| format!("; LEM Bishop FS of this circle {f:.3}"));
    let notes = vec![
        format!("Eq. 21: K = {:.3} (element stresses){springs_k}{lem}.", r.stresses.k),
        format!(
            "State: {}; strength: {}; circle ({}): centre ({:.2}, {:.2}) m, r {:.2} m, section y = {:.2} m.",
            r.state, r.strength_from, r.circle_from, r.arc.circle.xc, r.arc.circle.zc, r.arc.circle.r, r.arc.y
        ),
        format!("Shaded: K_i < 1 (zones lettered from the toe); {beyond} points beyond the window are drawn as triangles at its edge."),
    ];
    let fig = SlipProfile {
        title: "Safety factor K_i along the slip circle (eq. 19-22)",
        section,
        surface: &arc,
        y_label: "K_i (eq. 22)",
        series: &series,
        y_range: K_WINDOW,
        levels: &[(1.0, "K = 1"), (0.0, "K = 0")],
        strip: &strip,
        shaded: &shaded,
        unshaded: &unshaded,
        notes: &notes,
    };
    slip_profile(path, &fig)
}
