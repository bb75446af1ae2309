//! Benchmarks of the quantities measured on a fuzzy curve (docs/method.md
//! §11), criterion: the shipped example's whole measurement (11 levels, the
//! three functions, length and area) and a 20-point cubic's (length by
//! branch and bound past 2¹⁶ vertices, area by 2²⁰ x-vertices); the
//! baseline of the same run is sampling the example's seven layer curves
//! at 1000 parameters; the derivative, tangent angle and curvature of the
//! example at 100 parameters (`--at`) at one level. For surfaces (§14): the volumes and the plan area
//! below a datum of a bicubic 30 × 30 terrain at 11 levels (target 50 ms).
//!
//! ```text
//! cargo bench -p t2spline --bench measure
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::measure::{MeasureOptions, SurfaceMeasureOptions};
use t2spline::sampling::Params;
use t2spline::{FuzzyCurve, FuzzySurface, Nt2Number, Nt2Point};

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

/// A bicubic terrain on a regular 30 × 30 net of 10 m stations: rolling
/// heights around the datum 0 (seeded), spreads of 0.3 to 1 m.
pub fn terrain_30() -> FuzzySurface<3> {
    let mut uniform = t2spline::strategies::seeded_uniform(7);
    let n = 30;
    let points = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let (x, y) = (10.0 * i as f64, 10.0 * j as f64);
                    let z = 3.0 * (x / 60.0).sin() * (y / 80.0).cos() + uniform() - 0.5;
                    let s = 0.3 + 0.7 * uniform();
                    let c = |v: f64| Nt2Number::try_crisp(v).unwrap();
                    let h = Nt2Number::try_new(
                        z,
                        [z - s, z + s],
                        [z - 0.6 * s, z + 0.6 * s],
                        [z - 0.3 * s, z + 0.3 * s],
                        0.8,
                    )
                    .unwrap();
                    Nt2Point::new([c(x), c(y), h])
                })
                .collect()
        })
        .collect();
    FuzzySurface::try_new([3, 3], points, vec![vec![1.0; n]; n], [None, None]).unwrap()
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
    // `measure --at` with 100 parameters at the job's one level: the
    // derivative, the tangent angle and the curvature's bracket (a branch
    // and bound over the box of the cut control points) per function.
    let at = MeasureOptions::new(
        vec![t2spline::Alpha::try_new(0.8).unwrap()],
        (0..100).map(|k| f64::from(k) / 99.0).collect(),
        1,
    )
    .unwrap()
    .quantities(false, false);
    g.bench_function("shipped example, 100 parameters (--at), one level", |b| {
        b.iter(|| black_box(&curve).measure(&at).unwrap())
    });
    let twenty = twenty_points();
    g.bench_function("20-point cubic, 11 levels, length and area", |b| {
        b.iter(|| black_box(&twenty).measure(&options).unwrap())
    });
    let terrain = terrain_30();
    let volumes = SurfaceMeasureOptions::uniform(11).unwrap().with_area(false);
    g.bench_function(
        "30 x 30 bicubic terrain, 11 levels, volumes and plan area",
        |b| b.iter(|| black_box(&terrain).measure(&volumes).unwrap()),
    );
    g.finish();
}

criterion_group!(benches, measure);
criterion_main!(benches);
