//! The coarse space of the two-level preconditioner ([`super::pcg`]): the
//! continuous (merged) mesh.
//!
//! The prolongation `P` copies a displacement of the mesh nodes to every
//! copy made from them (`(P x)_i = x_(n_i)`, `n_i` the mesh node of copy `i`);
//! its transpose sums a residual of the copies onto their mesh nodes. The
//! coarse operator is the Galerkin product
//!
//! `A_c = P^T K P = sum_e P_e^T K_e P_e`                                [N/m]
//!
//! over the free components. A spring joins two copies of one mesh node, so
//! `d = u_b - u_a = 0` on every prolonged field: the springs drop out, and
//! `A_c` is the CDEM elements' own stiffness assembled on the merged mesh
//! (not the FEM's trilinear one: the coarse correction is then the exact
//! energy-norm projection onto continuous fields). The fixities of a mesh
//! node are those of its copies (every copy of a fixed node is fixed), so a
//! fixed component has no coarse unknown and gets no correction.
//!
//! `A_c` is assembled once into a lower-triangular column-compressed pattern
//! (no triplets: at 1e5 hexahedra they would take several times its memory)
//! and factored once by faer's sparse Cholesky (sequentially: the parallel factor sums in a thread-dependent order);
//! every application is then a pair of triangular solves. Every sum has a fixed order (elements in model
//! order for the assembly, copies in model order for the restriction), so the
//! result does not depend on the number of threads.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::cholesky::{factorize_symbolic_cholesky, LltRef, SymbolicCholesky};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par, Side};
use rayon::prelude::*;

use crate::error::SolveError;
use crate::model::Model;

/// No coarse unknown (a fixed component).
const NONE: u32 = u32::MAX;

/// `A_c = P^T K P` on the merged mesh, factored, with its restriction.
pub struct CoarseSpace {
    /// Coarse unknown of each copy component `3 i + d` (`NONE` if fixed).
    dof: Vec<u32>,
    /// Restriction lists: coarse unknown `j` sums the copy components
    /// `comp[ptr[j]..ptr[j + 1]]` (model order).
    ptr: Vec<u32>,
    comp: Vec<u32>,
    factor: Option<Factor>,
    /// Scratch: the coarse right-hand side and solution.
    rhs: Vec<f64>,
}

/// The Cholesky factor `A_c = L L^T` (faer, fill-reducing AMD order) with
/// the scratch of its solves.
struct Factor {
    symbolic: SymbolicCholesky<usize>,
    values: Vec<f64>,
    scratch: MemBuffer,
}

/// The parallelism of the factorisation and the solves: sequential, since
/// faer's parallel supernodal Cholesky sums in an order that depends on the
/// number of threads (measured: different bits with 1 and 2 threads on the
/// 16,000-hex slope).
const PAR: Par = Par::Seq;

impl CoarseSpace {
    /// Assembles and factors `A_c` of the model's elastic elements.
    pub fn new(model: &Model) -> Result<Self, SolveError> {
        let (dof, n) = coarse_dofs(model);
        let (ptr, comp) = restriction_lists(&dof, n);
        let (col_ptr, row_idx) = lower_pattern(model, &dof, n);
        let values = assemble(model, &dof, &col_ptr, &row_idx);
        let factor = match n {
            0 => None,
            _ => Some(factorize(n, &col_ptr, &row_idx, &values)?),
        };
        Ok(Self { dof, ptr, comp, factor, rhs: vec![0.0; n] })
    }

    /// Number of coarse unknowns (free components of the merged mesh).
    pub fn len(&self) -> usize {
        self.rhs.len()
    }

    pub fn is_empty(&self) -> bool {
        self.rhs.is_empty()
    }

    /// `z += P A_c^-1 P^T r` (`r`, `z` over the copy components).
    pub fn add_correction(&mut self, r: &[f64], z: &mut [f64]) {
        let Some(f) = &mut self.factor else { return };
        let (ptr, comp) = (&self.ptr, &self.comp);
        self.rhs.par_iter_mut().with_min_len(1024).enumerate().for_each(|(j, b)| {
            *b = comp[ptr[j] as usize..ptr[j + 1] as usize].iter().map(|&k| r[k as usize]).sum();
        });
        let n = self.rhs.len();
        LltRef::new(&f.symbolic, &f.values).solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut self.rhs, n, 1),
            PAR,
            MemStack::new(&mut f.scratch),
        );
        let (dof, x) = (&self.dof, &self.rhs);
        z.par_iter_mut().with_min_len(4096).enumerate().for_each(|(k, z)| {
            if dof[k] != NONE {
                *z += x[dof[k] as usize];
            }
        });
    }
}

/// Factors the lower triangle (`col_ptr`, `row_idx`, `values`) of `A_c`.
fn factorize(n: usize, col_ptr: &[usize], row_idx: &[usize], values: &[f64]) -> Result<Factor, SolveError> {
    let failed = |e: &dyn std::fmt::Debug| SolveError::Factorization { reason: format!("{e:?}") };
    let sym = SymbolicSparseColMatRef::new_checked(n, n, col_ptr, None, row_idx);
    let symbolic = factorize_symbolic_cholesky(sym, Side::Lower, Default::default(), Default::default())
        .map_err(|e| failed(&e))?;
    let mut l = vec![0.0; symbolic.len_val()];
    let mut buf = MemBuffer::try_new(symbolic.factorize_numeric_llt_scratch::<f64>(PAR, Default::default()))
        .map_err(|e| failed(&e))?;
    symbolic
        .factorize_numeric_llt(
            &mut l,
            SparseColMatRef::new(sym, values),
            Side::Lower,
            Default::default(),
            PAR,
            MemStack::new(&mut buf),
            Default::default(),
        )
        .map_err(|e| match e {
            faer::linalg::cholesky::llt::factor::LltError::NonPositivePivot { index } => {
                SolveError::NotPositiveDefinite { dofs: n, pivot: index }
            }
        })?;
    let scratch = MemBuffer::try_new(symbolic.solve_in_place_scratch::<f64>(1, PAR)).map_err(|e| failed(&e))?;
    Ok(Factor { symbolic, values: l, scratch })
}

/// The coarse unknown of every copy component: the free components of the
/// mesh nodes that have copies, numbered node by node in mesh-node order.
fn coarse_dofs(model: &Model) -> (Vec<u32>, usize) {
    let n_mesh = model.mesh_node.iter().map(|&m| m as usize + 1).max().unwrap_or(0);
    let mut first_copy = vec![usize::MAX; n_mesh];
    for (i, &m) in model.mesh_node.iter().enumerate().rev() {
        first_copy[m as usize] = i;
    }
    let mut of_mesh = vec![NONE; 3 * n_mesh];
    let mut n = 0u32;
    for (m, &i) in first_copy.iter().enumerate() {
        if i == usize::MAX {
            continue;
        }
        for d in 0..3 {
            if !model.fixed[3 * i + d] {
                of_mesh[3 * m + d] = n;
                n += 1;
            }
        }
    }
    let dof = (0..3 * model.n_nodes()).map(|k| of_mesh[3 * model.mesh_node[k / 3] as usize + k % 3]).collect();
    (dof, n as usize)
}

fn restriction_lists(dof: &[u32], n: usize) -> (Vec<u32>, Vec<u32>) {
    let mut ptr = vec![0u32; n + 1];
    for &j in dof.iter().filter(|&&j| j != NONE) {
        ptr[j as usize + 1] += 1;
    }
    for j in 0..n {
        ptr[j + 1] += ptr[j];
    }
    let mut fill = ptr.clone();
    let mut comp = vec![0u32; ptr[n] as usize];
    for (k, &j) in dof.iter().enumerate().filter(|(_, &j)| j != NONE) {
        comp[fill[j as usize] as usize] = k as u32;
        fill[j as usize] += 1;
    }
    (ptr, comp)
}

/// The coarse unknowns of element `e`'s corners, `3 c + d` (`NONE` if fixed).
fn element_dofs(model: &Model, dof: &[u32], e: usize, out: &mut Vec<u32>) {
    out.clear();
    for &c in model.elements.corners(e) {
        out.extend((0..3).map(|d| dof[3 * c as usize + d]));
    }
}

/// Sparsity of the lower triangle of `A_c` (column-compressed, rows sorted):
/// column `j` holds every coarse unknown `i >= j` that shares an element with it.
fn lower_pattern(model: &Model, dof: &[u32], n: usize) -> (Vec<usize>, Vec<usize>) {
    let mut rows: Vec<Vec<u32>> = vec![Vec::new(); n];
    let mut ed = Vec::new();
    for e in 0..model.elements.len() {
        element_dofs(model, dof, e, &mut ed);
        for &j in ed.iter().filter(|&&j| j != NONE) {
            rows[j as usize].extend(ed.iter().filter(|&&i| i != NONE && i >= j));
        }
    }
    let mut col_ptr = Vec::with_capacity(n + 1);
    col_ptr.push(0);
    let mut row_idx = Vec::new();
    for r in &mut rows {
        r.sort_unstable();
        r.dedup();
        row_idx.extend(r.iter().map(|&i| i as usize));
        col_ptr.push(row_idx.len());
        *r = Vec::new();
    }
    (col_ptr, row_idx)
}

/// Values of the lower triangle of `sum_e P_e^T K_e P_e`, elements in model order.
fn assemble(model: &Model, dof: &[u32], col_ptr: &[usize], row_idx: &[usize]) -> Vec<f64> {
    let mut values = vec![0.0; row_idx.len()];
    let mut ed = Vec::new();
    let el = &model.elements;
    for e in 0..el.len() {
        element_dofs(model, dof, e, &mut ed);
        let k = el.stiffness_full(e);
        let m = ed.len();
        for (b, &j) in ed.iter().enumerate().filter(|(_, &j)| j != NONE) {
            let col = &row_idx[col_ptr[j as usize]..col_ptr[j as usize + 1]];
            for (a, &i) in ed.iter().enumerate().filter(|(_, &i)| i != NONE && i >= j) {
                let at = col.partition_point(|&r| r < i as usize);
                values[col_ptr[j as usize] + at] += k[a * m + b];
            }
        }
    }
    values
}
