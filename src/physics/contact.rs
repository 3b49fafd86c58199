//! Frictional contact between blocks that were not neighbours at the start,
//! or whose joint has failed (docs/method.md 2.13): a vertex of one block
//! against a face triangle of another, a penalty spring along the face's
//! normal and a Coulomb slider across it (the semi-spring contact of later
//! CDEM, Feng, Li et al.; 3DEC's soft contact).
//!
//! The forces are incremental, as 3DEC's: with the relative displacement
//! increment of the vertex against the face point this step, `ds`, and the
//! face's outward unit normal `n`,
//!
//! - normal: `F_n += -K_n (ds . n)`, compression only: a contact whose force
//!   falls to zero opens and is forgotten. A new contact starts from the force
//!   it is given (zero, or what a released joint spring carried), so a vertex
//!   that enters a face already a little inside it is not struck by the
//!   whole penalty at once (which would make energy out of nothing);
//! - shear: the elastic tangential force `F_s`, carried in the tangent plane,
//!   grows by `-K_s ds_t` and is capped at `F_n tan(phi) + c A` (Coulomb); the
//!   part of the trial force above the cap is slip, whose work
//!   `cap (|F_s trial| - cap) / K_s` is the step's friction dissipation.
//!
//! The stored energy is `F_n^2 / (2 K_n) + |F_s|^2 / (2 K_s)`.

/// Stiffness and strength of one vertex contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// Normal penalty stiffness (N/m).
    pub kn: f64,
    /// Tangential stiffness (N/m).
    pub ks: f64,
    pub tan_phi: f64,
    /// Cohesive force `c A` (N): zero for a new contact.
    pub cohesion: f64,
}

/// What one contact did this step.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ContactStep {
    /// The force on the vertex (N); the face gets the opposite.
    pub force: [f64; 3],
    /// Compressive normal force (N, >= 0).
    pub normal: f64,
    /// Elastic energy stored in the contact now (J).
    pub energy: f64,
    /// Work dissipated by slip this step (J, >= 0).
    pub dissipated: f64,
    pub slipping: bool,
}

/// What a contact carries from step to step: its normal force (N, >= 0) and
/// its elastic tangential force on the vertex (N).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ContactHistory {
    pub normal: f64,
    pub shear: [f64; 3],
}

/// One contact's step (see the module doc), its history updated in place.
#[inline]
pub fn contact_force(law: &ContactLaw, n: [f64; 3], ds: [f64; 3], h: &mut ContactHistory) -> ContactStep {
    let dn = dot(ds, n);
    let f_n = (h.normal - law.kn * dn).max(0.0);
    h.normal = f_n;
    if f_n == 0.0 {
        h.shear = [0.0; 3];
        return ContactStep::default();
    }
    // Carry the old shear force into the current tangent plane, keeping its size.
    let old = norm(h.shear);
    let sn = dot(h.shear, n);
    let mut s = [0, 1, 2].map(|i| h.shear[i] - sn * n[i]);
    let projected = norm(s);
    if projected > 0.0 {
        s = s.map(|v| v * old / projected);
    }
    let trial = [0, 1, 2].map(|i| s[i] - law.ks * (ds[i] - dn * n[i]));
    let t = norm(trial);
    let cap = f_n * law.tan_phi + law.cohesion;
    let (f_s, dissipated, slipping) = match t > cap {
        true => {
            let scale = if t > 0.0 { cap / t } else { 0.0 };
            (trial.map(|v| v * scale), cap * (t - cap) / law.ks, true)
        }
        false => (trial, 0.0, false),
    };
    h.shear = f_s;
    let energy = 0.5 * f_n * f_n / law.kn + 0.5 * dot(f_s, f_s) / law.ks;
    ContactStep { force: [0, 1, 2].map(|i| f_n * n[i] + f_s[i]), normal: f_n, energy, dissipated, slipping }
}

#[inline]
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAW: ContactLaw = ContactLaw { kn: 1e6, ks: 5e5, tan_phi: 0.5, cohesion: 0.0 };

    #[test]
    fn a_contact_that_opens_carries_nothing_and_forgets_its_shear() {
        let mut h = ContactHistory { normal: 10.0, shear: [5.0, 0.0, 0.0] };
        // Moving out along n by more than F_n / K_n.
        let r = contact_force(&LAW, [0.0, 0.0, 1.0], [0.0, 0.0, 1e-3], &mut h);
        assert_eq!(r, ContactStep::default());
        assert_eq!(h, ContactHistory::default());
    }

    #[test]
    fn the_shear_force_is_capped_by_coulomb_and_the_excess_is_dissipated() {
        // 1 mm pressed in: F_n = 1000 N, cap 500 N; a 2 mm slide asks 1000 N.
        let mut h = ContactHistory::default();
        let r = contact_force(&LAW, [0.0, 0.0, 1.0], [2e-3, 0.0, -1e-3], &mut h);
        assert!((r.normal - 1000.0).abs() < 1e-9);
        assert!((r.force[0] + 500.0).abs() < 1e-9, "{:?}", r.force);
        assert!(r.slipping);
        // Slip = (1000 - 500) / K_s = 1 mm at 500 N: 0.5 J.
        assert!((r.dissipated - 0.5).abs() < 1e-12, "{}", r.dissipated);
    }
}
