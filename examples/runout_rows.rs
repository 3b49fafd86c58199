//! Prints every runout row (cdem::harness::suite::runout) with its note:
//! `cargo run --release --example runout_probe`.
fn main() -> Result<(), cdem::Error> {
    for r in cdem::harness::suite::runout::rows()? {
        println!(
            "{:<32} ours {:>12.6e} ref {:>12.6e} {} {} | {}",
            r.id,
            r.ours,
            r.reference,
            r.ours_text,
            if r.passed() { "ok" } else { "FAIL" },
            r.note
        );
    }
    Ok(())
}
