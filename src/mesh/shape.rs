//! Reference shapes of the supported cells (gmsh node order) and the
//! polyhedron -> tetrahedra decomposition of docs/method.md section 2.
//!
//! Every face is listed with its corners counter-clockwise seen from outside
//! (right-hand rule gives the outward normal). A face edge `(a, b)` with the
//! face centroid `F` and the body centroid `C` forms the tetrahedron
//! `(b, a, F, C)`, positively oriented for a valid cell: 24 tetrahedra for a
//! hexahedron, 18 for a prism; a tetrahedron is its own single tetrahedron.

/// Supported volume cells.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CellKind {
    Tet4,
    Prism6,
    Hex8,
}

const HEX_FACES: [&[usize]; 6] =
    [&[0, 3, 2, 1], &[4, 5, 6, 7], &[0, 1, 5, 4], &[3, 7, 6, 2], &[0, 4, 7, 3], &[1, 2, 6, 5]];
const PRISM_FACES: [&[usize]; 5] = [&[0, 2, 1], &[3, 4, 5], &[0, 1, 4, 3], &[1, 2, 5, 4], &[0, 3, 5, 2]];
const TET_FACES: [&[usize]; 4] = [&[0, 2, 1], &[0, 1, 3], &[0, 3, 2], &[1, 2, 3]];

impl CellKind {
    /// gmsh element type number.
    pub fn gmsh_type(self) -> i32 {
        match self {
            CellKind::Tet4 => 4,
            CellKind::Hex8 => 5,
            CellKind::Prism6 => 6,
        }
    }
    pub fn from_gmsh_type(t: i32) -> Option<Self> {
        match t {
            4 => Some(CellKind::Tet4),
            5 => Some(CellKind::Hex8),
            6 => Some(CellKind::Prism6),
            _ => None,
        }
    }
    pub fn n_nodes(self) -> usize {
        match self {
            CellKind::Tet4 => 4,
            CellKind::Prism6 => 6,
            CellKind::Hex8 => 8,
        }
    }
    /// Faces as local corner indices, counter-clockwise seen from outside.
    pub fn faces(self) -> &'static [&'static [usize]] {
        match self {
            CellKind::Tet4 => &TET_FACES,
            CellKind::Prism6 => &PRISM_FACES,
            CellKind::Hex8 => &HEX_FACES,
        }
    }
    /// Number of sub-tetrahedra of the decomposition.
    pub fn n_tets(self) -> usize {
        match self {
            CellKind::Tet4 => 1,
            _ => self.faces().iter().map(|f| f.len()).sum(),
        }
    }
    /// Number of points of the decomposition: corners, face centroids, body
    /// centroid (a tetrahedron has only its corners).
    pub fn n_points(self) -> usize {
        match self {
            CellKind::Tet4 => 4,
            _ => self.n_nodes() + self.faces().len() + 1,
        }
    }
}

/// Maximum number of decomposition points (hexahedron: 8 + 6 + 1).
pub const MAX_POINTS: usize = 15;
/// Maximum number of sub-tetrahedra (hexahedron).
pub const MAX_TETS: usize = 24;

/// The decomposition of one cell kind: the weights mapping corners to points
/// (`T`, rows sum to 1) and the sub-tetrahedra as point indices.
#[derive(Debug, Clone)]
pub struct Decomposition {
    pub n_corners: usize,
    /// `weights[p][c]`: weight of corner `c` in point `p`.
    pub weights: Vec<Vec<f64>>,
    pub tets: Vec<[usize; 4]>,
}

impl Decomposition {
    pub fn of(kind: CellKind) -> Self {
        let n = kind.n_nodes();
        if kind == CellKind::Tet4 {
            let weights = (0..4).map(|p| (0..4).map(|c| f64::from(u8::from(p == c))).collect()).collect();
            return Self { n_corners: 4, weights, tets: vec![[0, 1, 2, 3]] };
        }
        let faces = kind.faces();
        let mut weights: Vec<Vec<f64>> =
            (0..n).map(|p| (0..n).map(|c| f64::from(u8::from(p == c))).collect()).collect();
        for f in faces {
            let mut w = vec![0.0; n];
            for &c in *f {
                w[c] = 1.0 / f.len() as f64;
            }
            weights.push(w);
        }
        weights.push(vec![1.0 / n as f64; n]);
        let body = n + faces.len();
        let mut tets = Vec::with_capacity(kind.n_tets());
        for (fi, f) in faces.iter().enumerate() {
            for k in 0..f.len() {
                let (a, b) = (f[k], f[(k + 1) % f.len()]);
                tets.push([b, a, n + fi, body]);
            }
        }
        Self { n_corners: n, weights, tets }
    }

    /// Positions of all decomposition points from corner positions.
    pub fn points(&self, corners: &[[f64; 3]]) -> Vec<[f64; 3]> {
        self.weights
            .iter()
            .map(|w| {
                let mut p = [0.0; 3];
                for (c, &wc) in w.iter().enumerate() {
                    for d in 0..3 {
                        p[d] += wc * corners[c][d];
                    }
                }
                p
            })
            .collect()
    }
}

/// Signed volume of the tetrahedron (a, b, c, d): positive when (b-a, c-a, d-a)
/// is right-handed.
pub fn tet_volume(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> f64 {
    let u = sub(b, a);
    let v = sub(c, a);
    let w = sub(d, a);
    dot(cross(u, v), w) / 6.0
}

#[inline]
pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
#[inline]
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
#[inline]
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
#[inline]
pub fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// Why a cell failed its check: an inverted or degenerate sub-tetrahedron.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CellDefect {
    Inverted { tet: usize, volume: f64 },
    Degenerate { tet: usize, volume: f64 },
}

/// Relative volume below which a sub-tetrahedron counts as degenerate
/// (volume / longest-edge^3).
pub const DEGENERATE_RATIO: f64 = 1e-10;

/// Checks every sub-tetrahedron of a cell for positive volume. Returns the
/// cell volume.
pub fn check_cell(kind: CellKind, corners: &[[f64; 3]]) -> Result<f64, CellDefect> {
    let dec = Decomposition::of(kind);
    let p = dec.points(corners);
    let mut lmax: f64 = 0.0;
    for a in corners {
        for b in corners {
            lmax = lmax.max(norm(sub(*a, *b)));
        }
    }
    let tol = DEGENERATE_RATIO * lmax.powi(3);
    let mut total = 0.0;
    for (t, tet) in dec.tets.iter().enumerate() {
        let v = tet_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]);
        if !(v.abs() > tol) {
            return Err(CellDefect::Degenerate { tet: t, volume: v });
        }
        if v < 0.0 {
            return Err(CellDefect::Inverted { tet: t, volume: v });
        }
        total += v;
    }
    Ok(total)
}

impl CellDefect {
    /// The mesh error naming the element by its gmsh tag.
    pub fn into_mesh_error(self, element: u64) -> crate::error::MeshError {
        match self {
            CellDefect::Inverted { tet, volume } => crate::error::MeshError::Inverted { element, tet, volume },
            CellDefect::Degenerate { tet, volume } => crate::error::MeshError::Degenerate { element, tet, volume },
        }
    }
}
