//! Node-block mass scaling: the fictitious mass of dynamic relaxation as one
//! dense block per mesh node, coupling all the node copies made from it.
//!
//! With a lumped (diagonal) scaled mass, the explicit step is set by the
//! stiffest joint springs while convergence is set by the softest mode of the
//! rock mass, so the step count grows with the square root of the
//! spring-to-rock stiffness ratio (about 170 on the paper slope). The springs
//! of a joint only couple the copies of one mesh node, so a mass that contains
//! them exactly removes that ratio:
//!
//! `M_c = s (B_c + D_c)`, where `B_c` is the block of the assembled stiffness
//! `K` on the copies of mesh node `c` (the springs between them and each
//! copy's own 3x3 element and spring blocks) and `D_c` is diagonal, the
//! absolute row sums of the entries of `K` outside the block. For every `x`,
//! `x.K x = x.B x + x.O x <= x.B x + x.D x` (off-block part `O`,
//! `|O_ij x_i x_j| <= |O_ij| (x_i^2 + x_j^2) / 2`), so `K <= B + D` and the
//! largest eigenvalue of `M^-1 K` is at most `1 / s`. With
//! `s = 1 / (4 safety^2)` and `dt = 1` every mode is at `safety` of its
//! stability limit, the same guarantee the lumped Gershgorin masses give.
//! Fixed components get a unit row and column (their velocity stays zero).
//!
//! The failure phase keeps the blocks built from the intact springs. The
//! bound still holds because a spring's force, in every state, has a
//! stiffness no larger than the intact spring's block `K_aa`:
//! - intact: `K_aa` itself;
//! - broken and open: zero force, zero stiffness;
//! - reclosed in compression: the normal reference is never moved, so the
//!   normal force restarts from zero along `K_n`; the shear reference
//!   followed the motion while the spring was open, so the shear force
//!   restarts from zero along `K_s`: `K_aa` again, from a zero force;
//! - sliding: the shear force is the elastic trial scaled back by a factor
//!   in `[0, 1]` and the slip increment is parallel to the kept force, so
//!   the plastic work is not negative: sliding removes energy, never adds it.
//!
//! So the assembled stiffness of any failure state is at most the intact
//! `K <= B + D`, and every mode stays at `safety` of its limit or below. Not
//! covered by this quadratic-form bound: the friction limit `P tan(phi)`
//! moves with the normal force, a non-symmetric coupling of size
//! `tan(phi) K_n` between normal and shear increments. It is left to the
//! solver's energy monitor, which has not fired on any case with block masses
//! in phase 2 (the slip-surface slope, the stable slope, Wulong, the block on
//! a plane). The spring dashpots of a failure phase (`solver::has_dashpots`;
//! `physics::damping::dashpot_beta`) take half of the room this bound
//! leaves (`Omega <= 2 safety`) for a stiffness-proportional damping.
//! The blocks also couple the inertia of copies that have
//! separated: that changes the fictitious path of the relaxation, not its
//! equilibria (`M^-1 f = 0` if and only if `f = 0`).

use nalgebra::DMatrix;
use rayon::prelude::*;

use crate::error::SolveError;
use crate::model::Model;

/// The blocks, stored by cluster: cluster `c` (the copies of one mesh
/// node, `n = 3 n_c` components) owns an `n x n` block of the mass and of its
/// inverse at `start[c]`, column by column, so that a block times a vector
/// advances all `n` sums of its rows together.
#[derive(Debug, Clone)]
pub struct BlockMass {
    /// Cluster `c` holds the model nodes `nodes[ptr[c]..ptr[c + 1]]`.
    ptr: Vec<u32>,
    nodes: Vec<u32>,
    /// Model node -> its slot in `nodes` (the rows are stored in slot order).
    slot_of: Vec<u32>,
    start: Vec<usize>,
    mass: Vec<f64>,
    inverse: Vec<f64>,
    /// The diagonal of the mass, per node.
    pub diagonal: Vec<[f64; 3]>,
}

impl BlockMass {
    /// Blocks of `scale (B + D)` for the model's elastic stiffness.
    pub fn new(model: &Model, scale: f64) -> Result<Self, SolveError> {
        let n_nodes = model.n_nodes();
        let n_mesh = model.mesh_node.iter().map(|&m| m as usize + 1).max().unwrap_or(0);
        // Clusters: the copies of each mesh node, in model-node order.
        let mut ptr = vec![0u32; n_mesh + 1];
        for &m in &model.mesh_node {
            ptr[m as usize + 1] += 1;
        }
        for c in 0..n_mesh {
            ptr[c + 1] += ptr[c];
        }
        let mut fill = ptr.clone();
        let mut nodes = vec![0u32; n_nodes];
        let mut local = vec![0usize; n_nodes];
        for (i, &m) in model.mesh_node.iter().enumerate() {
            let slot = &mut fill[m as usize];
            local[i] = (*slot - ptr[m as usize]) as usize;
            nodes[*slot as usize] = i as u32;
            *slot += 1;
        }
        let cluster: Vec<u32> = model.mesh_node.clone();
        let size = |c: usize| 3 * (ptr[c + 1] - ptr[c]) as usize;
        let mut blocks: Vec<DMatrix<f64>> = (0..n_mesh).map(|c| DMatrix::zeros(size(c), size(c))).collect();
        let mut off = vec![0.0; 3 * n_nodes];
        // Adds the 3x3 block `k(a, b)` of K between nodes i and j.
        let mut add = |i: usize, j: usize, k: &dyn Fn(usize, usize) -> f64| {
            let c = cluster[i] as usize;
            if cluster[j] as usize == c {
                let b = &mut blocks[c];
                for a in 0..3 {
                    for d in 0..3 {
                        b[(3 * local[i] + a, 3 * local[j] + d)] += k(a, d);
                    }
                }
            } else {
                for a in 0..3 {
                    off[3 * i + a] += (0..3).map(|d| k(a, d).abs()).sum::<f64>();
                }
            }
        };
        let el = &model.elements;
        for e in 0..el.len() {
            let corners = el.corners(e);
            let k = el.stiffness_full(e);
            let n = 3 * corners.len();
            for (p, &i) in corners.iter().enumerate() {
                for (q, &j) in corners.iter().enumerate() {
                    add(i as usize, j as usize, &|a, d| k[(3 * p + a) * n + 3 * q + d]);
                }
            }
        }
        let sp = &model.springs;
        for s in 0..sp.len() {
            let (n, kn, ks) = (sp.normal[s], sp.kn[s], sp.ks[s]);
            let block = |a: usize, d: usize| {
                let nn = n[a] * n[d];
                kn * nn + ks * (if a == d { 1.0 } else { 0.0 } - nn)
            };
            let (i, j) = (sp.a[s] as usize, sp.b[s] as usize);
            add(i, i, &block);
            add(j, j, &block);
            add(i, j, &|a, d| -block(a, d));
            add(j, i, &|a, d| -block(a, d));
        }
        for (i, &c) in cluster.iter().enumerate() {
            let b = &mut blocks[c as usize];
            for a in 0..3 {
                let r = 3 * local[i] + a;
                b[(r, r)] += off[3 * i + a];
                if model.fixed[3 * i + a] {
                    b.row_mut(r).fill(0.0);
                    b.column_mut(r).fill(0.0);
                    b[(r, r)] = 1.0 / scale;
                }
            }
        }
        let mut start = Vec::with_capacity(n_mesh);
        let mut mass = Vec::new();
        let mut inverse = Vec::new();
        for b in blocks {
            let b = b * scale;
            let inv = b.clone().cholesky().ok_or(SolveError::NoTimeStep)?.inverse();
            // nalgebra stores a matrix column by column.
            start.push(mass.len());
            mass.extend_from_slice(b.as_slice());
            inverse.extend_from_slice(inv.as_slice());
        }
        let diagonal = (0..n_nodes)
            .map(|i| {
                let c = cluster[i] as usize;
                let n = size(c);
                [0, 1, 2].map(|a| mass[start[c] + (3 * local[i] + a) * (n + 1)])
            })
            .collect();
        let mut slot_of = vec![0u32; n_nodes];
        for (slot, &i) in nodes.iter().enumerate() {
            slot_of[i as usize] = slot as u32;
        }
        Ok(Self { ptr, nodes, slot_of, start, mass, inverse, diagonal })
    }

    /// All accelerations `M^-1 f` in two parallel passes, for the update:
    /// `f` (a model node's three components) is gathered once into `r` in
    /// slot order (each cluster's copies contiguous), then each cluster's
    /// block of `M^-1` multiplies its part of `r` into its part of `acc`
    /// (slot order; read it with [`Self::acceleration`]). Each output has one
    /// writer and each sum a fixed order: the result does not depend on the
    /// thread count.
    pub fn accelerations(&self, f: impl Fn(usize) -> [f64; 3] + Sync, r: &mut [f64], acc: &mut [f64]) {
        r.par_chunks_mut(3).with_min_len(512).enumerate().for_each(|(slot, r)| {
            r.copy_from_slice(&f(self.nodes[slot] as usize));
        });
        let r = &*r;
        self.per_cluster(acc).into_par_iter().with_min_len(128).enumerate().for_each(|(c, y)| {
            let (lo, hi) = self.span(c);
            block_times(&self.inverse[self.start[c]..], &r[lo..hi], y, -0.0);
        });
    }

    /// Cluster `c` as components `lo..hi` in slot order.
    #[inline]
    fn span(&self, c: usize) -> (usize, usize) {
        (3 * self.ptr[c] as usize, 3 * self.ptr[c + 1] as usize)
    }

    /// `x` (in slot order) cut into its clusters' parts.
    fn per_cluster<'a>(&self, mut x: &'a mut [f64]) -> Vec<&'a mut [f64]> {
        let mut parts = Vec::with_capacity(self.start.len());
        for c in 0..self.start.len() {
            let (lo, hi) = self.span(c);
            let (part, rest) = x.split_at_mut(hi - lo);
            parts.push(part);
            x = rest;
        }
        parts
    }

    /// Node `i`'s acceleration in the output of [`Self::accelerations`].
    #[inline]
    pub fn acceleration(&self, acc: &[f64], i: usize) -> [f64; 3] {
        let s = 3 * self.slot_of[i] as usize;
        [acc[s], acc[s + 1], acc[s + 2]]
    }

    /// `x . M x`: `x` gathered into `r` in slot order as for
    /// [`Self::accelerations`], `M x` per cluster into `mx`, each node's
    /// share `x_i . (M x)_i` written to `share` (slot order), and the shares
    /// summed in node order, so the result is thread-count independent.
    pub fn quadratic(&self, x: &[f64], r: &mut [f64], mx: &mut [f64], share: &mut [f64]) -> f64 {
        r.par_chunks_mut(3).with_min_len(512).enumerate().for_each(|(slot, r)| {
            let i = self.nodes[slot] as usize;
            r.copy_from_slice(&x[3 * i..3 * i + 3]);
        });
        let r = &*r;
        self.per_cluster(mx).into_par_iter().with_min_len(128).enumerate().for_each(|(c, y)| {
            let (lo, hi) = self.span(c);
            block_times(&self.mass[self.start[c]..], &r[lo..hi], y, 0.0);
        });
        let mx = &*mx;
        share.par_iter_mut().with_min_len(1024).enumerate().for_each(|(slot, q)| {
            *q = (0..3).map(|a| r[3 * slot + a] * mx[3 * slot + a]).sum::<f64>();
        });
        self.slot_of.iter().map(|&slot| share[slot as usize]).sum()
    }
}

/// `y = B x` for the block `B` stored column by column from the front of
/// `block` (`len(x)` columns of `len(x)`), each row's sum starting from
/// `zero` (the sign of an all-zero sum) and adding its terms in column order.
/// The rows' sums advance together, a column at a time, so they vectorize
/// and overlap; each is the same, bit for bit, as its row summed alone.
///
/// Runs with AVX2 where the CPU has it ([`crate::simd`]; the same bits).
#[inline(always)]
fn block_times(block: &[f64], x: &[f64], y: &mut [f64], zero: f64) {
    crate::simd::avx2!({
        let n = x.len();
        y.fill(zero);
        if n == 0 {
            return; // a mesh node no element uses
        }
        for (column, &xj) in block[..n * n].chunks_exact(n).zip(x) {
            for (yi, &m) in y.iter_mut().zip(column) {
                *yi += m * xj;
            }
        }
    })
}
