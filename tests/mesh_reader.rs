//! The committed meshes read back as the cases define them: node and cell
//! counts, physical groups, bounding box and total volume (the column is
//! 4 x 4 x 40 = 640 m^3; the slope slab 2 m x (80 x 20 + (60 + 24) / 2 x 20)
//! = 4880 m^3). The binary column equals the ASCII one (to the
//! last digit gmsh prints).

use std::fmt::Write;
use std::path::{Path, PathBuf};

use cdem::mesh::gmsh::{mesh_drift, read_msh};
use cdem::mesh::shape::check_cell;
use cdem::mesh::Mesh;

fn path(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

fn read(relative: &str) -> Mesh {
    read_msh(&path(relative)).unwrap_or_else(|e| panic!("{relative}: {e}"))
}

/// Rounds to 1e-6 and prints without a spurious `-0`.
fn round(x: f64) -> String {
    let r = (x * 1e6).round() / 1e6;
    format!("{}", if r == 0.0 { 0.0 } else { r })
}

/// A small text summary of a mesh, for a snapshot.
fn summary(mesh: &Mesh) -> String {
    let mut s = String::new();
    let (hex, prism, tet) = mesh.kind_counts();
    writeln!(s, "nodes: {}", mesh.nodes.len()).unwrap();
    writeln!(s, "cells: {hex} hexahedra, {prism} prisms, {tet} tetrahedra").unwrap();
    writeln!(s, "groups:").unwrap();
    for g in &mesh.groups {
        let members =
            if g.dim == 3 { format!("{} cells", g.cells.len()) } else { format!("{} facets", g.facets.len()) };
        writeln!(s, "  - dim {} tag {} {:?}: {members}", g.dim, g.tag, g.name).unwrap();
    }
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for x in &mesh.nodes {
        for d in 0..3 {
            lo[d] = lo[d].min(x[d]);
            hi[d] = hi[d].max(x[d]);
        }
    }
    let fmt = |p: [f64; 3]| format!("({}, {}, {})", round(p[0]), round(p[1]), round(p[2]));
    writeln!(s, "bounding box: {} to {}", fmt(lo), fmt(hi)).unwrap();
    let volume: f64 = mesh
        .cells
        .iter()
        .map(|c| {
            let corners: Vec<[f64; 3]> = c.corners().iter().map(|&n| mesh.nodes[n]).collect();
            check_cell(c.kind, &corners).expect("the reader checked every cell")
        })
        .sum();
    writeln!(s, "volume: {}", round(volume)).unwrap();
    s
}

#[test]
fn column_mesh_is_a_4_by_4_by_40_m_column_of_40_hexahedra() {
    insta::assert_snapshot!(summary(&read("verification/cases/column/column.msh")));
}

#[test]
fn slope_mesh_is_the_paper_section_one_element_thick() {
    insta::assert_snapshot!(summary(&read("verification/cases/slope/slope.msh")));
}

/// Same nodes, tags, cells and groups exactly. Coordinates agree to the last
/// printed digit: gmsh writes ASCII coordinates with 16 significant digits
/// (`%.16g`), which does not round-trip every double (a node gmsh places at
/// 1.9999999999947684 m reads back as 1.999999999994768 m), so they may
/// differ by about one unit in the 16th digit, far below 1e-15 of the size.
#[test]
fn binary_column_equals_ascii_column() {
    let ascii = read("verification/cases/column/column.msh");
    let binary = read("tests/fixtures/column-binary.msh");
    assert_eq!(mesh_drift(&ascii, &binary, 1e-15), None);
    for (a, b) in ascii.nodes.iter().zip(&binary.nodes) {
        for d in 0..3 {
            assert!((a[d] - b[d]).abs() <= 1e-15 * a[d].abs(), "{a:?} vs {b:?}");
        }
    }
}

#[test]
fn unit_cube_of_tetrahedra() {
    insta::assert_snapshot!(summary(&read("tests/fixtures/cube-tets.msh")));
}

#[test]
fn unit_cube_of_prisms() {
    insta::assert_snapshot!(summary(&read("tests/fixtures/cube-prisms.msh")));
}

/// gmsh renumbered this file's nodes to 1000 + 7 k and its elements to
/// 500 + 3 k (`cube-hex-sparse.py`, through the gmsh API): the reader numbers
/// nodes densely and keeps the tags.
#[test]
fn unit_cube_of_hexahedra_with_sparse_tags() {
    let mesh = read("tests/fixtures/cube-hex-sparse.msh");
    assert!(mesh.node_tags.iter().all(|t| (t - 1000) % 7 == 0));
    assert!(mesh.cells.iter().all(|c| (c.tag - 500) % 3 == 0));
    insta::assert_snapshot!(summary(&mesh));
}
