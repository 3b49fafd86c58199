//! Property-based fuzzing of user input, run in the suite: seeded random
//! mutations of valid MSH files (ASCII and binary) and scene files. Each input
//! must give `Ok` or a typed error, never a panic; an input that parses is
//! built into a model and stepped, so downstream code sees odd but valid input.
//!
//! `CDEM_FUZZ_ITERS=N` runs N mutations per target (default 1500 in the
//! suite). Inputs that ever panicked are kept in `tests/fuzz-regressions/`
//! with hand-made hostile inputs (`*-hand-*`), and replayed by
//! `regressions_do_not_panic`. The longest run is recorded
//! in `references/fuzz.md`.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;
use std::time::Instant;

use cdem::mesh::gmsh::parse_msh;
use cdem::mesh::perturb::SplitMix64;
use cdem::scene::Scene;

fn iterations() -> usize {
    std::env::var("CDEM_FUZZ_ITERS").ok().and_then(|v| v.parse().ok()).unwrap_or(1500)
}

const MSH_SEEDS: &[&str] = &[
    "verification/cases/column/column.msh",
    "tests/fixtures/column-binary.msh",
    "tests/fixtures/cube-tets.msh",
    "tests/fixtures/cube-prisms.msh",
    "tests/fixtures/cube-hex-sparse.msh",
];

const SCENE_SEEDS: &[&str] = &["verification/cases/column/column.toml", "verification/cases/column/column-merged.toml"];

const TOKENS: &[&str] = &[
    "0",
    "-1",
    "1e308",
    "-1e308",
    "nan",
    "inf",
    "4294967296",
    "18446744073709551616",
    "-0",
    "1e-320",
    "\"x\"",
    "[]",
    "{}",
];

fn mutate_bytes(rng: &mut SplitMix64, input: &[u8]) -> Vec<u8> {
    let mut v = input.to_vec();
    let n_mut = 1 + (rng.next_u64() % 4) as usize;
    for _ in 0..n_mut {
        if v.is_empty() {
            break;
        }
        let at = (rng.next_u64() as usize) % v.len();
        match rng.next_u64() % 6 {
            0 => v[at] = rng.next_u64() as u8,
            1 => v.truncate(at),
            2 => {
                let tok = TOKENS[(rng.next_u64() as usize) % TOKENS.len()];
                v.splice(at..at, tok.bytes());
            }
            3 => {
                // Replace a whitespace-delimited token.
                let start = v[..at].iter().rposition(|b| b.is_ascii_whitespace()).map_or(0, |p| p + 1);
                let end = v[at..].iter().position(|b| b.is_ascii_whitespace()).map_or(v.len(), |p| at + p);
                let tok = TOKENS[(rng.next_u64() as usize) % TOKENS.len()];
                v.splice(start..end, tok.bytes());
            }
            4 => {
                // Delete or duplicate a line.
                let start = v[..at].iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1);
                let end = v[at..].iter().position(|&b| b == b'\n').map_or(v.len(), |p| at + p + 1);
                if rng.next_u64().is_multiple_of(2) {
                    v.drain(start..end);
                } else {
                    let line: Vec<u8> = v[start..end].to_vec();
                    v.splice(end..end, line);
                }
            }
            _ => {
                let b = v[at];
                v[at] = if b.is_ascii_digit() { b'0' + (rng.next_u64() % 10) as u8 } else { b ^ 1 };
            }
        }
    }
    v
}

fn save_regression(kind: &str, input: &[u8]) -> String {
    let mut h: u64 = 0xcbf29ce484222325;
    for &b in input {
        h = (h ^ b as u64).wrapping_mul(0x100000001b3);
    }
    let path = format!("tests/fuzz-regressions/{kind}-{h:016x}");
    let _ = std::fs::write(&path, input);
    path
}

/// Parses a mesh and, if it parses, builds and steps a model on it.
fn exercise_msh(bytes: &[u8]) {
    if let Ok(mesh) = parse_msh(bytes) {
        let dir = std::env::temp_dir().join(format!("cdem-fuzz-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        let path = dir.join("m.msh");
        std::fs::write(&path, bytes).unwrap();
        let Some(vol) = mesh.groups.iter().find(|g| g.dim == 3) else { return };
        let text = format!(
            "[mesh]\nfile = \"m.msh\"\n[[material]]\ngroup = {:?}\nyoungs_modulus = 1e8\npoisson_ratio = 0.25\ndensity = 2000.0\n[joints]\nnormal_modulus = 1e10\nshear_modulus = 4e9\nthickness = 1.0\n[solver]\nmax_steps = 20\n",
            vol.name
        );
        if let Ok(scene) = Scene::from_toml(&text, &dir, Path::new("fuzz.toml")) {
            let _ = cdem::drivers::run_scene(&scene, &mut |_, _| {});
        }
    }
}

fn exercise_scene(text: &str, base: &Path) {
    if let Ok(mut scene) = Scene::from_toml(text, base, Path::new("fuzz.toml")) {
        scene.solver.max_steps = Some(scene.solver.max_steps.unwrap_or(20).min(20));
        let _ = cdem::drivers::run_scene(&scene, &mut |_, _| {});
    }
}

#[test]
fn mutated_msh_files_never_panic() {
    let seeds: Vec<Vec<u8>> = MSH_SEEDS.iter().map(|p| std::fs::read(p).unwrap()).collect();
    let mut rng = SplitMix64::new(0x5eed_0001);
    let t0 = Instant::now();
    let mut panics = Vec::new();
    for i in 0..iterations() {
        let input = mutate_bytes(&mut rng, &seeds[i % seeds.len()]);
        if catch_unwind(AssertUnwindSafe(|| exercise_msh(&input))).is_err() {
            panics.push(save_regression("msh", &input));
        }
    }
    println!("msh fuzz: {} inputs in {:.1} s, {} panics", iterations(), t0.elapsed().as_secs_f64(), panics.len());
    assert!(panics.is_empty(), "panicking inputs saved: {panics:?}");
}

#[test]
fn mutated_scene_files_never_panic() {
    let seeds: Vec<String> = SCENE_SEEDS.iter().map(|p| std::fs::read_to_string(p).unwrap()).collect();
    let base = Path::new("verification/cases/column");
    let mut rng = SplitMix64::new(0x5eed_0002);
    let t0 = Instant::now();
    let mut panics = Vec::new();
    for i in 0..iterations() {
        let input = mutate_bytes(&mut rng, seeds[i % seeds.len()].as_bytes());
        let text = String::from_utf8_lossy(&input).into_owned();
        if catch_unwind(AssertUnwindSafe(|| exercise_scene(&text, base))).is_err() {
            panics.push(save_regression("scene", text.as_bytes()));
        }
    }
    println!("scene fuzz: {} inputs in {:.1} s, {} panics", iterations(), t0.elapsed().as_secs_f64(), panics.len());
    assert!(panics.is_empty(), "panicking inputs saved: {panics:?}");
}

#[test]
fn regressions_do_not_panic() {
    let mut replayed = 0;
    for entry in std::fs::read_dir("tests/fuzz-regressions").unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let bytes = std::fs::read(&path).unwrap();
        let r = if name.starts_with("msh-") {
            catch_unwind(AssertUnwindSafe(|| exercise_msh(&bytes)))
        } else if name.starts_with("scene-") {
            let text = String::from_utf8_lossy(&bytes).into_owned();
            catch_unwind(AssertUnwindSafe(|| exercise_scene(&text, Path::new("verification/cases/column"))))
        } else {
            continue;
        };
        assert!(r.is_ok(), "{name} panics again");
        replayed += 1;
    }
    // A replay of an empty folder checks nothing: the hand-made hostile
    // inputs (`*-hand-*`) are always there.
    assert!(replayed >= 3, "replayed only {replayed} inputs from tests/fuzz-regressions");
}
