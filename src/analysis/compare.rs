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
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..model.n_nodes() {
        let n = model.mesh_node[i] as usize;
        for d in 0..3 {
            let (a, b) = (u[3 * i + d], u_fem[3 * n + d]);
            num += model.mass[i] * (a - b) * (a - b);
            den += model.mass[i] * b * b;
        }
    }
    (num / den).sqrt()
}
