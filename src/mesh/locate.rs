//! Which cell contains a point: a uniform grid of cell bounding boxes, then
//! the exact test on the cell's own tetrahedra (the decomposition of
//! [`super::shape`], so a perturbed hexahedron with warped faces is located
//! as the CDEM element it becomes).
//!
//! A point on a face shared by two cells goes to the lower cell index; a
//! point outside every cell (beyond `1e-9` of the mesh extent) has none.

use super::shape::{tet_volume, CellKind, Decomposition};
use super::Cell;

/// A point locator over the cells of a mesh.
pub struct CellLocator {
    /// Corner positions of each cell's decomposition points.
    points: Vec<Vec<[f64; 3]>>,
    kinds: Vec<CellKind>,
    /// Sub-tetrahedra of each kind, indexed by `CellKind as usize`.
    tets: [Vec<[usize; 4]>; 3],
    lo: [f64; 3],
    size: [f64; 3],
    dims: [usize; 3],
    /// Cells whose bounding box overlaps grid bin `b`: `bins[start[b]..start[b + 1]]`.
    start: Vec<usize>,
    bins: Vec<u32>,
    eps: f64,
}

impl CellLocator {
    /// Builds the locator over `cells` with node positions `coords`.
    pub fn new(coords: &[[f64; 3]], cells: &[Cell]) -> Self {
        let decs = [CellKind::Tet4, CellKind::Prism6, CellKind::Hex8].map(Decomposition::of);
        let dec = |k: CellKind| &decs[k as usize];
        let points: Vec<Vec<[f64; 3]>> = cells
            .iter()
            .map(|c| dec(c.kind).points(&c.corners().iter().map(|&n| coords[n]).collect::<Vec<_>>()))
            .collect();
        let boxes: Vec<([f64; 3], [f64; 3])> = cells
            .iter()
            .map(|c| {
                let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
                for &n in c.corners() {
                    for d in 0..3 {
                        lo[d] = lo[d].min(coords[n][d]);
                        hi[d] = hi[d].max(coords[n][d]);
                    }
                }
                (lo, hi)
            })
            .collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for (a, b) in &boxes {
            for d in 0..3 {
                lo[d] = lo[d].min(a[d]);
                hi[d] = hi[d].max(b[d]);
            }
        }
        let extent = (0..3).map(|d| hi[d] - lo[d]).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
        let eps = 1e-9 * extent;
        // About one cell per bin along each axis.
        let per_axis = (cells.len().max(1) as f64).cbrt().ceil();
        let dims = [0, 1, 2].map(|d| {
            let thin = (hi[d] - lo[d]) < 1e-6 * extent;
            if thin {
                1
            } else {
                (per_axis * (hi[d] - lo[d]) / extent).ceil().clamp(1.0, 512.0) as usize
            }
        });
        let size = [0, 1, 2].map(|d| ((hi[d] - lo[d]) / dims[d] as f64).max(f64::MIN_POSITIVE));
        let bin_range = |a: f64, b: f64, d: usize| {
            let i0 = (((a - eps - lo[d]) / size[d]).floor().max(0.0) as usize).min(dims[d] - 1);
            let i1 = (((b + eps - lo[d]) / size[d]).floor().max(0.0) as usize).min(dims[d] - 1);
            i0..=i1
        };
        let n_bins = dims[0] * dims[1] * dims[2];
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); n_bins];
        for (c, (a, b)) in boxes.iter().enumerate() {
            for i in bin_range(a[0], b[0], 0) {
                for j in bin_range(a[1], b[1], 1) {
                    for k in bin_range(a[2], b[2], 2) {
                        lists[(i * dims[1] + j) * dims[2] + k].push(c as u32);
                    }
                }
            }
        }
        let mut start = Vec::with_capacity(n_bins + 1);
        let mut bins = Vec::new();
        for l in lists {
            start.push(bins.len());
            bins.extend(l);
        }
        start.push(bins.len());
        let tets = decs.map(|d| d.tets);
        Self { points, kinds: cells.iter().map(|c| c.kind).collect(), tets, lo, size, dims, start, bins, eps }
    }

    /// The cell containing `p`, if any.
    pub fn locate(&self, p: [f64; 3]) -> Option<usize> {
        let mut bin = 0;
        for d in 0..3 {
            let t = (p[d] - self.lo[d]) / self.size[d];
            if t < -self.eps / self.size[d] || t > self.dims[d] as f64 + self.eps / self.size[d] {
                return None;
            }
            bin = bin * self.dims[d] + (t.floor().max(0.0) as usize).min(self.dims[d] - 1);
        }
        self.bins[self.start[bin]..self.start[bin + 1]].iter().map(|&c| c as usize).find(|&c| self.contains(c, p))
    }

    /// Whether cell `c` contains `p`: inside one of its tetrahedra, each
    /// barycentric volume at least `-eps` times the tetrahedron's scale.
    fn contains(&self, c: usize, p: [f64; 3]) -> bool {
        let x = &self.points[c];
        self.tets[self.kinds[c] as usize].iter().any(|t| {
            let [a, b, cc, d] = t.map(|i| x[i]);
            let v = tet_volume(a, b, cc, d);
            let tol = -self.eps * v.abs().cbrt().powi(2);
            tet_volume(p, b, cc, d) >= tol
                && tet_volume(a, p, cc, d) >= tol
                && tet_volume(a, b, p, d) >= tol
                && tet_volume(a, b, cc, p) >= tol
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_hex(first: usize) -> Cell {
        let mut nodes = [0; 8];
        for (k, n) in nodes.iter_mut().enumerate() {
            *n = first + k;
        }
        Cell { kind: CellKind::Hex8, nodes, tag: 1 }
    }

    fn hex_coords(o: [f64; 3]) -> Vec<[f64; 3]> {
        let c = [
            [0., 0., 0.],
            [1., 0., 0.],
            [1., 1., 0.],
            [0., 1., 0.],
            [0., 0., 1.],
            [1., 0., 1.],
            [1., 1., 1.],
            [0., 1., 1.],
        ];
        c.iter().map(|p| [p[0] + o[0], p[1] + o[1], p[2] + o[2]]).collect()
    }

    #[test]
    fn points_are_found_in_their_hexahedron_and_outside_points_in_none() {
        let mut coords = hex_coords([0.0, 0.0, 0.0]);
        coords.extend(hex_coords([1.0, 0.0, 0.0]));
        let cells = [unit_hex(0), unit_hex(8)];
        let loc = CellLocator::new(&coords, &cells);
        assert_eq!(loc.locate([0.3, 0.5, 0.7]), Some(0));
        assert_eq!(loc.locate([1.7, 0.2, 0.1]), Some(1));
        // On the shared face: the lower index.
        assert_eq!(loc.locate([1.0, 0.5, 0.5]), Some(0));
        // On the outer surface: still inside.
        assert_eq!(loc.locate([2.0, 1.0, 1.0]), Some(1));
        assert_eq!(loc.locate([2.01, 0.5, 0.5]), None);
        assert_eq!(loc.locate([0.5, 0.5, -0.01]), None);
    }

    #[test]
    fn a_warped_hexahedron_is_located_by_its_tetrahedra() {
        let mut coords = hex_coords([0.0; 3]);
        coords[6] = [1.2, 1.1, 1.3]; // corner pulled out
        let loc = CellLocator::new(&coords, &[unit_hex(0)]);
        assert_eq!(loc.locate([1.05, 1.02, 1.05]), Some(0));
        assert_eq!(loc.locate([0.02, 0.98, 1.05]), None);
    }
}
