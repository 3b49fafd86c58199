//! Meshes: the gmsh reader, node perturbation ("stochastic structural planes"),
//! the polyhedron -> tetrahedra decomposition and face adjacency.
//!
//! A [`Mesh`] is flat and index based (fenris style): node coordinates in one
//! array, volume cells referring to nodes by index (0-based, dense), physical
//! groups referring to cells (dimension 3) or to facets (dimension 0-2).

pub mod adjacency;
pub mod gmsh;
pub mod locate;
pub mod perturb;
pub mod refine;
pub mod shape;

// pub use adjacency::{FaceAdjacency, SharedFace};
pub use shape::CellKind;

/// A volume cell: a hexahedron, prism or tetrahedron in gmsh node order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub kind: CellKind,
    /// Node indices; only the first `kind.n_nodes()` are meaningful.
    pub nodes: [usize; 8],
    /// The gmsh element tag (for error messages).
    pub tag: u64,
}

impl Cell {
    pub fn corners(&self) -> &[usize] {
        &self.nodes[..self.kind.n_nodes()]
    }
}

/// A lower-dimensional element of a physical group: point (1 node), line (2),
/// triangle (3) or quadrangle (4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Facet {
    pub nodes: [usize; 4],
    pub n: u8,
}

impl Facet {
    pub fn nodes(&self) -> &[usize] {
        &self.nodes[..self.n as usize]
    }
}

/// A gmsh physical group.
#[derive(Debug, Clone, PartialEq)]
pub struct PhysicalGroup {
    pub dim: u8,
    pub tag: i32,
    /// Name from `$PhysicalNames`, or `"<dim>:<tag>"` if unnamed.
    pub name: String,
    /// Cells of a volume group (dim 3): indices into [`Mesh::cells`].
    pub cells: Vec<usize>,
    /// Facets of a surface/line/point group (dim 0-2).
    pub facets: Vec<Facet>,
}

/// A volume mesh with physical groups.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Mesh {
    /// Node coordinates (m).
    pub nodes: Vec<[f64; 3]>,
    /// gmsh node tags, parallel to `nodes` (for error messages).
    pub node_tags: Vec<u64>,
    /// Volume cells.
    pub cells: Vec<Cell>,
    pub groups: Vec<PhysicalGroup>,
}

impl Mesh {
    pub fn group(&self, name: &str) -> Option<&PhysicalGroup> {
        self.groups.iter().find(|g| g.name == name)
    }

    /// Sorted, deduplicated node indices of a group.
    pub fn group_nodes(&self, g: &PhysicalGroup) -> Vec<usize> {
        let mut v: Vec<usize> = if g.dim == 3 {
            g.cells.iter().flat_map(|&c| self.cells[c].corners().to_vec()).collect()
        } else {
            g.facets.iter().flat_map(|f| f.nodes().to_vec()).collect()
        };
        v.sort_unstable();
        v.dedup();
        v
    }

    /// Counts per cell kind: (hexahedra, prisms, tetrahedra).
    pub fn kind_counts(&self) -> (usize, usize, usize) {
        let mut c = (0, 0, 0);
        for cell in &self.cells {
            match cell.kind {
                CellKind::Hex8 => c.0 += 1,
                CellKind::Prism6 => c.1 += 1,
                CellKind::Tet4 => c.2 += 1,
            }
        }
        c
    }
}
