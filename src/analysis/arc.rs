//! A circular slip surface that need not follow the mesh: the arc of a
//! circle in the x-z section at `y` that lies inside the model, from the toe
//! to the crest, sampled at stations; each station takes the stress of the
//! cell that contains it ([`CellLocator`]), so eq. 19-22 run on any circle
//! of any mesh (CDEM element stresses and FEM cell stresses alike).
//!
//! The arc is the run of the circle inside the model that contains its lowest
//! point (or, if that point is outside, the longest run),
//! its two ends found by bisection on the model's boundary. The toe is the
//! lower end; the mass slides toward it. Each station represents the arc
//! length `ds` between its neighbours' midpoints per metre of width
//! (`area = ds x 1 m`).

use super::safety::{traction_from_stress, SurfacePoint};
use super::slip::SlipCircle;
use crate::geometry::Circle;
use crate::mesh::locate::CellLocator;

/// The arc of a circle inside the model's section.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Arc {
    /// The circle; its `xc`, `zc`, `r` are keys of this table in the JSON.
    #[serde(flatten)]
    pub circle: Circle,
    /// The section plane.
    pub y: f64,
    /// The toe (exit) end `[x, z]`.
    pub toe: [f64; 2],
    /// The crest (entry) end `[x, z]`.
    pub crest: [f64; 2],
    /// Arc length from the toe to the crest (m).
    pub length: f64,
    #[serde(skip)]
    a_toe: f64,
    #[serde(skip)]
    a_crest: f64,
}

/// A sample point of an [`Arc`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Station {
    /// Arc length from the toe (m).
    pub s: f64,
    /// Position (m).
    pub x: [f64; 3],
    /// Arc length it represents (m).
    pub ds: f64,
    /// The cell that contains it.
    pub cell: usize,
}

/// Angular samples of the full circle used to find the arc.
const SAMPLES: usize = 3600;

/// The point at polar angle `a` of `circle` in the plane `y`.
fn on_circle(circle: &Circle, y: f64, a: f64) -> [f64; 3] {
    let [x, z] = circle.at(a);
    [x, y, z]
}

impl Arc {
    /// The arc of `circle` in the plane `y` inside the cells of `locator`;
    /// the error says why there is none.
    pub fn find(locator: &CellLocator, circle: Circle, y: f64) -> Result<Self, String> {
        let at = |a: f64| on_circle(&circle, y, a);
        let inside = |a: f64| locator.locate(at(a)).is_some();
        let bottom = -std::f64::consts::FRAC_PI_2;
        let angle = |k: usize| bottom + std::f64::consts::TAU * k as f64 / SAMPLES as f64;
        let flags: Vec<bool> = (0..SAMPLES).map(|k| inside(angle(k))).collect();
        if flags.iter().all(|&f| !f) {
            return Err(format!("the circle does not cut the model's section at y = {y} m"));
        }
        if flags.iter().all(|&f| f) {
            return Err("the circle lies wholly inside the model: it does not reach the ground".into());
        }
        // Runs of inside samples as (first, count), cyclic.
        let first_out = flags.iter().position(|&f| !f).expect("some sample is outside");
        let mut runs: Vec<(usize, usize)> = Vec::new();
        for j in 0..SAMPLES {
            let k = (first_out + j) % SAMPLES;
            if !flags[k] {
                continue;
            }
            match runs.last_mut() {
                Some((s, n)) if (*s + *n) % SAMPLES == k => *n += 1,
                _ => runs.push((k, 1)),
            }
        }
        let contains_bottom = |&(s, n): &(usize, usize)| (0..n).any(|j| (s + j) % SAMPLES == 0);
        let run = runs
            .iter()
            .find(|r| contains_bottom(r))
            .or_else(|| runs.iter().max_by_key(|r| r.1))
            .copied()
            .expect("some sample is inside");
        if run.1 < 2 {
            return Err("the circle only grazes the model".into());
        }
        // Unwrapped angles of the run's first and last inside samples.
        let a_first = angle(run.0);
        let a_last = a_first + std::f64::consts::TAU * (run.1 - 1) as f64 / SAMPLES as f64;
        let step = std::f64::consts::TAU / SAMPLES as f64;
        let edge = |mut a_in: f64, mut a_out: f64| {
            for _ in 0..50 {
                let m = 0.5 * (a_in + a_out);
                if inside(m) {
                    a_in = m;
                } else {
                    a_out = m;
                }
            }
            a_in
        };
        let (a0, a1) = (edge(a_first, a_first - step), edge(a_last, a_last + step));
        let (p0, p1) = (at(a0), at(a1));
        let (a_toe, a_crest) = if p0[2] <= p1[2] { (a0, a1) } else { (a1, a0) };
        let (t, c) = (at(a_toe), at(a_crest));
        Ok(Self {
            circle,
            y,
            toe: [t[0], t[2]],
            crest: [c[0], c[2]],
            length: circle.r * (a_crest - a_toe).abs(),
            a_toe,
            a_crest,
        })
    }

    /// The circle with its toe, for the normal and the sliding direction.
    pub fn slip_circle(&self) -> SlipCircle {
        SlipCircle { circle: self.circle, toe: self.toe, clockwise: self.a_crest > self.a_toe }
    }

    /// The point `[x, z]` at arc length `s` from the toe.
    pub fn point_at(&self, s: f64) -> [f64; 2] {
        let a = self.a_toe + (self.a_crest - self.a_toe).signum() * s / self.circle.r;
        let p = on_circle(&self.circle, self.y, a);
        [p[0], p[2]]
    }

    /// `n` stations at the midpoints of equal arc intervals, toe to crest,
    /// each with its cell; a station no cell contains (a gap in the mesh) is
    /// left out.
    pub fn stations(&self, locator: &CellLocator, n: usize) -> Vec<Station> {
        let da = (self.a_crest - self.a_toe) / n as f64;
        (0..n)
            .filter_map(|k| {
                let a = self.a_toe + (k as f64 + 0.5) * da;
                let x = on_circle(&self.circle, self.y, a);
                let s = self.circle.r * (a - self.a_toe).abs();
                locator.locate(x).map(|cell| Station { s, x, ds: self.circle.r * da.abs(), cell })
            })
            .collect()
    }
}

/// Traction at each station from the stress of its cell (`stress[c]`, Pa),
/// per metre of width.
pub fn from_cell_stresses(arc: &Arc, stations: &[Station], stress: &[[f64; 6]]) -> Vec<SurfacePoint> {
    let circle = arc.slip_circle();
    stations
        .iter()
        .map(|st| {
            let (_, n, t) = circle.frame(st.x);
            let (sigma_n, tau) = traction_from_stress(stress[st.cell], n, t);
            SurfacePoint { s: st.s, area: st.ds, sigma_n, tau }
        })
        .collect()
}

/// The mean arc length per cell crossed (m): the arc length over the number
/// of runs of consecutive stations in one cell; the default minimum length
/// of a sign segment.
pub fn length_per_cell(arc: &Arc, stations: &[Station]) -> f64 {
    let runs = 1 + stations.windows(2).filter(|w| w[0].cell != w[1].cell).count();
    arc.length / runs as f64
}
