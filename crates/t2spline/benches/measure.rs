//! Benchmarks of the quantities measured on a fuzzy curve (docs/method.md
//! §11), criterion: the shipped example's whole measurement (11 levels, the
//! three functions, length and area) and a 20-point cubic's (length by
//! branch and bound past 2¹⁶ vertices, area by 2²⁰ x-vertices); the
//! baseline of the same run is sampling the example's seven layer curves
//! at 1000 parameters.
//!
//! ```text
//! cargo bench -p t2spline --bench measure
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::measure::MeasureOptions;
use t2spline::sampling::Params;
use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};

/// The shipped example (`examples/paper-alg-1-1.json`).
fn example() -> FuzzyCurve<2> {
    t2spline::strategies::paper_example()
}

/// A cubic through 20 fuzzy points along a wave, spreads of a tenth of the
/// spacing on every coordinate.
pub fn twenty_points() -> FuzzyCurve<2> {
    let n = |c: f64, s: f64| {
        Nt2Number::try_new(
            c,
            [c - s, c + 1.2 * s],
            [c - 0.7 * s, c + 0.8 * s],
            [c - 0.3 * s, c + 0.4 * s],
            0.6,
        )
        .unwrap()
    };
    let points = (0..20)
        .map(|i| {
            let x = i as f64;
            Nt2Point::new([n(x, 0.1), n((0.7 * x).sin() * 2.0, 0.1)])
        })
        .collect();
    FuzzyCurve::try_new(3, points, vec![1.0; 20], None).unwrap()
}

fn measure(c: &mut Criterion) {
    let curve = example();
    let options = MeasureOptions::uniform(11).unwrap();
    let mut g = c.benchmark_group("measure");
    g.sample_size(10);
    g.bench_function("baseline: seven layer curves at 1000 parameters", |b| {
        b.iter(|| {
            black_box(&curve)
                .sample_layers(Params::Uniform(1000))
                .unwrap()
        })
    });
    g.bench_function("shipped example, 11 levels, length and area", |b| {
        b.iter(|| black_box(&curve).measure(&options).unwrap())
    });
    let twenty = twenty_points();
    g.bench_function("20-point cubic, 11 levels, length and area", |b| {
        b.iter(|| black_box(&twenty).measure(&options).unwrap())
    });
    g.finish();
}

criterion_group!(benches, measure);
criterion_main!(benches);
