//! Joint sets to a mesh (`cdem mesh GEOMETRY.toml --out DIR`): a slope and
//! its `[[joint_set]]` tables, as a rock engineer describes them (dip, dip
//! direction, spacing, offset), made into a gmsh `.geo` with the OpenCASCADE
//! kernel, meshed by gmsh, and a scene skeleton beside it.
//!
//! The model frame is geographic: x east, y north, z up; the origin is the
//! toe at the middle of the model's width. The slope is a section in the
//! vertical plane of the face's dip direction, extruded along strike:
//!
//! ```text
//!            crest      crest_bench
//!   z = H       +--------------------+
//!              /                     |     the face dips at face_dip towards
//!   toe_bench / face                 |     face_dip_direction (out of the
//!   +--------+ (toe, origin)         |     slope); the top is horizontal
//!   |                                |
//!   +--------------------------------+  z = -base
//!   front                         back
//! ```
//!
//! Each set's planes are `n . p = offset + k spacing` for every integer `k`
//! whose plane cuts the rock volume (`n` the plane's upward unit normal,
//! `p` measured from the origin); without `spacing`, the one plane
//! `n . p = offset`. Planes are persistent (they cross the whole model): the
//! only `extent` there is. The `.geo` cuts each plane's square to the rock
//! volume (`BooleanIntersection`), fragments the volume with all of them
//! (`BooleanFragments`), and then groups the surfaces by the plane they lie
//! on (every point of the surface within `1e-7` of the model size of it):
//! `set1`, `set2`, ... (the surfaces between two volumes), and the outer
//! `bottom`, `back`, `front` (with a toe bench), `sides` (both ends of the
//! width); one volume group `rock`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::error::{Error, SceneError};
use crate::model::spec::StrengthSection;

/// At most this many planes in one set (a spacing far below the model's size
/// is a typo, not a rock mass).
pub const MAX_PLANES_PER_SET: usize = 200;

/// A geometry file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Geometry {
    /// The stem of the files written (default: the geometry file's stem).
    pub name: Option<String>,
    /// gmsh's largest element size (m).
    pub mesh_size: f64,
    pub slope: Slope,
    pub rock: Rock,
    #[serde(default)]
    pub joint_set: Vec<JointSet>,
}

/// The slope: a section extruded along strike.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Slope {
    /// Toe to crest (m).
    pub height: f64,
    /// Face dip (degrees, in (0, 90]).
    pub face_dip: f64,
    /// Face dip direction (degrees clockwise from north).
    pub face_dip_direction: f64,
    /// Horizontal distance from the crest to the back of the model (m, > 0).
    pub crest_bench: f64,
    /// Horizontal distance from the toe to the front of the model (m, >= 0).
    #[serde(default)]
    pub toe_bench: f64,
    /// Depth of the model below the toe (m, > 0).
    pub base: f64,
    /// Extent along strike (m, > 0), centred on the origin.
    pub width: f64,
}

/// The intact rock between the joints (one linear-elastic material).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rock {
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    pub density: f64,
}

/// One joint set and its joints' properties (as an `[[interface]]`).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointSet {
    /// Dip (degrees, in [0, 90]).
    pub dip: f64,
    /// Dip direction (degrees clockwise from north).
    pub dip_direction: f64,
    /// Distance between the set's planes along their normal (m, > 0);
    /// absent: one plane.
    pub spacing: Option<f64>,
    /// Signed distance of one plane from the origin along the upward normal (m).
    #[serde(default)]
    pub offset: f64,
    /// `"persistent"` (the default and, for now, the only extent).
    pub extent: Option<String>,
    /// `E_j`, `G_j` (Pa) and `L` (m) of the set's springs.
    pub normal_modulus: f64,
    pub shear_modulus: f64,
    #[serde(default = "one")]
    pub thickness: f64,
    pub strength: Option<StrengthSection>,
}

fn one() -> f64 {
    1.0
}

type V3 = [f64; 3];

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn unit(a: V3) -> V3 {
    let n = dot(a, a).sqrt();
    a.map(|x| x / n)
}

/// The upward unit normal of a plane of dip `dip` towards `dip_direction`
/// (degrees): `(sin(dip) sin(dd), sin(dip) cos(dd), cos(dip))`.
pub fn plane_normal(dip: f64, dip_direction: f64) -> V3 {
    let (d, a) = (dip.to_radians(), dip_direction.to_radians());
    snap([d.sin() * a.sin(), d.sin() * a.cos(), d.cos()])
}

/// A unit vector with the round-off of `sin(180 deg)` and the like set to
/// zero (so that a face dipping west gives the points of the model exact
/// y coordinates).
fn snap(v: V3) -> V3 {
    v.map(|c| if c.abs() < 1e-15 { 0.0 } else { c })
}

/// A plane `n . p = d` of the model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    pub normal: V3,
    pub d: f64,
}

impl Geometry {
    /// Reads and checks a geometry file.
    pub fn load(path: &Path) -> crate::Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        Ok(Self::from_toml(&text, path)?)
    }

    pub fn from_toml(text: &str, path_for_errors: &Path) -> Result<Self, SceneError> {
        let g: Geometry = toml::from_str(text)
            .map_err(|e| SceneError::Syntax { path: path_for_errors.to_path_buf(), message: e.to_string() })?;
        g.validate()?;
        Ok(g)
    }

    /// Every value in its range, every set with a plane in the volume.
    pub fn validate(&self) -> Result<(), SceneError> {
        let bad = |key: &str, reason: &str| Err(SceneError::invalid(key, reason));
        let positive =
            |key: &str, v: f64| if v.is_finite() && v > 0.0 { Ok(()) } else { bad(key, "must be finite and > 0") };
        positive("mesh_size", self.mesh_size)?;
        let s = &self.slope;
        positive("slope.height", s.height)?;
        if !(s.face_dip > 0.0 && s.face_dip <= 90.0) {
            return bad("slope.face_dip", "must be in (0, 90] degrees");
        }
        if !s.face_dip_direction.is_finite() {
            return bad("slope.face_dip_direction", "must be finite");
        }
        positive("slope.crest_bench", s.crest_bench)?;
        if !(s.toe_bench.is_finite() && s.toe_bench >= 0.0) {
            return bad("slope.toe_bench", "must be finite and >= 0");
        }
        positive("slope.base", s.base)?;
        positive("slope.width", s.width)?;
        positive("rock.youngs_modulus", self.rock.youngs_modulus)?;
        positive("rock.density", self.rock.density)?;
        if !(self.rock.poisson_ratio > -1.0 && self.rock.poisson_ratio < 0.5) {
            return bad("rock.poisson_ratio", "must be in (-1, 0.5)");
        }
        if let Some(name) = &self.name {
            if name.is_empty() || name.contains(['/', '\\']) {
                return bad("name", "must be a file stem (not empty, no path separators)");
            }
        }
        for (i, j) in self.joint_set.iter().enumerate() {
            let key = |k: &str| format!("joint_set[{i}].{k}");
            if !(j.dip >= 0.0 && j.dip <= 90.0) {
                return bad(&key("dip"), "must be in [0, 90] degrees");
            }
            if !j.dip_direction.is_finite() {
                return bad(&key("dip_direction"), "must be finite");
            }
            if !j.offset.is_finite() {
                return bad(&key("offset"), "must be finite");
            }
            if let Some(sp) = j.spacing {
                positive(&key("spacing"), sp)?;
            }
            if let Some(e) = &j.extent {
                if e != "persistent" {
                    return bad(&key("extent"), "only \"persistent\" (planes across the whole model) is implemented");
                }
            }
            positive(&key("normal_modulus"), j.normal_modulus)?;
            positive(&key("shear_modulus"), j.shear_modulus)?;
            positive(&key("thickness"), j.thickness)?;
            if let Some(st) = j.strength {
                if let Err((name, why)) = st.check() {
                    return bad(&key(&format!("strength.{name}")), &why);
                }
            }
            self.set_planes(i)?;
        }
        Ok(())
    }

    /// The horizontal unit vector into the slope (against the face's dip
    /// direction) and the strike vector (`z x u`), in the model frame.
    pub fn frame(&self) -> (V3, V3) {
        let a = self.slope.face_dip_direction.to_radians();
        let u = snap([-a.sin(), -a.cos(), 0.0]);
        (u, snap(cross([0.0, 0.0, 1.0], u)))
    }

    /// Where the crest is, along `u` from the toe (m).
    pub fn crest_u(&self) -> f64 {
        let s = &self.slope;
        if s.face_dip >= 90.0 {
            0.0
        } else {
            s.height / s.face_dip.to_radians().tan()
        }
    }

    /// The back of the model along `u` (m).
    pub fn back_u(&self) -> f64 {
        self.crest_u() + self.slope.crest_bench
    }

    /// The section's corners `(u, z)`, counter-clockwise seen from `-strike`.
    pub fn section(&self) -> Vec<[f64; 2]> {
        let s = &self.slope;
        let (uc, ub) = (self.crest_u(), self.back_u());
        let mut pts = vec![[-s.toe_bench, -s.base], [ub, -s.base], [ub, s.height], [uc, s.height], [0.0, 0.0]];
        if s.toe_bench > 0.0 {
            pts.push([-s.toe_bench, 0.0]);
        }
        pts
    }

    /// A section point at strike coordinate `w` in the model frame.
    pub fn point(&self, uz: [f64; 2], w: f64) -> V3 {
        let (u, s) = self.frame();
        [0, 1, 2].map(|d| uz[0] * u[d] + w * s[d] + if d == 2 { uz[1] } else { 0.0 })
    }

    /// The rock volume's corners (both ends of the width).
    pub fn corners(&self) -> Vec<V3> {
        let h = 0.5 * self.slope.width;
        let sec = self.section();
        sec.iter().map(|&p| self.point(p, -h)).chain(sec.iter().map(|&p| self.point(p, h))).collect()
    }

    /// The model's size: its bounding box diagonal (m).
    pub fn size(&self) -> f64 {
        let c = self.corners();
        let lo = [0, 1, 2].map(|d| c.iter().map(|p| p[d]).fold(f64::INFINITY, f64::min));
        let hi = [0, 1, 2].map(|d| c.iter().map(|p| p[d]).fold(f64::NEG_INFINITY, f64::max));
        (0..3).map(|d| (hi[d] - lo[d]).powi(2)).sum::<f64>().sqrt()
    }

    /// The planes of set `i` that cut the rock volume (a plane through a
    /// corner only, or along a face of the volume, is left out). An error
    /// names the set when none does, or when there are too many.
    pub fn set_planes(&self, i: usize) -> Result<Vec<Plane>, SceneError> {
        let j = &self.joint_set[i];
        let n = plane_normal(j.dip, j.dip_direction);
        let values: Vec<f64> = self.corners().iter().map(|&p| dot(n, p)).collect();
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let eps = 1e-6 * self.size();
        let inside = |d: f64| d > lo + eps && d < hi - eps;
        let ds: Vec<f64> = match j.spacing {
            None => vec![j.offset].into_iter().filter(|&d| inside(d)).collect(),
            Some(sp) => {
                let k0 = ((lo - j.offset) / sp).ceil() as i64;
                let k1 = ((hi - j.offset) / sp).floor() as i64;
                if k1 - k0 + 1 > MAX_PLANES_PER_SET as i64 {
                    return Err(SceneError::invalid(
                        format!("joint_set[{i}].spacing"),
                        format!("{} planes cut the model (at most {MAX_PLANES_PER_SET})", k1 - k0 + 1),
                    ));
                }
                (k0..=k1).map(|k| j.offset + k as f64 * sp).filter(|&d| inside(d)).collect()
            }
        };
        if ds.is_empty() {
            return Err(SceneError::invalid(
                format!("joint_set[{i}].offset"),
                format!("no plane of the set cuts the rock volume (n . p spans [{lo:.3}, {hi:.3}] m over it)"),
            ));
        }
        Ok(ds.into_iter().map(|d| Plane { normal: n, d }).collect())
    }

    /// The outer planes grouped for the boundary conditions: `bottom`,
    /// `back`, `front` (only with a toe bench) and `sides` (two planes).
    pub fn boundary_planes(&self) -> Vec<(&'static str, Vec<Plane>)> {
        let (u, s) = self.frame();
        let h = 0.5 * self.slope.width;
        let mut out = vec![
            ("bottom", vec![Plane { normal: [0.0, 0.0, 1.0], d: -self.slope.base }]),
            ("back", vec![Plane { normal: u, d: self.back_u() }]),
        ];
        if self.slope.toe_bench > 0.0 {
            out.push(("front", vec![Plane { normal: u, d: -self.slope.toe_bench }]));
        }
        out.push(("sides", vec![Plane { normal: s, d: -h }, Plane { normal: s, d: h }]));
        out
    }

    /// The `.geo` (the source of truth of the mesh).
    pub fn geo(&self, source: &str) -> Result<String, SceneError> {
        let mut g = String::new();
        let size = self.size();
        let w = |g: &mut String, s: String| {
            g.push_str(&s);
            g.push('\n');
        };
        w(
            &mut g,
            format!(
                "// Written by `cdem mesh {source}` (src/scene/joint_sets.rs): do not edit; edit the geometry file."
            ),
        );
        w(&mut g, "// The rock volume fragmented by the joint sets' planes (gmsh's OpenCASCADE kernel).".into());
        w(&mut g, "SetFactory(\"OpenCASCADE\");".into());
        w(&mut g, "Mesh.MshFileVersion = 4.1;".into());
        w(&mut g, format!("Mesh.MeshSizeMax = {};", self.mesh_size));
        w(&mut g, "Geometry.Tolerance = 1e-9;".into());
        w(&mut g, String::new());
        w(&mut g, "// The section, extruded along strike.".into());
        let sec = self.section();
        let h = 0.5 * self.slope.width;
        for (k, &p) in sec.iter().enumerate() {
            let [x, y, z] = self.point(p, -h);
            w(&mut g, format!("Point({}) = {{{x}, {y}, {z}}};", k + 1));
        }
        let m = sec.len();
        for k in 0..m {
            w(&mut g, format!("Line({}) = {{{}, {}}};", k + 1, k + 1, (k + 1) % m + 1));
        }
        let loop_: Vec<String> = (1..=m).map(|k| k.to_string()).collect();
        w(&mut g, format!("Curve Loop(1) = {{{}}};", loop_.join(", ")));
        w(&mut g, "Plane Surface(1) = {1};".into());
        let (_, s) = self.frame();
        let e = s.map(|c| c * self.slope.width);
        w(&mut g, format!("ex[] = Extrude {{{}, {}, {}}} {{ Surface{{1}}; }};", e[0], e[1], e[2]));
        w(&mut g, "rock = ex[1];".into());
        // The planes, each a square around the model cut to the volume.
        let c = self.corners();
        let centre = [0, 1, 2].map(|d| c.iter().map(|p| p[d]).sum::<f64>() / c.len() as f64);
        let mut tag = 100;
        let mut cut = Vec::new();
        for i in 0..self.joint_set.len() {
            for (k, pl) in self.set_planes(i)?.iter().enumerate() {
                let n = pl.normal;
                let off = dot(n, centre) - pl.d;
                let o = [0, 1, 2].map(|d| centre[d] - off * n[d]);
                let e1 =
                    if (n[0].abs() + n[1].abs()) > 1e-12 { unit(cross(n, [0.0, 0.0, 1.0])) } else { [1.0, 0.0, 0.0] };
                let e2 = cross(n, e1);
                w(&mut g, String::new());
                w(&mut g, format!("// set{} plane {k}: n . p = {}", i + 1, pl.d));
                let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
                for (q, (a, b)) in corners.iter().enumerate() {
                    let p = [0, 1, 2].map(|d| o[d] + size * (a * e1[d] + b * e2[d]));
                    w(&mut g, format!("Point({}) = {{{}, {}, {}}};", tag + q + 1, p[0], p[1], p[2]));
                }
                for q in 0..4 {
                    w(&mut g, format!("Line({}) = {{{}, {}}};", tag + q + 1, tag + q + 1, tag + (q + 1) % 4 + 1));
                }
                w(&mut g, format!("Curve Loop({}) = {{{}, {}, {}, {}}};", tag + 1, tag + 1, tag + 2, tag + 3, tag + 4));
                w(&mut g, format!("Plane Surface({}) = {{{}}};", tag + 1, tag + 1));
                w(
                    &mut g,
                    format!(
                        "j{tag}[] = BooleanIntersection{{ Surface{{{}}}; Delete; }}{{ Volume{{rock}}; }};",
                        tag + 1
                    ),
                );
                cut.push(format!("j{tag}[]"));
                tag += 10;
            }
        }
        w(&mut g, String::new());
        if !cut.is_empty() {
            w(
                &mut g,
                format!("BooleanFragments{{ Volume{{rock}}; Delete; }}{{ Surface{{{}}}; Delete; }}", cut.join(", ")),
            );
        }
        let tol = 1e-7 * size;
        g.push_str(&format!(
            r#"
// How many volumes each surface bounds (1: outer, 2: between two volumes).
all[] = Surface{{:}};
vols[] = Volume{{:}};
top = 0;
For i In {{0:#all[]-1}}
  top = (all[i] > top) ? all[i] : top;
EndFor
nvol[] = {{}};
For i In {{0:top}}
  nvol[] += 0;
EndFor
For v In {{0:#vols[]-1}}
  b[] = Abs(Boundary{{ Volume{{vols[v]}}; }});
  For q In {{0:#b[]-1}}
    nvol[b[q]] += 1;
  EndFor
EndFor

// on = 1 if every point of surface s lies on the plane nx x + ny y + nz z = dd.
tol = {tol};
Macro OnPlane
  on = 1;
  pts[] = PointsOf{{ Surface{{s}}; }};
  For q In {{0:#pts[]-1}}
    xyz[] = Point{{pts[q]}};
    If (Fabs(nx * xyz[0] + ny * xyz[1] + nz * xyz[2] - dd) > tol)
      on = 0;
    EndIf
  EndFor
Return
"#
        ));
        let mut groups: Vec<(String, usize, Vec<Plane>)> = Vec::new();
        for i in 0..self.joint_set.len() {
            groups.push((format!("set{}", i + 1), 2, self.set_planes(i)?));
        }
        for (name, planes) in self.boundary_planes() {
            groups.push((name.to_string(), 1, planes));
        }
        for (name, _, _) in &groups {
            w(&mut g, format!("{name}[] = {{}};"));
        }
        w(&mut g, "For i In {0:#all[]-1}".into());
        w(&mut g, "  s = all[i];".into());
        for (name, nvol, planes) in &groups {
            for pl in planes {
                let [nx, ny, nz] = pl.normal;
                w(&mut g, format!("  nx = {nx}; ny = {ny}; nz = {nz}; dd = {}; Call OnPlane;", pl.d));
                w(&mut g, format!("  If (on && nvol[s] == {nvol}) {name}[] += s; EndIf"));
            }
        }
        w(&mut g, "EndFor".into());
        w(&mut g, String::new());
        w(&mut g, "Physical Volume(\"rock\") = vols[];".into());
        for (name, _, _) in &groups {
            w(&mut g, format!("Physical Surface(\"{name}\") = {name}[];"));
        }
        Ok(g)
    }

    /// The scene skeleton: the rock, merged between the joints (`[joints]`
    /// mode `"merged"`), one `[[interface]]` per set, the outer groups held,
    /// gravity. `msh` is the mesh's file name beside it.
    pub fn scene_skeleton(&self, msh: &str, source: &str) -> String {
        let mut t = String::new();
        let r = &self.rock;
        let _ = writeln!(t, "# Scene skeleton written by `cdem mesh {source}`: edit before use.");
        let _ = writeln!(t, "[mesh]\nfile = \"{msh}\"\n");
        let _ = writeln!(
            t,
            "[[material]]\ngroup = \"rock\"\nyoungs_modulus = {:?}\npoisson_ratio = {:?}\ndensity = {:?}\n",
            r.youngs_modulus, r.poisson_ratio, r.density
        );
        let _ = writeln!(t, "# The intact rock between the joints is continuous.\n[joints]\nmode = \"merged\"\n");
        for (i, j) in self.joint_set.iter().enumerate() {
            let spacing = j.spacing.map_or("one plane".to_string(), |s| format!("spacing {s} m"));
            let _ = writeln!(
                t,
                "# set{}: dip {} towards {}, {spacing}, offset {} m\n[[interface]]\ngroup = \"set{}\"\nnormal_modulus = {:?}\nshear_modulus = {:?}\nthickness = {:?}",
                i + 1,
                j.dip,
                j.dip_direction,
                j.offset,
                i + 1,
                j.normal_modulus,
                j.shear_modulus,
                j.thickness
            );
            if let Some(s) = j.strength {
                let _ = writeln!(t, "strength = {}", s.to_toml());
            }
            t.push('\n');
        }
        let (_, s) = self.frame();
        let sides = match s.iter().position(|c| (c.abs() - 1.0).abs() < 1e-12) {
            Some(0) => "[\"x\"]",
            Some(1) => "[\"y\"]",
            _ => "[\"x\", \"y\", \"z\"]",
        };
        for (name, _) in self.boundary_planes() {
            let fix = if name == "sides" { sides } else { "[\"x\", \"y\", \"z\"]" };
            let _ = writeln!(t, "[[boundary]]\ngroup = \"{name}\"\nfix = {fix}\n");
        }
        let _ = writeln!(t, "[loads]\ngravity = [0.0, 0.0, -9.81]");
        t
    }
}

/// What `cdem mesh GEOMETRY.toml` wrote.
#[derive(Debug, Clone)]
pub struct Meshed {
    pub geo: PathBuf,
    pub msh: PathBuf,
    pub scene: PathBuf,
}

/// `cdem mesh GEOMETRY.toml --out DIR`: writes `DIR/NAME.geo`, meshes it
/// with gmsh into `DIR/NAME.msh` and writes the skeleton `DIR/NAME.toml`
/// (not over the geometry file itself: then `NAME-scene.toml`).
pub fn mesh_geometry(path: &Path, dir: &Path) -> crate::Result<Meshed> {
    let g = Geometry::load(path)?;
    let stem = g.name.clone().unwrap_or_else(|| path.file_stem().unwrap_or_default().to_string_lossy().into_owned());
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let source = path.file_name().unwrap_or_default().to_string_lossy().into_owned();
    let geo = dir.join(format!("{stem}.geo"));
    let msh = dir.join(format!("{stem}.msh"));
    let mut scene = dir.join(format!("{stem}.toml"));
    if same_file(&scene, path) {
        scene = dir.join(format!("{stem}-scene.toml"));
    }
    crate::atomic::write_atomic(&geo, g.geo(&source)?.as_bytes()).map_err(|e| Error::io(&geo, e))?;
    crate::mesh::gmsh::regenerate(&geo, &msh)?;
    let msh_name = msh.file_name().unwrap_or_default().to_string_lossy().into_owned();
    crate::atomic::write_atomic(&scene, g.scene_skeleton(&msh_name, &source).as_bytes())
        .map_err(|e| Error::io(&scene, e))?;
    Ok(Meshed { geo, msh, scene })
}

fn same_file(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}
