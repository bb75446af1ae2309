//! Sampling benchmarks (criterion): the crisp curve, the seven layer curves and
//! an 11-level alpha sweep of the `t2spline bench` curve, and the same crisp
//! curve sampled by the Rust crate curvo (`sample_regular_range`) in the same
//! run, so that the ratio is measured side by side.
//!
//! ```text
//! cargo bench -p t2spline --bench sampling
//! ```
//! Every benchmark runs on one thread except `threads/*`. Before timing, the
//! curvo and t2spline samples are compared point by point (1e-12), so both
//! compute the same thing.

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use curvo::prelude::NurbsCurve2D;
use nalgebra::Point3;
use t2spline::sampling::{CurveSamples, LayerSamples, Params};
use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point, NurbsCurve};

const POINTS: [[f64; 2]; 10] = [
    [0.0, 0.0],
    [1.0, 2.0],
    [2.0, -1.0],
    [3.0, 3.0],
    [4.0, 0.0],
    [5.0, 2.5],
    [6.0, -2.0],
    [7.0, 1.0],
    [8.0, 3.0],
    [9.0, 0.0],
];
const WEIGHTS: [f64; 10] = [1.0, 0.5, 2.0, 1.0, 3.0, 0.7, 1.0, 1.5, 0.8, 1.0];

/// The `t2spline bench` curve (see `t2spline_io::bench::default_curve`).
fn fuzzy_curve() -> FuzzyCurve<2> {
    let number = |c: f64| {
        Nt2Number::try_new(
            c,
            [c - 0.3, c + 0.45],
            [c - 0.2, c + 0.3],
            [c - 0.1, c + 0.15],
            0.6,
        )
        .unwrap()
    };
    let points = POINTS
        .iter()
        .map(|p| Nt2Point::new(p.map(number)))
        .collect();
    FuzzyCurve::try_new(3, points, WEIGHTS.to_vec(), None).unwrap()
}

/// The same crisp curve for curvo: homogeneous control points (w·x, w·y, w).
fn curvo_curve(c: &NurbsCurve<2>) -> NurbsCurve2D<f64> {
    let points = c
        .control_points()
        .iter()
        .zip(c.weights())
        .map(|(p, &w)| Point3::new(p[0] * w, p[1] * w, w))
        .collect();
    NurbsCurve2D::try_new(3, points, c.knots().as_slice().to_vec()).unwrap()
}

/// A rayon pool of `t` threads; each timed call runs inside it.
fn pool(t: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(t)
        .build()
        .unwrap()
}

fn crisp(c: &mut Criterion) {
    let curve = fuzzy_curve().crisp_curve();
    let peer = curvo_curve(&curve);
    let n = 1_000_000;
    // Same curve, same parameters: compare before timing.
    let ours = curve.sample_soa(Params::Uniform(1001)).unwrap();
    let theirs = peer.sample_regular_range(0.0, 1.0, 1001);
    for (i, q) in theirs.iter().enumerate() {
        let p = ours.point(i);
        assert!(
            (p[0] - q.x).abs() < 1e-12 && (p[1] - q.y).abs() < 1e-12,
            "{i}: {p:?} vs {q:?}"
        );
    }
    let mut g = c.benchmark_group("crisp");
    g.throughput(Throughput::Elements(n as u64)).sample_size(20);
    let one = pool(1);
    g.bench_function(BenchmarkId::new("t2spline", n), |b| {
        b.iter(|| one.install(|| black_box(curve.sample_soa(Params::Uniform(n)).unwrap())));
    });
    let mut out = CurveSamples::empty();
    g.bench_function(BenchmarkId::new("t2spline_reused_output", n), |b| {
        b.iter(|| {
            one.install(|| {
                curve
                    .sample_soa_into(Params::Uniform(n), black_box(&mut out))
                    .unwrap()
            })
        });
    });
    g.bench_function(BenchmarkId::new("curvo_sample_regular_range", n), |b| {
        b.iter(|| black_box(peer.sample_regular_range(0.0, 1.0, n)));
    });
    g.finish();
}

fn fuzzy(c: &mut Criterion) {
    let curve = fuzzy_curve();
    let n = 1_000_000;
    let mut g = c.benchmark_group("fuzzy");
    g.throughput(Throughput::Elements(n as u64)).sample_size(10);
    let one = pool(1);
    g.bench_function(BenchmarkId::new("seven_layers", n), |b| {
        b.iter(|| one.install(|| black_box(curve.sample_layers(Params::Uniform(n)).unwrap())));
    });
    let mut out = LayerSamples::empty();
    g.bench_function(BenchmarkId::new("seven_layers_reused_output", n), |b| {
        b.iter(|| {
            one.install(|| {
                curve
                    .sample_layers_into(Params::Uniform(n), black_box(&mut out))
                    .unwrap()
            })
        });
    });
    g.finish();
}

fn sweep(c: &mut Criterion) {
    let curve = fuzzy_curve();
    let levels: Vec<Alpha> = (0..=10)
        .map(|k| Alpha::try_new(k as f64 / 10.0).unwrap())
        .collect();
    let n = 100_000;
    let mut g = c.benchmark_group("sweep");
    g.throughput(Throughput::Elements(n as u64)).sample_size(10);
    let one = pool(1);
    g.bench_function(BenchmarkId::new("eleven_levels", n), |b| {
        b.iter(|| {
            one.install(|| black_box(curve.sample_sweep(Params::Uniform(n), &levels).unwrap()))
        });
    });
    g.finish();
}

fn threads(c: &mut Criterion) {
    let curve = fuzzy_curve();
    let crisp = curve.crisp_curve();
    let n = 10_000_000;
    let mut g = c.benchmark_group("threads");
    g.throughput(Throughput::Elements(n as u64)).sample_size(10);
    for t in [1, 2] {
        let threads = pool(t);
        let mut out = CurveSamples::empty();
        g.bench_function(BenchmarkId::new("crisp_reused_output", t), |b| {
            b.iter(|| {
                threads.install(|| {
                    crisp
                        .sample_soa_into(Params::Uniform(n), black_box(&mut out))
                        .unwrap()
                })
            });
        });
        let mut out = LayerSamples::empty();
        g.bench_function(BenchmarkId::new("seven_layers_reused_output", t), |b| {
            b.iter(|| {
                threads.install(|| {
                    curve
                        .sample_layers_into(Params::Uniform(n), black_box(&mut out))
                        .unwrap()
                })
            });
        });
    }
    g.finish();
}

criterion_group!(benches, crisp, fuzzy, sweep, threads);
criterion_main!(benches);
