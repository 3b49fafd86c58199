//! `cdem ensemble`: the Monte-Carlo statistics against an analytic case, the
//! determinism of member records under sharding and thread count, and input
//! errors (references/ensemble.md).

use std::path::{Path, PathBuf};
use std::process::Command;

use cdem::drivers::ensemble::{mean_critical_circle, run_members, EnsembleInput};
use cdem::error::SceneError;
use cdem::harness::registry as reg;
use cdem::harness::suite::ensemble::{segment, COHESION};

/// With c normal, FS = kappa c is normal with known mean and deviation, so
/// PF = Phi((1 - mean) / deviation) exactly: the ensemble's mean and PF must
/// contain them in their 95 % intervals, its deviation within 5 % (the
/// deviation of a sample deviation is sigma / sqrt(2 n): 1.1 % at n = 4000).
/// The run and its rows are [`cdem::harness::suite::ensemble::segment`]
/// (shared with `cdem reproduce`).
#[test]
fn mean_and_probability_of_failure_match_the_analytic_normal_case() {
    let seg = segment(Path::new(env!("CARGO_MANIFEST_DIR"))).unwrap();
    cdem::harness::report::record("ensemble_segment", &seg.rows);
    let (mean, sd, pf, n) = (seg.mean, seg.sd, seg.pf, seg.members);
    assert!((mean - 1.2).abs() < 1e-9 && (sd - 0.15).abs() < 1e-9, "the file's values: mean {mean}, sd {sd}");
    let s = &seg.summary;
    let (fs, r) = (s.fs.as_ref().unwrap(), s.reliability.as_ref().unwrap());
    println!(
        "n {n}: mean {:.5} CI {:?} (exact {mean}); sd {:.5} (exact {sd}); PF {:.5} CI {:?} (exact {pf:.5})",
        fs.mean, fs.mean_ci95, fs.std_dev, r.probability_of_failure, r.pf_ci95
    );
    assert_eq!(s.members_without_fs, 0);
    // The LEM's own error on this circle at 200 slices is ~2e-4 (second order,
    // tests/lem.rs), a twentieth of the mean's interval half-width (4.6e-3).
    assert!(fs.mean_ci95[0] <= mean && mean <= fs.mean_ci95[1], "mean {:?} vs {mean}", fs.mean_ci95);
    assert!(r.pf_ci95[0] <= pf && pf <= r.pf_ci95[1], "PF {:?} vs {pf}", r.pf_ci95);
    assert!((fs.std_dev / sd - 1.0).abs() < 0.05, "sd {} vs {sd}", fs.std_dev);
    // The drawn cohesions themselves: the sampler's mean and deviation.
    let (mu_c, sd_c) = COHESION;
    let (_, c) = &s.draws[0];
    assert!((c.mean - mu_c).abs() < 3.0 * sd_c / (n as f64).sqrt(), "{c:?}");
    assert!(seg.rows.iter().all(|r| r.passed()), "{:?}", seg.rows);
}

fn cdem() -> Command {
    Command::new(env!("CARGO_BIN_EXE_cdem"))
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cdem-ensemble-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The column scene with perturbed nodes and a random Young's modulus: a
/// small CDEM ensemble.
fn column_ensemble(dir: &Path) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("verification/cases/column/column.toml")).unwrap();
    let mesh = root.join("verification/cases/column/column.msh");
    let text = text.replace("file = \"column.msh\"", &format!("file = {:?}", mesh.display().to_string()));
    let text = format!(
        "{text}\n[perturbation]\nratio = 0.2\nseed = 1\n\n[ensemble]\nmembers = 7\nseed = 11\n\n\
         [[ensemble.random]]\nkey = \"material[0].youngs_modulus\"\ndistribution = \"lognormal\"\nstd_dev = 6.0e7\n"
    );
    let path = dir.join("column-ensemble.toml");
    std::fs::write(&path, text).unwrap();
    path
}

fn ok(o: std::process::Output) -> String {
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Three shards (one thread each) merged give the members of one unsharded
/// run (two threads) byte for byte, and the same statistics.
#[test]
fn three_shards_merge_to_the_unsharded_ensemble_byte_for_byte() {
    let dir = temp_dir("shards");
    let scene = column_ensemble(&dir);
    let whole = dir.join("whole");
    ok(cdem().env("RAYON_NUM_THREADS", "2").arg("ensemble").arg(&scene).arg("--out").arg(&whole).output().unwrap());
    let mut shards = Vec::new();
    for i in 0..3 {
        let d = dir.join(format!("shard{i}"));
        let text = ok(cdem()
            .env("RAYON_NUM_THREADS", "1")
            .arg("ensemble")
            .arg(&scene)
            .args(["--shard", &format!("{i}/3"), "--out"])
            .arg(&d)
            .output()
            .unwrap());
        assert!(text.contains(&format!("shard {i}/3")), "{text}");
        shards.push(d);
    }
    let merged = dir.join("merged");
    ok(cdem().arg("ensemble").arg("merge").args(&shards).arg("--out").arg(&merged).output().unwrap());
    let a = std::fs::read(whole.join("members.jsonl")).unwrap();
    let b = std::fs::read(merged.join("members.jsonl")).unwrap();
    assert_eq!(String::from_utf8_lossy(&a).lines().count(), 7);
    assert!(a == b, "members differ:\n{}\n---\n{}", String::from_utf8_lossy(&a), String::from_utf8_lossy(&b));
    let (ja, jb) = (
        std::fs::read_to_string(whole.join("ensemble.json")).unwrap(),
        std::fs::read_to_string(merged.join("ensemble.json")).unwrap(),
    );
    let strip = |s: &str| s.lines().filter(|l| !l.contains("\"input\"")).collect::<Vec<_>>().join("\n");
    assert_eq!(strip(&ja), strip(&jb));
    // Members differ from each other (the seeds and moduli do their work).
    let first: Vec<&str> = std::str::from_utf8(&a).unwrap().lines().take(2).collect();
    assert_ne!(first[0].split("\"draws\"").nth(1), first[1].split("\"draws\"").nth(1));

    // A missing shard is refused, naming the member.
    let o = cdem().arg("ensemble").arg("merge").args(&shards[..2]).arg("--out").arg(dir.join("bad")).output().unwrap();
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{msg}");
    assert!(msg.contains("4 of 7 members present"), "{msg}");
}

fn invalid(path: &Path) -> (String, String) {
    match EnsembleInput::load(path) {
        Err(cdem::Error::Scene(SceneError::Invalid { key, reason })) => (key, reason),
        Err(e) => panic!("expected an invalid key, got {e}"),
        Ok(_) => panic!("accepted {}", path.display()),
    }
}

#[test]
fn ensemble_errors_name_the_key() {
    let dir = temp_dir("errors");
    let base = std::fs::read_to_string("verification/ensemble/cohesive-segment.toml").unwrap();
    let write = |name: &str, text: String| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let p = write("key.toml", base.replace("key = \"material[0].cohesion\"", "key = \"material[0].strength\""));
    let (key, reason) = invalid(&p);
    assert_eq!(key, "ensemble.random[0].key", "{reason}");
    let p = write("sd.toml", base.replace("std_dev = 4815.4004224962855", "std_dev = -1.0"));
    assert_eq!(invalid(&p).0, "ensemble.random[0].std_dev");
    let p = write("cdem.toml", base.replace("seed = 7", "seed = 7\nanalyses = [\"cdem\"]"));
    assert_eq!(invalid(&p).0, "ensemble.analyses");
    let p = write(
        "lognormal.toml",
        base.replace("std_dev = 4815", "mean = -1.0\ndistribution = \"lognormal\"\nstd_dev = 4815"),
    );
    assert_eq!(invalid(&p).0, "ensemble.random[0].mean");

    // Truncation bounds that exclude the distribution: an error naming the variable, not a hang.
    let p = write("bounds.toml", base.replace("std_dev = 4815.4004224962855", "std_dev = 1.0\nmin = 1e9\nmax = 2e9"));
    let input = EnsembleInput::load(&p).unwrap();
    match run_members(&input, 1, 0..1, mean_critical_circle(&input).unwrap(), &mut |_| {}) {
        Err(cdem::Error::Scene(SceneError::Invalid { key, .. })) => assert_eq!(key, "ensemble.random[0]"),
        other => panic!("{other:?}"),
    }
    // A shard index out of range is invalid input (exit 2).
    let o =
        cdem().args(["ensemble", "verification/ensemble/cohesive-segment.toml", "--shard", "3/2"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
}

/// Strength reduction per member: the block on a plane with a normal
/// friction angle; each member's SRM FS is the analytic tan(phi_k) / tan(30
/// deg) of its own draw within the SRM tolerance (references/srm.md).
#[test]
fn srm_members_match_the_analytic_fs_of_their_draws() {
    let input = EnsembleInput::load(Path::new(reg::BLOCK_SRM_FRICTION.input)).unwrap();
    let records = run_members(&input, input.default_seed(), 0..8, None, &mut |_| {}).unwrap();
    for r in &records {
        let phi = r.draws[0].value;
        let exact = phi.to_radians().tan() / 30f64.to_radians().tan();
        let fs = r.fs.expect("a bracket");
        assert_eq!(r.srm.as_ref().unwrap().fs, Some(fs));
        assert!(
            ((fs - exact) / exact).abs() < reg::TOL_SRM_BLOCK,
            "member {}: phi {phi}, SRM {fs}, exact {exact}",
            r.member
        );
    }
    let phis: Vec<f64> = records.iter().map(|r| r.draws[0].value).collect();
    assert!(phis.windows(2).all(|w| w[0] != w[1]), "draws differ: {phis:?}");
}

/// A member that runs CDEM and the strength reduction (`analyses = ["cdem",
/// "srm"]`) takes its run's phase 2 over as the search's trial at F = 1
/// (`srm::Phase2Run`) instead of running it again: the search must find
/// what `cdem srm` on the member's scene finds, trial for trial, bit for
/// bit, with the first trial taken over. The member is the first of the
/// slip-surface slope's ensemble that `cdem perf` times.
#[test]
fn a_member_s_run_is_its_strength_reduction_s_first_trial() {
    use cdem::drivers::ensemble::MemberInput;
    use cdem::drivers::srm::{run_srm_after, Phase2Run};
    let input = EnsembleInput::load(Path::new(cdem::harness::perf::ensemble::PAPER_SLOPE_SLIP_SRM)).unwrap();
    let (seed, draws) = input.draws(input.default_seed(), 0).unwrap();
    let MemberInput::Scene(scene) = input.member_input(seed, &draws).unwrap() else { panic!("a scene") };
    let run = cdem::drivers::run_scene(&scene, &mut |_, _| {}).unwrap();
    let phase2 = Phase2Run { failure: run.failure.as_ref().unwrap(), state: &run.state };
    let (after, _) = run_srm_after(&scene, phase2, &mut |_| {}).unwrap();
    let (alone, _) = cdem::drivers::run_srm(&scene, &mut |_| {}).unwrap();
    assert!(after.trials[0].from_run && after.trials[0].factor == 1.0, "{:?}", after.trials[0]);
    assert!(after.trials[1..].iter().chain(&alone.trials).all(|t| !t.from_run));
    assert_eq!((after.fs, after.bracket), (alone.fs, alone.bracket));
    assert_eq!(after.trials.len(), alone.trials.len());
    for (a, b) in after.trials.iter().zip(&alone.trials) {
        let key = |t: &cdem::drivers::Trial| {
            (t.factor.to_bits(), t.outcome, t.steps, t.max_displacement.to_bits(), t.failed_springs, t.started_from)
        };
        assert_eq!(key(a), key(b), "trial at F = {}", a.factor);
    }
    let bits = |m: &Option<Vec<f64>>| m.as_ref().unwrap().iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&after.mechanism), bits(&alone.mechanism), "the mechanism");
    // The phase 2 is not that trial, and is not taken: one that went on with
    // phase 1's solver (its damping state), or one from another elastic state.
    assert!(!run.failure.as_ref().unwrap().continued, "PCG's phase 1 hands no solver over");
    let red = || cdem::drivers::srm::Reduction::new(&scene, cdem::drivers::srm::TrialStart::Warm).unwrap().0;
    let mut failure = run.failure.unwrap();
    assert!(red().adopt(Phase2Run { failure: &failure, state: &run.state }).is_some());
    failure.continued = true;
    assert!(red().adopt(Phase2Run { failure: &failure, state: &run.state }).is_none(), "a continued solver");
    failure.continued = false;
    failure.u_elastic[7] = f64::from_bits(failure.u_elastic[7].to_bits() ^ 1);
    assert!(red().adopt(Phase2Run { failure: &failure, state: &run.state }).is_none(), "another elastic state");
}
