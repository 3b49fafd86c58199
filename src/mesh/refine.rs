//! Uniform refinement without gmsh ([`split`]): every cell into eight of its
//! own kind at its edge midpoints (and face and body centres), every facet of
//! a physical group into its four (two for a line), so that the refined mesh
//! keeps the geometry, the groups and the cell kinds; and the MSH 4.1 ASCII
//! writer ([`write_msh`]) that the scene's loader reads back.
//!
//! A new node is the mean of the parent corners it lies between (an edge's
//! two, a quadrangle's four, a hexahedron's eight), keyed by their sorted
//! indices, so that neighbouring cells and the facets on them share it. The
//! children of a hexahedron or prism are its lattice of half-steps (the
//! parent's orientation); a tetrahedron gives its four corner tetrahedra and
//! the inner octahedron cut along one diagonal into four, each reoriented to
//! a positive volume.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

use super::shape::{tet_volume, CellKind};
use super::{Cell, Facet, Mesh, PhysicalGroup};
use crate::error::Error;

/// The refined mesh's nodes: the parent's, then one per key.
struct Nodes<'a> {
    mesh: &'a Mesh,
    out: Vec<[f64; 3]>,
    index: HashMap<Vec<usize>, usize>,
}

impl Nodes<'_> {
    /// The node at the mean of the parent nodes `of` (one: that node).
    fn at(&mut self, of: &[usize]) -> usize {
        let mut key = of.to_vec();
        key.sort_unstable();
        key.dedup();
        if let [one] = key[..] {
            return one;
        }
        if let Some(&i) = self.index.get(&key) {
            return i;
        }
        let mut x = [0.0; 3];
        for &n in &key {
            for d in 0..3 {
                x[d] += self.mesh.nodes[n][d] / key.len() as f64;
            }
        }
        self.out.push(x);
        self.index.insert(key, self.out.len() - 1);
        self.out.len() - 1
    }
}

/// Hexahedron corners in gmsh order as (xi, eta, zeta) in {0, 1}.
const HEX_CORNERS: [[usize; 3]; 8] =
    [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]];

/// The parent corners a lattice point of a hexahedron lies between
/// (`p` in {0, 1, 2}^3, half-steps).
fn hex_point(corners: &[usize], p: [usize; 3]) -> Vec<usize> {
    let allowed = |c: usize, q: usize| q == 1 || q == 2 * c;
    HEX_CORNERS.iter().zip(corners).filter(|(c, _)| (0..3).all(|d| allowed(c[d], p[d]))).map(|(_, &n)| n).collect()
}

/// A triangle's four children as (corner, corner) pairs whose means are
/// their corners: `[a, a]` is corner a, `[a, b]` the midpoint of a and b.
const TRI_CHILDREN: [[[usize; 2]; 3]; 4] =
    [[[0, 0], [0, 1], [2, 0]], [[0, 1], [1, 1], [1, 2]], [[2, 0], [1, 2], [2, 2]], [[0, 1], [1, 2], [2, 0]]];

/// A quadrangle's four children in (u, v) half-steps, counter-clockwise as the parent.
const QUAD_CHILDREN: [[[usize; 2]; 4]; 4] = [
    [[0, 0], [1, 0], [1, 1], [0, 1]],
    [[1, 0], [2, 0], [2, 1], [1, 1]],
    [[1, 1], [2, 1], [2, 2], [1, 2]],
    [[0, 1], [1, 1], [1, 2], [0, 2]],
];

/// The parent corners of a quadrangle's lattice point (corners 0..3 at
/// (0,0) (1,0) (1,1) (0,1)).
fn quad_point(corners: &[usize], p: [usize; 2]) -> Vec<usize> {
    const AT: [[usize; 2]; 4] = [[0, 0], [1, 0], [1, 1], [0, 1]];
    let allowed = |c: usize, q: usize| q == 1 || q == 2 * c;
    AT.iter().zip(corners).filter(|(c, _)| allowed(c[0], p[0]) && allowed(c[1], p[1])).map(|(_, &n)| n).collect()
}

/// The eight children of `cell`, as node lists.
fn split_cell(nodes: &mut Nodes, cell: &Cell) -> Vec<Vec<usize>> {
    let c = cell.corners();
    match cell.kind {
        CellKind::Hex8 => {
            let mut out = Vec::with_capacity(8);
            for o in HEX_CORNERS {
                out.push(
                    HEX_CORNERS
                        .iter()
                        .map(|k| nodes.at(&hex_point(c, [o[0] + k[0], o[1] + k[1], o[2] + k[2]])))
                        .collect(),
                );
            }
            out
        }
        CellKind::Prism6 => {
            // Bottom triangle 0 1 2, top 3 4 5; level 0, 1 (middle), 2 in zeta.
            let level = |pair: [usize; 2], z: usize| -> Vec<usize> {
                let bottom = [c[pair[0]], c[pair[1]]];
                let top = [c[pair[0] + 3], c[pair[1] + 3]];
                match z {
                    0 => bottom.to_vec(),
                    2 => top.to_vec(),
                    _ => bottom.iter().chain(&top).copied().collect(),
                }
            };
            let mut out = Vec::with_capacity(8);
            for z in 0..2 {
                for tri in TRI_CHILDREN {
                    let mut child: Vec<usize> = tri.iter().map(|&p| nodes.at(&level(p, z))).collect();
                    child.extend(tri.iter().map(|&p| nodes.at(&level(p, z + 1))));
                    out.push(child);
                }
            }
            out
        }
        CellKind::Tet4 => {
            let m = |a: usize, b: usize, nodes: &mut Nodes| nodes.at(&[c[a], c[b]]);
            let (m01, m02, m03) = (m(0, 1, nodes), m(0, 2, nodes), m(0, 3, nodes));
            let (m12, m13, m23) = (m(1, 2, nodes), m(1, 3, nodes), m(2, 3, nodes));
            let mut out = vec![
                vec![c[0], m01, m02, m03],
                vec![m01, c[1], m12, m13],
                vec![m02, m12, c[2], m23],
                vec![m03, m13, m23, c[3]],
            ];
            // The octahedron around the diagonal m02-m13: its ring m01 m12 m23 m03.
            let ring = [m01, m12, m23, m03];
            for i in 0..4 {
                out.push(vec![m02, m13, ring[i], ring[(i + 1) % 4]]);
            }
            for t in &mut out {
                let x = |k: usize| nodes.out[t[k]];
                if tet_volume(x(0), x(1), x(2), x(3)) < 0.0 {
                    t.swap(2, 3);
                }
            }
            out
        }
    }
}

/// The children of a facet of a physical group.
fn split_facet(nodes: &mut Nodes, f: &Facet) -> Vec<Vec<usize>> {
    let c = f.nodes();
    match c.len() {
        2 => {
            let m = nodes.at(c);
            vec![vec![c[0], m], vec![m, c[1]]]
        }
        3 => TRI_CHILDREN.iter().map(|t| t.iter().map(|p| nodes.at(&[c[p[0]], c[p[1]]])).collect()).collect(),
        4 => QUAD_CHILDREN.iter().map(|q| q.iter().map(|&p| nodes.at(&quad_point(c, p))).collect()).collect(),
        _ => vec![c.to_vec()],
    }
}

/// `mesh` with every cell split into eight and every facet of a group into
/// its four (see the module doc): the element size halved, the groups kept.
/// Cell and node tags are renumbered from 1.
pub fn split(mesh: &Mesh) -> Mesh {
    let mut nodes = Nodes { mesh, out: mesh.nodes.clone(), index: HashMap::new() };
    let mut cells = Vec::with_capacity(8 * mesh.cells.len());
    let mut children: Vec<Vec<usize>> = Vec::with_capacity(mesh.cells.len());
    for cell in &mesh.cells {
        let mut mine = Vec::with_capacity(8);
        for child in split_cell(&mut nodes, cell) {
            let mut n = [0; 8];
            n[..child.len()].copy_from_slice(&child);
            mine.push(cells.len());
            cells.push(Cell { kind: cell.kind, nodes: n, tag: cells.len() as u64 + 1 });
        }
        children.push(mine);
    }
    let groups = mesh
        .groups
        .iter()
        .map(|g| PhysicalGroup {
            dim: g.dim,
            tag: g.tag,
            name: g.name.clone(),
            cells: g.cells.iter().flat_map(|&c| children[c].iter().copied()).collect(),
            facets: g
                .facets
                .iter()
                .flat_map(|f| split_facet(&mut nodes, f))
                .map(|f| {
                    let mut n = [0; 4];
                    n[..f.len()].copy_from_slice(&f);
                    Facet { nodes: n, n: f.len() as u8 }
                })
                .collect(),
        })
        .collect();
    let node_tags = (1..=nodes.out.len() as u64).collect();
    Mesh { nodes: nodes.out, node_tags, cells, groups }
}

/// The gmsh element type of a facet of `n` nodes.
fn facet_type(n: u8) -> i32 {
    match n {
        1 => 15,
        2 => 1,
        3 => 2,
        _ => 3,
    }
}

/// Writes `mesh` as MSH 4.1 ASCII: one surface (curve, point) entity per
/// facet group (a facet in two groups is written once in each, as the
/// reader keeps it), one volume entity per set of volume groups a cell is in
/// (each cell written once); nodes and elements numbered from 1.
pub fn write_msh(mesh: &Mesh, path: &Path) -> Result<(), Error> {
    let mut s = String::from("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n");
    let _ = writeln!(s, "{}", mesh.groups.len());
    for g in &mesh.groups {
        let _ = writeln!(s, "{} {} \"{}\"", g.dim, g.tag, g.name);
    }
    s.push_str("$EndPhysicalNames\n$Entities\n");
    let mut member: Vec<Vec<i32>> = vec![Vec::new(); mesh.cells.len()];
    for g in mesh.groups.iter().filter(|g| g.dim == 3) {
        for &c in &g.cells {
            member[c].push(g.tag);
        }
    }
    let mut volumes: std::collections::BTreeMap<Vec<i32>, Vec<usize>> = Default::default();
    for (c, tags) in member.into_iter().enumerate() {
        volumes.entry(tags).or_default().push(c);
    }
    let mut counts = [0usize; 4];
    for g in mesh.groups.iter().filter(|g| g.dim < 3) {
        counts[g.dim as usize] += 1;
    }
    counts[3] = volumes.len();
    let _ = writeln!(s, "{} {} {} {}", counts[0], counts[1], counts[2], counts[3]);
    // Facet group k is entity (dim, k + 1); the volume entities are 1, 2, ...
    for dim in 0..3u8 {
        for (k, g) in mesh.groups.iter().enumerate().filter(|(_, g)| g.dim == dim) {
            let (coords, bounding) = if dim == 0 { ("0 0 0", "") } else { ("0 0 0 0 0 0", " 0") };
            let _ = writeln!(s, "{} {coords} 1 {}{bounding}", k + 1, g.tag);
        }
    }
    for (v, tags) in volumes.keys().enumerate() {
        let phys: Vec<String> = tags.iter().map(i32::to_string).collect();
        let _ = writeln!(s, "{} 0 0 0 0 0 0 {} {} 0", v + 1, tags.len(), phys.join(" "));
    }
    let _ = writeln!(s, "$EndEntities\n$Nodes\n1 {n} 1 {n}\n3 1 0 {n}", n = mesh.nodes.len());
    for i in 1..=mesh.nodes.len() {
        let _ = writeln!(s, "{i}");
    }
    for x in &mesh.nodes {
        let _ = writeln!(s, "{:.17e} {:.17e} {:.17e}", x[0], x[1], x[2]);
    }
    s.push_str("$EndNodes\n$Elements\n");
    let mut blocks = String::new();
    let (mut n_blocks, mut tag) = (0, 0usize);
    let mut block = |dim: u8, entity: usize, kind: i32, elements: &mut dyn Iterator<Item = &[usize]>| {
        let lines: Vec<String> = elements
            .map(|nodes| {
                tag += 1;
                let ids: Vec<String> = nodes.iter().map(|n| (n + 1).to_string()).collect();
                format!("{tag} {}", ids.join(" "))
            })
            .collect();
        if !lines.is_empty() {
            n_blocks += 1;
            let _ = writeln!(blocks, "{dim} {entity} {kind} {}\n{}", lines.len(), lines.join("\n"));
        }
    };
    for (k, g) in mesh.groups.iter().enumerate().filter(|(_, g)| g.dim < 3) {
        for n in 1..=4u8 {
            let mut it = g.facets.iter().filter(|f| f.n == n).map(|f| f.nodes());
            block(g.dim, k + 1, facet_type(n), &mut it);
        }
    }
    for (v, cells) in volumes.values().enumerate() {
        for kind in [CellKind::Tet4, CellKind::Hex8, CellKind::Prism6] {
            let mut it = cells.iter().map(|&c| &mesh.cells[c]).filter(|c| c.kind == kind).map(|c| c.corners());
            block(3, v + 1, kind.gmsh_type(), &mut it);
        }
    }
    let _ = writeln!(s, "{n_blocks} {tag} 1 {tag}");
    s.push_str(&blocks);
    s.push_str("$EndElements\n");
    crate::atomic::write_atomic(path, s.as_bytes()).map_err(|e| Error::io(path, e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::gmsh::parse_msh;
    use crate::mesh::shape::check_cell;

    fn volume(mesh: &Mesh) -> f64 {
        mesh.cells
            .iter()
            .map(|c| {
                let x: Vec<[f64; 3]> = c.corners().iter().map(|&n| mesh.nodes[n]).collect();
                check_cell(c.kind, &x).expect("a valid cell")
            })
            .sum()
    }

    fn one(kind: CellKind, x: &[[f64; 3]]) -> Mesh {
        let mut nodes = [0; 8];
        for (i, n) in nodes.iter_mut().enumerate().take(x.len()) {
            *n = i;
        }
        let faces = kind.faces();
        let bottom: Vec<usize> = faces[0].to_vec();
        let mut f = [0; 4];
        f[..bottom.len()].copy_from_slice(&bottom);
        Mesh {
            nodes: x.to_vec(),
            node_tags: (1..=x.len() as u64).collect(),
            cells: vec![Cell { kind, nodes, tag: 1 }],
            groups: vec![
                PhysicalGroup { dim: 3, tag: 1, name: "rock".into(), cells: vec![0], facets: vec![] },
                PhysicalGroup {
                    dim: 2,
                    tag: 2,
                    name: "face".into(),
                    cells: vec![],
                    facets: vec![Facet { nodes: f, n: bottom.len() as u8 }],
                },
            ],
        }
    }

    /// Each kind splits into eight valid cells of the same total volume; its
    /// facet into four; and the written file reads back as the same mesh.
    #[test]
    fn every_kind_splits_into_eight_of_the_same_volume_and_reads_back() {
        let hex = [
            [0., 0., 0.],
            [2., 0., 0.],
            [2., 1., 0.],
            [0., 1., 0.],
            [0., 0., 1.],
            [2., 0., 1.],
            [2., 1., 1.5],
            [0., 1., 1.],
        ];
        let prism = [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 2.], [1., 0., 2.], [0., 1., 2.]];
        let tet = [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]];
        for (kind, x) in [(CellKind::Hex8, &hex[..]), (CellKind::Prism6, &prism[..]), (CellKind::Tet4, &tet[..])] {
            let mesh = one(kind, x);
            let fine = split(&mesh);
            assert_eq!(fine.cells.len(), 8, "{kind:?}");
            assert!((volume(&fine) - volume(&mesh)).abs() < 1e-12, "{kind:?}");
            assert_eq!(fine.groups[1].facets.len(), 4, "{kind:?}");
            let dir = std::env::temp_dir().join(format!("cdem-split-{}", std::process::id()));
            std::fs::create_dir_all(&dir).unwrap();
            let path = dir.join(format!("{kind:?}.msh"));
            write_msh(&fine, &path).unwrap();
            let back = parse_msh(&std::fs::read(&path).unwrap()).unwrap();
            assert_eq!(back.cells.len(), 8);
            assert_eq!(back.nodes.len(), fine.nodes.len());
            assert_eq!(back.group("face").unwrap().facets.len(), 4);
            assert_eq!(back.group("rock").unwrap().cells.len(), 8);
            assert!((volume(&back) - volume(&mesh)).abs() < 1e-12, "{kind:?}");
        }
    }

    /// Two hexahedra that share a face share its refined nodes: 3 x 3 x 5
    /// lattice points, not two separate 27s.
    #[test]
    fn neighbours_share_their_refined_face() {
        let mut mesh = one(
            CellKind::Hex8,
            &[
                [0., 0., 0.],
                [1., 0., 0.],
                [1., 1., 0.],
                [0., 1., 0.],
                [0., 0., 1.],
                [1., 0., 1.],
                [1., 1., 1.],
                [0., 1., 1.],
            ],
        );
        mesh.nodes.extend([[0., 0., 2.], [1., 0., 2.], [1., 1., 2.], [0., 1., 2.]]);
        mesh.cells.push(Cell { kind: CellKind::Hex8, nodes: [4, 5, 6, 7, 8, 9, 10, 11], tag: 2 });
        let fine = split(&mesh);
        assert_eq!(fine.nodes.len(), 45);
        assert_eq!(fine.cells.len(), 16);
    }
}
