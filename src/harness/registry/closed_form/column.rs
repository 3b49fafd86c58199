//! The laterally confined column (references/column.md).

#[allow(unused_imports)]
use super::super::*;

/// A laterally confined elastic column under gravity: base fixed, sides on
/// rollers, so the only strain is eps_zz.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConfinedColumn {
    /// H (m).
    pub height: f64,
    /// rho (kg/m^3).
    pub density: f64,
    /// g (m/s^2).
    pub gravity: f64,
    /// E (Pa).
    pub young: f64,
    /// nu.
    pub poisson: f64,
    /// Cross-section (m^2): 4 m x 4 m.
    pub area: f64,
}

/// The column of `verification/cases/column/` (references/column.md).
pub const CONFINED_COLUMN: ConfinedColumn =
    ConfinedColumn { height: 40.0, density: 2100.0, gravity: GRAVITY, young: 3.0e8, poisson: 0.3, area: 16.0 };

/// The oedometric (constrained) modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
pub fn oedometric_modulus(e: f64, nu: f64) -> f64 {
    e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))
}

/// M of the column (Pa).
pub fn column_m() -> f64 {
    oedometric_modulus(CONFINED_COLUMN.young, CONFINED_COLUMN.poisson)
}

/// u_z(z) = -rho g (H z - z^2 / 2) / M (m).
pub fn column_uz(z: f64) -> f64 {
    let c = CONFINED_COLUMN;
    -c.density * c.gravity * (c.height * z - 0.5 * z * z) / column_m()
}

/// sigma_zz(z) = -rho g (H - z) (Pa).
pub fn column_szz(z: f64) -> f64 {
    let c = CONFINED_COLUMN;
    -c.density * c.gravity * (c.height - z)
}

/// The lateral stress ratio sigma_xx / sigma_zz = nu / (1 - nu).
pub fn column_k0() -> f64 {
    CONFINED_COLUMN.poisson / (1.0 - CONFINED_COLUMN.poisson)
}

/// The top settlement u_z(H) = -rho g H^2 / (2 M) (m).
pub fn column_top_uz() -> f64 {
    column_uz(CONFINED_COLUMN.height)
}

/// The column case's mesh as [`column_top_uz_jointed`] needs it
/// (verification/cases/column/column.geo): 2 x 2 cells across its 4 m
/// width, 10 layers of 4 m.
pub const COLUMN_CELLS_ACROSS: usize = 2;
pub const COLUMN_WIDTH: f64 = 4.0;
pub const COLUMN_LAYERS: usize = 10;

/// The top settlement of the column with a joint of normal stiffness `k`
/// per area (Pa/m, `E_j / L`) on every element interface, the joints in
/// series with the rock (references/column.md, "Series joints"): each
/// layer's lateral strain `e` is what the `n - 1` vertical joints across the
/// width `W` let it have, `W e + (n - 1) sigma_xx / k = 0`, which softens
/// the rock's constrained modulus to
/// `M_j = lambda + 2 mu - 2 lambda^2 b / (1 + 2 (lambda + mu) b)`,
/// `b = (n - 1) / (k W)`; every horizontal joint at `z_i` adds
/// `rho g (H - z_i) / k`.
pub fn column_top_uz_jointed(k: f64) -> f64 {
    let c = CONFINED_COLUMN;
    let (e, nu) = (c.young, c.poisson);
    let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    let mu = e / (2.0 * (1.0 + nu));
    let b = (COLUMN_CELLS_ACROSS - 1) as f64 / (k * COLUMN_WIDTH);
    let m_j = lambda + 2.0 * mu - 2.0 * lambda * lambda * b / (1.0 + 2.0 * (lambda + mu) * b);
    let weight = c.density * c.gravity;
    let h = c.height / COLUMN_LAYERS as f64;
    let joints: f64 = (1..COLUMN_LAYERS).map(|i| weight * (c.height - i as f64 * h) / k).sum();
    -weight * c.height * c.height / (2.0 * m_j) - joints
}

/// What the column cases measure: the mean u_z of the node copies at the
/// top (z = H) of a CDEM run (m).
pub fn measured_top_uz(r: &crate::drivers::RunResult) -> f64 {
    let top: Vec<usize> =
        (0..r.model.n_nodes()).filter(|&i| (r.model.x0[i][2] - CONFINED_COLUMN.height).abs() < 1e-9).collect();
    top.iter().map(|&i| r.state.u[3 * i + 2]).sum::<f64>() / top.len() as f64
}

/// Top settlement of a laterally confined column of layers `(z0, z1, rho, M)`
/// from the bottom up (references/extreme.md):
/// `u(H) = -int_0^H W(z) / M(z) dz` with `W(z)` the weight per area above z.
pub fn layered_top_uz(layers: &[(f64, f64, f64, f64)]) -> f64 {
    let g = CONFINED_COLUMN.gravity;
    let mut u = 0.0;
    for (k, &(z0, z1, rho, m)) in layers.iter().enumerate() {
        let above: f64 = layers[k + 1..].iter().map(|&(a, b, r, _)| r * g * (b - a)).sum();
        // int_z0^z1 [above + rho g (z1 - z)] dz
        u -= (above * (z1 - z0) + 0.5 * rho * g * (z1 - z0).powi(2)) / m;
    }
    u
}

/// A case of the stiff and extreme suite (`verification/extreme/<name>.toml`,
/// references/extreme.md): the analytic top u_z and its tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExtremeCase {
    pub name: &'static str,
    /// Its rows of the validation table ([`rows`]): with PCG and with DR.
    pub row: &'static str,
    /// The PCG row's case label.
    pub label: &'static str,
    pub row_dr: &'static str,
    /// The DR row's case label.
    pub label_dr: &'static str,
    pub what: &'static str,
    /// Analytic top u_z (m).
    pub reference: f64,
    /// Allowed relative error of a converged PCG run (0: exactly): at most
    /// 10x the measured error, or the physical error where the reference
    /// leaves one out (references/extreme.md).
    pub tolerance: f64,
    /// The same for a converged DR run, which stops at the scene's ratio
    /// 1e-7 and so leaves a larger error than PCG's residual does.
    pub tolerance_dr: f64,
}

impl ExtremeCase {
    /// The scene file.
    pub fn scene(&self) -> Result<Scene, Error> {
        Scene::load(&Path::new("verification/extreme").join(format!("{}.toml", self.name)))
    }
}

/// The extreme cases' rows: (scene name, PCG row id, its case label, DR row id, its case label).
#[rustfmt::skip]
const EXTREME_ROWS: [(&str, &str, &str, &str, &str); 8] = [
    ("joints-soft", "extreme/joints-soft", "extreme: joints-soft, PCG", "extreme/joints-soft/dr", "extreme: joints-soft, DR"),
    ("joints-stiff", "extreme/joints-stiff", "extreme: joints-stiff, PCG", "extreme/joints-stiff/dr", "extreme: joints-stiff, DR"),
    ("poisson-0499", "extreme/poisson-0499", "extreme: poisson-0499, PCG", "extreme/poisson-0499/dr", "extreme: poisson-0499, DR"),
    ("perturbation-near-limit", "extreme/perturbation-near-limit", "extreme: perturbation-near-limit, PCG", "extreme/perturbation-near-limit/dr", "extreme: perturbation-near-limit, DR"),
    ("aspect-1-50", "extreme/aspect-1-50", "extreme: aspect-1-50, PCG", "extreme/aspect-1-50/dr", "extreme: aspect-1-50, DR"),
    ("contrast-modulus-1e4", "extreme/contrast-modulus-1e4", "extreme: contrast-modulus-1e4, PCG", "extreme/contrast-modulus-1e4/dr", "extreme: contrast-modulus-1e4, DR"),
    ("contrast-density-1e3", "extreme/contrast-density-1e3", "extreme: contrast-density-1e3, PCG", "extreme/contrast-density-1e3/dr", "extreme: contrast-density-1e3, DR"),
    ("zero-gravity", "extreme/zero-gravity", "extreme: zero-gravity, PCG", "extreme/zero-gravity/dr", "extreme: zero-gravity, DR"),
];

impl ExtremeCase {
    /// Its PCG row spec (PCG is the default solver; asserted to its
    /// tolerance, references/extreme.md).
    pub fn row_spec(&self) -> RowSpec {
        self.row_spec_for(crate::solver::ElasticSolver::Pcg)
    }
    /// Its tolerance under `solver`.
    pub fn tolerance_for(&self, solver: crate::solver::ElasticSolver) -> f64 {
        match solver {
            crate::solver::ElasticSolver::Pcg => self.tolerance,
            crate::solver::ElasticSolver::Dr => self.tolerance_dr,
        }
    }
    /// Its row spec under `solver` (each solver its own tolerance; a run
    /// whose own convergence measure misses fails the row, see
    /// `harness::suite::extreme`).
    pub fn row_spec_for(&self, solver: crate::solver::ElasticSolver) -> RowSpec {
        let (id, case, quantity) = match solver {
            crate::solver::ElasticSolver::Pcg => {
                (self.row, self.label, "top u_z (m); PCG's true residual below the tolerance")
            }
            crate::solver::ElasticSolver::Dr => {
                (self.row_dr, self.label_dr, "top u_z (m); DR's kinetic energy decayed, ratio below the tolerance")
            }
        };
        RowSpec {
            id,
            case,
            quantity,
            kind: SpecKind::Asserted(self.tolerance_for(solver)),
            source: EXTREME_MD,
            test: "tests/extreme.rs",
            reference: Some(self.reference),
            skip: None,
        }
    }
}

/// The elastic solvers every extreme case runs under, in the order of its rows.
pub const EXTREME_SOLVERS: [crate::solver::ElasticSolver; 2] =
    [crate::solver::ElasticSolver::Pcg, crate::solver::ElasticSolver::Dr];

/// The stiff and extreme suite, in the order of references/extreme.md.
pub fn extreme_cases() -> [ExtremeCase; 8] {
    // The rock of the column (E = 3e8 Pa, nu = 0.3, rho = 2100 kg/m^3), H = 40 m.
    let c = CONFINED_COLUMN;
    let (h, g, rho) = (c.height, c.gravity, c.density);
    let m = oedometric_modulus(c.young, c.poisson);
    let column = layered_top_uz(&[(0.0, h, rho, m)]);
    // Soft joints, one element wide (column-single.msh): each horizontal
    // interface (z = 4, 8, ..., 36) adds the settlement W(z_i) L / E_j in
    // series, and there is no other interface; E_j = E (K_n L/(E A) = 1).
    let e_j = c.young;
    let soft = column - (1..10).map(|i| rho * g * (h - 4.0 * i as f64)).sum::<f64>() * 1.0 / e_j;
    let case = |name: &'static str, what, reference, (tolerance, tolerance_dr)| {
        let (row, label, row_dr, label_dr) =
            EXTREME_ROWS.iter().find(|r| r.0 == name).map_or(("", "", "", ""), |r| (r.1, r.2, r.3, r.4));
        ExtremeCase { name, row, label, row_dr, label_dr, what, reference, tolerance, tolerance_dr }
    };
    [
        case("joints-soft", "soft joints, K_n L/(E A) = 1: column + series joints", soft, (1e-9, 5e-7)),
        case("joints-stiff", "stiff joints, K_n L/(E A) = 1e6: column (joint compliance 3e-7)", column, (1e-6, 1e-6)),
        case(
            "poisson-0499",
            "nu = 0.499: column with M(nu = 0.499)",
            layered_top_uz(&[(0.0, h, rho, oedometric_modulus(c.young, 0.499))]),
            (1e-9, 5e-7),
        ),
        case(
            "perturbation-near-limit",
            "perturbation 0.49: column (distorted elements, measured 5.9e-5)",
            column,
            (2e-4, 2e-4),
        ),
        case("aspect-1-50", "aspect ratio 1:50: column", column, (2e-9, 5e-7)),
        case(
            "contrast-modulus-1e4",
            "E contrast 1e4: layered",
            layered_top_uz(&[(0.0, 20.0, rho, m), (20.0, h, rho, 1e4 * m)]),
            (1e-10, 5e-7),
        ),
        case(
            "contrast-density-1e3",
            "density contrast 1e3: layered",
            layered_top_uz(&[(0.0, 20.0, 2.1, m), (20.0, h, rho, m)]),
            (5e-10, 5e-7),
        ),
        case("zero-gravity", "zero gravity: u = 0 exactly", 0.0, (0.0, 0.0)),
    ]
}
