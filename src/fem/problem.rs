//! The FEM problem of a mesh and its model spec: the continuous mesh (shared nodes, every
//! interface merged, no springs), perturbed exactly as CDEM perturbs it,
//! materials per cell, fixed components and gravity.

use crate::error::Error;
use crate::mesh::adjacency::FaceAdjacency;
use crate::mesh::{Cell, Mesh};
use crate::model::{cell_materials, fixed_mesh_nodes, perturbed_coordinates, spec_materials, ModelSpec};
use crate::physics::material::Material;

/// A linear elastostatic problem on a continuous mesh.
#[derive(Debug, Clone)]
pub struct FemProblem {
    /// Node coordinates (m), perturbed as the scene asks.
    pub coords: Vec<[f64; 3]>,
    /// Volume cells (gmsh order), referring to `coords`.
    pub cells: Vec<Cell>,
    /// Material index of each cell into `materials`.
    pub cell_material: Vec<u16>,
    pub materials: Vec<Material>,
    /// Gravitational acceleration (m/s^2); the body force is `rho g`.
    pub gravity: [f64; 3],
    /// Fixed components, `3 node + axis`.
    pub fixed: Vec<bool>,
    /// Prescribed displacement of the fixed components (m), `3 node + axis`;
    /// zero for a scene (its boundaries only fix).
    pub prescribed: Vec<f64>,
}

impl FemProblem {
    /// Builds the problem of a model spec on a given mesh: 1. perturb the nodes
    /// (same call, seed and flat groups as `model::build`, so the coordinates
    /// are CDEM's bit for bit), 2. materials, 3. fixities.
    pub fn from_mesh(mesh: &Mesh, spec: &ModelSpec) -> Result<Self, Error> {
        let adj = FaceAdjacency::build(mesh)?;
        let coords = perturbed_coordinates(mesh, spec, &adj)?;
        let cell_material = cell_materials(mesh, spec)?;
        let materials = spec_materials(spec);
        let fixed = fixed_mesh_nodes(mesh, spec)?;
        Ok(Self {
            prescribed: vec![0.0; fixed.len()],
            coords,
            cells: mesh.cells.clone(),
            cell_material,
            materials,
            gravity: spec.gravity,
            fixed,
        })
    }

    pub fn n_nodes(&self) -> usize {
        self.coords.len()
    }

    /// Corner coordinates of cell `c`.
    pub fn cell_coords(&self, c: usize) -> Vec<[f64; 3]> {
        self.cells[c].corners().iter().map(|&n| self.coords[n]).collect()
    }
}
