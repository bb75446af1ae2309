//! Set-view benchmarks (criterion) on the shipped example
//! (`examples/paper-alg-1-1.json`, built here with the core API): the
//! membership map on a 1000 × 1000 grid (all three functions), one region
//! outline at the default tolerance, and the grades of 1000 points; the
//! baseline of the same run is sampling the seven layer curves at 1000
//! parameters.
//!
//! ```text
//! cargo bench -p t2spline --bench set
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::sampling::Params;
use t2spline::{Alpha, FuzzyCurve, Membership};

/// The shipped example (`examples/paper-alg-1-1.json`).
fn example() -> FuzzyCurve<2> {
    t2spline::strategies::paper_example()
}

fn set_view(c: &mut Criterion) {
    let curve = example();
    let mut g = c.benchmark_group("set view (shipped example)");
    g.sample_size(10);
    g.bench_function("baseline: seven layer curves at 1000 parameters", |b| {
        b.iter(|| {
            black_box(&curve)
                .sample_layers(Params::Uniform(1000))
                .unwrap()
        })
    });
    g.bench_function("membership map 1000 x 1000", |b| {
        b.iter(|| {
            black_box(&curve)
                .membership_grid([0.0, 7.5], [-0.5, 6.0], [1000, 1000])
                .unwrap()
        })
    });
    g.bench_function(
        "region outline (upper, alpha 0.5, default tolerance)",
        |b| {
            let a = Alpha::try_new(0.5).unwrap();
            b.iter(|| {
                black_box(&curve)
                    .region(Membership::Upper, a, None)
                    .unwrap()
            })
        },
    );
    let points: Vec<[f64; 2]> = (0..1000).map(|k| [7.5 * (k as f64 / 999.0), 3.0]).collect();
    g.bench_function("grades of 1000 points", |b| {
        b.iter(|| black_box(&curve).memberships(&points).unwrap())
    });
    g.finish();
}

criterion_group!(benches, set_view);
criterion_main!(benches);
