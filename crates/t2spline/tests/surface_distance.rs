//! The distance between the crisp and the defuzzified surface (docs/method.md §8):
//! closed forms (constant offset, a bilinear and a biquadratic difference,
//! whose squares integrate exactly) and bounds from brute-force fine grids.

use proptest::prelude::*;
use t2spline::sampling::Params;
use t2spline::{strategies, Alpha, FuzzySurface, Nt2Number, Nt2Point, NurbsSurface};

/// A number whose defuzzified value at alpha = 0 is `c + δ`: spreads `3|δ|` on
/// one side (docs/method.md §3–§4 with h = 1: the reduced side is `c ± 3|δ|`, the
/// centroid `c ± |δ|`).
fn offset(c: f64, delta: f64) -> Nt2Number {
    let s = 3.0 * delta.abs();
    if delta >= 0.0 {
        Nt2Number::try_new(c, [c, c + s], [c, c + s], [c, c + s], 1.0).unwrap()
    } else {
        Nt2Number::try_new(c, [c - s, c], [c - s, c], [c - s, c], 1.0).unwrap()
    }
}

/// A fuzzy surface on `points` (crisp values) whose defuzzified control points
/// at alpha = 0 are moved by `offsets`.
fn surface(
    degree: [usize; 2],
    points: &[Vec<[f64; 3]>],
    offsets: &[Vec<[f64; 3]>],
    weights: Vec<Vec<f64>>,
    knots: [Option<Vec<f64>>; 2],
) -> FuzzySurface<3> {
    let net = points
        .iter()
        .zip(offsets)
        .map(|(row, o)| {
            row.iter()
                .zip(o)
                .map(|(p, d)| Nt2Point::new(std::array::from_fn(|k| offset(p[k], d[k]))))
                .collect()
        })
        .collect();
    FuzzySurface::try_new(degree, net, weights, knots).unwrap()
}

fn alpha0() -> Alpha {
    Alpha::try_new(0.0).unwrap()
}

/// A wavy crisp net of `nu × nv` points.
fn net(nu: usize, nv: usize) -> Vec<Vec<[f64; 3]>> {
    (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| [i as f64, j as f64, ((i * 7 + j * 3) % 5) as f64 * 0.3])
                .collect()
        })
        .collect()
}

#[test]
fn constant_offset_gives_equal_max_and_rms() {
    // Rational weights and uneven knots: every defuzzified point is the crisp
    // one moved by (0.3, −0.4, 1.2), so d = 1.3 everywhere.
    let offsets = vec![vec![[0.3, -0.4, 1.2]; 5]; 6];
    let weights = (0..6)
        .map(|i| (0..5).map(|j| 0.3 + ((i + 2 * j) % 4) as f64).collect())
        .collect();
    let ku = vec![0.0, 0.0, 0.0, 0.0, 0.2, 0.7, 1.0, 1.0, 1.0, 1.0];
    let kv = vec![-2.0, -2.0, -2.0, 0.0, 0.0, 3.0, 3.0, 3.0];
    let s = surface([3, 2], &net(6, 5), &offsets, weights, [Some(ku), Some(kv)]);
    let d = s.solve(alpha0()).distance();
    assert!(
        (d.max - 1.3).abs() < 1e-14 && (d.rms - 1.3).abs() < 1e-14,
        "{d:?}"
    );
}

#[test]
fn bilinear_difference_has_the_closed_form() {
    // Offsets 0, 1, 2, −1 in x at the corners: d = |2u + v − 4uv| on [0, 1]²,
    // max 2 at (1, 0); ∫∫ d² = 4/9, so rms = 2/3.
    let x = |v: f64| [v, 0.0, 0.0];
    let offsets = vec![vec![x(0.0), x(1.0)], vec![x(2.0), x(-1.0)]];
    let s = surface(
        [1, 1],
        &net(2, 2),
        &offsets,
        vec![vec![1.0; 2]; 2],
        [None, None],
    );
    let d = s.solve(alpha0()).distance();
    assert_eq!(d.max_at, [1.0, 0.0]);
    assert!((d.max - 2.0).abs() < 1e-15, "{d:?}");
    assert!((d.rms - 2.0 / 3.0).abs() < 1e-15, "{d:?}");
}

#[test]
fn biquadratic_bump_has_its_maximum_inside() {
    // Only the middle control point moves, by 1 in z: d = 4u(1 − u)·v(1 − v)
    // (Bernstein), max 1/4 at (1/2, 1/2) between scan points of a shifted
    // domain; ∫∫ d² = 16·(1/30)², rms = 2/15.
    let mut offsets = vec![vec![[0.0; 3]; 3]; 3];
    offsets[1][1] = [0.0, 0.0, 1.0];
    let knots = [Some(vec![0.1, 0.1, 0.1, 1.4, 1.4, 1.4]), None];
    let s = surface([2, 2], &net(3, 3), &offsets, vec![vec![1.0; 3]; 3], knots);
    let d = s.solve(alpha0()).distance();
    assert!((d.max - 0.25).abs() < 1e-15, "{d:?}");
    assert!(
        (d.max_at[0] - 0.75).abs() < 1e-7 && (d.max_at[1] - 0.5).abs() < 1e-7,
        "{d:?}"
    );
    assert!((d.rms - 2.0 / 15.0).abs() < 1e-15, "{d:?}");
}

/// `‖D − C‖` on a uniform grid of `n × n` parameters, by the grid engine.
fn grid_distances(c: &NurbsSurface<3>, d: &NurbsSurface<3>, n: usize) -> Vec<f64> {
    let (gc, gd) = (
        c.sample_grid(Params::Uniform(n), Params::Uniform(n))
            .unwrap(),
        d.sample_grid(Params::Uniform(n), Params::Uniform(n))
            .unwrap(),
    );
    gc.samples()
        .points()
        .zip(gd.samples().points())
        .map(|(p, q)| {
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        })
        .collect()
}

#[test]
fn rational_surface_maximum_is_exact_to_1e_10_and_rms_matches_a_fine_grid() {
    // The benchmark net and weights (bicubic, 8 × 8, weights 0.5 … 2) with
    // offsets that vary from point to point.
    let b = t2spline::sampling::benchmark_surface();
    let crisp: Vec<Vec<[f64; 3]>> = (0..8)
        .map(|i| (0..8).map(|j| b.points()[i * 8 + j].crisp()).collect())
        .collect();
    let offsets: Vec<Vec<[f64; 3]>> = (0..8)
        .map(|i| {
            (0..8)
                .map(|j| {
                    let (x, y) = (i as f64, j as f64);
                    [
                        0.1 * (x + y).sin(),
                        0.05 * (2.0 * x - y).cos(),
                        0.2 * (x * y * 0.37).sin(),
                    ]
                })
                .collect()
        })
        .collect();
    let weights = (0..8)
        .map(|i| b.weights()[i * 8..(i + 1) * 8].to_vec())
        .collect();
    let s = surface([3, 3], &crisp, &offsets, weights, [None, None]);
    // Differences of two evaluations round at the size of the coordinates.
    let noise = 1e-14 * 10.0;
    for a in [0.0] {
        let solution = s.solve(Alpha::try_new(a).unwrap());
        let (c, d) = (solution.crisp_surface(), solution.defuzzified_surface());
        let dist = solution.distance();
        // A fine grid never beats the maximum, and gets close to it.
        let n = 1201;
        let values = grid_distances(&c, &d, n);
        let brute = values.iter().fold(0.0, |m: f64, &x| m.max(x));
        assert!(
            brute <= dist.max + noise,
            "alpha {a}: grid {brute} > {dist:?}"
        );
        assert!(
            dist.max - brute < 1e-5 * dist.max,
            "alpha {a}: grid {brute} vs {dist:?}"
        );
        // Around max_at, a much finer local grid agrees to 1e-10 relative.
        let [u0, v0] = dist.max_at;
        let h = 1e-4;
        let mut local: f64 = 0.0;
        for i in 0..=200 {
            for j in 0..=200 {
                let u = (u0 - h + 2.0 * h * i as f64 / 200.0).clamp(0.0, 1.0);
                let v = (v0 - h + 2.0 * h * j as f64 / 200.0).clamp(0.0, 1.0);
                let (p, q) = (c.eval(u, v).unwrap(), d.eval(u, v).unwrap());
                local = local.max(
                    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt(),
                );
            }
        }
        assert!(
            local <= dist.max + noise && dist.max - local < 1e-10 * dist.max,
            "alpha {a}: {local} vs {dist:?}"
        );
        // The trapezoidal rule on grids of 600 and 1200 intervals (the knots
        // lie on both), extrapolated (Richardson): error O(h⁴).
        let trapezoid = |values: &[f64], n: usize| {
            let w = |k: usize| if k == 0 || k == n - 1 { 0.5 } else { 1.0 };
            let mut sum = 0.0;
            for i in 0..n {
                for j in 0..n {
                    sum += w(i) * w(j) * values[i * n + j].powi(2);
                }
            }
            sum / ((n - 1) * (n - 1)) as f64
        };
        let coarse = trapezoid(&grid_distances(&c, &d, 601), 601);
        let fine = trapezoid(&values, n);
        let rms = (fine + (fine - coarse) / 3.0).sqrt();
        assert!(
            (rms - dist.rms).abs() < 1e-9 * dist.rms,
            "alpha {a}: {rms} vs {dist:?}"
        );
    }
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(4, 8))]

    #[test]
    fn no_fine_grid_point_beats_the_maximum(s in strategies::fuzzy_surface::<3>(), a in 0.0..=1.0f64) {
        let solution = s.solve(Alpha::try_new(a).unwrap());
        let dist = solution.distance();
        let values = grid_distances(&solution.crisp_surface(), &solution.defuzzified_surface(), 301);
        let brute = values.iter().fold(0.0, |m: f64, &x| m.max(x));
        let size = s.points().iter().flat_map(|p| p.crisp()).fold(1.0, |m: f64, x| m.max(x.abs()));
        prop_assert!(brute <= dist.max + 1e-13 * size, "grid {} > {:?}", brute, dist);
        prop_assert!(dist.rms <= dist.max * (1.0 + 1e-12), "{:?}", dist);
    }
}
