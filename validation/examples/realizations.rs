//! Build realizations 1…N of `models/tunnel.json`'s two joint sets scattered as
//! `adit_validation::realizations::STUDY`; print those that fail and how many.
//! `cargo run --release -p adit-validation --example realizations -- 800 [first]`.

fn main() -> anyhow::Result<()> {
    let mut args = std::env::args().skip(1);
    let count: u64 = args.next().map_or(Ok(100), |a| a.parse())?;
    let first: u64 = args.next().map_or(Ok(1), |a| a.parse())?;
    let start = std::time::Instant::now();
    let failed = adit_validation::realizations::failures(count, first)?;
    for f in &failed {
        println!("{f}");
    }
    println!(
        "{} of {count} realizations failed to build ({:.1} s)",
        failed.len(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
