//! # Limit equilibrium (2D): circular slip surfaces, methods of slices
//!
//! A 2D section (x horizontal, z up, SI units: m, Pa, N/m^3, forces per
//! metre run) is cut by a trial circle `(xc, zc, r)`. Only the lower arc
//! `z = zc - sqrt(r^2 - (x - xc)^2)` is a slip surface: the part of it under
//! the ground between two crossings of the ground polyline, the *exit* on the
//! toe side and the *entry* on the crest side. Where the arc cuts the ground
//! more than twice (a toe circle of a steep slope whose continuation
//! re-enters the level ground in front of the toe), the sliding mass is the
//! crest-side run of the arc under the ground, and the rest of the arc is not
//! part of it. The sliding mass is divided into `n`
//! vertical slices of equal width `b` (default [`DEFAULT_SLICES`] = 50); on
//! a layered section the slices end where the arc changes material, each
//! run between such ends cut into equal slices (`geometry::layered_ends`).
//!
//! Per slice `i` (math names): weight `W` (exact area between the ground and
//! the arc times `gamma` for a homogeneous section; the column at the slice's
//! centre line times `b` when material zones are given), base inclination
//! `alpha` (the arc's inclination at the mid-angle of the slice, positive
//! where the base descends in the direction of sliding), exact arc length `l`,
//! and the strength `c`, `tan(phi)` of the material at the middle of the base.
//!
//! **Pore water** (`water.rs`, a file's `[water]`; effective stress, `c`
//! and `phi` are `c'` and `phi'`): the pore pressure `u` at the middle of each
//! base, from a phreatic surface (`u = gamma_w h H_u`, `h` the vertical
//! distance up to it, [`crate::physics::water::Phreatic`]) or from Slide's
//! pore-pressure ratio (`u = r_u W / b`, the slice's vertical overburden
//! stress). A **tension crack** (Slide's crack line `d` below the ground):
//! a circle that crosses the crack line ends there (its crest-most crossing),
//! closed by a vertical crack to the ground filled to `h_w = fill d`, whose
//! water pushes the mass toward the toe with `H = gamma_w h_w^2 / 2` at
//! `z_H = z_crack bottom + h_w / 3`: a driving moment `H (zc - z_H)` about the
//! centre. Dry: `u = 0`, `H = 0`.
//!
//! **Ordinary (Fellenius)**, moment equilibrium about the centre, interslice
//! forces ignored (negative effective normal forces are not clipped, as in
//! Fredlund & Krahn 1977):
//! `FS = sum(c l + (W cos(alpha) - u l) tan(phi)) / (sum(W sin(alpha)) + H (zc - z_H) / r)`.
//!
//! **Bishop simplified**, moment equilibrium with horizontal interslice forces:
//! `FS = sum[(c b + (W - u b) tan(phi)) / m_alpha] / (sum(W sin(alpha)) + H (zc - z_H) / r)`,
//! `m_alpha = cos(alpha) + sin(alpha) tan(phi) / FS`, with `b = l cos(alpha)`;
//! Halley's method (Newton with the second derivative) on
//! `FS sum(W sin(alpha)) - sum[...] = 0` from the ordinary
//! FS (a fixed-point step where that step is unusable) until the update
//! `|dFS| <= 1e-10 FS` (tighter than the customary 1e-6 because the search's
//! refinement compares neighbouring circles). A circle with any
//! `m_alpha <= 0` has no Bishop FS.
//!
//! **Spencer (1967)**, force and moment equilibrium with parallel interslice
//! resultants `Q` inclined at a constant `theta`:
//! `Q = (R / FS - D) / m`, `R = c l + (W cos(alpha) - H sin(alpha) - u l) tan(phi)`,
//! `D = W sin(alpha) + H cos(alpha)` (`H` on the crest-side slice only),
//! `m = cos(alpha - theta) + sin(alpha - theta) tan(phi) / FS`;
//! force equilibrium `sum Q = 0`, moment equilibrium about the centre
//! `r sum Q cos(alpha - theta) = H ((zc - z_H) - r cos(alpha_n))` (`H` acts at
//! `z_H`, not at the base of its slice). Solved for `(FS, theta)` by a damped 2D
//! Newton iteration from `(FS_Bishop, 0)` (at `theta = 0` the moment equation
//! is Bishop's), with a bracketing fallback on `theta` if Newton fails.
//!
//! **Search** (`search.rs`): a grid of centres times radius increments, and
//! entry-exit circles through pairs of ground points, each method's best
//! circle then refined by Nelder-Mead on `(xc, zc, r)`. Each method is
//! minimised on its own: `fs.<method>` is that method's own minimum and
//! `critical.<method>` its circle; `on_bishop_critical` gives all three
//! methods on the Bishop critical circle. See `search.rs` for the admissibility
//! rules (a closed sliding mass, lower bound, minimum depth and width, direction).
//!
//! Sections facing either way are supported: a section facing +x is mirrored
//! internally (x -> -x) and results are mirrored back.

mod geometry;
mod input;
mod methods;
mod search;
mod section;
mod water;

use std::time::Instant;

use serde::Serialize;

use crate::error::SceneError;

pub use geometry::{slices_of, Reject, SliceInfo};
pub use input::{EntryExitSpec, GridSpec, LemInput, Mode, SceneLem, SearchSpec};
pub use methods::{evaluate_circle, CircleFs};
pub use section::{cut_mesh, Facing, LemSection, LowerBound, Material, SectionCut, Zone};
pub use water::{Pore, TensionCrack, Water, WaterModel};

/// Default number of slices. On a circle near the ACADS 1(a) critical one,
/// every method's FS at 50 slices is within 1e-4 of its value at 400, and the
/// error falls at second order (`tests/lem.rs`, `fs_converges_with_slice_count`).
pub const DEFAULT_SLICES: usize = 50;

/// A trial circle (m), in the section's own coordinates: the crate's one
/// circle type, re-exported as the circle of `lem`'s API.
pub use crate::geometry::Circle;

/// The three methods of slices.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    Ordinary,
    Bishop,
    Spencer,
}

impl Method {
    pub const ALL: [Method; 3] = [Method::Ordinary, Method::Bishop, Method::Spencer];

    pub fn name(self) -> &'static str {
        match self {
            Method::Ordinary => "ordinary",
            Method::Bishop => "bishop",
            Method::Spencer => "spencer",
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// One value per method (`None`: not requested, or no admissible solution).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PerMethod<T> {
    pub ordinary: Option<T>,
    pub bishop: Option<T>,
    pub spencer: Option<T>,
}

impl<T> Default for PerMethod<T> {
    fn default() -> Self {
        PerMethod { ordinary: None, bishop: None, spencer: None }
    }
}

impl<T> PerMethod<T> {
    pub fn get(&self, m: Method) -> Option<&T> {
        match m {
            Method::Ordinary => self.ordinary.as_ref(),
            Method::Bishop => self.bishop.as_ref(),
            Method::Spencer => self.spencer.as_ref(),
        }
    }

    fn set(&mut self, m: Method, v: Option<T>) {
        match m {
            Method::Ordinary => self.ordinary = v,
            Method::Bishop => self.bishop = v,
            Method::Spencer => self.spencer = v,
        }
    }
}

/// A method's critical circle, with where it meets the ground.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CriticalCircle {
    /// The circle; its `xc`, `zc`, `r` are keys of this table in the JSON.
    #[serde(flatten)]
    pub circle: Circle,
    /// Crest-side intersection with the ground `[x, z]`.
    pub entry: [f64; 2],
    /// Toe-side intersection with the ground `[x, z]`.
    pub exit: [f64; 2],
    pub fs: f64,
    /// Spencer only: interslice force inclination (deg), positive when the
    /// resultant rises toward the crest.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theta_deg: Option<f64>,
}

/// The result of [`analyse`]; serialised as the JSON `cdem lem` writes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LemResult {
    /// Each method's minimum FS (its own critical circle).
    pub fs: PerMethod<f64>,
    pub critical: PerMethod<CriticalCircle>,
    /// All methods evaluated on the Bishop critical circle.
    pub on_bishop_critical: PerMethod<f64>,
    /// Admissible circles whose FS was computed (grid, entry-exit, refinement).
    pub circles_evaluated: usize,
    /// Trial circles rejected as inadmissible.
    pub circles_rejected: usize,
    pub slices: usize,
    /// The water model that ran (`pore`: "dry", "surface" or "ru"; the crack).
    pub water: WaterModel,
    pub wall_s: f64,
}

/// Runs the analysis an input asks for: one circle or a search.
pub fn analyse(input: &LemInput) -> Result<LemResult, crate::Error> {
    let t0 = Instant::now();
    let mut result = match &input.mode {
        Mode::Circle(c) => single_circle(input, *c)?,
        Mode::Search(spec) => search::run(input, spec)?,
    };
    result.wall_s = t0.elapsed().as_secs_f64();
    Ok(result)
}

fn single_circle(input: &LemInput, circle: Circle) -> Result<LemResult, crate::Error> {
    let fs = methods::evaluate_circle(&input.section, circle, input.slices)
        .map_err(|e| SceneError::invalid("circle", format!("not an admissible slip circle: {e}")))?;
    let mut result = LemResult {
        fs: PerMethod::default(),
        critical: PerMethod::default(),
        on_bishop_critical: PerMethod::default(),
        circles_evaluated: 1,
        circles_rejected: 0,
        slices: input.slices,
        water: input.section.water().model(),
        wall_s: 0.0,
    };
    for m in input.methods.iter().copied() {
        let v = fs.get(m);
        result.fs.set(m, v);
        result.on_bishop_critical.set(m, v);
        result.critical.set(
            m,
            v.map(|f| CriticalCircle {
                circle,
                entry: fs.entry,
                exit: fs.exit,
                fs: f,
                theta_deg: if m == Method::Spencer { fs.spencer_theta_deg } else { None },
            }),
        );
    }
    Ok(result)
}

/// A short human-readable table of a result.
pub fn table(result: &LemResult) -> String {
    let mut s = format!(
        "{:<9} {:>7} {:>9} {:>9} {:>8}  {:>17}  {:>17}\n",
        "method", "FS", "xc", "zc", "r", "exit (x, z)", "entry (x, z)"
    );
    for m in Method::ALL {
        if let Some(c) = result.critical.get(m) {
            s += &format!(
                "{:<9} {:>7.4} {:>9.3} {:>9.3} {:>8.3}  ({:>7.3},{:>7.3})  ({:>7.3},{:>7.3})\n",
                m.name(),
                c.fs,
                c.circle.xc,
                c.circle.zc,
                c.circle.r,
                c.exit[0],
                c.exit[1],
                c.entry[0],
                c.entry[1]
            );
        }
    }
    s += &format!("water: {}\n", result.water.describe());
    s += &format!(
        "{} circles evaluated, {} rejected, {} slices, {:.3} s\n",
        result.circles_evaluated, result.circles_rejected, result.slices, result.wall_s
    );
    s
}
