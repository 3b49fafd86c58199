//! Kinematic analysis of a rock slope (Markland's test, after Hoek & Bray,
//! Rock Slope Engineering, ch. 2 and Goodman & Bray 1976, as Rocscience Dips
//! draws it): for each joint set, plane sliding and flexural toppling; for
//! each pair of sets, wedge sliding along their line of intersection.
//!
//! Orientations in degrees: a plane by its dip and dip direction (clockwise
//! from north), a line by its plunge and trend. x east, y north, z up.
//!
//! - plane sliding: the plane daylights (`dip < face dip`), is steeper than
//!   its friction angle (`dip > phi`), and dips within
//!   [`LATERAL_LIMIT`] of the face's dip direction;
//! - wedge sliding: the line of intersection plunges out of the face
//!   (trend within 90 deg of the face's dip direction), less steeply than the
//!   face's apparent dip along it, `tan(a) = tan(face dip) cos(trend - dd_f)`
//!   (it daylights), and more steeply than the smaller friction angle of the
//!   pair (outside the friction cone);
//! - flexural toppling (Goodman & Bray): the plane dips into the slope,
//!   within [`LATERAL_LIMIT`] of the opposite of the face's dip direction,
//!   steeply enough that `(90 - dip) + phi < face dip` (its pole inside the
//!   slip limit).
//!
//! Direct (block) toppling, which needs a base plane and an interlayer pair,
//! is not tested here.

/// Dips' default lateral limit of the plane-sliding and toppling tests (deg).
pub const LATERAL_LIMIT: f64 = 20.0;

/// A plane: dip and dip direction (deg).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Orientation {
    pub dip: f64,
    pub dip_direction: f64,
}

/// A line: plunge (down from horizontal) and trend (deg).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    pub plunge: f64,
    pub trend: f64,
}

impl Orientation {
    /// The upward unit normal `(sin(dip) sin(dd), sin(dip) cos(dd), cos(dip))`.
    pub fn normal(&self) -> [f64; 3] {
        let (d, a) = (self.dip.to_radians(), self.dip_direction.to_radians());
        [d.sin() * a.sin(), d.sin() * a.cos(), d.cos()]
    }
    /// The pole: the downward normal, plunging `90 - dip` towards `dd + 180`.
    pub fn pole(&self) -> Line {
        Line { plunge: 90.0 - self.dip, trend: (self.dip_direction + 180.0).rem_euclid(360.0) }
    }
    /// The plane's apparent dip along `trend` (deg, negative when the plane
    /// rises that way): `atan(tan(dip) cos(trend - dd))`.
    pub fn apparent_dip(&self, trend: f64) -> f64 {
        (self.dip.to_radians().tan() * (trend - self.dip_direction).to_radians().cos()).atan().to_degrees()
    }
}

/// The smallest angle between two azimuths (deg, in [0, 180]).
pub fn azimuth_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

/// The line of intersection of two planes, as a downward line; `None` for
/// parallel planes.
pub fn intersection(a: Orientation, b: Orientation) -> Option<Line> {
    let (n, m) = (a.normal(), b.normal());
    let i = [n[1] * m[2] - n[2] * m[1], n[2] * m[0] - n[0] * m[2], n[0] * m[1] - n[1] * m[0]];
    let len = (i[0] * i[0] + i[1] * i[1] + i[2] * i[2]).sqrt();
    if len < 1e-9 {
        return None;
    }
    let s = if i[2] > 0.0 { -1.0 / len } else { 1.0 / len };
    let i = i.map(|c| c * s);
    Some(Line {
        plunge: (-i[2]).clamp(-1.0, 1.0).asin().to_degrees(),
        trend: i[0].atan2(i[1]).to_degrees().rem_euclid(360.0),
    })
}

/// A joint set as the kinematic tests see it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SetInput {
    pub orientation: Orientation,
    /// Friction angle (deg).
    pub friction: f64,
}

/// One set's tests.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SetTests {
    pub set: usize,
    pub plane_sliding: bool,
    pub flexural_toppling: bool,
}

/// One pair's test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairTest {
    pub sets: (usize, usize),
    /// `None`: parallel sets.
    pub intersection: Option<Line>,
    /// The face's apparent dip along the intersection's trend (deg).
    pub face_apparent_dip: f64,
    pub wedge_sliding: bool,
}

/// Plane sliding of `s` on a face `face`.
pub fn plane_sliding(s: SetInput, face: Orientation) -> bool {
    let o = s.orientation;
    o.dip < face.dip && o.dip > s.friction && azimuth_difference(o.dip_direction, face.dip_direction) <= LATERAL_LIMIT
}

/// Flexural toppling of `s` on a face `face`.
pub fn flexural_toppling(s: SetInput, face: Orientation) -> bool {
    let o = s.orientation;
    azimuth_difference(o.dip_direction, face.dip_direction + 180.0) <= LATERAL_LIMIT
        && (90.0 - o.dip) + s.friction < face.dip
}

/// Wedge sliding on the pair `(a, b)`.
pub fn wedge(a: SetInput, b: SetInput, face: Orientation, sets: (usize, usize)) -> PairTest {
    let line = intersection(a.orientation, b.orientation);
    let (face_apparent_dip, wedge_sliding) = match line {
        None => (f64::NAN, false),
        Some(l) => {
            let app = face.apparent_dip(l.trend);
            let out_of_face = azimuth_difference(l.trend, face.dip_direction) < 90.0;
            (app, out_of_face && l.plunge < app && l.plunge > a.friction.min(b.friction))
        }
    };
    PairTest { sets, intersection: line, face_apparent_dip, wedge_sliding }
}

/// Every set's and every pair's tests.
pub fn analyse(sets: &[SetInput], face: Orientation) -> (Vec<SetTests>, Vec<PairTest>) {
    let singles = sets
        .iter()
        .enumerate()
        .map(|(i, &s)| SetTests {
            set: i,
            plane_sliding: plane_sliding(s, face),
            flexural_toppling: flexural_toppling(s, face),
        })
        .collect();
    let mut pairs = Vec::new();
    for i in 0..sets.len() {
        for j in i + 1..sets.len() {
            pairs.push(wedge(sets[i], sets[j], face, (i, j)));
        }
    }
    (singles, pairs)
}

/// Lower-hemisphere equal-area (Schmidt) projection of a line onto the unit
/// disc: `r = sqrt(2) sin((90 - plunge) / 2)`, `(x, y) = r (sin(trend), cos(trend))`
/// (north up).
pub fn equal_area(l: Line) -> (f64, f64) {
    let r = std::f64::consts::SQRT_2 * ((90.0 - l.plunge).to_radians() / 2.0).sin();
    let t = l.trend.to_radians();
    (r * t.sin(), r * t.cos())
}

/// A plane's great circle: the projections of its lines `cos(a) s + sin(a) d`
/// for `a` from 0 to 180 deg (`s` along strike, `d` down the dip), so that a
/// vertical plane's is a diameter.
pub fn great_circle(o: Orientation, n: usize) -> Vec<(f64, f64)> {
    let (dip, dd) = (o.dip.to_radians(), o.dip_direction.to_radians());
    let s = [(dd - std::f64::consts::FRAC_PI_2).sin(), (dd - std::f64::consts::FRAC_PI_2).cos(), 0.0];
    let d = [dip.cos() * dd.sin(), dip.cos() * dd.cos(), -dip.sin()];
    (0..=n)
        .map(|k| {
            let a = std::f64::consts::PI * k as f64 / n as f64;
            let v = [0, 1, 2].map(|i| a.cos() * s[i] + a.sin() * d[i]);
            let plunge = (-v[2]).clamp(-1.0, 1.0).asin().to_degrees().max(0.0);
            equal_area(Line { plunge, trend: v[0].atan2(v[1]).to_degrees() })
        })
        .collect()
}

/// The circle of lines plunging `plunge` (a friction circle of the wedge test).
pub fn small_circle(plunge: f64, n: usize) -> Vec<(f64, f64)> {
    (0..=n).map(|k| equal_area(Line { plunge, trend: 360.0 * k as f64 / n as f64 })).collect()
}
