//! Build stage 8: the water's nodal forces (UDEC's joint water: impermeable
//! blocks, pressure in the joints).
//!
//! The pore pressure `u` ([`crate::physics::water`]) at each spring's node
//! pushes the two faces of its interface apart, `-u A n` on node `a` and
//! `+u A n` on node `b` (`A` the spring's share of the face, `n` its normal
//! from `a` to `b`), and pushes on the model's outer faces, `-u A n_out` at
//! each corner's share. The forces join gravity in `f_ext` and stay fixed
//! (small displacements). On each block the resultant is its buoyancy plus
//! the seepage force, and the springs' normal stress is the effective stress
//! `sigma_n' = sigma_n - u`: eq. 17-18 then act on it unchanged. The blocks'
//! own stress is the total stress; a plastic block yields on
//! `sigma + u I` ([`WaterModel::element_pressure`]).

use serde::Serialize;

use super::spec::WaterSection;
use super::Interface;
use crate::error::{Error, SceneError};
use crate::mesh::adjacency::{corner_shares, face_nodes, FaceAdjacency};
use crate::mesh::Mesh;
use crate::physics::spring::Springs;
use crate::physics::water::{crack_pressure, Phreatic};

/// The water a model carries, for the outputs and for plastic blocks.
#[derive(Debug, Clone, Serialize)]
pub struct WaterModel {
    /// What ran, for `summary.json` and `srm.json`.
    pub model: &'static str,
    /// `gamma_w` (N/m^3).
    pub unit_weight: f64,
    pub surface: Option<Phreatic>,
    /// `(interface group, level)` of each water-filled crack.
    pub cracks: Vec<(String, f64)>,
    /// `u` at each spring (Pa).
    #[serde(skip)]
    pub spring_pressure: Vec<f64>,
    /// `u` at each node copy's rest position (Pa), from the surface only.
    #[serde(skip)]
    pub node_pressure: Vec<f64>,
    /// `u` at each element's centroid (Pa), from the surface only; 0 in an
    /// element joined to a neighbour by a merged interface (inside a larger
    /// impermeable block). What a plastic block yields on.
    #[serde(skip)]
    pub element_pressure: Vec<f64>,
    /// Per node copy: the vector area its water force acts on (m^2), so that
    /// its force is `-u a` with `u` the pressure at the node: `A n` of each
    /// spring at node `a` (`-A n` at node `b`) plus the outer faces' corner
    /// shares `A n_out`. The runout turns it with the node's block and takes
    /// `u` where the node is now (`solver::runout`).
    #[serde(skip)]
    pub node_area: Vec<[f64; 3]>,
    /// Resultant of the water forces (N).
    pub resultant: [f64; 3],
}

impl WaterModel {
    /// What `summary.json` and `srm.json` say of it.
    pub fn summary(&self) -> crate::summary::WaterSummary {
        crate::summary::WaterSummary {
            model: self.model.to_string(),
            surface: self.surface.as_ref().map(|s| s.points.clone()),
            unit_weight: self.unit_weight,
            hu: match self.surface.as_ref().map(|s| s.hu) {
                Some(crate::physics::water::Hu::Cos2) => "cos2".into(),
                _ => "vertical".into(),
            },
            cracks: self.cracks.clone(),
            resultant: self.resultant,
            wet_springs: self.spring_pressure.iter().filter(|&&u| u > 0.0).count(),
        }
    }
}

/// What UDEC calls it: pressure in the joints, blocks impermeable.
pub const JOINT_WATER: &str =
    "joint water (UDEC): impermeable blocks, pore pressure on every spring interface and outer face below the surface";

/// The water's forces (`3 i + d`, N) and what the model keeps of it.
#[allow(clippy::too_many_arguments)]
pub(super) fn water_forces(
    water: &WaterSection,
    mesh: &Mesh,
    adj: &FaceAdjacency,
    coords: &[[f64; 3]],
    x0: &[[f64; 3]],
    springs: &Springs,
    interfaces: &[Interface],
    node_of: impl Fn(usize, usize) -> u32,
    element_centroids: &[Option<[f64; 3]>],
) -> Result<(Vec<f64>, WaterModel), Error> {
    let surface = water.phreatic()?;
    let (lo, hi) = super::point_bounds(x0.iter().copied());
    if let Some(s) = &surface {
        let [a, b] = s.x_range();
        let tol = 1e-9 * (hi[0] - lo[0]).abs().max(1.0);
        if a > lo[0] + tol || b < hi[0] - tol {
            return Err(SceneError::invalid(
                "water.surface",
                format!(
                    "spans x in [{a}, {b}] but the model spans [{}, {}]: draw it over the whole model",
                    lo[0], hi[0]
                ),
            )
            .into());
        }
    }
    let at = |p: [f64; 3]| surface.as_ref().map_or(0.0, |s| s.pressure(p[0], p[2]));
    // Cracks: each an [[interface]] with springs, filled no higher than its top.
    let mut crack_of_interface: Vec<Option<f64>> = vec![None; interfaces.len()];
    for (i, c) in water.crack.iter().enumerate() {
        let key = format!("water.crack[{i}]");
        let Some(k) = interfaces.iter().skip(1).position(|f| f.name == c.group).map(|k| k + 1) else {
            let names: Vec<&str> = interfaces.iter().skip(1).map(|f| f.name.as_str()).collect();
            return Err(SceneError::invalid(
                format!("{key}.group"),
                format!("{:?} is not an [[interface]] group (they are: {})", c.group, names.join(", ")),
            )
            .into());
        };
        let (mut bottom, mut top) = (f64::INFINITY, f64::NEG_INFINITY);
        for s in (0..springs.len()).filter(|&s| springs.interface[s] as usize == k) {
            let z = x0[springs.a[s] as usize][2];
            (bottom, top) = (bottom.min(z), top.max(z));
        }
        if top < bottom {
            return Err(SceneError::invalid(
                format!("{key}.group"),
                format!("{:?} has no springs (a merged interface has no open joint to fill)", c.group),
            )
            .into());
        }
        if c.level > top {
            return Err(SceneError::invalid(
                format!("{key}.level"),
                format!("{} m is above the crack's top at z = {top} m", c.level),
            )
            .into());
        }
        if c.level < bottom {
            return Err(SceneError::invalid(
                format!("{key}.level"),
                format!("{} m is below the crack's bottom at z = {bottom} m: the crack would be dry", c.level),
            )
            .into());
        }
        crack_of_interface[k] = Some(c.level);
    }

    let mut f = vec![0.0; 3 * x0.len()];
    let mut node_area = vec![[0.0; 3]; x0.len()];
    let mut spring_pressure = Vec::with_capacity(springs.len());
    for s in 0..springs.len() {
        let p = x0[springs.a[s] as usize];
        let mut u = at(p);
        if let Some(level) = crack_of_interface[springs.interface[s] as usize] {
            u = u.max(crack_pressure(water.unit_weight, level, p[2]));
        }
        spring_pressure.push(u);
        let (a, b, n, area) = (springs.a[s] as usize, springs.b[s] as usize, springs.normal[s], springs.area[s]);
        for d in 0..3 {
            f[3 * a + d] -= u * area * n[d];
            f[3 * b + d] += u * area * n[d];
            node_area[a][d] += area * n[d];
            node_area[b][d] -= area * n[d];
        }
    }
    for &(c, face) in &adj.exterior {
        let nodes = face_nodes(mesh, c, face);
        let p: Vec<[f64; 3]> = nodes.iter().map(|&n| coords[n]).collect();
        for (k, area, n) in corner_shares(&p) {
            let u = at(p[k]);
            let i = node_of(c, nodes[k]) as usize;
            for d in 0..3 {
                f[3 * i + d] -= u * area * n[d];
                node_area[i][d] += area * n[d];
            }
        }
    }
    let resultant = [0, 1, 2].map(|d| (0..x0.len()).map(|i| f[3 * i + d]).sum());
    let node_pressure = x0.iter().map(|&p| at(p)).collect();
    let element_pressure = element_centroids.iter().map(|p| p.map_or(0.0, at)).collect();
    let model = WaterModel {
        model: JOINT_WATER,
        unit_weight: water.unit_weight,
        surface,
        cracks: water.crack.iter().map(|c| (c.group.clone(), c.level)).collect(),
        spring_pressure,
        node_pressure,
        element_pressure,
        node_area,
        resultant,
    };
    Ok((f, model))
}
