//! Shared by the benches: the paper slope's scene with the committed meshes.

use std::path::{Path, PathBuf};

use cdem::model::Model;
use cdem::scene::Scene;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The committed paper-slope meshes (`cdem::harness::perf::scaling::SLOPE_MESHES`), coarse to
/// fine, with their hexahedron counts (1000 refine^2): 250, 1000, 4000, 16000.
pub fn meshes() -> Vec<(PathBuf, usize)> {
    cdem::harness::perf::scaling::SLOPE_MESHES
        .iter()
        .map(|&(refine, path)| (root().join(path), (1000.0 * refine * refine) as usize))
        .collect()
}

/// The paper slope's scene with another mesh.
pub fn slope_scene(mesh: &Path) -> Scene {
    let mut scene = Scene::load(&root().join(cdem::harness::registry::SLOPE.input)).expect("slope scene loads");
    scene.mesh.file = mesh.into();
    scene
}

/// The paper slope's model with another mesh.
#[allow(dead_code)] // not every bench builds from a mesh name
pub fn slope_model(mesh: &Path) -> Model {
    cdem::drivers::build_model(&slope_scene(mesh)).expect("slope model builds")
}
