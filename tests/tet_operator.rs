//! The per-tetrahedron operator form of eq. 12 (src/physics/tet_operator.rs)
//! gives the condensed `K_e u_e` of src/physics/element.rs to round-off, for
//! every supported cell kind, and zero force for rigid motions.
//! References: references/layout.md.

mod common;

use std::path::Path;

use cdem::mesh::perturb::SplitMix64;
use cdem::mesh::shape::{cross, CellKind};
use cdem::model::ELEMENT_SLOT;
use cdem::physics::element::{element_force, element_operators, pack_symmetric};
use cdem::physics::tet_operator::{tet_element_force, tet_operator, TetTopology};
use cdem::scene::Scene;
use cdem::solver::forces;
use common::{perturbed, rock, UNIT_HEX, UNIT_PRISM, UNIT_TET};

/// Relative tolerance of the per-tet force against the condensed one.
const REL_TOL: f64 = 1e-12;

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// Both forms of one cell for displacement `u` (3 per corner).
fn both(kind: CellKind, x: &[[f64; 3]], u: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
    let mat = rock();
    let op = element_operators(kind, x, &mat).unwrap();
    let b = tet_operator(kind, x).unwrap();
    let nodes: Vec<u32> = (0..x.len() as u32).collect();
    let mut f_k = vec![0.0; u.len()];
    element_force(&pack_symmetric(&op.k, x.len()), &nodes, u, &mut f_k);
    let mut f_t = vec![0.0; u.len()];
    tet_element_force(&TetTopology::of(kind), &b, mat.lame, &nodes, u, &mut f_t);
    // Scale of the forces: |K_e|_max |u|_max.
    let scale = max_abs(&op.k) * max_abs(u);
    (f_k, f_t, scale)
}

fn cells() -> [(CellKind, &'static [[f64; 3]]); 3] {
    [(CellKind::Hex8, &UNIT_HEX), (CellKind::Prism6, &UNIT_PRISM), (CellKind::Tet4, &UNIT_TET)]
}

#[test]
fn per_tet_force_equals_condensed_force_on_random_displacements() {
    let mut rng = SplitMix64::new(2024);
    for seed in 0..10 {
        for (kind, base) in cells() {
            let x = perturbed(base, 2.0, 0.3, seed);
            let u: Vec<f64> = (0..3 * x.len()).map(|_| 1e-3 * (2.0 * rng.next_f64() - 1.0)).collect();
            let (f_k, f_t, _) = both(kind, &x, &u);
            let fmax = max_abs(&f_k);
            assert!(fmax > 0.0);
            for (i, (a, b)) in f_k.iter().zip(&f_t).enumerate() {
                assert!((a - b).abs() <= REL_TOL * fmax, "{kind:?} seed {seed} dof {i}: condensed {a} per-tet {b}");
            }
        }
    }
}

#[test]
fn per_tet_tetrahedron_has_one_tet_and_hexahedron_24() {
    assert_eq!(TetTopology::of(CellKind::Hex8).tets.len(), 24);
    assert_eq!(TetTopology::of(CellKind::Prism6).tets.len(), 18);
    assert_eq!(TetTopology::of(CellKind::Tet4).tets.len(), 1);
    assert_eq!(tet_operator(CellKind::Hex8, &perturbed(&UNIT_HEX, 2.0, 0.3, 1)).unwrap().len(), 24);
}

#[test]
fn per_tet_rigid_motion_gives_zero_force() {
    for seed in 0..5 {
        for (kind, base) in cells() {
            let x = perturbed(base, 2.0, 0.3, seed);
            // Translation plus an infinitesimal rotation about an arbitrary point.
            let (a, w, o) = ([1e-3, -2e-3, 0.5e-3], [0.3e-3, -0.2e-3, 0.5e-3], [0.4, 1.1, -0.7]);
            let u: Vec<f64> = x
                .iter()
                .flat_map(|p| {
                    let r = cross(w, [p[0] - o[0], p[1] - o[1], p[2] - o[2]]);
                    [a[0] + r[0], a[1] + r[1], a[2] + r[2]]
                })
                .collect();
            let (f_k, f_t, scale) = both(kind, &x, &u);
            assert!(max_abs(&f_t) <= REL_TOL * scale, "{kind:?} seed {seed}: per-tet rigid force {}", max_abs(&f_t));
            assert!(max_abs(&f_k) <= REL_TOL * scale, "{kind:?} seed {seed}: condensed rigid force {}", max_abs(&f_k));
        }
    }
}

#[test]
fn per_tet_pass_equals_condensed_pass_on_the_paper_slope() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("verification/cases/slope/slope.toml");
    let scene = Scene::load(&path).unwrap();
    let model = cdem::drivers::build_model(&scene).unwrap();
    let el = &model.elements;
    let ops = model.tet_operators().unwrap();
    let u: Vec<f64> = (0..3 * model.n_nodes()).map(|k| 1e-3 * (0.37 * k as f64).sin()).collect();
    let mut f_k = vec![0.0; ELEMENT_SLOT * el.len()];
    forces::element_forces(&model, &u, &mut f_k);
    for e in 0..el.len() {
        let nodes = el.corners(e);
        let mut f_t = [0.0; ELEMENT_SLOT];
        tet_element_force(ops.topology(el.kind[e]), ops.tets(e), ops.lame[e], nodes, &u, &mut f_t[..3 * nodes.len()]);
        let slot = &f_k[ELEMENT_SLOT * e..ELEMENT_SLOT * e + 3 * nodes.len()];
        let scale = max_abs(el.stiffness(e)) * max_abs(&u);
        for (a, b) in slot.iter().zip(&f_t) {
            assert!((a - b).abs() <= REL_TOL * scale, "element {e}: condensed {a} per-tet {b}");
        }
    }
}
