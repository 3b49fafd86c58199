//! The byte model of one elastic step: the bytes a step must move between
//! memory and the cores, counted from the model's sizes (no timing), so
//! that `bytes / step time` is the step's effective bandwidth and can be
//! set against the STREAM triad ([`super::stream`]). The count is the one
//! of references/performance.md, "Bytes per unit of work".
//!
//! Lumped masses, per unit of work:
//! - **element** (`K_e u_e` of a hexahedron): the upper triangle of `K_e`,
//!   300 f64 = 2400 B read (4608 B before it was packed, 2026-12-02); the
//!   corner gather, 8 x 3 f64 = 192 B read; the slot write, 24 f64 = 192 B:
//!   **2784 B** (the node indices and offsets, under 3 %, are not counted);
//!   counted from what the model stores, so prisms and tetrahedra count
//!   their own sizes;
//! - **spring** (elastic phase): indices 8 B, normal 24 B, `k_n` and `k_s`
//!   16 B, plastic slip 24 B, status 1 B, `u_a` and `u_b` 48 B read, the
//!   force 24 B written: **145 B**;
//! - **gather, per node copy**: two CSR pointers 8 B, its one element slot
//!   (4 B index + 24 B), per spring end 4 B index + 24 B, the `f_int` write
//!   24 B: **60 B + 28 B per spring end**, with `2 n_springs / n_copies`
//!   ends per copy;
//! - **update, per node copy**: fixity 3 B, mass 8 B, `f_ext` and `f_int`
//!   48 B, `u` and `v` read and written 96 B, and the monitor and the
//!   damping's Rayleigh quotient amortised 9 B: **164 B**.
//!
//! On the paper slope (8 copies and 7.4-7.9 springs per hexahedron) that is
//! 6072-6172 B per hexahedron, 45 % of it the element pass.
//!
//! Node-block masses add, per copy, its rows of the block inverse: `3 x 3 n_c`
//! f64 for a mesh node of `n_c` copies, i.e. `72 n_c^2` B per mesh node; and
//! the two slot-order passes, **151 B per copy**: the force gather reads
//! `f_ext`, `f_int`, fixity and the slot's node (55 B) and writes 24 B; the
//! product writes 24 B of acceleration that the update reads (24 B) through
//! `slot_of` (4 B); the cluster range (8 B) and the row offset (8 B); the
//! cluster's forces are re-read from cache and not counted.

use crate::model::Model;

/// Bytes one elastic step moves on `model`, with node-block masses if
/// `block` (the count in the module doc): per element its packed `K_e` and
/// 48 B per corner (2784 B for a hexahedron), per spring
/// 145 B, per node copy `60 + 28 ends + 164` B; with block masses `72 n_c^2`
/// B per mesh node of `n_c` copies and 151 B per copy more.
pub fn step_bytes(model: &Model, block: bool) -> f64 {
    let (n_s, n_n) = (model.springs.len() as f64, model.n_nodes() as f64);
    let ends = if n_n > 0.0 { 2.0 * n_s / n_n } else { 0.0 };
    let mut bytes = element_bytes(model) + 145.0 * n_s + (60.0 + 28.0 * ends + 164.0) * n_n;
    if block {
        let mut copies = std::collections::HashMap::<u32, f64>::new();
        for &m in &model.mesh_node {
            *copies.entry(m).or_default() += 1.0;
        }
        // Sum over copies of 72 n_c B = sum over mesh nodes of 72 n_c^2 B.
        bytes += copies.values().map(|n_c| 72.0 * n_c * n_c).sum::<f64>() + 151.0 * n_n;
    }
    bytes
}

/// Bytes of the element pass: every element's packed `K_e` and, per corner,
/// the `u` gather and the slot write (3 f64 each): 2784 B per hexahedron.
pub fn element_bytes(model: &Model) -> f64 {
    let el = &model.elements;
    (8 * el.k.len() + 48 * el.nodes.len()) as f64
}

/// Bytes per hexahedron element-step before `K_e` was packed (the full
/// 24 x 24 `K_e`, 4608 B, plus 384 B; references/performance.md).
pub const FULL_KE_ELEMENT_BYTES: f64 = 4992.0;
