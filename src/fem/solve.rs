//! Assembly and solution of `K u = f` with the fixed components eliminated.
//!
//! Partitioning the degrees of freedom into free (`f`) and fixed (`p`, with
//! prescribed values `u_p`), the solved system is
//!
//! `K_ff u_f = b`, `b = f_f - K_fp u_p`,
//!
//! assembled as lower-triangle triplets of `K_ff` (N/m) and factorised by
//! faer's sparse Cholesky `K_ff = L L^T`. Afterwards the internal forces
//! `f_int = sum_e K_e u_e` are recomputed element by element (independently of
//! the assembled matrix): the residual `r = f_int - f` at the free components
//! measures the solution (`|r_f| / |b|`), and at the fixed ones it is the
//! reaction (N).
//!
//! Nodes that belong to no cell carry no stiffness: their components are not
//! unknowns and keep their prescribed value (zero for a scene).
//!
//! Before factorising, the rigid-body motions (3 translations, 3 rotations
//! about the centroid) are tested against the fixed components: if a
//! combination of them moves no fixed component, the model is
//! under-constrained and the error names that motion.

use std::time::Instant;

use crate::model::supports::free_rigid_motion;
use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Mat, Side};

use super::element::{element_matrices, BadJacobian, ElementMatrices};
use super::problem::FemProblem;
use crate::error::{Error, SolveError};

/// Wall-clock times of the stages (s).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Timings {
    /// Element matrices and triplet assembly of `K_ff` and `b`.
    pub assemble_s: f64,
    /// Symbolic and numeric Cholesky factorisation.
    pub factor_s: f64,
    /// Triangular solves.
    pub solve_s: f64,
    /// Residual, reactions and element stresses.
    pub post_s: f64,
}

/// The raw solution of a problem.
#[derive(Debug, Clone)]
pub struct Solved {
    /// Displacement, `3 node + axis` (m).
    pub u: Vec<f64>,
    /// Consistent external (gravity) load, `3 node + axis` (N).
    pub f_ext: Vec<f64>,
    /// `f_int - f_ext`: the reaction at fixed components, the residual at
    /// free ones (N).
    pub reaction: Vec<f64>,
    /// `|r_f|_2 / |b|_2` (0 when `b = 0` and `r_f = 0`).
    pub residual_ratio: f64,
    pub free_dofs: usize,
    pub timings: Timings,
}

fn element_of(p: &FemProblem, c: usize) -> Result<ElementMatrices, Error> {
    let mat = p.materials[p.cell_material[c] as usize];
    let b = p.gravity.map(|g| mat.density * g);
    element_matrices(p.cells[c].kind, &p.cell_coords(c), mat.lame, b).map_err(|BadJacobian { point, det }| {
        SolveError::NonPositiveJacobian { element: p.cells[c].tag, point, det }.into()
    })
}

/// Assembles, factorises and solves `p`.
pub fn solve_linear(p: &FemProblem) -> Result<Solved, Error> {
    let n_dof = 3 * p.n_nodes();
    // 1. Dof map: free index of each component, usize::MAX if fixed or unused.
    let mut used = vec![false; p.n_nodes()];
    for cell in &p.cells {
        for &n in cell.corners() {
            used[n] = true;
        }
    }
    let mut free = vec![usize::MAX; n_dof];
    let mut n_free = 0;
    for k in 0..n_dof {
        if used[k / 3] && !p.fixed[k] {
            free[k] = n_free;
            n_free += 1;
        }
    }
    check_rigid_motions(p, &used)?;

    // 2. Assembly.
    let t0 = Instant::now();
    let mut trip: Vec<Triplet<usize, usize, f64>> = Vec::new();
    let mut f_ext = vec![0.0; n_dof];
    let mut b = vec![0.0; n_free];
    let mut dofs = [0usize; 24];
    for (c, cell) in p.cells.iter().enumerate() {
        let em = element_of(p, c)?;
        let m = 3 * cell.kind.n_nodes();
        for (k, &node) in cell.corners().iter().enumerate() {
            for i in 0..3 {
                dofs[3 * k + i] = 3 * node + i;
            }
        }
        for a in 0..m {
            f_ext[dofs[a]] += em.f[a];
            let fa = free[dofs[a]];
            if fa == usize::MAX {
                continue;
            }
            b[fa] += em.f[a];
            for bb in 0..m {
                let kab = em.k[a * m + bb];
                match free[dofs[bb]] {
                    usize::MAX => b[fa] -= kab * p.prescribed[dofs[bb]],
                    fb if fb <= fa => trip.push(Triplet::new(fa, fb, kab)),
                    _ => {}
                }
            }
        }
    }
    let assemble_s = t0.elapsed().as_secs_f64();

    // 3. Factorise and solve.
    let t1 = Instant::now();
    let mut x = Mat::<f64>::from_fn(n_free, 1, |i, _| b[i]);
    let mut factor_s = 0.0;
    if n_free > 0 {
        let k = SparseColMat::<usize, f64>::try_new_from_triplets(n_free, n_free, &trip)
            .map_err(|e| SolveError::Factorization { reason: format!("{e:?}") })?;
        drop(trip);
        let llt = k.sp_cholesky(Side::Lower).map_err(|e| match e {
            faer::sparse::linalg::LltError::Numeric(
                faer::linalg::cholesky::llt::factor::LltError::NonPositivePivot { index },
            ) => SolveError::NotPositiveDefinite { dofs: n_free, pivot: index },
            other => SolveError::Factorization { reason: format!("{other:?}") },
        })?;
        factor_s = t1.elapsed().as_secs_f64();
        llt.solve_in_place(x.as_mut());
    }
    let solve_s = t1.elapsed().as_secs_f64() - factor_s;

    // 4. Full displacement, internal forces, residual and reactions.
    let t2 = Instant::now();
    let mut u = p.prescribed.clone();
    for k in 0..n_dof {
        if free[k] != usize::MAX {
            u[k] = x[(free[k], 0)];
        }
    }
    if let Some(k) = u.iter().position(|v| !v.is_finite()) {
        return Err(SolveError::NonFinite { step: 0, node: k / 3 }.into());
    }
    let mut reaction: Vec<f64> = f_ext.iter().map(|f| -f).collect();
    for (c, cell) in p.cells.iter().enumerate() {
        let em = element_of(p, c)?;
        let m = 3 * cell.kind.n_nodes();
        let corners = cell.corners();
        for a in 0..m {
            let mut s = 0.0;
            for bb in 0..m {
                s += em.k[a * m + bb] * u[3 * corners[bb / 3] + bb % 3];
            }
            reaction[3 * corners[a / 3] + a % 3] += s;
        }
    }
    let r2: f64 = (0..n_dof).filter(|&k| free[k] != usize::MAX).map(|k| reaction[k] * reaction[k]).sum();
    let b2: f64 = b.iter().map(|v| v * v).sum();
    let residual_ratio = if b2 > 0.0 { (r2 / b2).sqrt() } else { r2.sqrt() };
    let post_s = t2.elapsed().as_secs_f64();
    Ok(Solved {
        u,
        f_ext,
        reaction,
        residual_ratio,
        free_dofs: n_free,
        timings: Timings { assemble_s, factor_s, solve_s, post_s },
    })
}

/// Rejects a problem whose fixed components leave a rigid-body motion free
/// ([`free_rigid_motion`], the check `cdem run` makes too).
fn check_rigid_motions(p: &FemProblem, used: &[bool]) -> Result<(), SolveError> {
    let nodes: Vec<usize> = (0..p.n_nodes()).filter(|&n| used[n]).collect();
    match free_rigid_motion(&p.coords, &p.fixed, &nodes) {
        None => Ok(()),
        Some(motion) => Err(SolveError::UnderConstrained { motion }),
    }
}
