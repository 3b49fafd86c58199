//! The FEM reference of a scene: read the mesh, perturb it as CDEM does
//! (the same coordinates bit for bit), solve (see [`crate::fem`]).

use std::time::Instant;

use super::analysis::{run_analysis, AnalysisReport};
use super::input::read_mesh;
use crate::fem::{self, FemProblem, FemSolution};
use crate::mesh::Mesh;
use crate::scene::Scene;

/// `cdem fem`: the solution and the scene's `[analysis]` on it.
pub struct FemRun {
    pub solution: FemSolution,
    pub surface: Option<AnalysisReport>,
}

/// Solves the scene's FEM reference and runs its `[analysis]` on the cell stresses.
pub fn run_fem(scene: &Scene) -> crate::Result<FemRun> {
    let t0 = Instant::now();
    let mesh = read_mesh(scene)?;
    let solution = solve_mesh(scene, &mesh, t0)?;
    let surface = match &scene.analysis {
        Some(_) => run_analysis(scene, &mesh, &solution.coords, &solution.stress, None, "FEM (linear elastic)")?,
        None => None,
    };
    Ok(FemRun { solution, surface })
}

/// Reads the scene's mesh, perturbs it as CDEM does, and solves.
pub fn solve_scene(scene: &Scene) -> crate::Result<FemSolution> {
    let t0 = Instant::now();
    solve_mesh(scene, &read_mesh(scene)?, t0)
}

/// Solves on the scene's mesh, already read; the wall time counts from `t0`.
fn solve_mesh(scene: &Scene, mesh: &Mesh, t0: Instant) -> crate::Result<FemSolution> {
    if scene.water.is_some() {
        return Err(crate::error::SceneError::invalid(
            "water",
            "the FEM reference (`cdem fem`) is a dry continuum: it has no pore water; run `cdem run` or `cdem srm`",
        )
        .into());
    }
    let problem = FemProblem::from_mesh(mesh, &scene.model_spec())?;
    let mut sol = fem::solve(&problem)?;
    sol.summary.wall_s = t0.elapsed().as_secs_f64();
    Ok(sol)
}
