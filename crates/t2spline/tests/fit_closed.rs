//! Closed fits (`FitOptions::closed`): periodic knots on the loop
//! parameters, the last `p` control points repeating the first `p`.
//!
//! Closed forms: a periodic spline on the fit's own knots is recovered from
//! its samples (interpolation and least squares). Properties, each checked
//! against an independent computation: the interpolant passes through every
//! crisp and layer value (evaluated as plain B-splines from the control
//! values); the seam is `C^{p−1}` (derivatives 0 … p − 1 at both ends of the
//! domain); least-squares residuals are orthogonal to the folded basis
//! (built here densely from the curve's own basis functions); on nested
//! knot vectors the residual does not grow; the fitted curve is closed with
//! its wrapped points merged, as the measures need.

use t2spline::fit::{
    fit_curve, fit_fuzzy, periodic_knots, FitOptions, FuzzyData, FuzzyFitMode, Parametrization,
};
use t2spline::{Error, KnotVector, Layer, Nt2Number, Nt2Point, NurbsCurve};

/// `|a − b| ≤ tol·max(1, |a|, |b|)`.
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * 1f64.max(a.abs()).max(b.abs())
}

/// A star-shaped loop of `n` points, uneven in angle and radius.
fn star(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let k = k as f64;
            let a = std::f64::consts::TAU * (k + 0.3 * (1.7 * k).sin()) / n as f64;
            let r = 5.0 + 1.5 * (2.3 * k).cos();
            [r * a.cos(), r * a.sin() + 0.5]
        })
        .collect()
}

/// The curve of control values `control` (all `n + p`) on `knots`.
fn curve(control: &[[f64; 2]], knots: &KnotVector) -> NurbsCurve<2> {
    NurbsCurve::try_new(control.to_vec(), vec![1.0; control.len()], knots.clone()).unwrap()
}

/// Fuzzy data around `star(n)`: spreads that differ per point and layer.
fn fuzzy_star(n: usize) -> Vec<Nt2Point<2>> {
    star(n)
        .iter()
        .enumerate()
        .map(|(k, q)| {
            let s = 0.1 + 0.05 * ((k * 7) % 5) as f64;
            let num = |c: f64, w: f64| {
                Nt2Number::try_new(
                    c,
                    [c - 3.0 * w, c + 2.5 * w],
                    [c - 2.0 * w, c + 1.5 * w],
                    [c - w, c + 0.5 * w],
                    0.6,
                )
                .unwrap()
            };
            Nt2Point::new([num(q[0], s), num(q[1], 1.3 * s)])
        })
        .collect()
}

#[test]
fn interpolation_passes_through_every_crisp_and_layer_value() {
    let data = fuzzy_star(11);
    for p in 1..=5 {
        for method in Parametrization::ALL {
            let options = FitOptions::interpolation(p)
                .unwrap()
                .with_parametrization(method)
                .closed();
            // Independent: every layer interpolates its own data.
            let fit = fit_fuzzy(&data, &options, FuzzyFitMode::Independent).unwrap();
            assert_eq!(fit.knots().count(), 11 + p);
            for layer in Layer::ALL {
                let c = curve(fit.layer_control_points(layer), fit.knots());
                for (k, (&t, q)) in fit.params().iter().zip(&data).enumerate() {
                    let (got, want) = (c.eval(t).unwrap(), q.layer(layer));
                    for d in 0..2 {
                        assert!(
                            close(got[d], want[d], 1e-10),
                            "p {p}, {method}, {layer:?}, point {k}: {got:?} vs {want:?}"
                        );
                    }
                }
            }
            // Valid: the crisp layer is the same interpolant, and the curve
            // is a valid fuzzy curve.
            let valid = fit_fuzzy(&data, &options, FuzzyFitMode::Valid).unwrap();
            assert_eq!(
                valid.layer_control_points(Layer::Crisp),
                fit.layer_control_points(Layer::Crisp)
            );
            assert!(valid.violations().is_empty());
            assert!(valid.to_curve().is_ok());
        }
    }
}

#[test]
fn the_seam_is_c_p_minus_1_and_the_curve_closes_with_its_points_merged() {
    let q = star(9);
    let size = 13.0; // about the extent of the star
    for p in 1..=5 {
        for control_points in [None, Some(p + 1), Some(7)] {
            if control_points.is_some_and(|n| n > 9) {
                continue;
            }
            let options = FitOptions::new(p, control_points).unwrap().closed();
            let fit = fit_curve(&q, &options).unwrap();
            let c = &fit.curve;
            let n = c.control_points().len() - p;
            assert_eq!(&c.control_points()[n..], &c.control_points()[..p]);
            let (a, b) = (c.domain().start, c.domain().end);
            assert_eq!((a, b), (0.0, 1.0));
            let (start, end) = (c.derivatives(a, p).unwrap(), c.derivatives(b, p).unwrap());
            for k in 0..p {
                // The k-th derivative scales as size·n^k.
                let scale = size * (n as f64).powi(k as i32);
                for d in 0..2 {
                    assert!(
                        (start[k][d] - end[k][d]).abs() <= 1e-10 * scale,
                        "p {p}, n {n}, derivative {k}: {:?} vs {:?}",
                        start[k],
                        end[k]
                    );
                }
            }
            // The fuzzy curve of the same fit closes, its wrapped points one.
            let data: Vec<Nt2Point<2>> = q
                .iter()
                .map(|x| {
                    Nt2Point::new(x.map(|v| {
                        Nt2Number::try_new(
                            v,
                            [v - 0.2, v + 0.2],
                            [v - 0.1, v + 0.1],
                            [v - 0.05, v + 0.05],
                            0.5,
                        )
                        .unwrap()
                    }))
                })
                .collect();
            let fuzzy = fit_fuzzy(&data, &options, FuzzyFitMode::Valid)
                .unwrap()
                .to_curve()
                .unwrap();
            let closure = fuzzy.closure().expect("a closed fit closes");
            assert_eq!((closure.wrap, closure.merged), (p, true), "p {p}, n {n}");
        }
    }
}

/// Samples of a known periodic spline of `n` control values on the knots a
/// closed fit of `big_n` uniform parameters gives, at those parameters.
fn known_spline(p: usize, n: usize, big_n: usize) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let params: Vec<f64> = (0..big_n).map(|k| k as f64 / big_n as f64).collect();
    let knots = periodic_knots(&params, p, n).unwrap();
    let distinct: Vec<[f64; 2]> = (0..n)
        .map(|j| {
            let a = std::f64::consts::TAU * j as f64 / n as f64;
            let r = 3.0 + (j % 3) as f64;
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    let control: Vec<[f64; 2]> = (0..n + p).map(|i| distinct[i % n]).collect();
    let c = curve(&control, &knots);
    let samples = params.iter().map(|&t| c.eval(t).unwrap()).collect();
    (control, samples)
}

#[test]
fn a_periodic_spline_is_recovered_from_its_samples() {
    for p in 1..=5 {
        for (n, big_n) in [
            (p + 1, p + 1),
            (8, 8),
            (13, 13),
            (p + 1, 20),
            (8, 20),
            (13, 40),
        ] {
            let (control, samples) = known_spline(p, n, big_n);
            let options = FitOptions::new(p, (n < big_n).then_some(n))
                .unwrap()
                .with_parametrization(Parametrization::Uniform)
                .closed();
            let fit = fit_curve(&samples, &options).unwrap();
            for (i, (got, want)) in fit.curve.control_points().iter().zip(&control).enumerate() {
                for d in 0..2 {
                    assert!(
                        (got[d] - want[d]).abs() < 1e-9,
                        "p {p}, n {n}, N {big_n}, control point {i}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_last_point_repeating_the_first_is_the_same_point() {
    let q = star(10);
    let mut again = q.clone();
    again.push([q[0][0] + 1e-12, q[0][1]]);
    let options = FitOptions::interpolation(3).unwrap().closed();
    let (a, b) = (
        fit_curve(&q, &options).unwrap(),
        fit_curve(&again, &options).unwrap(),
    );
    assert_eq!(a.params, b.params);
    assert_eq!(a.curve, b.curve);
    // Not a repeat: one more point on the loop.
    again.push([q[0][0] + 0.5, q[0][1]]);
    assert_eq!(fit_curve(&again, &options).unwrap().params.len(), 12);
}

/// The dense folded basis `A[k][j] = Σ_{i ≡ j (mod n)} N_i(ū_k)`, from the
/// curve's own rational basis (weights 1: the B-spline basis).
fn folded_basis(c: &NurbsCurve<2>, params: &[f64], p: usize) -> Vec<Vec<f64>> {
    let n = c.control_points().len() - p;
    params
        .iter()
        .map(|&t| {
            let r = c.rational_basis(t).unwrap();
            let mut row = vec![0.0; n];
            for (i, v) in r.iter().enumerate() {
                row[i % n] += v;
            }
            row
        })
        .collect()
}

fn residual(c: &NurbsCurve<2>, params: &[f64], q: &[[f64; 2]]) -> Vec<[f64; 2]> {
    params
        .iter()
        .zip(q)
        .map(|(&t, q)| {
            let v = c.eval(t).unwrap();
            [q[0] - v[0], q[1] - v[1]]
        })
        .collect()
}

#[test]
fn least_squares_residuals_are_orthogonal_to_the_folded_basis() {
    let q = star(30);
    for p in 1..=4 {
        for n in [p + 1, 7, 12, 29] {
            let options = FitOptions::approximation(p, n).unwrap().closed();
            let fit = fit_curve(&q, &options).unwrap();
            let a = folded_basis(&fit.curve, &fit.params, p);
            let r = residual(&fit.curve, &fit.params, &q);
            for j in 0..n {
                for d in 0..2 {
                    let g: f64 = a.iter().zip(&r).map(|(row, r)| row[j] * r[d]).sum();
                    assert!(g.abs() < 1e-10, "p {p}, n {n}, column {j}: {g}");
                }
            }
        }
    }
}

#[test]
fn on_nested_knots_the_residual_does_not_grow() {
    // Uniform parameters and odd degree give the uniform knots j/n, so the
    // spline spaces of n = 4, 8, 16, 32 are nested and least squares in the
    // larger one can only do better: a noisy circle of 64 points.
    let q: Vec<[f64; 2]> = (0..64)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 64.0;
            let r = 4.0 + 0.3 * (5.0 * a).sin() + 0.05 * ((k * 37 % 11) as f64 - 5.0) / 5.0;
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    for p in [1, 3, 5] {
        let mut previous = f64::INFINITY;
        for n in [8, 16, 32, 64] {
            let options = FitOptions::approximation(p, n)
                .unwrap()
                .with_parametrization(Parametrization::Uniform)
                .closed();
            let fit = fit_curve(&q, &options).unwrap();
            let knots = fit.curve.knots().as_slice();
            for j in 0..=n {
                assert!((knots[p + j] - j as f64 / n as f64).abs() < 1e-15);
            }
            let sum: f64 = residual(&fit.curve, &fit.params, &q)
                .iter()
                .map(|r| r[0] * r[0] + r[1] * r[1])
                .sum();
            assert!(
                sum <= previous * (1.0 + 1e-12),
                "p {p}, n {n}: {sum} > {previous}"
            );
            previous = sum;
        }
        // 64 control points interpolate.
        assert!(previous < 1e-20, "p {p}: {previous}");
    }
}

#[test]
fn bad_closed_fits_name_the_rule() {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let closed = |p| FitOptions::interpolation(p).unwrap().closed();
    // Degree 0 is refused when the options are made.
    assert!(matches!(
        FitOptions::interpolation(0),
        Err(Error::Setting {
            setting: t2spline::job::Setting::Degree,
            ..
        })
    ));
    assert_eq!(
        fit_curve(&square, &closed(4)).unwrap_err(),
        Error::TooFewClosedDataPoints {
            degree: 4,
            count: 4,
            repeated: false
        }
    );
    assert_eq!(
        fit_curve(&square, &FitOptions::approximation(2, 5).unwrap().closed()).unwrap_err(),
        Error::ControlPointCount {
            count: 5,
            min: 3,
            max: 4
        }
    );
    let net = vec![vec![Nt2Point::new([Nt2Number::try_crisp(0.0).unwrap(); 3]); 3]; 3];
    assert_eq!(
        FuzzyData::Net(net)
            .fit(&closed(2), FuzzyFitMode::Valid)
            .unwrap_err(),
        Error::ClosedSurfaceFit
    );
}
