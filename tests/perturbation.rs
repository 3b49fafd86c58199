//! Stochastic structural planes: the seeded perturbation repeats bit for bit,
//! stays within r h per axis, and keeps boundary nodes on their planes.

use std::path::Path;

use cdem::mesh::adjacency::{face_nodes, polygon_normal_area, FaceAdjacency};
use cdem::mesh::gmsh::read_msh;
use cdem::mesh::perturb::{local_edge_length, perturb_nodes};
use cdem::mesh::shape::dot;
use cdem::mesh::Mesh;
use cdem::{Error, ModelError};

fn slope() -> Mesh {
    read_msh(Path::new("verification/cases/slope/slope.msh")).unwrap()
}

#[test]
fn same_seed_same_mesh_bit_for_bit_other_seed_differs() {
    let mesh = slope();
    let adj = FaceAdjacency::build(&mesh).unwrap();
    let a = perturb_nodes(&mesh, &adj, 0.2, 42, &[]).unwrap();
    let b = perturb_nodes(&mesh, &adj, 0.2, 42, &[]).unwrap();
    let c = perturb_nodes(&mesh, &adj, 0.2, 43, &[]).unwrap();
    let bits = |v: &[[f64; 3]]| v.iter().flat_map(|x| x.map(f64::to_bits)).collect::<Vec<_>>();
    assert_eq!(bits(&a), bits(&b));
    assert_ne!(bits(&a), bits(&c));
    assert!(a.iter().zip(&mesh.nodes).any(|(p, q)| p != q), "nodes moved");
}

#[test]
fn offsets_are_bounded_by_ratio_times_local_edge() {
    let mesh = slope();
    let adj = FaceAdjacency::build(&mesh).unwrap();
    let r = 0.2;
    let p = perturb_nodes(&mesh, &adj, r, 7, &[]).unwrap();
    let h = local_edge_length(&mesh);
    for (i, (x, x0)) in p.iter().zip(&mesh.nodes).enumerate() {
        // Projection onto boundary planes never lengthens the offset vector.
        let d = ((0..3).map(|k| (x[k] - x0[k]).powi(2)).sum::<f64>()).sqrt();
        assert!(d <= r * h[i] * 3f64.sqrt() * (1.0 + 1e-12), "node {i}: {d} > r h sqrt 3");
    }
}

#[test]
fn boundary_nodes_stay_on_their_planes() {
    let mesh = slope();
    let adj = FaceAdjacency::build(&mesh).unwrap();
    let p = perturb_nodes(&mesh, &adj, 0.1, 99, &[]).unwrap();
    let mut moved_in_plane = 0;
    for &(c, f) in &adj.exterior {
        let nodes = face_nodes(&mesh, c, f);
        let x0: Vec<[f64; 3]> = nodes.iter().map(|&n| mesh.nodes[n]).collect();
        let (n, _) = polygon_normal_area(&x0);
        let d0 = dot(n, x0[0]);
        for &i in &nodes {
            assert!((dot(n, p[i]) - d0).abs() < 1e-9, "boundary node {i} left its plane");
            moved_in_plane += usize::from(p[i] != mesh.nodes[i]);
        }
    }
    assert!(moved_in_plane > 0, "boundary nodes still move within their planes");
}

#[test]
fn too_large_a_ratio_is_a_typed_error_naming_the_element() {
    // Offsets of nearly half an edge at both ends of the skewed wedges at the
    // toe invert them; the scene-level error names the gmsh element tag.
    let mut scene = cdem::harness::registry::SLOPE.scene().unwrap();
    scene.perturbation.ratio = 0.45;
    scene.perturbation.seed = 5;
    match cdem::drivers::build_model(&scene) {
        Err(Error::Model(ModelError::PerturbationInverts { element, volume, .. })) => {
            let mesh = slope();
            assert!(mesh.cells.iter().any(|c| c.tag == element), "element {element} is a gmsh tag of the mesh");
            assert!(volume <= 0.0 || volume.abs() < 1e-6);
        }
        Err(e) => panic!("wrong error: {e}"),
        Ok(_) => panic!("ratio 0.45 should invert an element of the slope mesh"),
    }
}
