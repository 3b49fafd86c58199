//! The 2D section: ground polyline, lower bound of slip surfaces, materials.
//!
//! The ground is a polyline `(x, z)` with x strictly increasing (a vertical
//! face needs two x a little apart). Materials fill the section between the
//! ground and the lower bound: a zone polygon gives its own material (the
//! first zone listed that contains a point wins); a point in no zone takes
//! the background material. One background material and no zones is the
//! homogeneous case. Slip circles may not pass below the lower bound (a
//! level `z_min` or a polyline whose x-range covers the ground's).
//!
//! Internally every section is held facing -x (the crest on the right, the
//! sliding mass moving toward -x): a section facing +x is mirrored, x -> -x.

use serde::Serialize;

use crate::error::SceneError;
use crate::mesh::Mesh;

use super::water::Water;

/// Soil or rock strength and weight (Mohr-Coulomb, dry).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Material {
    /// Effective cohesion `c'` (Pa).
    pub cohesion: f64,
    /// Effective friction angle `phi'` (deg).
    pub friction_angle: f64,
    /// Unit weight `gamma` (N/m^3).
    pub unit_weight: f64,
}

/// A material zone: a closed polygon (the last vertex joins the first).
#[derive(Debug, Clone, PartialEq)]
pub struct Zone {
    pub polygon: Vec<[f64; 2]>,
    pub material: Material,
}

/// Where slip circles may not go.
#[derive(Debug, Clone, PartialEq)]
pub enum LowerBound {
    /// No slip surface below this z (m).
    Level(f64),
    /// No slip surface below this polyline (x strictly increasing).
    Polyline(Vec<[f64; 2]>),
}

/// The direction the slope face looks, i.e. the direction of sliding.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Facing {
    /// Down-slope toward -x: crest on the right (the paper's section).
    Left,
    /// Down-slope toward +x: crest on the left.
    Right,
}

/// Material in the form the kernels use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Strength {
    pub c: f64,
    pub tan_phi: f64,
    pub gamma: f64,
}

impl From<Material> for Strength {
    fn from(m: Material) -> Self {
        Strength { c: m.cohesion, tan_phi: m.friction_angle.to_radians().tan(), gamma: m.unit_weight }
    }
}

/// A validated section, with its internal (facing -x) copy.
#[derive(Debug, Clone, PartialEq)]
pub struct LemSection {
    ground: Vec<[f64; 2]>,
    lower_bound: LowerBound,
    background: Option<Material>,
    zones: Vec<Zone>,
    facing: Facing,
    water: Water,
    pub(crate) frame: Frame,
}

/// The section facing -x, as the kernels see it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Frame {
    pub ground: Vec<[f64; 2]>,
    pub lower: LowerBound,
    pub background: Option<Strength>,
    pub zones: Vec<(Vec<[f64; 2]>, Strength)>,
    pub mirrored: bool,
    /// The section's water, mirrored with it.
    pub water: Water,
    /// Heuristic toe and crest (internal frame), for default search ranges.
    pub toe: [f64; 2],
    pub crest: [f64; 2],
}

impl Frame {
    pub fn homogeneous(&self) -> Option<Strength> {
        if self.zones.is_empty() {
            self.background
        } else {
            None
        }
    }

    /// Slope height `H` (crest minus toe), at least 1e-3 of the ground's length.
    pub fn height(&self) -> f64 {
        let len = self.ground[self.ground.len() - 1][0] - self.ground[0][0];
        (self.crest[1] - self.toe[1]).max(1e-3 * len)
    }

    /// x in the user's frame <-> x in the internal frame (an involution).
    pub fn x(&self, x: f64) -> f64 {
        if self.mirrored {
            -x
        } else {
            x
        }
    }

    /// The strength at a point: first zone containing it, else background.
    pub fn strength_at(&self, p: [f64; 2]) -> Option<Strength> {
        for (poly, s) in &self.zones {
            if point_in_polygon(poly, p) {
                return Some(*s);
            }
        }
        self.background
    }
}

fn mirror(poly: &[[f64; 2]], reverse: bool) -> Vec<[f64; 2]> {
    let mut v: Vec<[f64; 2]> = poly.iter().map(|p| [-p[0], p[1]]).collect();
    if reverse {
        v.reverse();
    }
    v
}

fn check_polyline(key: &str, pts: &[[f64; 2]]) -> Result<(), SceneError> {
    if pts.len() < 2 {
        return Err(SceneError::invalid(key, "needs at least two points"));
    }
    for (i, p) in pts.iter().enumerate() {
        if !p[0].is_finite() || !p[1].is_finite() {
            return Err(SceneError::invalid(format!("{key}[{i}]"), "coordinate is not finite"));
        }
        if i > 0 && p[0] <= pts[i - 1][0] {
            return Err(SceneError::invalid(format!("{key}[{i}]"), "x must increase strictly along the polyline"));
        }
    }
    Ok(())
}

pub(crate) fn check_material(key: &str, m: &Material) -> Result<(), SceneError> {
    if !(m.cohesion.is_finite() && m.cohesion >= 0.0) {
        return Err(SceneError::invalid(format!("{key}.cohesion"), "must be finite and >= 0 (Pa)"));
    }
    if !(m.friction_angle.is_finite() && (0.0..90.0).contains(&m.friction_angle)) {
        return Err(SceneError::invalid(format!("{key}.friction_angle"), "must be in [0, 90) degrees"));
    }
    if !(m.unit_weight.is_finite() && m.unit_weight > 0.0) {
        return Err(SceneError::invalid(format!("{key}.unit_weight"), "must be finite and > 0 (N/m^3)"));
    }
    if m.cohesion == 0.0 && m.friction_angle == 0.0 {
        return Err(SceneError::invalid(key, "cohesion and friction angle are both zero: no strength"));
    }
    Ok(())
}

/// Height of a polyline at x (linear interpolation; clamped at the ends).
pub(crate) fn polyline_z(p: &[[f64; 2]], x: f64) -> f64 {
    let i = p.partition_point(|q| q[0] <= x);
    if i == 0 {
        return p[0][1];
    }
    if i >= p.len() {
        return p[p.len() - 1][1];
    }
    let (a, b) = (p[i - 1], p[i]);
    a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0])
}

pub(crate) fn point_in_polygon(poly: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut inside = false;
    let n = poly.len();
    let mut j = n - 1;
    for i in 0..n {
        let (a, b) = (poly[i], poly[j]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0] {
            inside = !inside;
        }
        j = i;
    }
    inside
}

impl LemSection {
    /// Validates a section. `facing: None` infers it from the ground's ends
    /// (higher right end: faces -x). Errors name the TOML key they concern.
    pub fn new(
        ground: Vec<[f64; 2]>,
        lower_bound: LowerBound,
        background: Option<Material>,
        zones: Vec<Zone>,
        facing: Option<Facing>,
    ) -> Result<Self, SceneError> {
        check_polyline("section.ground", &ground)?;
        let (gx0, gx1) = (ground[0][0], ground[ground.len() - 1][0]);
        match &lower_bound {
            LowerBound::Level(z) => {
                let zg = ground.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
                if !z.is_finite() || *z > zg {
                    return Err(SceneError::invalid(
                        "section.z_min",
                        format!("must be finite and at or below the lowest ground point (z = {zg}; at it: a base at toe level)"),
                    ));
                }
            }
            LowerBound::Polyline(lb) => {
                check_polyline("section.lower_bound", lb)?;
                if lb[0][0] > gx0 || lb[lb.len() - 1][0] < gx1 {
                    return Err(SceneError::invalid("section.lower_bound", "its x-range must cover the ground's"));
                }
                let below = ground.iter().all(|p| polyline_z(lb, p[0]) < p[1])
                    && lb.iter().filter(|q| q[0] >= gx0 && q[0] <= gx1).all(|q| q[1] < polyline_z(&ground, q[0]));
                if !below {
                    return Err(SceneError::invalid("section.lower_bound", "must lie below the ground everywhere"));
                }
            }
        }
        if background.is_none() && zones.is_empty() {
            return Err(SceneError::invalid("material", "at least one material is needed"));
        }
        if let Some(m) = &background {
            check_material("material", m)?;
        }
        for (i, z) in zones.iter().enumerate() {
            let key = format!("material[{i}]");
            check_material(&key, &z.material)?;
            if z.polygon.len() < 3 || z.polygon.iter().any(|p| !p[0].is_finite() || !p[1].is_finite()) {
                return Err(SceneError::invalid(format!("{key}.zone"), "needs at least three finite vertices"));
            }
        }
        let facing = match facing {
            Some(f) => f,
            None if ground[ground.len() - 1][1] > ground[0][1] => Facing::Left,
            None if ground[ground.len() - 1][1] < ground[0][1] => Facing::Right,
            None => {
                return Err(SceneError::invalid(
                    "section.facing",
                    "the ground's ends are level: say which way the slope faces (\"left\" or \"right\")",
                ))
            }
        };
        let frame = build_frame(&ground, &lower_bound, background, &zones, facing);
        Ok(LemSection { ground, lower_bound, background, zones, facing, water: Water::default(), frame })
    }

    /// The section with pore water and a tension crack (checked against the
    /// ground; errors name the `[water]` key).
    pub fn with_water(mut self, water: Water) -> Result<Self, SceneError> {
        water.check(&self.ground)?;
        self.frame.water = if self.frame.mirrored { water.mirrored() } else { water.clone() };
        self.water = water;
        Ok(self)
    }

    pub fn water(&self) -> &Water {
        &self.water
    }

    /// The slope section of a 3D mesh: the nodes of the surface group
    /// `ground_group` (optionally only those with `|y - y_plane| < 1e-6 m`)
    /// projected on the x-z plane, one point per distinct x (nodes whose x
    /// agree within 1e-9 of the model size must agree in z too, else the
    /// ground is not a function of x: error). The lower bound is the lowest
    /// node of the mesh. Materials are added by the caller.
    pub fn from_mesh(
        mesh: &Mesh,
        ground_group: &str,
        y_plane: Option<f64>,
    ) -> Result<(Vec<[f64; 2]>, f64), SceneError> {
        let key = "section.ground_group";
        let g = mesh
            .group(ground_group)
            .filter(|g| g.dim == 2)
            .ok_or_else(|| SceneError::invalid(key, format!("{ground_group:?} is not a surface group of the mesh")))?;
        let mut pts: Vec<[f64; 2]> = mesh
            .group_nodes(g)
            .into_iter()
            .map(|i| mesh.nodes[i])
            .filter(|p| y_plane.is_none_or(|y| (p[1] - y).abs() < 1e-6))
            .map(|p| [p[0], p[2]])
            .collect();
        if pts.len() < 2 {
            return Err(SceneError::invalid(key, "fewer than two ground nodes (check section.y_plane)"));
        }
        pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        let size = pts[pts.len() - 1][0] - pts[0][0];
        let tol = 1e-9 * size.max(1.0);
        let mut ground: Vec<[f64; 2]> = Vec::with_capacity(pts.len());
        for p in pts {
            match ground.last() {
                Some(q) if (p[0] - q[0]).abs() <= tol => {
                    if (p[1] - q[1]).abs() > tol {
                        return Err(SceneError::invalid(
                            key,
                            format!(
                                "the ground has two heights ({} and {}) at x = {}: not a function of x",
                                q[1], p[1], p[0]
                            ),
                        ));
                    }
                }
                _ => ground.push(p),
            }
        }
        let z_min = mesh.nodes.iter().map(|p| p[2]).fold(f64::INFINITY, f64::min);
        Ok((ground, z_min))
    }

    pub fn ground(&self) -> &[[f64; 2]] {
        &self.ground
    }
    pub fn lower_bound(&self) -> &LowerBound {
        &self.lower_bound
    }
    pub fn background(&self) -> Option<&Material> {
        self.background.as_ref()
    }
    pub fn zones(&self) -> &[Zone] {
        &self.zones
    }
    pub fn facing(&self) -> Facing {
        self.facing
    }
    /// The facing the ground's ends suggest (the crest at the higher end),
    /// None if they are level.
    pub fn ground_facing(&self) -> Option<Facing> {
        let (z0, z1) = (self.ground[0][1], self.ground[self.ground.len() - 1][1]);
        (z0 != z1).then_some(if z1 > z0 { Facing::Left } else { Facing::Right })
    }
    /// Ground height at x (m).
    pub fn ground_z(&self, x: f64) -> f64 {
        polyline_z(&self.ground, x)
    }
}

fn build_frame(
    ground: &[[f64; 2]],
    lower: &LowerBound,
    background: Option<Material>,
    zones: &[Zone],
    facing: Facing,
) -> Frame {
    let mirrored = facing == Facing::Right;
    let line = |p: &[[f64; 2]]| if mirrored { mirror(p, true) } else { p.to_vec() };
    let g = line(ground);
    let lower = match lower {
        LowerBound::Level(z) => LowerBound::Level(*z),
        LowerBound::Polyline(p) => LowerBound::Polyline(line(p)),
    };
    let zones = zones
        .iter()
        .map(|z| (if mirrored { mirror(&z.polygon, false) } else { z.polygon.clone() }, Strength::from(z.material)))
        .collect();
    let (toe, crest) = toe_and_crest(&g);
    Frame {
        ground: g,
        lower,
        background: background.map(Strength::from),
        zones,
        mirrored,
        water: Water::default(),
        toe,
        crest,
    }
}

/// Toe: the last vertex within 1 % of H of the lowest ground level before
/// the ground first comes within 1 % of H of its highest level (the crest).
fn toe_and_crest(g: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let zlo = g.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
    let zhi = g.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
    let tol = 0.01 * (zhi - zlo);
    let k = g.iter().position(|p| p[1] >= zhi - tol).unwrap_or(g.len() - 1);
    let t = g[..=k].iter().rposition(|p| p[1] <= zlo + tol).unwrap_or(0);
    (g[t], g[k])
}

/// The material zones of a 3D mesh on a section plane `y = y_plane`: for every
/// volume group with element faces on the mesh's outer surface in that plane,
/// the outer boundary loops of those faces, as polygons in `(x, z)`.
///
/// Each face is oriented counter-clockwise in `(x, z)`; the edges of a group
/// that no other face of the same group runs back along form its boundary;
/// chained, they give counter-clockwise outer loops and clockwise holes.
/// Holes are dropped: the group filling a hole has its own loop there, and
/// the caller lists smaller zones first so that the inner one wins
/// ([`Frame::strength_at`] takes the first zone containing a point).
/// Groups are returned in the mesh's group order with their loops, and the
/// outline of the whole section beside them.
pub fn cut_mesh(mesh: &Mesh, y_plane: f64) -> Result<SectionCut, SceneError> {
    use std::collections::BTreeMap;
    let adjacency = crate::mesh::adjacency::FaceAdjacency::build(mesh)
        .map_err(|e| SceneError::invalid("lem.y_plane", format!("the mesh's faces: {e}")))?;
    let extent = mesh.nodes.iter().fold([f64::INFINITY, f64::NEG_INFINITY], |a, p| [a[0].min(p[1]), a[1].max(p[1])]);
    let size = mesh.nodes.iter().fold(0.0f64, |s, p| s.max(p[0].abs()).max(p[1].abs()).max(p[2].abs())).max(1.0);
    let tol = 1e-9 * size;
    if !(y_plane >= extent[0] - tol && y_plane <= extent[1] + tol) {
        return Err(SceneError::invalid(
            "lem.y_plane",
            format!("y = {y_plane} is outside the mesh (y from {} to {})", extent[0], extent[1]),
        ));
    }
    let mut group_of = vec![usize::MAX; mesh.cells.len()];
    for (gi, g) in mesh.groups.iter().enumerate().filter(|(_, g)| g.dim == 3) {
        for &c in &g.cells {
            group_of[c] = gi;
        }
    }
    // Directed boundary-candidate edges per group, from the faces in the plane.
    let mut edges: BTreeMap<usize, BTreeMap<(usize, usize), usize>> = BTreeMap::new();
    for &(c, f) in &adjacency.exterior {
        let nodes = crate::mesh::adjacency::face_nodes(mesh, c, f);
        if !nodes.iter().all(|&n| (mesh.nodes[n][1] - y_plane).abs() <= tol) || group_of[c] == usize::MAX {
            continue;
        }
        let xz: Vec<[f64; 2]> = nodes.iter().map(|&n| [mesh.nodes[n][0], mesh.nodes[n][2]]).collect();
        let ccw = signed_area(&xz) > 0.0;
        let e = edges.entry(group_of[c]).or_default();
        for i in 0..nodes.len() {
            let (a, b) = (nodes[i], nodes[(i + 1) % nodes.len()]);
            let (a, b) = if ccw { (a, b) } else { (b, a) };
            *e.entry((a, b)).or_default() += 1;
        }
    }
    if edges.is_empty() {
        return Err(SceneError::invalid(
            "lem.y_plane",
            format!("no element face lies in the plane y = {y_plane}: the section must be an outer face of the mesh"),
        ));
    }
    let mut out = Vec::new();
    for (gi, e) in &edges {
        let name = &mesh.groups[*gi].name;
        out.push((name.clone(), outer_loops(mesh, e).map_err(|()| not_closed(name))?));
    }
    let mut all: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for e in edges.values() {
        for (&k, &n) in e {
            *all.entry(k).or_default() += n;
        }
    }
    let outline = outer_loops(mesh, &all).map_err(|()| not_closed("(all)"))?;
    Ok(SectionCut { zones: out, outline })
}

fn not_closed(group: &str) -> SceneError {
    SceneError::invalid("lem.y_plane", format!("the faces of volume group {group:?} in the section do not close"))
}

/// The counter-clockwise boundary loops of a set of directed face edges.
fn outer_loops(mesh: &Mesh, e: &std::collections::BTreeMap<(usize, usize), usize>) -> Result<Vec<Vec<[f64; 2]>>, ()> {
    let mut next: std::collections::BTreeMap<usize, Vec<usize>> = Default::default();
    for (&(a, b), _) in e.iter().filter(|((a, b), _)| !e.contains_key(&(*b, *a))) {
        next.entry(a).or_default().push(b);
    }
    let mut loops = Vec::new();
    while let Some((&start, _)) = next.iter().find(|(_, v)| !v.is_empty()) {
        let mut ring = vec![start];
        let mut at = start;
        loop {
            let b = next.get_mut(&at).and_then(Vec::pop).ok_or(())?;
            if b == start {
                break;
            }
            ring.push(b);
            at = b;
        }
        let poly: Vec<[f64; 2]> = ring.iter().map(|&n| [mesh.nodes[n][0], mesh.nodes[n][2]]).collect();
        if signed_area(&poly) > 0.0 {
            loops.push(poly);
        }
    }
    Ok(loops)
}

/// A mesh cut by a section plane.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionCut {
    /// Per volume group met by the plane (mesh order): its outer loops.
    pub zones: Vec<(String, Vec<Vec<[f64; 2]>>)>,
    /// The outer loops of the whole section.
    pub outline: Vec<Vec<[f64; 2]>>,
}

impl SectionCut {
    /// The ground: the top of the section's outline, from its leftmost to its
    /// rightmost point (the highest of each where several share an x).
    /// Vertical runs keep their upper end. Err when the section is not one piece.
    pub fn ground(&self) -> Result<Vec<[f64; 2]>, SceneError> {
        let [ring] = self.outline.as_slice() else {
            return Err(SceneError::invalid(
                "lem.ground_group",
                format!("the section has {} separate pieces: name the ground's surface group", self.outline.len()),
            ));
        };
        let pick = |better: &dyn Fn(&[f64; 2], &[f64; 2]) -> bool| {
            (0..ring.len()).fold(0, |b, i| if better(&ring[i], &ring[b]) { i } else { b })
        };
        let left = pick(&|p, q| p[0] < q[0] || (p[0] == q[0] && p[1] > q[1]));
        let right = pick(&|p, q| p[0] > q[0] || (p[0] == q[0] && p[1] > q[1]));
        // Counter-clockwise, the top runs from the right end to the left end.
        let mut top = Vec::new();
        let mut i = right;
        loop {
            top.push(ring[i]);
            if i == left {
                break;
            }
            i = (i + 1) % ring.len();
        }
        top.reverse();
        let size = (ring[right][0] - ring[left][0]).abs().max(1.0);
        let mut ground: Vec<[f64; 2]> = Vec::with_capacity(top.len());
        for p in top {
            match ground.last_mut() {
                Some(q) if (p[0] - q[0]).abs() <= 1e-9 * size => q[1] = q[1].max(p[1]),
                Some(q) if p[0] < q[0] => {
                    return Err(SceneError::invalid(
                        "lem.ground_group",
                        format!("the top of the section overhangs at x = {}: name the ground's surface group", p[0]),
                    ))
                }
                _ => ground.push(p),
            }
        }
        Ok(ground)
    }
}

/// Signed area of a polygon in the plane (positive: counter-clockwise).
pub(crate) fn signed_area(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    0.5 * (0..n).map(|i| p[i][0] * p[(i + 1) % n][1] - p[(i + 1) % n][0] * p[i][1]).sum::<f64>()
}
