//! Contact detection between blocks (docs/method.md 2.13), in two phases:
//!
//! 1. **Broad phase, sort and sweep.** Each block's box (its corners now,
//!    widened by the tolerance) is sorted by its lower x; a sweep pairs the
//!    boxes that overlap on all three axes. `O(n log n + pairs)`. Pairs that
//!    share a node (one continuous body), that a bonded spring still joins,
//!    or whose every component is fixed are dropped.
//! 2. **Narrow phase, vertex to face.** For each pair, each corner of one
//!    block against the face triangles of the other (a quadrilateral face is
//!    four triangles about its centroid, so warped and perturbed faces are
//!    used as they are). For a convex block the largest signed distance to
//!    its triangles' planes is the vertex's gap when negative (inside) and a
//!    lower bound of its distance when positive. The contact triangle is the
//!    one of that largest distance (within a rounding band) on which the
//!    vertex projects.
//!
//! The broad phase runs only when some node has moved more than half the
//! tolerance since the last mapping (3DEC's CTOL): until then no pair can
//! come within reach that was not within the tolerance at the mapping. A
//! quiet model pays only the narrow phase of the pairs it has.

use crate::model::Model;
use crate::physics::corotation::{rotate, Mat3};

/// A face triangle of a block: local corners `a`, `b` of face `face` and
/// that face's centroid (a triangular face is its own triangle: `centroid`
/// false, third point its third corner).
#[derive(Debug, Clone, Copy)]
pub struct Triangle {
    pub face: u8,
    /// Local corner indices of the triangle's first two points.
    pub a: u8,
    pub b: u8,
    /// Third point: the face centroid (true) or local corner `c` (false).
    pub centroid: bool,
    pub c: u8,
}

/// The blocks' faces as the contact sees them, built once.
#[derive(Debug, Clone, Default)]
pub struct Faces {
    /// Per element: its triangles, `tri[tri_ptr[e]..tri_ptr[e+1]]`.
    pub tri_ptr: Vec<usize>,
    pub tri: Vec<Triangle>,
    /// Per element and face: local corners, in `face_corner[face_ptr[e] + f]`.
    pub face_ptr: Vec<usize>,
    pub face_corners: Vec<&'static [usize]>,
    /// Per element and face: rest outward normal and the area share of each of its corners (m^2).
    pub face_normal: Vec<[f64; 3]>,
    pub face_share: Vec<f64>,
}

impl Faces {
    pub fn build(model: &Model) -> Self {
        let el = &model.elements;
        let mut out = Faces::default();
        for e in 0..el.len() {
            out.tri_ptr.push(out.tri.len());
            out.face_ptr.push(out.face_corners.len());
            let corners: Vec<[f64; 3]> = el.corners(e).iter().map(|&n| model.x0[n as usize]).collect();
            for (f, fc) in el.kind[e].faces().iter().enumerate() {
                let p: Vec<[f64; 3]> = fc.iter().map(|&c| corners[c]).collect();
                let (n, area) = crate::mesh::adjacency::polygon_normal_area(&p);
                out.face_corners.push(fc);
                out.face_normal.push(n);
                out.face_share.push(area / fc.len() as f64);
                if fc.len() == 3 {
                    out.tri.push(Triangle {
                        face: f as u8,
                        a: fc[0] as u8,
                        b: fc[1] as u8,
                        centroid: false,
                        c: fc[2] as u8,
                    });
                } else {
                    for k in 0..fc.len() {
                        let (a, b) = (fc[k], fc[(k + 1) % fc.len()]);
                        out.tri.push(Triangle { face: f as u8, a: a as u8, b: b as u8, centroid: true, c: 0 });
                    }
                }
            }
        }
        out.tri_ptr.push(out.tri.len());
        out.face_ptr.push(out.face_corners.len());
        out
    }

    pub fn triangles(&self, e: usize) -> &[Triangle] {
        &self.tri[self.tri_ptr[e]..self.tri_ptr[e + 1]]
    }

    /// Element `e`'s triangles where its corners are now (`corners`), into
    /// `out` (one per triangle): placed once a step for every block that a
    /// candidate vertex may touch, then read by [`vertex_face`] and [`covers`].
    pub fn place(&self, e: usize, corners: &[[f64; 3]], out: &mut [Placed]) {
        let fp = self.face_ptr[e];
        for (t, o) in self.triangles(e).iter().zip(out) {
            let face = self.face_corners[fp + t.face as usize];
            let q = triangle_points(t, face, corners);
            let n = cross(sub(q[1], q[0]), sub(q[2], q[0]));
            let len = dot(n, n).sqrt();
            let unit = if len == 0.0 { [0.0; 3] } else { n.map(|v| v / len) };
            *o = Placed { q, n, unit };
        }
    }

    /// The outward normals (rotated by `r`) of the exterior faces of element
    /// `e` that hold its local corner `c`, appended to `out`.
    pub fn vertex_normals(&self, e: usize, c: usize, r: &Mat3, out: &mut Vec<[f64; 3]>) {
        for f in self.face_ptr[e]..self.face_ptr[e + 1] {
            if self.face_share[f] > 0.0 && self.face_corners[f].contains(&c) {
                out.push(rotate(r, self.face_normal[f]));
            }
        }
    }

    /// The contact area of corner `c` of element `e` (its corners now in
    /// `corners`) towards a contact of normal `n` (out of the other block):
    /// the corner's share of each of its exterior faces whose share lies over
    /// the other block (`over` the midpoint between the corner and the face's
    /// centroid, the centre of the corner's share), weighted by how squarely
    /// the face (rotated by `r`) faces the contact, `max(-n_f . n, 0)`. So a
    /// vertex at the edge of an overlap counts only the part of its faces
    /// that overlaps, and the contacts that take over from a joint's springs
    /// carry the springs' stiffness.
    pub fn vertex_area(
        &self,
        e: usize,
        c: usize,
        r: &Mat3,
        corners: &[[f64; 3]],
        n: [f64; 3],
        over: &dyn Fn([f64; 3]) -> bool,
    ) -> f64 {
        let mut a = 0.0;
        for f in self.face_ptr[e]..self.face_ptr[e + 1] {
            let fc = self.face_corners[f];
            if self.face_share[f] == 0.0 || !fc.contains(&c) {
                continue;
            }
            let nf = rotate(r, self.face_normal[f]);
            let w = (-(nf[0] * n[0] + nf[1] * n[1] + nf[2] * n[2])).max(0.0);
            if w == 0.0 {
                continue;
            }
            let mut m = [0.0; 3];
            for &k in fc {
                for d in 0..3 {
                    m[d] += corners[k][d] / fc.len() as f64;
                }
            }
            let mid = [0, 1, 2].map(|d| 0.5 * (m[d] + corners[c][d]));
            if over(mid) {
                a += self.face_share[f] * w;
            }
        }
        a
    }
}

/// A face triangle where it is now: its three points and `(q1 - q0) x (q2 - q0)`
/// (outward, twice its area long).
#[derive(Debug, Clone, Copy, Default)]
pub struct Placed {
    pub q: [[f64; 3]; 3],
    pub n: [f64; 3],
    /// `n` made unit (zero for a degenerate triangle).
    pub unit: [f64; 3],
}

/// Where a vertex touches a face: the triangle's points as weighted sums of
/// the face block's local corners (up to 4 for the centroid of a quad face,
/// plus the two edge corners).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FacePoint {
    /// Local corners of the face block and their weights (sum 1).
    pub corners: [u8; 6],
    pub weights: [f64; 6],
    pub len: u8,
    /// Outward unit normal of the triangle (out of the face block).
    pub normal: [f64; 3],
    /// Signed distance of the vertex to the triangle's plane (m, negative inside).
    pub gap: f64,
    /// The least barycentric coordinate of the vertex's projection (negative:
    /// just outside the triangle, by that fraction of its size).
    pub inside: f64,
}

/// How far outside a triangle's edges (as a fraction of its size) a
/// projection still makes a contact: 1e-3, 2 mm on a 2 m face.
pub const EDGE_SLACK: f64 = 1e-3;

/// The points of a triangle of block `corners` (positions of its local corners).
fn triangle_points(t: &Triangle, face: &[usize], corners: &[[f64; 3]]) -> [[f64; 3]; 3] {
    let third = match t.centroid {
        true => {
            let mut m = [0.0; 3];
            for &c in face {
                for d in 0..3 {
                    m[d] += corners[c][d] / face.len() as f64;
                }
            }
            m
        }
        false => corners[t.c as usize],
    };
    [corners[t.a as usize], corners[t.b as usize], third]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The narrow phase of one vertex `p` against block `e` (its triangles now
/// in `placed`): the contact point if the vertex is within `reach` of the block
/// and projects on the triangle of its largest signed distance; None if it is
/// farther or beside the block (an edge or corner region: no vertex-face
/// contact there).
///
/// `near` lists the triangles (indices into the block's own) to look at: those
/// near the vertex at the last mapping. `opposing` holds the outward normals
/// of the vertex's own exterior faces now: a triangle counts only if one of
/// them faces it (`-n_f . n_t > 1/2`, within 60 degrees), so that a vertex
/// on the plane of a side face of the other block (two blocks flush along
/// a side) is judged by the faces that meet, not by that plane; and only if
/// the vertex is less than `depth` (the largest penetration allowed) behind
/// its plane: a plane it is farther behind is the block's far side.
///
/// Also returns the largest signed distance of the vertex to the planes of
/// all the block's triangles: when that is negative the vertex is inside
/// every one of them, so inside the block by at least as much (the missed
/// contact's test).
pub fn vertex_face(
    faces: &Faces,
    e: usize,
    placed: &[Placed],
    p: [f64; 3],
    (reach, depth): (f64, f64),
    near: &[u16],
    opposing: &[[f64; 3]],
) -> (Option<FacePoint>, f64) {
    let fp = faces.face_ptr[e];
    let all = faces.triangles(e);
    let inside_all = placed
        .iter()
        .filter(|t| t.unit != [0.0; 3])
        .map(|t| dot(sub(p, t.q[0]), t.unit))
        .fold(f64::NEG_INFINITY, f64::max);
    let mut best_gap = f64::NEG_INFINITY;
    let mut planes = [([0.0; 3], f64::NEG_INFINITY); 24];
    for (k, &i) in near.iter().enumerate() {
        let Placed { q: [q0, _, _], unit: n, .. } = placed[i as usize];
        if n == [0.0; 3] || !opposing.iter().any(|&nf| -dot(nf, n) > 0.5) {
            continue;
        }
        let g = dot(sub(p, q0), n);
        if g < -depth {
            continue;
        }
        planes[k] = (n, g);
        best_gap = best_gap.max(g);
    }
    if best_gap > reach {
        return (None, inside_all);
    }
    // The triangle the vertex projects on (up to `EDGE_SLACK` of its size
    // outside its edges: two blocks flush along a side put every vertex on an
    // edge) of the largest signed distance: for a convex block the face it is
    // nearest to, inside or out. Warped faces are not planar, so the four
    // triangles of one face need not agree on the distance. Ties (within a
    // rounding band): the one the vertex projects on most squarely.
    // Only triangles within `reach` of the largest distance: for a convex
    // block the vertex is at least `best_gap` from it, so a plane it is far
    // inside (the far side of a corner it sits just beside) is not its
    // contact; where the nearest triangles miss its projection there is none.
    let band = 1e-9 * reach.max(best_gap.abs());
    let mut chosen: Option<FacePoint> = None;
    for (k, &i) in near.iter().enumerate() {
        let (n, g) = planes[k];
        if g == f64::NEG_INFINITY || g < best_gap - reach || chosen.is_some_and(|c| g < c.gap - band) {
            continue;
        }
        let t = &all[i as usize];
        let face = faces.face_corners[fp + t.face as usize];
        let [q0, q1, q2] = placed[i as usize].q;
        // Barycentric coordinates of the projection.
        let q = sub(p, n.map(|v| v * g));
        let (e0, e1, w) = (sub(q1, q0), sub(q2, q0), sub(q, q0));
        let (d00, d01, d11, d20, d21) = (dot(e0, e0), dot(e0, e1), dot(e1, e1), dot(w, e0), dot(w, e1));
        let den = d00 * d11 - d01 * d01;
        if den <= 0.0 {
            continue;
        }
        let l1 = (d11 * d20 - d01 * d21) / den;
        let l2 = (d00 * d21 - d01 * d20) / den;
        let l0 = 1.0 - l1 - l2;
        let inside = l0.min(l1).min(l2);
        if inside < -EDGE_SLACK || chosen.is_some_and(|c| g <= c.gap + band && c.inside >= inside) {
            continue;
        }
        // Weights of a projection just outside are clamped onto the triangle.
        let (l0, l1, l2) = {
            let (a, b, c) = (l0.max(0.0), l1.max(0.0), l2.max(0.0));
            let s = a + b + c;
            (a / s, b / s, c / s)
        };
        let mut fpnt = FacePoint { corners: [0; 6], weights: [0.0; 6], len: 0, normal: n, gap: g, inside };
        let mut push = |c: usize, w: f64| {
            if let Some(i) = (0..fpnt.len as usize).find(|&i| fpnt.corners[i] as usize == c) {
                fpnt.weights[i] += w;
            } else {
                fpnt.corners[fpnt.len as usize] = c as u8;
                fpnt.weights[fpnt.len as usize] = w;
                fpnt.len += 1;
            }
        };
        push(t.a as usize, l0);
        push(t.b as usize, l1);
        match t.centroid {
            true => face.iter().for_each(|&c| push(c, l2 / face.len() as f64)),
            false => push(t.c as usize, l2),
        }
        chosen = Some(fpnt);
    }
    (chosen.filter(|c| c.gap <= reach), inside_all)
}

/// Whether `point`, moved along `n`, lands on one of the exterior triangles
/// of a block (its triangles now in `placed`) that face `n`, within [`EDGE_SLACK`].
pub fn covers(placed: &[Placed], point: [f64; 3], n: [f64; 3]) -> bool {
    placed.iter().any(|&Placed { q: [q0, q1, q2], n: nt, .. }| {
        // Only the triangles that face the contact.
        if dot(nt, n) <= 0.0 {
            return false;
        }
        // Project along n onto the triangle's plane.
        let s = dot(sub(q0, point), nt) / dot(n, nt);
        let q = [0, 1, 2].map(|d| point[d] + s * n[d]);
        let (e0, e1, w) = (sub(q1, q0), sub(q2, q0), sub(q, q0));
        let (d00, d01, d11, d20, d21) = (dot(e0, e0), dot(e0, e1), dot(e1, e1), dot(w, e0), dot(w, e1));
        let den = d00 * d11 - d01 * d01;
        if den <= 0.0 {
            return false;
        }
        let l1 = (d11 * d20 - d01 * d21) / den;
        let l2 = (d00 * d21 - d01 * d20) / den;
        (1.0 - l1 - l2).min(l1).min(l2) >= -EDGE_SLACK
    })
}

/// A block's box now, widened by `margin` on every side.
pub fn block_box(corners: impl Iterator<Item = [f64; 3]>, margin: f64) -> ([f64; 3], [f64; 3]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in corners {
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    (lo.map(|v| v - margin), hi.map(|v| v + margin))
}

/// Broad phase by sort and sweep on x: the pairs `(a, b)`, `a < b`, whose
/// boxes overlap, sorted. `keep` filters a pair.
pub fn sweep(boxes: &[([f64; 3], [f64; 3])], keep: impl Fn(usize, usize) -> bool) -> Vec<(u32, u32)> {
    let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
    order.sort_by(|&i, &j| boxes[i as usize].0[0].total_cmp(&boxes[j as usize].0[0]).then(i.cmp(&j)));
    let mut pairs = Vec::new();
    for (k, &i) in order.iter().enumerate() {
        let (lo_i, hi_i) = boxes[i as usize];
        for &j in &order[k + 1..] {
            let (lo_j, hi_j) = boxes[j as usize];
            if lo_j[0] > hi_i[0] {
                break;
            }
            if lo_j[1] <= hi_i[1] && lo_i[1] <= hi_j[1] && lo_j[2] <= hi_i[2] && lo_i[2] <= hi_j[2] {
                let (a, b) = if i < j { (i, j) } else { (j, i) };
                if keep(a as usize, b as usize) {
                    pairs.push((a, b));
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs
}

/// Broad phase by a uniform grid of cells of side `cell` (Munjiza's NBS and
/// 3DEC's cell mapping in their simplest form): each box is entered in the
/// cells it covers and pairs are read cell by cell, each once. The same
/// pairs as [`sweep`], sorted; kept to measure against it (benches/broad_phase.rs).
pub fn grid(boxes: &[([f64; 3], [f64; 3])], cell: f64, keep: impl Fn(usize, usize) -> bool) -> Vec<(u32, u32)> {
    use std::collections::HashMap;
    let key = |p: [f64; 3]| p.map(|v| (v / cell).floor() as i64);
    let mut cells: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
    for (i, (lo, hi)) in boxes.iter().enumerate() {
        let (a, b) = (key(*lo), key(*hi));
        for x in a[0]..=b[0] {
            for y in a[1]..=b[1] {
                for z in a[2]..=b[2] {
                    cells.entry([x, y, z]).or_default().push(i as u32);
                }
            }
        }
    }
    let mut pairs = Vec::new();
    for (c, members) in &cells {
        for (k, &i) in members.iter().enumerate() {
            for &j in &members[k + 1..] {
                let ((lo_i, hi_i), (lo_j, hi_j)) = (boxes[i as usize], boxes[j as usize]);
                if (0..3).any(|d| lo_j[d] > hi_i[d] || lo_i[d] > hi_j[d]) {
                    continue;
                }
                // Count the pair only in the cell of the lower corner of the boxes' overlap.
                let low = key([0, 1, 2].map(|d| lo_i[d].max(lo_j[d])));
                if low != *c {
                    continue;
                }
                let (a, b) = if i < j { (i, j) } else { (j, i) };
                if keep(a as usize, b as usize) {
                    pairs.push((a, b));
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;

    fn boxes(n: usize) -> Vec<([f64; 3], [f64; 3])> {
        // A jittered lattice of unit boxes that touch their neighbours.
        (0..n)
            .map(|i| {
                let (x, y, z) = ((i % 10) as f64, ((i / 10) % 10) as f64, (i / 100) as f64);
                let j = 0.01 * ((i * 7919) % 13) as f64;
                ([x + j, y, z], [x + 1.0 + j, y + 1.0, z + 1.0])
            })
            .collect()
    }

    #[test]
    fn sweep_and_grid_find_the_same_pairs() {
        let b = boxes(500);
        let s = sweep(&b, |_, _| true);
        let g = grid(&b, 1.5, |_, _| true);
        assert!(!s.is_empty());
        assert_eq!(s, g);
    }
}
