//! The tutorial (`docs/tutorial.md`) cannot rot: this test reads it, runs every
//! command of its ```sh blocks through the built binary and checks what they print.
//!
//! - Every non-comment line of a ```sh block must be `cargo run --release -- ARGS`, one
//!   command per block; it runs as `cdem ARGS` from the repository root. Its `--out`
//!   path must lie under `out/tutorial/` and is redirected into a temporary directory
//!   under `target/` (a command without `--out`, `mesh`, gets one there).
//! - Each command must exit with code 0.
//! - The first fenced block after a command is the output the page shows; the line
//!   `Checked by the test: `A`, `B`` after it lists texts that must appear both in that
//!   shown output and in what the command prints now (standard output and error).
//! - The `mesh` step runs only with gmsh on PATH (in CI, `CI=true`, gmsh must be there);
//!   its mesh, written into the temporary directory, must equal the committed one
//!   (as `tests/gmsh_regen.rs` also checks for every committed mesh).
//! - Every `out/tutorial/...` path the page names (files to open) must have been written.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use cdem::mesh::gmsh::{gmsh_available, mesh_drift, read_msh};

const DOC: &str = "docs/tutorial.md";
const PREFIX: &str = "cargo run --release -- ";
const CHECKED: &str = "Checked by the test:";
const OUT: &str = "out/tutorial/";

/// One command of the page with the output shown after it and the texts to check.
#[derive(Debug)]
struct Step {
    line: usize,
    args: Vec<String>,
    shown: Option<String>,
    checks: Vec<String>,
}

fn parse(doc: &str) -> Vec<Step> {
    let mut steps: Vec<Step> = Vec::new();
    let mut lines = doc.lines().enumerate();
    while let Some((i, line)) = lines.next() {
        let n = i + 1;
        if let Some(lang) = line.strip_prefix("```") {
            let mut body = Vec::new();
            for (_, l) in lines.by_ref() {
                if l.starts_with("```") {
                    break;
                }
                body.push(l);
            }
            if lang.trim() == "sh" {
                let commands: Vec<&str> =
                    body.iter().map(|l| l.trim()).filter(|l| !l.is_empty() && !l.starts_with('#')).collect();
                assert_eq!(commands.len(), 1, "{DOC}:{n}: a sh block holds exactly one command, found {commands:?}");
                let args = commands[0].strip_prefix(PREFIX).unwrap_or_else(|| {
                    panic!("{DOC}:{n}: `{}` does not start with `{PREFIX}`: the test would not run it", commands[0])
                });
                steps.push(Step {
                    line: n,
                    args: args.split_whitespace().map(String::from).collect(),
                    shown: None,
                    checks: Vec::new(),
                });
            } else if let Some(step) = steps.last_mut().filter(|s| s.shown.is_none()) {
                step.shown = Some(body.join("\n"));
            }
        } else if let Some(rest) = line.strip_prefix(CHECKED) {
            let step = steps.last_mut().unwrap_or_else(|| panic!("{DOC}:{n}: `{CHECKED}` before any command"));
            assert!(
                step.checks.is_empty(),
                "{DOC}:{n}: a second `{CHECKED}` line for the command of line {}",
                step.line
            );
            step.checks = rest.split('`').skip(1).step_by(2).map(String::from).collect();
            assert!(!step.checks.is_empty(), "{DOC}:{n}: `{CHECKED}` lists no `text`");
        }
    }
    steps
}

/// Every `out/tutorial/...` path the page names, without a trailing period.
fn named_outputs(doc: &str) -> Vec<String> {
    let mut paths: Vec<String> = doc
        .match_indices(OUT)
        .map(|(i, _)| {
            let rest = &doc[i..];
            let end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || "_-./".contains(c))).unwrap_or(rest.len());
            rest[..end].trim_end_matches('.').to_string()
        })
        .collect();
    paths.sort();
    paths.dedup();
    paths
}

fn note(text: &str) {
    // Straight to stderr: the test harness would capture `eprintln!`.
    let _ = writeln!(std::io::stderr(), "{text}");
}

#[test]
fn every_tutorial_command_runs_and_prints_what_the_page_shows() {
    let t0 = Instant::now();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let doc = std::fs::read_to_string(root.join(DOC)).expect("docs/tutorial.md");
    let steps = parse(&doc);
    for sub in ["mesh", "run", "fem", "lem", "srm", "ensemble"] {
        assert!(steps.iter().any(|s| s.args[0] == sub), "{DOC} has no `cdem {sub}` step");
    }
    let tmp = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tutorial");
    let _ = std::fs::remove_dir_all(&tmp);
    std::fs::create_dir_all(&tmp).expect("temporary directory");
    let in_tmp = |path: &str| -> PathBuf {
        let rest = path
            .strip_prefix(OUT)
            .unwrap_or_else(|| panic!("{DOC}: `{path}` is not under `{OUT}`: the tutorial writes only there"));
        tmp.join(rest)
    };

    let mut ran = 0;
    for step in &steps {
        let at = format!("{DOC}:{} (`cdem {}`)", step.line, step.args.join(" "));
        let shown = step.shown.as_deref().unwrap_or_else(|| panic!("{at}: no output shown after the command"));
        assert!(!step.checks.is_empty(), "{at}: no `{CHECKED}` line after its output");
        for check in &step.checks {
            assert!(shown.contains(check.as_str()), "{at}: the output shown lacks its checked text `{check}`");
        }

        let mut args = step.args.clone();
        let mut committed_mesh = None;
        if args[0] == "mesh" {
            if !gmsh_available() {
                assert!(
                    std::env::var("CI").as_deref() != Ok("true"),
                    "{at}: gmsh must run in CI, but it is not on PATH"
                );
                note(&format!("note: gmsh is not on PATH; skipping {at}"));
                continue;
            }
            committed_mesh = Some(root.join(&args[1]).with_extension("msh"));
        }
        let out_at = match args.iter().position(|a| a == "--out") {
            Some(i) => {
                args[i + 1] = in_tmp(&args[i + 1]).display().to_string();
                i
            }
            // `cdem mesh GEO` writes beside the .geo: here into the temporary directory.
            None if committed_mesh.is_some() => {
                let name = Path::new(&args[1]).with_extension("msh").file_name().expect("a .geo file name").to_owned();
                args.push("--out".into());
                args.push(tmp.join(name).display().to_string());
                args.len() - 2
            }
            None => panic!("{at}: no `--out {OUT}...`: the command would write into the repository"),
        };

        let t = Instant::now();
        ran += 1;
        let output = Command::new(env!("CARGO_BIN_EXE_cdem")).args(&args).current_dir(root).output().expect("run cdem");
        let printed = format!("{}{}", String::from_utf8_lossy(&output.stdout), String::from_utf8_lossy(&output.stderr));
        note(&format!("{at}: {:.1} s", t.elapsed().as_secs_f64()));
        assert_eq!(output.status.code(), Some(0), "{at}: exit code\n{printed}");
        for check in &step.checks {
            assert!(printed.contains(check.as_str()), "{at}: prints no `{check}` now; it printed:\n{printed}");
        }
        if let Some(committed) = committed_mesh {
            let fresh = PathBuf::from(&args[out_at + 1]);
            let a = read_msh(&committed).unwrap_or_else(|e| panic!("{}: {e}", committed.display()));
            let b = read_msh(&fresh).unwrap_or_else(|e| panic!("{}: {e}", fresh.display()));
            if let Some(drift) = mesh_drift(&a, &b, 1e-9) {
                panic!("{at}: the committed {} differs from what gmsh makes now: {drift}", committed.display());
            }
        }
    }

    for path in named_outputs(&doc) {
        assert!(in_tmp(&path).exists(), "{DOC} names `{path}`, which the commands did not write");
    }
    let _ = std::fs::remove_dir_all(&tmp);
    note(&format!("tutorial: ran {ran} of {} commands in {:.1} s", steps.len(), t0.elapsed().as_secs_f64()));
}
