//! Performance figures for the validation report (issue: performance). The
//! times are measured and reported, never asserted (a shared machine makes
//! them noise); what is asserted is the arithmetic behind them. The criterion
//! benches (`benches/`) and `cdem perf` measure the same figures with more
//! care; references/performance.md records them.

use std::path::Path;

use cdem::harness::perf::bytes::step_bytes;
use cdem::harness::perf::headline::{headline, paper_slope};
use cdem::harness::perf::scaling::fit_power;
use cdem::harness::report::{record, Check};

/// The fit recovers an exact power law.
#[test]
fn power_fit_recovers_an_exact_power_law() {
    let x = [250.0, 1000.0, 4000.0, 16000.0, 1e5];
    let y: Vec<f64> = x.iter().map(|x: &f64| 3.0 * x.powf(1.5)).collect();
    let (p, a) = fit_power(&x, &y);
    assert!((p - 1.5).abs() < 1e-12 && (a - 3.0).abs() < 1e-9, "{p} {a}");
}

/// The byte count of a lumped-mass step on the paper slope is the one
/// derived by hand in references/performance.md ("Bytes per unit of work":
/// 8280-8380 B per hexahedron with 7.4-7.9 springs per hexahedron).
#[test]
fn step_bytes_match_the_hand_count() {
    let (_, model) = paper_slope(Path::new(".")).unwrap();
    let per_element = step_bytes(&model, false) / model.elements.len() as f64;
    assert!((8280.0..=8380.0).contains(&per_element), "{per_element} B per element");
    // Block masses add 72 n_c^2 B per mesh node of n_c copies and 151 B per copy: more than
    // nothing, less than the element operators themselves.
    let extra = step_bytes(&model, true) / model.elements.len() as f64 - per_element;
    assert!(extra > 0.0 && extra < 4992.0, "{extra}");
}

/// The four figures, side by side in one run, as reported rows.
#[test]
fn headline_figures_for_the_report() {
    let (scene, model) = paper_slope(Path::new(".")).unwrap();
    let h = headline(Path::new("."), &scene, &model, &mut |_| {}).unwrap();
    assert!(h.dr_block.converged, "DR of the paper slope converges");
    assert!(h.pcg.converged, "PCG of the paper slope converges");
    println!("{}", h.markdown());
    let src = "references/performance.md";
    let mut rows = vec![
        Check::new(
            "performance: paper slope step (block masses)",
            "M element-steps/s; reference: lumped masses",
            h.step_block.mega_element_steps_per_s,
            h.step_lumped.mega_element_steps_per_s,
            f64::NAN,
            src,
            h.step_block.step_s,
        ),
        Check::new(
            "performance: paper slope step",
            "bandwidth / stream triad (goal 0.5)",
            h.step_fraction_of_stream(),
            0.5,
            f64::NAN,
            src,
            h.step_block.step_s,
        ),
        Check::new(
            "performance: paper slope",
            "DR to 1e-5 / FEM solve time (goal 3)",
            h.dr_over_fem(),
            3.0,
            f64::NAN,
            src,
            h.dr_block.seconds,
        ),
        Check::new(
            "performance: paper slope",
            "PCG to 1e-5 / FEM solve time (goal 3)",
            h.pcg_over_fem(),
            3.0,
            f64::NAN,
            src,
            h.pcg.seconds,
        ),
    ];
    for (case, ours, pyslope) in &h.lem {
        rows.push(Check::new(
            &format!("performance: LEM grid, {case}"),
            "pySlope / ours time (goal 100)",
            pyslope / ours,
            100.0,
            f64::NAN,
            src,
            *ours,
        ));
    }
    record("performance", &rows);
}
