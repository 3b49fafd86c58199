//! The plasticity itself against closed forms (references/plastic.md):
//!
//! 1. one plastic hexahedron in plane-strain compression at a confining
//!    stress: the axial stress it carries (its top face's nodal forces over
//!    the face area) rises to the Mohr-Coulomb limit
//!    `sigma_1 = sigma_3 N_phi + 2 c sqrt(N_phi)` and stays there;
//! 2. the mixed element elastic: it is the condensed element of the same
//!    cell with the volumetric strain averaged, no more (its forces equal
//!    `K_mixed u` to round-off, and its stiffness differs from today's
//!    condensed `K_e` only in the volumetric part).

use crate::mesh::shape::CellKind;
use crate::physics::element::element_operators;
use crate::physics::material::{Lame, Material, MaterialLaw, RockStrength, YoungPoisson};
use crate::physics::mohr_coulomb::MohrCoulomb;
use crate::physics::plastic::{plastic_element_force, plastic_operator, TetPlastic, Volumetric, MAX_TETS};
use crate::physics::tet_operator::TetTopology;

/// The unit cube's corners in gmsh's hexahedron order.
pub const UNIT_HEX: [[f64; 3]; 8] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
    [1.0, 0.0, 1.0],
    [1.0, 1.0, 1.0],
    [0.0, 1.0, 1.0],
];

/// One point of the compression test: the confining stress and the axial
/// stress the element carries at the end of the loading (both Pa,
/// compression positive), and the Mohr-Coulomb limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompressionLimit {
    pub confinement: f64,
    pub axial: f64,
    pub limit: f64,
}

impl CompressionLimit {
    /// `|axial - limit| / limit`.
    pub fn error(&self) -> f64 {
        (self.axial - self.limit).abs() / self.limit
    }
}

/// The material of the compression test: E 1 GPa, nu 0.25.
fn elasticity() -> Lame {
    YoungPoisson { young: 1e9, poisson: 0.25 }.into()
}

/// Plane-strain compression (`eps_yy = 0`) of the unit hexahedron with the
/// lateral stress held at `-confinement` and the axial strain driven to
/// `steps x d_axial` (homogeneous displacement field, the element's own
/// kernel each step, its history carried). The axial stress is the top
/// face's nodal force sum over its area.
pub fn compression(strength: RockStrength, confinement: f64, steps: usize, d_axial: f64) -> CompressionLimit {
    let lame = elasticity();
    let material = Material { lame, density: 1.0, law: MaterialLaw::MohrCoulomb(strength) };
    let ops = element_operators(CellKind::Hex8, &UNIT_HEX, &material).expect("the unit cube is a valid cell");
    let tets = plastic_operator(CellKind::Hex8, &UNIT_HEX);
    let topo = TetTopology::of(CellKind::Hex8);
    let surface = MohrCoulomb::of(&strength);
    let nodes: Vec<u32> = (0..8).collect();
    let mut hist = [TetPlastic::default(); MAX_TETS];
    let (mut exx, mut ezz) = (-confinement * (1.0 - 0.25 * 0.25) / 1e9, 0.0);
    let mut f = [0.0; 24];
    let mut forces = |exx: f64, ezz: f64, hist: &mut [TetPlastic]| {
        let u: Vec<f64> = UNIT_HEX.iter().flat_map(|x| [exx * x[0], 0.0, ezz * x[2]]).collect();
        plastic_element_force(
            &topo,
            &tets,
            &ops.grad,
            lame,
            &surface,
            &nodes,
            &u,
            Volumetric::Cell,
            0.0,
            &[],
            hist,
            &mut f,
        );
        // Top face (z = 1, corners 4-7): sigma_zz = sum f_z; the face x = 1
        // (corners 1, 2, 5, 6): sigma_xx = sum f_x.
        let szz: f64 = (4..8).map(|c| f[3 * c + 2]).sum();
        let sxx: f64 = [1, 2, 5, 6].iter().map(|&c| f[3 * c]).sum();
        (sxx, szz)
    };
    let mut szz = 0.0;
    for _ in 0..steps {
        ezz -= d_axial;
        // Hold sigma_xx at -confinement: secant iterations on eps_xx with the
        // elastic P-modulus, each from the step's starting history (the
        // iterations' return mappings must not accumulate).
        let start = hist;
        for _ in 0..200 {
            let mut h = start;
            let (sxx, s) = forces(exx, ezz, &mut h);
            szz = s;
            hist = h;
            let miss = sxx + confinement;
            if miss.abs() <= 1e-10 * confinement.max(1.0) {
                break;
            }
            exx -= miss / lame.p_modulus();
        }
    }
    let n_phi = {
        let s = strength.tan_phi.atan().sin();
        (1.0 + s) / (1.0 - s)
    };
    CompressionLimit { confinement, axial: -szz, limit: confinement * n_phi + 2.0 * strength.cohesion * n_phi.sqrt() }
}

/// A load-displacement curve under a prescribed velocity: FLAC's
/// velocity-controlled loading (its footing and column verifications). The
/// nodes of the surface group `group` move along z at a constant rate, by
/// `total / (increments x steps)` each dynamic-relaxation step, to `total`
/// (m; they must be fixed in z by the scene), the failure phase on (plastic
/// blocks yield); the reaction, the z sum of the internal forces on those
/// nodes (N), is recorded every `steps` steps. With `hold` > 0 the group
/// is then held at `total` for `hold` steps and the reaction read again
/// ([`LoadCurve::held`]): the viscous damping's share of the reaction, which
/// grows with the rate, relaxes away (Prandtl's footing; references/plastic.md).
///
/// The rate matters: moving the group by a whole increment at once (1 mm a
/// jump, 400 steps to settle) left the column's plateau 12 % below the
/// uniaxial strength (references/plastic.md): the jump overshoots the
/// yield locally and the non-associated flow (dilation 0) locks in the
/// residual stresses.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadCurve {
    /// (displacement (m), reaction (N)) after each increment.
    pub points: Vec<(f64, f64)>,
    /// The loaded group's area, from the plastic blocks' x-y extent at its
    /// nodes (m^2): the reaction over it is the mean stress.
    pub area: f64,
    /// The reaction after the group was held at `total` for the hold's
    /// steps (N; None without a hold): the plateau with the damping's
    /// share of it relaxed away.
    pub held: Option<f64>,
    pub seconds: f64,
}

impl LoadCurve {
    /// The last `n` reactions and their mean (N).
    fn tail(&self, n: usize) -> (&[(f64, f64)], f64) {
        let tail = &self.points[self.points.len().saturating_sub(n)..];
        (tail, tail.iter().map(|p| p.1).sum::<f64>() / tail.len() as f64)
    }
    /// The mean of the last `n` reactions over the area (Pa): the plateau.
    pub fn plateau(&self, n: usize) -> f64 {
        self.tail(n).1 / self.area
    }
    /// The spread of the last `n` reactions relative to their mean: how flat
    /// the plateau is.
    pub fn plateau_spread(&self, n: usize) -> f64 {
        let (tail, mean) = self.tail(n);
        let (lo, hi) = tail.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
        (hi - lo) / mean.abs()
    }
}

/// Runs the loading of [`LoadCurve`] on `scene`.
pub fn load_curve(
    scene: &crate::scene::Scene,
    group: &str,
    total: f64,
    increments: usize,
    steps: usize,
    hold: usize,
) -> Result<LoadCurve, crate::error::Error> {
    use crate::error::SceneError;
    let t0 = std::time::Instant::now();
    let mesh = crate::drivers::read_mesh(scene)?;
    let model = crate::model::build(&mesh, &scene.model_spec())?;
    let g = mesh.group(group).ok_or_else(|| SceneError::invalid("group", format!("no group `{group}`")))?;
    let on: std::collections::HashSet<usize> = mesh.group_nodes(g).into_iter().collect();
    let nodes: Vec<usize> = (0..model.n_nodes()).filter(|&i| on.contains(&(model.mesh_node[i] as usize))).collect();
    if let Some(&i) = nodes.iter().find(|&&i| !model.fixed[3 * i + 2]) {
        return Err(SceneError::invalid("boundary", format!("node {i} of `{group}` is not fixed in z")).into());
    }
    let area = {
        let (lo, hi) = model.bounds_of(nodes.iter().copied());
        (hi[0] - lo[0]) * (hi[1] - lo[1])
    };
    let mut solver = crate::solver::Solver::new(&model, scene.solver.clone())?;
    solver.set_failure(&model, true);
    let mut state = crate::solver::State::new(&model);
    let mut points = Vec::with_capacity(increments);
    let rate = total / (increments * steps) as f64;
    let reaction = |state: &crate::solver::State| -> f64 { nodes.iter().map(|&i| state.f_int[3 * i + 2]).sum() };
    for k in 1..=increments {
        for s in 1..=steps {
            let uz = rate * ((k - 1) * steps + s) as f64;
            for &i in &nodes {
                state.u[3 * i + 2] = uz;
            }
            solver.step(&model, &mut state)?;
        }
        points.push((total * k as f64 / increments as f64, reaction(&state)));
    }
    for _ in 0..hold {
        solver.step(&model, &mut state)?;
    }
    let held = (hold > 0).then(|| reaction(&state));
    Ok(LoadCurve { points, area, held, seconds: t0.elapsed().as_secs_f64() })
}

/// The row `plastic/element-limit`: the largest relative error of
/// [`compression`] over the confinements of the registry (c = 100 kPa,
/// phi = 30 deg, psi = 0, no cut-off), and the points.
pub fn element_limit_row() -> (crate::harness::report::Check, Vec<CompressionLimit>) {
    use crate::harness::registry as reg;
    let t0 = std::time::Instant::now();
    let strength =
        RockStrength { cohesion: 1e5, tan_phi: 30f64.to_radians().tan(), tensile: f64::INFINITY, tan_psi: 0.0 };
    let points: Vec<CompressionLimit> =
        reg::PLASTIC_ELEMENT_CONFINEMENTS.iter().map(|&s3| compression(strength, s3, 200, 2e-5)).collect();
    let worst = points.iter().map(CompressionLimit::error).fold(0.0, f64::max);
    (reg::row("plastic/element-limit").value(worst, 0.0, t0.elapsed().as_secs_f64()), points)
}

/// The rows `plastic/column-compression` and `plastic/column-tension`: the
/// unconfined column ([`load_curve`] on its top at the registry's rate)
/// against the uniaxial strength and the tension cut-off, and the curves.
pub fn column_rows() -> Result<Vec<(crate::harness::report::Check, LoadCurve)>, crate::error::Error> {
    use crate::harness::registry as reg;
    let (total, increments, steps) = reg::PLASTIC_COLUMN_LOADING;
    let cases = [
        (reg::PLASTIC_COLUMN_COMPRESSION, -1.0, reg::plastic_column_ucs(), "plastic/column-compression"),
        (reg::PLASTIC_COLUMN_TENSION, 1.0, reg::PLASTIC_COLUMN_TENSILE, "plastic/column-tension"),
    ];
    let mut rows = Vec::new();
    for (case, sign, limit, id) in cases {
        let curve = load_curve(&case.scene()?, "top", sign * total, increments, steps, 0)?;
        let row = reg::row(id).value(sign * curve.plateau(5), limit, curve.seconds);
        rows.push((row, curve));
    }
    Ok(rows)
}

/// The row `plastic/prandtl`: the footing pressure of Prandtl's strip
/// footing ([`load_curve`] on `footing` at the registry's rate) against
/// `(2 + pi) c`, and the curve.
pub fn prandtl_row() -> Result<(crate::harness::report::Check, LoadCurve), crate::error::Error> {
    use crate::harness::registry as reg;
    let (total, increments, steps, hold) = reg::PRANDTL_LOADING;
    let curve = load_curve(&reg::PLASTIC_PRANDTL.scene()?, "footing", -total, increments, steps, hold)?;
    let held = curve.held.map_or(f64::NAN, |r| -r / curve.area);
    let row = reg::row("plastic/prandtl").value(held, reg::prandtl_bearing_capacity(), curve.seconds);
    Ok((row, curve))
}

/// One homogeneous slope with plastic blocks: the reduction and its row.
pub struct SlopeRun {
    pub result: crate::drivers::SrmResult,
    pub row: crate::harness::report::Check,
}

/// The row `plastic/gl1-hex-srm`: `cdem srm` on Griffiths & Lane's example
/// 1 (plastic blocks, structured hexahedra) against Bishop & Morgenstern's
/// chart. The row fails (with the reason) without a bracket at most
/// [`crate::harness::suite::srm::BRACKET_WIDTH`] wide; its upper end may be
/// Undecided (counted unstable, as FLAC counts a trial that does not
/// converge): `srm.json` and the test say which.
pub fn gl1_hex_row() -> Result<SlopeRun, crate::error::Error> {
    use crate::harness::registry as reg;
    slope_row(&reg::PLASTIC_GL1_HEX, "plastic/gl1-hex-srm", reg::GL1_CHART_FS.value)
}

/// The row `plastic/paper-slope-srm` (issue 24, item 6): `cdem srm` on the
/// paper's slope with plastic blocks and every interface breakable at the
/// rock mass's strength, against Liu, Li & Liu's LEM; a defect without a
/// bracket, as [`gl1_hex_row`].
pub fn paper_slope_row() -> Result<SlopeRun, crate::error::Error> {
    use crate::harness::registry as reg;
    slope_row(&reg::PLASTIC_PAPER_SLOPE, "plastic/paper-slope-srm", reg::PAPER_LEM_FS.value)
}

/// `cdem srm` on `case` as the row `id` against `reference`, with a defect
/// unless the bracket is at most [`crate::harness::suite::srm::BRACKET_WIDTH`] wide,
/// and the row's discretisation figure in its note
/// ([`crate::harness::registry::with_mesh_error`]).
fn slope_row(case: &crate::harness::registry::Case, id: &str, reference: f64) -> Result<SlopeRun, crate::error::Error> {
    let t0 = std::time::Instant::now();
    let (result, _) = crate::drivers::run_srm(&case.scene()?, &mut |_| {})?;
    let mut row =
        crate::harness::registry::row(id).value(result.fs.unwrap_or(f64::NAN), reference, t0.elapsed().as_secs_f64());
    if let Some(why) = bracket_defect(&result) {
        row = row.with_defect(why);
    }
    Ok(SlopeRun { result, row: crate::harness::registry::with_mesh_error(row) })
}

/// Why a strength reduction's result is not a factor of safety: no bracket
/// at most [`crate::harness::suite::srm::BRACKET_WIDTH`] wide (None: it is).
pub fn bracket_defect(result: &crate::drivers::SrmResult) -> Option<String> {
    let width = crate::harness::suite::srm::BRACKET_WIDTH;
    match result.bracket {
        [Some(lo), Some(hi)] if hi - lo <= width + 1e-12 => None,
        b => Some(format!("no bracket of width {width}: {b:?}")),
    }
}

/// The mesh-independence measure of issue 24 item 4: `(max - min) / min` of
/// one slope's factors of safety on several meshes (a NaN factor, a
/// reduction without a bracket, is left out: [`bracket_defect`] reports it).
pub fn mesh_spread(fs: &[f64]) -> f64 {
    let lo = fs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = fs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (hi - lo) / lo
}

/// The rows `plastic/gl1-prism-srm`, `plastic/gl1-tet-srm` and
/// `plastic/gl1-mesh-spread`: `cdem srm` on the same slope meshed with
/// unstructured prisms and tetrahedra (node-smoothed, docs/method.md 2.9b),
/// each against the chart within the hexahedra's 5 %, and the spread
/// `(max - min) / min` of the three shapes' factors (issue 24's 3 %). A
/// shape without a bracket gives its row and the spread a defect.
pub fn gl1_shape_rows(
    hex: &SlopeRun,
) -> Result<(SlopeRun, SlopeRun, crate::harness::report::Check), crate::error::Error> {
    use crate::harness::registry as reg;
    let prism = slope_row(&reg::PLASTIC_GL1_PRISM, "plastic/gl1-prism-srm", reg::GL1_CHART_FS.value)?;
    let tet = slope_row(&reg::PLASTIC_GL1_TET, "plastic/gl1-tet-srm", reg::GL1_CHART_FS.value)?;
    let spread = mesh_spread(&[hex.row.ours, prism.row.ours, tet.row.ours]);
    let seconds = prism.row.seconds + tet.row.seconds;
    let mut spread_row = reg::row("plastic/gl1-mesh-spread").value(spread, 0.0, seconds).with_note(format!(
        "hexahedra {:.4} {:?}, prisms {:.4} {:?}, tetrahedra {:.4} {:?} (references/plastic.md)",
        hex.row.ours, hex.result.bracket, prism.row.ours, prism.result.bracket, tet.row.ours, tet.result.bracket
    ));
    if let Some(why) = [&hex.row, &prism.row, &tet.row].iter().find_map(|r| r.defect.clone()) {
        spread_row = spread_row.with_defect(why);
    }
    Ok((prism, tet, spread_row))
}

/// A published slope of issue 24 item 4 on its three shapes
/// ([`crate::harness::registry::PUBLISHED_SLOPES`]): each shape's `cdem srm`
/// and our Bishop on the same section.
pub struct PublishedSlopeRun {
    /// Hexahedra, prisms, tetrahedra, as the slope lists its scenes.
    pub results: Vec<crate::drivers::SrmResult>,
    /// The wall time of each (s).
    pub seconds: Vec<f64>,
    /// Our Bishop factor of the slope's LEM input.
    pub bishop: f64,
}

/// `cdem srm` on `scene`: its result and wall time (s).
fn reduce(scene: &str) -> Result<(crate::drivers::SrmResult, f64), crate::error::Error> {
    let t0 = std::time::Instant::now();
    let loaded = crate::scene::Scene::load(std::path::Path::new(scene))?;
    let result = crate::drivers::run_srm(&loaded, &mut |_| {})?.0;
    Ok((result, t0.elapsed().as_secs_f64()))
}

impl PublishedSlopeRun {
    /// Runs `slopes` (each slope's three strength reductions, and our Bishop
    /// on its LEM input) on `workers` threads, each reduction alone on one thread (a rayon
    /// pool of one: the results are bit for bit those of any thread count),
    /// the largest meshes first so that the longest reduction does not start
    /// last. The runs come back in the order of `slopes`; `progress` hears
    /// each reduction as it starts.
    pub fn run_all(
        slopes: &[&crate::harness::registry::PublishedSlope],
        workers: usize,
        progress: &(dyn Fn(&str) + Sync),
    ) -> Result<Vec<Self>, crate::error::Error> {
        use std::sync::atomic::{AtomicUsize, Ordering};
        use std::sync::Mutex;
        let path = |p: &'static str| std::path::Path::new(p);
        let mut jobs: Vec<(usize, usize, u64)> = Vec::new();
        for (i, slope) in slopes.iter().enumerate() {
            for (k, scene) in slope.scenes.iter().enumerate() {
                // The mesh file's size stands for the reduction's cost.
                let size = crate::scene::Scene::load(path(scene))
                    .ok()
                    .and_then(|s| std::fs::metadata(s.mesh_path()).ok())
                    .map_or(0, |m| m.len());
                jobs.push((i, k, size));
            }
        }
        jobs.sort_by(|a, b| b.2.cmp(&a.2).then(a.0.cmp(&b.0)).then(a.1.cmp(&b.1)));
        type Done = (crate::drivers::SrmResult, f64);
        let done: Mutex<Vec<Vec<Option<Done>>>> = Mutex::new(slopes.iter().map(|_| vec![None, None, None]).collect());
        let first_error: Mutex<Option<crate::error::Error>> = Mutex::new(None);
        let next = AtomicUsize::new(0);
        std::thread::scope(|scope| {
            for _ in 0..workers.max(1) {
                scope.spawn(|| {
                    let pool = match rayon::ThreadPoolBuilder::new().num_threads(1).build() {
                        Ok(pool) => pool,
                        Err(e) => {
                            let e = crate::error::Error::io("rayon thread pool", std::io::Error::other(e.to_string()));
                            if let Ok(mut f) = first_error.lock() {
                                f.get_or_insert(e);
                            }
                            return;
                        }
                    };
                    loop {
                        let j = next.fetch_add(1, Ordering::SeqCst);
                        let Some(&(i, k, _)) = jobs.get(j) else { break };
                        if first_error.lock().map_or(true, |f| f.is_some()) {
                            break;
                        }
                        let scene = slopes[i].scenes[k];
                        progress(&format!("{}: cdem srm {scene}", slopes[i].name));
                        match pool.install(|| reduce(scene)) {
                            Ok(r) => {
                                if let Ok(mut d) = done.lock() {
                                    d[i][k] = Some(r);
                                }
                            }
                            Err(e) => {
                                if let Ok(mut f) = first_error.lock() {
                                    f.get_or_insert(e);
                                }
                            }
                        }
                    }
                });
            }
        });
        if let Some(e) = first_error.into_inner().ok().flatten() {
            return Err(e);
        }
        let done = done.into_inner().unwrap_or_default();
        let mut runs = Vec::new();
        for (slope, shapes) in slopes.iter().zip(done) {
            let input = crate::drivers::lem::load_lem_input(path(slope.lem_input))?;
            let bishop = crate::lem::analyse(&input)?.fs.bishop.as_ref().map_or(f64::NAN, |b| *b);
            let (mut results, mut seconds) = (Vec::new(), Vec::new());
            for (r, s) in shapes.into_iter().flatten() {
                results.push(r);
                seconds.push(s);
            }
            runs.push(Self { results, seconds, bishop });
        }
        Ok(runs)
    }

    /// The factors of safety (NaN without a bracket).
    pub fn factors(&self) -> Vec<f64> {
        self.results.iter().map(|r| r.fs.unwrap_or(f64::NAN)).collect()
    }

    /// Its four rows ([`crate::harness::registry::published_slope_ids`]):
    /// each shape against the published FE strength reduction (the note has
    /// the published LEM and our Bishop too), and the spread of the three.
    /// A shape without a bracket gives its row and the spread a defect.
    pub fn rows(&self, slope: &crate::harness::registry::PublishedSlope) -> Vec<crate::harness::report::Check> {
        use crate::harness::registry as reg;
        let ids = reg::published_slope_ids(slope);
        let fs = self.factors();
        let mut rows = Vec::new();
        for (k, result) in self.results.iter().enumerate() {
            let f = fs[k];
            let bracket = match result.bracket {
                [Some(lo), Some(hi)] => format!("[{lo:.4}, {hi:.4}]"),
                b => format!("{b:?}"),
            };
            let upper = result.hi_outcome.map_or("-".to_string(), |o| format!("{o:?}"));
            let mut row = reg::row(&ids[k]).value(f, slope.fe_srm, self.seconds[k]).with_note(format!(
                "{}: bracket {bracket}, upper end {upper}, {} trials; against the published LEM {:.3} {:+.1} %, \
                 our Bishop {:.4} {:+.1} %",
                slope.scenes[k],
                result.trials.len(),
                slope.lem,
                100.0 * (f / slope.lem - 1.0),
                self.bishop,
                100.0 * (f / self.bishop - 1.0)
            ));
            if let Some(why) = bracket_defect(result) {
                row = row.with_defect(why);
            }
            rows.push(reg::with_mesh_error(row));
        }
        let mut spread = reg::row(&ids[3])
            .value(mesh_spread(&fs), 0.0, self.seconds.iter().sum())
            .with_note(format!("hexahedra, prisms, tetrahedra: {fs:.4?} (references/plastic.md)"));
        if let Some(why) = rows.iter().find_map(|r| r.defect.clone()) {
            spread = spread.with_defect(why);
        }
        rows.push(spread);
        rows
    }
}

/// The rows of the five published slopes beside Griffiths & Lane's, skipped
/// with `reason`.
pub fn published_slopes_skipped(reason: &str) -> Vec<crate::harness::report::Check> {
    heavy_published_slopes().flat_map(|s| published_slope_skipped(s, reason)).collect()
}

/// The four rows of `slope`, skipped with `reason`.
pub fn published_slope_skipped(
    slope: &crate::harness::registry::PublishedSlope,
    reason: &str,
) -> [crate::harness::report::Check; 4] {
    use crate::harness::registry as reg;
    reg::published_slope_ids(slope).map(|id| reg::with_mesh_error(reg::row(&id).skipped(reason)))
}

/// The published slopes that `tests/plastic_slopes.rs` and `cdem reproduce`
/// run together ([`PublishedSlopeRun::run_all`]): all but Griffiths & Lane's,
/// whose rows tests/plasticity.rs computes. (The name is from when they were
/// too heavy for `cargo test`.)
pub fn heavy_published_slopes() -> impl Iterator<Item = &'static crate::harness::registry::PublishedSlope> {
    crate::harness::registry::PUBLISHED_SLOPES.iter().filter(|s| s.key != "gl1")
}
