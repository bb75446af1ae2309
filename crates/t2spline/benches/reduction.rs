//! Reduction benchmarks (criterion): the exact reductions of one number
//! (centroid, Nie–Tan, alpha-planes) beside the paper's reduction as the
//! baseline of the same run, and the discrete algorithms (KM, EKM, EIASC,
//! Nie–Tan) on N = 1000 samples of a number's membership functions.
//!
//! ```text
//! cargo bench -p t2spline --bench reduction
//! ```
//! Before timing, the mean iteration counts of KM, EKM and EIASC over the
//! sampled numbers are printed, and the discrete centroids are checked against
//! the exact one (the O(1/N²) limit).

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::reduction::discrete::{sample, SampledSet};
use t2spline::{Alpha, Nt2Number, TypeReduction};

/// 64 numbers with spreads from a fixed xorshift sequence (no RNG crate).
fn numbers() -> Vec<Nt2Number> {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..64)
        .map(|_| {
            let c = 10.0 * next() - 5.0;
            let mut l = [next(), next(), next()];
            let mut r = [next(), next(), next()];
            l.sort_by(f64::total_cmp);
            r.sort_by(f64::total_cmp);
            let h = 0.1 + 0.9 * next();
            Nt2Number::try_new(
                c,
                [c - l[2], c + r[2]],
                [c - l[1], c + r[1]],
                [c - l[0], c + r[0]],
                h,
            )
            .unwrap()
        })
        .collect()
}

fn exact(c: &mut Criterion) {
    let xs = numbers();
    let alpha = Alpha::try_new(0.5).unwrap();
    let mut g = c.benchmark_group("exact (64 numbers)");
    for method in TypeReduction::ALL {
        g.bench_function(method.name(), |b| {
            b.iter(|| {
                let mut s = 0.0;
                for x in &xs {
                    s += black_box(x).reduce(method, alpha).defuzzified();
                }
                s
            });
        });
    }
    g.bench_function("centroid only", |b| {
        b.iter(|| {
            xs.iter()
                .map(|x| black_box(x).centroid().left())
                .sum::<f64>()
        });
    });
    g.finish();
}

fn discrete(c: &mut Criterion) {
    const N: usize = 1000;
    let sets: Vec<_> = numbers()
        .iter()
        .map(|x| (*x, sample(x, N).unwrap()))
        .collect();
    let (mut km, mut ekm, mut eiasc) = ([0usize; 2], [0usize; 2], [0usize; 2]);
    for (x, (xs, lmf, umf)) in &sets {
        let set = SampledSet::try_new(xs, lmf, umf).unwrap();
        let exact = x.centroid();
        for (sum, r) in [
            (&mut km, set.km()),
            (&mut ekm, set.ekm()),
            (&mut eiasc, set.eiasc()),
        ] {
            assert!(
                (r.left() - exact.left()).abs() < 1e-4 * x.upper().width(),
                "{x:?}"
            );
            sum[0] += r.iterations().left;
            sum[1] += r.iterations().right;
        }
    }
    let mean = |s: [usize; 2]| {
        (
            s[0] as f64 / sets.len() as f64,
            s[1] as f64 / sets.len() as f64,
        )
    };
    println!(
        "mean iterations on N = {N} (left, right): KM {:?}, EKM {:?}, EIASC {:?}",
        mean(km),
        mean(ekm),
        mean(eiasc)
    );
    let (x, (xs, lmf, umf)) = &sets[0];
    let set = SampledSet::try_new(xs, lmf, umf).unwrap();
    let mut g = c.benchmark_group("discrete N=1000 (one set)");
    g.bench_function("km", |b| b.iter(|| black_box(&set).km()));
    g.bench_function("ekm", |b| b.iter(|| black_box(&set).ekm()));
    g.bench_function("eiasc", |b| b.iter(|| black_box(&set).eiasc()));
    g.bench_function("nie-tan", |b| b.iter(|| black_box(&set).nie_tan()));
    g.bench_function("exact centroid of the same number", |b| {
        b.iter(|| black_box(x).centroid())
    });
    g.finish();
}

criterion_group!(benches, exact, discrete);
criterion_main!(benches);
