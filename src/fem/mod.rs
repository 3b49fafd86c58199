//! The implicit FEM reference (`cdem fem SCENE.toml`): linear elastostatics on
//! the scene's mesh taken as a continuum, to check CDEM against.
//!
//! Same scene file and mesh as `cdem run`, with the same node perturbation
//! (bit-identical coordinates), but every interface merged: cells share their
//! nodes and there are no springs (`[joints]` and `[[interface]]` are ignored).
//! The weak form, in SI units (m, N, Pa),
//!
//! `int_V eps(v) : C : eps(u) dV = int_V v . rho g dV`  for all admissible `v`,
//!
//! `C` isotropic (`sigma = lambda tr(eps) I + 2 mu eps`, from each
//! `[[material]]`'s `E, nu`), is discretised with isoparametric trilinear
//! hexahedra (2x2x2 Gauss), linear wedges (3-point triangle x 2-point line
//! rule) and linear tetrahedra (1 point): see [`element`]. The body force
//! `rho g` is integrated **consistently** (`f_c = int N_c rho g dV`); CDEM
//! instead lumps `rho V` to the corners through its tetrahedral decomposition.
//! For undistorted hexahedra (parallelepipeds) the two agree (`V/8` per
//! corner); on perturbed meshes they differ at the order of the distortion.
//! The `[[boundary]]` groups fix components (`u = 0`); fixed components are
//! eliminated, and `K_ff u_f = f_f` is solved by sparse Cholesky (see
//! [`solve`](mod@solve)).
//!
//! Outputs mirror `cdem run` (written by `output::fem`): `summary.json` (the same keys as
//! [`crate::summary::Summary`]: `steps = 1`, `dt = 0`, `unbalanced_ratio` the
//! relative residual `|K u - f|_2 / |f|_2` over the free components, `springs =
//! 0`) and `final.vtu` + `run.pvd` (points the mesh nodes, perturbed).

pub mod element;
pub mod problem;
pub mod solve;

use std::time::Instant;

pub use problem::FemProblem;
pub use solve::Timings;

use crate::error::{Error, SolveError};
use crate::mesh::Cell;
use crate::summary::{EndState, FailedSprings, FieldExtremes, Summary};

/// Relative residual below which the direct solve is reported as converged.
pub const CONVERGED_RESIDUAL: f64 = 1e-8;

/// The FEM solution of a problem.
#[derive(Debug, Clone)]
pub struct FemSolution {
    /// Mesh node coordinates (m), perturbed as the scene asks.
    pub coords: Vec<[f64; 3]>,
    /// Volume cells (gmsh order), referring to `coords`.
    pub cells: Vec<Cell>,
    /// Material index of each cell.
    pub cell_material: Vec<u16>,
    /// Displacement, 3 per mesh node (m).
    pub u: Vec<f64>,
    /// Volume-averaged stress per cell (Pa, Voigt xx yy zz yz xz xy).
    pub stress: Vec<[f64; 6]>,
    /// Consistent gravity load, 3 per node (N).
    pub f_ext: Vec<f64>,
    /// `K u - f`, 3 per node: reactions at fixed components, residual at free
    /// ones (N).
    pub reaction: Vec<f64>,
    /// Number of unknowns solved for.
    pub free_dofs: usize,
    pub timings: Timings,
    pub summary: Summary,
}

/// Solves a problem: assembly, Cholesky, residual, element stresses, summary.
pub fn solve(p: &FemProblem) -> crate::Result<FemSolution> {
    let t0 = Instant::now();
    let s = solve::solve_linear(p)?;
    let t1 = Instant::now();
    let mut stress = Vec::with_capacity(p.cells.len());
    let mut ue = [0.0; 24];
    for (c, cell) in p.cells.iter().enumerate() {
        for (k, &n) in cell.corners().iter().enumerate() {
            ue[3 * k..3 * k + 3].copy_from_slice(&s.u[3 * n..3 * n + 3]);
        }
        let lame = p.materials[p.cell_material[c] as usize].lame;
        let m = 3 * cell.kind.n_nodes();
        let sigma = element::element_stress(cell.kind, &p.cell_coords(c), &ue[..m], lame).map_err(|b| {
            Error::from(SolveError::NonPositiveJacobian { element: cell.tag, point: b.point, det: b.det })
        })?;
        stress.push(sigma);
    }
    let mut timings = s.timings;
    timings.post_s += t1.elapsed().as_secs_f64();
    let field = FieldExtremes::of(&s.u, Some(&stress));
    let converged = s.residual_ratio < CONVERGED_RESIDUAL;
    let summary = Summary {
        end_state: if converged { EndState::Equilibrium } else { EndState::Undecided },
        converged,
        steps: 1,
        wall_s: t0.elapsed().as_secs_f64(),
        dt: 0.0,
        unbalanced_ratio: s.residual_ratio,
        max_abs_uz: field.max_abs_uz,
        min_uz: field.min_uz,
        max_abs_u: field.max_abs_u,
        min_szz: field.min_szz,
        failed_springs: FailedSprings::default(),
        elements: p.cells.len(),
        nodes: p.n_nodes(),
        springs: 0,
        phase1: None,
        phase2: None,
        plastic: None,
        water: None,
        runout: None,
    };
    Ok(FemSolution {
        coords: p.coords.clone(),
        cells: p.cells.clone(),
        cell_material: p.cell_material.clone(),
        u: s.u,
        stress,
        f_ext: s.f_ext,
        reaction: s.reaction,
        free_dofs: s.free_dofs,
        timings,
        summary,
    })
}

impl FemSolution {
    /// The FEM displacement (m) at a point `x` inside the mesh, interpolated
    /// in the cell containing it (inverse isoparametric map); `None` outside.
    /// A point on a shared face gets the value of the first cell found (the
    /// field is continuous, so any is right).
    pub fn displacement_at(&self, x: [f64; 3]) -> Option<[f64; 3]> {
        const TOL: f64 = 1e-9;
        for cell in &self.cells {
            let corners: Vec<[f64; 3]> = cell.corners().iter().map(|&n| self.coords[n]).collect();
            let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            for c in &corners {
                for d in 0..3 {
                    lo[d] = lo[d].min(c[d]);
                    hi[d] = hi[d].max(c[d]);
                }
            }
            let pad = TOL * (0..3).map(|d| hi[d] - lo[d]).fold(0.0, f64::max);
            if (0..3).any(|d| x[d] < lo[d] - pad || x[d] > hi[d] + pad) {
                continue;
            }
            let Some(xi) = element::reference_point(cell.kind, &corners, x) else { continue };
            if !element::inside_reference(cell.kind, xi, 1e-7) {
                continue;
            }
            let (n, _) = element::shape(cell.kind, xi);
            let mut u = [0.0; 3];
            for (k, &node) in cell.corners().iter().enumerate() {
                for d in 0..3 {
                    u[d] += n[k] * self.u[3 * node + d];
                }
            }
            return Some(u);
        }
        None
    }
}
