//! The kernels' two instruction sets (`cdem::simd`) give the same bits:
//! `cdem run` with `CDEM_SIMD=baseline` (SSE2 on x86-64) and with the
//! default (AVX2 where the CPU has it) writes the same files, byte for byte
//! but for the wall time, on the paper slope with plastic blocks and every
//! interface breakable (a plastic cell's pass, the screens' condensed
//! force, the block masses' products) and on the slip-surface slope
//! (elastic blocks: the condensed force). A value of `CDEM_SIMD` it does not
//! know is an input error.

use std::path::{Path, PathBuf};
use std::process::Command;

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cdem-simd-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// The scene `dir/file` with its mesh path made absolute and 300 phase-2
/// steps, written into `into`.
fn short_scene(dir: &str, file: &str, into: &Path) -> PathBuf {
    let text = std::fs::read_to_string(Path::new(dir).join(file)).unwrap();
    let line = text.lines().find(|l| l.starts_with("file = ")).expect("the scene's mesh line").to_string();
    let rel = line.trim_start_matches("file = ").trim_matches('"');
    let mesh = std::fs::canonicalize(Path::new(dir).join(rel)).unwrap();
    let text = text.replace(&line, &format!("file = {:?}", mesh.to_str().unwrap()));
    // `[failure] max_steps = 300`, replacing the scene's own budget.
    let (head, failure) = text.split_once("[failure]").unwrap_or((&text, ""));
    let mut section = true;
    let kept: Vec<&str> = failure
        .lines()
        .filter(|l| {
            section &= !l.starts_with('[');
            !(section && l.starts_with("max_steps"))
        })
        .collect();
    let text = format!("{head}\n[failure]\nmax_steps = 300{}\n", kept.join("\n"));
    std::fs::create_dir_all(into).unwrap();
    let scene = into.join(file);
    std::fs::write(&scene, text).unwrap();
    scene
}

fn run(scene: &Path, out: &Path, simd: &str) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_cdem"))
        .env("CDEM_SIMD", simd)
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap()
}

/// Every file of `a` and `b`, `summary.json` without its `wall_s`.
fn assert_same_outputs(a: &Path, b: &Path) {
    let mut names: Vec<_> = std::fs::read_dir(a).unwrap().map(|e| e.unwrap().file_name()).collect();
    names.sort();
    assert!(names.len() >= 3, "{names:?}");
    for name in names {
        let (x, y) = (std::fs::read(a.join(&name)).unwrap(), std::fs::read(b.join(&name)).unwrap());
        if name == "summary.json" {
            let parse = |t: &[u8]| {
                let mut v: serde_json::Value = serde_json::from_slice(t).unwrap();
                v.as_object_mut().unwrap().remove("wall_s");
                v
            };
            assert_eq!(parse(&x), parse(&y), "summary.json differs between the instruction sets");
        } else {
            assert!(x == y, "{} differs between the instruction sets", name.to_string_lossy());
        }
    }
}

fn both_instruction_sets_agree(name: &str, dir: &str, file: &str) {
    if !cdem::simd::cpu_has_avx2() {
        eprintln!("this CPU has no AVX2: both runs take the baseline kernels");
    }
    let root = temp_dir(name);
    let scene = short_scene(dir, file, &root);
    let (auto, baseline) = (root.join("auto"), root.join("baseline"));
    for (out, simd) in [(&auto, "auto"), (&baseline, "baseline")] {
        let o = run(&scene, out, simd);
        // Exit code 3: the 300 steps ran out before phase 2 decided, as asked.
        assert_eq!(o.status.code(), Some(3), "CDEM_SIMD={simd}: {}", String::from_utf8_lossy(&o.stderr));
    }
    assert_same_outputs(&auto, &baseline);
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn plastic_blocks_give_the_same_bits_with_either_instruction_set() {
    both_instruction_sets_agree("plastic", "verification/plastic/paper-slope", "paper-slope.toml");
}

#[test]
fn elastic_blocks_give_the_same_bits_with_either_instruction_set() {
    both_instruction_sets_agree("elastic", "verification/cases/slope-slip", "slope-slip.toml");
}

#[test]
fn an_unknown_instruction_set_is_an_input_error() {
    let root = temp_dir("unknown");
    let scene = short_scene("verification/cases/slope-slip", "slope-slip.toml", &root);
    let o = run(&scene, &root.join("out"), "avx512");
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("CDEM_SIMD=\"avx512\"") && err.contains("baseline"), "{err}");
    assert!(!root.join("out").exists());
    let _ = std::fs::remove_dir_all(&root);
}
