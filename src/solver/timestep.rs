//! The stable time step from the model (Gershgorin bound) and mass scaling.
//!
//! For the assembled stiffness `K` and lumped masses `m_i`, the largest
//! eigenvalue of `M^-1 K` is at most `max_i r_i / m_i` with the absolute row
//! sums `r_i = max_d sum_j |K_(3i+d) j|`. Central differences are stable for
//! `dt < 2 / sqrt(lambda_max)`.

use crate::model::Model;

/// Absolute row sums of the assembled stiffness, per node (max over its 3 rows).
pub fn stiffness_row_sums(model: &Model) -> Vec<f64> {
    max_of_rows(&component_row_sums(model, true))
}

/// Absolute row sums of the elements' stiffness alone, per node (max over its 3 rows).
pub fn element_row_sums(model: &Model) -> Vec<f64> {
    max_of_rows(&component_row_sums(model, false))
}

/// Absolute row sums of a spring's block `K_aa = K_n n n^T + K_s (I - n n^T)`
/// (its `K_ab = -K_aa`, so a node's row over both is twice these).
pub fn spring_block_rows(kn: f64, ks: f64, n: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| {
        (0..3)
            .map(|j| {
                let nn = n[i] * n[j];
                let id = if i == j { 1.0 } else { 0.0 };
                (kn * nn + ks * (id - nn)).abs()
            })
            .sum()
    })
}

fn max_of_rows(rows: &[f64]) -> Vec<f64> {
    rows.chunks(3).map(|r| r[0].max(r[1]).max(r[2])).collect()
}

/// Absolute row sums per component, of the elements and, if `springs`, the springs.
fn component_row_sums(model: &Model, springs: bool) -> Vec<f64> {
    let mut rows = vec![0.0; 3 * model.n_nodes()];
    let el = &model.elements;
    for e in 0..el.len() {
        let nodes = el.corners(e);
        let k = el.stiffness_full(e);
        let n = 3 * nodes.len();
        for (c, &node) in nodes.iter().enumerate() {
            for i in 0..3 {
                let r: f64 = k[(3 * c + i) * n..(3 * c + i + 1) * n].iter().map(|v| v.abs()).sum();
                rows[3 * node as usize + i] += r;
            }
        }
    }
    let sp = &model.springs;
    for s in (0..sp.len()).filter(|_| springs) {
        let block = spring_block_rows(sp.kn[s], sp.ks[s], sp.normal[s]);
        for (i, &r) in block.iter().enumerate() {
            rows[3 * sp.a[s] as usize + i] += 2.0 * r;
            rows[3 * sp.b[s] as usize + i] += 2.0 * r;
        }
    }
    rows
}

/// Inertial masses and time step. Without mass scaling: the physical masses
/// and `dt = safety * 2 / sqrt(amplification * max r_i / m_i)`. With it:
/// `dt = 1` and `m_i = amplification * r_i / (2 safety)^2`, so that every node
/// sits at the same fraction of its own stability limit.
///
/// `amplification` is how much the damping can amplify the restoring force:
/// local damping adds `alpha |f|` along `f` when a node decelerates, so it is
/// `1 + alpha` (without it a spring chain, whose largest eigenvalue equals the
/// Gershgorin bound, blows up); 1 for viscous and kinetic damping.
pub fn masses_and_step(
    model: &Model,
    rows: &[f64],
    safety: f64,
    mass_scaling: bool,
    amplification: f64,
) -> Option<(Vec<f64>, f64)> {
    if mass_scaling {
        let scale = amplification / (4.0 * safety * safety);
        let m: Vec<f64> = rows.iter().zip(&model.mass).map(|(&r, &m)| if r > 0.0 { scale * r } else { m }).collect();
        return Some((m, 1.0));
    }
    let lambda = amplification * rows.iter().zip(&model.mass).map(|(r, m)| r / m).fold(0.0, f64::max);
    (lambda > 0.0 && lambda.is_finite()).then(|| (model.mass.clone(), safety * 2.0 / lambda.sqrt()))
}
