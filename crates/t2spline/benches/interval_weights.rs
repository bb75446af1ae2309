//! Curves with uncertain weights at one parameter (docs/method.md §15): the
//! envelope, the support function, membership and a section, for the terms
//! of a cubic (4 terms) and of a curve of degree 15 (16 terms), in two and
//! three coordinates, at random query points inside the envelope.
//!
//! ```text
//! cargo bench -p t2spline --bench interval_weights
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::interval_weights::IntervalTerms;
use t2spline::strategies::seeded_uniform;
use t2spline::Axis;

fn terms<const D: usize>(n: usize, seed: u64) -> IntervalTerms<D> {
    let mut r = seeded_uniform(seed);
    let mut basis: Vec<f64> = (0..n).map(|_| 0.1 + r()).collect();
    let sum: f64 = basis.iter().sum();
    basis.iter_mut().for_each(|b| *b /= sum);
    let weights: Vec<[f64; 2]> = (0..n)
        .map(|_| {
            let a = 0.5 + r();
            [a, a + r()]
        })
        .collect();
    let points: Vec<[[f64; 2]; D]> = (0..n)
        .map(|_| {
            std::array::from_fn(|_| {
                let a = 10.0 * r();
                [a, a + r()]
            })
        })
        .collect();
    IntervalTerms::try_new(&basis, &weights, &points).unwrap()
}

fn queries<const D: usize>(t: &IntervalTerms<D>, count: usize) -> Vec<[f64; D]> {
    let env = t.envelope();
    let mut r = seeded_uniform(99);
    (0..count)
        .map(|_| std::array::from_fn(|k| env[k].left() + env[k].width() * r()))
        .collect()
}

fn bench<const D: usize>(c: &mut Criterion, n: usize) {
    let t = terms::<D>(n, 7 + n as u64);
    let qs = queries(&t, 64);
    let name = |what: &str| format!("{what}/d{D}/n{n}");
    c.bench_function(&name("envelope"), |b| b.iter(|| black_box(&t).envelope()));
    c.bench_function(&name("support"), |b| {
        b.iter(|| black_box(&t).support([1.0; D]).unwrap())
    });
    c.bench_function(&name("contains_x64"), |b| {
        b.iter(|| {
            qs.iter()
                .filter(|&&q| t.contains(black_box(q)).unwrap())
                .count()
        })
    });
    if D >= 2 {
        let env = t.envelope();
        let x0 = env[0].left() + 0.37 * env[0].width();
        c.bench_function(&name("section"), |b| {
            b.iter(|| t.section(Axis::X, black_box(x0), Axis::Y).unwrap())
        });
    }
}

fn all(c: &mut Criterion) {
    bench::<2>(c, 4);
    bench::<2>(c, 16);
    bench::<3>(c, 4);
    bench::<3>(c, 16);
}

criterion_group!(benches, all);
criterion_main!(benches);
