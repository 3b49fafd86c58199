//! Traces strength-reduction trials window by window: for each factor given
//! (in order, warm-started as `cdem srm` does), the mean displacement since
//! the trial's start, its increment per sliding window, the unbalanced ratio
//! and the kinetic energy. The measurement behind the plastic-flow rule of
//! docs/method.md section 2.9b.
//!
//! `cargo run --release --example trial_probe -- SCENE F1 F2 ...` (with
//! `PROBE_WORST=1`: also the node with the largest unbalanced force; with
//! `PROBE_STEPS=A-B`: the ratio and kinetic energy at every step from A to B).
//! Give the factors exactly as `srm.json` has them: `cdem srm` prints them to
//! four decimals, and its bisection's 1.09375 given as the printed 1.0938 is
//! another trial.

use std::ops::ControlFlow;

use cdem::drivers::failure::sliding_rule;
use cdem::drivers::phase::{Phase, Watch};
use cdem::drivers::srm::{Reduction, TrialStart};
use cdem::solver::StepView;

struct Trace<'a> {
    model: &'a cdem::model::Model,
    start: Vec<f64>,
    window: usize,
    last: f64,
}

impl Watch for Trace<'_> {
    fn step(&mut self, _phase: Phase, view: &StepView) -> ControlFlow<()> {
        if view.steps == 1 {
            self.start = view.state.u.clone();
            self.last = 0.0;
        }
        // PROBE_STEPS=A-B: every step of that range (ratio, kinetic energy).
        if let Some((a, b)) = std::env::var("PROBE_STEPS").ok().and_then(|r| {
            let (a, b) = r.split_once('-')?;
            Some((a.parse::<usize>().ok()?, b.parse::<usize>().ok()?))
        }) {
            if (a..=b).contains(&view.steps) {
                println!("    step {:6} ratio {:.3e} kinetic {:.3e}", view.steps, view.ratio, view.kinetic);
            }
        }
        if view.steps.is_multiple_of(self.window) {
            let rule = sliding_rule(self.model, &self.start, &Default::default());
            let mean = rule.mean_displacement(&view.state.u);
            let max = cdem::solver::relax::max_displacement_since(&view.state.u, &self.start);
            println!(
                "  step {:6} mean {:.4e} incr {:.4e} max {:.4e} ratio {:.3e} kinetic {:.3e}",
                view.steps,
                mean,
                mean - self.last,
                max,
                view.ratio,
                view.kinetic
            );
            self.last = mean;
            if std::env::var_os("PROBE_WORST").is_some() {
                // The node with the largest unbalanced force: where the
                // ratio comes from.
                let st = view.state;
                let worst = (0..self.model.n_nodes())
                    .max_by(|&a, &b| unbalanced(self.model, st, a).total_cmp(&unbalanced(self.model, st, b)))
                    .unwrap_or(0);
                let v: f64 = (0..3).map(|d| st.v[3 * worst + d].powi(2)).sum::<f64>().sqrt();
                let x = self.model.x0[worst];
                println!(
                    "    worst node {worst} at ({:.2}, {:.2}, {:.2}): |f| {:.3e} N, |v| {:.3e}",
                    x[0],
                    x[1],
                    x[2],
                    unbalanced(self.model, st, worst),
                    v
                );
            }
        }
        ControlFlow::Continue(())
    }
}

/// `|f_ext - f_int|` of node `i` over its free components.
fn unbalanced(model: &cdem::model::Model, st: &cdem::solver::State, i: usize) -> f64 {
    (0..3)
        .filter(|&d| !model.fixed[3 * i + d])
        .map(|d| (model.f_ext[3 * i + d] - st.f_int[3 * i + d]).powi(2))
        .sum::<f64>()
        .sqrt()
}

fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().expect("SCENE F...");
    let scene = cdem::scene::Scene::load(std::path::Path::new(&path)).unwrap();
    let (mut red, _) = Reduction::new(&scene, TrialStart::Warm).unwrap();
    let model = red.model.clone();
    let window = sliding_rule(&model, &vec![0.0; model.mass.len() * 3], &Default::default()).window;
    println!("window {window} steps, budget {}", red.budget());
    for f in args.map(|a| a.parse::<f64>().unwrap()) {
        println!("F = {f}");
        let mut trace = Trace { model: &model, start: Vec::new(), window, last: 0.0 };
        let run = red.trial(f, &mut trace).unwrap();
        println!(
            "  -> {:?} after {} steps, max {:.3e}",
            run.trial.outcome, run.trial.steps, run.trial.max_displacement
        );
    }
}
