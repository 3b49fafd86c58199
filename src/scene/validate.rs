//! Semantic checks of a scene: each failure names its key.

use super::{JointMode, Scene};
use crate::error::SceneError;

fn finite_positive(key: &str, v: f64) -> Result<(), SceneError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(SceneError::invalid(key, format!("must be a finite positive number, got {v}")))
    }
}

fn stiffness_given(key: &str, [e, g, l]: [Option<f64>; 3]) -> Result<(), SceneError> {
    for (name, v) in [("normal_modulus", e), ("shear_modulus", g), ("thickness", l)] {
        match v {
            Some(v) => finite_positive(&format!("{key}.{name}"), v)?,
            None => return Err(SceneError::invalid(format!("{key}.{name}"), "required for springs")),
        }
    }
    Ok(())
}

fn strength(key: &str, st: &super::StrengthSection) -> Result<(), SceneError> {
    st.check().map_err(|(name, why)| SceneError::invalid(format!("{key}.strength.{name}"), why))
}

fn rock_strength(key: &str, st: &super::RockStrengthSection) -> Result<(), SceneError> {
    let key = format!("{key}.strength");
    for (name, v) in [("cohesion", Some(st.cohesion)), ("tensile", st.tensile)] {
        if let Some(v) = v.filter(|v| !(v.is_finite() && *v >= 0.0)) {
            return Err(SceneError::invalid(format!("{key}.{name}"), format!("must be finite and >= 0, got {v}")));
        }
    }
    let phi = st.friction_angle;
    if !(phi.is_finite() && (0.0..90.0).contains(&phi)) {
        return Err(SceneError::invalid(
            format!("{key}.friction_angle"),
            format!("must be in [0, 90) degrees, got {phi}"),
        ));
    }
    let psi = st.dilation_angle;
    if !(psi.is_finite() && (0.0..=phi).contains(&psi)) {
        return Err(SceneError::invalid(
            format!("{key}.dilation_angle"),
            format!("must be in [0, friction_angle = {phi}] degrees, got {psi}"),
        ));
    }
    if st.cohesion == 0.0 && phi == 0.0 {
        return Err(SceneError::invalid(key, "cohesion and friction_angle both 0: the material carries no shear"));
    }
    Ok(())
}

pub(super) fn validate(s: &Scene) -> Result<(), SceneError> {
    if let Some(e) = &s.ensemble {
        e.validate()?;
    }
    let p = &s.perturbation;
    if !(p.ratio.is_finite() && (0.0..0.5).contains(&p.ratio)) {
        return Err(SceneError::invalid("perturbation.ratio", format!("must be in [0, 0.5), got {}", p.ratio)));
    }
    if s.material.is_empty() {
        return Err(SceneError::invalid("material", "at least one [[material]] is required"));
    }
    for (i, m) in s.material.iter().enumerate() {
        let key = format!("material[{i}]");
        finite_positive(&format!("{key}.youngs_modulus"), m.youngs_modulus)?;
        finite_positive(&format!("{key}.density"), m.density)?;
        if !(m.poisson_ratio.is_finite() && m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5) {
            return Err(SceneError::invalid(
                format!("{key}.poisson_ratio"),
                format!("must be in (-1, 0.5), got {}", m.poisson_ratio),
            ));
        }
        if let Some(st) = &m.strength {
            rock_strength(&key, st)?;
        }
    }
    let j = &s.joints;
    if !j.group.is_empty() {
        return Err(SceneError::invalid(
            "joints.group",
            "[joints] is every interface not listed in [[interface]]: name a group in an [[interface]] table",
        ));
    }
    let any_springs = j.mode == JointMode::Springs || s.interface.iter().any(|i| i.mode == JointMode::Springs);
    if j.mode == JointMode::Springs || (any_springs && (j.normal_modulus.is_some() || j.thickness.is_some())) {
        stiffness_given("joints", j.moduli(j))?;
    }
    if let Some(st) = &j.strength {
        strength("joints", st)?;
        if j.mode == JointMode::Merged {
            return Err(SceneError::invalid("joints.strength", "a merged interface has no springs to break"));
        }
    }
    for (i, f) in s.interface.iter().enumerate() {
        if f.group.is_empty() {
            return Err(SceneError::invalid(format!("interface[{i}].group"), "missing: the surface physical group"));
        }
        if let Some(st) = &f.strength {
            strength(&format!("interface[{i}]"), st)?;
            if f.mode == JointMode::Merged {
                return Err(SceneError::invalid(
                    format!("interface[{i}].strength"),
                    "a merged interface has no springs to break",
                ));
            }
        }
        if f.mode == JointMode::Springs {
            stiffness_given(&format!("interface[{i}]"), f.moduli(j))?;
        }
    }
    for (i, b) in s.boundary.iter().enumerate() {
        if b.fix.is_empty() {
            return Err(SceneError::invalid(format!("boundary[{i}].fix"), "names no component"));
        }
    }
    if s.loads.gravity.iter().any(|g| !g.is_finite()) {
        return Err(SceneError::invalid("loads.gravity", "must be finite"));
    }
    if let Some(w) = &s.water {
        w.validate()?;
    }
    s.solver.validate()?;
    if let Some(f) = &s.failure {
        f.validate()?;
    }
    if let Some(r) = &s.runout {
        r.validate()?;
        // The runout's water follows the blocks by the phreatic surface's
        // pressure where each node is now (solver::runout); a crack's water
        // has no surface to follow (references/runout.md).
        if let Some(w) = s.water.as_ref().filter(|w| !w.crack.is_empty()) {
            return Err(SceneError::invalid(
                "water.crack[0]",
                format!(
                    "{:?}: a runout with water-filled cracks is not supported (their water has no surface to follow once the blocks move); give the water as a phreatic surface",
                    w.crack[0].group
                ),
            ));
        }
    }
    if let Some(a) = &s.analysis {
        let interfaces: Vec<&str> = s.interface.iter().map(|i| i.group.as_str()).collect();
        a.validate(&interfaces, s.lem.is_some())?;
    }
    if s.output.history_every == 0 {
        return Err(SceneError::invalid("output.history_every", "must be at least 1"));
    }
    Ok(())
}
