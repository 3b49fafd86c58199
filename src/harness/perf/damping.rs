//! The damping table: every damping kind (local, viscous, kinetic) with and
//! without mass scaling, plus viscous damping with node-block masses (the
//! default), each relaxed from rest on one model to the tolerance or a step
//! cap ([`super::timing::time_dr`]); the outcome, the steps, the wall time
//! and the largest vertical displacement of each. A diverging variant is a
//! row with the solver's error, not a failure of the table.

use std::time::Instant;

use serde::Serialize;

use super::timing::time_dr;
use crate::model::Model;
use crate::solver::{DampingKind, SolverParams};

/// One row of the damping table.
#[derive(Debug, Clone, Serialize)]
pub struct DampingRow {
    pub damping: String,
    pub mass_scaling: bool,
    pub block_mass: bool,
    /// "converged", "max_steps" or the solver's error.
    pub outcome: String,
    pub steps: usize,
    pub seconds: f64,
    pub max_abs_uz: f64,
}

/// Every damping kind with and without mass scaling, plus viscous damping
/// with node-block masses, on one model, each from rest to the tolerance
/// (at most `max_steps`).
pub fn damping_table(
    model: &Model,
    base: &SolverParams,
    max_steps: usize,
    progress: &mut dyn FnMut(&str),
) -> Vec<DampingRow> {
    let mut variants = Vec::new();
    for damping in [DampingKind::Local, DampingKind::Viscous, DampingKind::Kinetic] {
        for mass_scaling in [true, false] {
            variants.push(SolverParams {
                damping,
                mass_scaling,
                block_mass: Some(false),
                max_steps: Some(max_steps),
                ..base.clone()
            });
        }
    }
    variants.push(SolverParams {
        damping: DampingKind::Viscous,
        mass_scaling: true,
        block_mass: Some(true),
        max_steps: Some(max_steps),
        ..base.clone()
    });
    variants
        .into_iter()
        .map(|p| {
            let name = format!("{:?}", p.damping).to_lowercase();
            progress(&format!(
                "damping: {name}, mass scaling {}, block masses {}",
                p.mass_scaling,
                p.uses_block_mass()
            ));
            let t = Instant::now();
            let (outcome, steps, max_abs_uz) = match time_dr(model, &p) {
                Ok(f) => ((if f.converged { "converged" } else { "max_steps" }).to_string(), f.steps, f.max_abs_uz),
                Err(e) => (e.to_string(), 0, f64::NAN),
            };
            DampingRow {
                damping: name,
                mass_scaling: p.mass_scaling,
                block_mass: p.uses_block_mass(),
                outcome,
                steps,
                seconds: t.elapsed().as_secs_f64(),
                max_abs_uz,
            }
        })
        .collect()
}
