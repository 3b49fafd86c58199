//! The inertial masses of dynamic relaxation, one type for both forms:
//! lumped (one mass per node copy, [`timestep::masses_and_step`](super::timestep::masses_and_step))
//! or node-block ([`BlockMass`]: one dense block per mesh node over its
//! copies). Everything that depends on the form (the accelerations of a step,
//! `x . M x` for the kinetic energy and the Rayleigh quotient) is a method
//! here, so the step does not branch on it.

use super::block_mass::BlockMass;
use super::integrate::{self, Masses};

/// Inertial masses with their scratch.
#[derive(Debug, Clone)]
pub struct Inertia {
    /// Lumped masses (kg, or scaled), one per node copy. With block masses
    /// they remain the per-node diagnostic (which node blew up).
    lumped: Vec<f64>,
    block: Option<Block>,
}

#[derive(Debug, Clone)]
struct Block {
    mass: BlockMass,
    /// One value per node (the quadratic forms' shares, in slot order).
    per_node: Vec<f64>,
    /// `M x` of the quadratic forms, in slot order.
    slot_mx: Vec<f64>,
    /// The unbalanced force and the acceleration, per component in
    /// cluster-slot order (the force's also the quadratic forms' `x`).
    slot_force: Vec<f64>,
    slot_acc: Vec<f64>,
}

impl Inertia {
    pub fn lumped(mass: Vec<f64>) -> Self {
        Self { lumped: mass, block: None }
    }

    pub fn block(mass: Vec<f64>, block: BlockMass) -> Self {
        let n = mass.len();
        let block = Block {
            mass: block,
            per_node: vec![0.0; n],
            slot_mx: vec![0.0; 3 * n],
            slot_force: vec![0.0; 3 * n],
            slot_acc: vec![0.0; 3 * n],
        };
        Self { lumped: mass, block: Some(block) }
    }

    /// Back to lumped masses (the failure phase: separated copies must not
    /// share inertia).
    pub fn to_lumped(&mut self) {
        self.block = None;
    }

    pub fn is_block(&self) -> bool {
        self.block.is_some()
    }

    /// The lumped masses, one per node copy.
    pub fn lumped_masses(&self) -> &[f64] {
        &self.lumped
    }

    /// `x . M x`.
    pub fn quadratic(&mut self, x: &[f64]) -> f64 {
        match &mut self.block {
            Some(b) => b.mass.quadratic(x, &mut b.slot_force, &mut b.slot_mx, &mut b.per_node),
            None => (0..x.len()).map(|k| self.lumped[k / 3] * x[k] * x[k]).sum(),
        }
    }

    /// Prepares this step's accelerations (block masses: `M^-1 (f_ext - f_int
    /// - f_dash)` in two parallel passes; lumped: nothing, the update divides).
    pub fn prepare(&mut self, fixed: &[bool], f_ext: &[f64], f_int: &[f64], f_dash: Option<&[f64]>) {
        if let Some(b) = &mut self.block {
            let f = |i| integrate::driving_node(fixed, f_ext, f_int, f_dash, i);
            b.mass.accelerations(f, &mut b.slot_force, &mut b.slot_acc);
        }
    }

    /// The masses the update reads (after [`Self::prepare`]).
    pub fn masses(&self) -> Masses<'_> {
        match &self.block {
            Some(b) => Masses::Block(&b.mass, &b.slot_acc),
            None => Masses::Lumped(&self.lumped),
        }
    }
}
