//! The deformable element: polyhedron -> tetrahedra volumes, lumped mass and
//! the patch test (uniform strain reproduced exactly by one perturbed element).
//! References: references/kernels.md.

mod common;

use cdem::mesh::shape::{check_cell, cross, dot, CellKind, Decomposition};
use cdem::physics::element::{
    element_force, element_operators, element_stress, pack_symmetric, packed_entry, packed_len, unpack_symmetric,
};
use common::{perturbed, rock, UNIT_HEX, UNIT_PRISM};

/// Polyhedron volume by the divergence theorem over the face fans (a, b, F):
/// an independent path from the tetrahedra.
fn divergence_volume(kind: CellKind, x: &[[f64; 3]]) -> f64 {
    let mut v = 0.0;
    for f in kind.faces() {
        let m = f.len() as f64;
        let c = [0, 1, 2].map(|d| f.iter().map(|&k| x[k][d]).sum::<f64>() / m);
        for k in 0..f.len() {
            let (a, b) = (x[f[k]], x[f[(k + 1) % f.len()]]);
            v += dot(a, cross(b, c)) / 6.0;
        }
    }
    v
}

#[test]
fn hexahedron_is_24_tetrahedra_and_prism_18() {
    assert_eq!(Decomposition::of(CellKind::Hex8).tets.len(), 24);
    assert_eq!(Decomposition::of(CellKind::Prism6).tets.len(), 18);
    assert_eq!(Decomposition::of(CellKind::Tet4).tets.len(), 1);
}

#[test]
fn tetrahedra_volume_equals_parallelepiped_volume() {
    // Affine image of the unit cube: volume |det A|.
    let a = [[2.0, 0.3, -0.1], [0.2, 1.5, 0.4], [0.1, -0.2, 3.0]];
    let x: Vec<[f64; 3]> = UNIT_HEX.iter().map(|p| [0, 1, 2].map(|i| (0..3).map(|j| a[i][j] * p[j]).sum())).collect();
    let det = dot(a[0], cross(a[1], a[2]));
    let v = check_cell(CellKind::Hex8, &x).unwrap();
    assert!((v - det).abs() < 1e-12 * det, "{v} vs {det}");
}

#[test]
fn tetrahedra_volume_equals_right_prism_volume() {
    let x: Vec<[f64; 3]> = UNIT_PRISM.iter().map(|p| [2.0 * p[0], 3.0 * p[1], 5.0 * p[2]]).collect();
    let v = check_cell(CellKind::Prism6, &x).unwrap();
    assert!((v - 0.5 * 2.0 * 3.0 * 5.0).abs() < 1e-12 * 15.0);
}

#[test]
fn tetrahedra_volume_equals_perturbed_polyhedron_volume() {
    for seed in 0..20 {
        for (kind, base) in [(CellKind::Hex8, &UNIT_HEX[..]), (CellKind::Prism6, &UNIT_PRISM[..])] {
            let x = perturbed(base, 1.0, 0.15, seed);
            let v = check_cell(kind, &x).unwrap();
            let reference = divergence_volume(kind, &x);
            assert!((v - reference).abs() < 1e-12 * reference, "{kind:?} seed {seed}: {v} vs {reference}");
        }
    }
}

#[test]
fn lumped_mass_is_positive_and_sums_to_rho_v() {
    for (kind, base) in [(CellKind::Hex8, &UNIT_HEX[..]), (CellKind::Prism6, &UNIT_PRISM[..])] {
        let x = perturbed(base, 1.0, 0.15, 7);
        let op = element_operators(kind, &x, &rock()).unwrap();
        assert!(op.mass.iter().all(|&m| m > 0.0));
        let total: f64 = op.mass.iter().sum();
        assert!((total - 2100.0 * op.volume).abs() < 1e-12 * total);
    }
}

/// Patch test: u = H x gives the exact uniform stress in a perturbed element,
/// the exact strain energy, zero net force; rigid rotations give zero force.
#[test]
fn patch_test_uniform_strain_is_exact_in_one_perturbed_element() {
    let h = [[1.0e-3, 2.0e-4, -3.0e-4], [5.0e-4, -2.0e-3, 1.0e-4], [-1.0e-4, 3.0e-4, 1.5e-3]];
    let mat = rock();
    let (lambda, mu) = (mat.lame.lambda, mat.lame.mu);
    let eps = [0, 1, 2].map(|i| [0, 1, 2].map(|j| 0.5 * (h[i][j] + h[j][i])));
    let tr = eps[0][0] + eps[1][1] + eps[2][2];
    let sig = [0, 1, 2].map(|i| [0, 1, 2].map(|j| lambda * tr * f64::from(u8::from(i == j)) + 2.0 * mu * eps[i][j]));
    let expected = [sig[0][0], sig[1][1], sig[2][2], sig[1][2], sig[0][2], sig[0][1]];
    let smax = expected.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (kind, base) in
        [(CellKind::Hex8, &UNIT_HEX[..]), (CellKind::Prism6, &UNIT_PRISM[..]), (CellKind::Tet4, &UNIT_HEX[..4])]
    {
        let base: Vec<[f64; 3]> = if kind == CellKind::Tet4 {
            vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]]
        } else {
            base.to_vec()
        };
        let x = perturbed(&base, 1.0, 0.2, 11);
        let op = element_operators(kind, &x, &mat).unwrap();
        let nodes: Vec<u32> = (0..x.len() as u32).collect();
        let u: Vec<f64> =
            x.iter().flat_map(|p| [0, 1, 2].map(|i| (0..3).map(|j| h[i][j] * p[j]).sum::<f64>())).collect();
        let s = element_stress(&op.grad, &nodes, &u, mat.lame);
        for c in 0..6 {
            assert!((s[c] - expected[c]).abs() < 1e-10 * smax, "{kind:?} stress[{c}] {} vs {}", s[c], expected[c]);
        }
        let mut f = vec![0.0; u.len()];
        element_force(&pack_symmetric(&op.k, x.len()), &nodes, &u, &mut f); // one element: its slot is the global vector
        let energy = 0.5 * f.iter().zip(&u).map(|(a, b)| a * b).sum::<f64>();
        let exact = 0.5
            * op.volume
            * (0..3).flat_map(|i| (0..3).map(move |j| (i, j))).map(|(i, j)| eps[i][j] * sig[i][j]).sum::<f64>();
        assert!((energy - exact).abs() < 1e-10 * exact, "{kind:?} energy {energy} vs {exact}");
        let fmax = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for d in 0..3 {
            let net: f64 = f.iter().skip(d).step_by(3).sum();
            assert!(net.abs() < 1e-10 * fmax, "{kind:?} net force {d}: {net}");
        }
        // Infinitesimal rigid rotation about an arbitrary axis: zero force.
        let w = [0.3e-3, -0.2e-3, 0.5e-3];
        let ur: Vec<f64> = x.iter().flat_map(|p| cross(w, *p)).collect();
        let mut fr = vec![0.0; u.len()];
        element_force(&pack_symmetric(&op.k, x.len()), &nodes, &ur, &mut fr);
        assert!(fr.iter().all(|v| v.abs() < 1e-10 * fmax), "{kind:?} rotation gives force");
    }
}

#[test]
fn stiffness_is_symmetric() {
    let x = perturbed(&UNIT_HEX, 1.0, 0.2, 3);
    let op = element_operators(CellKind::Hex8, &x, &rock()).unwrap();
    let kmax = op.k.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for i in 0..24 {
        for j in 0..24 {
            assert!((op.k[i * 24 + j] - op.k[j * 24 + i]).abs() < 1e-12 * kmax);
        }
    }
}

/// The packed upper triangle ([`pack_symmetric`]) gives the same `K_e u_e` as
/// the full matrix to round-off, and [`packed_entry`] reads back every entry
/// (the upper triangle exactly, the lower one as its transpose).
#[test]
fn packed_stiffness_is_the_full_one() {
    for (kind, base) in [(CellKind::Hex8, UNIT_HEX.to_vec()), (CellKind::Prism6, UNIT_PRISM.to_vec())] {
        let x = perturbed(&base, 1.0, 0.2, 5);
        let op = element_operators(kind, &x, &rock()).unwrap();
        let (m, n) = (x.len(), 3 * x.len());
        let k = pack_symmetric(&op.k, m);
        assert_eq!(k.len(), packed_len(m));
        let kmax = op.k.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        for i in 0..n {
            for j in 0..n {
                let (r, c) = if i / 3 <= j / 3 { (i, j) } else { (j, i) };
                let upper = if r / 3 == c / 3 { op.k[r.min(c) * n + r.max(c)] } else { op.k[r * n + c] };
                assert_eq!(packed_entry(&k, m, i, j), upper, "{kind:?} entry ({i}, {j})");
                assert!((packed_entry(&k, m, i, j) - op.k[i * n + j]).abs() < 1e-12 * kmax);
            }
        }
        let full = unpack_symmetric(&k, m);
        for i in 0..n {
            for j in 0..n {
                assert_eq!(full[i * n + j], packed_entry(&k, m, i, j), "{kind:?} unpacked ({i}, {j})");
            }
        }
        let u: Vec<f64> = (0..n).map(|i| ((i * 7 + 3) % 11) as f64 * 1e-3 - 5e-3).collect();
        let nodes: Vec<u32> = (0..m as u32).collect();
        let mut f = vec![0.0; n];
        element_force(&k, &nodes, &u, &mut f);
        let full: Vec<f64> = (0..n).map(|i| (0..n).map(|j| op.k[i * n + j] * u[j]).sum()).collect();
        let scale = kmax * 5e-3;
        for i in 0..n {
            assert!((f[i] - full[i]).abs() < 1e-13 * scale * n as f64, "{kind:?} f[{i}] {} vs {}", f[i], full[i]);
        }
    }
}
