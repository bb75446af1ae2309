//! The envelope of a fuzzy surface (docs/method.md §12) against the surface
//! evaluations it stands for: a bicubic 30 × 30 net over a crisp, regular
//! plan (a terrain's) on a 1000 × 1000 grid at 11 levels — 66 surfaces (11
//! levels × 3 functions × 2 bounds) — against sampling the crisp surface on a
//! 1000 × 1000 grid 66 times, both on one thread.
//!
//! The fuzzy contour (§13) of the shipped seabed
//! (`examples/salish-sea-seabed.json`, 16 × 20 stations) at z = 0 and one
//! level, on its default grid, as `t2spline contour` computes it.
//!
//! ```text
//! cargo bench -p t2spline --bench envelope
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use t2spline::sampling::Params;
use t2spline::set::PlanGrid;
use t2spline::strategies::seeded_uniform;
use t2spline::{Alpha, FuzzySurface, Nt2Number, Nt2Point};

/// Grid cells per direction.
const SIDE: usize = 1000;
/// Control points per direction.
const NET: usize = 30;

/// A bicubic 30 × 30 terrain: stations 10 apart, heights with spreads.
fn terrain() -> FuzzySurface<3> {
    let mut random = seeded_uniform(30);
    let crisp = |x: f64| Nt2Number::try_crisp(x).unwrap();
    let net = (0..NET)
        .map(|i| {
            (0..NET)
                .map(|j| {
                    let (x, y) = (10.0 * i as f64, 10.0 * j as f64);
                    let c = (x / 40.0).sin() * (y / 50.0).cos() * 20.0;
                    let (l, p, u) = (random(), random(), random());
                    let (l, p) = (1.0 + l, 2.0 + l + p);
                    let u = p + 1.0 + u;
                    let z =
                        Nt2Number::try_new(c, [c - u, c + u], [c - p, c + p], [c - l, c + l], 0.5)
                            .unwrap();
                    Nt2Point::new([crisp(x), crisp(y), z])
                })
                .collect()
        })
        .collect();
    FuzzySurface::try_new([3, 3], net, vec![vec![1.0; NET]; NET], [None, None]).unwrap()
}

fn envelope(c: &mut Criterion) {
    let s = terrain();
    let grid = PlanGrid::try_new(s.plan_extent(), [SIDE, SIDE]).unwrap();
    let levels: Vec<Alpha> = (0..=10)
        .map(|k| Alpha::try_new(f64::from(k) / 10.0).unwrap())
        .collect();
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let crisp = s.crisp_surface();
    let mut group = c.benchmark_group("envelope_30x30_on_1000x1000");
    group.sample_size(10);
    group.bench_function("envelope_11_levels", |b| {
        b.iter(|| black_box(s.envelope(&grid, &levels).unwrap()));
    });
    group.bench_function("crisp_grid_66_times", |b| {
        b.iter(|| {
            one.install(|| {
                for _ in 0..66 {
                    black_box(
                        crisp
                            .sample_grid(Params::Uniform(SIDE), Params::Uniform(SIDE))
                            .unwrap(),
                    );
                }
            });
        });
    });
    group.finish();
}

/// The shipped seabed, read from its job file with the core's constructors.
fn seabed() -> FuzzySurface<3> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/salish-sea-seabed.json"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let job: serde_json::Value = serde_json::from_str(&text).unwrap();
    let f = |v: &serde_json::Value| v.as_f64().unwrap();
    let pair = |v: &serde_json::Value| [f(&v[0]), f(&v[1])];
    let number = |v: &serde_json::Value| {
        let h = job["lower_height"].as_f64().unwrap_or(1.0);
        Nt2Number::try_new(
            f(&v["crisp"]),
            pair(&v["upper"]),
            pair(&v["primary"]),
            pair(&v["lower"]),
            h,
        )
        .unwrap()
    };
    let net = job["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|row| {
            row.as_array()
                .unwrap()
                .iter()
                .map(|p| Nt2Point::new([number(&p["x"]), number(&p["y"]), number(&p["z"])]))
                .collect()
        })
        .collect();
    let weights = job["weights"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_array().unwrap().iter().map(f).collect())
        .collect();
    let knots =
        ["u", "v"].map(|d| Some(job["knots"][d].as_array().unwrap().iter().map(f).collect()));
    let degree = [0, 1].map(|k| job["degree"][k].as_u64().unwrap() as usize);
    FuzzySurface::try_new(degree, net, weights, knots).unwrap()
}

fn contour(c: &mut Criterion) {
    let s = seabed();
    let extent = s.plan_extent();
    let grid = PlanGrid::try_new(extent, s.contour_shape(extent)).unwrap();
    let level = [Alpha::try_new(0.5).unwrap()];
    let mut group = c.benchmark_group("contour_seabed");
    group.bench_function("shoreline_one_level", |b| {
        b.iter(|| black_box(s.contour(&grid, 0.0, &level).unwrap()));
    });
    group.finish();
}

criterion_group!(benches, envelope, contour);
criterion_main!(benches);
