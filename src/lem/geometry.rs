//! Circle-ground intersection and slices (internal frame: the section faces
//! -x, so the exit is the left crossing and the entry the right one).
//!
//! Lower arc `z_arc(x) = zc - sqrt(r^2 - u^2)`, `u = x - xc`. Slice `[x0, x1]`:
//! `beta = asin(u / r)` at its ends, base inclination `alpha = (beta0 + beta1)/2`
//! (`sin(alpha) > 0` under the crest side: driving), base length
//! `l = r (beta1 - beta0)` (exact arc length), area
//! `A = int z_ground dx - [zc (x1 - x0) - (S(u1) - S(u0))]` with
//! `S(u) = (u sqrt(r^2 - u^2) + r^2 asin(u / r)) / 2` (exact for a polyline
//! ground). Weight `W = gamma A` in a homogeneous section; with zones, the
//! centre-line column `W = b sum(gamma_k h_k)`.

use super::section::{polyline_z, Frame, LowerBound};
use super::water::{Pore, TensionCrack};
use super::{Circle, LemSection};

/// Why a trial circle is not an admissible slip surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum Reject {
    #[error("radius or centre is not finite and positive")]
    Degenerate,
    #[error("the lower arc does not reach the ground")]
    Misses,
    #[error("the sliding mass is open: the arc ends under the ground on the crest side, or the mass reaches the section's toe-side end (centre too low, or the section too short)")]
    OpenArc,
    #[error("the lower arc cuts the ground in {0} points and bounds no sliding mass there (or more than 16)")]
    Crossings(usize),
    #[error("the arc passes below the lower bound")]
    BelowLowerBound,
    #[error("sliver: the sliding mass is thinner than the minimum depth or narrower than the minimum width")]
    Sliver,
    #[error("the mass would slide toward the crest (driving moment <= 0, or within rounding of 0)")]
    WrongDirection,
    #[error("part of the sliding mass lies in no material")]
    NoMaterial,
}

/// Minimum size of a sliding mass (m): the deepest slice's mean height and
/// the entry-exit width. The search's defaults are `0.02 H` and `0.1 H`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Limits {
    pub min_depth: f64,
    pub min_width: f64,
}

impl Limits {
    pub const NONE: Limits = Limits { min_depth: 0.0, min_width: 0.0 };
}

/// `sum W sin(alpha)` at or below this fraction of `sum |W sin(alpha)|` is no
/// net driving moment (`Reject::WrongDirection`).
const DRIVE_ROUNDING: f64 = 1e-10;

/// Slice data, struct-of-arrays, reused from circle to circle.
#[derive(Debug, Clone, Default)]
pub(crate) struct Slices {
    pub w: Vec<f64>,
    pub sin_a: Vec<f64>,
    pub cos_a: Vec<f64>,
    pub l: Vec<f64>,
    pub c: Vec<f64>,
    pub tan_phi: Vec<f64>,
    /// Bishop's per-slice constants: `c l cos(alpha) + W tan_phi` and
    /// `sin(alpha) tan_phi` ([`super::methods::bishop`]).
    pub bishop_a: Vec<f64>,
    pub bishop_b: Vec<f64>,
    /// The ordinary method's `sum(c l + (W cos(alpha) - u l) tan_phi)` (N/m).
    pub resist_ordinary: f64,
    /// Pore pressure at the middle of each base (Pa).
    pub u: Vec<f64>,
    /// Spencer's per-slice `R = c l + (W cos(alpha) - H sin(alpha) - u l) tan_phi`
    /// and `D = W sin(alpha) + H cos(alpha)` (`H` the crack water force, on
    /// the crest-side slice only) ([`super::methods::spencer`]).
    pub spencer_r: Vec<f64>,
    pub spencer_d: Vec<f64>,
    /// Spencer's moment equation `sum Q cos(alpha - theta) = K`,
    /// `K = H ((zc - z_H) - r cos(alpha_n)) / r` (0 without a crack force).
    pub moment_k: f64,
    /// The water force in the tension crack `H = gamma_w h_w^2 / 2` (N/m)
    /// and its height `z_H` (m); 0 if the circle ends at no crack.
    pub crack_force: f64,
    pub crack_z: f64,
    /// Scratch: z of zone-edge crossings in one column.
    column: Vec<f64>,
    /// Scratch: the slice ends of a layered section ([`layered_ends`]).
    ends: Vec<f64>,
    /// Scratch, at the `n + 1` slice ends: x, `u = x - xc`,
    /// `w = sqrt(r^2 - u^2)`, ground height.
    xb: Vec<f64>,
    ub: Vec<f64>,
    wb: Vec<f64>,
    zg: Vec<f64>,
    /// The driving moment over `r`: `sum W sin(alpha) + H (zc - z_H) / r` (N/m).
    pub drive: f64,
    pub x_exit: f64,
    pub x_entry: f64,
}

impl Slices {
    pub fn with_capacity(n: usize) -> Self {
        let v = || Vec::with_capacity(n);
        Slices {
            w: v(),
            sin_a: v(),
            cos_a: v(),
            l: v(),
            c: v(),
            tan_phi: v(),
            bishop_a: v(),
            bishop_b: v(),
            u: v(),
            spencer_r: v(),
            spencer_d: v(),
            column: Vec::with_capacity(16),
            ends: v(),
            xb: v(),
            ub: v(),
            wb: v(),
            zg: v(),
            ..Default::default()
        }
    }

    pub fn len(&self) -> usize {
        self.w.len()
    }
}

#[inline]
fn z_arc(c: Circle, x: f64) -> f64 {
    let u = x - c.xc;
    c.zc - (c.r * c.r - u * u).max(0.0).sqrt()
}

/// The exit and entry x of the lower arc on the ground (internal frame): the
/// two crossings when there are two and the arc's ends are above the ground
/// (the common case, its own branch), else the crest-side run of the arc
/// under the ground ([`crest_side_mass`]).
pub(crate) fn cut(f: &Frame, c: Circle) -> Result<(f64, f64), Reject> {
    if !(c.r > 0.0 && c.r.is_finite() && c.xc.is_finite() && c.zc.is_finite()) {
        return Err(Reject::Degenerate);
    }
    let g = &f.ground;
    let (gx0, gx1) = (g[0][0], g[g.len() - 1][0]);
    let (lo, hi) = (gx0.max(c.xc - c.r), gx1.min(c.xc + c.r));
    if lo >= hi {
        return Err(Reject::Misses);
    }
    // The arc's crest-side end must be above the ground; its toe-side end
    // may leave the section under the ground if a closed run of the arc
    // under the ground lies on the crest side of it ([`crest_side_mass`]).
    if polyline_z(g, hi) >= z_arc(c, hi) {
        return Err(Reject::OpenArc);
    }
    let left_open = polyline_z(g, lo) >= z_arc(c, lo);
    let mut xs = [0.0f64; MAX_CROSSINGS];
    let mut count = 0usize;
    let last = g.len() - 2;
    for k in 0..=last {
        let (a, b) = (g[k], g[k + 1]);
        if b[0] < lo || a[0] > hi {
            continue;
        }
        let d = [b[0] - a[0], b[1] - a[1]];
        let e = [a[0] - c.xc, a[1] - c.zc];
        let qa = d[0] * d[0] + d[1] * d[1];
        let qb = 2.0 * (e[0] * d[0] + e[1] * d[1]);
        let qc = e[0] * e[0] + e[1] * e[1] - c.r * c.r;
        let disc = qb * qb - 4.0 * qa * qc;
        if disc < 0.0 {
            continue;
        }
        let s = disc.sqrt();
        for t in [(-qb - s) / (2.0 * qa), (-qb + s) / (2.0 * qa)] {
            let in_segment = t >= 0.0 && (t < 1.0 || (k == last && t <= 1.0));
            if in_segment && a[1] + t * d[1] < c.zc {
                if count < MAX_CROSSINGS {
                    xs[count] = a[0] + t * d[0];
                }
                count += 1;
            }
        }
    }
    match count {
        0 if left_open => Err(Reject::OpenArc),
        0 => Err(Reject::Misses),
        2 if !left_open => Ok((xs[0].min(xs[1]), xs[0].max(xs[1]))),
        n if n > MAX_CROSSINGS => Err(if left_open { Reject::OpenArc } else { Reject::Crossings(n) }),
        n => crest_side_mass(g, c, &mut xs[..n], left_open),
    }
}

/// Crossings [`cut`] keeps; a circle cutting the ground more often is rejected.
const MAX_CROSSINGS: usize = 16;

/// The sliding mass of a lower arc that cuts the ground more than twice (or
/// touches it, or leaves the section under the ground on the toe side,
/// `left_open`): the crest-side run of the arc under the ground, as (exit,
/// entry). Between consecutive crossings the arc is either under the ground
/// (mass) or above it (air); a run is a maximal chain of mass intervals, so a
/// point where the arc only touches the ground (a toe vertex) does not split
/// it, and intervals narrower than rounding neither split nor start one. The
/// runs further toward the toe are the arc's continuation under the ground
/// (Taylor's toe circles of steep slopes: the arc re-enters the level ground
/// in front of the toe) and are not part of this sliding mass. Errors: the
/// crest-side run reaches the section's toe-side end under the ground
/// (`OpenArc`), or the arc is nowhere under the ground (`Crossings`).
fn crest_side_mass(g: &[[f64; 2]], c: Circle, xs: &mut [f64], left_open: bool) -> Result<(f64, f64), Reject> {
    xs.sort_unstable_by(f64::total_cmp);
    let tol = 1e-9 * (1.0 + c.r);
    let mut entry: Option<f64> = None;
    for i in (0..xs.len() - 1).rev() {
        let (a, b) = (xs[i], xs[i + 1]);
        if b - a <= tol {
            continue;
        }
        let m = 0.5 * (a + b);
        let under = polyline_z(g, m) > z_arc(c, m);
        match (under, entry) {
            (true, None) => entry = Some(b),
            (false, Some(e)) => return Ok((b, e)),
            _ => {}
        }
    }
    match entry {
        _ if left_open => Err(Reject::OpenArc),
        Some(e) => Ok((xs[0], e)),
        None => Err(Reject::Crossings(xs.len())),
    }
}

/// Is the arc between x0 and x1 on or above the lower bound?
fn above_lower_bound(f: &Frame, c: Circle, x0: f64, x1: f64) -> bool {
    let tol = 1e-9 * (1.0 + c.r + c.zc.abs());
    match &f.lower {
        LowerBound::Level(z) => {
            let lowest = if (x0..=x1).contains(&c.xc) { c.zc - c.r } else { z_arc(c, x0).min(z_arc(c, x1)) };
            lowest >= z - tol
        }
        LowerBound::Polyline(p) => {
            // z_arc minus a linear piece is convex: its minimum is at an end
            // or where the arc's slope u / sqrt(r^2 - u^2) equals the piece's.
            let ok = |x: f64| z_arc(c, x) >= polyline_z(p, x) - tol;
            if !ok(x0) || !ok(x1) {
                return false;
            }
            for k in 0..p.len() - 1 {
                let (a, b) = (p[k], p[k + 1]);
                if b[0] < x0 || a[0] > x1 {
                    continue;
                }
                if (x0..=x1).contains(&a[0]) && !ok(a[0]) {
                    return false;
                }
                let s = (b[1] - a[1]) / (b[0] - a[0]);
                let x = c.xc + s * c.r / (1.0 + s * s).sqrt();
                if x >= a[0].max(x0) && x <= b[0].min(x1) && !ok(x) {
                    return false;
                }
            }
            true
        }
    }
}

/// Integral of the ground over `[x0, x1]`; `k` is a segment hint that only moves right.
pub(crate) fn ground_integral(g: &[[f64; 2]], x0: f64, x1: f64, k: &mut usize) -> f64 {
    while *k + 2 < g.len() && g[*k + 1][0] <= x0 {
        *k += 1;
    }
    let lerp = |k: usize, x: f64| {
        let (a, b) = (g[k], g[k + 1]);
        a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0])
    };
    let (mut sum, mut a, mut j) = (0.0, x0, *k);
    loop {
        let b = if j + 2 < g.len() { x1.min(g[j + 1][0]) } else { x1 };
        sum += 0.5 * (lerp(j, a) + lerp(j, b)) * (b - a);
        if b >= x1 {
            return sum;
        }
        a = b;
        j += 1;
    }
}

/// Where [`asin_series`] is used (else the library's `asin`).
const ASIN_SERIES_MAX: f64 = 0.1;

/// `asin(x)` for `0 <= x <= ASIN_SERIES_MAX`: its Maclaurin series through
/// `x^15` (truncation below `1.2e-2 x^17`, relative `< 2e-18` there).
#[inline]
fn asin_series(x: f64) -> f64 {
    // (2k)! / (4^k (k!)^2 (2k + 1)), k = 0..7.
    const A: [f64; 8] =
        [1.0, 1.0 / 6.0, 3.0 / 40.0, 5.0 / 112.0, 35.0 / 1152.0, 63.0 / 2816.0, 231.0 / 13312.0, 143.0 / 10240.0];
    let y = x * x;
    // Horner; plain multiply-add (`mul_add` is a library call without `target-cpu`).
    let mut p = A[7];
    for a in A[..7].iter().rev() {
        p = p * y + a;
    }
    x * p
}

/// `v` at length `n` (its values are overwritten by the caller).
#[inline]
fn sized(v: &mut Vec<f64>, n: usize) {
    if v.len() != n {
        v.resize(n, 0.0);
    }
}

/// Cuts the circle (internal frame) into `n` slices, filling `s`.
///
/// No trigonometry per slice: with `w = sqrt(r^2 - u^2)` at the slice ends
/// (the arc is at `z = zc - w`), the base chord `(dx, dz) = (x1 - x0, w0 - w1)`
/// of length `d` is perpendicular to the radius at `alpha = (beta0 + beta1)/2`,
/// so `cos(alpha) = dx / d` and `sin(alpha) = dz / d` exactly; the angle the
/// slice subtends is `beta1 - beta0 = 2 asin(d / 2r)` (a short series, slices
/// being thin), which gives the arc length `l = r (beta1 - beta0)` and
/// `S(u1) - S(u0) = (u1 w1 - u0 w0 + r^2 (beta1 - beta0)) / 2`.
pub(crate) fn fill_slices(f: &Frame, c: Circle, n: usize, lim: Limits, s: &mut Slices) -> Result<(), Reject> {
    let (xx, xe) = cut(f, c)?;
    // A tension crack cuts the mass at the crack line's crest-most crossing.
    let crack = f.water.crack.and_then(|k| crack_cut(f, c, xx, xe, k).map(|x| (x, k)));
    let xe = crack.map_or(xe, |(x, _)| x);
    if !above_lower_bound(f, c, xx, xe) {
        return Err(Reject::BelowLowerBound);
    }
    if xe - xx < lim.min_width {
        return Err(Reject::Sliver);
    }
    s.x_exit = xx;
    s.x_entry = xe;
    let g = &f.ground;
    let b = (xe - xx) / n as f64;
    let (r, r2) = (c.r, c.r * c.r);
    let half_inv_r = 0.5 / r;
    let homogeneous = f.homogeneous();
    let eps_z = 1e-9 * f.height();
    // A layered section's slices end where the arc changes material.
    let mut ends = std::mem::take(&mut s.ends);
    let layered = homogeneous.is_none() && layered_ends(f, c, xx, xe, n, eps_z, &mut ends);
    // Pass 1, slice ends: x, u = x - xc, w = sqrt(r^2 - u^2) (branch-free,
    // it vectorizes), then the ground height segment by segment.
    for v in [&mut s.xb, &mut s.ub, &mut s.wb, &mut s.zg] {
        sized(v, n + 1);
    }
    for (i, ((xb, ub), wb)) in s.xb.iter_mut().zip(s.ub.iter_mut()).zip(s.wb.iter_mut()).enumerate() {
        let x = if layered { ends[i] } else { xx + i as f64 * b };
        let u = x - c.xc;
        *xb = x;
        *ub = u;
        *wb = (r2 - u * u).max(0.0).sqrt();
    }
    // The ends exactly (`xx + n b` may round off `xe`).
    for (i, x) in [(0, xx), (n, xe)] {
        let u = x - c.xc;
        (s.xb[i], s.ub[i], s.wb[i]) = (x, u, (r2 - u * u).max(0.0).sqrt());
    }
    // The ends are in order of x: ground segment k takes those left of its
    // right vertex that no segment before it took (the last one, the rest).
    let mut start = 0;
    for k in 0..g.len() - 1 {
        let end = if k + 2 < g.len() { start + s.xb[start..].partition_point(|&x| x < g[k + 1][0]) } else { n + 1 };
        let (a, slope) = (g[k], (g[k + 1][1] - g[k][1]) / (g[k + 1][0] - g[k][0]));
        for (zg, &x) in s.zg[start..end].iter_mut().zip(&s.xb[start..end]) {
            *zg = a[1] + slope * (x - a[0]);
        }
        start = end;
    }
    // Pass 2, per slice and branch-free: base direction from the chord,
    // subtended angle, area under the ground (trapezoid) less the arc's.
    // Every slice's four values are written below: no need to zero them.
    for v in
        [&mut s.w, &mut s.sin_a, &mut s.cos_a, &mut s.l, &mut s.c, &mut s.tan_phi, &mut s.bishop_a, &mut s.bishop_b]
    {
        sized(v, n);
    }
    let (xb, ub, wb, zg) = (&s.xb[..=n], &s.ub[..=n], &s.wb[..=n], &s.zg[..=n]);
    let (area, sin_a, cos_a, l) = (&mut s.w[..n], &mut s.sin_a[..n], &mut s.cos_a[..n], &mut s.l[..n]);
    // Slice i's chord `(dx, d)` and half chord over radius `h = sin(dbeta / 2)`.
    let chord = |i: usize| {
        let (dx, dz) = (xb[i + 1] - xb[i], wb[i] - wb[i + 1]);
        let d = (dx * dx + dz * dz).sqrt();
        (dx, dz, d, d * half_inv_r)
    };
    // Slice i's arc length and area (ground trapezoid less the arc's) for the angle `dbeta`.
    let arc = |i: usize, dx: f64, dbeta: f64| {
        (
            r * dbeta,
            0.5 * (zg[i] + zg[i + 1]) * dx - (c.zc * dx - 0.5 * (ub[i + 1] * wb[i + 1] - ub[i] * wb[i] + r2 * dbeta)),
        )
    };
    let mut fix = false;
    for i in 0..n {
        let (dx, dz, d, h) = chord(i);
        let inv_d = 1.0 / d;
        cos_a[i] = dx * inv_d;
        sin_a[i] = dz * inv_d;
        fix |= h > ASIN_SERIES_MAX || !(d > 0.0);
        (l[i], area[i]) = arc(i, dx, 2.0 * asin_series(h));
    }
    // Fix-ups, rare: long chords (asin), zero-width slices (the arc's tangent),
    // slices with a ground vertex inside (exact ground integral).
    if fix {
        for i in 0..n {
            let (dx, _, d, h) = chord(i);
            if h > ASIN_SERIES_MAX || !(d > 0.0) {
                (l[i], area[i]) = arc(i, dx, 2.0 * h.min(1.0).asin());
                if !(d > 0.0) {
                    (cos_a[i], sin_a[i]) = (wb[i] / r, ub[i] / r);
                }
            }
        }
    }
    for v in &g[1..g.len() - 1] {
        if !(v[0] > xx && v[0] < xe) {
            continue;
        }
        let j = match layered {
            true => xb.partition_point(|&x| x <= v[0]).saturating_sub(1).min(n - 1),
            false => (((v[0] - xx) / b) as usize).min(n - 1),
        };
        for i in j.saturating_sub(1)..(j + 2).min(n) {
            let (x0, x1) = (xb[i], xb[i + 1]);
            if v[0] > x0 && v[0] < x1 {
                let mut kk = 0;
                let trapezoid = 0.5 * (zg[i] + zg[i + 1]) * (x1 - x0);
                area[i] += ground_integral(g, x0, x1, &mut kk) - trapezoid;
            }
        }
    }
    s.ends = ends;
    // Pass 3: weights and strengths.
    let (mut deep, mut drive, mut gross, mut resist) = (false, 0.0, 0.0f64, 0.0);
    for v in [&mut s.u, &mut s.spencer_r, &mut s.spencer_d] {
        sized(v, n);
    }
    let water = &f.water;
    let dry = matches!(water.pore, Pore::Dry);
    if let Some(m) = homogeneous {
        // One material: the same sums as below, without the per-slice lookups;
        // dry, pass 4's Spencer constants too (u = 0), in the same loop.
        s.c.fill(m.c);
        s.tan_phi.fill(m.tan_phi);
        let ends = s.xb.windows(2);
        let per_slice = s.w.iter_mut().zip(&s.sin_a).zip(&s.cos_a).zip(&s.l);
        let out = s.bishop_a.iter_mut().zip(s.bishop_b.iter_mut()).zip(s.spencer_r.iter_mut().zip(&mut s.spencer_d));
        for (((((w, &sin_a), &cos_a), &l), x), ((ba, bb), (sr, sd))) in per_slice.zip(ends).zip(out) {
            let a = w.max(0.0);
            let weight = m.gamma * a;
            deep |= a >= lim.min_depth * (x[1] - x[0]);
            drive += weight * sin_a;
            gross += (weight * sin_a).abs();
            *w = weight;
            let r_i = m.c * l + weight * cos_a * m.tan_phi;
            resist += r_i;
            *ba = m.c * l * cos_a + weight * m.tan_phi;
            *bb = sin_a * m.tan_phi;
            *sr = r_i;
            *sd = weight * sin_a;
        }
        if dry {
            s.u.fill(0.0);
        }
    }
    for i in (0..n).filter(|_| homogeneous.is_none()) {
        let (x0, x1) = (s.xb[i], s.xb[i + 1]);
        let a = s.w[i].max(0.0);
        let base = [c.xc + r * s.sin_a[i], c.zc - r * s.cos_a[i] + eps_z];
        let w = column_weight(f, c, 0.5 * (x0 + x1), &mut s.column).ok_or(Reject::NoMaterial)? * (x1 - x0);
        let strength = f.strength_at(base).ok_or(Reject::NoMaterial)?;
        // The deepest slice's mean height a / (x1 - x0) reaches min_depth.
        deep |= a >= lim.min_depth * (x1 - x0);
        drive += w * s.sin_a[i];
        gross += (w * s.sin_a[i]).abs();
        s.w[i] = w;
        s.c[i] = strength.c;
        s.tan_phi[i] = strength.tan_phi;
        resist += strength.c * s.l[i] + w * s.cos_a[i] * strength.tan_phi;
        s.bishop_a[i] = strength.c * s.l[i] * s.cos_a[i] + w * strength.tan_phi;
        s.bishop_b[i] = s.sin_a[i] * strength.tan_phi;
    }
    // Pass 4: pore water (module docs of `lem`): u at the middle of each
    // base, the effective normal forces, and the crack's water force.
    for i in (0..n).filter(|_| !(dry && homogeneous.is_some())) {
        let (w, sa, ca, l, t) = (s.w[i], s.sin_a[i], s.cos_a[i], s.l[i], s.tan_phi[i]);
        let u = match &water.pore {
            Pore::Dry => 0.0,
            Pore::Surface(p) => p.pressure(c.xc + r * sa, c.zc - r * ca),
            Pore::Ru(ru) => ru * w / (s.xb[i + 1] - s.xb[i]),
        };
        s.u[i] = u;
        resist -= u * l * t;
        s.bishop_a[i] -= u * l * ca * t;
        s.spencer_r[i] = s.c[i] * l + (w * ca - u * l) * t;
        s.spencer_d[i] = w * sa;
    }
    let (mut force, mut z_h, mut k) = (0.0, 0.0, 0.0);
    if let Some((xt, crack)) = crack {
        let h_w = crack.fill * crack.depth;
        force = 0.5 * water.unit_weight * h_w * h_w;
        z_h = z_arc(c, xt) + h_w / 3.0;
        let last = n - 1;
        let (sa, ca) = (s.sin_a[last], s.cos_a[last]);
        s.spencer_r[last] -= force * sa * s.tan_phi[last];
        s.spencer_d[last] += force * ca;
        k = force * ((c.zc - z_h) - r * ca) / r;
        drive += force * (c.zc - z_h) / r;
        gross += (force * (c.zc - z_h) / r).abs();
    }
    s.crack_force = force;
    s.crack_z = z_h;
    s.moment_k = k;
    if !deep {
        return Err(Reject::Sliver);
    }
    // A net driving moment within rounding of zero (a circle symmetric under
    // level ground, F ~ 1e16) is no direction: its sign is noise.
    if drive <= DRIVE_ROUNDING * gross {
        return Err(Reject::WrongDirection);
    }
    s.drive = drive;
    s.resist_ordinary = resist;
    Ok(())
}

/// The slice ends of a layered section (Slide's rule: every base in one
/// material): into `ends` the `n + 1` ends from `xx` to `xe`, with an end
/// wherever the arc's material changes, found by sampling the arc at `8 n`
/// points (a zone the arc crosses for less than `(xe - xx) / 8 n` may be
/// missed) and bisecting each change to `1e-9` of the width; the runs
/// between two such ends get slices of equal width, their number in
/// proportion to the run's length (at least one each, by largest remainder).
/// False (the ends are the uniform ones) when the arc stays in one material
/// or crosses more boundaries than it has slices.
fn layered_ends(f: &Frame, c: Circle, xx: f64, xe: f64, n: usize, eps_z: f64, ends: &mut Vec<f64>) -> bool {
    let at = |x: f64| f.strength_at([x, z_arc(c, x) + eps_z]);
    let width = xe - xx;
    let m = 8 * n;
    let h = width / m as f64;
    ends.clear();
    ends.push(xx);
    let mut prev = (xx + 0.5 * h, at(xx + 0.5 * h));
    for k in 1..m {
        let x = xx + (k as f64 + 0.5) * h;
        let here = at(x);
        if here != prev.1 {
            let (mut lo, mut hi) = (prev.0, x);
            while hi - lo > 1e-9 * width {
                let mid = 0.5 * (lo + hi);
                if at(mid) == prev.1 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            ends.push(0.5 * (lo + hi));
        }
        prev = (x, here);
    }
    ends.push(xe);
    let runs = ends.len() - 1;
    if runs == 1 || runs > n {
        return false;
    }
    // Slices per run: the largest remainders of n w_k / W, at least one.
    let share: Vec<f64> = ends.windows(2).map(|e| n as f64 * (e[1] - e[0]) / width).collect();
    let mut count: Vec<usize> = share.iter().map(|&q| (q.floor() as usize).max(1)).collect();
    while count.iter().sum::<usize>() < n {
        let k = (0..runs).max_by(|&a, &b| (share[a] - count[a] as f64).total_cmp(&(share[b] - count[b] as f64)));
        count[k.unwrap_or(0)] += 1;
    }
    while count.iter().sum::<usize>() > n {
        let k = (0..runs)
            .filter(|&k| count[k] > 1)
            .max_by(|&a, &b| (count[a] as f64 - share[a]).total_cmp(&(count[b] as f64 - share[b])));
        count[k.unwrap_or(0)] -= 1;
    }
    let cuts = std::mem::take(ends);
    for (k, e) in cuts.windows(2).enumerate() {
        let step = (e[1] - e[0]) / count[k] as f64;
        ends.extend((0..count[k]).map(|i| e[0] + i as f64 * step));
    }
    ends.push(xe);
    true
}

/// Where the arc meets a tension crack's line `z = ground - depth` (inside
/// its zone) nearest the entry `xe`: scanning from the crest side toward the
/// exit `xx`, the first point where the arc passes from above the crack line
/// to below it (256 steps, then bisection to 1e-12 of the width). `None`: the
/// arc does not cross the crack line there (the whole circle is used).
fn crack_cut(f: &Frame, c: Circle, xx: f64, xe: f64, k: TensionCrack) -> Option<f64> {
    // The frame's zone is in the internal frame already (Water::mirrored).
    let (lo, hi) = k.zone.map_or((xx, xe), |[a, b]| (a.max(xx), b.min(xe)));
    if lo >= hi {
        return None;
    }
    let below = |x: f64| polyline_z(&f.ground, x) - z_arc(c, x) - k.depth;
    const STEPS: usize = 256;
    let (mut a, mut ga) = (hi, below(hi));
    for j in 1..=STEPS {
        let b = hi - (hi - lo) * j as f64 / STEPS as f64;
        let gb = below(b);
        if ga < 0.0 && gb >= 0.0 {
            // a: above the crack line (crest side), b: below it.
            let (mut up, mut down) = (a, b);
            while (up - down).abs() > 1e-12 * (xe - xx) {
                let m = 0.5 * (up + down);
                if below(m) < 0.0 {
                    up = m;
                } else {
                    down = m;
                }
            }
            return Some(0.5 * (up + down));
        }
        (a, ga) = (b, gb);
    }
    None
}

/// `sum gamma_k h_k` on the vertical line x between the arc and the ground.
fn column_weight(f: &Frame, c: Circle, x: f64, zs: &mut Vec<f64>) -> Option<f64> {
    let (z0, z1) = (z_arc(c, x), polyline_z(&f.ground, x));
    if z1 <= z0 {
        return Some(0.0);
    }
    zs.clear();
    zs.push(z0);
    // Zone edges along the ground or the arc (a mesh's zones share the
    // ground's vertices) cross within rounding of z1 or z0: such a crossing
    // would leave a sliver of air or of nothing between it and the end.
    let eps = 1e-9 * f.height();
    for (poly, _) in &f.zones {
        let n = poly.len();
        for i in 0..n {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            if (a[0] <= x) != (b[0] <= x) {
                let z = a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
                if z > z0 + eps && z < z1 - eps {
                    zs.push(z);
                }
            }
        }
    }
    zs.push(z1);
    zs.sort_unstable_by(f64::total_cmp);
    let mut sum = 0.0;
    for p in zs.windows(2) {
        if p[1] > p[0] {
            sum += f.strength_at([x, 0.5 * (p[0] + p[1])])?.gamma * (p[1] - p[0]);
        }
    }
    Some(sum)
}

/// One slice as a person reads it (user frame).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SliceInfo {
    /// Left and right x of the slice (m).
    pub x: [f64; 2],
    /// Weight per metre run (N/m).
    pub weight: f64,
    /// Base inclination (rad), positive where the base descends in the
    /// direction of sliding.
    pub alpha: f64,
    /// Base (arc) length (m).
    pub base_length: f64,
    pub cohesion: f64,
    pub tan_phi: f64,
    /// Pore pressure at the middle of the base (Pa).
    pub pore_pressure: f64,
}

/// The slices of a circle (no minimum depth or width), in order of x.
pub fn slices_of(section: &LemSection, circle: Circle, n: usize) -> Result<Vec<SliceInfo>, Reject> {
    let f = &section.frame;
    let c = Circle { xc: f.x(circle.xc), ..circle };
    let mut s = Slices::with_capacity(n);
    fill_slices(f, c, n.max(1), Limits::NONE, &mut s)?;
    let b = (s.x_entry - s.x_exit) / s.len() as f64;
    let mut v: Vec<SliceInfo> = (0..s.len())
        .map(|i| {
            let (x0, x1) = (s.x_exit + i as f64 * b, s.x_exit + (i + 1) as f64 * b);
            let (xa, xb) = (f.x(x0), f.x(x1));
            SliceInfo {
                x: [xa.min(xb), xa.max(xb)],
                weight: s.w[i],
                alpha: s.sin_a[i].atan2(s.cos_a[i]),
                base_length: s.l[i],
                cohesion: s.c[i],
                tan_phi: s.tan_phi[i],
                pore_pressure: s.u[i],
            }
        })
        .collect();
    if f.mirrored {
        v.reverse();
    }
    Ok(v)
}
