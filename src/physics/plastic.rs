//! The plastic block: eq. 12 for an element whose material yields
//! (Mohr-Coulomb, [`super::mohr_coulomb`]), integrated per tetrahedron of
//! its decomposition with a history per tetrahedron.
//!
//! # The two traps, and how this element avoids them
//!
//! 1. **Internal points.** A cell's face and body centroids are not
//!    independent nodes eliminated by static condensation: they are fixed
//!    averages of the corners, `u_p = T u_c` ([`super::tet_operator`]). That
//!    stays exact when tetrahedra yield, so the plastic element has the same
//!    kinematics as the condensed elastic one and nothing is re-condensed.
//! 2. **Volumetric locking.** Constant-strain tetrahedra lock under
//!    isochoric plastic flow (Nagtegaal, Parks & Rice 1974) and overestimate
//!    collapse loads. As FLAC's mixed discretization does over the
//!    tetrahedra of a zone, each tetrahedron's volumetric strain is replaced
//!    by the volume average over its cell's tetrahedra (a B-bar element):
//!
//!    `eps_t' = dev(eps_t) + (e / 3) I`,  `e = sum_t V_t tr(eps_t) / V`.
//!
//!    Its nodal forces are the virtual work of that strain,
//!
//!    `f_c = (T^T sum_t V_t dev(sigma_t) grad N_t)_c + (sum_t V_t p_t) g_c`,
//!
//!    with `p_t = tr(sigma_t) / 3` and `g_c` the cell's volume-averaged
//!    corner gradient (the gradient of `e`). Elastic, it is the stiffness
//!    [`mixed_stiffness`](super::element::mixed_stiffness) that phase 1 uses for the same elements, so the
//!    elastic state is the plastic element's own. A single tetrahedron (a
//!    `Tet4` cell) has nothing to average with and keeps its own strain.
//!    Prisms and tetrahedra average over their mesh vertices instead
//!    ([`Volumetric::Nodal`]), and their deviatoric strain, nearly one
//!    constant per cell and too stiff on unstructured meshes, is blended
//!    with a node-smoothed one ([`Volumetric::Smoothed`], [`NODE_SMOOTHING`]).
//!
//! Per tetrahedron the state is the plastic strain and the yield flag:
//! `sigma_t = D (eps_t' - eps_t^p)`, returned by the Mohr-Coulomb return
//! mapping each step, `eps_t^p += D^-1 (sigma_trial - sigma_t)`.

use super::elasticity::Lame;
use super::mohr_coulomb::{
    compliance, lanes_of, principal_lanes, six, CommonReturns, Lanes, MohrCoulomb, RockStrength, Yield,
};
use super::tet_operator::{corner_forces, point_displacements, scaled_gradients, TetTopology};
use crate::mesh::shape::{CellKind, MAX_POINTS};

/// The default weight `alpha` of the node-smoothed deviatoric strain of
/// plastic prisms and tetrahedra (`[failure] smoothing`,
/// [`Volumetric::Smoothed`]): 0.6, the value Nguyen-Thoi & Nguyen-Xuan
/// (2010) recommend for plane problems in the alpha-FEM of Liu, Nguyen-Thoi
/// & Lam (2008), which blends the over-stiff compatible strain (0) with the
/// over-soft node-smoothed one (1). Our smoothed strain is not theirs (it is
/// the average over a cell's vertices of the vertex averages), so the value
/// was checked, not fitted, on elastic compliance: references/plastic.md.
pub const NODE_SMOOTHING: f64 = 0.6;

/// Most sub-tetrahedra of a cell (a hexahedron's 24).
pub use crate::mesh::shape::MAX_TETS;

/// The history of one tetrahedron.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct TetPlastic {
    /// Plastic strain (Voigt xx yy zz yz xz xy, engineering shear).
    pub eps_p: [f64; 6],
    /// What the return mapping did at the last step.
    pub now: Yield,
    /// Whether it has ever yielded (in shear or tension).
    pub ever: bool,
    /// Whether it has ever yielded in tension (FLAC's `tension-p`; `ever`
    /// without it: shear only).
    pub ever_tension: bool,
}

/// The history of one cell's tetrahedra (the front `n_tets` are used).
pub type CellHistory = [TetPlastic; MAX_TETS];

/// Per-tetrahedron operator of a plastic cell: `b_k = sqrt(V_t) grad N_k`
/// of vertices 0-2 (as [`super::tet_operator`]) and `sqrt(V_t)`.
#[derive(Debug, Clone, Copy)]
pub struct TetB {
    pub b: [f64; 9],
    pub sqrt_v: f64,
}

/// The operators of a cell's tetrahedra, in [`TetTopology::tets`] order.
pub fn plastic_operator(kind: CellKind, corners: &[[f64; 3]]) -> Vec<TetB> {
    scaled_gradients(kind, corners).map(|(b, sqrt_v)| TetB { b, sqrt_v }).collect()
}

/// Each tetrahedron's strain (Voigt, engineering shear) from the point
/// displacements `d`, and the cell's volume-averaged volumetric strain `e`.
fn tet_strains(topo: &TetTopology, tets: &[TetB], d: &[[f64; 3]; MAX_POINTS]) -> ([[f64; 6]; MAX_TETS], f64) {
    let mut eps = [[0.0; 6]; MAX_TETS];
    let e = tet_strains_into(topo, tets, d, &mut eps);
    (eps, e)
}

/// [`tet_strains`] into `eps` (the element pass's buffer: no copy of the
/// array on return); returns `e`.
#[inline(always)]
fn tet_strains_into(
    topo: &TetTopology,
    tets: &[TetB],
    d: &[[f64; 3]; MAX_POINTS],
    eps: &mut [[f64; 6]; MAX_TETS],
) -> f64 {
    let (mut ve, mut v) = (0.0, 0.0);
    for ((t, op), e) in topo.tets.iter().zip(tets).zip(eps.iter_mut()) {
        let mut h = [[0.0; 3]; 3]; // sqrt(V_t) du_i/dx_j
        for (k, &p) in t.iter().enumerate() {
            let dp = d[p as usize];
            for i in 0..3 {
                for j in 0..3 {
                    h[i][j] += dp[i] * op.b[3 * k + j];
                }
            }
        }
        let w = 1.0 / op.sqrt_v;
        let g = [h[0][0], h[1][1], h[2][2], h[1][2] + h[2][1], h[0][2] + h[2][0], h[0][1] + h[1][0]];
        *e = six(|i| w * g[i]);
        let vt = op.sqrt_v * op.sqrt_v;
        ve += vt * (e[0] + e[1] + e[2]);
        v += vt;
    }
    ve / v
}

/// The mixed strain `dev(eps) + (e / 3) I`.
fn mixed(eps: [f64; 6], e: f64) -> [f64; 6] {
    let shift = (e - (eps[0] + eps[1] + eps[2])) / 3.0;
    [eps[0] + shift, eps[1] + shift, eps[2] + shift, eps[3], eps[4], eps[5]]
}

/// Which volumetric strain a plastic cell's tetrahedra share.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Volumetric {
    /// The cell's own volume average (a hexahedron: its 24 tetrahedra,
    /// one pressure per cell as Q1/P0), and its pressure force applied here.
    Cell,
    /// This value, the average over the cell's mesh vertices of their
    /// cells' volumetric strains (prisms and tetrahedra, whose one pressure
    /// per cell still locks: P1/P0); the caller applies the pressure force
    /// ([`add_pressure_force`]) from the vertices' mean pressures.
    Nodal(f64),
    /// As `Nodal`, and the deviatoric strain smoothed too: each
    /// tetrahedron's deviatoric strain is shifted by
    /// `alpha (d - dev(eps_cell))`, `d` the average over the cell's
    /// vertices of their cells' mean deviatoric strains and `eps_cell` the
    /// cell's own volume-averaged strain (a blend of the cell's strain and a
    /// node-based smoothed one, Liu et al.'s alpha-FEM). The caller applies
    /// the pressure and smoothing forces ([`add_stress_force`]).
    Smoothed(Smoothing),
}

/// The vertex-averaged strains a [`Volumetric::Smoothed`] cell uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Smoothing {
    /// The averaged volumetric strain.
    pub volumetric: f64,
    /// The averaged deviatoric strain (Voigt, engineering shear).
    pub deviatoric: [f64; 6],
    /// The weight of the smoothed deviatoric strain, 0 to 1.
    pub alpha: f64,
}

impl Volumetric {
    /// The mode of a nodally averaged cell: [`Volumetric::Nodal`] with the
    /// vertex-averaged volumetric strain `volumetric`, or with `alpha > 0`
    /// [`Volumetric::Smoothed`] with the vertex-averaged `deviatoric` too.
    pub fn at_vertices(volumetric: f64, deviatoric: [f64; 6], alpha: f64) -> Self {
        match alpha > 0.0 {
            true => Volumetric::Smoothed(Smoothing { volumetric, deviatoric, alpha }),
            false => Volumetric::Nodal(volumetric),
        }
    }

    /// The volumetric strain the tetrahedra share, given the cell's own.
    fn value(self, own: f64) -> f64 {
        match self {
            Volumetric::Cell => own,
            Volumetric::Nodal(e) => e,
            Volumetric::Smoothed(s) => s.volumetric,
        }
    }

    /// The deviatoric shift `alpha (d - dev(eps_cell))` given the cell's own
    /// mean strain (None unless smoothed).
    fn shift(self, tets: &[TetB], eps: &[[f64; 6]; MAX_TETS]) -> Option<[f64; 6]> {
        match self {
            Volumetric::Smoothed(s) if s.alpha > 0.0 => {
                let own = deviatoric(mean_strain(tets, eps));
                Some(six(|i| s.alpha * (s.deviatoric[i] - own[i])))
            }
            _ => None,
        }
    }
}

/// What one plastic cell's step gives the nodal average: the volumetric
/// strain its tetrahedra used and their volume-averaged mean stress (Pa).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellStep {
    pub volumetric: f64,
    pub pressure: f64,
    /// A smoothed cell's `alpha dev(sigma_cell)` (Pa, Voigt), the
    /// volume-averaged deviatoric stress its vertices average; zero otherwise.
    pub deviatoric: [f64; 6],
    /// Its screen's radius ([`screen_radius`], m) when the pass was given
    /// the sensitivities and left every tetrahedron elastic; 0 otherwise.
    pub radius: f64,
}

/// The deviatoric part of a Voigt strain or stress.
pub fn deviatoric(x: [f64; 6]) -> [f64; 6] {
    let m = (x[0] + x[1] + x[2]) / 3.0;
    [x[0] - m, x[1] - m, x[2] - m, x[3], x[4], x[5]]
}

/// A cell's volume-averaged volumetric strain (as
/// [`cell_volumetric_strain`]) and volume-averaged strain (Voigt,
/// engineering shear), from one evaluation of its tetrahedra's strains.
pub fn cell_strains(topo: &TetTopology, tets: &[TetB], nodes: &[u32], u: &[f64]) -> (f64, [f64; 6]) {
    let (eps, e) = tet_strains(topo, tets, &point_displacements(topo, nodes, u));
    (e, mean_strain(tets, &eps))
}

fn mean_strain(tets: &[TetB], eps: &[[f64; 6]; MAX_TETS]) -> [f64; 6] {
    let (mut m, mut v) = ([0.0; 6], 0.0);
    for (op, e) in tets.iter().zip(eps) {
        let vt = op.sqrt_v * op.sqrt_v;
        for i in 0..6 {
            m[i] += vt * e[i];
        }
        v += vt;
    }
    m.map(|x| x / v)
}

/// Adds `V S g_c` to the corner forces `f_e`: `S` a stress (Pa, Voigt) the
/// cell carries through its volume-averaged strain, `volume` its volume,
/// `g_c` its volume-averaged corner gradients (the virtual work of
/// `V S : eps_cell`).
pub fn add_stress_force(grad: &[[f64; 3]], volume: f64, s: [f64; 6], f_e: &mut [f64]) {
    let t = [[s[0], s[5], s[4]], [s[5], s[1], s[3]], [s[4], s[3], s[2]]];
    for (fc, g) in f_e.chunks_exact_mut(3).zip(grad) {
        for i in 0..3 {
            fc[i] += volume * (t[i][0] * g[0] + t[i][1] * g[1] + t[i][2] * g[2]);
        }
    }
}

/// The volume-averaged volumetric strain of a cell, `sum_t V_t tr(eps_t) / V`.
pub fn cell_volumetric_strain(topo: &TetTopology, tets: &[TetB], nodes: &[u32], u: &[f64]) -> f64 {
    tet_strains(topo, tets, &point_displacements(topo, nodes, u)).1
}

/// Adds a cell's pressure force `P g_c` to its corner forces `f_e`: `P` is
/// the cell's volume times the mean stress it carries (N m), `g_c` its
/// volume-averaged corner gradients (1/m).
pub fn add_pressure_force(grad: &[[f64; 3]], pressure: f64, f_e: &mut [f64]) {
    for (fc, g) in f_e.chunks_exact_mut(3).zip(grad) {
        for i in 0..3 {
            fc[i] += pressure * g[i];
        }
    }
}

/// Eq. 12 for a plastic cell: writes its corner forces `f_e` (`3n` values)
/// and advances the history `hist` of its tetrahedra by one return mapping
/// each (see the module documentation). `grad` are the cell's
/// volume-averaged corner gradients, `volume` its volume. With
/// [`Volumetric::Nodal`] the pressure force is left to the caller.
/// `pore` is the pore pressure `u` of the cell (Pa, compression positive;
/// 0 when dry): the stress is total, and the cell yields on the effective
/// stress `sigma' = sigma + u I` (Terzaghi; tension positive).
/// `sensitivity` are the tetrahedra's `G_t` ([`stress_sensitivity`]) of a
/// cell with a [`Screen`], empty for none: if every tetrahedron is elastic
/// after the pass, [`CellStep::radius`] is then the screen's radius from
/// the stresses the pass already has (what [`screen_radius`] computes anew).
///
/// Runs with AVX2 where the CPU has it ([`crate::simd`]; the same bits).
#[allow(clippy::too_many_arguments)]
pub fn plastic_element_force(
    topo: &TetTopology,
    tets: &[TetB],
    grad: &[[f64; 3]],
    lame: Lame,
    surface: &MohrCoulomb,
    nodes: &[u32],
    u: &[f64],
    volumetric: Volumetric,
    pore: f64,
    sensitivity: &[f64],
    hist: &mut [TetPlastic],
    f_e: &mut [f64],
) -> CellStep {
    crate::simd::avx2!({
        let d = point_displacements(topo, nodes, u);
        let mut eps = [[0.0; 6]; MAX_TETS];
        let own = tet_strains_into(topo, tets, &d, &mut eps);
        let e = volumetric.value(own);
        let shift = volumetric.shift(tets, &eps);
        let mut f = [[0.0; 3]; MAX_POINTS];
        let (mut pressure, mut volume) = (0.0, 0.0); // sum_t V_t p_t, sum_t V_t
        let mut dev = [0.0; 6]; // sum_t V_t dev(sigma_t)

        // The trial stresses first, then the principal values of their effective
        // parts (the pore pressure added) all at once (vectorized), then the
        // returns.
        let n = tets.len();
        let mut trials = [[0.0; 6]; MAX_TETS];
        for ((eps, h), trial) in eps[..n].iter().zip(hist.iter()).zip(trials.iter_mut()) {
            let strain = shifted(mixed(*eps, e), shift);
            *trial = lame.stress_voigt(six(|i| strain[i] - h.eps_p[i]));
        }
        let mut effective = trials;
        if pore != 0.0 {
            effective[..n].iter_mut().for_each(|t| *t = shift_normal(*t, pore));
        }
        let lanes = lanes_of(&effective, n);
        // A hexahedron's 24 lanes as a constant: whole vectors, no remainder.
        let values = match n {
            MAX_TETS => principal_lanes(&lanes, MAX_TETS),
            _ => principal_lanes(&lanes, n),
        };
        // The common returns (elastic, or onto the main plane) of all at
        // once, vectorized, the others one by one; a tetrahedral cell's one
        // tetrahedron has nothing to vectorize and takes the scalar return.
        let CommonReturns { stress: returned, elastic, main } = match n {
            MAX_TETS => surface.common_returns(lame, &lanes, &values, MAX_TETS),
            _ => surface.common_returns(lame, &lanes, &values, if n > 1 { n } else { 0 }),
        };
        let each = topo.tets.iter().zip(tets).zip(hist.iter_mut()).zip(trials.iter().zip(&effective)).enumerate();
        for (k, (((t, op), h), (&trial, &eff))) in each {
            let (s, now) = match (elastic[k], main[k]) {
                (true, _) => (eff, Yield::Elastic),
                (false, true) => (six(|i| returned[i][k]), Yield::Shear),
                (false, false) => surface.return_map_with(lame, eff, [values[0][k], values[1][k], values[2][k]]),
            };
            let sigma = match pore {
                0.0 => s,
                _ => shift_normal(s, -pore),
            };
            if now != Yield::Elastic {
                let dep = compliance(lame, six(|i| trial[i] - sigma[i]));
                for i in 0..6 {
                    h.eps_p[i] += dep[i];
                }
                h.ever = true;
                h.ever_tension |= now == Yield::Tension;
            }
            h.now = now;
            let p = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
            pressure += op.sqrt_v * op.sqrt_v * p;
            volume += op.sqrt_v * op.sqrt_v;
            if shift.is_some() {
                let vt = op.sqrt_v * op.sqrt_v;
                for (i, x) in deviatoric(sigma).into_iter().enumerate() {
                    dev[i] += vt * x;
                }
            }
            // V_t dev(sigma) grad N_k = sqrt(V_t) dev(sigma) b_k.
            let s = op.sqrt_v;
            let (sxx, syy, szz) = (s * (sigma[0] - p), s * (sigma[1] - p), s * (sigma[2] - p));
            let (syz, sxz, sxy) = (s * sigma[3], s * sigma[4], s * sigma[5]);
            for (k, &pt) in t.iter().enumerate() {
                let (bx, by, bz) = (op.b[3 * k], op.b[3 * k + 1], op.b[3 * k + 2]);
                let fp = &mut f[pt as usize];
                fp[0] += sxx * bx + sxy * by + sxz * bz;
                fp[1] += sxy * bx + syy * by + syz * bz;
                fp[2] += sxz * bx + syz * by + szz * bz;
            }
        }
        corner_forces(topo, &mut f, f_e);
        let mut deviatoric = [0.0; 6];
        match volumetric {
            Volumetric::Cell => add_pressure_force(grad, pressure, f_e),
            Volumetric::Nodal(_) => {}
            Volumetric::Smoothed(s) => {
                // The cell's own share of the smoothed strain, `-alpha dev(eps_cell)`:
                // its virtual work `-alpha V dev(sigma_cell) : eps_cell`.
                if shift.is_some() {
                    deviatoric = dev.map(|x| s.alpha * x / volume);
                    add_stress_force(grad, -volume, deviatoric, f_e);
                }
            }
        }
        let radius = match sensitivity.len() >= n && hist[..n].iter().all(|h| h.now == Yield::Elastic) {
            true => radius_of(surface, &values, &sensitivity[..n]),
            false => 0.0,
        };
        CellStep { volumetric: e, pressure: pressure / volume, deviatoric, radius }
    })
}

/// `eps + shift` (None: `eps`).
fn shifted(eps: [f64; 6], shift: Option<[f64; 6]>) -> [f64; 6] {
    match shift {
        Some(d) => six(|i| eps[i] + d[i]),
        None => eps,
    }
}

/// The elastic screen of a hexahedral plastic cell (one pressure per cell,
/// [`Volumetric::Cell`]): while none of its tetrahedra yields, its force is
/// affine in its corner displacements, `f_e = K_e u_e - f_p` (`K_e` the
/// mixed stiffness of phase 1, `f_p` the force of the plastic strain it
/// already has), and the return mappings can be skipped. When a full pass
/// finds every tetrahedron elastic, [`Screen::arm`] records the corner
/// displacements `u_c` and a radius `r = min_t margin_t / (2 G_t)`:
/// `margin_t` the distance of tetrahedron `t`'s stress to the surface
/// ([`MohrCoulomb::margin`]), `G_t` its largest stress change per unit
/// corner motion ([`stress_sensitivity`]). No tetrahedron can reach the
/// surface while the corners' motion since then, less its mean (a
/// translation strains nothing), stays within `r`
/// ([`Screen::holds`]): the fast path then gives the full pass's force,
/// to rounding. A strength reduction disarms every screen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Screen {
    /// Corner displacements at the last check (m).
    pub u_check: [f64; 24],
    /// `f_p = K_e u_e - f_e` at the last check (N).
    pub offset: [f64; 24],
    /// `r^2` (m^2); 0: disarmed, the next step makes a full pass.
    pub radius2: f64,
}

impl Default for Screen {
    fn default() -> Self {
        Self { u_check: [0.0; 24], offset: [0.0; 24], radius2: 0.0 }
    }
}

impl Screen {
    /// Whether the corner motion since the check, less its mean, is inside
    /// the radius.
    #[inline]
    pub fn holds(&self, nodes: &[u32], u: &[f64]) -> bool {
        if self.radius2 <= 0.0 {
            return false;
        }
        let n = nodes.len();
        let mut du = [[0.0; 3]; 8];
        let mut mean = [0.0; 3];
        for (c, &node) in nodes.iter().enumerate() {
            let k = 3 * node as usize;
            for i in 0..3 {
                du[c][i] = u[k + i] - self.u_check[3 * c + i];
                mean[i] += du[c][i];
            }
        }
        let mean = mean.map(|m| m / n as f64);
        let mut r2 = 0.0;
        for d in &du[..n] {
            for i in 0..3 {
                r2 += (d[i] - mean[i]) * (d[i] - mean[i]);
            }
        }
        r2 < self.radius2
    }

    /// Arms the screen after a full pass that gave `f_e` and left every
    /// tetrahedron elastic: `radius` from the cell's margin and
    /// sensitivity, `f_p = K_e u_e - f_e` from its mixed stiffness `k`.
    pub fn arm(&mut self, k: &[f64], nodes: &[u32], u: &[f64], f_e: &[f64], radius: f64) {
        let n = nodes.len();
        for (c, &node) in nodes.iter().enumerate() {
            let b = 3 * node as usize;
            self.u_check[3 * c..3 * c + 3].copy_from_slice(&u[b..b + 3]);
        }
        let mut ku = [0.0; 24];
        super::element::element_force(k, nodes, u, &mut ku[..3 * n]);
        for i in 0..3 * n {
            self.offset[i] = ku[i] - f_e[i];
        }
        self.radius2 = radius * radius;
    }

    /// The fast path: `f_e = K_e u_e - f_p`.
    #[inline]
    pub fn force(&self, k: &[f64], nodes: &[u32], u: &[f64], f_e: &mut [f64]) {
        super::element::element_force(k, nodes, u, f_e);
        for (f, p) in f_e.iter_mut().zip(&self.offset) {
            *f -= p;
        }
    }
}

/// `G_t` of each tetrahedron of a [`Volumetric::Cell`] cell (Pa/m): the
/// norm of the linear map from the cell's corner displacements to the
/// tetrahedron's stress, the stress measured by its tensor (Frobenius) norm,
/// which bounds its spectral norm: `|d sigma_t| <= G_t |d u|`. The map is
/// probed with the unit displacements; `G_t` is the square root of the
/// largest eigenvalue of `M_t M_t^T` (6 x 6, the shear rows scaled by
/// `sqrt 2`).
pub fn stress_sensitivity(topo: &TetTopology, tets: &[TetB], lame: Lame) -> Vec<f64> {
    let n = topo.n_corners;
    let nodes: Vec<u32> = (0..n as u32).collect();
    let mut mmt = vec![nalgebra::Matrix6::<f64>::zeros(); tets.len()];
    for j in 0..3 * n {
        let mut u = vec![0.0; 3 * n];
        u[j] = 1.0;
        let (eps, e) = tet_strains(topo, tets, &point_displacements(topo, &nodes, &u));
        for (a, eps) in mmt.iter_mut().zip(&eps) {
            let s = lame.stress_voigt(mixed(*eps, e));
            let r2 = std::f64::consts::SQRT_2;
            let col = nalgebra::Vector6::new(s[0], s[1], s[2], r2 * s[3], r2 * s[4], r2 * s[5]);
            *a += col * col.transpose();
        }
    }
    mmt.into_iter().map(|a| a.symmetric_eigenvalues().max().max(0.0).sqrt()).collect()
}

/// The screen's radius of a [`Volumetric::Cell`] cell whose tetrahedra
/// are all elastic now: `min_t margin_t / (2 G_t)` (m), the margins of the
/// effective stresses (`pore` as in [`plastic_element_force`]); 0 if a
/// tetrahedron is on or outside the surface.
#[allow(clippy::too_many_arguments)]
pub fn screen_radius(
    topo: &TetTopology,
    tets: &[TetB],
    lame: Lame,
    surface: &MohrCoulomb,
    sensitivity: &[f64],
    nodes: &[u32],
    u: &[f64],
    pore: f64,
    hist: &[TetPlastic],
) -> f64 {
    let (eps, e) = tet_strains(topo, tets, &point_displacements(topo, nodes, u));
    let n = tets.len().min(hist.len()).min(sensitivity.len());
    let mut sigma = [[0.0; 6]; MAX_TETS];
    for ((s, eps), h) in sigma.iter_mut().zip(&eps[..n]).zip(hist) {
        let strain = mixed(*eps, e);
        *s = shift_normal(lame.stress_voigt(six(|i| strain[i] - h.eps_p[i])), pore);
    }
    radius_of(surface, &principal_lanes(&lanes_of(&sigma, n), n), &sensitivity[..n])
}

/// `min_t margin_t / (2 G_t)` from the lanes of the tetrahedra's principal
/// effective stresses `values` and their sensitivities `G_t` (one per
/// tetrahedron); 0 if one is on or outside the surface.
#[inline(always)]
fn radius_of(surface: &MohrCoulomb, values: &Lanes<3>, sensitivity: &[f64]) -> f64 {
    let mut radius = f64::INFINITY;
    for (t, &g) in sensitivity.iter().enumerate() {
        let margin = surface.margin_of([values[0][t], values[1][t], values[2][t]]);
        if !(margin > 0.0) {
            return 0.0;
        }
        radius = radius.min(margin / (2.0 * g));
    }
    if radius.is_finite() {
        radius
    } else {
        0.0
    }
}

/// `sigma + p I` (Voigt).
fn shift_normal(sigma: [f64; 6], p: f64) -> [f64; 6] {
    [sigma[0] + p, sigma[1] + p, sigma[2] + p, sigma[3], sigma[4], sigma[5]]
}

/// What a plastic cell looks like now: its volume-averaged stress (Pa,
/// Voigt), the volume fraction of its tetrahedra yielding now and ever (in
/// shear or tension), the fractions of those in tension (FLAC's
/// `tension-n` and `tension-p`: a tetrahedron on a tension plane, with or
/// without a shear plane; the rest of `yielding` is in shear alone), and
/// its volume-averaged plastic shear strain `sqrt(2/3 e^p : e^p)` of the
/// deviatoric plastic strain (FLAC's shear-strain measure).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CellPlastic {
    pub stress: [f64; 6],
    pub yielding: f64,
    pub yielded: f64,
    pub yielding_tension: f64,
    pub yielded_tension: f64,
    pub plastic_shear: f64,
}

/// [`CellPlastic`] of one cell from its displacement, its volumetric strain
/// and its history.
#[allow(clippy::too_many_arguments)]
pub fn cell_plastic(
    topo: &TetTopology,
    tets: &[TetB],
    lame: Lame,
    nodes: &[u32],
    u: &[f64],
    volumetric: Volumetric,
    hist: &[TetPlastic],
) -> CellPlastic {
    let d = point_displacements(topo, nodes, u);
    let (eps, own) = tet_strains(topo, tets, &d);
    let e = volumetric.value(own);
    let shift = volumetric.shift(tets, &eps);
    let mut out = CellPlastic::default();
    let mut v = 0.0;
    for ((op, eps), h) in tets.iter().zip(&eps).zip(hist) {
        let vt = op.sqrt_v * op.sqrt_v;
        let strain = shifted(mixed(*eps, e), shift);
        let sigma = lame.stress_voigt(six(|i| strain[i] - h.eps_p[i]));
        for i in 0..6 {
            out.stress[i] += vt * sigma[i];
        }
        if h.now != Yield::Elastic {
            out.yielding += vt;
        }
        if h.now == Yield::Tension {
            out.yielding_tension += vt;
        }
        if h.ever {
            out.yielded += vt;
        }
        if h.ever_tension {
            out.yielded_tension += vt;
        }
        out.plastic_shear += vt * plastic_shear(h.eps_p);
        v += vt;
    }
    out.stress = out.stress.map(|s| s / v);
    out.yielding /= v;
    out.yielded /= v;
    out.yielding_tension /= v;
    out.yielded_tension /= v;
    out.plastic_shear /= v;
    out
}

/// `sqrt(2/3 e : e)` of the deviatoric part `e` of a plastic strain (Voigt,
/// engineering shear).
pub fn plastic_shear(eps_p: [f64; 6]) -> f64 {
    let m = (eps_p[0] + eps_p[1] + eps_p[2]) / 3.0;
    let d = [eps_p[0] - m, eps_p[1] - m, eps_p[2] - m];
    let ee = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + 0.5 * (eps_p[3].powi(2) + eps_p[4].powi(2) + eps_p[5].powi(2));
    (2.0 / 3.0 * ee).sqrt()
}

/// What every plastic cell can carry now and its tetrahedra's history,
/// owned by the loop beside the springs' (the counterpart of
/// [`super::joint::JointState`]). Strength reduction rescales the
/// strengths ([`Self::reduced`]); the model is not touched.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RockState {
    /// Each material's strength as given (None: linear elastic).
    pub given: Vec<Option<RockStrength>>,
    /// The kernel's form of `given` (reduced in a strength-reduction trial).
    pub surface: Vec<Option<MohrCoulomb>>,
    /// One history per element, empty if no material yields.
    pub history: Vec<CellHistory>,
    /// Per element: the volumetric strain its tetrahedra used at the last
    /// step, and their mean stress (Pa) (the nodal average's inputs).
    pub volumetric: Vec<f64>,
    pub pressure: Vec<f64>,
    /// Per mesh vertex: the averaged volumetric strain and mean stress of
    /// its nodally averaged cells (scratch of each step).
    pub vertex_strain: Vec<f64>,
    pub vertex_pressure: Vec<f64>,
    /// The weight `alpha` of the smoothed deviatoric strain of the nodally
    /// averaged cells ([`Volumetric::Smoothed`]; 0: [`Volumetric::Nodal`]).
    pub smoothing: f64,
    /// Per element (smoothing only): its mean deviatoric strain, the
    /// vertex-averaged one it used, and its `alpha dev(sigma_cell)`; per
    /// mesh vertex the averages of the first and the last (scratch).
    pub cell_strain: Vec<[f64; 6]>,
    pub used_strain: Vec<[f64; 6]>,
    pub cell_stress: Vec<[f64; 6]>,
    pub vertex_dev_strain: Vec<[f64; 6]>,
    pub vertex_dev_stress: Vec<[f64; 6]>,
    /// Per element: its elastic screen (used by cells with one pressure).
    pub screen: Vec<Screen>,
}

impl RockState {
    /// The state of a model with these material strengths and `n_elements`
    /// elements, every tetrahedron elastic.
    pub fn new(given: Vec<Option<RockStrength>>, n_elements: usize, n_vertices: usize, smoothing: f64) -> Self {
        let surface = given.iter().map(|s| s.map(|s| MohrCoulomb::of(&s))).collect();
        let any = given.iter().any(Option::is_some);
        let (ne, nv) = if any { (n_elements, n_vertices) } else { (0, 0) };
        Self {
            given,
            surface,
            history: vec![[TetPlastic::default(); MAX_TETS]; ne],
            volumetric: vec![0.0; ne],
            pressure: vec![0.0; ne],
            vertex_strain: vec![0.0; nv],
            vertex_pressure: vec![0.0; nv],
            smoothing,
            cell_strain: vec![[0.0; 6]; ne],
            used_strain: vec![[0.0; 6]; ne],
            cell_stress: vec![[0.0; 6]; ne],
            vertex_dev_strain: vec![[0.0; 6]; nv],
            vertex_dev_stress: vec![[0.0; 6]; nv],
            screen: vec![Screen::default(); ne],
        }
    }

    /// Strengths divided by `f` ([`RockStrength::reduced`]); the history is
    /// kept, the screens are disarmed (their margins were of the old surface).
    pub fn reduce(&mut self, f: f64) {
        self.surface = self.given.iter().map(|s| s.map(|s| MohrCoulomb::of(&s.reduced(f)))).collect();
        self.disarm();
    }

    /// Every tetrahedron back to elastic with no plastic strain.
    pub fn reset_history(&mut self) {
        self.history.iter_mut().for_each(|h| *h = Default::default());
        self.disarm();
    }

    /// Disarms every screen: the next step makes a full pass everywhere.
    pub fn disarm(&mut self) {
        self.screen.iter_mut().for_each(|s| s.radius2 = 0.0);
    }

    /// Whether any material yields.
    pub fn any_plastic(&self) -> bool {
        self.given.iter().any(Option::is_some)
    }
}

/// The per-tetrahedron operators of a model's plastic cells, struct of
/// arrays: element `e` has tetrahedra `tets[offset[e]..offset[e + 1]]`
/// (none for an element whose material does not yield). Prisms and
/// tetrahedra average their volumetric strain over the mesh vertices
/// ([`Volumetric::Nodal`]): `vertex_cells[vertex_ptr[a]..vertex_ptr[a + 1]]`
/// are the cells at mesh vertex `a`.
#[derive(Debug, Clone)]
pub struct PlasticCells {
    pub offset: Vec<usize>,
    pub tets: Vec<TetB>,
    /// Per element: whether its volumetric strain is the nodal average.
    pub nodal: Vec<bool>,
    /// Per tetrahedron (as `tets`): `G_t` of [`stress_sensitivity`] for a
    /// cell with one pressure, 0 for the others (no [`Screen`]).
    pub sensitivity: Vec<f64>,
    pub vertex_ptr: Vec<u32>,
    pub vertex_cells: Vec<u32>,
    topo: [TetTopology; 3],
}

impl Default for PlasticCells {
    fn default() -> Self {
        Self {
            offset: vec![0],
            tets: Vec::new(),
            nodal: Vec::new(),
            sensitivity: Vec::new(),
            vertex_ptr: vec![0],
            vertex_cells: Vec::new(),
            topo: [TetTopology::of(CellKind::Tet4), TetTopology::of(CellKind::Prism6), TetTopology::of(CellKind::Hex8)],
        }
    }
}

impl PlasticCells {
    /// Appends one cell: its tetrahedra if it yields (`lame`: its
    /// elasticity), none if not.
    pub fn push(&mut self, kind: CellKind, corners: &[[f64; 3]], plastic: Option<Lame>) {
        let start = self.tets.len();
        if plastic.is_some() {
            self.tets.extend(plastic_operator(kind, corners));
        }
        self.offset.push(self.tets.len());
        let nodal = plastic.is_some() && kind != CellKind::Hex8;
        self.nodal.push(nodal);
        let g = match plastic {
            Some(lame) if !nodal => stress_sensitivity(self.topology(kind), &self.tets[start..], lame),
            _ => vec![0.0; self.tets.len() - start],
        };
        self.sensitivity.extend(g);
    }

    /// `G_t` of element `e`'s tetrahedra (zeros: the element has no screen).
    pub fn sensitivity(&self, e: usize) -> &[f64] {
        &self.sensitivity[self.offset[e]..self.offset[e + 1]]
    }

    /// Builds the vertex lists of the nodally averaged cells from each
    /// element's mesh vertices (`vertices(e)`), `n_vertices` in all.
    pub fn link_vertices(&mut self, n_vertices: usize, vertices: impl Fn(usize) -> Vec<u32>) {
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); n_vertices];
        for e in (0..self.nodal.len()).filter(|&e| self.nodal[e]) {
            for a in vertices(e) {
                lists[a as usize].push(e as u32);
            }
        }
        self.vertex_ptr = std::iter::once(0)
            .chain(lists.iter().scan(0u32, |n, l| {
                *n += l.len() as u32;
                Some(*n)
            }))
            .collect();
        self.vertex_cells = lists.concat();
    }

    /// The nodally averaged cells at mesh vertex `a`.
    pub fn vertex(&self, a: usize) -> &[u32] {
        &self.vertex_cells[self.vertex_ptr[a] as usize..self.vertex_ptr[a + 1] as usize]
    }

    /// Whether any cell averages over its vertices.
    pub fn any_nodal(&self) -> bool {
        !self.vertex_cells.is_empty()
    }

    /// The tetrahedra of element `e`.
    pub fn tets(&self, e: usize) -> &[TetB] {
        &self.tets[self.offset[e]..self.offset[e + 1]]
    }

    pub fn topology(&self, kind: CellKind) -> &TetTopology {
        match kind {
            CellKind::Tet4 => &self.topo[0],
            CellKind::Prism6 => &self.topo[1],
            CellKind::Hex8 => &self.topo[2],
        }
    }

    /// Whether any cell yields.
    pub fn any(&self) -> bool {
        !self.tets.is_empty()
    }
}
