//! Times the element pass of plastic blocks against the condensed one on
//! the paper slope's plastic scene at its elastic state, one thread: each
//! pass starts from the elastic history (every tetrahedron elastic, no
//! plastic strain), so the tetrahedra beyond the surface return to it.
//!
//! `cargo run --release --example plastic_pass -- [SCENE] [PASSES]`
//! (default `verification/plastic/paper-slope/paper-slope.toml`, 200).

use std::time::Instant;

use cdem::harness::perf::timing::strains_pass;
use cdem::model::ELEMENT_SLOT;
use cdem::physics::mohr_coulomb::Yield;
use cdem::solver::forces;

fn main() {
    let _ = rayon::ThreadPoolBuilder::new().num_threads(1).use_current_thread().build_global();
    let mut args = std::env::args().skip(1);
    let path = args.next().unwrap_or_else(|| "verification/plastic/paper-slope/paper-slope.toml".into());
    let passes: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(200);
    let scene = cdem::scene::Scene::load(std::path::Path::new(&path)).expect("scene");
    let model = cdem::drivers::build_model(&scene).expect("model");
    let (state, _) = cdem::drivers::run::relax_elastic(&model, &scene.solver, 1000).expect("elastic");
    let mut f = vec![0.0; ELEMENT_SLOT * model.elements.len()];
    let fresh = state.rock.clone();
    let mut rock = fresh.clone();
    forces::element_forces_plastic(&model, &mut rock, &state.u, &mut f);
    let (mut n, mut y) = (0usize, 0usize);
    for e in 0..model.elements.len() {
        for h in &rock.history[e][..model.plastic.tets(e).len()] {
            n += 1;
            y += (h.now != Yield::Elastic) as usize;
        }
    }
    // A fingerprint of the forces and the plastic strains, bit for bit.
    let bits = f.iter().chain(rock.history.iter().flat_map(|h| h.iter().flat_map(|t| t.eps_p.iter())));
    let fingerprint = bits.fold(0u64, |h, x| h.rotate_left(5) ^ x.to_bits());
    println!("fingerprint {fingerprint:016x}");
    let mut check = 0.0;
    let t = Instant::now();
    for _ in 0..passes {
        rock.clone_from(&fresh);
        forces::element_forces_plastic(&model, &mut rock, &state.u, &mut f);
        check += f[7];
    }
    let plastic = t.elapsed().as_secs_f64() / passes as f64;
    let t = Instant::now();
    for _ in 0..passes {
        rock.clone_from(&fresh);
    }
    let clone = t.elapsed().as_secs_f64() / passes as f64;
    let t = Instant::now();
    for _ in 0..passes * 10 {
        forces::element_forces(&model, &state.u, &mut f);
        check += f[7];
    }
    let condensed = t.elapsed().as_secs_f64() / (10 * passes) as f64;
    // The strains alone (the corner motion to the 24 tetrahedra's strains,
    // nothing else): a floor under any pass that integrates each
    // tetrahedron, whatever its return mapping costs.
    let t = Instant::now();
    for _ in 0..passes {
        check += strains_pass(&model, &state.u);
    }
    let strains = t.elapsed().as_secs_f64() / passes as f64;
    println!("tetrahedra yielding {y} of {n}");
    println!("the tetrahedra's strains alone {:.3} ms; ratio {:.1}", 1e3 * strains, strains / condensed);
    println!("plastic pass {:.3} ms (the history copy {:.3} ms of it)", 1e3 * plastic, 1e3 * clone);
    println!("condensed pass {:.3} ms; ratio {:.1}", 1e3 * condensed, (plastic - clone) / condensed);
    println!("checksum {check:.6e}");
}
