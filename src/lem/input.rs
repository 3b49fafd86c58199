//! LEM input files (TOML). Unknown keys are rejected; every bad value is a
//! [`SceneError::Invalid`] naming its key. Units: m, Pa, deg, N/m^3.
//!
//! ```toml
//! [section]
//! ground = [[20.0, 25.0], [30.0, 25.0], [50.0, 35.0], [70.0, 35.0]]  # (x, z), x increasing
//! # or: from_mesh = "../slope/slope.msh", ground_group = "ground", y_plane = 0.0
//! z_min = 20.0                  # or lower_bound = [[x, z], ...]; from_mesh: lowest node
//! facing = "left"               # optional: "left" (down-slope toward -x) or "right"
//!
//! [[material]]                  # no zone: the whole section (at most one such)
//! cohesion = 3.0e3              # c' (Pa)
//! friction_angle = 19.6         # phi' (deg)
//! unit_weight = 20.0e3          # gamma (N/m^3)
//! # zone = [[x, z], ...]        # a polygon; the first zone containing a point wins
//!
//! [analysis]
//! slices = 50                   # default DEFAULT_SLICES
//! methods = ["ordinary", "bishop", "spencer"]
//!
//! [search]                      # all optional; see SearchSpec for defaults
//! refine = true
//! [search.grid]                 # centres over x-z (default ranges from the slope)
//! nx = 20
//! nz = 20
//! radii = 10
//! [search.entry_exit]
//! n_exit = 20
//! n_entry = 20
//! radii = 10
//!
//! # [circle]                    # instead of a search: one circle
//! # xc = 35.0
//! # zc = 50.0
//! # r = 25.0
//!
//! [water]                       # optional: pore water (module docs of `lem`)
//! surface = [[20.0, 25.0], [70.0, 32.0]]  # phreatic surface z_w(x), x increasing, spanning the ground
//! # ru = 0.25                   # instead of surface: u = r_u sigma_v (Slide's pore-pressure ratio)
//! unit_weight = 9810.0          # gamma_w (N/m^3), default 9810
//! hu = "vertical"               # or "cos2" (with surface only)
//! crack_depth = 3.8             # optional: a tension crack line this deep below the ground (m)
//! crack_fill = 1.0              # its filled fraction, 0 (dry, the default) to 1 (full)
//! crack_zone = [50.0, 70.0]     # optional: the x-range of the crack line (default: the whole ground)
//! ```

use std::path::{Path, PathBuf};

use serde::Deserialize;

use super::section::{Facing, LemSection, LowerBound, Material, Zone};
use super::water::{Pore, TensionCrack, Water};
use super::{Circle, Method, DEFAULT_SLICES};
use crate::error::SceneError;
use crate::physics::water::{Hu, Phreatic, DEFAULT_UNIT_WEIGHT};

/// A validated LEM input.
#[derive(Debug, Clone, PartialEq)]
pub struct LemInput {
    pub section: LemSection,
    /// Slices per circle.
    pub slices: usize,
    pub methods: Vec<Method>,
    pub mode: Mode,
}

/// One given circle, or a search.
#[derive(Debug, Clone, PartialEq)]
pub enum Mode {
    Circle(Circle),
    Search(SearchSpec),
}

/// Search settings; ranges are in the section's own coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchSpec {
    /// Grid of centres x radius increments (`None`: off).
    pub grid: Option<GridSpec>,
    /// Entry-exit circles (`None`: off).
    pub entry_exit: Option<EntryExitSpec>,
    /// Nelder-Mead refinement of each method's best circles. Default true.
    pub refine: bool,
    /// Minimum mean height of the deepest slice (m). Default `0.02 H`.
    pub min_depth: Option<f64>,
    /// Minimum entry-exit width (m). Default `0.1 H`.
    pub min_width: Option<f64>,
    /// Use rayon over the grid (results do not depend on it). Default true.
    pub parallel: bool,
}

impl Default for SearchSpec {
    fn default() -> Self {
        SearchSpec {
            grid: Some(GridSpec::default()),
            entry_exit: Some(EntryExitSpec::default()),
            refine: true,
            min_depth: None,
            min_width: None,
            parallel: true,
        }
    }
}

/// Centres on an `nx x nz` grid over `x` x `z`; at each, `radii` radii
/// evenly from the nearest ground point (exclusive) to the lower bound
/// (inclusive). Default ranges (H the slope height, Wf its face width, toe
/// and crest as in the section): x from the toe - Wf/4 to the crest + Wf/4,
/// z from the toe + H/2 to the crest + max(H, Wf).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridSpec {
    pub x: Option<[f64; 2]>,
    pub z: Option<[f64; 2]>,
    pub nx: usize,
    pub nz: usize,
    pub radii: usize,
}

impl Default for GridSpec {
    fn default() -> Self {
        GridSpec { x: None, z: None, nx: 20, nz: 20, radii: 10 }
    }
}

/// Circles through an exit point (toe side) and an entry point (crest side)
/// on the ground, `radii` per pair: sagitta `k L / 2` below the chord of
/// length `L`, `k = j / radii`, `j = 1..=radii` (k = 1: a half circle).
/// Default ranges: exits from the toe - Wf/4 to the toe + Wf/2, entries from
/// the toe + Wf/2 to the crest + 1.5 Wf (clipped to the ground).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EntryExitSpec {
    pub exit: Option<[f64; 2]>,
    pub entry: Option<[f64; 2]>,
    pub n_exit: usize,
    pub n_entry: usize,
    pub radii: usize,
}

impl Default for EntryExitSpec {
    fn default() -> Self {
        EntryExitSpec { exit: None, entry: None, n_exit: 20, n_entry: 20, radii: 10 }
    }
}

fn twenty() -> usize {
    20
}
fn ten() -> usize {
    10
}
fn yes() -> bool {
    true
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileToml {
    section: SectionToml,
    #[serde(default)]
    material: Vec<MaterialToml>,
    #[serde(default)]
    analysis: AnalysisToml,
    search: Option<SearchToml>,
    circle: Option<Circle>,
    water: Option<WaterToml>,
    /// Read and checked by `cdem ensemble` (the scene's `EnsembleSpec`); the
    /// LEM itself runs the file's own (mean) values.
    #[allow(dead_code)]
    ensemble: Option<toml::Table>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SectionToml {
    ground: Option<Vec<[f64; 2]>>,
    from_mesh: Option<PathBuf>,
    ground_group: Option<String>,
    y_plane: Option<f64>,
    z_min: Option<f64>,
    lower_bound: Option<Vec<[f64; 2]>>,
    facing: Option<Facing>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MaterialToml {
    #[allow(dead_code)]
    name: Option<String>,
    cohesion: f64,
    friction_angle: f64,
    unit_weight: f64,
    zone: Option<Vec<[f64; 2]>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AnalysisToml {
    #[serde(default = "default_slices")]
    slices: usize,
    #[serde(default = "all_methods")]
    methods: Vec<Method>,
}

fn default_slices() -> usize {
    DEFAULT_SLICES
}
fn all_methods() -> Vec<Method> {
    Method::ALL.to_vec()
}

impl Default for AnalysisToml {
    fn default() -> Self {
        AnalysisToml { slices: DEFAULT_SLICES, methods: all_methods() }
    }
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct SearchToml {
    grid: Option<GridToml>,
    entry_exit: Option<EntryExitToml>,
    #[serde(default = "yes")]
    refine: bool,
    min_depth: Option<f64>,
    min_width: Option<f64>,
    #[serde(default = "yes")]
    parallel: bool,
}

/// Component `k` of an optional range `[lo, hi]`.
fn pair(a: &mut Option<[f64; 2]>, k: Option<usize>) -> Option<&mut f64> {
    a.as_mut()?.get_mut(k?)
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct GridToml {
    #[serde(default = "yes")]
    enabled: bool,
    x: Option<[f64; 2]>,
    z: Option<[f64; 2]>,
    #[serde(default = "twenty")]
    nx: usize,
    #[serde(default = "twenty")]
    nz: usize,
    #[serde(default = "ten")]
    radii: usize,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct EntryExitToml {
    #[serde(default = "yes")]
    enabled: bool,
    exit: Option<[f64; 2]>,
    entry: Option<[f64; 2]>,
    #[serde(default = "twenty")]
    n_exit: usize,
    #[serde(default = "twenty")]
    n_entry: usize,
    #[serde(default = "ten")]
    radii: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct WaterToml {
    surface: Option<Vec<[f64; 2]>>,
    ru: Option<f64>,
    #[serde(default = "default_water_unit_weight")]
    unit_weight: f64,
    hu: Option<Hu>,
    crack_depth: Option<f64>,
    crack_fill: Option<f64>,
    crack_zone: Option<[f64; 2]>,
}

fn default_water_unit_weight() -> f64 {
    DEFAULT_UNIT_WEIGHT
}

/// `[water]` of a LEM file (checked against the ground by [`LemSection::with_water`]).
fn water_of(t: WaterToml) -> Result<Water, SceneError> {
    let pore = match (t.surface, t.ru) {
        (Some(_), Some(_)) => {
            return Err(SceneError::invalid("water.ru", "give either water.surface or water.ru, not both"))
        }
        (Some(points), None) => Pore::Surface(Phreatic::new("water", points, t.unit_weight, t.hu.unwrap_or_default())?),
        (None, Some(ru)) => {
            if t.hu.is_some() {
                return Err(SceneError::invalid("water.hu", "only with water.surface (r_u has no surface)"));
            }
            Pore::Ru(ru)
        }
        (None, None) => {
            if t.hu.is_some() {
                return Err(SceneError::invalid("water.hu", "only with water.surface"));
            }
            Pore::Dry
        }
    };
    let crack = match t.crack_depth {
        Some(depth) => Some(TensionCrack { depth, fill: t.crack_fill.unwrap_or(0.0), zone: t.crack_zone }),
        None if t.crack_fill.is_some() || t.crack_zone.is_some() => {
            return Err(SceneError::invalid("water.crack_depth", "missing: water.crack_fill and crack_zone need it"))
        }
        None => None,
    };
    if pore == Pore::Dry && crack.is_none() {
        return Err(SceneError::invalid("water", "gives none of surface, ru, crack_depth"));
    }
    Ok(Water { pore, crack, unit_weight: t.unit_weight })
}

fn check_count(key: &str, n: usize, lo: usize, hi: usize) -> Result<(), SceneError> {
    if n < lo || n > hi {
        return Err(SceneError::invalid(key, format!("must be in [{lo}, {hi}], got {n}")));
    }
    Ok(())
}

fn check_range(key: &str, r: Option<[f64; 2]>) -> Result<(), SceneError> {
    match r {
        Some([a, b]) if !(a.is_finite() && b.is_finite() && a <= b) => {
            Err(SceneError::invalid(key, "must be [low, high], finite, low <= high"))
        }
        _ => Ok(()),
    }
}

fn check_length(key: &str, v: Option<f64>) -> Result<(), SceneError> {
    match v {
        Some(x) if !(x.is_finite() && x >= 0.0) => Err(SceneError::invalid(key, "must be finite and >= 0 (m)")),
        _ => Ok(()),
    }
}

impl LemInput {
    /// Parses and validates LEM TOML text; `base_dir` resolves `from_mesh`.
    pub fn from_toml(text: &str, base_dir: &Path, path_for_errors: &Path) -> crate::Result<Self> {
        let file: FileToml = toml::from_str(text)
            .map_err(|e| SceneError::Syntax { path: path_for_errors.to_path_buf(), message: e.to_string() })?;
        let s = file.section;
        let (ground, mesh_z_min) = match (s.ground, &s.from_mesh) {
            (Some(_), Some(_)) => {
                return Err(SceneError::invalid(
                    "section.from_mesh",
                    "give either section.ground or section.from_mesh, not both",
                )
                .into())
            }
            (None, None) => {
                return Err(
                    SceneError::invalid("section.ground", "missing: give section.ground or section.from_mesh").into()
                )
            }
            (Some(g), None) => {
                if s.ground_group.is_some() || s.y_plane.is_some() {
                    return Err(SceneError::invalid("section.ground_group", "only used with section.from_mesh").into());
                }
                (g, None)
            }
            (None, Some(mesh_path)) => {
                let group = s.ground_group.as_deref().ok_or_else(|| {
                    SceneError::invalid("section.ground_group", "missing: the mesh's ground surface group")
                })?;
                let mesh = crate::mesh::gmsh::read_msh(&base_dir.join(mesh_path))?;
                let (g, z) = LemSection::from_mesh(&mesh, group, s.y_plane)?;
                (g, Some(z))
            }
        };
        let lower = match (s.z_min, s.lower_bound, mesh_z_min) {
            (Some(_), Some(_), _) => {
                return Err(SceneError::invalid(
                    "section.lower_bound",
                    "give either section.z_min or section.lower_bound, not both",
                )
                .into())
            }
            (Some(z), None, _) => LowerBound::Level(z),
            (None, Some(p), _) => LowerBound::Polyline(p),
            (None, None, Some(z)) => LowerBound::Level(z),
            (None, None, None) => {
                return Err(SceneError::invalid(
                    "section.z_min",
                    "missing: the level slip circles may not pass below (or section.lower_bound)",
                )
                .into())
            }
        };
        let mut background = None;
        let mut zones = Vec::new();
        for (i, m) in file.material.into_iter().enumerate() {
            let material =
                Material { cohesion: m.cohesion, friction_angle: m.friction_angle, unit_weight: m.unit_weight };
            // Checked here, where the file's index is known (the section only sees zones).
            super::section::check_material(&format!("material[{i}]"), &material)?;
            match m.zone {
                Some(polygon) => zones.push(Zone { polygon, material }),
                None if background.is_some() => {
                    return Err(SceneError::invalid(
                        format!("material[{i}].zone"),
                        "missing: only one material may fill the whole section",
                    )
                    .into())
                }
                None => background = Some(material),
            }
        }
        let mut section = LemSection::new(ground, lower, background, zones, s.facing)?;
        if let Some(w) = file.water {
            section = section.with_water(water_of(w)?)?;
        }

        let (slices, methods, mode) = analysis_and_mode(file.analysis, file.circle, file.search)?;
        Ok(LemInput { section, slices, methods, mode })
    }

    /// Reads and validates a LEM TOML file.
    pub fn load(path: &Path) -> crate::Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| crate::Error::io(path, e))?;
        Self::from_toml(&text, path.parent().unwrap_or(Path::new(".")), path)
    }
}

/// `[analysis]`, `[circle]` and `[search]`, checked (keys as in a LEM file).
fn analysis_and_mode(
    a: AnalysisToml,
    circle: Option<Circle>,
    search: Option<SearchToml>,
) -> Result<(usize, Vec<Method>, Mode), SceneError> {
    check_count("analysis.slices", a.slices, 3, 10_000)?;
    if a.methods.is_empty() {
        return Err(SceneError::invalid("analysis.methods", "must name at least one method"));
    }
    let mut methods: Vec<Method> = Method::ALL.into_iter().filter(|m| a.methods.contains(m)).collect();
    methods.dedup();
    let mode = match (circle, search) {
        (Some(_), Some(_)) => return Err(SceneError::invalid("circle", "give either [circle] or [search], not both")),
        (Some(c), None) => {
            if !(c.xc.is_finite() && c.zc.is_finite() && c.r.is_finite() && c.r > 0.0) {
                return Err(SceneError::invalid("circle", "xc, zc must be finite and r > 0"));
            }
            Mode::Circle(c)
        }
        (None, search) => Mode::Search(search_spec(search)?),
    };
    Ok((a.slices, methods, mode))
}

fn search_spec(t: Option<SearchToml>) -> Result<SearchSpec, SceneError> {
    let Some(t) = t else { return Ok(SearchSpec::default()) };
    let grid = match t.grid {
        None => Some(GridSpec::default()),
        Some(g) if !g.enabled => None,
        Some(g) => {
            let s = GridSpec { x: g.x, z: g.z, nx: g.nx, nz: g.nz, radii: g.radii };
            check_range("search.grid.x", s.x)?;
            check_range("search.grid.z", s.z)?;
            check_count("search.grid.nx", s.nx, 1, 1000)?;
            check_count("search.grid.nz", s.nz, 1, 1000)?;
            check_count("search.grid.radii", s.radii, 1, 1000)?;
            Some(s)
        }
    };
    let entry_exit = match t.entry_exit {
        None => Some(EntryExitSpec::default()),
        Some(e) if !e.enabled => None,
        Some(e) => {
            let s =
                EntryExitSpec { exit: e.exit, entry: e.entry, n_exit: e.n_exit, n_entry: e.n_entry, radii: e.radii };
            check_range("search.entry_exit.exit", s.exit)?;
            check_range("search.entry_exit.entry", s.entry)?;
            check_count("search.entry_exit.n_exit", s.n_exit, 1, 1000)?;
            check_count("search.entry_exit.n_entry", s.n_entry, 1, 1000)?;
            check_count("search.entry_exit.radii", s.radii, 1, 1000)?;
            Some(s)
        }
    };
    if grid.is_none() && entry_exit.is_none() {
        return Err(SceneError::invalid("search", "both search.grid and search.entry_exit are disabled"));
    }
    check_length("search.min_depth", t.min_depth)?;
    check_length("search.min_width", t.min_width)?;
    Ok(SearchSpec {
        grid,
        entry_exit,
        refine: t.refine,
        min_depth: t.min_depth,
        min_width: t.min_width,
        parallel: t.parallel,
    })
}

/// Scene table `[lem]`: the limit-equilibrium analysis of a CDEM scene's own
/// mesh, so that `cdem lem SCENE.toml` needs no second input file.
///
/// ```toml
/// [lem]
/// ground_group = "ground"    # optional: the mesh's ground surface group (default: the section's top)
/// y_plane = 0.0              # optional: the section plane, an outer face of the mesh (default: lowest y)
/// z_min = 0.0                # optional: no slip circle below (default: the lowest node; the toe's level is allowed)
/// facing = "left"            # optional: detected from the ground's ends
/// slices = 50                # optional (default DEFAULT_SLICES)
/// methods = ["bishop"]       # optional (default all)
/// [[lem.material]]           # one per volume group met by the section
/// group = "rock"
/// cohesion = 16.0e3          # c' (Pa)
/// friction_angle = 18.0      # phi' (deg)
/// unit_weight = 20.6e3       # optional: default the group's density x |gravity|
/// # [lem.circle] xc, zc, r   # one circle instead of a search
/// # [lem.search] ...         # as [search] of a LEM file
/// ```
///
/// The zones are the volume groups' outlines on the section plane
/// ([`super::section::cut_mesh`]); one group, or groups of one
/// strength, make a homogeneous section.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneLem {
    ground_group: Option<String>,
    y_plane: Option<f64>,
    z_min: Option<f64>,
    facing: Option<Facing>,
    #[serde(default = "default_slices")]
    slices: usize,
    #[serde(default = "all_methods")]
    methods: Vec<Method>,
    #[serde(default)]
    material: Vec<SceneLemMaterial>,
    search: Option<SearchToml>,
    circle: Option<Circle>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneLemMaterial {
    group: String,
    cohesion: f64,
    friction_angle: f64,
    unit_weight: Option<f64>,
}

impl SceneLem {
    /// The real number that a key path under `[lem]` names, as path segments
    /// (`material[0].cohesion` is `[("material", Some(0)), ("cohesion", None)]`):
    /// what an ensemble draws. None for a key that names no real number the
    /// table gives (an integer setting, an absent optional value).
    pub fn number_mut(&mut self, path: &[(&str, Option<usize>)]) -> Option<&mut f64> {
        match path {
            [("y_plane", None)] => self.y_plane.as_mut(),
            [("z_min", None)] => self.z_min.as_mut(),
            [("material", Some(i)), (f, None)] => self.material.get_mut(*i).and_then(|m| match *f {
                "cohesion" => Some(&mut m.cohesion),
                "friction_angle" => Some(&mut m.friction_angle),
                "unit_weight" => m.unit_weight.as_mut(),
                _ => None,
            }),
            [("circle", None), (f, None)] => self.circle.as_mut().and_then(|c| match *f {
                "xc" => Some(&mut c.xc),
                "zc" => Some(&mut c.zc),
                "r" => Some(&mut c.r),
                _ => None,
            }),
            [("search", None), rest @ ..] => {
                let search = self.search.as_mut()?;
                match rest {
                    [("min_depth", None)] => search.min_depth.as_mut(),
                    [("min_width", None)] => search.min_width.as_mut(),
                    [("grid", None), (f, k)] => search.grid.as_mut().and_then(|g| match *f {
                        "x" => pair(&mut g.x, *k),
                        "z" => pair(&mut g.z, *k),
                        _ => None,
                    }),
                    [("entry_exit", None), (f, k)] => search.entry_exit.as_mut().and_then(|e| match *f {
                        "exit" => pair(&mut e.exit, *k),
                        "entry" => pair(&mut e.entry, *k),
                        _ => None,
                    }),
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// The `(cohesion (Pa), friction angle (deg))` of a volume group's
    /// `[[lem.material]]`, if it has one.
    pub fn strength_of(&self, group: &str) -> Option<(f64, f64)> {
        self.material.iter().find(|m| m.group == group).map(|m| (m.cohesion, m.friction_angle))
    }
}

/// A LEM file's key as it is spelled inside a scene's `[lem]` table.
fn in_scene(e: SceneError) -> SceneError {
    match e {
        SceneError::Invalid { key, reason } => {
            let key = key.strip_prefix("analysis.").unwrap_or(&key);
            let key = key.strip_prefix("section.").unwrap_or(key);
            SceneError::Invalid { key: format!("lem.{key}"), reason }
        }
        other => other,
    }
}

impl LemInput {
    /// The LEM of a scene's mesh: `lem` is the scene's `[lem]` table,
    /// `unit_weight_of(group)` the weight per volume (N/m^3) of a volume
    /// group from the scene's own materials and gravity, if it has one, and
    /// `water` the scene's phreatic surface (`[water]`, raised), if any.
    pub fn from_scene(
        lem: &SceneLem,
        mesh: &crate::mesh::Mesh,
        unit_weight_of: &dyn Fn(&str) -> Option<f64>,
        water: Option<&Phreatic>,
    ) -> crate::Result<Self> {
        let y_plane = lem.y_plane.unwrap_or_else(|| mesh.nodes.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min));
        let cut = super::section::cut_mesh(mesh, y_plane)?;
        let (ground, mesh_z_min) = match &lem.ground_group {
            Some(group) => LemSection::from_mesh(mesh, group, Some(y_plane)).map_err(in_scene)?,
            None => (cut.ground()?, mesh.nodes.iter().map(|p| p[2]).fold(f64::INFINITY, f64::min)),
        };
        let lower = LowerBound::Level(lem.z_min.unwrap_or(mesh_z_min));
        let outlines = cut.zones;
        let mut materials = Vec::with_capacity(outlines.len());
        for (group, loops) in &outlines {
            let Some(i) = lem.material.iter().position(|m| &m.group == group) else {
                let given: Vec<&str> = lem.material.iter().map(|m| m.group.as_str()).collect();
                return Err(SceneError::invalid(
                    "lem.material",
                    format!("volume group {group:?} meets the section but has no [[lem.material]] (given: {given:?})"),
                )
                .into());
            };
            let m = &lem.material[i];
            let unit_weight = match m.unit_weight.or_else(|| unit_weight_of(group)) {
                Some(w) => w,
                None => {
                    return Err(SceneError::invalid(
                        format!("lem.material[{i}].unit_weight"),
                        format!("missing, and volume group {group:?} has no [[material]] density to take it from"),
                    )
                    .into())
                }
            };
            let material = Material { cohesion: m.cohesion, friction_angle: m.friction_angle, unit_weight };
            super::section::check_material(&format!("lem.material[{i}]"), &material)?;
            materials.push((material, loops));
        }
        for (i, m) in lem.material.iter().enumerate() {
            if !outlines.iter().any(|(g, _)| g == &m.group) {
                let groups: Vec<&str> = outlines.iter().map(|(g, _)| g.as_str()).collect();
                return Err(SceneError::invalid(
                    format!("lem.material[{i}].group"),
                    format!("{:?} is not a volume group met by the section (those are: {groups:?})", m.group),
                )
                .into());
            }
        }
        let homogeneous = materials.windows(2).all(|w| w[0].0 == w[1].0);
        let (background, zones) = if homogeneous {
            (Some(materials[0].0), Vec::new())
        } else {
            let mut zones: Vec<Zone> = materials
                .iter()
                .flat_map(|(m, loops)| loops.iter().map(|p| Zone { polygon: p.clone(), material: *m }))
                .collect();
            // Smaller first: a zone inside another's hole wins there.
            zones.sort_by(|a, b| {
                super::section::signed_area(&a.polygon).total_cmp(&super::section::signed_area(&b.polygon))
            });
            (None, zones)
        };
        let mut section = LemSection::new(ground, lower, background, zones, lem.facing).map_err(in_scene)?;
        if let Some(p) = water {
            let water = Water { pore: Pore::Surface(p.clone()), crack: None, unit_weight: p.unit_weight };
            section = section.with_water(water)?;
        }
        let analysis = AnalysisToml { slices: lem.slices, methods: lem.methods.clone() };
        let (slices, methods, mode) = analysis_and_mode(analysis, lem.circle, lem.search.clone()).map_err(in_scene)?;
        Ok(LemInput { section, slices, methods, mode })
    }
}
