//! The paper's elastic slope (docs/method.md section 3, Figs. 5-7): CDEM with
//! perturbed nodes and springs on every interface, by dynamic relaxation,
//! against the implicit FEM (trilinear hexahedra) on the same perturbed mesh:
//! max |u_z| and min sigma_zz within 1 %, and the relative L2 error of the
//! displacement field (defined in `cdem::analysis::compare`). The paper's
//! pairs are printed beside ours (references/paper.md).

use std::path::Path;

use cdem::analysis::compare::relative_l2_displacement;
use cdem::drivers::run_scene;
use cdem::harness::report::Check;
use cdem::scene::Scene;

#[test]
fn paper_slope_cdem_matches_fem_on_the_same_mesh() {
    let scene = Scene::load(Path::new("verification/cases/slope/slope.toml")).unwrap();
    let r = run_scene(&scene, &mut |_, _| {}).unwrap();
    let fem = cdem::drivers::solve_fem(&scene).unwrap();
    let (c, f) = (&r.summary, &fem.summary);
    assert!(c.converged && c.unbalanced_ratio < scene.solver.tolerance);
    let l2 = relative_l2_displacement(&r.model, &r.state.u, &fem.u);
    let err_u = (c.max_abs_uz - f.max_abs_uz).abs() / f.max_abs_uz;
    let (cs, fs) = (c.min_szz.unwrap(), f.min_szz.unwrap());
    let err_s = ((cs - fs) / fs).abs();
    println!("slope CDEM: {} steps, {:.1} s; FEM {:.2} s", c.steps, c.wall_s, f.wall_s);
    println!(
        "max |u_z|: CDEM {:.4e} m, FEM {:.4e} m (diff {:.2} %); paper 4.18e-2 / ANSYS 4.16e-2",
        c.max_abs_uz,
        f.max_abs_uz,
        100.0 * err_u
    );
    println!(
        "min sigma_zz: CDEM {cs:.4e} Pa, FEM {fs:.4e} Pa (diff {:.2} %); paper -7.89e5 / ANSYS -7.81e5",
        100.0 * err_s
    );
    println!("relative L2 error of the displacement field: {:.3} %", 100.0 * l2);
    let t = c.wall_s;
    cdem::harness::report::record(
        "slope_elastic",
        &[
            Check::new(
                "paper slope, CDEM vs FEM",
                "max |u_z| (m)",
                c.max_abs_uz,
                f.max_abs_uz,
                0.01,
                "cdem fem (references/skfem.md)",
                t,
            ),
            Check::new(
                "paper slope, CDEM vs FEM",
                "min sigma_zz (Pa)",
                cs,
                fs,
                0.01,
                "cdem fem (references/skfem.md)",
                t,
            ),
            Check::new(
                "paper slope, CDEM vs FEM",
                "relative L2 error of u",
                l2,
                0.0,
                0.01,
                "cdem fem (references/skfem.md)",
                t,
            ),
            Check::new(
                "paper slope, CDEM vs paper",
                "max |u_z| (m)",
                c.max_abs_uz,
                4.18e-2,
                f64::NAN,
                "references/paper.md",
                t,
            ),
            Check::new(
                "paper slope, CDEM vs paper",
                "min sigma_zz (Pa)",
                cs,
                -7.89e5,
                f64::NAN,
                "references/paper.md",
                t,
            ),
        ],
    );
    assert!(err_u < 0.01, "max |u_z| differs by {:.2} %", 100.0 * err_u);
    assert!(err_s < 0.01, "min sigma_zz differs by {:.2} %", 100.0 * err_s);
    assert!(l2 < 0.01, "relative L2 displacement error {:.2} %", 100.0 * l2);
}
