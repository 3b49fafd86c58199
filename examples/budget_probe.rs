//! The measurement behind the step-budget factors `C` of `solver::budget`
//! (docs/method.md section 2.8): for each scene given, the elements across
//! the model `n_c`, the stiffness ratio `kappa`, and the steps phase 1 takes
//! to converge with each damping and mass form, with the ratio
//! `steps / (n_c sqrt(kappa))` (`kappa` = 1 with block masses).
//!
//! `cargo run --release --example budget_probe -- verification/cases/*/*.toml tests/fixtures/block-on-plane.toml`
//! (local damping on the slopes takes minutes).

use cdem::solver::budget::{crossing_elements, spring_stiffness_ratio};
use cdem::solver::{DampingKind, SolverParams};
fn main() {
    for path in std::env::args().skip(1) {
        let scene = cdem::scene::Scene::load(std::path::Path::new(&path)).unwrap();
        let model = cdem::drivers::build_model(&scene).unwrap();
        let (nc, kappa) = (crossing_elements(&model), spring_stiffness_ratio(&model));
        for (name, damping, block) in [
            ("viscous-block", DampingKind::Viscous, true),
            ("viscous-lumped", DampingKind::Viscous, false),
            ("local-lumped", DampingKind::Local, false),
            ("kinetic-lumped", DampingKind::Kinetic, false),
        ] {
            let p =
                SolverParams { damping, block_mass: Some(block), max_steps: Some(3_000_000), ..scene.solver.clone() };
            let k = if block { 1.0 } else { kappa };
            match cdem::drivers::run::relax_elastic(&model, &p, 1_000_000) {
                Ok((_, r)) => println!(
                    "{path} {name}: n_c {nc:.1} kappa {kappa:.1} steps {} converged {} ratio {:.1}",
                    r.steps,
                    r.converged,
                    r.steps as f64 / (nc * k.sqrt())
                ),
                Err(e) => println!("{path} {name}: n_c {nc:.1} kappa {kappa:.1} error {e}"),
            }
        }
    }
}
