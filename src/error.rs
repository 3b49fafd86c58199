//! Typed errors. Every variant says where: the file line, key, element, node or
//! step. The CLI is the only place that turns them into text and an exit code.

use std::path::PathBuf;

/// Any error of the library.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    #[error(transparent)]
    Mesh(#[from] MeshError),
    #[error("{path}: {source}")]
    MeshFile { path: PathBuf, source: MeshError },
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Solve(#[from] SolveError),
    #[error("{path}: {source}")]
    Io { path: PathBuf, source: std::io::Error },
    #[error("gmsh: {0}")]
    Gmsh(String),
    /// The run finished and wrote its report, and rows of it fail (the
    /// report lists them): a program whose checks fail exits non-zero.
    #[error("{count} validation rows fail (listed in {report}), the first: {first}")]
    Validation { count: usize, report: PathBuf, first: String },
    /// A checkpoint that cannot be resumed from: refused, never used.
    #[error("checkpoint {path}: {source}")]
    Checkpoint { path: PathBuf, source: CheckpointError },
    /// The run stopped on a signal after writing its checkpoint (the CLI's
    /// exit code 128 + the signal: 130 for SIGINT, 143 for SIGTERM).
    #[error("stopped by signal {signal} ({name}); checkpoint written to {checkpoint}: continue with --resume")]
    Interrupted { signal: i32, name: &'static str, checkpoint: PathBuf },
}

/// Why a checkpoint file is refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum CheckpointError {
    #[error("not a cdem checkpoint (its first bytes are not the checkpoint magic)")]
    NotACheckpoint,
    #[error("format version {found}, this binary reads version {expected}")]
    Version { found: u32, expected: u32 },
    #[error("a checkpoint of `cdem {found}`, not of `cdem {expected}`")]
    Command { found: String, expected: String },
    #[error("truncated: {found} bytes, its header says {expected}")]
    Truncated { found: u64, expected: u64 },
    #[error("corrupt: its checksum is {found:016x}, its bytes give {computed:016x}")]
    Corrupt { found: u64, computed: u64 },
    #[error("belongs to another scene or mesh (digest {found:016x}, this scene and mesh give {expected:016x})")]
    Foreign { found: u64, expected: u64 },
    #[error("its elastic state differs from this binary's phase 1 of the same scene (digest {found:016x} vs {computed:016x}): written by another build or machine")]
    ElasticState { found: u64, computed: u64 },
    #[error("unreadable content at byte {offset} of its payload: {reason}")]
    Content { offset: usize, reason: String },
}

impl Error {
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Error::Io { path: path.into(), source }
    }
}

/// Errors reading or checking a mesh.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum MeshError {
    /// A syntax or structure error in an MSH file, with the line (ASCII) or
    /// byte offset (binary) where it was found.
    #[error("MSH parse error at {location}: {reason}")]
    Parse { location: String, reason: String },
    #[error("MSH format {version} is not supported (need 4.1)")]
    UnsupportedVersion { version: String },
    #[error("element {element}: gmsh element type {gmsh_type} is not supported in a volume mesh")]
    UnsupportedElement { element: u64, gmsh_type: i32 },
    #[error("element {element}: refers to node {node}, which is not in $Nodes")]
    UnknownNode { element: u64, node: u64 },
    #[error("node {node}: duplicate tag")]
    DuplicateNode { node: u64 },
    #[error("node {node}: coordinate is not finite")]
    NonFiniteNode { node: u64 },
    #[error("element {element}: inverted (sub-tetrahedron {tet} has volume {volume:.3e} m^3)")]
    Inverted { element: u64, tet: usize, volume: f64 },
    #[error("element {element}: degenerate (sub-tetrahedron {tet} has volume {volume:.3e} m^3)")]
    Degenerate { element: u64, tet: usize, volume: f64 },
    #[error("the mesh has no volume elements")]
    NoCells,
    #[error("physical group {name:?} (dim {dim}) not found in the mesh")]
    MissingGroup { name: String, dim: u8 },
    #[error("face shared by more than two elements: elements {elements:?}")]
    NonManifold { elements: Vec<u64> },
}

/// Errors in a scene file: always name the key.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("{path}: {message}")]
    Syntax { path: PathBuf, message: String },
    #[error("scene key `{key}`: {reason}")]
    Invalid { key: String, reason: String },
}

impl SceneError {
    pub fn invalid(key: impl Into<String>, reason: impl Into<String>) -> Self {
        SceneError::Invalid { key: key.into(), reason: reason.into() }
    }
}

/// Errors building the model from a mesh and a scene.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    #[error("element {element}: no material (its volume group{groups} is not given a [[material]])")]
    NoMaterial { element: u64, groups: String },
    #[error("node {node}: non-positive lumped mass {mass:.3e} kg")]
    NonPositiveMass { node: usize, mass: f64 },
    #[error("perturbation inverts element {element} (sub-tetrahedron {tet}, volume {volume:.3e} m^3); lower perturbation.ratio")]
    PerturbationInverts { element: u64, tet: usize, volume: f64 },
    #[error("scene key `{key}`: group {group:?} is not a {what} group of the mesh (its {what} groups: {available})")]
    UnknownGroup { key: String, group: String, what: String, available: String },
    #[error("scene key `{key}`: group {group:?} has {outer} of its {facets} facets on the outer surface, not between two elements: an [[interface]] must be an internal surface")]
    NotAnInterface { key: String, group: String, outer: usize, facets: usize },
    #[error("scene key `{key}`: group {group:?} is not one plane: a node lies {deviation:.3e} m from its plane (extent {extent:.3e} m); keep_flat needs a plane, keep_on keeps nodes on a curved surface")]
    NotPlanar { key: String, group: String, deviation: f64, extent: f64 },
    #[error("part {part} of the model ({elements} elements, the first gmsh element {first_element}) is free to move: the [[boundary]] fixities leave the rigid motion {motion} unresisted; fix more components on a boundary group of that part")]
    FreeRigidMotion { part: usize, elements: usize, first_element: u64, motion: String },
}

impl Error {
    /// Whether the error is in the input (scene, mesh, or what the model
    /// makes of them) rather than in the run: the CLI's exit code 2.
    pub fn is_input(&self) -> bool {
        matches!(
            self,
            Error::Mesh(_) | Error::MeshFile { .. } | Error::Scene(_) | Error::Model(_) | Error::Checkpoint { .. }
        )
    }
}

/// Errors of the time integration.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum SolveError {
    #[error("step {step}: non-finite state at node {node}")]
    NonFinite { step: usize, node: usize },
    #[error("step {step}: energy blow-up at node {node} (kinetic energy {kinetic:.3e} J > external work {work:.3e} J): unstable time step")]
    Unstable { step: usize, node: usize, kinetic: f64, work: f64 },
    /// Conjugate gradients (`elastic = "pcg"`): a search direction with
    /// `p . K p <= 0`, so the elastic stiffness is not positive definite.
    #[error("conjugate gradients, iteration {iteration}: p.Kp = {pkp:.3e} <= 0: the elastic stiffness is not positive definite (a part held by no [[boundary]] group, or a mechanism)")]
    NotPositiveDefiniteCg { iteration: usize, pkp: f64 },
    /// Runout: a vertex deeper inside another block than `[runout]
    /// max_penetration` allows: a contact the detection missed.
    #[error("step {step}: a vertex of element {a} is {depth:.3e} m inside element {b} (deeper than [runout] max_penetration): a missed contact; lower the time step or raise the contact stiffness")]
    Interpenetration { step: usize, a: u64, b: u64, depth: f64 },
    #[error("the model has zero stiffness or zero mass: no stable time step")]
    NoTimeStep,
    /// Implicit FEM: the fixities leave a rigid-body motion free.
    #[error("the model is under-constrained: the [[boundary]] groups leave the rigid-body motion {motion} free; fix more components")]
    UnderConstrained { motion: String },
    /// Implicit FEM: Cholesky met a non-positive pivot although no rigid-body
    /// motion of the whole model is free.
    #[error("the stiffness matrix ({dofs} free components) is not positive definite (non-positive pivot {pivot} in the solver's fill-reducing order): the model is under-constrained, e.g. a part of the mesh held by no [[boundary]] group or a mechanism")]
    NotPositiveDefinite { dofs: usize, pivot: usize },
    /// Implicit FEM: an element's isoparametric map is inverted or degenerate.
    #[error("element {element}: Jacobian determinant {det:.3e} <= 0 at Gauss point {point} (inverted or degenerate element)")]
    NonPositiveJacobian { element: u64, point: usize, det: f64 },
    /// Implicit FEM: the sparse matrix could not be built or factorised for a
    /// non-numerical reason (index overflow, out of memory).
    #[error("sparse factorisation failed: {reason}")]
    Factorization { reason: String },
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
