//! The immutable [`Model`]: node copies (struct of arrays), elements with their
//! condensed operators, springs, constraints and loads. Built once from a
//! [`Mesh`](crate::mesh::Mesh) and a [`Scene`](crate::scene::Scene) by [`build`].

mod build;

pub use build::build;

use crate::mesh::CellKind;
use crate::physics::element::element_stress;
use crate::physics::material::Material;
use crate::physics::spring::{Springs, Strength};
use crate::scene::JointMode;

/// Elements, struct of arrays. Element `e` owns corners
/// `nodes[offset[e]..offset[e+1]]` (model node indices) and the stiffness
/// block `k[k_offset[e]..]` of size `(3n)^2`.
#[derive(Debug, Clone, Default)]
pub struct Elements {
    pub kind: Vec<CellKind>,
    pub offset: Vec<usize>,
    pub nodes: Vec<u32>,
    pub k_offset: Vec<usize>,
    pub k: Vec<f64>,
    /// Volume-averaged corner gradients, parallel to `nodes` (for stress).
    pub grad: Vec<[f64; 3]>,
    pub material: Vec<u16>,
    pub volume: Vec<f64>,
    /// gmsh element tag, for messages.
    pub tag: Vec<u64>,
}

impl Elements {
    pub fn len(&self) -> usize {
        self.kind.len()
    }
    pub fn is_empty(&self) -> bool {
        self.kind.is_empty()
    }
    pub fn corners(&self, e: usize) -> &[u32] {
        &self.nodes[self.offset[e]..self.offset[e + 1]]
    }
    pub fn stiffness(&self, e: usize) -> &[f64] {
        let n = 3 * (self.offset[e + 1] - self.offset[e]);
        &self.k[self.k_offset[e]..self.k_offset[e] + n * n]
    }
}

/// One interface kind: index 0 is the scene's default `[joints]`, then one per
/// `[[interface]]` in scene order.
#[derive(Debug, Clone)]
pub struct Interface {
    pub name: String,
    pub mode: JointMode,
    /// Strength if the interface is breakable (failure phase only).
    pub strength: Option<Strength>,
}

/// Everything that does not change during a run.
#[derive(Debug, Clone)]
pub struct Model {
    /// Reference (perturbed) position of each node copy (m).
    pub x0: Vec<[f64; 3]>,
    /// The mesh node each copy was made from.
    pub mesh_node: Vec<u32>,
    /// Lumped physical mass of each node (kg).
    pub mass: Vec<f64>,
    /// Fixed components, `3 i + d`.
    pub fixed: Vec<bool>,
    /// External force (gravity), `3 i + d` (N).
    pub f_ext: Vec<f64>,
    pub elements: Elements,
    pub springs: Springs,
    pub materials: Vec<Material>,
    pub interfaces: Vec<Interface>,
    /// Perturbed mesh node coordinates (m).
    pub mesh_coords: Vec<[f64; 3]>,
}

impl Model {
    pub fn n_nodes(&self) -> usize {
        self.x0.len()
    }

    /// Stress of every element (Pa, Voigt xx yy zz yz xz xy) for displacements `u`.
    pub fn element_stresses(&self, u: &[f64]) -> Vec<[f64; 6]> {
        let el = &self.elements;
        (0..el.len())
            .map(|e| {
                let r = el.offset[e]..el.offset[e + 1];
                element_stress(&el.grad[r.clone()], &el.nodes[r], u, self.materials[el.material[e] as usize].lame)
            })
            .collect()
    }
}
