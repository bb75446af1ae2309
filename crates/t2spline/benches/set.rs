//! Set-view benchmarks (criterion) on the shipped example
//! (`examples/paper-alg-1-1.json`, built here with the core API): the
//! membership map on a 1000 × 1000 grid (all three functions), one region
//! outline at the default tolerance, the grades of 1000 points on a line
//! and of 10 000 points scattered over the map (one thread); the
//! baseline of the same run is sampling the seven layer curves at 1000
//! parameters. Beside them, one level of a station section of the shipped
//! cylinder (`examples/fuzzy-cylinder.json`) at its edge and on its wall.
//!
//! ```text
//! cargo bench -p t2spline --bench set
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::sampling::Params;
use t2spline::{Alpha, FuzzyCurve, FuzzySurface, Membership, Nt2Number, Nt2Point};

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
    let scattered = scattered_points(10_000);
    g.bench_function("grades of 10000 scattered points (one thread)", |b| {
        b.iter(|| black_box(&curve).memberships(&scattered).unwrap())
    });
    g.finish();
}

/// The shipped cylinder (`examples/fuzzy-cylinder.json`, built with the core
/// API): x and y spread radially, z crisp and a function of v only.
fn cylinder() -> FuzzySurface<3> {
    let n = |c: f64, u: [f64; 2], p: [f64; 2], l: [f64; 2]| {
        Nt2Number::try_new(c, u, p, l, 0.6).unwrap()
    };
    let r = |c: f64| {
        n(
            c,
            [0.94 * c, 1.09 * c],
            [0.96 * c, 1.06 * c],
            [0.98 * c, 1.03 * c],
        )
    };
    let z = |c: f64| n(c, [c, c], [c, c], [c, c]);
    let row = |x: f64, y: f64| {
        vec![
            Nt2Point::new([r(x), r(y), z(0.0)]),
            Nt2Point::new([r(x), r(y), z(3.0)]),
        ]
    };
    let w = std::f64::consts::FRAC_1_SQRT_2;
    FuzzySurface::try_new(
        [2, 1],
        vec![row(2.5, 0.0), row(2.5, 2.5), row(0.0, 2.5)],
        vec![vec![1.0, 1.0], vec![w, w], vec![1.0, 1.0]],
        [None, None],
    )
    .unwrap()
}

fn sections(c: &mut Criterion) {
    let s = cylinder();
    let mut g = c.benchmark_group("surface sections (shipped cylinder)");
    g.sample_size(10);
    let level = [Alpha::try_new(0.5).unwrap()];
    let diagonal = 2.5 * std::f64::consts::FRAC_1_SQRT_2;
    for (name, at) in [
        ("edge (2.5, 0)", [2.5, 0.0]),
        ("wall (1.77, 1.77)", [diagonal, diagonal]),
    ] {
        g.bench_function(format!("one level at the {name}"), |b| {
            b.iter(|| black_box(&s).sections(at, &level).unwrap())
        });
    }
    g.finish();
}

/// `count` points spread over the map's rectangle `[0, 7.5] × [−0.5, 6]` by
/// a fixed linear congruential generator (Knuth's MMIX constants): about
/// two in five fall in the upper region at level 0.
fn scattered_points(count: usize) -> Vec<[f64; 2]> {
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|_| [7.5 * next(), -0.5 + 6.5 * next()])
        .collect()
}

criterion_group!(benches, set_view, sections);
criterion_main!(benches);
