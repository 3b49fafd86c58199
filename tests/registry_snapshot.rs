//! Issue 59 item 3: the registry's table of rows (id, kind with its tolerance,
//! bounds or goal, reference, whether and why it may be skipped, source, test)
//! as an insta snapshot, so that loosening, re-kinding or re-sourcing a row is a
//! visible diff in review: a registry edit without the snapshot's update fails
//! this test (`cargo insta review` accepts it, on purpose).

use cdem::harness::registry as reg;
use cdem::harness::report::{Goal, SpecKind};

fn kind(k: &SpecKind) -> String {
    match k {
        SpecKind::Asserted(t) => format!("asserted |e| <= {t:e}"),
        SpecKind::Bounded(above, below) => format!("asserted -{below:e} <= e <= +{above:e}"),
        SpecKind::Reported(Goal::Within(t)) => format!("reported, goal |e| <= {t:e}"),
        SpecKind::Reported(Goal::AtLeast) => "reported, goal ours >= reference".into(),
        SpecKind::Reported(Goal::AtMost) => "reported, goal ours <= reference".into(),
        SpecKind::Compared(true) => "compared, asserted".into(),
        SpecKind::Compared(false) => "compared, reported".into(),
    }
}

#[test]
fn the_registry_table_is_as_reviewed() {
    let mut out = String::new();
    for s in reg::rows() {
        let reference = s.reference.map_or("computed by the test".to_string(), |r| format!("{r:e}"));
        let skip = s.skip.map_or("never skipped", |_| "may skip");
        out.push_str(&format!("{} | {} | ref {reference} | {skip} | {} | {}\n", s.id, kind(&s.kind), s.source, s.test));
    }
    insta::assert_snapshot!("registry", out);
}
