//! Reading job files from text: the shipped example, a curve of 100 000
//! fuzzy points (about 21 MB) and a surface of a 100 × 100 net (about
//! 4 MB), each through [`t2spline_io::parse_job`]; the curve again with
//! one rule broken in its last point, to time a file that has a problem; and
//! data files for `t2spline fit` through [`t2spline_io::parse_data`]: the
//! shipped one and 100 000 fuzzy data points (about 21 MB). The
//! large jobs are written here as text the way the shipped examples write
//! points, with numbers of a few decimals. Criterion prints each as bytes per
//! second.
//!
//! ```sh
//! cargo bench -p t2spline-io --bench parse
//! cargo bench -p t2spline-io --bench parse -- --save-baseline before   # then, after a change:
//! cargo bench -p t2spline-io --bench parse -- --baseline before
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::fmt::Write;
use std::hint::black_box;
use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};

/// One fuzzy number around `c` with spreads `s`, as the examples write it.
fn number(out: &mut String, c: f64, s: f64) {
    let _ = write!(
        out,
        "{{\"crisp\": {c:.3}, \"upper\": [{:.3}, {:.3}], \"primary\": [{:.3}, {:.3}], \"lower\": [{:.3}, {:.3}]}}",
        c - 3.0 * s,
        c + 2.5 * s,
        c - 2.0 * s,
        c + 1.5 * s,
        c - s,
        c + 0.5 * s
    );
}

/// A point of `coordinates` fuzzy numbers around `(x, y, z)`.
fn point(out: &mut String, xyz: [f64; 3], coordinates: usize) {
    out.push('{');
    for (i, (name, c)) in ["x", "y", "z"]
        .iter()
        .zip(xyz)
        .take(coordinates)
        .enumerate()
    {
        if i > 0 {
            out.push_str(", ");
        }
        let _ = write!(out, "\"{name}\": ");
        number(out, c, 0.05 + 0.01 * (c.abs() % 7.0));
    }
    out.push('}');
}

/// A planar curve job of `n` points of order 3 with weights, one point per
/// line.
fn curve(n: usize) -> String {
    let mut out = String::from(
        "{\n  \"description\": \"A long fuzzy curve\",\n  \"order\": 3,\n  \"alpha\": 0.8,\n  \"lower_height\": 0.6,\n  \"weights\": [",
    );
    for i in 0..n {
        let _ = write!(out, "{}{}", if i > 0 { ", " } else { "" }, 1 + i % 3);
    }
    out.push_str("],\n");
    planar_points(&mut out, n);
    out
}

/// A data file of `n` planar fuzzy data points for a fit of degree 3, one
/// point per line.
fn data(n: usize) -> String {
    let mut out = String::from(
        "{\n  \"description\": \"Many fuzzy measurements\",\n  \"degree\": 3,\n  \"alpha\": 0.8,\n  \"lower_height\": 0.6,\n  \"samples\": 200,\n",
    );
    planar_points(&mut out, n);
    out
}

/// The key `points` and `n` planar points along a wave, then the end of the
/// file.
fn planar_points(out: &mut String, n: usize) {
    out.push_str("  \"points\": [\n");
    for i in 0..n {
        let t = i as f64;
        out.push_str("    ");
        point(out, [t * 0.125, (t * 0.01).sin() * 40.0, 0.0], 2);
        out.push_str(if i + 1 < n { ",\n" } else { "\n" });
    }
    out.push_str("  ]\n}\n");
}

/// A surface job of an `n × n` net of orders 3 × 3, one point per line.
fn surface(n: usize) -> String {
    let mut out = String::from(
        "{\n  \"description\": \"A fuzzy terrain\",\n  \"order\": [3, 3],\n  \"alpha\": 0.5,\n  \"lower_height\": 0.6,\n  \"samples\": [21, 21],\n  \"points\": [\n",
    );
    for i in 0..n {
        out.push_str("    [\n");
        for j in 0..n {
            let (x, y) = (i as f64 * 10.0, j as f64 * 10.0);
            let z = 100.0 + (x * 0.01).sin() * 5.0 + (y * 0.02).cos() * 3.0;
            out.push_str("      ");
            point(&mut out, [x, y, z], 3);
            out.push_str(if j + 1 < n { ",\n" } else { "\n" });
        }
        out.push_str(if i + 1 < n { "    ],\n" } else { "    ]\n" });
    }
    out.push_str("  ]\n}\n");
    out
}

fn bench(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json");
    let example = std::fs::read_to_string(path).expect("the shipped example");
    let long = curve(100_000);
    // One broken rule at the end: every problem must be found and placed.
    let crisp = long.rfind("\"crisp\": ").expect("a crisp value");
    let after = crisp + long[crisp..].find(',').expect("more values");
    let broken = format!("{}\"crisp\": 1e9{}", &long[..crisp], &long[after..]);
    let inputs = [
        ("example", example, 100, true),
        ("curve-100000-points", long, 10, true),
        ("surface-100x100", surface(100), 10, true),
        ("curve-100000-points-last-broken", broken, 10, false),
    ];
    let mut g = c.benchmark_group("parse");
    for (name, text, samples, valid) in &inputs {
        let read = t2spline_io::parse_job(text, name);
        assert_eq!(read.is_ok(), *valid, "{:?}", read.err());
        g.sample_size(*samples);
        g.throughput(Throughput::Bytes(text.len() as u64));
        g.bench_function(*name, |b| {
            b.iter(|| t2spline_io::parse_job(black_box(text), name));
        });
    }
    g.finish();
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fit-measurements.json");
    let example = std::fs::read_to_string(path).expect("the shipped data file");
    let inputs = [
        ("data-example", example, 100),
        ("data-100000-points", data(100_000), 10),
    ];
    let mut g = c.benchmark_group("parse-data");
    for (name, text, samples) in &inputs {
        let read = t2spline_io::parse_data(text, name);
        assert!(read.is_ok(), "{:?}", read.err());
        g.sample_size(*samples);
        g.throughput(Throughput::Bytes(text.len() as u64));
        g.bench_function(*name, |b| {
            b.iter(|| t2spline_io::parse_data(black_box(text), name));
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
