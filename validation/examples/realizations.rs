//! Draw realizations of `models/tunnel.json`'s two joint sets (`adit_validation::realizations`)
//! and build each; print those that fail and how many.
//! `cargo run --release -p adit-validation --example realizations -- 800 [seed]`.

fn main() -> anyhow::Result<()> {
    let mut args = std::env::args().skip(1);
    let count: usize = args.next().map_or(Ok(100), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(1), |a| a.parse())?;
    let start = std::time::Instant::now();
    let failed = adit_validation::realizations::failures(count, seed)?;
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
