//! Comparing a CDEM state with a continuous FEM solution on the same mesh.

use crate::model::Model;

/// Relative L2 error of the CDEM displacement against an FEM displacement
/// given per mesh node (`u_fem[3 n + d]`), both on the same (perturbed) mesh:
///
/// `e = sqrt(sum_i m_i |u_i - u_fem(n_i)|^2) / sqrt(sum_i m_i |u_fem(n_i)|^2)`
///
/// over the CDEM node copies `i`, `n_i` the mesh node copy `i` was made from
/// and `m_i` its lumped mass (a volume share, so the sums approximate the
/// L2 norm over the domain, rho times).
pub fn relative_l2_displacement(model: &Model, u: &[f64], u_fem: &[f64]) -> f64 {
    mass_weighted_l2(model, u, |i| &u_fem[3 * model.mesh_node[i] as usize..][..3])
}

/// The same error between two CDEM fields on the same model (both indexed by
/// node copy), e.g. two solver settings.
pub fn relative_l2_between_copies(model: &Model, u: &[f64], reference: &[f64]) -> f64 {
    mass_weighted_l2(model, u, |i| &reference[3 * i..][..3])
}

/// `sqrt(sum_i m_i |u_i - r_i|^2 / sum_i m_i |r_i|^2)` over the node copies
/// `i`, with `r_i = reference(i)`.
fn mass_weighted_l2<'a>(model: &Model, u: &[f64], reference: impl Fn(usize) -> &'a [f64]) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..model.n_nodes() {
        let r = reference(i);
        for d in 0..3 {
            let (a, b) = (u[3 * i + d], r[d]);
            num += model.mass[i] * (a - b) * (a - b);
            den += model.mass[i] * b * b;
        }
    }
    (num / den).sqrt()
}
