//! Contact springs between coincident node copies (paper section 3.3 (2),
//! eq. 15-18).
//!
//! For a spring from node `a` to node `b` with unit normal `n` (out of a's
//! element, into b's): relative displacement `d = u_b - u_a`, opening
//! `d_n = d . n`, shear `d_s = d - d_n n`.
//! Eq. 15: `F_n = K_n d_n` (positive = tension), `F_s = K_s (d_s - d_s^p)`.
//! The force on `a` is `F_n n + F_s`; `b` gets the opposite.

use serde::Serialize;

/// Eq. 16: spring stiffnesses `K_n = E_j A / L`, `K_s = G_j A / L` (N/m) from
/// the structural plane's moduli `E_j`, `G_j` (Pa), the node's area share `A`
/// (m^2) and the plane's equivalent thickness `L` (m).
pub fn spring_stiffness(e_j: f64, g_j: f64, area: f64, thickness: f64) -> (f64, f64) {
    (e_j * area / thickness, g_j * area / thickness)
}

/// Eq. 15: normal force (positive in tension) and shear force vector of a
/// spring with relative displacement `d` and plastic slip `slip`.
#[inline]
pub fn spring_force(kn: f64, ks: f64, n: [f64; 3], d: [f64; 3], slip: [f64; 3]) -> (f64, [f64; 3]) {
    let dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    let fs = [0, 1, 2].map(|i| ks * (d[i] - dn * n[i] - slip[i]));
    (kn * dn, fs)
}

/// Eq. 17: the tension cut-off. True when the spring breaks in tension
/// (`F_n >= T A`).
#[inline]
pub fn tension_cutoff(f_n: f64, tensile_strength: f64, area: f64) -> bool {
    f_n >= tensile_strength * area
}

/// Eq. 18: Mohr–Coulomb. With compression `P = max(-F_n, 0)`, returns the
/// admissible shear force magnitude if `|F_s| > P tan(phi) + c A` (the spring
/// slips and keeps only friction, `P tan(phi)`), or `None` if it holds.
#[inline]
pub fn mohr_coulomb(f_n: f64, f_s_abs: f64, tan_phi: f64, cohesion: f64, area: f64) -> Option<f64> {
    let p = (-f_n).max(0.0);
    (f_s_abs > p * tan_phi + cohesion * area).then_some(p * tan_phi)
}

/// The state of a spring.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum SpringStatus {
    /// Elastic, with cohesion and tensile strength.
    Intact,
    /// Broken in tension (eq. 17): no tension, no cohesion; may close again.
    Tension,
    /// Slipped in shear (eq. 18): cohesion lost, friction only.
    Shear,
}

/// One spring as a law sees it: stiffness (N/m), unit normal out of node
/// `a`'s element, and area share (m^2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spring {
    pub kn: f64,
    pub ks: f64,
    pub normal: [f64; 3],
    pub area: f64,
}

/// The immutable springs of a model, struct of arrays.
#[derive(Debug, Clone, Default)]
pub struct Springs {
    pub a: Vec<u32>,
    pub b: Vec<u32>,
    pub normal: Vec<[f64; 3]>,
    pub area: Vec<f64>,
    pub kn: Vec<f64>,
    pub ks: Vec<f64>,
    /// Interface index (into the model's interface list) of each spring.
    pub interface: Vec<u16>,
}

impl Springs {
    pub fn len(&self) -> usize {
        self.a.len()
    }
    pub fn is_empty(&self) -> bool {
        self.a.is_empty()
    }
    /// Spring `s` as a joint law sees it.
    #[inline]
    pub fn get(&self, s: usize) -> Spring {
        Spring { kn: self.kn[s], ks: self.ks[s], normal: self.normal[s], area: self.area[s] }
    }
}

/// What changes in the springs during a run.
#[derive(Debug, Clone)]
pub struct SpringState {
    pub slip: Vec<[f64; 3]>,
    pub status: Vec<SpringStatus>,
}

impl SpringState {
    pub fn new(n: usize) -> Self {
        Self { slip: vec![[0.0; 3]; n], status: vec![SpringStatus::Intact; n] }
    }
}

/// Eq. 15 for one spring with its state: the force the spring exerts on
/// node `a` (`F_n n + F_s`; node `b` gets the opposite). A broken joint that
/// is open carries nothing: no tension and hence no friction.
#[inline]
pub fn spring_contact_force(
    kn: f64,
    ks: f64,
    n: [f64; 3],
    d: [f64; 3],
    slip: [f64; 3],
    status: SpringStatus,
) -> [f64; 3] {
    let (f_n, f_s) = spring_force(kn, ks, n, d, slip);
    if status != SpringStatus::Intact && f_n > 0.0 {
        return [0.0; 3];
    }
    [0, 1, 2].map(|i| f_n * n[i] + f_s[i])
}

/// Relative displacement `u_b - u_a` of a spring.
#[inline]
pub fn relative_displacement(u: &[f64], a: usize, b: usize) -> [f64; 3] {
    [u[3 * b] - u[3 * a], u[3 * b + 1] - u[3 * a + 1], u[3 * b + 2] - u[3 * a + 2]]
}

/// Adds the spring forces (eq. 15, no failure) to the internal force `f` (the
/// force that resists deformation: `a` receives `-(F_n n + F_s)`, `b` the
/// opposite). The sequential reference of the solver's gathered version.
pub fn spring_forces(springs: &Springs, state: &SpringState, u: &[f64], f: &mut [f64]) {
    for s in 0..springs.len() {
        let (a, b) = (springs.a[s] as usize, springs.b[s] as usize);
        let d = relative_displacement(u, a, b);
        let fa =
            spring_contact_force(springs.kn[s], springs.ks[s], springs.normal[s], d, state.slip[s], state.status[s]);
        for i in 0..3 {
            f[3 * a + i] -= fa[i];
            f[3 * b + i] += fa[i];
        }
    }
}
