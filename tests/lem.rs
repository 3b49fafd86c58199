//! Limit equilibrium (src/lem): published benchmarks, analytic identities,
//! slice-count convergence, determinism and input errors. Every reference
//! number is in references/lem.md with its source.

use std::path::Path;

use cdem::harness::registry as reg;
use cdem::lem::{
    analyse, evaluate_circle, slices_of, Circle, LemInput, LemResult, LemSection, LowerBound, Material, Method, Mode,
    Zone,
};

// ACADS (1989) problem 1(a); Rocscience Slide verification manual, problem 1;
// Liu, Li & Liu (2014): the paper's LEM safety factor of its slope.
const ACADS_REFEREE: f64 = reg::ACADS_REFEREE.value;
const ACADS_SLIDE_BISHOP: f64 = reg::ACADS_SLIDE_BISHOP.value;
const ACADS_SLIDE_SPENCER: f64 = reg::ACADS_SLIDE_SPENCER.value;
const PAPER_LEM_FS: f64 = reg::PAPER_LEM_FS.value;

fn load(case: reg::Case) -> LemInput {
    case.lem_input().unwrap()
}

fn parse(text: &str) -> cdem::Result<LemInput> {
    LemInput::from_toml(text, Path::new("verification/lem"), Path::new("inline.toml"))
}

fn critical(r: &LemResult, m: Method) -> cdem::lem::CriticalCircle {
    *r.critical.get(m).unwrap()
}

/// The intersection of the 1.5 % bands around two references.
fn both_bands(a: f64, b: f64) -> (f64, f64) {
    ((a * 0.985).max(b * 0.985), (a * 1.015).min(b * 1.015))
}

fn acads_section(c: f64, phi: f64) -> LemSection {
    let ground = vec![[20.0, 25.0], [30.0, 25.0], [50.0, 35.0], [70.0, 35.0]];
    LemSection::new(
        ground,
        LowerBound::Level(20.0),
        Some(Material { cohesion: c, friction_angle: phi, unit_weight: 20e3 }),
        vec![],
        None,
    )
    .unwrap()
}

#[test]
fn acads_1a_bishop_agrees_with_slide_and_the_referee() {
    let r = analyse(&load(reg::LEM_ACADS_1A)).unwrap();
    let c = critical(&r, Method::Bishop);
    let (lo, hi) = both_bands(ACADS_SLIDE_BISHOP, ACADS_REFEREE);
    println!(
        "ACADS 1(a) Bishop {:.5} in [{lo:.5}, {hi:.5}]? circle ({:.3}, {:.3}, {:.3})",
        c.fs, c.circle.xc, c.circle.zc, c.circle.r
    );
    assert!(c.fs >= lo && c.fs <= hi, "Bishop FS {} outside [{lo}, {hi}]", c.fs);
    // The critical circle stays above the base z = 20 of the problem.
    assert!(c.circle.zc - c.circle.r >= 20.0 - 1e-9 || c.circle.xc < c.exit[0] || c.circle.xc > c.entry[0]);
}

/// Spencer on ACADS 1(a): measured 0.9841 (converged in slice count), 0.2 %
/// below Slide's 0.986 (asserted: within 1.5 %) and 1.6 % below the
/// referee's 1.00, i.e. outside the referee's 1.5 % band by 0.0009. That
/// half is not widened and not asserted: it is recorded in the validation
/// report and explained in references/lem.md (our Bishop minimum is 0.2 %
/// below Slide's too, and pySlope agrees with our Bishop on our circle: the
/// search finds a slightly more critical circle than Slide's).
#[test]
fn acads_1a_spencer_agrees_with_slide_and_is_reported_against_the_referee() {
    let r = analyse(&load(reg::LEM_ACADS_1A)).unwrap();
    let c = critical(&r, Method::Spencer);
    let b = critical(&r, Method::Bishop);
    println!("ACADS 1(a) Spencer {:.5}: Slide {ACADS_SLIDE_SPENCER}, referee {ACADS_REFEREE}", c.fs);
    let tol = reg::TOL_ACADS;
    let rows = cdem::harness::validation::acads_rows(&r);
    assert_eq!((rows[0].ours, rows[2].ours), (b.fs, c.fs), "the rows are the critical circles' FS");
    cdem::harness::report::record("lem_acads", &rows);
    // The referee half is reported, not asserted: outside the 1.5 % band, a
    // `not met` row in plain sight (references/lem.md).
    assert_eq!(
        rows[3].status(),
        cdem::harness::report::Status::NotMet,
        "Spencer vs referee: {:.2e}",
        rows[3].rel_error()
    );
    assert!(
        (c.fs - ACADS_SLIDE_SPENCER).abs() <= tol * ACADS_SLIDE_SPENCER,
        "Spencer FS {} vs Slide {ACADS_SLIDE_SPENCER}",
        c.fs
    );
}

/// ACADS 1(c), three soils: Bishop and Spencer against Slide2, and the
/// default 50 slices against 400 (issue 58 item 6: within 0.3 %, the
/// slice ends at the layers).
#[test]
fn acads_1c_layers_agree_with_slide_and_with_400_slices() {
    let (r50, r400) = cdem::harness::suite::lem_layers::acads_1c().unwrap();
    let rows = cdem::harness::validation::acads_1c_rows(&r50, &r400);
    for r in &rows {
        println!(
            "{}: ours {:.5}, reference {:.5}, error {:+.3} %",
            r.id,
            r.ours,
            r.reference,
            100.0 * (r.ours - r.reference) / r.reference
        );
    }
    cdem::harness::report::record("lem_acads_1c", &rows);
    for r in rows.iter().filter(|r| r.id != "lem/acads-1c/bishop-vs-referee") {
        assert!(r.passed(), "{}: {:?} (ours {}, reference {})", r.id, r.defect, r.ours, r.reference);
    }
}

#[test]
fn acads_1a_method_ordering_is_textbook() {
    // Ordinary (no interslice forces) is conservative for phi > 0; Bishop
    // and Spencer agree within 1 % on circles.
    let r = analyse(&load(reg::LEM_ACADS_1A)).unwrap();
    let (o, b, s) = (r.fs.ordinary.unwrap(), r.fs.bishop.unwrap(), r.fs.spencer.unwrap());
    println!(
        "ACADS 1(a): ordinary {o:.4}, Bishop {b:.4}, Spencer {s:.4}; theta {:?} deg",
        critical(&r, Method::Spencer).theta_deg
    );
    assert!(o < b);
    assert!((s - b).abs() < 0.01 * b);
}

#[test]
fn paper_slope_bishop_matches_the_papers_lem() {
    let r = analyse(&load(reg::LEM_PAPER_SLOPE)).unwrap();
    let c = critical(&r, Method::Bishop);
    println!(
        "paper slope Bishop {:.4} (paper 1.084), circle ({:.3}, {:.3}, {:.3})",
        c.fs, c.circle.xc, c.circle.zc, c.circle.r
    );
    cdem::harness::report::record("lem_paper_slope", &[cdem::harness::validation::paper_lem_row(&r)]);
    assert!((c.fs - PAPER_LEM_FS).abs() <= reg::TOL_PAPER_LEM_FS_ABSOLUTE, "Bishop FS {}", c.fs);
    for m in Method::ALL {
        let c = critical(&r, m);
        assert!(
            c.circle.zc - c.circle.r >= -1e-9 || c.circle.xc < c.exit[0] || c.circle.xc > c.entry[0],
            "{m:?} circle below z = 0"
        );
    }
}

#[test]
fn section_from_the_mesh_equals_the_explicit_section() {
    let a = analyse(&load(reg::LEM_PAPER_SLOPE)).unwrap();
    let b = analyse(&load(reg::LEM_PAPER_SLOPE_EXPLICIT)).unwrap();
    for m in Method::ALL {
        let (x, y) = (a.fs.get(m).unwrap(), b.fs.get(m).unwrap());
        assert!((x - y).abs() < 1e-6, "{m:?}: mesh {x}, explicit {y}");
    }
}

/// Planar ground z = s x, circle centre (0, zc): the sliding mass is a
/// circular segment with half-angle t = acos(d / r), d = zc / sqrt(1 + s^2):
/// area r^2 (t - sin t cos t), arc length 2 r t, centroid 2 r sin^3 t /
/// (3 (t - sin t cos t)) from the centre toward the chord, whose x-part is
/// that times s / sqrt(1 + s^2). With phi = 0, FS = c (2 r t) r / (gamma A x_g).
fn segment_case() -> (LemSection, Circle, f64) {
    let (s, zc, r, c, gamma) = (0.5f64, 12.0f64, 20.0f64, 20e3, 18e3);
    let ground = vec![[-100.0, -100.0 * s], [100.0, 100.0 * s]];
    let section = LemSection::new(
        ground,
        LowerBound::Level(-1e3),
        Some(Material { cohesion: c, friction_angle: 0.0, unit_weight: gamma }),
        vec![],
        None,
    )
    .unwrap();
    let k = (1.0 + s * s).sqrt();
    let t = (zc / k / r).acos();
    let area = r * r * (t - t.sin() * t.cos());
    let g = 2.0 * r * t.sin().powi(3) / (3.0 * (t - t.sin() * t.cos()));
    let fs = c * 2.0 * r * t * r / (gamma * area * g * s / k);
    (section, Circle { xc: 0.0, zc, r }, fs)
}

#[test]
fn slice_weights_and_base_lengths_add_up_to_the_circular_segment() {
    let (section, circle, _) = segment_case();
    let (s, zc, r, gamma) = (0.5f64, 12.0f64, 20.0f64, 18e3);
    let t = (zc / (1.0 + s * s).sqrt() / r).acos();
    let slices = slices_of(&section, circle, 7).unwrap();
    let w: f64 = slices.iter().map(|q| q.weight).sum();
    let l: f64 = slices.iter().map(|q| q.base_length).sum();
    assert!((w - gamma * r * r * (t - t.sin() * t.cos())).abs() < 1e-9 * w, "weight {w}");
    assert!((l - 2.0 * r * t).abs() < 1e-12 * l, "arc length {l}");
    // Equal widths, contiguous, base inclinations increasing toward the crest.
    for p in slices.windows(2) {
        assert!((p[0].x[1] - p[1].x[0]).abs() < 1e-12);
        assert!(p[1].alpha > p[0].alpha);
    }
}

#[test]
fn cohesive_fs_converges_to_the_closed_form_at_second_order() {
    let (section, circle, exact) = segment_case();
    let err = |n: usize| {
        let fs = evaluate_circle(&section, circle, n).unwrap();
        let (o, b) = (fs.ordinary.unwrap(), fs.bishop.unwrap());
        // Bishop sums its slices in four interleaved lanes, the ordinary
        // method in one: the same value up to the order of the additions.
        assert!((o - b).abs() <= 1e-14 * o, "phi = 0: Bishop {b} should reduce to the ordinary method {o}");
        (o - exact).abs() / exact
    };
    let (e25, e100) = (err(25), err(100));
    let rate = (e25 / e100).ln() / 4f64.ln();
    println!("closed form {exact:.6}: rel. error {e25:.2e} (25 slices), {e100:.2e} (100); rate {rate:.2}");
    assert!(e100 < 1e-3);
    assert!(rate > 1.8, "rate {rate}");
}

#[test]
fn bishop_equals_ordinary_for_purely_cohesive_soil() {
    // phi = 0: m_alpha = cos(alpha), so both give c L R / sum(W x).
    let section = acads_section(10e3, 0.0);
    for circle in [Circle { xc: 35.0, zc: 50.0, r: 27.0 }, Circle { xc: 32.0, zc: 54.0, r: 28.5 }] {
        let fs = evaluate_circle(&section, circle, 50).unwrap();
        let (o, b) = (fs.ordinary.unwrap(), fs.bishop.unwrap());
        assert!((o - b).abs() <= 1e-12 * o, "ordinary {o}, Bishop {b}");
    }
}

#[test]
fn fs_converges_with_slice_count() {
    // A fixed circle through the ACADS 1(a) slope (near its critical one).
    let section = acads_section(3e3, 19.6);
    let circle = Circle { xc: 29.6, zc: 53.4, r: 28.4 };
    let fs = |n: usize, m: Method| evaluate_circle(&section, circle, n).unwrap().get(m).unwrap();
    for m in Method::ALL {
        let v: Vec<f64> = [25, 50, 100, 200, 400].iter().map(|&n| fs(n, m)).collect();
        let d: Vec<f64> = v.windows(2).map(|p| (p[1] - p[0]).abs()).collect();
        println!("{m:?}: {v:?}");
        assert!((v[1] - v[4]).abs() < 1e-4, "{m:?}: 50 slices off by {}", (v[1] - v[4]).abs());
        for w in d.windows(2) {
            assert!(w[1] < 0.5 * w[0] || w[1] < 1e-9, "{m:?}: differences {d:?} do not shrink");
        }
    }
}

#[test]
fn spencer_moment_equation_at_zero_inclination_is_bishop() {
    // Spencer's theta is far from 0 on a real slope, but its F must satisfy
    // both equations; Bishop satisfies the moment one at theta = 0. Check the
    // Spencer theta and FS are finite and close to Bishop on several circles.
    let section = acads_section(3e3, 19.6);
    for circle in [
        Circle { xc: 35.0, zc: 50.0, r: 27.0 },
        Circle { xc: 32.0, zc: 54.0, r: 28.5 },
        Circle { xc: 40.0, zc: 45.0, r: 18.0 },
    ] {
        let fs = evaluate_circle(&section, circle, 50).unwrap();
        let (b, s) = (fs.bishop.unwrap(), fs.spencer.unwrap());
        assert!((b - s).abs() < 0.02 * b, "Bishop {b}, Spencer {s}");
        assert!(fs.spencer_theta_deg.unwrap().abs() < 45.0);
    }
}

#[test]
fn search_is_deterministic_and_independent_of_threads() {
    let input = load(reg::LEM_ACADS_1A);
    let a = analyse(&input).unwrap();
    let b = analyse(&input).unwrap();
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap().install(|| analyse(&input).unwrap());
    let mut seq = input.clone();
    if let Mode::Search(s) = &mut seq.mode {
        s.parallel = false;
    }
    let c = analyse(&seq).unwrap();
    for r in [&b, &one, &c] {
        for m in Method::ALL {
            let (x, y) = (critical(&a, m), critical(r, m));
            assert_eq!(x.fs.to_bits(), y.fs.to_bits(), "{m:?}");
            let bits = |c: Circle| [c.xc, c.zc, c.r].map(f64::to_bits);
            assert_eq!(bits(x.circle), bits(y.circle), "{m:?}");
        }
        assert_eq!(a.circles_evaluated, r.circles_evaluated);
    }
}

#[test]
fn mirrored_section_gives_the_mirrored_answer() {
    let text = std::fs::read_to_string(reg::LEM_ACADS_1A.input).unwrap();
    let mirrored = text
        .replace(
            "ground = [[20.0, 25.0], [30.0, 25.0], [50.0, 35.0], [70.0, 35.0]]",
            "ground = [[20.0, 35.0], [40.0, 35.0], [60.0, 25.0], [70.0, 25.0]]",
        )
        .replace("facing = \"left\"", "facing = \"right\"");
    assert_ne!(text, mirrored);
    let a = analyse(&load(reg::LEM_ACADS_1A)).unwrap();
    let b = analyse(&parse(&mirrored).unwrap()).unwrap();
    for m in Method::ALL {
        let (x, y) = (critical(&a, m), critical(&b, m));
        assert!((x.fs - y.fs).abs() < 1e-6, "{m:?}: {} vs {}", x.fs, y.fs);
        assert!((x.circle.xc - (90.0 - y.circle.xc)).abs() < 1e-2 && (x.circle.zc - y.circle.zc).abs() < 1e-2, "{m:?}");
        assert!((x.exit[0] - (90.0 - y.exit[0])).abs() < 1e-2);
    }
}

#[test]
fn lower_bound_as_polyline_equals_the_level() {
    let level = acads_section(3e3, 19.6);
    let poly = LemSection::new(
        level.ground().to_vec(),
        LowerBound::Polyline(vec![[0.0, 20.0], [100.0, 20.0]]),
        level.background().copied(),
        vec![],
        None,
    )
    .unwrap();
    // A circle dipping below z = 20 is rejected by both; one above by neither.
    for circle in [Circle { xc: 40.0, zc: 45.0, r: 26.0 }, Circle { xc: 40.0, zc: 45.0, r: 24.0 }] {
        assert_eq!(evaluate_circle(&level, circle, 50).is_ok(), evaluate_circle(&poly, circle, 50).is_ok());
    }
    assert!(evaluate_circle(&level, Circle { xc: 40.0, zc: 45.0, r: 26.0 }, 50).is_err());
}

#[test]
fn zones_of_one_material_match_the_homogeneous_section() {
    let m = Material { cohesion: 3e3, friction_angle: 19.6, unit_weight: 20e3 };
    let ground = acads_section(3e3, 19.6).ground().to_vec();
    let upper = Zone { polygon: vec![[0.0, 30.0], [100.0, 30.0], [100.0, 50.0], [0.0, 50.0]], material: m };
    let zoned = LemSection::new(ground, LowerBound::Level(20.0), Some(m), vec![upper], None).unwrap();
    let circle = Circle { xc: 29.6, zc: 53.4, r: 28.4 };
    let (a, b) = (
        evaluate_circle(&acads_section(3e3, 19.6), circle, 200).unwrap(),
        evaluate_circle(&zoned, circle, 200).unwrap(),
    );
    for m in Method::ALL {
        let (x, y) = (a.get(m).unwrap(), b.get(m).unwrap());
        assert!((x - y).abs() < 1e-4 * x, "{m:?}: {x} vs {y}");
    }
}

#[test]
fn input_errors_name_the_key() {
    let base = std::fs::read_to_string(reg::LEM_ACADS_1A.input).unwrap();
    let cases = [
        (base.replace("z_min = 20.0", "z_min = 20.0\nwater = 1.0"), "water"),
        (base.replace("friction_angle = 19.6", "friction_angle = 95.0"), "material[0].friction_angle"),
        (base.replace("nx = 20", "nx = 0"), "search.grid.nx"),
        (base.replace("z_min = 20.0", "z_min = 30.0"), "section.z_min"),
        (base.replace("[50.0, 35.0], [70.0", "[50.0, 35.0], [45.0"), "section.ground[3]"),
        (base.replace("z_min = 20.0", "z_min = 20.0\nfrom_mesh = \"x.msh\""), "section.from_mesh"),
        (base.replace("slices = 50", "slices = 1"), "analysis.slices"),
        (base.replace("methods = [\"ordinary\", \"bishop\", \"spencer\"]", "methods = [\"janbu\"]"), "janbu"),
        (base.replace("unit_weight = 20.0e3", "unit_weight = -1.0"), "material[0].unit_weight"),
    ];
    for (text, key) in cases {
        let err = parse(&text).unwrap_err().to_string();
        assert!(err.contains(key), "error for {key:?} does not name it: {err}");
    }
    // A facing against the ground: the search finds nothing and names the facing.
    let wrong = parse(&base.replace("facing = \"left\"", "facing = \"right\"")).unwrap();
    let err = cdem::lem::analyse(&wrong).unwrap_err().to_string();
    assert!(err.contains("section.facing is Right") && err.contains("a wrong facing is the likely cause"), "{err}");
    // With two materials, the bad one is named by its index.
    let two = format!(
        "{base}\n[[material]]\nname = \"weak\"\ncohesion = -1.0\nfriction_angle = 10.0\nunit_weight = 20.0e3\nzone = [[20.0, 20.0], [70.0, 20.0], [70.0, 22.0]]\n"
    );
    let err = parse(&two).unwrap_err().to_string();
    assert!(err.contains("material[1].cohesion"), "{err}");
    let err = parse(&format!("{base}\n[circle]\nxc = 1.0\nzc = 2.0\nr = 3.0\n")).unwrap_err().to_string();
    assert!(err.contains("circle"), "{err}");
}

#[test]
fn an_inadmissible_given_circle_is_an_error_not_a_panic() {
    let base = std::fs::read_to_string(reg::LEM_ACADS_1A.input).unwrap();
    let search_start = base.find("[search]").unwrap();
    let text = format!("{}\n[circle]\nxc = 40.0\nzc = 45.0\nr = 40.0\n", &base[..search_start]);
    let err = analyse(&parse(&text).unwrap()).unwrap_err().to_string();
    assert!(err.contains("circle"), "{err}");
}

use cdem::harness::suite::taylor::taylor_text;

/// Our Bishop minimum on [`taylor_text`] against Taylor's chart
/// `F = c / (N gamma H)` (`cdem::harness::suite::taylor`, shared with
/// `cdem reproduce`), recorded as row `id`; returns the result and F.
fn taylor_case(beta: f64, n: reg::Reference, id: &str, file: &str) -> (LemResult, f64) {
    let run = cdem::harness::suite::taylor::run(beta, n, id).unwrap();
    let (r, b, expected) = (run.result, run.bishop, run.expected);
    println!(
        "Taylor {beta} deg: Bishop {:.4}, chart {expected:.4} ({:+.2} %), circle ({:.3}, {:.3}, {:.3}), exit ({:.3}, {:.3}), entry ({:.3}, {:.3})",
        b.fs,
        100.0 * (b.fs / expected - 1.0),
        b.circle.xc,
        b.circle.zc,
        b.circle.r,
        b.exit[0],
        b.exit[1],
        b.entry[0],
        b.entry[1]
    );
    cdem::harness::report::record(file, &[run.row]);
    assert!(
        (b.fs - expected).abs() <= reg::TOL_TAYLOR * expected,
        "{beta} deg: Bishop {} against Taylor {expected}",
        b.fs
    );
    // The search's admissibility tolerance: 1e-9 (1 + r + |zc|); only the
    // arc from the exit to the entry is the slip surface.
    let Circle { xc, zc, r: radius } = b.circle;
    let lowest = if (b.exit[0]..=b.entry[0]).contains(&xc) {
        zc - radius
    } else {
        zc - (radius * radius - (b.exit[0] - xc).powi(2)).sqrt()
    };
    assert!(
        lowest >= -1e-9 * (1.0 + radius + zc.abs()),
        "{beta} deg: the slip surface passes {} m below the base",
        -lowest
    );
    (r, expected)
}

/// A base at the toe's level (no foundation layer, the textbook case): a
/// purely cohesive 60 deg slope of height H whose critical circle is a toe
/// circle, so Taylor's chart applies: F = c / (N gamma H), N = 0.191.
#[test]
fn a_base_at_toe_level_is_allowed_and_matches_taylors_chart() {
    let (r, _) = taylor_case(60.0, reg::TAYLOR_N_60, "lem/taylor-60", "lem_taylor_toe_level");
    let b = critical(&r, Method::Bishop);
    // The 60 deg toe circle's lowest point is the toe: it needs no arc beyond
    // the toe (its continuation stays above the toe-level ground).
    assert!(b.circle.zc - b.circle.r >= -1e-9 * (1.0 + b.circle.r + b.circle.zc.abs()));
    // The level z_min may equal the lowest ground point, not lie above it.
    let above = taylor_text(60.0, 100).replace("z_min = 0.0", "z_min = 0.5");
    assert!(
        matches!(parse(&above), Err(cdem::Error::Scene(cdem::error::SceneError::Invalid { ref key, .. })) if key == "section.z_min")
    );
}

/// Steep cohesive slopes (75 and 90 deg): Taylor's toe circles have their
/// centre in front of the toe, so the circle continued beyond the toe
/// re-enters the level ground; the slip surface is only the arc from the
/// toe (or the face just above it) to the crest (references/lem.md).
#[test]
fn steep_cohesive_slopes_match_taylors_chart_with_toe_circles_whose_continuation_re_enters_the_ground() {
    for (beta, n, id, file) in [
        (75.0, reg::TAYLOR_N_75, "lem/taylor-75", "lem_taylor_75"),
        (90.0, reg::TAYLOR_N_90, "lem/taylor-90", "lem_taylor_90"),
    ] {
        let (r, _) = taylor_case(beta, n, id, file);
        let b = critical(&r, Method::Bishop);
        // The critical circle is a toe circle whose centre lies in front of
        // the toe (x < 20): the one the two-crossing rule rejected.
        assert!(b.circle.xc < 20.0 && b.exit[0] >= 20.0 - 1e-6, "{beta} deg: {b:?}");
        assert!(b.circle.zc - b.circle.r < 0.0, "{beta} deg: the full circle dips below the toe-level ground");
    }
}

/// A circle that cuts the ground four times (the level ground in front of
/// the toe twice, the face and the crest) slides on the crest-side run only:
/// its slices span the face crossing to the crest crossing, and its FS is
/// the one the same arc gives on a section whose level ground is lowered
/// out of the circle's way (the run in front of the toe is not part of it).
#[test]
fn a_circle_re_entering_the_ground_in_front_of_the_toe_slides_on_its_crest_side_arc() {
    let material = Some(Material { cohesion: 20e3, friction_angle: 0.0, unit_weight: 20e3 });
    let section = |front: Vec<[f64; 2]>| {
        let ground = [front, vec![[20.0, 0.0], [20.001, 10.0], [60.0, 10.0]]].concat();
        LemSection::new(ground, LowerBound::Level(-30.0), material, vec![], Some(cdem::lem::Facing::Left)).unwrap()
    };
    // Centre in front of the face, radius reaching below z = 0 there.
    let circle = Circle { xc: 15.0, zc: 14.0, r: 14.5 };
    let (four, lowered) = (section(vec![[0.0, 0.0]]), section(vec![[0.0, -5.0], [19.9, -5.0]]));
    let s = slices_of(&four, circle, 50).unwrap();
    let (x0, x1) = (s[0].x[0], s[s.len() - 1].x[1]);
    assert!(x0 > 20.0 && x0 < 20.001, "exit on the face: {x0}");
    assert!((x1 - (15.0 + (14.5f64.powi(2) - 16.0).sqrt())).abs() < 1e-9, "entry on the crest: {x1}");
    let (a, b) = (evaluate_circle(&four, circle, 50).unwrap(), evaluate_circle(&lowered, circle, 50).unwrap());
    // Lowered to z = -5 in front of the toe, the ground is out of the arc's
    // way (its lowest point is at z = -0.5): two crossings, the same mass.
    let (fa, fb) = (a.bishop.unwrap(), b.bishop.unwrap());
    assert!((fa - fb).abs() <= 1e-12 * fb, "four crossings {fa}, two {fb}");
    assert!((a.exit[0] - b.exit[0]).abs() <= 1e-12 && (a.entry[0] - b.entry[0]).abs() <= 1e-12);
    // The section may end where the arc's continuation is under the ground
    // (x = 12, between its re-entry points 11.2 and 18.8): the crest-side run
    // is closed, so the same mass.
    let short = section(vec![[12.0, 0.0]]);
    let fc = evaluate_circle(&short, circle, 50).unwrap().bishop.unwrap();
    assert!((fc - fb).abs() <= 1e-12 * fb, "section from x = 12: {fc}, two crossings {fb}");
    // A deeper circle passes under the toe: its one run reaches x = 12 under
    // the ground, an open mass (rejected), but a whole one on the longer section.
    let deeper = Circle { r: 15.0, ..circle };
    assert_eq!(evaluate_circle(&short, deeper, 50).unwrap_err(), cdem::lem::Reject::OpenArc);
    let s = slices_of(&four, deeper, 50).unwrap();
    assert!((s[0].x[0] - (15.0 - 29f64.sqrt())).abs() < 1e-9, "exit in front of the toe: {}", s[0].x[0]);
}

/// pySlope 1.4.0's Bishop simplified on our critical circles (its FS
/// recorded in references/pyslope.json by scripts/pyslope_check.py, 50
/// slices) against ours on the same circles (references/lem.md).
#[test]
fn our_bishop_matches_pyslope_on_the_same_circles() {
    let rows = cdem::harness::validation::pyslope_rows(std::path::Path::new(env!("CARGO_MANIFEST_DIR"))).unwrap();
    for c in &rows {
        println!("{}: ours {:.6}, pySlope {:.6}, rel {:.1e}", c.case, c.ours, c.reference, c.rel_error());
    }
    cdem::harness::report::record("lem_pyslope", &rows);
    assert_eq!(rows.len(), 2);
    for c in &rows {
        assert!(c.rel_error() <= reg::TOL_PYSLOPE_SAME_CIRCLE, "{}: {:.2e}", c.case, c.rel_error());
    }
}
