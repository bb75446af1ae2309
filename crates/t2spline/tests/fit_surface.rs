//! Fitting surfaces to nets (The NURBS Book §9.2.5 A9.4, §9.4.3 A9.7):
//! closed forms and properties.
//!
//! Closed forms: a polynomial surface of degrees up to the fit's, sampled at
//! uniform parameters, is recovered by interpolation and by least squares;
//! a tensor-product spline is recovered from its samples on its own knots.
//! Properties: interpolants pass through the whole net; least squares with as
//! many control points as data is interpolation; the valid fuzzy fit always
//! gives a valid fuzzy surface and equals the independent fit when that is
//! valid; independent interpolation passes through every layer.

use proptest::prelude::*;
use t2spline::fit::{
    averaging_knots, fit_fuzzy_surface, fit_surface, FuzzyFitMode, Parametrization,
    SurfaceFitOptions,
};
use t2spline::{Direction, Error, Layer, Nt2Number, Nt2Point, NurbsSurface};

/// `|a − b| ≤ tol·max(1, |a|, |b|)`.
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * 1f64.max(a.abs()).max(b.abs())
}

fn uniform(m: usize) -> Vec<f64> {
    (0..=m).map(|k| k as f64 / m as f64).collect()
}

/// The net `f(u_k, v_l)` at uniform parameters.
fn sampled(rows: usize, columns: usize, f: impl Fn(f64, f64) -> [f64; 3]) -> Vec<Vec<[f64; 3]>> {
    let (u, v) = (uniform(rows - 1), uniform(columns - 1));
    u.iter()
        .map(|&uk| v.iter().map(|&vl| f(uk, vl)).collect())
        .collect()
}

/// A polynomial patch of degree 2 in u and 3 in v.
fn patch(u: f64, v: f64) -> [f64; 3] {
    [
        2.0 * u + 0.3 * v,
        v - 0.2 * u * u,
        1.0 - u + 2.0 * u * u * v - 3.0 * v * v * v + u * v,
    ]
}

#[test]
fn interpolation_and_least_squares_recover_a_polynomial_patch() {
    let net = sampled(7, 9, patch);
    let uniform_params = |o: SurfaceFitOptions| o.with_parametrization(Parametrization::Uniform);
    for options in [
        uniform_params(SurfaceFitOptions::interpolation([2, 3]).unwrap()),
        uniform_params(SurfaceFitOptions::interpolation([3, 4]).unwrap()),
        uniform_params(SurfaceFitOptions::approximation([2, 3], [4, 5]).unwrap()),
        uniform_params(SurfaceFitOptions::approximation([3, 3], [5, 6]).unwrap()),
    ] {
        let fit = fit_surface(&net, &options).unwrap();
        // The polynomial lies in the spline space: reproduced everywhere.
        for s in 0..=10 {
            for t in 0..=10 {
                let (u, v) = (f64::from(s) / 10.0, f64::from(t) / 10.0);
                let got = fit.surface.eval(u, v).unwrap();
                let want = patch(u, v);
                for d in 0..3 {
                    assert!(
                        close(got[d], want[d], 1e-11),
                        "{options:?} at ({u}, {v}): {got:?} != {want:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn interpolation_recovers_a_spline_on_the_averaging_knots() {
    let (pu, pv) = (uniform(5), uniform(4));
    let knots = [
        averaging_knots(&pu, 3).unwrap(),
        averaging_knots(&pv, 2).unwrap(),
    ];
    let control: Vec<Vec<[f64; 3]>> = (0..6)
        .map(|i| {
            (0..5)
                .map(|j| {
                    let (x, y) = (i as f64, j as f64);
                    [x, y, (x * 1.7 + y * y * 0.3).sin()]
                })
                .collect()
        })
        .collect();
    let truth =
        NurbsSurface::try_new(control.clone(), vec![vec![1.0; 5]; 6], knots.clone()).unwrap();
    let net: Vec<Vec<[f64; 3]>> = pu
        .iter()
        .map(|&u| pv.iter().map(|&v| truth.eval(u, v).unwrap()).collect())
        .collect();
    let options = SurfaceFitOptions::interpolation([3, 2])
        .unwrap()
        .with_parametrization(Parametrization::Uniform);
    let fit = fit_surface(&net, &options).unwrap();
    assert_eq!(fit.surface.knots(Direction::U), &knots[0]);
    assert_eq!(fit.surface.knots(Direction::V), &knots[1]);
    for (got, want) in fit.surface.control_points().iter().zip(control.concat()) {
        for d in 0..3 {
            assert!(close(got[d], want[d], 1e-12), "{got:?} != {want:?}");
        }
    }
}

#[test]
fn bad_nets_are_clear_errors() {
    let net = sampled(3, 4, patch);
    let e = fit_surface(&net, &SurfaceFitOptions::interpolation([3, 2]).unwrap()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "in u: points: a curve of degree 3 needs at least 4 data points, got 3"
    );
    let e = fit_surface(
        &net,
        &SurfaceFitOptions::approximation([2, 2], [3, 5]).unwrap(),
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InDirection {
                direction: Direction::V,
                ..
            }
        ),
        "{e}"
    );
    let mut ragged = net.clone();
    ragged[1].pop();
    assert!(matches!(
        fit_surface(&ragged, &SurfaceFitOptions::interpolation([1, 1]).unwrap()),
        Err(Error::NetShape { row: 1, .. })
    ));
    let mut repeated = net.clone();
    repeated[2] = repeated[1].clone();
    let e = fit_surface(
        &repeated,
        &SurfaceFitOptions::interpolation([1, 1]).unwrap(),
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InDirection {
                direction: Direction::U,
                ..
            }
        ),
        "{e}"
    );
    let mut nan = net;
    nan[2][1][2] = f64::NAN;
    assert!(matches!(
        fit_surface(&nan, &SurfaceFitOptions::interpolation([1, 1]).unwrap()),
        Err(Error::NotFinite { .. })
    ));
}

/// A fuzzy number around `c` with left spreads `l` and right spreads `r`
/// (inner to outer: lower, primary, upper), height 0.5.
fn number(c: f64, l: [f64; 3], r: [f64; 3]) -> Nt2Number {
    Nt2Number::try_new(
        c,
        [c - l[2], c + r[2]],
        [c - l[1], c + r[1]],
        [c - l[0], c + r[0]],
        0.5,
    )
    .unwrap()
}

/// A fuzzy net around `crisp` whose z spreads are `spread(k, l)` (x and y crisp).
fn fuzzy_net(
    crisp: &[Vec<[f64; 3]>],
    spread: impl Fn(usize, usize) -> ([f64; 3], [f64; 3]),
) -> Vec<Vec<Nt2Point<3>>> {
    crisp
        .iter()
        .enumerate()
        .map(|(k, row)| {
            row.iter()
                .enumerate()
                .map(|(l, p)| {
                    let (left, right) = spread(k, l);
                    Nt2Point::new([
                        number(p[0], [0.0; 3], [0.0; 3]),
                        number(p[1], [0.0; 3], [0.0; 3]),
                        number(p[2], left, right),
                    ])
                })
                .collect()
        })
        .collect()
}

#[test]
fn constant_spreads_are_fitted_exactly_by_the_valid_fit() {
    let crisp = sampled(6, 5, patch);
    let net = fuzzy_net(&crisp, |_, _| ([0.1, 0.2, 0.4], [0.05, 0.3, 0.35]));
    for options in [
        SurfaceFitOptions::interpolation([3, 2]).unwrap(),
        SurfaceFitOptions::approximation([2, 2], [4, 4]).unwrap(),
    ] {
        let fit = fit_fuzzy_surface(&net, &options, FuzzyFitMode::Valid).unwrap();
        assert!(fit.violations().is_empty());
        for layer in Layer::ALL {
            assert!(
                fit.spread_deviations()[layer].max < 1e-12,
                "{layer:?}: {:?}",
                fit.spread_deviations()[layer]
            );
        }
        let surface = fit.to_surface().unwrap();
        assert_eq!(surface.points().len(), fit.counts()[0] * fit.counts()[1]);
    }
}

#[test]
fn spreads_that_swing_are_kept_valid_by_the_valid_fit() {
    // Alternating spikes of spread: fitting each layer on its own overshoots
    // below the crisp layer between spikes.
    let crisp = sampled(9, 8, patch);
    let net = fuzzy_net(&crisp, |k, l| {
        let s = if (k + l) % 3 == 0 { 1.0 } else { 0.0 };
        ([0.0, 0.5 * s, s], [0.0, 0.0, 2.0 * s])
    });
    let options = SurfaceFitOptions::interpolation([3, 3]).unwrap();
    let independent = fit_fuzzy_surface(&net, &options, FuzzyFitMode::Independent).unwrap();
    assert!(
        !independent.violations().is_empty(),
        "the case should break the order on its own"
    );
    assert!(matches!(
        independent.to_surface(),
        Err(Error::UnorderedFit { .. })
    ));
    let valid = fit_fuzzy_surface(&net, &options, FuzzyFitMode::Valid).unwrap();
    assert!(valid.violations().is_empty());
    assert_eq!(valid.independent_violations(), independent.violations());
    valid.to_surface().unwrap();
    // The crisp layer is the interpolant in both.
    assert!(valid.deviations()[Layer::Crisp].max < 1e-12);
}

/// A random net: a bumpy graph over a jittered grid, with random spreads.
fn random_net() -> impl Strategy<Value = (Vec<Vec<Nt2Point<3>>>, [usize; 2])> {
    (2usize..7, 2usize..7, 1usize..4, 1usize..4).prop_flat_map(|(extra_u, extra_v, p, q)| {
        let (rows, columns) = (p + extra_u, q + extra_v);
        (
            proptest::collection::vec(
                (
                    -0.3f64..0.3,
                    -0.3f64..0.3,
                    -2.0f64..2.0,
                    0.0f64..0.5,
                    0.0f64..0.5,
                    0.0f64..1.0,
                ),
                rows * columns,
            ),
            Just((rows, columns, p, q)),
        )
            .prop_map(|(values, (rows, columns, p, q))| {
                let net = (0..rows)
                    .map(|k| {
                        (0..columns)
                            .map(|l| {
                                let (jx, jy, z, a, b, c) = values[k * columns + l];
                                Nt2Point::new([
                                    number(k as f64 + jx, [0.0; 3], [0.0; 3]),
                                    number(
                                        l as f64 + jy,
                                        [a * 0.1, a * 0.2, a * 0.3],
                                        [b * 0.1, b * 0.2, b * 0.3],
                                    ),
                                    number(z, [a, a + b, a + b + c], [c, c + b, c + b + 2.0 * a]),
                                ])
                            })
                            .collect()
                    })
                    .collect();
                (net, [p, q])
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn interpolants_pass_through_the_net_and_valid_fits_are_valid(
        (net, degree) in random_net(),
        method in prop_oneof![Just(Parametrization::ChordLength), Just(Parametrization::Centripetal), Just(Parametrization::Uniform)],
    ) {
        let options = SurfaceFitOptions::interpolation(degree).unwrap().with_parametrization(method);
        let crisp: Vec<Vec<[f64; 3]>> = net.iter().map(|r| r.iter().map(|p| p.layer(Layer::Crisp)).collect()).collect();
        let fit = match fit_surface(&crisp, &options) {
            Ok(f) => f,
            // An ill-conditioned draw is refused, not mis-fitted.
            Err(Error::IllConditionedFit { .. }) => return Ok(()),
            Err(e) => panic!("{e}"),
        };
        let [u, v] = &fit.params;
        for (k, row) in crisp.iter().enumerate() {
            for (l, q) in row.iter().enumerate() {
                let s = fit.surface.eval(u[k], v[l]).unwrap();
                for d in 0..3 {
                    prop_assert!(close(s[d], q[d], 1e-9), "({k}, {l}): {s:?} != {q:?}");
                }
            }
        }
        let independent = fit_fuzzy_surface(&net, &options, FuzzyFitMode::Independent).unwrap();
        for layer in Layer::ALL {
            prop_assert!(independent.deviations()[layer].max <= 1e-9 * 3.0, "{layer:?}: {:?}", independent.deviations()[layer]);
        }
        let valid = fit_fuzzy_surface(&net, &options, FuzzyFitMode::Valid).unwrap();
        prop_assert!(valid.violations().is_empty());
        prop_assert!(valid.to_surface().is_ok());
        if independent.violations().is_empty() {
            for layer in Layer::ALL {
                for (a, b) in valid.layer_control_points(layer).iter().zip(independent.layer_control_points(layer)) {
                    for d in 0..3 {
                        prop_assert!(close(a[d], b[d], 1e-9), "{layer:?}: {a:?} != {b:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn least_squares_with_as_many_control_points_as_data_is_interpolation(
        (net, degree) in random_net(),
    ) {
        let crisp: Vec<Vec<[f64; 3]>> = net.iter().map(|r| r.iter().map(|p| p.layer(Layer::Crisp)).collect()).collect();
        let shape = [crisp.len(), crisp[0].len()];
        let a = fit_surface(&crisp, &SurfaceFitOptions::interpolation(degree).unwrap());
        let b = fit_surface(&crisp, &SurfaceFitOptions::approximation(degree, shape).unwrap());
        match (a, b) {
            (Ok(a), Ok(b)) => prop_assert_eq!(a, b),
            (Err(a), Err(b)) => prop_assert_eq!(a, b),
            (a, b) => prop_assert!(false, "{a:?} / {b:?}"),
        }
    }
}
