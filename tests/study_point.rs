//! One small point of the error-against-run-time study (src/study.rs; the
//! full study runs in `cdem study` / `cdem reproduce`): the 10-layer column
//! against the analytic solution (references/column.md). The continuous FEM
//! is nodally exact for this 1-D problem; CDEM with E_j/L = 1e11 Pa/m is
//! within the 1 % of the core issue (series joint compliance, about 0.1 %).

use cdem::harness::registry as reg;

#[test]
fn column_point_of_the_study_fem_exact_cdem_within_one_percent() {
    let (cdem, fem) = cdem::harness::study::column_base_point().unwrap();
    println!("study column point: CDEM L2 error {cdem:.3e}, FEM {fem:.3e}");
    cdem::harness::report::record(
        "study_point",
        &[
            cdem::harness::report::Check::new(
                "study: column 10 layers",
                "CDEM relative L2 error of u",
                cdem,
                0.0,
                reg::TOL_COLUMN_SPRINGS,
                reg::COLUMN_MD,
                0.0,
            ),
            cdem::harness::report::Check::new(
                "study: column 10 layers",
                "FEM relative L2 error of u",
                fem,
                0.0,
                1e-10,
                reg::COLUMN_MD,
                0.0,
            ),
        ],
    );
    assert!(fem < 1e-10, "FEM error {fem}");
    assert!(cdem < reg::TOL_COLUMN_SPRINGS, "CDEM error {cdem}");
    assert!(cdem > 1e-5, "CDEM with springs cannot be exact: joint compliance is missing");
}
