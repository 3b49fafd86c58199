//! Prandtl's footing on another mesh or at another rate (references/plastic.md,
//! "Prandtl's strip footing"): the footing pressure's plateau of
//! `harness::suite::plastic::load_curve` against `(2 + pi) c`.
//!
//! `cargo run --release --example prandtl_probe -- SCENE [TOTAL_M INCREMENTS STEPS [HOLD]]`
//! (the row's loading by default: 0.06 m in 30 x 400 steps, then 4,000 steps held).

fn main() -> Result<(), cdem::error::Error> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let scene = cdem::scene::Scene::load(std::path::Path::new(&args[0]))?;
    let (mut total, mut increments, mut steps, mut hold) = cdem::harness::registry::PRANDTL_LOADING;
    if args.len() >= 4 {
        (total, increments, steps) = (args[1].parse().unwrap(), args[2].parse().unwrap(), args[3].parse().unwrap());
        hold = args.get(4).map_or(0, |h| h.parse().unwrap());
    }
    let curve = cdem::harness::suite::plastic::load_curve(&scene, "footing", -total, increments, steps, hold)?;
    let exact = cdem::harness::registry::prandtl_bearing_capacity();
    for (u, r) in &curve.points {
        println!("{:.4} m  {:.2} kPa", -u, -r / curve.area / 1e3);
    }
    let q = -curve.plateau(3);
    if let Some(r) = curve.held {
        let q = -r / curve.area;
        println!("held {hold} steps: {:.2} kPa: {:+.2} %", q / 1e3, 100.0 * (q / exact - 1.0));
    }
    println!(
        "plateau {:.2} kPa against {:.2} kPa: {:+.2} %, {:.0} s",
        q / 1e3,
        exact / 1e3,
        100.0 * (q / exact - 1.0),
        curve.seconds
    );
    Ok(())
}
