//! The Mohr-Coulomb rock mass against closed forms (references/plastic.md).

use cdem::harness::suite::plastic::compression;
use cdem::physics::material::RockStrength;

#[test]
fn one_plastic_hexahedron_carries_the_mohr_coulomb_limit_in_plane_strain_compression() {
    let strength = RockStrength { cohesion: 1e5, tan_phi: 30f64.to_radians().tan(), tensile: f64::INFINITY, tan_psi: 0.0 };
    for confinement in [0.0, 1e5, 1e6] {
        let r = compression(strength, confinement, 200, 2e-5);
        eprintln!("{r:?} error {:.2e}", r.error());
        assert!(r.error() < 1e-6, "{r:?}");
    }
}
