//! The immutable [`Model`]: node copies (struct of arrays), elements with their
//! condensed operators, springs, constraints and loads. Built once from a
//! [`Mesh`](crate::mesh::Mesh) and a [`ModelSpec`] by [`build`], never
//! changed after: what a run changes (displacements, spring history, what
//! each joint can carry) is the solver's state.

mod build;
pub mod spec;
pub mod supports;
pub(crate) mod union_find;
pub mod water;

pub use build::build;
pub use build::{cell_materials, fixed_mesh_nodes, perturbed_coordinates, spec_materials};
pub use spec::{JointMode, ModelSpec};

use crate::mesh::shape::CellDefect;
use crate::mesh::CellKind;
use crate::physics::element::{element_stress, packed_entry, packed_len};
use crate::physics::joint::{JointProps, JointState};
use crate::physics::material::Material;
use crate::physics::plastic::{cell_plastic, CellPlastic, PlasticCells, RockState, Volumetric};
use crate::physics::spring::Springs;
use crate::physics::tet_operator::TetOperators;
use crate::summary::PlasticSummary;

/// Elements, struct of arrays. Element `e` owns corners
/// `nodes[offset[e]..offset[e+1]]` (model node indices) and the stiffness
/// block `k[k_offset[e]..]`: the upper triangle of the symmetric `K_e` in
/// corner blocks, [`packed_len`]`(n)` values
/// ([`pack_symmetric`](crate::physics::element::pack_symmetric)).
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
    /// The packed `K_e` of element `e` (what [`element_force`](crate::physics::element::element_force) reads).
    pub fn stiffness(&self, e: usize) -> &[f64] {
        let n = self.offset[e + 1] - self.offset[e];
        &self.k[self.k_offset[e]..self.k_offset[e] + packed_len(n)]
    }
    /// Entry `(row, col)` of element `e`'s `K_e` (dof `3c + i`).
    pub fn stiffness_entry(&self, e: usize, row: usize, col: usize) -> f64 {
        packed_entry(self.stiffness(e), self.offset[e + 1] - self.offset[e], row, col)
    }
    /// Element `e`'s full `K_e`, `3n x 3n` row-major in the first `(3n)^2`
    /// values ([`unpack_symmetric`](crate::physics::element::unpack_symmetric)).
    pub fn stiffness_full(&self, e: usize) -> [f64; 576] {
        crate::physics::element::unpack_symmetric(self.stiffness(e), self.offset[e + 1] - self.offset[e])
    }
}

/// One interface kind: index 0 is the scene's default `[joints]`, then one per
/// `[[interface]]` in scene order.
#[derive(Debug, Clone)]
pub struct Interface {
    pub name: String,
    pub mode: JointMode,
    /// Stiffness and, if breakable, strength, as the scene gives them (what
    /// a spring can carry now is the run's [`JointState`]).
    pub props: JointProps,
}

/// Stride of an element's force slot in the solver's scratch (a hexahedron's
/// 8 corners x 3; prisms and tetrahedra use the front of their slot).
pub const ELEMENT_SLOT: usize = 24;

/// Per-node gather lists (CSR): where each node finds its force contributions,
/// in a fixed order, so that forces are summed without two threads writing
/// one node and with the same result whatever the thread count.
#[derive(Debug, Clone, Default)]
pub struct Gather {
    pub elem_ptr: Vec<u32>,
    /// Offsets `ELEMENT_SLOT e + 3 c` of the element-force scratch.
    pub elem_slot: Vec<u32>,
    pub spring_ptr: Vec<u32>,
    /// `2 s` if the node is the spring's `a` (gets `-F`), `2 s + 1` if `b` (`+F`).
    pub spring_end: Vec<u32>,
}

impl Gather {
    pub fn build(elements: &Elements, springs: &Springs, n_nodes: usize) -> Self {
        let mut per_node: Vec<Vec<u32>> = vec![Vec::new(); n_nodes];
        for e in 0..elements.len() {
            for (c, &node) in elements.corners(e).iter().enumerate() {
                per_node[node as usize].push((ELEMENT_SLOT * e + 3 * c) as u32);
            }
        }
        let (elem_ptr, elem_slot) = csr(&per_node);
        let mut per_node: Vec<Vec<u32>> = vec![Vec::new(); n_nodes];
        for s in 0..springs.len() {
            per_node[springs.a[s] as usize].push(2 * s as u32);
            per_node[springs.b[s] as usize].push(2 * s as u32 + 1);
        }
        let (spring_ptr, spring_end) = csr(&per_node);
        Self { elem_ptr, elem_slot, spring_ptr, spring_end }
    }
}

fn csr(lists: &[Vec<u32>]) -> (Vec<u32>, Vec<u32>) {
    let mut ptr = Vec::with_capacity(lists.len() + 1);
    ptr.push(0);
    let mut idx = Vec::new();
    for l in lists {
        idx.extend_from_slice(l);
        ptr.push(idx.len() as u32);
    }
    (ptr, idx)
}

/// The box of `points`: `(lo, hi)` per axis (m); infinite bounds (`lo > hi`)
/// for no point. [`Model::bounds_of`], and the build before there is a model.
pub fn point_bounds(points: impl IntoIterator<Item = [f64; 3]>) -> ([f64; 3], [f64; 3]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in points {
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    (lo, hi)
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
    /// External force (gravity and water), `3 i + d` (N).
    pub f_ext: Vec<f64>,
    /// The scene's gravity (m/s^2): its direction is "down" for a runout's drop.
    pub gravity: [f64; 3],
    pub elements: Elements,
    /// Per-tetrahedron operators of the elements whose material yields.
    pub plastic: PlasticCells,
    pub springs: Springs,
    pub materials: Vec<Material>,
    pub interfaces: Vec<Interface>,
    pub gather: Gather,
    /// Perturbed mesh node coordinates (m).
    pub mesh_coords: Vec<[f64; 3]>,
    /// The scene's `[water]` (its forces are in `f_ext`), if any.
    pub water: Option<water::WaterModel>,
    /// The plastic prisms' and tetrahedra's smoothing weight
    /// (`[failure] smoothing`, [`crate::physics::plastic::NODE_SMOOTHING`]).
    pub smoothing: f64,
}

impl Model {
    /// The per-tetrahedron operators of every element (the alternative form of
    /// eq. 12, [`TetOperators`]), from the reference coordinates; the error
    /// names the first element whose cell is defective.
    pub fn tet_operators(&self) -> Result<TetOperators, (usize, CellDefect)> {
        let el = &self.elements;
        let mut ops = TetOperators::new();
        for e in 0..el.len() {
            let corners: Vec<[f64; 3]> = el.corners(e).iter().map(|&n| self.x0[n as usize]).collect();
            ops.push(el.kind[e], &corners, self.materials[el.material[e] as usize].lame).map_err(|d| (e, d))?;
        }
        Ok(ops)
    }

    pub fn n_nodes(&self) -> usize {
        self.x0.len()
    }

    /// Each element's equivalent normal stiffness per unit area,
    /// `(K + 4G/3) / dz_min` (Pa/m): the P-wave modulus `lambda + 2 mu` over
    /// the element's smallest width normal to one of its faces (the distance
    /// from the face's plane to the farthest corner), as the Itasca codes
    /// measure "the stiffest neighbouring zone".
    pub fn zone_stiffness(&self) -> Vec<f64> {
        let el = &self.elements;
        (0..el.len())
            .map(|e| {
                let corners: Vec<[f64; 3]> = el.corners(e).iter().map(|&c| self.x0[c as usize]).collect();
                let width = el.kind[e]
                    .faces()
                    .iter()
                    .map(|fc| {
                        let p: Vec<[f64; 3]> = fc.iter().map(|&c| corners[c]).collect();
                        let (n, _) = crate::mesh::adjacency::polygon_normal_area(&p);
                        corners
                            .iter()
                            .map(|q| ((0..3).map(|d| (q[d] - p[0][d]) * n[d]).sum::<f64>()).abs())
                            .fold(0.0, f64::max)
                    })
                    .fold(f64::INFINITY, f64::min);
                let lame = self.materials[el.material[e] as usize].lame;
                (lame.lambda + 2.0 * lame.mu) / width
            })
            .collect()
    }

    /// This model with every spring's normal and shear stiffness limited to
    /// `factor` times the [`Self::zone_stiffness`] of the softer of its two
    /// elements, times its area: the Itasca codes' rule for joint stiffness
    /// (at most ten times the stiffest neighbouring zone's), taken on the
    /// softer side so that each node's own element bounds its time step
    /// (references/runout.md). Returns the model and how many springs were
    /// limited.
    pub fn with_spring_limit(&self, factor: f64) -> (Model, usize) {
        let zone = self.zone_stiffness();
        let mut elem_of = vec![0u32; self.n_nodes()];
        let el = &self.elements;
        for e in (0..el.len()).rev() {
            for &c in el.corners(e) {
                elem_of[c as usize] = e as u32;
            }
        }
        let mut out = self.clone();
        let sp = &mut out.springs;
        let mut limited = 0;
        for s in 0..sp.len() {
            let k = zone[elem_of[sp.a[s] as usize] as usize].min(zone[elem_of[sp.b[s] as usize] as usize]);
            let cap = factor * k * sp.area[s];
            limited += usize::from(sp.kn[s] > cap || sp.ks[s] > cap);
            sp.kn[s] = sp.kn[s].min(cap);
            sp.ks[s] = sp.ks[s].min(cap);
        }
        (out, limited)
    }

    /// The box of the node copies `nodes` at rest: `(lo, hi)` per axis (m);
    /// infinite bounds (`lo > hi`) for no node.
    pub fn bounds_of(&self, nodes: impl IntoIterator<Item = usize>) -> ([f64; 3], [f64; 3]) {
        point_bounds(nodes.into_iter().map(|i| self.x0[i]))
    }

    /// The box of every node at rest ([`Self::bounds_of`]).
    pub fn bounds(&self) -> ([f64; 3], [f64; 3]) {
        self.bounds_of(0..self.n_nodes())
    }

    /// Each spring's strength as the scene gives it (its interface's): the
    /// joint state a run starts from.
    pub fn joint_state(&self) -> JointState {
        let strengths: Vec<_> = self.interfaces.iter().map(|i| i.props.strength).collect();
        JointState::new(&self.springs.interface, &strengths)
    }

    /// Each material's strength and every tetrahedron elastic: the rock
    /// state a run starts from.
    pub fn rock_state(&self) -> RockState {
        let given = self.materials.iter().map(|m| m.law.strength()).collect();
        RockState::new(given, self.elements.len(), self.mesh_coords.len(), self.smoothing)
    }

    /// Whether any element's material yields (has a strength).
    pub fn has_plastic_blocks(&self) -> bool {
        self.plastic.any()
    }

    /// Whether any interface is breakable (has a strength).
    pub fn has_breakable_interface(&self) -> bool {
        self.interfaces.iter().any(|i| i.props.strength.is_some())
    }

    /// Whether the mesh's own faces carry springs that can all break: the
    /// default joints (interface 0, `[joints]`) carry springs and every
    /// spring has a strength. Springs only on named interface groups
    /// (`[joints]` merged) are real joints between real blocks.
    pub fn every_face_breakable(&self) -> bool {
        self.springs.interface.contains(&0) && self.joint_state().strength.iter().all(Option::is_some)
    }

    /// What each element's plastic tetrahedra look like now (None without
    /// plastic blocks; an elastic element has yielded nothing and its
    /// condensed stress).
    pub fn plastic_cells(&self, rock: &RockState, u: &[f64]) -> Option<Vec<CellPlastic>> {
        if !self.has_plastic_blocks() || rock.history.len() != self.elements.len() {
            return None;
        }
        let el = &self.elements;
        Some(
            (0..el.len())
                .map(|e| {
                    let material = el.material[e] as usize;
                    match rock.given[material] {
                        Some(_) => cell_plastic(
                            self.plastic.topology(el.kind[e]),
                            self.plastic.tets(e),
                            self.materials[material].lame,
                            el.corners(e),
                            u,
                            match self.plastic.nodal[e] {
                                true => {
                                    Volumetric::at_vertices(rock.volumetric[e], rock.used_strain[e], rock.smoothing)
                                }
                                false => Volumetric::Cell,
                            },
                            &rock.history[e],
                        ),
                        None => CellPlastic { stress: self.element_stress(e, u), ..CellPlastic::default() },
                    }
                })
                .collect(),
        )
    }

    /// The summary of [`Self::plastic_cells`].
    pub fn plastic_summary(&self, cells: &[CellPlastic]) -> PlasticSummary {
        let el = &self.elements;
        let mut out = PlasticSummary {
            volume: 0.0,
            yielding_volume: 0.0,
            yielded_volume: 0.0,
            yielding_tension_volume: 0.0,
            yielded_tension_volume: 0.0,
            max_plastic_shear: 0.0,
        };
        for (e, c) in cells.iter().enumerate() {
            if self.materials[el.material[e] as usize].law.strength().is_some() {
                let v = el.volume[e];
                out.volume += v;
                out.yielding_volume += c.yielding * v;
                out.yielded_volume += c.yielded * v;
                out.yielding_tension_volume += c.yielding_tension * v;
                out.yielded_tension_volume += c.yielded_tension * v;
                out.max_plastic_shear = out.max_plastic_shear.max(c.plastic_shear);
            }
        }
        out
    }

    /// Stress of every element (Pa, Voigt xx yy zz yz xz xy) for
    /// displacements `u` and the rock state `rock` (a plastic element's is
    /// the volume average of its tetrahedra's).
    pub fn element_stresses_in(&self, rock: &RockState, u: &[f64]) -> Vec<[f64; 6]> {
        match self.plastic_cells(rock, u) {
            Some(cells) => cells.iter().map(|c| c.stress).collect(),
            None => self.element_stresses(u),
        }
    }

    /// Stress of every element (Pa, Voigt xx yy zz yz xz xy) for displacements
    /// `u`, every element elastic (phase 1).
    pub fn element_stresses(&self, u: &[f64]) -> Vec<[f64; 6]> {
        (0..self.elements.len()).map(|e| self.element_stress(e, u)).collect()
    }

    /// Stress of element `e`, elastic (see [`Self::element_stresses`]).
    pub fn element_stress(&self, e: usize, u: &[f64]) -> [f64; 6] {
        let el = &self.elements;
        let r = el.offset[e]..el.offset[e + 1];
        element_stress(&el.grad[r.clone()], &el.nodes[r], u, self.materials[el.material[e] as usize].lame)
    }
}
