//! The LEM of a file: either a LEM input or a CDEM scene with a `[lem]` table,
//! whose section, zones and unit weights come from the scene's own mesh and
//! materials (docs/method.md, section 5).

use std::path::Path;

use crate::error::SceneError;
use crate::lem::LemInput;
use crate::scene::Scene;

/// The LEM input of the scene's `[lem]` table.
pub fn scene_lem_input(scene: &Scene) -> crate::Result<LemInput> {
    let Some(lem) = &scene.lem else {
        return Err(SceneError::invalid(
            "lem",
            "missing: `cdem lem` on a scene needs a [lem] table (ground_group and [[lem.material]])",
        )
        .into());
    };
    let mesh = super::input::read_mesh(scene)?;
    let g = scene.loads.gravity;
    let gravity = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    let unit_weight_of = |group: &str| {
        scene.material.iter().find(|m| m.group == group).map(|m| m.density * gravity).filter(|w| *w > 0.0)
    };
    // The scene's [water]: its (raised) phreatic surface. Its
    // [[water.crack]] are interface groups of the mesh, which the section
    // does not carry: refused rather than dropped.
    let water =
        match &scene.water {
            Some(w) if !w.crack.is_empty() => return Err(SceneError::invalid(
                "water.crack",
                "`cdem lem` on a scene uses the [water] surface only: its [[water.crack]] are interface groups of the \
                 mesh, which the LEM section does not carry (give the LEM a file with water.crack_depth instead)",
            )
            .into()),
            Some(w) => w.phreatic()?,
            None => None,
        };
    LemInput::from_scene(lem, &mesh, &unit_weight_of, water.as_ref())
}

/// A LEM input file, or a scene (a TOML file with a `[mesh]` table).
pub fn load_lem_input(path: &Path) -> crate::Result<LemInput> {
    let text = std::fs::read_to_string(path).map_err(|e| crate::Error::io(path, e))?;
    let is_scene = text.parse::<toml::Table>().is_ok_and(|t| t.contains_key("mesh"));
    if is_scene {
        scene_lem_input(&Scene::from_toml(&text, path.parent().unwrap_or(Path::new(".")), path)?)
    } else {
        LemInput::from_toml(&text, path.parent().unwrap_or(Path::new(".")), path)
    }
}
