//! Writes a job file with many control points, for trying figures and
//! reports on large jobs and for timing them.
//!
//! ```text
//! cargo run --example many_points -- N [--dim 2|3] [--seed S] > job.json
//! cargo run --example many_points -- N --net SAMPLES > surface.json
//! ```
//!
//! The crisp control points follow an Archimedean spiral, 1.5 apart along it
//! and 3 apart between turns, so a job of any size fills a disc with points
//! about as far apart as in a hand-made job (in 3-D the spiral also waves in
//! z). Spreads, weights and lower heights vary from point to point by a seeded
//! generator, so the same arguments give the same file.

use serde_json::{json, Value};

/// SplitMix64: a small, seeded generator of uniform numbers in [0, 1).
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi), rounded to 3 decimals so the file stays short.
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        round(lo + (hi - lo) * self.next())
    }
}

fn round(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

/// One fuzzy number around `c` with left and right spreads drawn at random
/// (unequal, so the solution curve leaves the crisp curve).
fn number(c: f64, r: &mut Random, height: Option<f64>) -> Value {
    let c = round(c);
    let (l, rt) = (r.range(0.1, 0.6), r.range(0.1, 0.6));
    let mut n = json!({
        "crisp": c,
        "upper": [round(c - l), round(c + rt)],
        "primary": [round(c - 0.7 * l), round(c + 0.7 * rt)],
        "lower": [round(c - 0.35 * l), round(c + 0.35 * rt)],
    });
    if let Some(h) = height {
        n["lower_height"] = json!(h);
    }
    n
}

/// A job of `n` control points (at least 4) in `dim` (2 or 3) dimensions.
pub fn job(n: usize, dim: usize, seed: u64) -> Value {
    let n = n.max(4);
    let mut r = Random(seed);
    let points: Vec<Value> = (0..n)
        .map(|i| {
            // On r = GAP·θ/2π the arc length from the centre is about
            // GAP·θ²/4π; points are STEP apart along it, from the second turn.
            const GAP: f64 = 3.0;
            const STEP: f64 = 1.5;
            let length = STEP * i as f64 + GAP * std::f64::consts::PI;
            let theta = (4.0 * std::f64::consts::PI * length / GAP).sqrt();
            let radius = GAP * theta / std::f64::consts::TAU;
            let (x, y) = (radius * theta.cos(), radius * theta.sin());
            // Every seventh point has its own lower height in y (mixed heights).
            let hy = (i % 7 == 3).then_some(0.4);
            let mut p = json!({
                "x": number(x, &mut r, None),
                "y": number(y, &mut r, hy),
            });
            if dim == 3 {
                p["z"] = number(2.0 * (3.0 * theta).sin(), &mut r, None);
            }
            p
        })
        .collect();
    let weights: Vec<f64> = (0..n).map(|_| r.range(0.5, 3.0)).collect();
    json!({
        "description": format!("{n} control points made by the many_points example (seed {seed})"),
        "order": 4,
        "weights": weights,
        "alpha": 0.8,
        "lower_height": 0.6,
        "points": points,
    })
}

/// A bicubic surface job on an `n` × `n` net sampled `samples` × `samples`:
/// a crisp grid in x and y, a wave in z whose spreads grow with the row
/// (`0.05 + 0.01·i`; upper −3s..+2s, primary −2s..+1.5s, lower −s..+s).
pub fn net(n: usize, samples: usize) -> Value {
    let fuzzy = |c: f64, s: f64| {
        json!({"crisp": c, "upper": [c - 3.0 * s, c + 2.0 * s],
               "primary": [c - 2.0 * s, c + 1.5 * s], "lower": [c - s, c + s]})
    };
    let rows: Vec<Value> = (0..n)
        .map(|i| {
            let x = i as f64;
            let row: Vec<Value> = (0..n)
                .map(|j| {
                    let y = j as f64;
                    let z = (x / 7.0).sin() * (y / 5.0).cos() * 4.0;
                    json!({"x": fuzzy(x, 0.0), "y": fuzzy(y, 0.0), "z": fuzzy(z, 0.05 + 0.01 * x)})
                })
                .collect();
            json!(row)
        })
        .collect();
    json!({
        "description": format!("{n} × {n} net made by the many_points example"),
        "order": [4, 4],
        "alpha": 0.5,
        "lower_height": 0.6,
        "samples": [samples, samples],
        "points": rows,
    })
}

// Tests include this file for `job` or `net` alone.
#[allow(dead_code)]
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut n = 40usize;
    let mut dim = 2usize;
    let mut seed = 1u64;
    let mut samples = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = || it.next().and_then(|v| v.parse::<u64>().ok());
        match a.as_str() {
            "--dim" => dim = value().map_or(2, |v| if v == 3 { 3 } else { 2 }),
            "--seed" => seed = value().unwrap_or(1),
            "--net" => samples = value().and_then(|v| usize::try_from(v).ok()),
            s => n = s.parse().unwrap_or(n),
        }
    }
    // Writing to a closed pipe is not worth a panic message.
    let value = match samples {
        Some(s) => net(n, s),
        None => job(n, dim, seed),
    };
    let _ = serde_json::to_writer(std::io::stdout(), &value);
    println!();
}
