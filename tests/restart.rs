//! `cdem srm` stopped and resumed gives the same files as a run never
//! stopped: killed with SIGKILL at seeded random moments (and inside a
//! checkpoint's write), stopped by SIGTERM and SIGINT (exit 143, 130), each
//! resumed with `--resume` and every output file compared byte for byte
//! with the uninterrupted run's (srm.json with its wall-clock fields, which
//! differ between any two runs, set aside: every other byte of it is
//! compared). Damaged and foreign checkpoints are refused with a named
//! error and exit 2. The tests assert bytes and exit codes, never times.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use cdem::mesh::perturb::SplitMix64;

const CKPT: &str = "checkpoint.cdem";

/// The tests of this file run one at a time: the kill moments are drawn
/// over an uninterrupted run's wall time, which another test running
/// beside it would stretch.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// The joint-plane slope: elastic blocks, one breakable interface, eight
/// trials in about a second and a half.
fn plane() -> PathBuf {
    root().join("verification/joints/plane.toml")
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cdem-restart-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn srm(scene: &Path, out: &Path, extra: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_cdem"));
    c.arg("srm").arg(scene).arg("--out").arg(out).args(extra).stdout(Stdio::piped()).stderr(Stdio::piped());
    c
}

fn run_to_end(mut c: Command) -> std::process::Output {
    c.output().unwrap()
}

fn spawn(mut c: Command) -> Child {
    c.stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap()
}

/// A JSON file without its wall-clock fields (keys ending in `_s`: the
/// seconds a run or trial took), every other value kept.
fn without_wall_times(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(m) => {
            m.retain(|k, _| !k.ends_with("_s"));
            m.values_mut().for_each(without_wall_times);
        }
        serde_json::Value::Array(a) => a.iter_mut().for_each(without_wall_times),
        _ => {}
    }
}

/// Every file of `got` equals `want`'s (the same names; JSON without wall
/// times, everything else byte for byte).
fn assert_same_files(want: &Path, got: &Path, what: &str) {
    let names = |d: &Path| {
        let mut n: Vec<String> =
            std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        n.sort();
        n
    };
    let (a, b) = (names(want), names(got));
    assert_eq!(a, b, "{what}: the files differ");
    assert!(a.iter().any(|n| n == "srm.json"), "{what}: {a:?}");
    for name in a {
        let (x, y) = (std::fs::read(want.join(&name)).unwrap(), std::fs::read(got.join(&name)).unwrap());
        if name.ends_with(".json") {
            let parse = |t: &[u8]| {
                let mut v: serde_json::Value = serde_json::from_slice(t).unwrap();
                without_wall_times(&mut v);
                serde_json::to_string(&v).unwrap()
            };
            assert!(parse(&x) == parse(&y), "{what}: {name} differs");
            // The layout too: the same lines apart from the wall times.
            let lines = |t: &[u8]| {
                String::from_utf8_lossy(t)
                    .lines()
                    .filter(|l| !l.contains("_s\": "))
                    .map(String::from)
                    .collect::<Vec<_>>()
            };
            assert!(lines(&x) == lines(&y), "{what}: {name}'s text differs");
        } else {
            assert!(x == y, "{what}: {name} differs byte for byte");
        }
    }
}

/// Resumes the run in `out` to its end and compares its files with `want`.
fn resume_and_compare(scene: &Path, out: &Path, want: &Path, what: &str) -> String {
    let o = run_to_end(srm(scene, out, &["--resume", out.to_str().unwrap(), "--checkpoint-every", "0"]));
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(0), "{what}: resume failed: {err}");
    assert!(!out.join(CKPT).exists(), "{what}: the checkpoint is removed once the files are written");
    assert_same_files(want, out, what);
    err
}

/// The uninterrupted run of `scene` (default checkpoint interval) and its wall time.
fn baseline(scene: &Path, dir: &Path) -> (PathBuf, Duration) {
    let base = dir.join("base");
    let t = Instant::now();
    let o = run_to_end(srm(scene, &base, &[]));
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    (base, t.elapsed())
}

/// Waits until `cond` holds (polling), at most `limit`.
fn wait_for(limit: Duration, mut cond: impl FnMut() -> bool) -> bool {
    let t = Instant::now();
    while t.elapsed() < limit {
        if cond() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    false
}

#[test]
fn srm_killed_at_seeded_random_moments_resumes_to_the_same_bytes() {
    let _serial = serial();
    let dir = temp_dir("kill");
    let scene = plane();
    let (base, wall) = baseline(&scene, &dir);
    // A second uninterrupted run, checkpointing after every trial: the
    // checkpoints change nothing.
    let every = dir.join("every");
    let t = Instant::now();
    let o = run_to_end(srm(&scene, &every, &["--checkpoint-every", "0"]));
    assert_eq!(o.status.code(), Some(0));
    let wall = wall.min(t.elapsed());
    assert_same_files(&base, &every, "checkpointing after every trial");

    let mut rng = SplitMix64::new(57);
    let mut killed_mid_run = 0;
    let mut resumed_from_checkpoint = 0;
    let mut log = Vec::new();
    for k in 0..14 {
        let out = dir.join(format!("kill-{k}"));
        // Uniform over the first 90 % of an uninterrupted run's wall time.
        let at = wall.mul_f64(0.9 * rng.next_f64());
        let mut child = spawn(srm(&scene, &out, &["--checkpoint-every", "0"]));
        std::thread::sleep(at);
        child.kill().unwrap(); // SIGKILL
        let status = child.wait().unwrap();
        let finished = status.success();
        killed_mid_run += usize::from(!finished);
        let had = out.join(CKPT).exists();
        resumed_from_checkpoint += usize::from(had);
        let err = resume_and_compare(&scene, &out, &base, &format!("kill {k} at {at:?}"));
        let trials = err.lines().find(|l| l.starts_with("resumed from the checkpoint")).unwrap_or("from the start");
        log.push(format!("kill {k} at {:.0} ms: {}, {trials}", at.as_secs_f64() * 1e3, status));
    }
    eprintln!("{}", log.join("\n"));
    assert!(killed_mid_run >= 10, "{killed_mid_run} of 14 kills landed before the end:\n{}", log.join("\n"));
    assert!(
        resumed_from_checkpoint >= 3,
        "only {resumed_from_checkpoint} resumed from a checkpoint:\n{}",
        log.join("\n")
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn srm_killed_inside_a_checkpoint_write_resumes_to_the_same_bytes() {
    let _serial = serial();
    let dir = temp_dir("torn");
    let scene = plane();
    let (base, _) = baseline(&scene, &dir);
    // The first, the third and the sixth write: killed after half its bytes.
    for nth in [1usize, 3, 6] {
        let out = dir.join(format!("torn-{nth}"));
        let mut c = srm(&scene, &out, &["--checkpoint-every", "0"]);
        c.env("CDEM_TEST_CHECKPOINT_STALL_MS", "400");
        let mut child = spawn(c);
        let partial = |out: &Path| {
            std::fs::read_dir(out)
                .map(|d| {
                    d.filter_map(Result::ok).any(|e| e.file_name().to_string_lossy().starts_with(".checkpoint.partial"))
                })
                .unwrap_or(false)
        };
        let mut seen = 0;
        while seen < nth {
            assert!(wait_for(Duration::from_secs(60), || partial(&out)), "write {nth}: no checkpoint being written");
            seen += 1;
            if seen < nth {
                assert!(wait_for(Duration::from_secs(60), || !partial(&out)), "write {seen} never ended");
            }
        }
        child.kill().unwrap();
        assert!(!child.wait().unwrap().success());
        assert!(partial(&out), "the kill landed inside the write");
        // The previous checkpoint, if any, is whole: resume reads it.
        assert_eq!(out.join(CKPT).exists(), nth > 1);
        resume_and_compare(&scene, &out, &base, &format!("killed inside checkpoint write {nth}"));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Sends `signal` (by name) to `child` once its first checkpoint exists;
/// returns its exit code.
fn signal_after_first_checkpoint(child: &mut Child, out: &Path, signal: &str) -> Option<i32> {
    assert!(wait_for(Duration::from_secs(60), || out.join(CKPT).exists()), "no checkpoint");
    let ok = Command::new("kill").arg(format!("-{signal}")).arg(child.id().to_string()).status().unwrap();
    assert!(ok.success());
    child.wait().unwrap().code()
}

#[test]
fn sigterm_and_sigint_write_a_checkpoint_and_exit_143_and_130_and_the_run_resumes() {
    let _serial = serial();
    let dir = temp_dir("signals");
    let scene = plane();
    let (base, _) = baseline(&scene, &dir);
    for (signal, code) in [("TERM", 143), ("INT", 130)] {
        let out = dir.join(signal);
        let mut child = spawn(srm(&scene, &out, &["--checkpoint-every", "0"]));
        assert_eq!(signal_after_first_checkpoint(&mut child, &out, signal), Some(code), "SIG{signal}");
        assert!(out.join(CKPT).exists(), "SIG{signal}: the checkpoint stays");
        assert!(!out.join("srm.json").exists(), "SIG{signal}: no result yet");
        let err = resume_and_compare(&scene, &out, &base, &format!("SIG{signal}"));
        assert!(err.contains("resumed from the checkpoint"), "{err}");
    }
    // SIGTERM with the default interval (300 s): the signal's checkpoint alone.
    let out = dir.join("default-interval");
    let mut child = spawn(srm(&scene, &out, &[]));
    std::thread::sleep(Duration::from_millis(300));
    let ok = Command::new("kill").arg("-TERM").arg(child.id().to_string()).status().unwrap();
    assert!(ok.success());
    let code = child.wait().unwrap().code();
    if code == Some(143) {
        assert!(out.join(CKPT).exists());
        resume_and_compare(&scene, &out, &base, "SIGTERM at the default interval");
    } else {
        // The run had ended before the signal came.
        assert_eq!(code, Some(0));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn damaged_foreign_and_other_version_checkpoints_are_refused_with_exit_2() {
    let _serial = serial();
    let dir = temp_dir("refused");
    let scene = plane();
    let src = dir.join("src");
    let mut child = spawn(srm(&scene, &src, &["--checkpoint-every", "0"]));
    assert_eq!(signal_after_first_checkpoint(&mut child, &src, "TERM"), Some(143));
    let good = std::fs::read(src.join(CKPT)).unwrap();
    let mut corrupt = good.clone();
    let mid = corrupt.len() / 2;
    corrupt[mid] ^= 0x40;
    let mut version = good.clone();
    version[8] = version[8].wrapping_add(1);
    let cases: [(&str, Vec<u8>, &str); 5] = [
        ("truncated", good[..good.len() * 2 / 3].to_vec(), "truncated"),
        ("corrupt", corrupt, "corrupt"),
        ("version", version, "format version"),
        ("not-a-checkpoint", b"# a text file\n".to_vec(), "not a cdem checkpoint"),
        ("empty", Vec::new(), "not a cdem checkpoint"),
    ];
    for (name, bytes, says) in cases {
        let d = dir.join(name);
        std::fs::create_dir_all(&d).unwrap();
        std::fs::write(d.join(CKPT), bytes).unwrap();
        let o = run_to_end(srm(&scene, &d.join("out"), &["--resume", d.to_str().unwrap()]));
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains("checkpoint") && err.contains(says), "{name}: {err}");
        assert!(!d.join("out").join("srm.json").exists(), "{name}: nothing computed from it");
    }
    // Another scene (the same mesh directory, another scene file): foreign.
    let other = root().join("verification/cases/block-srm/block-srm-cohesion.toml");
    let o = run_to_end(srm(&other, &dir.join("foreign-out"), &["--resume", src.to_str().unwrap()]));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("another scene or mesh"), "{err}");
    // The same scene with one value changed: foreign too.
    let text = std::fs::read_to_string(&scene).unwrap();
    let changed = scene.with_file_name(format!(".plane-changed-{}.toml", std::process::id()));
    let edited = text.replacen("cohesion = 48000.0", "cohesion = 48001.0", 1);
    assert_ne!(edited, text);
    std::fs::write(&changed, edited).unwrap();
    let o = run_to_end(srm(&changed, &dir.join("changed-out"), &["--resume", src.to_str().unwrap()]));
    let _ = std::fs::remove_file(&changed);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("another scene or mesh"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Plastic blocks (Griffiths & Lane's slope, hexahedra): the warm start's
/// state carries every tetrahedron's history; stopped by SIGTERM after its
/// second checkpoint and killed at a seeded moment, each resumed.
#[test]
fn plastic_blocks_stopped_and_killed_resume_to_the_same_bytes() {
    let _serial = serial();
    let dir = temp_dir("plastic");
    let scene = root().join("verification/plastic/griffiths-lane-1/gl1-hex.toml");
    let (base, wall) = baseline(&scene, &dir);
    let out = dir.join("term");
    let mut child = spawn(srm(&scene, &out, &["--checkpoint-every", "0"]));
    assert!(wait_for(Duration::from_secs(120), || out.join(CKPT).exists()), "no first checkpoint");
    let first = std::fs::read(out.join(CKPT)).unwrap();
    assert!(
        wait_for(Duration::from_secs(120), || std::fs::read(out.join(CKPT)).is_ok_and(|b| b != first)),
        "no second checkpoint"
    );
    let ok = Command::new("kill").arg("-TERM").arg(child.id().to_string()).status().unwrap();
    assert!(ok.success());
    assert_eq!(child.wait().unwrap().code(), Some(143));
    let err = resume_and_compare(&scene, &out, &base, "plastic, SIGTERM");
    assert!(err.contains("resumed from the checkpoint"), "{err}");
    let mut rng = SplitMix64::new(5757);
    let out = dir.join("kill");
    let at = wall.mul_f64(0.3 + 0.6 * rng.next_f64());
    let mut child = spawn(srm(&scene, &out, &["--checkpoint-every", "0"]));
    std::thread::sleep(at);
    child.kill().unwrap();
    let status = child.wait().unwrap();
    eprintln!("plastic: killed at {:.0} ms ({status})", at.as_secs_f64() * 1e3);
    resume_and_compare(&scene, &out, &base, "plastic, SIGKILL");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The column with perturbed nodes and a random Young's modulus, `members`
/// members: a small CDEM ensemble (tests/ensemble.rs's).
fn column_ensemble(dir: &Path, members: usize) -> PathBuf {
    let text = std::fs::read_to_string(root().join("verification/cases/column/column.toml")).unwrap();
    let mesh = root().join("verification/cases/column/column.msh");
    let text = text.replace("file = \"column.msh\"", &format!("file = {:?}", mesh.display().to_string()));
    let text = format!(
        "{text}\n[perturbation]\nratio = 0.2\nseed = 1\n\n[ensemble]\nmembers = {members}\nseed = 11\n\n\
         [[ensemble.random]]\nkey = \"material[0].youngs_modulus\"\ndistribution = \"lognormal\"\nstd_dev = 6.0e7\n"
    );
    let path = dir.join("column-ensemble.toml");
    std::fs::write(&path, text).unwrap();
    path
}

fn ensemble(scene: &Path, out: &Path, extra: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_cdem"));
    c.env("RAYON_NUM_THREADS", "1").arg("ensemble").arg(scene).arg("--out").arg(out).args(extra);
    c.stdout(Stdio::piped()).stderr(Stdio::piped());
    c
}

/// Every file of `got` equals `want`'s: JSON without wall times, the rest
/// byte for byte (the ensemble's figures and members.jsonl included).
fn assert_same_ensemble(want: &Path, got: &Path, what: &str) {
    let names = |d: &Path| {
        let mut n: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| !n.starts_with('.'))
            .collect();
        n.sort();
        n
    };
    assert_eq!(names(want), names(got), "{what}");
    for name in names(want) {
        let (x, y) = (std::fs::read(want.join(&name)).unwrap(), std::fs::read(got.join(&name)).unwrap());
        if name.ends_with(".json") {
            let parse = |t: &[u8]| {
                let mut v: serde_json::Value = serde_json::from_slice(t).unwrap();
                without_wall_times(&mut v);
                v
            };
            assert_eq!(parse(&x), parse(&y), "{what}: {name}");
        } else {
            assert!(x == y, "{what}: {name} differs byte for byte");
        }
    }
}

#[test]
fn an_ensemble_and_a_shard_killed_resume_to_the_same_bytes_and_a_torn_line_is_dropped() {
    let _serial = serial();
    let dir = temp_dir("ensemble");
    let scene = column_ensemble(&dir, 24);
    let base = dir.join("base");
    let t = Instant::now();
    let o = run_to_end(ensemble(&scene, &base, &[]));
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let wall = t.elapsed();
    let lines = std::fs::read_to_string(base.join("members.jsonl")).unwrap().lines().count();
    assert_eq!(lines, 24);
    let mut rng = SplitMix64::new(5700);
    let mut log = Vec::new();
    for k in 0..6 {
        let out = dir.join(format!("kill-{k}"));
        let at = wall.mul_f64(0.9 * rng.next_f64());
        let mut child = spawn(ensemble(&scene, &out, &[]));
        std::thread::sleep(at);
        child.kill().unwrap();
        let status = child.wait().unwrap();
        let kept = std::fs::read_to_string(out.join("members.jsonl")).map(|t| t.lines().count()).unwrap_or(0);
        let o = run_to_end(ensemble(&scene, &out, &["--resume"]));
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        assert_eq!(o.status.code(), Some(0), "kill {k}: {err}");
        assert_same_ensemble(&base, &out, &format!("ensemble killed at {at:?}"));
        let said = err.lines().filter(|l| l.starts_with("resumed")).collect::<Vec<_>>().join("; ");
        log.push(format!("kill {k} at {:.0} ms ({status}): {kept} lines kept; {said}", at.as_secs_f64() * 1e3));
    }
    eprintln!("{}", log.join("\n"));

    // A torn last line (a record cut by a kill): dropped, said so, run again.
    let out = dir.join("torn");
    let mut child = spawn(ensemble(&scene, &out, &[]));
    let journal = out.join("members.jsonl");
    let lines = || std::fs::read_to_string(&journal).map(|t| t.lines().count()).unwrap_or(0);
    assert!(wait_for(Duration::from_secs(120), || lines() >= 10), "no ten members");
    child.kill().unwrap();
    let _ = child.wait();
    let text = std::fs::read_to_string(&journal).unwrap();
    let keep: String = text.lines().take(9).map(|l| format!("{l}\n")).collect();
    let tenth = text.lines().nth(9).unwrap();
    std::fs::write(&journal, format!("{keep}{}", &tenth[..tenth.len() / 2])).unwrap();
    let o = run_to_end(ensemble(&scene, &out, &["--resume"]));
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("dropped a torn last line"), "{err}");
    assert!(err.contains("9 members from the journal"), "{err}");
    assert_same_ensemble(&base, &out, "torn last line");
    // Resuming a finished run runs no member and gives the same files.
    let o = run_to_end(ensemble(&scene, &out, &["--resume"]));
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(err.contains("24 members from the journal"), "{err}");
    assert_same_ensemble(&base, &out, "resumed after the end");

    // A shard: killed and resumed, the same files as the shard never stopped.
    let shard_base = dir.join("shard-base");
    let o = run_to_end(ensemble(&scene, &shard_base, &["--shard", "1/2"]));
    assert_eq!(o.status.code(), Some(0));
    let out = dir.join("shard-kill");
    let mut child = spawn(ensemble(&scene, &out, &["--shard", "1/2"]));
    std::thread::sleep(wall.mul_f64(0.25));
    child.kill().unwrap();
    let _ = child.wait();
    let o = run_to_end(ensemble(&scene, &out, &["--shard", "1/2", "--resume"]));
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert_same_ensemble(&shard_base, &out, "shard killed");

    // A journal of another seed is refused.
    let out = dir.join("foreign");
    let mut child = spawn(ensemble(&scene, &out, &[]));
    assert!(
        wait_for(Duration::from_secs(60), || std::fs::metadata(out.join("members.jsonl")).is_ok_and(|m| m.len() > 0))
    );
    child.kill().unwrap();
    let _ = child.wait();
    let o = run_to_end(ensemble(&scene, &out, &["--resume", "--seed", "12"]));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("another ensemble"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
