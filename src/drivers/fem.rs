//! The FEM reference of a scene: read the mesh, perturb it as CDEM does
//! (the same coordinates bit for bit), solve (see [`crate::fem`]).

use std::time::Instant;

use super::run::read_mesh;
use super::surface::{surface_analysis, SurfaceReport};
use crate::fem::{self, FemProblem, FemSolution};
use crate::scene::Scene;

/// `cdem fem`: the solution and the scene's `[analysis]` on it.
pub struct FemRun {
    pub solution: FemSolution,
    pub surface: Option<SurfaceReport>,
}

/// Solves the scene's FEM reference and runs its `[analysis]` on the cell stresses.
pub fn run_fem(scene: &Scene) -> crate::Result<FemRun> {
    let solution = solve_scene(scene)?;
    let surface = match &scene.analysis {
        Some(_) => {
            let mesh = read_mesh(scene)?;
            surface_analysis(scene, &mesh, &solution.coords, &solution.stress, None, "FEM (linear elastic)")?
        }
        None => None,
    };
    Ok(FemRun { solution, surface })
}

/// Reads the scene's mesh, perturbs it as CDEM does, and solves.
pub fn solve_scene(scene: &Scene) -> crate::Result<FemSolution> {
    let t0 = Instant::now();
    let mesh = read_mesh(scene)?;
    let problem = FemProblem::from_mesh(&mesh, &scene.model_spec())?;
    let mut sol = fem::solve(&problem)?;
    sol.summary.wall_s = t0.elapsed().as_secs_f64();
    Ok(sol)
}
