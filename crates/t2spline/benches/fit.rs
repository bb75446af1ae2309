//! Fitting benchmarks (criterion): the valid fuzzy fit (`fit_fuzzy`,
//! interpolation, chord-length parameters) of random fuzzy data at 1 000,
//! 10 000 and 100 000 points of degree 3, and 10 000 points of degree 9.
//!
//! ```text
//! cargo bench -p t2spline --bench fit
//! ```
//! The data are a random walk in the plane (steps 0.1–3) whose spreads are
//! drawn per point and coordinate, zero half of the time, as in the peer check
//! `peer/fit/check_fit.py`: spreads that jump from point to point make the
//! non-negative least squares of the valid fit hold thousands of constraints.
//! The time should grow linearly with the number of points: compare the
//! ratios of the three sizes.
//!
//! Surfaces: the valid fuzzy fit (`fit_fuzzy_surface`, least squares with
//! 40 × 40 control points, chord-length parameters) of a fuzzy terrain on
//! nets of 125 × 125, 250 × 250 and 500 × 500 stations (x and y crisp, z
//! spread as blocks of a raster give it); for a fixed net of control points
//! the time should grow linearly with the number of stations.

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use t2spline::fit::{fit_fuzzy, fit_fuzzy_surface, FitOptions, FuzzyFitMode, SurfaceFitOptions};
use t2spline::strategies::seeded_uniform;
use t2spline::{Nt2Number, Nt2Point};

/// Three spreads in increasing order, each zero half of the time.
fn spreads(random: &mut impl FnMut() -> f64) -> [f64; 3] {
    let mut s = [0.0; 3].map(|_| if random() < 0.5 { 0.0 } else { 3.0 * random() });
    s.sort_by(f64::total_cmp);
    s
}

/// `count` fuzzy data points on a random walk.
fn data(count: usize, seed: u64) -> Vec<Nt2Point<2>> {
    let mut random = seeded_uniform(seed);
    let mut at = [20.0 * random() - 10.0, 20.0 * random() - 10.0];
    (0..count)
        .map(|_| {
            let point = Nt2Point::new(at.map(|c| {
                let [l0, l1, l2] = spreads(&mut random);
                let [r0, r1, r2] = spreads(&mut random);
                Nt2Number::try_new(c, [c - l2, c + r2], [c - l1, c + r1], [c - l0, c + r0], 0.5)
                    .expect("ordered by construction")
            }));
            let angle = std::f64::consts::TAU * random();
            let step = 0.1 + 2.9 * random();
            at = [at[0] + step * angle.cos(), at[1] + step * angle.sin()];
            point
        })
        .collect()
}

fn valid_fit(c: &mut Criterion) {
    let mut g = c.benchmark_group("fit_fuzzy_valid");
    g.sample_size(10);
    for (count, degree, seconds) in [
        (1_000, 3, 5),
        (10_000, 3, 10),
        (100_000, 3, 20),
        (10_000, 9, 20),
    ] {
        let points = data(count, 1);
        let options = FitOptions::interpolation(degree).unwrap();
        g.throughput(Throughput::Elements(count as u64))
            .measurement_time(Duration::from_secs(seconds));
        g.bench_function(BenchmarkId::new(format!("degree_{degree}"), count), |b| {
            b.iter(|| {
                black_box(fit_fuzzy(black_box(&points), &options, FuzzyFitMode::Valid).unwrap())
            });
        });
    }
    g.finish();
}

/// A fuzzy terrain on a `size × size` net of stations: crisp x and y on a
/// grid, a smooth height with random spreads (zero a quarter of the time).
fn terrain(size: usize, seed: u64) -> Vec<Vec<Nt2Point<3>>> {
    let mut random = seeded_uniform(seed);
    let crisp = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 0.5).expect("crisp");
    (0..size)
        .map(|i| {
            (0..size)
                .map(|j| {
                    let (x, y) = (i as f64 * 4.0, j as f64 * 4.0);
                    let z = 20.0 * (x / 150.0).sin() * (y / 110.0).cos() + 0.01 * x;
                    let mut s = [0.0; 3].map(|_| if random() < 0.25 { 0.0 } else { random() });
                    s.sort_by(f64::total_cmp);
                    let r = s.map(|v| 1.3 * v);
                    let z = Nt2Number::try_new(
                        z,
                        [z - s[2], z + r[2]],
                        [z - s[1], z + r[1]],
                        [z - s[0], z + r[0]],
                        0.5,
                    )
                    .expect("ordered by construction");
                    Nt2Point::new([crisp(x), crisp(y), z])
                })
                .collect()
        })
        .collect()
}

fn valid_surface_fit(c: &mut Criterion) {
    let mut g = c.benchmark_group("fit_fuzzy_surface_valid");
    g.sample_size(10);
    let options = SurfaceFitOptions::approximation([3, 3], [40, 40]).unwrap();
    for size in [125, 250, 500] {
        let net = terrain(size, 2);
        g.throughput(Throughput::Elements((size * size) as u64))
            .measurement_time(Duration::from_secs(10));
        g.bench_function(BenchmarkId::new("least_squares_40x40", size * size), |b| {
            b.iter(|| {
                black_box(
                    fit_fuzzy_surface(black_box(&net), &options, FuzzyFitMode::Valid).unwrap(),
                )
            });
        });
    }
    g.finish();
}

criterion_group!(benches, valid_fit, valid_surface_fit);
criterion_main!(benches);
