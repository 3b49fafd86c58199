//! The `discretisation` section of `srm.json` (`cdem srm --mesh-check`,
//! [`super::mesh_check`]): the factors on each mesh, Richardson's
//! extrapolation ([`crate::analysis::richardson`]) and the error and side of
//! the scene's mesh (references/srm.md, "Discretisation error").

use std::path::PathBuf;

use serde::Serialize;

use crate::analysis::richardson::{extrapolate, OrderSource};
use crate::summary::EndState;

/// The bracket width of every reduction of the check: a quarter of a plain
/// `cdem srm`'s ([`super::srm::BRACKET_WIDTH`]), so that the factors of two
/// meshes differ by more than their brackets (Griffiths & Lane's hexahedra
/// differ by 0.02 to 0.04 between refinements).
pub const CHECK_BRACKET_WIDTH: f64 = 0.0025;
/// One mesh of the check.
#[derive(Debug, Clone, Serialize)]
pub struct CheckedMesh {
    /// The refinement factor (1: the scene's mesh).
    pub refine: f64,
    /// The mesh file (the scene's, or the one made in `mesh-check/`).
    pub mesh: PathBuf,
    pub elements: usize,
    pub fs: Option<f64>,
    pub bracket: [Option<f64>; 2],
    pub hi_outcome: Option<EndState>,
    pub trials: usize,
    /// The whole reduction on this mesh, meshing excluded (s).
    pub wall_s: f64,
    /// Meshing it (gmsh or the split), s.
    pub mesh_s: f64,
}

/// Which side of the extrapolated factor the scene's mesh lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// Above it: the mesh overstates the factor of safety.
    Unsafe,
    /// Below it.
    Safe,
    /// Within the brackets' resolution of it (half [`CHECK_BRACKET_WIDTH`]).
    Within,
}

/// The `discretisation` section of `srm.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Discretisation {
    /// How the refined meshes were made.
    pub refined_by: String,
    pub bracket_width: f64,
    /// The scene's mesh first, then each refinement.
    pub meshes: Vec<CheckedMesh>,
    /// Richardson's factor at `h -> 0` (None: a mesh without a bracket).
    pub extrapolated: Option<f64>,
    pub order: Option<f64>,
    pub order_source: Option<OrderSource>,
    /// Roache's grid convergence index of the extrapolated factor (absolute).
    pub uncertainty: Option<f64>,
    /// `(FS - FS_0) / FS_0` of the scene's mesh.
    pub error: Option<f64>,
    pub side: Option<Side>,
    /// The wall time of the whole check over that of the scene's reduction.
    pub cost_ratio: f64,
    /// The one line the command prints.
    pub line: String,
}

/// Richardson's extrapolation of `meshes` (the scene's first) and the error
/// of the scene's mesh.
pub fn discretisation(refined_by: String, meshes: Vec<CheckedMesh>, cost_ratio: f64) -> Discretisation {
    let fs: Option<Vec<f64>> = meshes.iter().map(|m| m.fs).collect();
    let h: Vec<f64> = meshes.iter().map(|m| 1.0 / m.refine).collect();
    let ex = fs.as_ref().and_then(|f| extrapolate(&h, f, 0.5 * CHECK_BRACKET_WIDTH));
    let own = meshes[0].fs;
    let error = ex.zip(own).map(|(e, f)| (f - e.value) / e.value);
    let resolution = 0.5 * CHECK_BRACKET_WIDTH;
    let side = ex.zip(own).map(|(e, f)| match f - e.value {
        d if d.abs() <= resolution => Side::Within,
        d if d > 0.0 => Side::Unsafe,
        _ => Side::Safe,
    });
    let line = match (own, ex, error.zip(side)) {
        (Some(f), Some(e), Some((err, side))) => {
            let how = match e.order_source {
                OrderSource::Observed => format!("order {:.2} observed on {} meshes", e.order, meshes.len()),
                OrderSource::AssumedTwoMeshes => format!("order {} assumed from 2 meshes", e.order),
                OrderSource::AssumedNotObserved => format!(
                    "order {} assumed on the two finest: the {} meshes' changes do not shrink monotonically, or the last \
                     is within the brackets",
                    e.order,
                    meshes.len()
                ),
            };
            let side = match side {
                Side::Unsafe => "unsafe side",
                Side::Safe => "safe side",
                Side::Within => "within the brackets: no side",
            };
            format!(
                "FS {f:.3} on this mesh; about {:.3} converged (+/- {:.3}, {how}); this mesh errs {:+.1} % ({side})",
                e.value,
                e.uncertainty,
                100.0 * err
            )
        }
        _ => {
            let missing: Vec<String> =
                meshes.iter().filter(|m| m.fs.is_none()).map(|m| format!("refine {}", m.refine)).collect();
            format!("no discretisation error: no factor of safety on {}", missing.join(", "))
        }
    };
    Discretisation {
        refined_by,
        bracket_width: CHECK_BRACKET_WIDTH,
        meshes,
        extrapolated: ex.map(|e| e.value),
        order: ex.map(|e| e.order),
        order_source: ex.map(|e| e.order_source),
        uncertainty: ex.map(|e| e.uncertainty),
        error,
        side,
        cost_ratio,
        line,
    }
}
