//! Circular slip-surface search (internal frame: the section faces -x).
//!
//! 1. **Grid and radius**: centres on an `nx x nz` grid; at each centre,
//!    `radii` radii evenly spaced from the distance to the nearest ground
//!    point (exclusive) to the distance to the lower bound (inclusive: the
//!    circle tangent to the lower bound is tried).
//! 2. **Entry-exit**: circles through an exit point (toe side) and an entry
//!    point (crest side) on the ground, `radii` sagittas per pair.
//! 3. **Refinement**: for each method, Nelder-Mead on `(xc, zc, r)` from the
//!    method's best grid circle and its best entry-exit circle (initial steps
//!    `0.05 H`, then one restart with `0.01 H`), inadmissible circles scoring
//!    +inf.
//!
//! A circle is admissible if its lower arc bounds a closed sliding mass with
//! the ground (the arc ends above the ground on the crest side; two crossings,
//! or with more, the crest-side run of the arc under the ground, which must
//! not reach the section's toe-side end), whose arc from exit to entry stays
//! above the lower bound, drives the mass toward -x (`sum W sin(alpha) > 0`),
//! and is not a sliver: the deepest slice's mean height is at least
//! `min_depth` (default `0.02 H`) and the entry-exit width at least
//! `min_width` (default `0.1 H`).
//!
//! Determinism: every circle has a fixed key (its place in the grid or the
//! entry-exit list); the best circle is the least `(FS, key)`, so the result
//! does not depend on rayon's thread count or scheduling. Each worker owns
//! one [`Slices`] buffer: no allocation per circle.

use rayon::prelude::*;

use super::geometry::{fill_slices, Limits, Reject, Slices};
use super::input::{EntryExitSpec, GridSpec, LemInput, SearchSpec};
use super::methods::{bishop, ordinary, spencer};
use super::section::{polyline_z, Frame, LowerBound};
use super::{Circle, CriticalCircle, LemResult, Method, PerMethod};
use crate::error::SceneError;

/// Which method results a circle's evaluation needs.
#[derive(Clone, Copy)]
struct Want([bool; 3]);

struct Evaluator<'a> {
    f: &'a Frame,
    n: usize,
    lim: Limits,
}

impl Evaluator<'_> {
    /// FS per method (+inf where not wanted or no solution); theta for Spencer.
    fn fs(&self, c: Circle, want: Want, s: &mut Slices) -> Result<([f64; 3], f64), Reject> {
        fill_slices(self.f, c, self.n, self.lim, s)?;
        let mut out = [f64::INFINITY; 3];
        let mut theta = f64::NAN;
        let o = ordinary(s);
        if want.0[0] {
            out[0] = o.unwrap_or(f64::INFINITY);
        }
        if want.0[1] || want.0[2] {
            let b = o.and_then(|o| bishop(s, o));
            if want.0[1] {
                out[1] = b.unwrap_or(f64::INFINITY);
            }
            if want.0[2] {
                if let Some((fs, t)) = b.and_then(|b| spencer(s, b)) {
                    (out[2], theta) = (fs, t);
                }
            }
        }
        Ok((out, theta))
    }
}

#[derive(Clone, Copy, Debug)]
struct Best {
    fs: f64,
    key: u64,
    circle: Circle,
}

fn better(a: Option<Best>, b: Option<Best>) -> Option<Best> {
    match (a, b) {
        (Some(x), Some(y)) => Some(if (y.fs, y.key) < (x.fs, x.key) { y } else { x }),
        (x, None) => x,
        (None, y) => y,
    }
}

/// Per family (0 grid, 1 entry-exit) and method, the least `(FS, key)`.
#[derive(Clone, Copy, Default)]
struct Acc {
    best: [[Option<Best>; 3]; 2],
    evaluated: usize,
    rejected: usize,
    reasons: [usize; 8],
}

impl Acc {
    fn merge(mut self, o: Acc) -> Acc {
        for fam in 0..2 {
            for m in 0..3 {
                self.best[fam][m] = better(self.best[fam][m], o.best[fam][m]);
            }
        }
        self.evaluated += o.evaluated;
        self.rejected += o.rejected;
        for i in 0..8 {
            self.reasons[i] += o.reasons[i];
        }
        self
    }

    fn record(&mut self, fam: usize, key: u64, c: Circle, r: Result<([f64; 3], f64), Reject>) {
        match r {
            Ok((fs, _)) => {
                self.evaluated += 1;
                for (best, &f) in self.best[fam].iter_mut().zip(&fs) {
                    if f.is_finite() {
                        *best = better(*best, Some(Best { fs: f, key, circle: c }));
                    }
                }
            }
            Err(e) => {
                self.rejected += 1;
                self.reasons[reason_index(e)] += 1;
            }
        }
    }
}

fn reason_index(e: Reject) -> usize {
    match e {
        Reject::Degenerate => 0,
        Reject::Misses => 1,
        Reject::OpenArc => 2,
        Reject::Crossings(_) => 3,
        Reject::BelowLowerBound => 4,
        Reject::Sliver => 5,
        Reject::WrongDirection => 6,
        Reject::NoMaterial => 7,
    }
}

const REASONS: [&str; 8] = [
    "degenerate",
    "misses the ground",
    "open arc",
    "no sliding mass among the crossings",
    "below the lower bound",
    "sliver",
    "wrong direction",
    "no material",
];

fn dist_to_polyline(p: &[[f64; 2]], q: [f64; 2]) -> f64 {
    let mut d2 = f64::INFINITY;
    for w in p.windows(2) {
        let (a, b) = (w[0], w[1]);
        let ab = [b[0] - a[0], b[1] - a[1]];
        let t = (((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / (ab[0] * ab[0] + ab[1] * ab[1])).clamp(0.0, 1.0);
        let (dx, dz) = (a[0] + t * ab[0] - q[0], a[1] + t * ab[1] - q[1]);
        d2 = d2.min(dx * dx + dz * dz);
    }
    d2.sqrt()
}

/// `n` evenly spaced values over `[a, b]` (the midpoint if `n == 1`).
fn lin(r: [f64; 2], i: usize, n: usize) -> f64 {
    if n <= 1 {
        0.5 * (r[0] + r[1])
    } else {
        r[0] + (r[1] - r[0]) * i as f64 / (n - 1) as f64
    }
}

/// A range given in the user's frame, in the internal frame.
fn internal_range(f: &Frame, r: [f64; 2]) -> [f64; 2] {
    let (a, b) = (f.x(r[0]), f.x(r[1]));
    [a.min(b), a.max(b)]
}

struct Plan {
    grid: Option<(GridSpec, [f64; 2], [f64; 2])>,
    entry_exit: Option<(EntryExitSpec, [f64; 2], [f64; 2])>,
}

impl Plan {
    fn new(f: &Frame, spec: &SearchSpec) -> Plan {
        let (h, toe, crest) = (f.height(), f.toe, f.crest);
        let wf = (crest[0] - toe[0]).max(h);
        let (gx0, gx1) = (f.ground[0][0], f.ground[f.ground.len() - 1][0]);
        let clip = |r: [f64; 2]| [r[0].max(gx0), r[1].min(gx1)];
        let grid = spec.grid.map(|g| {
            let x = g.x.map_or([toe[0] - 0.25 * wf, crest[0] + 0.25 * wf], |r| internal_range(f, r));
            let z = g.z.unwrap_or([toe[1] + 0.5 * h, crest[1] + h.max(wf)]);
            (g, x, z)
        });
        let entry_exit = spec.entry_exit.map(|e| {
            let exit = e.exit.map_or(clip([toe[0] - 0.25 * wf, toe[0] + 0.5 * wf]), |r| internal_range(f, r));
            let entry = e.entry.map_or(clip([toe[0] + 0.5 * wf, crest[0] + 1.5 * wf]), |r| internal_range(f, r));
            (e, exit, entry)
        });
        Plan { grid, entry_exit }
    }

    fn n_grid_jobs(&self) -> usize {
        self.grid.map_or(0, |(g, _, _)| g.nx * g.nz)
    }

    fn n_jobs(&self) -> usize {
        self.n_grid_jobs() + self.entry_exit.map_or(0, |(e, _, _)| e.n_exit * e.n_entry)
    }

    /// Grid job `job`'s centre and radius range.
    fn grid_circles(&self, f: &Frame, job: usize) -> GridCircles {
        let (g, xr, zr) = self.grid.expect("grid job");
        let (i, j) = (job / g.nz, job % g.nz);
        let centre = [lin(xr, i, g.nx), lin(zr, j, g.nz)];
        let r_hi = match &f.lower {
            LowerBound::Level(z) => centre[1] - z,
            LowerBound::Polyline(p) => dist_to_polyline(p, centre),
        };
        GridCircles { centre, r_lo: dist_to_polyline(&f.ground, centre), r_hi, radii: g.radii }
    }

    /// Evaluates every circle of job `job` (a grid centre or an exit-entry pair).
    fn job(&self, ev: &Evaluator, want: Want, job: usize, s: &mut Slices) -> Acc {
        let mut acc = Acc::default();
        let f = ev.f;
        if job < self.n_grid_jobs() {
            let g = self.grid_circles(f, job);
            for q in 0..g.radii {
                let key = (job * g.radii + q) as u64;
                let c = g.circle(q);
                let r = if g.spans() { ev.fs(c, want, s) } else { Err(Reject::Misses) };
                acc.record(0, key, c, r);
            }
        } else {
            let (e, xr, er) = self.entry_exit.expect("entry-exit job");
            let k = job - self.n_grid_jobs();
            let (p, q) = (k / e.n_entry, k % e.n_entry);
            let (xx, xe) = (lin(xr, p, e.n_exit), lin(er, q, e.n_entry));
            let (a, b) = ([xx, polyline_z(&f.ground, xx)], [xe, polyline_z(&f.ground, xe)]);
            let (dx, dz) = (b[0] - a[0], b[1] - a[1]);
            let len = dx.hypot(dz);
            let normal = [-dz / len, dx / len];
            let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
            for j in 1..=e.radii {
                let key = (1u64 << 40) + (k * e.radii + j) as u64;
                let sag = 0.5 * len * j as f64 / e.radii as f64;
                let r = (sag * sag + 0.25 * len * len) / (2.0 * sag);
                let c = Circle { xc: mid[0] + normal[0] * (r - sag), zc: mid[1] + normal[1] * (r - sag), r };
                let res = if dx > 0.0 { ev.fs(c, want, s) } else { Err(Reject::Degenerate) };
                acc.record(1, key, c, res);
            }
        }
        acc
    }
}

/// The circles of one grid centre: `radii` radii spread over `(r_lo, r_hi]`,
/// from the distance to the ground to the distance to the lower bound.
struct GridCircles {
    centre: [f64; 2],
    r_lo: f64,
    r_hi: f64,
    radii: usize,
}

impl GridCircles {
    /// False where the lower bound is nearer than the ground: no circle cuts
    /// the slope above it.
    fn spans(&self) -> bool {
        self.r_hi > self.r_lo
    }

    /// The `q`-th circle, `q` in `0..radii`, smallest first.
    fn circle(&self, q: usize) -> Circle {
        Circle {
            xc: self.centre[0],
            zc: self.centre[1],
            r: self.r_lo + (self.r_hi - self.r_lo) * (q + 1) as f64 / self.radii as f64,
        }
    }
}

/// Nelder-Mead on `x` in R^3 (reflection 1, expansion 2, contraction 1/2,
/// shrink 1/2); stops when the simplex's values agree within `ftol` and its
/// vertices within `xtol` of the best, or after `max_evals`.
fn nelder_mead(
    obj: &mut impl FnMut([f64; 3]) -> f64,
    x0: [f64; 3],
    f0: f64,
    step: f64,
    xtol: f64,
    max_evals: usize,
) -> ([f64; 3], f64) {
    let mut p = [x0; 4];
    let mut v = [f0; 4];
    for i in 0..3 {
        p[i + 1][i] += step;
        v[i + 1] = obj(p[i + 1]);
    }
    let mut evals = 3;
    let comb = |a: [f64; 3], b: [f64; 3], t: f64| {
        [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
    };
    while evals < max_evals {
        let mut idx = [0usize, 1, 2, 3];
        idx.sort_by(|&a, &b| v[a].total_cmp(&v[b]).then(a.cmp(&b)));
        (p, v) = (idx.map(|i| p[i]), idx.map(|i| v[i]));
        let spread = (1..4).map(|i| (0..3).map(|k| (p[i][k] - p[0][k]).abs()).fold(0.0, f64::max)).fold(0.0, f64::max);
        if v[3] - v[0] <= 1e-10 * v[0].abs().max(1.0) && spread <= xtol {
            break;
        }
        let c = [0, 1, 2].map(|k| (p[0][k] + p[1][k] + p[2][k]) / 3.0);
        let xr = comb(c, p[3], -1.0);
        let fr = obj(xr);
        evals += 1;
        if fr < v[0] {
            let xe = comb(c, p[3], -2.0);
            let fe = obj(xe);
            evals += 1;
            (p[3], v[3]) = if fe < fr { (xe, fe) } else { (xr, fr) };
        } else if fr < v[2] {
            (p[3], v[3]) = (xr, fr);
        } else {
            let (xk, fk) = if fr < v[3] {
                let x = comb(c, xr, 0.5);
                (x, obj(x))
            } else {
                let x = comb(c, p[3], 0.5);
                (x, obj(x))
            };
            evals += 1;
            if fk < fr.min(v[3]) {
                (p[3], v[3]) = (xk, fk);
            } else {
                for i in 1..4 {
                    p[i] = comb(p[0], p[i], 0.5);
                    v[i] = obj(p[i]);
                }
                evals += 3;
            }
        }
    }
    let b = (0..4).min_by(|&a, &b| v[a].total_cmp(&v[b]).then(a.cmp(&b))).expect("four vertices");
    (p[b], v[b])
}

/// Refines `start` for method `m`; returns the best circle and the counts.
fn refine(ev: &Evaluator, m: Method, start: Best, h: f64) -> (Best, usize, usize) {
    let mut s = Slices::with_capacity(ev.n);
    let mut want = Want([false; 3]);
    want.0[m.index()] = true;
    let (mut evaluated, mut rejected) = (0, 0);
    let mut obj = |x: [f64; 3]| match ev.fs(Circle { xc: x[0], zc: x[1], r: x[2] }, want, &mut s) {
        Ok((fs, _)) => {
            evaluated += 1;
            fs[m.index()]
        }
        Err(_) => {
            rejected += 1;
            f64::INFINITY
        }
    };
    let x0 = [start.circle.xc, start.circle.zc, start.circle.r];
    let (x1, f1) = nelder_mead(&mut obj, x0, start.fs, 0.05 * h, 1e-6 * h, 600);
    let (x2, f2) = nelder_mead(&mut obj, x1, f1, 0.01 * h, 1e-7 * h, 400);
    let best = if f2 < start.fs {
        Best { fs: f2, key: start.key, circle: Circle { xc: x2[0], zc: x2[1], r: x2[2] } }
    } else {
        start
    };
    (best, evaluated, rejected)
}

pub(crate) fn run(input: &LemInput, spec: &SearchSpec) -> Result<LemResult, crate::Error> {
    let f = &input.section.frame;
    let h = f.height();
    let lim = Limits { min_depth: spec.min_depth.unwrap_or(0.02 * h), min_width: spec.min_width.unwrap_or(0.1 * h) };
    let ev = Evaluator { f, n: input.slices, lim };
    let mut want = Want([false; 3]);
    for m in &input.methods {
        want.0[m.index()] = true;
    }
    let plan = Plan::new(f, spec);
    let n = input.slices;
    let acc = if spec.parallel {
        (0..plan.n_jobs())
            .into_par_iter()
            .map_init(|| Slices::with_capacity(n), |s, j| plan.job(&ev, want, j, s))
            .reduce(Acc::default, Acc::merge)
    } else {
        let mut s = Slices::with_capacity(n);
        (0..plan.n_jobs()).fold(Acc::default(), |a, j| a.merge(plan.job(&ev, want, j, &mut s)))
    };
    let (mut evaluated, mut rejected) = (acc.evaluated, acc.rejected);

    // Refinement: (method, start) pairs, results in a fixed order.
    let mut tasks: Vec<(Method, Best)> = Vec::new();
    for m in input.methods.iter().copied() {
        for fam in 0..2 {
            if let Some(b) = acc.best[fam][m.index()] {
                if !tasks.iter().any(|(tm, tb)| *tm == m && tb.key == b.key) {
                    tasks.push((m, b));
                }
            }
        }
    }
    let refined: Vec<(Method, Best, usize, usize)> = if !spec.refine {
        tasks.iter().map(|&(m, b)| (m, b, 0, 0)).collect()
    } else if spec.parallel {
        tasks
            .par_iter()
            .map(|&(m, b)| {
                let (r, e, j) = refine(&ev, m, b, h);
                (m, r, e, j)
            })
            .collect()
    } else {
        tasks
            .iter()
            .map(|&(m, b)| {
                let (r, e, j) = refine(&ev, m, b, h);
                (m, r, e, j)
            })
            .collect()
    };
    let mut best: [Option<Best>; 3] = [None; 3];
    for (m, b, e, j) in refined {
        evaluated += e;
        rejected += j;
        best[m.index()] = better(best[m.index()], Some(b));
    }
    if input.methods.iter().all(|m| best[m.index()].is_none()) {
        let (i, most) = acc.reasons.iter().enumerate().max_by_key(|(_, &c)| c).expect("eight reasons");
        let sec = &input.section;
        let hint = match sec.ground_facing() {
            Some(g) if g != sec.facing() => format!(
                "; section.facing is {:?} but the ground rises toward its {} end (the slope faces {:?}): \
                 a wrong facing is the likely cause",
                sec.facing(),
                if g == super::section::Facing::Left { "right" } else { "left" },
                g
            ),
            _ => "; check the search ranges".to_string(),
        };
        return Err(SceneError::invalid(
            "search",
            format!(
                "no admissible slip circle among {} trial circles (most rejected as {}: {most}){hint}",
                acc.rejected, REASONS[i]
            ),
        )
        .into());
    }

    let mut s = Slices::with_capacity(n);
    let all = Want([true; 3]);
    let mut result = LemResult {
        fs: PerMethod::default(),
        critical: PerMethod::default(),
        on_bishop_critical: PerMethod::default(),
        circles_evaluated: evaluated,
        circles_rejected: rejected,
        slices: n,
        water: input.section.water().model(),
        wall_s: 0.0,
    };
    for m in input.methods.iter().copied() {
        let Some(b) = best[m.index()] else { continue };
        let Ok((fs, theta)) = ev.fs(b.circle, all, &mut s) else { continue };
        let point = |x: f64| [f.x(x), polyline_z(&f.ground, x)];
        result.fs.set(m, Some(b.fs));
        result.critical.set(
            m,
            Some(CriticalCircle {
                circle: Circle { xc: f.x(b.circle.xc), ..b.circle },
                entry: point(s.x_entry),
                exit: point(s.x_exit),
                fs: b.fs,
                theta_deg: (m == Method::Spencer && theta.is_finite()).then(|| theta.to_degrees()),
            }),
        );
        if m == Method::Bishop {
            for k in input.methods.iter().copied() {
                result.on_bishop_critical.set(k, fs[k.index()].is_finite().then_some(fs[k.index()]));
            }
        }
    }
    Ok(result)
}

#[cfg(test)]
mod tests {
    //! The trig-free slices and Newton's Bishop against the formulation they
    //! replaced (`asin` at each slice end, `sin_cos` of the mid angle, and
    //! fixed-point iteration), on every circle of the default grid.
    use super::*;
    use crate::lem::geometry::{cut, ground_integral};
    use crate::lem::methods::bishop_counted;
    use std::path::Path;

    /// Slices as before: `beta = asin(u / r)` at the ends, `alpha` their mean.
    fn reference_slices(f: &Frame, c: Circle, n: usize) -> (Vec<[f64; 4]>, f64) {
        let (xx, xe) = cut(f, c).unwrap();
        let sector =
            |u: f64| 0.5 * (u * (c.r * c.r - u * u).max(0.0).sqrt() + c.r * c.r * (u / c.r).clamp(-1.0, 1.0).asin());
        let gamma = f.homogeneous().unwrap().gamma;
        let b = (xe - xx) / n as f64;
        let (mut out, mut drive) = (Vec::new(), 0.0);
        for i in 0..n {
            let (x0, x1) = (xx + i as f64 * b, if i + 1 == n { xe } else { xx + (i + 1) as f64 * b });
            let (b0, b1) = (((x0 - c.xc) / c.r).clamp(-1.0, 1.0).asin(), ((x1 - c.xc) / c.r).clamp(-1.0, 1.0).asin());
            let (sa, ca) = (0.5 * (b0 + b1)).sin_cos();
            let mut k = 0;
            let area = (ground_integral(&f.ground, x0, x1, &mut k)
                - (c.zc * (x1 - x0) - (sector(x1 - c.xc) - sector(x0 - c.xc))))
            .max(0.0);
            drive += gamma * area * sa;
            out.push([gamma * area, sa, ca, c.r * (b1 - b0)]);
        }
        (out, drive)
    }

    /// Bishop as before: fixed-point iteration, `|dF| <= 1e-10 F`.
    fn reference_bishop(s: &[[f64; 4]], drive: f64, c: f64, t: f64, f0: f64) -> Option<(f64, usize)> {
        let mut f = f0;
        for it in 1..=200 {
            let mut resist = 0.0;
            for &[w, sa, ca, l] in s {
                let m = ca + sa * t / f;
                if m <= 0.0 {
                    return None;
                }
                resist += (c * l * ca + w * t) / m;
            }
            let f_new = resist / drive;
            if !(f_new.is_finite() && f_new > 0.0) {
                return None;
            }
            if (f_new - f).abs() <= 1e-10 * f_new {
                return Some((f_new, it));
            }
            f = f_new;
        }
        None
    }

    #[test]
    fn trig_free_slices_and_newton_bishop_match_the_old_formulation_on_the_grid() {
        for path in ["verification/lem/acads-1a.toml", "verification/lem/paper-slope-explicit.toml"] {
            let input = LemInput::load(Path::new(path)).unwrap();
            let f = &input.section.frame;
            let h = f.height();
            let n = input.slices;
            let ev = Evaluator { f, n, lim: Limits { min_depth: 0.02 * h, min_width: 0.1 * h } };
            let spec = SearchSpec { entry_exit: None, refine: false, parallel: false, ..SearchSpec::default() };
            let plan = Plan::new(f, &spec);
            let strength = f.homogeneous().unwrap();
            let mut s = Slices::with_capacity(n);
            let (mut accepted, mut with_fs, mut passes_new, mut passes_old) = (0usize, 0usize, 0usize, 0usize);
            let (mut geo_err, mut fs_err, mut noise_accepted) = ([0.0f64; 4], 0.0f64, 0usize);
            let mut circles = 0;
            for job in 0..plan.n_grid_jobs() {
                let g = plan.grid_circles(f, job);
                circles += g.radii;
                if !g.spans() {
                    continue;
                }
                for q in 0..g.radii {
                    let c = g.circle(q);
                    match fill_slices(f, c, n, ev.lim, &mut s) {
                        Ok(()) => {}
                        Err(Reject::WrongDirection) => {
                            // Net drive within rounding of 0: the old test `drive <= 0` took its sign.
                            if reference_slices(f, c, n).1 > 0.0 {
                                noise_accepted += 1;
                            }
                            continue;
                        }
                        Err(_) => continue,
                    }
                    accepted += 1;
                    let (old, drive) = reference_slices(f, c, n);
                    let scale = old.iter().map(|v| v[0]).fold(0.0, f64::max);
                    for (i, v) in old.iter().enumerate() {
                        let d = [
                            (s.w[i] - v[0]).abs() / scale,
                            (s.sin_a[i] - v[1]).abs(),
                            (s.cos_a[i] - v[2]).abs(),
                            (s.l[i] - v[3]).abs() / v[3],
                        ];
                        for k in 0..4 {
                            geo_err[k] = geo_err[k].max(d[k]);
                        }
                    }
                    let o = ordinary(&s).unwrap();
                    let new = bishop_counted(&s, o);
                    let old = reference_bishop(&old, drive, strength.c, strength.tan_phi, o);
                    assert_eq!(
                        new.is_some(),
                        old.is_some(),
                        "{path}: {c:?}: Bishop F {new:?} (Newton) but {old:?} (fixed point)"
                    );
                    if let (Some((a, na)), Some((b, nb))) = (new, old) {
                        with_fs += 1;
                        passes_new += na;
                        passes_old += nb;
                        fs_err = fs_err.max((a - b).abs() / b);
                    }
                }
            }
            println!(
                "{path}: {accepted} admissible of {} circles ({noise_accepted} more with the old `drive > 0`), {with_fs} with a Bishop F; passes per circle Newton {:.2}, fixed point {:.2}; max slice differences (W / max W, sin, cos, l relative) {geo_err:?}, max relative F difference {fs_err:.1e}",
                circles,
                passes_new as f64 / with_fs as f64,
                passes_old as f64 / with_fs as f64
            );
            assert!(geo_err.iter().all(|&e| e < 1e-10), "{path}: slices differ by {geo_err:?}");
            assert!(fs_err < 1e-9, "{path}: Bishop F differs by {fs_err:e}");
        }
    }
}
