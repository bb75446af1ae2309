//! Samples the seven layer surfaces of `sampling::benchmark_surface` on an
//! `N × N` grid and prints the size of the output arrays, so that the peak
//! memory of the grid engine can be compared with them:
//!
//! ```text
//! cargo build --release -p t2spline --example surface_memory
//! /usr/bin/time -f %M target/release/examples/surface_memory 3163   # 10⁷ points
//! ```
//! `%M` is the peak resident set in KiB.

use t2spline::sampling::{benchmark_surface, Params};
use t2spline::Layer;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let side: usize = std::env::args().nth(1).map_or(Ok(1000), |s| s.parse())?;
    let surface = benchmark_surface();
    let grid = surface.sample_layers(Params::Uniform(side), Params::Uniform(side))?;
    let values = Layer::ALL.len() * 3 * grid.samples().len();
    let kib = values * std::mem::size_of::<f64>() / 1024;
    // Touch the result so that nothing is optimised away.
    let sum: f64 = grid.samples()[Layer::UpperRight].coord(2).iter().sum();
    println!("grid {side} x {side}: {values} values, output arrays {kib} KiB (checksum {sum:.6})");
    Ok(())
}
