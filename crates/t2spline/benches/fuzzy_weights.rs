//! Curves with fuzzy weights (docs/method.md §16) against the same curves
//! with crisp weights, on the shipped example (`examples/fuzzy-weights.json`:
//! the paper's configuration, its third weight fuzzy, and every weight
//! fuzzy): the four stages sampled at 10 001 parameters, the certified
//! membership of one point, and the section at one station at 11 levels.
//!
//! ```text
//! cargo bench -p t2spline --bench fuzzy_weights
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::sampling::Params;
use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point};

fn number(c: f64, [ul, ur]: [f64; 2], [pl, pr]: [f64; 2], [ll, lr]: [f64; 2]) -> Nt2Number {
    Nt2Number::try_new(c, [ul, ur], [pl, pr], [ll, lr], 0.6).unwrap()
}

/// The paper's configuration (examples/paper-alg-1-1.json).
fn crisp() -> FuzzyCurve<2> {
    let points = vec![
        Nt2Point::new([
            number(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3]),
            number(1.0, [0.2, 1.5], [0.5, 1.35], [0.75, 1.2]),
        ]),
        Nt2Point::new([
            number(2.0, [1.5, 2.8], [1.7, 2.5], [1.85, 2.25]),
            number(4.0, [3.3, 4.4], [3.5, 4.3], [3.8, 4.15]),
        ]),
        Nt2Point::new([
            number(5.0, [4.1, 5.6], [4.4, 5.45], [4.7, 5.2]),
            number(4.5, [4.0, 5.4], [4.2, 5.1], [4.35, 4.8]),
        ]),
        Nt2Point::new([
            number(6.0, [5.3, 6.9], [5.5, 6.6], [5.8, 6.3]),
            number(1.0, [0.4, 1.8], [0.6, 1.5], [0.8, 1.25]),
        ]),
    ];
    FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 3.0, 1.0], None).unwrap()
}

/// Every weight fuzzy: ±(1/3, 1/2) of its value on the upper cut.
fn all_fuzzy() -> FuzzyCurve<2> {
    let w = |c: f64| {
        number(
            c,
            [c * 2.0 / 3.0, c * 1.5],
            [c * 0.8, c * 1.33],
            [c * 0.9, c * 1.17],
        )
    };
    crisp()
        .with_weight_numbers(vec![w(1.0), w(1.0), w(3.0), w(1.0)])
        .unwrap()
}

fn bench(c: &mut Criterion) {
    let alpha = Alpha::try_new(0.8).unwrap();
    let (plain, fuzzy) = (crisp(), all_fuzzy());
    let mut g = c.benchmark_group("fuzzy weights");
    for (name, curve) in [("crisp", &plain), ("fuzzy", &fuzzy)] {
        g.bench_function(
            format!("four stages, 10 001 samples, {name} weights"),
            |b| {
                b.iter(|| {
                    let s = curve.solve(alpha);
                    black_box(
                        curve
                            .sample_sweep(Params::Uniform(10_001), &[alpha])
                            .unwrap(),
                    );
                    black_box(s.distance())
                });
            },
        );
        g.bench_function(format!("membership of one point, {name} weights"), |b| {
            b.iter(|| black_box(curve.membership(&[3.5, 4.2]).unwrap()));
        });
        let levels: Vec<Alpha> = (0..=10)
            .map(|k| Alpha::try_new(f64::from(k) / 10.0).unwrap())
            .collect();
        g.bench_function(
            format!("section at x = 3, 11 levels, {name} weights"),
            |b| {
                b.iter(|| black_box(curve.sections(3.0, &levels, None).unwrap()));
            },
        );
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
