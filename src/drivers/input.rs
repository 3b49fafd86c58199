//! A scene's inputs as the drivers read them: its mesh (errors name the
//! file) and the model built from it.

use crate::error::Error;
use crate::mesh::gmsh::read_msh;
use crate::mesh::Mesh;
use crate::model::{self, Model};
use crate::scene::Scene;

/// Reads the scene's mesh; an error names the file.
pub fn read_mesh(scene: &Scene) -> Result<Mesh, Error> {
    let path = scene.mesh_path();
    read_msh(&path).map_err(|e| match e {
        Error::Mesh(source) => Error::MeshFile { path, source },
        other => other,
    })
}

/// Builds the model of a scene (mesh read and perturbed, springs made).
pub fn build_model(scene: &Scene) -> Result<Model, Error> {
    model::build(&read_mesh(scene)?, &scene.model_spec())
}
