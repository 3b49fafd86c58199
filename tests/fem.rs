//! The implicit FEM reference (`cdem fem`): the laterally confined column is
//! reproduced nodally exactly (references/column.md), a uniform strain is
//! reproduced exactly on perturbed hexahedra, prisms and tetrahedra (patch
//! test), element stiffnesses have exactly the six rigid-body modes, the slope
//! converges under mesh refinement, and the unperturbed column and slope agree
//! with an independent scikit-fem solution (references/skfem.md).

use std::path::Path;

use cdem::drivers::solve_fem as solve_scene;
use cdem::fem::element::element_matrices;
use cdem::fem::{solve, FemProblem, FemSolution};
use cdem::harness::registry::{self as reg, column_k0, column_szz, column_uz, CONFINED_COLUMN};
use cdem::harness::suite::skfem;
use cdem::mesh::adjacency::{face_nodes, FaceAdjacency};
use cdem::mesh::gmsh::read_msh;
use cdem::mesh::perturb::SplitMix64;
use cdem::mesh::{Cell, CellKind, Facet, Mesh, PhysicalGroup};
use cdem::physics::material::{Lame, YoungPoisson};
use cdem::scene::Scene;
use cdem::{Error, SolveError};

// The column's rock and height (references/column.md, via the registry).
const H: f64 = CONFINED_COLUMN.height;
const RHO: f64 = CONFINED_COLUMN.density;
const G: f64 = CONFINED_COLUMN.gravity;
const E: f64 = CONFINED_COLUMN.young;
const NU: f64 = CONFINED_COLUMN.poisson;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn column() -> Scene {
    reg::COLUMN_MERGED.scene().unwrap()
}

fn centroid(sol: &FemSolution, c: usize) -> [f64; 3] {
    let n = sol.cells[c].corners();
    [0, 1, 2].map(|d| n.iter().map(|&i| sol.coords[i][d]).sum::<f64>() / n.len() as f64)
}

#[test]
fn confined_column_settlement_and_stress_are_nodally_exact() {
    let sol = solve_scene(&column()).unwrap();
    assert!(sol.summary.converged && sol.summary.unbalanced_ratio < 1e-12);
    // u_z is exact at every node (consistent load; for these undistorted
    // hexahedra it equals the lumped rho V / 8 per corner), u_x = u_y = 0.
    let mut err_u: f64 = 0.0;
    for (x, u) in sol.coords.iter().zip(sol.u.chunks(3)) {
        if x[2] > 0.0 {
            err_u = err_u.max(rel(u[2], column_uz(x[2])));
        }
        assert!(u[0].abs() < 1e-15 && u[1].abs() < 1e-15, "lateral displacement {u:?} at {x:?}");
    }
    let top = sol.summary.min_uz;
    // Element sigma_zz (volume average) equals the exact stress at the centroid.
    let mut err_s: f64 = 0.0;
    for (c, s) in sol.stress.iter().enumerate() {
        let z = centroid(&sol, c)[2];
        err_s = err_s.max(rel(s[2], column_szz(z)));
        let k0 = column_k0();
        assert!(rel(s[0], k0 * s[2]) < 1e-9 && rel(s[1], k0 * s[2]) < 1e-9, "sigma_xx, sigma_yy of element {c}");
    }
    // Base stress from the bottom reactions.
    let rz: f64 = (0..sol.coords.len()).filter(|&n| sol.coords[n][2] == 0.0).map(|n| sol.reaction[3 * n + 2]).sum();
    let base = -rz / CONFINED_COLUMN.area;
    println!(
        "column FEM: top u_z {top:.10e} (exact {:.10e}, max nodal err {err_u:.1e}); element sigma_zz max err {err_s:.1e}; base {base:.6e} (exact {:.6e})",
        column_uz(H),
        column_szz(0.0)
    );
    assert!(rel(top, column_uz(H)) < 1e-9 && err_u < 1e-9, "u_z error {err_u:e}");
    assert!(err_s < 1e-9, "element sigma_zz error {err_s:e}");
    assert!(rel(base, column_szz(0.0)) < 1e-9, "base stress {base}");
}

/// Imposes `u = Hx` on every node of the boundary, no gravity.
fn patch_problem(mesh: &Mesh, scene: &Scene, h: [[f64; 3]; 3]) -> FemProblem {
    let mut scene = scene.clone();
    scene.boundary.clear(); // the whole boundary is prescribed below
    let mut p = FemProblem::from_mesh(mesh, &scene.model_spec()).unwrap();
    p.gravity = [0.0; 3];
    let adj = FaceAdjacency::build(mesh).unwrap();
    for &(c, f) in &adj.exterior {
        for n in face_nodes(mesh, c, f) {
            for (i, h_i) in h.iter().enumerate() {
                p.fixed[3 * n + i] = true;
                p.prescribed[3 * n + i] = (0..3).map(|j| h_i[j] * p.coords[n][j]).sum();
            }
        }
    }
    p
}

fn check_patch(name: &str, mesh: &Mesh, scene: &Scene) {
    let h = [[1.0e-3, -2.0e-4, 5.0e-4], [3.0e-4, -7.0e-4, 1.0e-4], [-4.0e-4, 6.0e-4, 2.0e-3]];
    let p = patch_problem(mesh, scene, h);
    let interior = (0..p.n_nodes()).filter(|&n| !p.fixed[3 * n]).count();
    assert!(interior > 0 && p.coords != mesh.nodes, "{name}: the patch needs perturbed interior nodes");
    let sol = solve(&p).unwrap();
    let lame = p.materials[0].lame;
    let exact = lame.stress(&h);
    let scale = exact.iter().map(|v| v.abs()).fold(0.0, f64::max);
    let mut err_s: f64 = 0.0;
    for s in &sol.stress {
        for k in 0..6 {
            err_s = err_s.max((s[k] - exact[k]).abs() / scale);
        }
    }
    let mut err_u: f64 = 0.0;
    for (x, u) in sol.coords.iter().zip(sol.u.chunks(3)) {
        for i in 0..3 {
            let ui: f64 = (0..3).map(|j| h[i][j] * x[j]).sum();
            err_u = err_u.max((u[i] - ui).abs() / (2e-3 * 40.0));
        }
    }
    println!(
        "patch {name}: {} cells, {interior} free interior nodes, stress err {err_s:.1e}, displacement err {err_u:.1e}",
        sol.cells.len()
    );
    assert!(err_s < 1e-9 && err_u < 1e-9, "{name}: uniform strain not reproduced (stress {err_s:e}, u {err_u:e})");
}

#[test]
fn uniform_strain_patch_is_exact_on_perturbed_hexahedra_prisms_and_tetrahedra() {
    let mut s = column();
    s.perturbation.ratio = 0.1;
    s.perturbation.seed = 7;
    check_patch("column hexahedra (ratio 0.1)", &read_msh(&s.mesh_path()).unwrap(), &s);
    let column_mesh = read_msh(&s.mesh_path()).unwrap();
    check_patch("column split into 24 tetrahedra per hexahedron (ratio 0.1)", &tetrahedralise(&column_mesh), &s);
    let text = "[mesh]\nfile = \"cube-prisms.msh\"\n[perturbation]\nratio = 0.15\nseed = 3\n[[material]]\ngroup = \"rock\"\nyoungs_modulus = 3.0e8\npoisson_ratio = 0.3\ndensity = 2100.0\n[joints]\nmode = \"merged\"\n";
    let dir = Path::new("tests/fixtures");
    let s = Scene::from_toml(text, dir, &dir.join("patch.toml")).unwrap();
    check_patch("unit cube of prisms (ratio 0.15)", &read_msh(&s.mesh_path()).unwrap(), &s);
}

/// A conforming tetrahedral mesh of the same volume: every cell split into
/// the tetrahedra of CDEM's decomposition (face edge, face centroid, body
/// centroid), face centroids shared between neighbours. Only the volume
/// groups are kept (cells renumbered).
fn tetrahedralise(mesh: &Mesh) -> Mesh {
    use cdem::mesh::adjacency::face_key;
    use cdem::mesh::shape::Decomposition;
    let mut nodes = mesh.nodes.clone();
    let mut face_centre = std::collections::HashMap::new();
    let mut cells = Vec::new();
    let mut children = Vec::new();
    for cell in &mesh.cells {
        let dec = Decomposition::of(cell.kind);
        let corners = cell.corners();
        let points = dec.points(&corners.iter().map(|&n| mesh.nodes[n]).collect::<Vec<_>>());
        let mut id: Vec<usize> = corners.to_vec();
        for (f, face) in cell.kind.faces().iter().enumerate() {
            let key = face_key(&face.iter().map(|&k| corners[k]).collect::<Vec<_>>());
            id.push(*face_centre.entry(key).or_insert_with(|| {
                nodes.push(points[corners.len() + f]);
                nodes.len() - 1
            }));
        }
        nodes.push(points[points.len() - 1]);
        id.push(nodes.len() - 1);
        let first = cells.len();
        for t in &dec.tets {
            let mut n = [0; 8];
            for k in 0..4 {
                n[k] = id[t[k]];
            }
            cells.push(Cell { kind: CellKind::Tet4, nodes: n, tag: cells.len() as u64 + 1 });
        }
        children.push(first..cells.len());
    }
    let groups = mesh
        .groups
        .iter()
        .filter(|g| g.dim == 3)
        .map(|g| PhysicalGroup {
            dim: 3,
            tag: g.tag,
            name: g.name.clone(),
            cells: g.cells.iter().flat_map(|&c| children[c].clone()).collect(),
            facets: Vec::new(),
        })
        .collect();
    Mesh { node_tags: (1..=nodes.len() as u64).collect(), nodes, cells, groups }
}

/// Rigid motions of the corners: 3 translations, 3 rotations.
fn rigid_modes(x: &[[f64; 3]]) -> Vec<Vec<f64>> {
    let mut modes = Vec::new();
    for d in 0..3 {
        modes.push((0..3 * x.len()).map(|k| f64::from(u8::from(k % 3 == d))).collect());
    }
    for a in 0..3 {
        let mut m = vec![0.0; 3 * x.len()];
        for (c, p) in x.iter().enumerate() {
            let e = [0, 1, 2].map(|d| f64::from(u8::from(d == a)));
            let r = [e[1] * p[2] - e[2] * p[1], e[2] * p[0] - e[0] * p[2], e[0] * p[1] - e[1] * p[0]];
            m[3 * c..3 * c + 3].copy_from_slice(&r);
        }
        modes.push(m);
    }
    modes
}

#[test]
fn element_stiffness_is_symmetric_with_exactly_six_rigid_body_modes() {
    let lame: Lame = YoungPoisson { young: E, poisson: NU }.into();
    let mut rng = SplitMix64::new(11);
    let cases: [(CellKind, Vec<[f64; 3]>); 3] = [
        (
            CellKind::Hex8,
            vec![
                [0., 0., 0.],
                [2., 0., 0.],
                [2., 1., 0.],
                [0., 1., 0.],
                [0., 0., 3.],
                [2., 0., 3.],
                [2., 1., 3.],
                [0., 1., 3.],
            ],
        ),
        (CellKind::Prism6, vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.], [1., 0., 1.], [0., 1., 1.]]),
        (CellKind::Tet4, vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]]),
    ];
    for (kind, base) in cases {
        let x: Vec<[f64; 3]> = base.iter().map(|p| p.map(|v| v + 0.15 * (2.0 * rng.next_f64() - 1.0))).collect();
        let em = element_matrices(kind, &x, lame, [0.0, 0.0, -RHO * G]).unwrap();
        let n = 3 * kind.n_nodes();
        let kmax = em.k.iter().map(|v| v.abs()).fold(0.0, f64::max);
        for a in 0..n {
            for b in 0..n {
                assert!((em.k[a * n + b] - em.k[b * n + a]).abs() < 1e-12 * kmax, "{kind:?} not symmetric");
            }
        }
        for (m, r) in rigid_modes(&x).iter().enumerate() {
            let rn = r.iter().map(|v| v * v).sum::<f64>().sqrt();
            let kr = (0..n).map(|a| (0..n).map(|b| em.k[a * n + b] * r[b]).sum::<f64>().powi(2)).sum::<f64>().sqrt();
            assert!(kr < 1e-12 * kmax * rn, "{kind:?}: rigid mode {m} strains the element (|K r| = {kr:e})");
        }
        let k = nalgebra::DMatrix::from_row_slice(n, n, &em.k);
        let eig = nalgebra::SymmetricEigen::new(k).eigenvalues;
        let zero = eig.iter().filter(|&&l| l.abs() < 1e-10 * kmax).count();
        let positive = eig.iter().filter(|&&l| l > 1e-10 * kmax).count();
        println!("{kind:?}: {zero} zero and {positive} positive eigenvalues of {n}");
        assert_eq!((zero, positive), (6, n - 6), "{kind:?}: spectrum");
        // The consistent load sums to the weight rho g V.
        let fz: f64 = em.f.iter().skip(2).step_by(3).sum();
        assert!(rel(fz, -RHO * G * em.volume) < 1e-12, "{kind:?}: load {fz} vs weight");
    }
}

#[test]
fn unit_cube_strain_energy_equals_the_continuum_value() {
    // u = eps x on one undistorted hexahedron: u^T K u / 2 = V eps : C : eps / 2.
    let lame: Lame = YoungPoisson { young: E, poisson: NU }.into();
    let x = [
        [0., 0., 0.],
        [1., 0., 0.],
        [1., 1., 0.],
        [0., 1., 0.],
        [0., 0., 1.],
        [1., 0., 1.],
        [1., 1., 1.],
        [0., 1., 1.],
    ];
    let eps = [[1e-3, 2e-4, 0.0], [2e-4, -5e-4, 3e-4], [0.0, 3e-4, 2e-3]];
    let em = element_matrices(CellKind::Hex8, &x, lame, [0.0; 3]).unwrap();
    let u: Vec<f64> =
        x.iter().flat_map(|p| (0..3).map(move |i| (0..3).map(|j| eps[i][j] * p[j]).sum::<f64>())).collect();
    let energy = 0.5 * (0..24).map(|a| u[a] * (0..24).map(|b| em.k[a * 24 + b] * u[b]).sum::<f64>()).sum::<f64>();
    let tr = eps[0][0] + eps[1][1] + eps[2][2];
    let eps2: f64 = eps.iter().flatten().map(|v| v * v).sum();
    let exact = 0.5 * (lame.lambda * tr * tr + 2.0 * lame.mu * eps2);
    assert!(rel(energy, exact) < 1e-12, "energy {energy} vs {exact}");
}

/// Makes (or finds) the node at the mean of the given nodes, returning its index.
type MidNode<'a> = dyn FnMut(&[usize], &mut Vec<[f64; 3]>) -> usize + 'a;

/// Splits every hexahedron of a slab extruded along y (corners 0-3 on one
/// face, 4-7 on the other, as gmsh extrudes) 2 x 2 in the section plane.
/// Surface groups become node sets (point facets): a new node belongs to a
/// group if all the nodes it is the average of do (right for planar groups).
fn refine_slab(mesh: &Mesh) -> Mesh {
    use std::collections::HashMap;
    let mut nodes = mesh.nodes.clone();
    let mut made: HashMap<Vec<usize>, usize> = HashMap::new();
    let mut parents: Vec<Vec<usize>> = (0..nodes.len()).map(|n| vec![n]).collect();
    let mut mid = |ids: &[usize], nodes: &mut Vec<[f64; 3]>| {
        let mut key = ids.to_vec();
        key.sort_unstable();
        *made.entry(key.clone()).or_insert_with(|| {
            nodes.push([0, 1, 2].map(|d| ids.iter().map(|&i| mesh.nodes[i][d]).sum::<f64>() / ids.len() as f64));
            parents.push(key);
            nodes.len() - 1
        })
    };
    let mut cells = Vec::new();
    for cell in &mesh.cells {
        assert_eq!(cell.kind, CellKind::Hex8);
        let quad = |o: usize, nodes: &mut Vec<[f64; 3]>, mid: &mut MidNode<'_>| {
            let c = [0, 1, 2, 3].map(|k| cell.nodes[o + k]);
            let m = [0, 1, 2, 3].map(|k| mid(&[c[k], c[(k + 1) % 4]], nodes));
            let f = mid(&c, nodes);
            [[c[0], m[0], f, m[3]], [m[0], c[1], m[1], f], [f, m[1], c[2], m[2]], [m[3], f, m[2], c[3]]]
        };
        let (lo, hi) = (quad(0, &mut nodes, &mut mid), quad(4, &mut nodes, &mut mid));
        for k in 0..4 {
            let mut n = [0; 8];
            n[..4].copy_from_slice(&lo[k]);
            n[4..].copy_from_slice(&hi[k]);
            cells.push(Cell { kind: CellKind::Hex8, nodes: n, tag: cells.len() as u64 + 1 });
        }
    }
    let groups = mesh
        .groups
        .iter()
        .map(|g| {
            let mut g2 =
                PhysicalGroup { dim: g.dim, tag: g.tag, name: g.name.clone(), cells: Vec::new(), facets: Vec::new() };
            if g.dim == 3 {
                g2.cells = g.cells.iter().flat_map(|&c| 4 * c..4 * c + 4).collect();
            } else {
                let set: std::collections::HashSet<usize> = mesh.group_nodes(g).into_iter().collect();
                for (n, p) in parents.iter().enumerate() {
                    if p.iter().all(|i| set.contains(i)) {
                        g2.facets.push(Facet { nodes: [n, 0, 0, 0], n: 1 });
                    }
                }
            }
            g2
        })
        .collect();
    Mesh { node_tags: (1..=nodes.len() as u64).collect(), nodes, cells, groups }
}

#[test]
fn slope_displacement_and_stress_converge_under_refinement() {
    // The case as CDEM sees it (perturbed, 1000 hexahedra).
    let s = reg::SLOPE.scene().unwrap();
    let sol = solve_scene(&s).unwrap();
    let t = sol.timings;
    println!(
        "slope (perturbed, ratio {}): {} cells, {} unknowns: max|u_z| {:.6e} m, min sigma_zz {:.6e} Pa, residual {:.1e}; assemble {:.3} s, factor {:.3} s, solve {:.4} s",
        s.perturbation.ratio, sol.cells.len(), sol.free_dofs, sol.summary.max_abs_uz, sol.summary.min_szz.unwrap(),
        sol.summary.unbalanced_ratio, t.assemble_s, t.factor_s, t.solve_s
    );
    assert!(sol.summary.converged);
    // Unperturbed, refined 2 x 2 in the section plane twice.
    let mut s0 = s.clone();
    s0.perturbation.ratio = 0.0;
    let mut mesh = read_msh(&s0.mesh_path()).unwrap();
    let mut uz = Vec::new();
    for level in 0..3 {
        if level > 0 {
            mesh = refine_slab(&mesh);
        }
        let sol = solve(&FemProblem::from_mesh(&mesh, &s0.model_spec()).unwrap()).unwrap();
        let t = sol.timings;
        let (u, sz) = (sol.summary.max_abs_uz, sol.summary.min_szz.unwrap());
        println!(
            "slope level {level} (h = {} m): {} cells, {} unknowns: max|u_z| {u:.8e} m, min sigma_zz {sz:.6e} Pa; assemble {:.3} s, factor {:.3} s, solve {:.4} s",
            2.0 / f64::from(1 << level), sol.cells.len(), sol.free_dofs, t.assemble_s, t.factor_s, t.solve_s
        );
        assert!(sol.summary.converged && u.is_finite() && sz.is_finite());
        // Sanity: of the order of the confined column (4.08e-2 m, -8.24e5 Pa).
        assert!((0.03..0.05).contains(&u) && (-8.3e5..-7.0e5).contains(&sz), "level {level}: {u} m, {sz} Pa");
        uz.push(u);
    }
    let (d1, d2) = (uz[1] - uz[0], uz[2] - uz[1]);
    println!("max|u_z| increments {d1:.3e}, {d2:.3e}: ratio {:.2} (4 for an O(h^2) error)", d1 / d2);
    assert!(d1.abs() > 2.0 * d2.abs(), "max|u_z| does not converge: increments {d1:e}, {d2:e}");
}

#[test]
fn a_model_without_enough_fixities_is_reported_under_constrained() {
    let mut s = column();
    s.boundary.retain(|b| b.group != "bottom"); // rollers only: vertical translation free
    match solve_scene(&s) {
        Err(Error::Solve(SolveError::UnderConstrained { motion })) => {
            println!("{motion}");
            assert!(motion.starts_with("translation (0.00, 0.00, 1.00) + rotation (0.00, 0.00, 0.00)"), "{motion}");
        }
        other => panic!("expected UnderConstrained, got {:?}", other.map(|s| s.summary)),
    }
    s.boundary.clear();
    assert!(matches!(solve_scene(&s), Err(Error::Solve(SolveError::UnderConstrained { .. }))));
}

#[test]
fn displacement_inside_a_cell_interpolates_the_column() {
    let mut s = column();
    s.perturbation.ratio = 0.1; // a perturbed mesh: the inverse map is not trivial
    s.perturbation.seed = 5;
    let sol = solve_scene(&s).unwrap();
    for c in [0, 17, 39] {
        let x = centroid(&sol, c);
        let u = sol.displacement_at(x).unwrap();
        let corners = sol.cells[c].corners();
        // At the reference centre all eight trilinear shape functions are 1/8.
        let mean = [0, 1, 2].map(|d| corners.iter().map(|&n| sol.u[3 * n + d]).sum::<f64>() / 8.0);
        for d in 0..3 {
            assert!((u[d] - mean[d]).abs() < 1e-12, "cell {c}: {u:?} vs {mean:?}");
        }
    }
    let node = sol.coords[5];
    let u = sol.displacement_at(node).unwrap();
    assert!((0..3).all(|d| (u[d] - sol.u[15 + d]).abs() < 1e-12));
    assert_eq!(sol.displacement_at([10.0, 10.0, 10.0]), None);
}

#[test]
fn outputs_have_the_keys_of_cdem_run() {
    let sol = solve_scene(&column()).unwrap();
    let dir = std::env::temp_dir().join(format!("cdem-fem-test-{}", std::process::id()));
    cdem::output::write_fem(&sol, None, &dir).unwrap();
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let keys: Vec<&str> = summary.as_object().unwrap().keys().map(|k| k.as_str()).collect();
    for k in [
        "converged",
        "steps",
        "wall_s",
        "dt",
        "unbalanced_ratio",
        "max_abs_uz",
        "min_uz",
        "max_abs_u",
        "min_szz",
        "failed_springs",
        "elements",
        "nodes",
        "springs",
    ] {
        assert!(keys.contains(&k), "summary.json lacks {k}");
    }
    let vtu = std::fs::read_to_string(dir.join("final.vtu")).unwrap();
    assert!(vtu.contains("NumberOfPoints=\"99\" NumberOfCells=\"40\"") && vtu.contains("Name=\"szz\""));
    assert!(dir.join("run.pvd").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The comparison and its rows are [`cdem::harness::suite::skfem::cases`]
/// (shared with `cdem reproduce`, which reads the same committed JSON).
#[test]
fn fem_agrees_with_scikit_fem_on_the_column_and_the_slope_unperturbed_and_perturbed() {
    let cases = skfem::cases(Path::new(env!("CARGO_MANIFEST_DIR"))).unwrap();
    let names: Vec<&str> = cases.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["column", "slope", "slope_perturbed"], "the cases of references/skfem.json");
    for case in &cases {
        let name = &case.name;
        cdem::harness::report::record(&skfem::record_name(name), &case.rows);
        assert_eq!(case.elements.0 as u64, case.elements.1, "{name}: cells");
        assert_eq!(case.free_dofs.0 as u64, case.free_dofs.1, "{name}: free unknowns");
        for (key, v, r) in &case.values {
            println!("{name} {key}: cdem fem {v:.12e}, scikit-fem {r:.12e}, rel {:.1e}", rel(*v, *r));
        }
        println!("{name}: largest relative difference {:.1e}", case.worst);
        assert!(case.rows.iter().all(|r| r.passed()), "{name}: {:?}", case.rows);
    }
}
