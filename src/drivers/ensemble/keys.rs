//! The numbers an `[[ensemble.random]]` key names, on the typed inputs: a
//! key as errors spell it (`interface[0].strength.cohesion`,
//! `material[1].youngs_modulus`, `loads.gravity[2]`) is mapped to the
//! `&mut f64` of the [`Scene`] (or of a LEM file's [`LemParts`]) it names,
//! and a member is the mean input with its drawn values set there.
//!
//! A key names a real number the input carries: a field of type `f64`, or an
//! `Option<f64>` the file gives. Integers (`solver.max_steps`,
//! `analysis.slices`), strings and absent optional numbers are not keys
//! ([`UnknownKey`]). A scene's `[lem]` numbers (`lem.…`) are those
//! [`crate::lem::SceneLem::number_mut`] names.

use crate::error::SceneError;
use crate::lem::{Facing, LemInput, LemSection, LowerBound, Material, Mode, Zone};
use crate::model::spec::StrengthSection;
use crate::scene::{AnalysisSpec, Scene};

/// A key that names no real number of the input.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{key:?} is not a number of this file (keys are spelled as in errors: interface[0].strength.cohesion)")]
pub struct UnknownKey {
    pub key: String,
}

/// A key's segments: `interface[0].strength.cohesion` ->
/// `[("interface", Some(0)), ("strength", None), ("cohesion", None)]`.
pub fn segments(key: &str) -> Option<Vec<(&str, Option<usize>)>> {
    key.split('.')
        .map(|s| match s.split_once('[') {
            None if !s.is_empty() => Some((s, None)),
            None => None,
            Some((name, rest)) => Some((name, Some(rest.strip_suffix(']')?.parse().ok()?))),
        })
        .collect()
}

type Segs<'k> = [(&'k str, Option<usize>)];

fn strength<'a>(s: &'a mut StrengthSection, field: &str) -> Option<&'a mut f64> {
    s.number_mut(field)
}

fn analysis<'a>(a: &'a mut AnalysisSpec, segs: &Segs) -> Option<&'a mut f64> {
    match segs {
        [("circle", None), (f, None)] => {
            let c = a.circle.as_mut()?;
            match *f {
                "xc" => Some(&mut c.xc),
                "zc" => Some(&mut c.zc),
                "r" => Some(&mut c.r),
                _ => None,
            }
        }
        [("strength", None), (f, None)] => {
            let s = a.strength.as_mut()?;
            match *f {
                "cohesion" => Some(&mut s.cohesion),
                "friction_angle" => Some(&mut s.friction_angle),
                _ => None,
            }
        }
        [("y", None)] => a.y.as_mut(),
        [("min_segment", None)] => a.min_segment.as_mut(),
        _ => None,
    }
}

/// The number `key` names in a scene, its `[lem]` table included.
pub fn scene_number<'a>(s: &'a mut Scene, key: &str) -> Result<&'a mut f64, UnknownKey> {
    let unknown = || UnknownKey { key: key.to_string() };
    let segs = segments(key).ok_or_else(unknown)?;
    let found = match segs.as_slice() {
        [("perturbation", None), ("ratio", None)] => Some(&mut s.perturbation.ratio),
        [("material", Some(i)), (f, None)] => s.material.get_mut(*i).and_then(|m| match *f {
            "youngs_modulus" => Some(&mut m.youngs_modulus),
            "poisson_ratio" => Some(&mut m.poisson_ratio),
            "density" => Some(&mut m.density),
            _ => None,
        }),
        [("material", Some(i)), ("strength", None), (f, None)] => {
            s.material.get_mut(*i).and_then(|m| m.strength.as_mut()).and_then(|st| match *f {
                "cohesion" => Some(&mut st.cohesion),
                "friction_angle" => Some(&mut st.friction_angle),
                "tensile" => st.tensile.as_mut(),
                "dilation_angle" => Some(&mut st.dilation_angle),
                _ => None,
            })
        }
        [("joints", None), (f, None)] => match *f {
            "normal_modulus" => s.joints.normal_modulus.as_mut(),
            "shear_modulus" => s.joints.shear_modulus.as_mut(),
            "thickness" => s.joints.thickness.as_mut(),
            _ => None,
        },
        [("joints", None), ("strength", None), (f, None)] => s.joints.strength.as_mut().and_then(|st| strength(st, f)),
        [("interface", Some(i)), (f, None)] => s.interface.get_mut(*i).and_then(|j| match *f {
            "normal_modulus" => j.normal_modulus.as_mut(),
            "shear_modulus" => j.shear_modulus.as_mut(),
            "thickness" => j.thickness.as_mut(),
            _ => None,
        }),
        [("interface", Some(i)), ("strength", None), (f, None)] => {
            s.interface.get_mut(*i).and_then(|j| j.strength.as_mut()).and_then(|st| strength(st, f))
        }
        [("loads", None), ("gravity", Some(d))] => s.loads.gravity.get_mut(*d),
        [("solver", None), (f, None)] => match *f {
            "safety" => Some(&mut s.solver.safety),
            "local_damping" => Some(&mut s.solver.local_damping),
            "tolerance" => Some(&mut s.solver.tolerance),
            _ => None,
        },
        [("failure", None), ("sliding_displacement", None)] => {
            s.failure.as_mut().and_then(|f| f.sliding_displacement.as_mut())
        }
        [("failure", None), ("sliding_travel", None)] => s.failure.as_mut().and_then(|f| f.sliding_travel.as_mut()),
        [("runout", None), (f, None)] => s.runout.as_mut().and_then(|r| match *f {
            "duration" => Some(&mut r.duration),
            "local_damping" => Some(&mut r.local_damping),
            "rayleigh_ratio" => Some(&mut r.rayleigh_ratio),
            "rayleigh_frequency" => Some(&mut r.rayleigh_frequency),
            "safety" => Some(&mut r.safety),
            "tolerance" => r.tolerance.as_mut(),
            "max_penetration" => r.max_penetration.as_mut(),
            "rest_velocity" => Some(&mut r.rest_velocity),
            "rest_time" => Some(&mut r.rest_time),
            "frame_every" => r.frame_every.as_mut(),
            "stiffness_limit" => r.stiffness_limit.as_mut(),
            _ => None,
        }),
        [("runout", None), ("contact", None), (f, None)] => s.runout.as_mut().and_then(|r| match *f {
            "normal_stiffness" => r.contact.normal_stiffness.as_mut(),
            "shear_stiffness" => r.contact.shear_stiffness.as_mut(),
            "friction_angle" => r.contact.friction_angle.as_mut(),
            _ => None,
        }),
        [("water", None), (f, None)] => s.water.as_mut().and_then(|w| match *f {
            "rise" => Some(&mut w.rise),
            "unit_weight" => Some(&mut w.unit_weight),
            _ => None,
        }),
        [("water", None), ("surface", Some(i)), (f, None)] => {
            s.water.as_mut().and_then(|w| w.surface.get_mut(*i)).and_then(|p| match *f {
                "x" => Some(&mut p[0]),
                "z" => Some(&mut p[1]),
                _ => None,
            })
        }
        [("water", None), ("crack", Some(i)), ("level", None)] => {
            s.water.as_mut().and_then(|w| w.crack.get_mut(*i)).map(|c| &mut c.level)
        }
        [("analysis", None), rest @ ..] => s.analysis.as_mut().and_then(|a| analysis(a, rest)),
        [("lem", None), rest @ ..] => s.lem.as_mut().and_then(|l| l.number_mut(rest)),
        _ => None,
    };
    found.ok_or_else(unknown)
}

/// Where a LEM file's `[[material]]` went: the background (no zone) or the
/// `j`-th zone.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Slot {
    Background,
    Zone(usize),
}

/// A LEM file's input, open to its numbers: the parts of its
/// [`LemInput`] and where each `[[material]]` of the file went.
#[derive(Debug, Clone)]
pub struct LemParts {
    pub ground: Vec<[f64; 2]>,
    pub lower_bound: LowerBound,
    pub background: Option<Material>,
    pub zones: Vec<Zone>,
    pub facing: Facing,
    pub slices: usize,
    pub methods: Vec<crate::lem::Method>,
    pub mode: Mode,
    /// The file's `material[i]` is `slots[i]`.
    pub slots: Vec<Slot>,
    /// The file's `[water]`, carried unchanged into every member.
    pub water: crate::lem::Water,
}

impl LemParts {
    /// `slots`: one per `[[material]]` of the file, true for one with a `zone`.
    pub fn new(input: &LemInput, zoned: &[bool]) -> Self {
        let mut j = 0;
        let slots = zoned
            .iter()
            .map(|&z| {
                if z {
                    j += 1;
                    Slot::Zone(j - 1)
                } else {
                    Slot::Background
                }
            })
            .collect();
        let s = &input.section;
        LemParts {
            ground: s.ground().to_vec(),
            lower_bound: s.lower_bound().clone(),
            background: s.background().copied(),
            zones: s.zones().to_vec(),
            facing: s.facing(),
            slices: input.slices,
            methods: input.methods.clone(),
            mode: input.mode.clone(),
            slots,
            water: s.water().clone(),
        }
    }

    /// The number `key` names (keys as in the LEM file).
    pub fn number(&mut self, key: &str) -> Result<&mut f64, UnknownKey> {
        let unknown = || UnknownKey { key: key.to_string() };
        let segs = segments(key).ok_or_else(unknown)?;
        fn pair(r: &mut Option<[f64; 2]>, i: usize) -> Option<&mut f64> {
            r.as_mut().and_then(|r| r.get_mut(i))
        }
        let found = match (segs.as_slice(), &mut self.mode) {
            ([("section", None), ("z_min", None)], _) => match &mut self.lower_bound {
                LowerBound::Level(z) => Some(z),
                LowerBound::Polyline(_) => None,
            },
            ([("material", Some(i)), (f, None)], _) => {
                let m = match self.slots.get(*i) {
                    Some(Slot::Background) => self.background.as_mut(),
                    Some(Slot::Zone(j)) => self.zones.get_mut(*j).map(|z| &mut z.material),
                    None => None,
                };
                m.and_then(|m| match *f {
                    "cohesion" => Some(&mut m.cohesion),
                    "friction_angle" => Some(&mut m.friction_angle),
                    "unit_weight" => Some(&mut m.unit_weight),
                    _ => None,
                })
            }
            ([("circle", None), (f, None)], Mode::Circle(c)) => match *f {
                "xc" => Some(&mut c.xc),
                "zc" => Some(&mut c.zc),
                "r" => Some(&mut c.r),
                _ => None,
            },
            ([("search", None), (f, None)], Mode::Search(s)) => match *f {
                "min_depth" => s.min_depth.as_mut(),
                "min_width" => s.min_width.as_mut(),
                _ => None,
            },
            ([("water", None), (f, None)], _) => {
                let w = &mut self.water;
                match (*f, &mut w.pore) {
                    ("ru", crate::lem::Pore::Ru(r)) => Some(r),
                    ("crack_depth", _) => w.crack.as_mut().map(|c| &mut c.depth),
                    ("crack_fill", _) => w.crack.as_mut().map(|c| &mut c.fill),
                    // gamma_w of the file (the surface's is set from it when a member is built).
                    ("unit_weight", _) => Some(&mut w.unit_weight),
                    _ => None,
                }
            }
            ([("search", None), ("grid", None), (f, Some(i))], Mode::Search(s)) => {
                s.grid.as_mut().and_then(|g| match *f {
                    "x" => pair(&mut g.x, *i),
                    "z" => pair(&mut g.z, *i),
                    _ => None,
                })
            }
            ([("search", None), ("entry_exit", None), (f, Some(i))], Mode::Search(s)) => {
                s.entry_exit.as_mut().and_then(|e| match *f {
                    "exit" => pair(&mut e.exit, *i),
                    "entry" => pair(&mut e.entry, *i),
                    _ => None,
                })
            }
            _ => None,
        };
        found.ok_or_else(unknown)
    }

    /// The LEM input of these parts, checked as the file's would be (errors
    /// name the file's keys).
    pub fn input(&self) -> Result<LemInput, SceneError> {
        let file_key = |e: SceneError| match e {
            SceneError::Invalid { key, reason } => SceneError::Invalid { key: self.file_key(&key), reason },
            other => other,
        };
        let section = LemSection::new(
            self.ground.clone(),
            self.lower_bound.clone(),
            self.background,
            self.zones.clone(),
            Some(self.facing),
        )
        .and_then(|s| {
            let mut water = self.water.clone();
            if let crate::lem::Pore::Surface(p) = &mut water.pore {
                p.unit_weight = water.unit_weight;
            }
            s.with_water(water)
        })
        .map_err(file_key)?;
        match &self.mode {
            Mode::Circle(c) => {
                if !(c.xc.is_finite() && c.zc.is_finite() && c.r.is_finite() && c.r > 0.0) {
                    return Err(SceneError::invalid("circle", "xc, zc must be finite and r > 0"));
                }
            }
            Mode::Search(s) => {
                let ranges = [
                    ("search.grid.x", s.grid.and_then(|g| g.x)),
                    ("search.grid.z", s.grid.and_then(|g| g.z)),
                    ("search.entry_exit.exit", s.entry_exit.and_then(|e| e.exit)),
                    ("search.entry_exit.entry", s.entry_exit.and_then(|e| e.entry)),
                ];
                for (key, r) in ranges {
                    if r.is_some_and(|[a, b]| !(a.is_finite() && b.is_finite() && a <= b)) {
                        return Err(SceneError::invalid(key, "must be [low, high], finite, low <= high"));
                    }
                }
                for (key, v) in [("search.min_depth", s.min_depth), ("search.min_width", s.min_width)] {
                    if v.is_some_and(|x| !(x.is_finite() && x >= 0.0)) {
                        return Err(SceneError::invalid(key, "must be finite and >= 0 (m)"));
                    }
                }
            }
        }
        Ok(LemInput { section, slices: self.slices, methods: self.methods.clone(), mode: self.mode.clone() })
    }

    /// A section's key for a material (`material` the background,
    /// `material[j]` the j-th zone) as the file spells it (`material[i]`).
    fn file_key(&self, key: &str) -> String {
        let (slot, rest) = match key.strip_prefix("material") {
            Some(rest) if rest.is_empty() || rest.starts_with('.') => (Slot::Background, rest),
            Some(rest) => match rest.strip_prefix('[').and_then(|r| r.split_once(']')) {
                Some((j, rest)) => match j.parse() {
                    Ok(j) => (Slot::Zone(j), rest),
                    Err(_) => return key.to_string(),
                },
                None => return key.to_string(),
            },
            None => return key.to_string(),
        };
        match self.slots.iter().position(|s| *s == slot) {
            Some(i) => format!("material[{i}]{rest}"),
            None => key.to_string(),
        }
    }
}
