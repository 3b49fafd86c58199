//! Sampling a circular slip surface of a conforming mesh (the interface group
//! that follows the LEM critical circle) for eq. 19-22.
//!
//! Geometry in the x-z section: the circle (centre `(xc, zc)`), the toe
//! (exit) point, the sliding direction toward the toe. At a point `x` of the
//! surface the normal out of the sliding mass points away from the centre
//! (the mass lies inside the circle, between it and the ground), `t` is the
//! tangent pointing toward the toe, and `s` the arc length from the toe; the
//! radius there is the point's distance from the centre.
//!
//! Two sources of traction:
//! - stresses: per slip facet, the average of the two cells that share it
//!   (CDEM element stresses or FEM cell stresses, same cell order as the mesh);
//! - springs (CDEM, as in the paper): per spring of the slip interface, the
//!   force the rest of the slope exerts on the mass, divided by its area.
//!
//! Points at the same `s` (the front and back of the slab) are merged
//! area-weighted into one station.

use std::collections::HashMap;

use super::safety::{traction_from_stress, SurfacePoint};
use crate::geometry::Circle;
use crate::mesh::adjacency::{face_key, face_nodes, polygon_normal_area, FaceAdjacency};
use crate::mesh::Mesh;
use crate::model::Model;
use crate::physics::spring::{relative_displacement, spring_contact_force, SpringState};

/// A circular slip surface in the x-z section: a circle with the point
/// and the sense the mass slides toward.
#[derive(Debug, Clone, Copy)]
pub struct SlipCircle {
    pub circle: Circle,
    /// The toe (exit) point (x, z).
    pub toe: [f64; 2],
    /// Whether the mass turns clockwise (x right, z up) as it slides toward
    /// the toe: a slope facing -x, its toe on the left.
    pub clockwise: bool,
}

/// `a` wrapped into (-pi, pi].
fn wrap(a: f64) -> f64 {
    let w = a.rem_euclid(std::f64::consts::TAU);
    if w > std::f64::consts::PI {
        w - std::f64::consts::TAU
    } else {
        w
    }
}

impl SlipCircle {
    /// `(s, n, t)` at a point: arc length from the toe (negative beyond
    /// it), unit normal out of the mass, unit tangent in the sliding
    /// direction (toward the toe).
    pub fn frame(&self, x: [f64; 3]) -> (f64, [f64; 3], [f64; 3]) {
        let Circle { xc, zc, .. } = self.circle;
        let (dx, dz) = (x[0] - xc, x[2] - zc);
        let r = dx.hypot(dz);
        let n = [dx / r, 0.0, dz / r];
        let cw = self.clockwise;
        // d(position)/d(angle) is (-n_z, n_x); clockwise motion is its opposite.
        let t = if cw { [n[2], 0.0, -n[0]] } else { [-n[2], 0.0, n[0]] };
        let a_t = (self.toe[1] - zc).atan2(self.toe[0] - xc);
        // From the toe toward the crest the angle grows when sliding is clockwise.
        let from_toe = wrap(dz.atan2(dx) - a_t);
        (r * if cw { from_toe } else { -from_toe }, n, t)
    }
}

/// Merges points at the same arc length (within 1e-6 m), area-weighted, and
/// sorts them from the toe.
fn stations(mut pts: Vec<SurfacePoint>) -> Vec<SurfacePoint> {
    pts.sort_by(|a, b| a.s.total_cmp(&b.s));
    let mut out: Vec<SurfacePoint> = Vec::new();
    for p in pts {
        match out.last_mut() {
            Some(q) if (q.s - p.s).abs() < 1e-6 => {
                let a = q.area + p.area;
                q.sigma_n = (q.sigma_n * q.area + p.sigma_n * p.area) / a;
                q.tau = (q.tau * q.area + p.tau * p.area) / a;
                q.area = a;
            }
            _ => out.push(p),
        }
    }
    out
}

/// Traction at the slip facets from cell stresses (`stress[c]` for mesh cell `c`).
pub fn from_stresses(
    mesh: &Mesh,
    coords: &[[f64; 3]],
    group: &str,
    circle: &SlipCircle,
    stress: &[[f64; 6]],
) -> Option<Vec<SurfacePoint>> {
    let g = mesh.groups.iter().find(|g| g.name == group && g.dim == 2)?;
    let adj = FaceAdjacency::build(mesh).ok()?;
    let mut shared: HashMap<[usize; 4], [usize; 2]> = HashMap::new();
    for s in &adj.shared {
        shared.insert(face_key(&face_nodes(mesh, s.cells[0], s.faces[0])), s.cells);
    }
    let mut pts = Vec::new();
    for f in &g.facets {
        let cells = shared.get(&face_key(f.nodes()))?;
        let p: Vec<[f64; 3]> = f.nodes().iter().map(|&n| coords[n]).collect();
        let (_, area) = polygon_normal_area(&p);
        let c = [0, 1, 2].map(|d| p.iter().map(|x| x[d]).sum::<f64>() / p.len() as f64);
        let (s, n, t) = circle.frame(c);
        let sigma = [0, 1, 2, 3, 4, 5].map(|k| 0.5 * (stress[cells[0]][k] + stress[cells[1]][k]));
        let (sigma_n, tau) = traction_from_stress(sigma, n, t);
        pts.push(SurfacePoint { s, area, sigma_n, tau });
    }
    Some(stations(pts))
}

/// Traction at the slip springs of a CDEM state (interface named `group`),
/// merged into stations.
pub fn from_springs(
    model: &Model,
    u: &[f64],
    springs: &SpringState,
    group: &str,
    circle: &SlipCircle,
) -> Option<Vec<SurfacePoint>> {
    Some(stations(spring_points(model, u, springs, group, circle)?.into_iter().map(|(_, p)| p).collect()))
}

/// Traction at each spring of the slip interface, with the spring's index.
pub fn spring_points(
    model: &Model,
    u: &[f64],
    springs: &SpringState,
    group: &str,
    circle: &SlipCircle,
) -> Option<Vec<(usize, SurfacePoint)>> {
    let iface = model.interfaces.iter().position(|i| i.name == group)? as u16;
    let sp = &model.springs;
    let mut pts = Vec::new();
    for k in (0..sp.len()).filter(|&k| sp.interface[k] == iface) {
        let (a, b) = (sp.a[k] as usize, sp.b[k] as usize);
        let d = relative_displacement(u, a, b);
        let f_on_a = spring_contact_force(sp.kn[k], sp.ks[k], sp.normal[k], d, springs.slip[k], springs.status[k]);
        let (s, n, t) = circle.frame(model.x0[a]);
        // The spring normal points from a's element into b's: if it points out
        // of the mass, a is on the mass side and feels the ground's force.
        let on_mass_side = sp.normal[k][0] * n[0] + sp.normal[k][2] * n[2] > 0.0;
        let f = if on_mass_side { f_on_a } else { f_on_a.map(|v| -v) };
        let traction = f.map(|v| v / sp.area[k]);
        let sigma_n = -(traction[0] * n[0] + traction[1] * n[1] + traction[2] * n[2]);
        let tau = -(traction[0] * t[0] + traction[1] * t[1] + traction[2] * t[2]);
        pts.push((k, SurfacePoint { s, area: sp.area[k], sigma_n, tau }));
    }
    Some(pts)
}
