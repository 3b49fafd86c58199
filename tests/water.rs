//! Pore water (src/physics/water.rs, src/model/water.rs; references/water.md):
//! the water forces against Archimedes, the submerged column against
//! Terzaghi's effective stress, and strength reduction with water against the
//! closed forms of the infinite slope and of Hoek & Bray's plane failure.
//! The runs and rows are [`cdem::harness::suite::water`] (shared with
//! `cdem reproduce`).

use cdem::drivers::build_model;
use cdem::harness::registry as reg;
use cdem::harness::report::record;
use cdem::harness::suite::water;
use cdem::scene::{Scene, WaterSection};

/// A closed model wholly under water feels its buoyancy, gamma_w V upwards,
/// whatever its interfaces: the interfaces' forces cancel in pairs and the
/// outer faces' integrate to it (Gauss). Both element shapes of the column.
#[test]
fn a_submerged_model_feels_its_buoyancy() {
    for case in [reg::COLUMN, reg::COLUMN_MERGED] {
        let mut s: Scene = case.scene().unwrap();
        s.water = Some(WaterSection { surface: vec![[-10.0, 55.0], [10.0, 55.0]], ..WaterSection::default() });
        s.water.as_mut().unwrap().unit_weight = 9810.0;
        let m = build_model(&s).unwrap();
        let w = m.water.as_ref().unwrap();
        let volume: f64 = m.elements.volume.iter().sum();
        let expected = 9810.0 * volume;
        println!("{}: resultant {:?}, gamma_w V = {expected}", case.name, w.resultant);
        assert!((w.resultant[2] - expected).abs() < 1e-9 * expected, "{:?}", w.resultant);
        assert!(w.resultant[0].abs() < 1e-9 * expected && w.resultant[1].abs() < 1e-9 * expected);
    }
}

#[test]
fn the_submerged_column_carries_effective_stress_in_its_springs() {
    let (rows, r) = water::column_rows().unwrap();
    for c in &rows {
        println!("{}: {:.6e} vs {:.6e} (err {:.2e})", c.id, c.ours, c.reference, c.rel_error());
    }
    record("water_column", &rows);
    assert!(r.summary.converged);
    assert!(rows.iter().all(|c| c.passed()), "{rows:?}");
}

#[test]
fn strength_reduction_with_water_matches_the_closed_forms() {
    let mut rows = Vec::new();
    for (case, fs, id) in water::srm_cases() {
        let (row, r, _) = water::srm_row(case, fs, id).unwrap();
        println!("{id}: FS {:.4} {:?} vs {fs:.4} ({} trials)", r.fs.unwrap_or(f64::NAN), r.bracket, r.trials.len());
        rows.push(row);
    }
    record("water_srm", &rows);
    assert!(rows.iter().all(|c| c.passed()), "{rows:?}");
}

/// The registry's closed forms against the independent script
/// (`python3 scripts/rock_slope_closed_forms.py`, references/water.md).
#[test]
fn the_registry_closed_forms_equal_the_reference_script() {
    let (p, z) = (reg::PLANE_FAILURE_SET, reg::PLANE_FAILURE_SET.crack_depth());
    let script = [(0.5 * z, true, 1.1152), (z, true, 0.7943), (z, false, 1.0424)];
    for (z_w, uplift, fs) in script {
        let ours = p.fs_with_water(9810.0, z_w, uplift);
        assert!((ours - fs).abs() < 1e-4, "z_w {z_w} uplift {uplift}: {ours} vs the script's {fs}");
    }
    assert!((p.fs_with_water(9810.0, 0.0, true) - p.fs()).abs() < 1e-12);
    for (m, fs) in [(0.0, 1.3378), (0.5, 1.0404), (1.0, 0.7429)] {
        let ours = reg::INFINITE_SLOPE_SET.fs(m);
        assert!((ours - fs).abs() < 1e-4, "m {m}: {ours} vs the script's {fs}");
    }
}

/// Bad water input: a typed error naming its key.
#[test]
fn bad_water_is_named() {
    let base = || reg::WATER_PLANE_CRACK.scene().unwrap();
    let err = |s: Scene| build_model(&s).unwrap_err().to_string();
    // A crack filled above its top.
    let mut s = base();
    s.water.as_mut().unwrap().crack[0].level = 31.0;
    assert!(err(s).contains("water.crack[0].level"));
    // A crack that is not an interface group.
    let mut s = base();
    s.water.as_mut().unwrap().crack[0].group = "rock".into();
    assert!(err(s).contains("water.crack[0].group"));
    // A surface that does not span the model.
    let mut s = base();
    s.water.as_mut().unwrap().surface = vec![[0.0, 10.0], [20.0, 10.0]];
    assert!(err(s).contains("water.surface"));
    // Non-monotone x, through the scene's own check.
    let mut s = base();
    s.water.as_mut().unwrap().surface = vec![[-5.0, 10.0], [50.0, 10.0], [40.0, 10.0]];
    let e = s.validate().unwrap_err().to_string();
    assert!(e.contains("water.surface[2]"), "{e}");
    // Neither a surface nor a crack.
    let mut s = base();
    s.water.as_mut().unwrap().crack.clear();
    assert!(s.validate().unwrap_err().to_string().contains("water"));
}

/// A plastic cell yields on the effective stress: a unit cube compressed
/// hydrostatically to p = -50 kPa (total) is elastic dry, and with a pore
/// pressure of 60 kPa its effective stress is +10 kPa of tension, past a
/// cut-off of 5 kPa: it yields in tension, and its total stress comes back
/// to the cut-off less the pore pressure, T - u = -55 kPa.
#[test]
fn plastic_blocks_yield_on_the_effective_stress() {
    use cdem::mesh::shape::CellKind;
    use cdem::physics::element::element_operators;
    use cdem::physics::material::{Material, MaterialLaw, RockStrength, YoungPoisson};
    use cdem::physics::mohr_coulomb::{MohrCoulomb, Yield};
    use cdem::physics::plastic::{plastic_element_force, plastic_operator, TetPlastic, Volumetric, MAX_TETS};
    use cdem::physics::tet_operator::TetTopology;
    let strength = RockStrength { cohesion: 20e3, tan_phi: 30f64.to_radians().tan(), tensile: 5e3, tan_psi: 0.0 };
    let material = Material {
        lame: YoungPoisson { young: 1e9, poisson: 0.25 }.into(),
        density: 2000.0,
        law: MaterialLaw::MohrCoulomb(strength),
    };
    let corners = vec![
        [0., 0., 0.],
        [1., 0., 0.],
        [1., 1., 0.],
        [0., 1., 0.],
        [0., 0., 1.],
        [1., 0., 1.],
        [1., 1., 1.],
        [0., 1., 1.],
    ];
    let ops = element_operators(CellKind::Hex8, &corners, &material).unwrap();
    // Uniform volumetric strain e: p = K e (K = E / (3 (1 - 2 nu)) = 666.7 MPa).
    let bulk = 1e9 / (3.0 * (1.0 - 0.5));
    let e = -50e3 / bulk / 3.0;
    let u: Vec<f64> = corners.iter().flat_map(|c| c.map(|x| e * x)).collect();
    let nodes: Vec<u32> = (0..8).collect();
    let tets = plastic_operator(CellKind::Hex8, &corners);
    let surface = MohrCoulomb::of(&strength);
    let run = |pore: f64| {
        let mut hist = [TetPlastic::default(); MAX_TETS];
        let mut f = vec![0.0; 24];
        let step = plastic_element_force(
            &TetTopology::of(CellKind::Hex8),
            &tets,
            &ops.grad,
            material.lame,
            &surface,
            &nodes,
            &u,
            Volumetric::Cell,
            pore,
            &[],
            &mut hist,
            &mut f,
        );
        (step.pressure, hist.iter().take(tets.len()).all(|h| h.now == Yield::Tension), hist[0].now)
    };
    let (p_dry, _, now_dry) = run(0.0);
    assert_eq!(now_dry, Yield::Elastic);
    assert!((p_dry + 50e3).abs() < 1e-6 * 50e3, "{p_dry}");
    let (p_wet, all_tension, _) = run(60e3);
    assert!(all_tension, "every tetrahedron yields in tension");
    assert!((p_wet - (5e3 - 60e3)).abs() < 1e-6 * 50e3, "{p_wet}");
}

/// The Wulong model after rain slides where the dry one does not
/// (`wulong/no-slide`, tests/wulong.rs), and the water table's rise at which
/// it first slides is bracketed to 1 m.
#[test]
fn wulong_slides_after_rain() {
    let (rows, (lo, hi, tried)) = cdem::harness::suite::wulong::wet_rows().unwrap();
    for (rise, slid, moved) in &tried {
        println!("rise {rise:.2} m: slid {slid}, max displacement {moved:.3} m");
    }
    record("wulong_wet", &rows);
    println!("stands at {lo:?}, slides at {hi:?}");
    assert!(rows.iter().all(|c| c.passed()), "{rows:?}");
    let (lo, hi) = (lo.unwrap(), hi.unwrap());
    assert!(hi - lo <= cdem::harness::suite::wulong::WET_LEVEL_RESOLUTION + 1e-12);
}

/// The LEM of the wet Wulong scene: at rise 0 the table (20 m below the
/// ground) misses the critical circle, so the FS is the dry scene's; then it
/// falls as the table rises (a minimum over circles of factors that each fall
/// with the pore pressure; the search's own scatter is far below the steps).
#[test]
fn wulong_lem_fs_falls_as_the_table_rises() {
    use cdem::harness::suite::wulong::{figure_rises, lem_fs_by_rise};
    use cdem::lem::Method;
    let wet = reg::WULONG_WET.scene().unwrap();
    let fs = lem_fs_by_rise(&wet, &figure_rises()).unwrap();
    let dry = cdem::lem::analyse(&cdem::drivers::scene_lem_input(&reg::WULONG.scene().unwrap()).unwrap()).unwrap();
    let dry = *dry.fs.get(Method::Bishop).unwrap();
    for (rise, bishop, spencer) in &fs {
        println!("rise {rise:4.1} m: Bishop {bishop:.4}, Spencer {spencer:.4}");
    }
    assert!((fs[0].1 - dry).abs() < 1e-9, "rise 0: {} vs dry {dry}", fs[0].1);
    for w in fs.windows(2) {
        assert!(w[1].1 <= w[0].1 + 1e-3 && w[1].2 <= w[0].2 + 1e-3, "{w:?}");
    }
    // The table at rise 0 is the ground WET_TABLE_DEPTH down (the file's
    // comment; the rows' depths below the ground are computed from it).
    let ground = cdem::drivers::scene_lem_input(&wet).unwrap().section;
    for p in &wet.water.as_ref().unwrap().surface {
        let depth = ground.ground_z(p[0].clamp(0.0, 141.0)) - p[1];
        assert!((depth - cdem::harness::suite::wulong::WET_TABLE_DEPTH).abs() < 1e-3, "{p:?}: {depth}");
    }
    let last = fs.last().unwrap();
    assert!(last.1 < 0.5 * dry, "a table 1 m below the ground at least halves the FS: {last:?} vs {dry}");
    let dir = std::env::temp_dir().join("cdem-wulong-fs-by-water");
    std::fs::create_dir_all(&dir).unwrap();
    let verdicts =
        [(0.0, false), (9.5, false), (14.25, false), (16.62, false), (17.81, false), (18.41, false), (19.0, true)];
    cdem::output::figures::water::fs_by_rise(&dir.join("fs.png"), &fs, &verdicts).unwrap();
}
