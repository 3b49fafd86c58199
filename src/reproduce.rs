//! `cdem reproduce`: run every committed case and write a report.
//! (The figures and the full validation table grow with the later issues.)

use std::fmt::Write;
use std::path::Path;

use crate::error::Error;
use crate::run::{run_scene, write_outputs};
use crate::scene::Scene;

/// The committed default cases, relative to the repository root.
pub const CASES: &[(&str, &str)] = &[
    ("column (springs)", "verification/cases/column/column.toml"),
    ("column (merged)", "verification/cases/column/column-merged.toml"),
    ("slope (elastic)", "verification/cases/slope/slope.toml"),
];

/// Runs the cases into `out/<case file stem>/` and writes `out/report.md`.
pub fn reproduce(out: &Path, progress: &mut dyn FnMut(usize, f64)) -> Result<(), Error> {
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    let mut md = String::from("# cdem reproduce\n\n| case | converged | steps | wall (s) | min u_z (m) | min sigma_zz (Pa) |\n|---|---|---|---|---|---|\n");
    for (name, path) in CASES {
        let path = Path::new(path);
        eprintln!("running {name} ({})", path.display());
        let scene = Scene::load(path)?;
        let result = run_scene(&scene, progress)?;
        let dir = out.join(path.file_stem().unwrap_or_default());
        write_outputs(&scene, &result, &dir)?;
        let s = &result.summary;
        let _ = writeln!(
            md,
            "| {name} | {} | {} | {:.2} | {:.4e} | {} |",
            s.converged,
            s.steps,
            s.wall_s,
            s.min_uz,
            s.min_szz.map_or("-".into(), |v| format!("{v:.4e}"))
        );
    }
    eprintln!("running the error-against-run-time study");
    let study_dir = out.join("study");
    crate::study::run_study(&study_dir, &mut |what| eprintln!("  {what}"))?;
    let table = std::fs::read_to_string(study_dir.join("study.md")).map_err(|e| Error::io(study_dir.join("study.md"), e))?;
    let _ = write!(
        md,
        "\n## Error against run time\n\nRelative L2 error of the displacement field (column: analytic; slope: FEM on the 0.5 m mesh), one factor varied at a time.\n\n{table}\n![column](study/study-column.png)\n![slope](study/study-slope.png)\n"
    );
    crate::output::write_atomic(&out.join("report.md"), md.as_bytes())?;
    eprintln!("wrote {}", out.join("report.md").display());
    Ok(())
}
