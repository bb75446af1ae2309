//! Sampling benchmarks (criterion): the crisp curve, the seven layer curves and
//! an 11-level alpha sweep of the `t2spline bench` curve, and the same crisp
//! curve sampled by the Rust crate curvo (`sample_regular_range`) in the same
//! run, so that the ratio is measured side by side.
//!
//! ```text
//! cargo bench -p t2spline --bench sampling
//! ```
//! `fresh_vs_reused/*` samples the crisp curve and the seven layers at 10⁶
//! points into fresh arrays and into reused ones, on one and on two threads,
//! and into fresh arrays with the cache of dropped mappings emptied before
//! each call (`*_fresh_uncached`: every page new, as in a process's first
//! call).
//! Every benchmark runs on one thread except `threads/*` and
//! `fresh_vs_reused/*`. Before timing, the
//! curvo and t2spline samples are compared point by point (1e-12), so both
//! compute the same thing.

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use curvo::prelude::NurbsCurve2D;
use nalgebra::Point3;
use t2spline::sampling::{
    benchmark_curve, benchmark_levels, release_cached_memory, CurveSamples, LayerSamples, Params,
};
use t2spline::{FuzzyCurve, NurbsCurve};

/// The `t2spline bench` curve.
fn fuzzy_curve() -> FuzzyCurve<2> {
    benchmark_curve()
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
        let p = ours.point(i).unwrap();
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
    let levels = benchmark_levels();
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

fn fresh_vs_reused(c: &mut Criterion) {
    let curve = fuzzy_curve();
    let crisp = curve.crisp_curve();
    let n = 1_000_000;
    let mut g = c.benchmark_group("fresh_vs_reused");
    g.throughput(Throughput::Elements(n as u64)).sample_size(10);
    for t in [1, 2] {
        let threads = pool(t);
        g.bench_function(BenchmarkId::new("crisp_fresh", t), |b| {
            b.iter(|| threads.install(|| black_box(crisp.sample_soa(Params::Uniform(n)).unwrap())));
        });
        // As the first call of a process: every page new from the system
        // (the cache of dropped mappings emptied before each call).
        g.bench_function(BenchmarkId::new("crisp_fresh_uncached", t), |b| {
            b.iter_batched(
                release_cached_memory,
                |()| threads.install(|| black_box(crisp.sample_soa(Params::Uniform(n)).unwrap())),
                BatchSize::PerIteration,
            );
        });
        let mut out = CurveSamples::empty();
        g.bench_function(BenchmarkId::new("crisp_reused", t), |b| {
            b.iter(|| {
                threads.install(|| {
                    crisp
                        .sample_soa_into(Params::Uniform(n), black_box(&mut out))
                        .unwrap()
                })
            });
        });
        g.bench_function(BenchmarkId::new("seven_layers_fresh", t), |b| {
            b.iter(|| {
                threads.install(|| black_box(curve.sample_layers(Params::Uniform(n)).unwrap()))
            });
        });
        g.bench_function(BenchmarkId::new("seven_layers_fresh_uncached", t), |b| {
            b.iter_batched(
                release_cached_memory,
                |()| {
                    threads.install(|| black_box(curve.sample_layers(Params::Uniform(n)).unwrap()))
                },
                BatchSize::PerIteration,
            );
        });
        let mut out = LayerSamples::empty();
        g.bench_function(BenchmarkId::new("seven_layers_reused", t), |b| {
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

criterion_group!(benches, crisp, fuzzy, sweep, threads, fresh_vs_reused);
criterion_main!(benches);
