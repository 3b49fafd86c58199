//! The FEM reference of a scene: read the mesh, perturb it as CDEM does
//! (the same coordinates bit for bit), solve (see [`crate::fem`]).

use std::time::Instant;

use super::run::read_mesh;
use crate::fem::{self, FemProblem, FemSolution};
use crate::scene::Scene;

/// Reads the scene's mesh, perturbs it as CDEM does, and solves.
pub fn solve_scene(scene: &Scene) -> crate::Result<FemSolution> {
    let t0 = Instant::now();
    let mesh = read_mesh(scene)?;
    let problem = FemProblem::from_mesh(&mesh, &scene.model_spec())?;
    let mut sol = fem::solve(&problem)?;
    sol.summary.wall_s = t0.elapsed().as_secs_f64();
    Ok(sol)
}
