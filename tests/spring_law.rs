//! The spring force law, eq. 15-18 (docs/method.md section 2), on hand-worked values.

use cdem::physics::spring::{
    mohr_coulomb, spring_force, spring_forces, spring_stiffness, tension_cutoff, SpringState, Springs,
};

#[test]
fn eq16_stiffness_is_modulus_times_area_over_thickness() {
    let (kn, ks) = spring_stiffness(3.0e10, 1.2e10, 0.5, 2.0);
    assert_eq!(kn, 3.0e10 * 0.5 / 2.0);
    assert_eq!(ks, 1.2e10 * 0.5 / 2.0);
}

#[test]
fn eq15_splits_relative_displacement_into_opening_and_shear() {
    // n = z, d = (3, 4, 2) mm, no slip: d_n = 2 mm (opening), d_s = (3, 4, 0) mm.
    let (f_n, f_s) = spring_force(100.0, 10.0, [0.0, 0.0, 1.0], [3e-3, 4e-3, 2e-3], [0.0; 3]);
    assert!((f_n - 0.2).abs() < 1e-15);
    assert!((f_s[0] - 0.03).abs() < 1e-15 && (f_s[1] - 0.04).abs() < 1e-15 && f_s[2].abs() < 1e-15);
    // Plastic slip is subtracted from the shear displacement only.
    let (f_n2, f_s2) = spring_force(100.0, 10.0, [0.0, 0.0, 1.0], [3e-3, 4e-3, 2e-3], [1e-3, 0.0, 0.0]);
    assert_eq!(f_n2, f_n);
    assert!((f_s2[0] - 0.02).abs() < 1e-15);
}

#[test]
fn eq17_tension_cutoff_at_tensile_strength_times_area() {
    assert!(tension_cutoff(1000.0, 1.0e3, 1.0));
    assert!(!tension_cutoff(999.0, 1.0e3, 1.0));
    assert!(!tension_cutoff(-5.0e6, 1.0e3, 1.0), "compression never breaks in tension");
}

#[test]
fn eq18_mohr_coulomb_limits_shear_to_friction_after_slip() {
    let tan_phi = 18f64.to_radians().tan();
    // P = 100 kN, c A = 16 kN: limit 100 tan(18) + 16 = 48.49 kN.
    assert_eq!(mohr_coulomb(-100e3, 48e3, tan_phi, 16e3, 1.0), None);
    let after = mohr_coulomb(-100e3, 49e3, tan_phi, 16e3, 1.0).unwrap();
    assert!((after - 100e3 * tan_phi).abs() < 1e-9, "cohesion is lost: {after}");
    // In tension P = 0: only cohesion holds it.
    assert!(mohr_coulomb(10.0, 16.1e3, tan_phi, 16e3, 1.0).is_some());
}

#[test]
fn spring_forces_are_equal_and_opposite_and_resist_the_motion() {
    let springs = Springs {
        a: vec![0],
        b: vec![1],
        normal: vec![[1.0, 0.0, 0.0]],
        area: vec![1.0],
        kn: vec![1.0e6],
        ks: vec![1.0e5],
        interface: vec![0],
    };
    let state = SpringState::new(1);
    // Node b moved +1 mm in x (opening) and +2 mm in y (shear).
    let u = [0.0, 0.0, 0.0, 1e-3, 2e-3, 0.0];
    let mut f = [0.0; 6];
    spring_forces(&springs, &state, &u, &mut f);
    // Internal (restoring) force on b is +K d; on a, -K d.
    assert!((f[3] - 1.0e3).abs() < 1e-9 && (f[4] - 200.0).abs() < 1e-9);
    for d in 0..3 {
        assert!((f[d] + f[3 + d]).abs() < 1e-12);
    }
}
