use cdem::scene::Scene;
use cdem::solver::{Solver, State, DampingKind};
fn main() {
    let scene = Scene::load("verification/cases/slope/slope.toml".as_ref()).unwrap();
    let model = cdem::run::build_model(&scene).unwrap();
    let mut p = scene.solver.clone(); p.damping = DampingKind::Kinetic;
    let mut solver = Solver::new(&model, p).unwrap();
    let mut st = State::new(&model);
    let mut maxke = 0.0f64;
    for i in 0..6400 { match solver.step(&model, &mut st) { Ok((u,k)) => { maxke = maxke.max(k); if i % 200 == 0 || i > 6300 && i % 10 == 0 { let w: f64 = model.f_ext.iter().zip(&st.u).map(|(a,b)| a*b).sum(); println!("{} unbal {:.3e} ke {:.3e} maxke200 {:.3e} W {:.3e}", st.step, u, k, maxke, w); maxke = 0.0; } }, Err(e) => {println!("{e}"); break;} } }
}
