//! Surface sampling benchmarks (criterion): the `benchmark_surface` (bicubic,
//! rational, 8 × 8 net) on a 1000 × 1000 grid — the crisp surface on one
//! thread, the seven layer surfaces on one thread, both on one and two threads
//! into fresh arrays and into reused ones (and `crisp_fresh_uncached`: fresh
//! with the cache of dropped mappings emptied before each call, as a
//! process's first call) — and
//! the same crisp surface sampled by curvo's `NurbsSurface::regular_sample_points`
//! in the same run, so that the ratios are measured side by side.
//!
//! ```text
//! cargo bench -p t2spline --bench surface
//! ```
//! Before timing, the curvo and t2spline grids are compared point by point
//! (1e-12), so both compute the same thing.

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use curvo::prelude::NurbsSurface3D;
use nalgebra::Point4;
use t2spline::sampling::{
    benchmark_surface, release_cached_memory, CurveSamples, Grid, LayerSamples, Params,
};
use t2spline::{Direction, NurbsSurface};

/// Grid points per direction.
const SIDE: usize = 1000;

/// The same crisp surface for curvo: homogeneous control points (w·P, w).
fn curvo_surface(s: &NurbsSurface<3>) -> NurbsSurface3D<f64> {
    let [nu, nv] = s.shape();
    let points = (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| {
                    let (p, w) = (s.control_point(i, j).unwrap(), s.weights()[i * nv + j]);
                    Point4::new(p[0] * w, p[1] * w, p[2] * w, w)
                })
                .collect()
        })
        .collect();
    let [p, q] = s.degree();
    NurbsSurface3D::new(
        p,
        q,
        s.knots(Direction::U).as_slice().to_vec(),
        s.knots(Direction::V).as_slice().to_vec(),
        points,
    )
}

fn pool(t: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(t)
        .build()
        .unwrap()
}

fn crisp(c: &mut Criterion) {
    let surface = benchmark_surface().crisp_surface();
    let peer = curvo_surface(&surface);
    // Same surface, same grid: compare before timing.
    let ours = surface
        .sample_grid(Params::Uniform(101), Params::Uniform(101))
        .unwrap();
    let theirs = peer.regular_sample_points(100, 100);
    for (a, row) in theirs.iter().enumerate() {
        for (b, q) in row.iter().enumerate() {
            let p = ours.samples().point(ours.index(a, b).unwrap()).unwrap();
            assert!(
                (p[0] - q.x).abs() < 1e-12
                    && (p[1] - q.y).abs() < 1e-12
                    && (p[2] - q.z).abs() < 1e-12,
                "({a}, {b}): {p:?} vs {q:?}"
            );
        }
    }
    let n = SIDE * SIDE;
    let mut g = c.benchmark_group("surface_crisp");
    g.throughput(Throughput::Elements(n as u64)).sample_size(10);
    let one = pool(1);
    g.bench_function(BenchmarkId::new("t2spline", n), |b| {
        b.iter(|| {
            one.install(|| {
                black_box(
                    surface
                        .sample_grid(Params::Uniform(SIDE), Params::Uniform(SIDE))
                        .unwrap(),
                )
            })
        });
    });
    let mut out = Grid::buffer(CurveSamples::empty());
    g.bench_function(BenchmarkId::new("t2spline_reused_output", n), |b| {
        b.iter(|| {
            one.install(|| {
                surface
                    .sample_grid_into(
                        Params::Uniform(SIDE),
                        Params::Uniform(SIDE),
                        black_box(&mut out),
                    )
                    .unwrap()
            })
        });
    });
    g.bench_function(BenchmarkId::new("curvo_regular_sample_points", n), |b| {
        b.iter(|| black_box(peer.regular_sample_points(SIDE - 1, SIDE - 1)));
    });
    g.finish();
}

fn fuzzy(c: &mut Criterion) {
    let surface = benchmark_surface();
    let crisp = surface.crisp_surface();
    let n = SIDE * SIDE;
    let mut g = c.benchmark_group("surface_threads");
    g.throughput(Throughput::Elements(n as u64)).sample_size(10);
    for t in [1, 2] {
        let threads = pool(t);
        g.bench_function(BenchmarkId::new("crisp", t), |b| {
            b.iter(|| {
                threads.install(|| {
                    black_box(
                        crisp
                            .sample_grid(Params::Uniform(SIDE), Params::Uniform(SIDE))
                            .unwrap(),
                    )
                })
            });
        });
        g.bench_function(BenchmarkId::new("crisp_fresh_uncached", t), |b| {
            b.iter_batched(
                release_cached_memory,
                |()| {
                    threads.install(|| {
                        black_box(
                            crisp
                                .sample_grid(Params::Uniform(SIDE), Params::Uniform(SIDE))
                                .unwrap(),
                        )
                    })
                },
                BatchSize::PerIteration,
            );
        });
        let mut out = Grid::buffer(CurveSamples::empty());
        g.bench_function(BenchmarkId::new("crisp_reused_output", t), |b| {
            b.iter(|| {
                threads.install(|| {
                    crisp
                        .sample_grid_into(
                            Params::Uniform(SIDE),
                            Params::Uniform(SIDE),
                            black_box(&mut out),
                        )
                        .unwrap()
                })
            });
        });
        g.bench_function(BenchmarkId::new("seven_layers", t), |b| {
            b.iter(|| {
                threads.install(|| {
                    black_box(
                        surface
                            .sample_layers(Params::Uniform(SIDE), Params::Uniform(SIDE))
                            .unwrap(),
                    )
                })
            });
        });
        let mut out = Grid::buffer(LayerSamples::empty());
        g.bench_function(BenchmarkId::new("seven_layers_reused_output", t), |b| {
            b.iter(|| {
                threads.install(|| {
                    surface
                        .sample_layers_into(
                            Params::Uniform(SIDE),
                            Params::Uniform(SIDE),
                            black_box(&mut out),
                        )
                        .unwrap()
                })
            });
        });
    }
    g.finish();
}

criterion_group!(benches, crisp, fuzzy);
criterion_main!(benches);
