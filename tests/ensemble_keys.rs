//! Every `[[ensemble.random]]` key reaches the member: for each number of
//! each verification scene and LEM file (and a few numbers they leave at
//! their defaults), an ensemble drawing that key to a distinctive value
//! (`std_dev = 0`) builds a member whose typed input — the scene the model
//! and the solver are built from, and its LEM input — equals the file read
//! with that number written in, and differs from the mean input. The numbers
//! that are not keys are the integer settings only.

use std::path::{Path, PathBuf};

use cdem::drivers::ensemble::{EnsembleInput, MemberInput};
use cdem::lem::LemInput;
use cdem::scene::Scene;
use cdem::SceneError;

/// Integer settings: numbers of a file that no draw may replace.
const INTEGER_KEYS: [&str; 16] = [
    "perturbation.seed",
    "runout.row_every",
    "solver.max_steps",
    "failure.max_steps",
    "failure.stage_every",
    "output.frame_every",
    "output.history_every",
    "analysis.stations",
    "analysis.slices",
    "lem.slices",
    "search.grid.nx",
    "search.grid.nz",
    "search.grid.radii",
    "search.entry_exit.n_exit",
    "search.entry_exit.n_entry",
    "search.entry_exit.radii",
];

/// A LEM file's section plane through its mesh: the mesh is cut once, when
/// the ensemble is loaded, as before the typed members.
const READ_ONCE: [&str; 1] = ["section.y_plane"];

/// Numbers a scene may leave at their defaults that are keys all the same.
const DEFAULTED: [&str; 7] = [
    "perturbation.ratio",
    "solver.safety",
    "solver.local_damping",
    "solver.tolerance",
    "loads.gravity[0]",
    "loads.gravity[1]",
    "loads.gravity[2]",
];

/// Numbers the verification files leave out, added to copies of three of
/// them: the optional strengths and moduli of a scene, `[analysis]`'s, a
/// scene's `[lem]`'s, and a LEM file's search ranges and zones (the zoned
/// material first: a file's `material[0]` is then the section's zone 0 and
/// `material[1]` its background).
const EXTRAS: [(&str, &str); 3] = [
    (
        "cases/slope-slip/slope-slip.toml",
        r#"
        joints = { strength = { tensile = 1e3, cohesion = 2e3, friction_angle = 25.0 } }
        interface = [{ group = "slip", normal_modulus = 1e11, shear_modulus = 3.85e10, thickness = 1.0,
                       strength = { tensile = 16.0e3, cohesion = 16.0e3, friction_angle = 18.0 } }]
        analysis = { circle = { xc = 24.0, zc = 63.2, r = 43.4 }, y = 0.5, min_segment = 1.0, interface = "slip" }
        "#,
    ),
    ("cases/slope/slope.toml", "lem = { z_min = 5.0, search = { min_depth = 0.5 } }"),
    (
        "lem/paper-slope.toml",
        r#"
        material = [{ cohesion = 20e3, friction_angle = 25.0, unit_weight = 21e3,
                      zone = [[20.0, 20.0], [70.0, 20.0], [70.0, 28.0], [20.0, 28.0]] },
                    { cohesion = 16.0e3, friction_angle = 18.0, unit_weight = 20.6e3 }]
        search = { min_depth = 0.5, min_width = 2.0, grid = { x = [10.0, 40.0], z = [40.0, 80.0] },
                   entry_exit = { exit = [15.0, 25.0], entry = [45.0, 70.0] } }
        "#,
    ),
];

/// `extra` written over `t` (tables merged, other values replaced).
fn merge(t: &mut toml::Table, extra: toml::Table) {
    for (k, v) in extra {
        match (t.get_mut(&k), v) {
            (Some(toml::Value::Table(a)), toml::Value::Table(b)) => merge(a, b),
            (_, v) => {
                t.insert(k, v);
            }
        }
    }
}

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            files(&p, out);
        } else if p.extension().is_some_and(|e| e == "toml") {
            out.push(p);
        }
    }
}

/// The numbers of a table as keys (`a.b[0].c`), one index per segment.
fn numbers(prefix: &str, t: &toml::Table, out: &mut Vec<(String, f64, bool)>) {
    for (k, v) in t {
        let key = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
        leaf(&key, v, out);
    }
}

fn leaf(key: &str, v: &toml::Value, out: &mut Vec<(String, f64, bool)>) {
    match v {
        toml::Value::Float(f) => out.push((key.to_string(), *f, false)),
        toml::Value::Integer(n) => out.push((key.to_string(), *n as f64, true)),
        toml::Value::Table(t) => numbers(key, t, out),
        toml::Value::Array(a) => {
            for (i, v) in a.iter().enumerate() {
                // One index per segment: an array of arrays has no keys.
                if !v.is_array() {
                    leaf(&format!("{key}[{i}]"), v, out);
                }
            }
        }
        _ => {}
    }
}

/// Writes `value` at `key`, making the tables on the way.
fn set(t: &mut toml::Table, key: &str, value: toml::Value) {
    let mut segs = key.split('.').peekable();
    let mut t = t;
    while let Some(s) = segs.next() {
        let (name, index) = match s.split_once('[') {
            Some((n, i)) => (n, Some(i.trim_end_matches(']').parse::<usize>().unwrap())),
            None => (s, None),
        };
        let last = segs.peek().is_none();
        let slot = match index {
            None if last => {
                t.insert(name.to_string(), value);
                return;
            }
            None => t.entry(name).or_insert_with(|| toml::Value::Table(Default::default())),
            Some(i) => {
                let default = if name == "gravity" { vec![0.0.into(), 0.0.into(), (-9.81).into()] } else { vec![] };
                let a = t.entry(name).or_insert(toml::Value::Array(default)).as_array_mut().unwrap();
                if last {
                    a[i] = value;
                    return;
                }
                &mut a[i]
            }
        };
        t = slot.as_table_mut().unwrap();
    }
}

/// The file's paths made absolute, so that the variants can live elsewhere.
fn absolute(t: &mut toml::Table, dir: &Path) {
    for (table, key) in [("mesh", "file"), ("section", "from_mesh")] {
        if let Some(v) = t.get_mut(table).and_then(|s| s.get_mut(key)) {
            *v = dir.join(v.as_str().unwrap()).display().to_string().into();
        }
    }
}

enum Built {
    Scene(Box<Scene>, Option<Box<LemInput>>),
    Lem(Box<LemInput>),
}

impl Built {
    fn of(member: &MemberInput, has_lem: bool) -> Self {
        match member {
            MemberInput::Scene(s) => Built::Scene(s.clone(), has_lem.then(|| Box::new(member.lem_input().unwrap()))),
            MemberInput::Lem(l) => Built::Lem(l.clone()),
        }
    }
    fn read(text: &str, path: &Path, is_scene: bool, has_lem: bool) -> cdem::Result<Self> {
        let dir = path.parent().unwrap();
        Ok(if is_scene {
            let s = Scene::from_toml(text, dir, path)?;
            let lem = if has_lem { Some(Box::new(cdem::drivers::scene_lem_input(&s)?)) } else { None };
            Built::Scene(Box::new(s), lem)
        } else {
            Built::Lem(Box::new(LemInput::from_toml(text, dir, path)?))
        })
    }
    fn text(&self) -> String {
        match self {
            Built::Scene(s, l) => format!("{s:?} {l:?}"),
            Built::Lem(l) => format!("{l:?}"),
        }
    }
}

#[test]
fn every_ensemble_random_key_reaches_the_members_model() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let tmp = std::env::temp_dir().join(format!("cdem-ensemble-keys-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let mut found = Vec::new();
    files(&root.join("verification"), &mut found);
    found.sort();
    let mut paths: Vec<(PathBuf, Option<&str>)> = found.into_iter().map(|p| (p, None)).collect();
    paths.extend(EXTRAS.iter().map(|(p, extra)| (root.join("verification").join(p), Some(*extra))));
    let (mut reached, mut files_seen) = (std::collections::BTreeSet::new(), 0);
    for (f, (path, extra)) in paths.iter().enumerate() {
        let text = std::fs::read_to_string(path).unwrap();
        let Ok(mut table) = text.parse::<toml::Table>() else { continue };
        if let Some(extra) = extra {
            merge(&mut table, extra.parse().unwrap());
        }
        let is_scene = table.contains_key("mesh");
        if !is_scene && !table.contains_key("section") {
            continue;
        }
        absolute(&mut table, path.parent().unwrap());
        table.remove("ensemble");
        let has_lem = !is_scene || table.contains_key("lem");
        let mut keys = Vec::new();
        numbers("", &table, &mut keys);
        if is_scene {
            for k in DEFAULTED {
                if !keys.iter().any(|(key, ..)| key == k) {
                    let v = match k {
                        "perturbation.ratio" => 0.0,
                        "solver.safety" => 0.9,
                        "solver.local_damping" => 0.8,
                        "solver.tolerance" => 1e-5,
                        "loads.gravity[2]" => -9.81,
                        _ => 0.0,
                    };
                    keys.push((k.to_string(), v, false));
                }
            }
        }
        files_seen += 1;
        let name = format!("{f}-{}", path.file_stem().unwrap().to_string_lossy());
        for (n, (key, v, integer)) in keys.iter().enumerate() {
            // A distinctive value the file would accept.
            let candidates = [v * 1.0001 + 1e-6, v * 0.9999 - 1e-6, v * 0.9999, v * 1.0001, 0.25];
            let file = tmp.join(format!("{name}-{n}.toml"));
            let mut expected = None;
            for value in candidates {
                let mut t = table.clone();
                set(&mut t, key, toml::Value::Float(value));
                if let Ok(b) = Built::read(&toml::to_string(&t).unwrap(), &file, is_scene, has_lem) {
                    expected = Some((value, t, b));
                    break;
                }
            }
            let mut t = table.clone();
            let value = expected.as_ref().map_or(*v, |e| e.0);
            let mut random = toml::Table::new();
            random.insert("key".into(), key.clone().into());
            random.insert("std_dev".into(), 0.0.into());
            random.insert("mean".into(), value.into());
            let mut ensemble = toml::Table::new();
            ensemble.insert("members".into(), 1.into());
            ensemble.insert("random".into(), toml::Value::Array(vec![random.into()]));
            ensemble.insert("analyses".into(), vec![toml::Value::from(if is_scene { "cdem" } else { "lem" })].into());
            t.insert("ensemble".into(), ensemble.into());
            std::fs::write(&file, toml::to_string(&t).unwrap()).unwrap();
            let input = match EnsembleInput::load(&file) {
                Ok(i) => i,
                Err(cdem::Error::Scene(SceneError::Invalid { key: k, reason })) if k == "ensemble.random[0].key" => {
                    let bare = key.strip_prefix("lem.").unwrap_or(key);
                    assert!(
                        READ_ONCE.contains(&key.as_str())
                            || *integer && (INTEGER_KEYS.contains(&key.as_str()) || INTEGER_KEYS.contains(&bare)),
                        "{}: {key} refused: {reason}",
                        path.display()
                    );
                    continue;
                }
                Err(e) => panic!("{}: {key}: {e}", path.display()),
            };
            assert!(!INTEGER_KEYS.contains(&key.as_str()), "{}: the integer {key} accepted", path.display());
            let Some((_, mut t, want)) = expected else {
                panic!("{}: no value of {key} near {v} is valid", path.display())
            };
            let (seed, draws) = input.draws(1, 0).unwrap();
            assert_eq!(draws[0].value, value, "{key}: std_dev 0 draws the mean");
            let got = Built::of(&input.member_input(seed, &draws).unwrap(), has_lem);
            // The file as read, with the member's seed: what the member must equal.
            let want = if t.contains_key("perturbation") {
                set(&mut t, "perturbation.seed", toml::Value::Integer(seed as i64));
                Built::read(&toml::to_string(&t).unwrap(), &file, is_scene, has_lem).unwrap()
            } else {
                want
            };
            assert_eq!(got.text(), want.text(), "{}: {key}", path.display());
            let mut mean = table.clone();
            if mean.contains_key("perturbation") {
                set(&mut mean, "perturbation.seed", toml::Value::Integer(seed as i64));
            }
            let mean = Built::read(&toml::to_string(&mean).unwrap(), &file, is_scene, has_lem).unwrap();
            assert_ne!(got.text(), mean.text(), "{}: {key} = {value} does not reach the member", path.display());
            reached.insert(key.strip_prefix("lem.").map_or(key.clone(), |k| format!("lem.{k}")));
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
    eprintln!("{} keys reached in {files_seen} files: {reached:?}", reached.len());
    assert!(files_seen >= 10, "{files_seen} files");
    // The keys of the docs and verification cases are among those reached.
    for k in [
        "material[0].cohesion",
        "material[0].youngs_modulus",
        "interface[0].strength.cohesion",
        "interface[0].strength.friction_angle",
        "analysis.strength.cohesion",
        "lem.material[0].cohesion",
        "loads.gravity[2]",
        "solver.tolerance",
        "joints.strength.cohesion",
        "interface[0].normal_modulus",
        "analysis.y",
        "analysis.min_segment",
        "lem.z_min",
        "lem.search.min_depth",
        "material[1].cohesion",
        "search.grid.x[0]",
        "search.entry_exit.entry[1]",
        "search.min_width",
    ] {
        assert!(reached.contains(k), "{k} not reached (reached: {reached:?})");
    }
}
