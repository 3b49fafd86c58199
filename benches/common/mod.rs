//! Shared by the benches: the paper slope's scene with the study meshes.

use std::path::Path;

use cdem::model::Model;
use cdem::scene::Scene;

/// Mesh files relative to the slope scene's directory, with their hex counts.
pub const MESHES: [(&str, usize); 4] = [
    ("../../study/slope-h4.msh", 250),
    ("slope.msh", 1000),
    ("../../study/slope-h1.msh", 4000),
    ("../../study/slope-h05.msh", 16000),
];

/// The paper slope's scene with another mesh.
pub fn slope_scene(mesh: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("verification/cases/slope/slope.toml");
    let mut scene = Scene::load(&path).expect("slope scene loads");
    scene.mesh.file = mesh.into();
    scene
}

/// The paper slope's model with another mesh.
#[allow(dead_code)] // not every bench builds from a mesh name
pub fn slope_model(mesh: &str) -> Model {
    cdem::run::build_model(&slope_scene(mesh)).expect("slope model builds")
}
