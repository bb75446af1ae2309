//! Fitting (The NURBS Book §9.2.1, §9.4.1): closed-form cases and properties.
//!
//! Closed forms: a curve in the spline space is recovered from its samples;
//! data on a line are reproduced by chord-length interpolation of any degree.
//! Properties: interpolants pass through their data, least-squares residuals
//! are orthogonal to the interior basis, the valid fuzzy fit always gives a
//! valid fuzzy curve and equals the independent one whenever that is valid.

use proptest::prelude::*;
use t2spline::fit::{
    approximation_knots, averaging_knots, fit_curve, fit_fuzzy, CurveFit, FitOptions, FuzzyFitMode,
    Parametrization,
};
use t2spline::{strategies, Axis, Error, KnotVector, Layer, Nt2Number, Nt2Point, NurbsCurve};

/// `|a − b| ≤ tol·max(1, |a|, |b|)`.
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * 1f64.max(a.abs()).max(b.abs())
}

fn close_point<const D: usize>(a: &[f64; D], b: &[f64; D], tol: f64) -> bool {
    a.iter().zip(b).all(|(&x, &y)| close(x, y, tol))
}

/// Uniform parameters `k/m`.
fn uniform(m: usize) -> Vec<f64> {
    (0..=m).map(|k| k as f64 / m as f64).collect()
}

#[test]
fn interpolation_recovers_a_spline_on_the_averaging_knots() {
    // A cubic with 8 control points on the knots that averaging gives for
    // uniform parameters; its samples at those parameters are interpolated by
    // exactly that curve.
    let params = uniform(7);
    let knots = averaging_knots(&params, 3).unwrap();
    let control = vec![
        [0.0, 0.0],
        [1.0, 3.0],
        [2.5, -1.0],
        [4.0, 2.0],
        [5.0, 5.0],
        [7.0, 4.0],
        [8.0, 0.5],
        [9.0, 1.0],
    ];
    let truth = NurbsCurve::try_new(control.clone(), vec![1.0; 8], knots.clone()).unwrap();
    let data = truth.sample(&params).unwrap();
    let options = FitOptions::interpolation(3)
        .unwrap()
        .with_parametrization(Parametrization::Uniform);
    let fit = fit_curve(&data, &options).unwrap();
    assert_eq!(fit.curve.knots(), &knots);
    for (got, want) in fit.curve.control_points().iter().zip(&control) {
        assert!(close_point(got, want, 1e-12), "{got:?} != {want:?}");
    }
}

#[test]
fn interpolation_reproduces_a_polynomial_of_the_same_degree() {
    // P(t) = (t, 1 − 3t + 2t³ − t⁴ + t⁵) is a quintic; sampled at uniform
    // parameters it lies in every quintic spline space on [0, 1].
    let poly = |t: f64| [t, 1.0 - 3.0 * t + 2.0 * t.powi(3) - t.powi(4) + t.powi(5)];
    let params = uniform(11);
    let data: Vec<[f64; 2]> = params.iter().map(|&t| poly(t)).collect();
    let options = FitOptions::interpolation(5)
        .unwrap()
        .with_parametrization(Parametrization::Uniform);
    let fit = fit_curve(&data, &options).unwrap();
    for t in fit.curve.domain().uniform(201).unwrap() {
        let (got, want) = (fit.curve.eval(t).unwrap(), poly(t));
        assert!(
            close_point(&got, &want, 1e-12),
            "t {t}: {got:?} != {want:?}"
        );
    }
}

#[test]
fn chord_length_interpolation_of_points_on_a_line_is_the_line() {
    // Chord-length parameters of collinear points are their arc lengths over
    // the total, so the line itself (linear in u) interpolates them.
    let (a, b) = ([1.0, -2.0, 0.5], [4.0, 2.0, 12.5]); // |b − a| = 13
    let s = [0.0, 0.1, 0.15, 0.5, 0.55, 0.9, 1.0];
    let data: Vec<[f64; 3]> = s
        .iter()
        .map(|&s| std::array::from_fn(|d| a[d] + s * (b[d] - a[d])))
        .collect();
    for p in 1..=5 {
        let fit = fit_curve(&data, &FitOptions::interpolation(p).unwrap()).unwrap();
        for (u, &want) in fit.params.iter().zip(&s) {
            assert!(
                close(*u, want, 1e-15),
                "degree {p}: parameter {u} != {want}"
            );
        }
        for t in fit.curve.domain().uniform(101).unwrap() {
            let got = fit.curve.eval(t).unwrap();
            let want: [f64; 3] = std::array::from_fn(|d| a[d] + t * (b[d] - a[d]));
            assert!(
                close_point(&got, &want, 1e-12),
                "degree {p}, t {t}: {got:?}"
            );
        }
    }
}

#[test]
fn least_squares_recovers_a_spline_on_its_own_knots() {
    // Data sampled from a quadratic on the knots of Eqs. 9.68–9.69 are fitted
    // with zero residual by that very curve.
    let params = uniform(14);
    let knots = approximation_knots(&params, 2, 6).unwrap();
    let control = vec![
        [0.0, 0.0],
        [1.0, 2.0],
        [3.0, 2.5],
        [4.0, 0.0],
        [6.0, 1.0],
        [7.0, 3.0],
    ];
    let truth = NurbsCurve::try_new(control.clone(), vec![1.0; 6], knots).unwrap();
    let data = truth.sample(&params).unwrap();
    let options = FitOptions::approximation(2, 6)
        .unwrap()
        .with_parametrization(Parametrization::Uniform);
    let fit = fit_curve(&data, &options).unwrap();
    for (got, want) in fit.curve.control_points().iter().zip(&control) {
        assert!(close_point(got, want, 1e-12), "{got:?} != {want:?}");
    }
}

#[test]
fn approximation_knots_follow_eq_9_69() {
    // m + 1 = 10 parameters, n + 1 = 6 control points, p = 2: d = 10/4 = 2.5;
    // j = 1: i = 2, α = 0.5; j = 2: i = 5, α = 0; j = 3: i = 7, α = 0.5.
    let params = [0.0, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.7, 0.85, 1.0];
    let u = approximation_knots(&params, 2, 6).unwrap();
    let want = [
        0.0,
        0.0,
        0.0,
        0.5 * 0.05 + 0.5 * 0.1,
        0.3,
        0.5 * 0.6 + 0.5 * 0.7,
        1.0,
        1.0,
        1.0,
    ];
    for (got, want) in u.as_slice().iter().zip(want) {
        assert!(close(*got, want, 1e-15), "{u:?}");
    }
}

/// A fuzzy number with the given crisp value and left/right spreads
/// (lower, primary, upper).
fn number(c: f64, left: [f64; 3], right: [f64; 3], h: f64) -> Nt2Number {
    Nt2Number::try_new(
        c,
        [c - left[2], c + right[2]],
        [c - left[1], c + right[1]],
        [c - left[0], c + right[0]],
        h,
    )
    .unwrap()
}

#[test]
fn order_detection_names_the_broken_place() {
    // Only the x upper-left spread of the middle point is wide. The independent
    // cubic interpolant of the upper.left layer then swings, around the middle,
    // to control values above those of the primary.left layer.
    let spread = [0.1, 0.2, 0.3];
    let data: Vec<Nt2Point<2>> = (0..5)
        .map(|k| {
            let c = k as f64;
            let mut left = spread;
            if k == 2 {
                left[2] = 3.0;
            }
            Nt2Point::new([number(c, left, spread, 1.0), number(c, spread, spread, 1.0)])
        })
        .collect();
    let options = FitOptions::interpolation(3).unwrap();
    let independent = fit_fuzzy(&data, &options, FuzzyFitMode::Independent).unwrap();
    let found = independent.violations();
    assert!(!found.is_empty());
    assert!(
        found
            .iter()
            .all(|v| v.axis == Axis::X && v.rule == "upper.left <= primary.left"),
        "{found:?}"
    );
    assert!(found.iter().all(|v| v.control_point != 2), "{found:?}");
    let e = independent.to_curve().unwrap_err();
    assert!(matches!(e, Error::UnorderedFit { count, .. } if count == found.len()));
    assert!(
        e.to_string()
            .contains("control point 1, x: the order upper.left <= primary.left is broken"),
        "{e}"
    );
    // Every layer is still interpolated exactly: the fault is in the control
    // points, not at the data.
    for (layer, d) in independent.deviations().iter() {
        assert!(d.max < 1e-12, "{layer}: {d:?}");
    }
    // The valid fit keeps the order and says what it changed.
    let valid = fit_fuzzy(&data, &options, FuzzyFitMode::Valid).unwrap();
    assert!(valid.violations().is_empty());
    assert_eq!(valid.independent_violations(), found.as_slice());
    assert!(valid.to_curve().is_ok());
    let (layer, worst) = valid.max_spread_deviation();
    assert_eq!(layer, Layer::UpperLeft);
    assert!(worst.max > 1e-3 && worst.max < 3.0, "{worst:?}");
    assert!(valid.deviations()[Layer::Crisp].max < 1e-12);
}

#[test]
fn constant_spreads_are_fitted_exactly_by_the_valid_fit() {
    // A constant spread is in the spline space with non-negative coefficients
    // (partition of unity), so the constraint costs nothing.
    let crisp = [
        [0.0, 0.0],
        [1.0, 2.0],
        [2.0, 2.5],
        [4.0, 0.0],
        [5.0, 1.0],
        [7.0, 1.5],
    ];
    let data: Vec<Nt2Point<2>> = crisp
        .iter()
        .map(|c| Nt2Point::new(c.map(|x| number(x, [0.1, 0.4, 0.5], [0.05, 0.3, 0.9], 0.6))))
        .collect();
    for options in [
        FitOptions::interpolation(3).unwrap(),
        FitOptions::approximation(2, 4).unwrap(),
    ] {
        let fit = fit_fuzzy(&data, &options, FuzzyFitMode::Valid).unwrap();
        let crisp_error = fit.deviations()[Layer::Crisp].max;
        for (layer, d) in fit.deviations().iter() {
            // Each layer is the crisp curve moved by a constant.
            assert!(d.max <= crisp_error + 1e-12, "{options:?}, {layer}: {d:?}");
            let s = fit.spread_deviations()[layer];
            assert!(s.max < 1e-12, "{options:?}, {layer}: spread {s:?}");
        }
        assert_eq!(fit.heights().map(|h| h.get()), [0.6, 0.6]);
        assert_eq!(fit.mixed_heights(), [false, false]);
    }
}

#[test]
fn mixed_heights_take_the_smallest() {
    let data: Vec<Nt2Point<2>> = (0..4)
        .map(|k| {
            let c = k as f64;
            let h = if k == 2 { 0.3 } else { 0.8 };
            Nt2Point::new([
                number(c, [0.1; 3], [0.1; 3], h),
                number(c * c, [0.1; 3], [0.1; 3], 0.5),
            ])
        })
        .collect();
    let fit = fit_fuzzy(
        &data,
        &FitOptions::interpolation(2).unwrap(),
        FuzzyFitMode::Valid,
    )
    .unwrap();
    assert_eq!(fit.heights().map(|h| h.get()), [0.3, 0.5]);
    assert_eq!(fit.mixed_heights(), [true, false]);
}

#[test]
fn bad_data_are_clear_errors() {
    let q = [[0.0, 0.0], [1.0, 1.0], [2.0, f64::NAN]];
    let e = fit_curve(&q, &FitOptions::interpolation(1).unwrap()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "points[2].y: coordinate = NaN is not a finite number"
    );
    let q = [[0.0, 0.0], [0.0, 0.0], [2.0, 1.0]];
    for p in [Parametrization::ChordLength, Parametrization::Centripetal] {
        let e = fit_curve(
            &q,
            &FitOptions::interpolation(1)
                .unwrap()
                .with_parametrization(p),
        )
        .unwrap_err();
        assert!(e
            .to_string()
            .starts_with("points[0] and points[1]: consecutive data points"));
    }
    let q = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
    // Fewer control points than degree + 1: refused when the options are
    // made; more than the data: by the fit.
    let e = FitOptions::approximation(2, 2).unwrap_err();
    assert_eq!(e.setting(), Some(t2spline::job::Setting::ControlPoints));
    assert_eq!(
        e.to_string(),
        "2 is fewer than degree + 1 (the degree is 2)"
    );
    assert!(matches!(
        fit_curve(&q, &FitOptions::approximation(2, 4).unwrap()),
        Err(Error::ControlPointCount {
            count: 4,
            min: 3,
            max: 3
        })
    ));
}

/// Cases per property (200, 400 under `T2SPLINE_LONG_TESTS=1`); each fits a
/// few systems of up to 40 unknowns.
fn cases() -> ProptestConfig {
    t2spline::strategies::cases(200, 400)
}

fn options_strategy(points: usize) -> impl Strategy<Value = FitOptions> {
    let max_degree = (points - 1).min(5);
    (
        1..=max_degree,
        prop::sample::select(Parametrization::ALL.to_vec()),
        any::<bool>(),
        0.0..1.0f64,
    )
        .prop_map(move |(degree, parametrization, approximate, s)| {
            let control_points = approximate.then(|| {
                let (lo, hi) = (degree + 1, points);
                lo + ((hi - lo) as f64 * s).round() as usize
            });
            FitOptions::new(degree, control_points)
                .unwrap()
                .with_parametrization(parametrization)
        })
}

/// Data and matching options.
fn data_and_options<const D: usize>() -> impl Strategy<Value = (Vec<[f64; D]>, FitOptions)> {
    strategies::data_points::<D>(2..=40).prop_flat_map(|q| {
        let n = q.len();
        (Just(q), options_strategy(n))
    })
}

fn fuzzy_data_and_options<const D: usize>() -> impl Strategy<Value = (Vec<Nt2Point<D>>, FitOptions)>
{
    strategies::fuzzy_data::<D>(2..=25).prop_flat_map(|q| {
        let n = q.len();
        (Just(q), options_strategy(n))
    })
}

/// The largest coordinate of the data, for relative tolerances.
fn scale<const D: usize>(q: &[[f64; D]]) -> f64 {
    q.iter().flatten().fold(1.0, |m: f64, x| m.max(x.abs()))
}

/// The fit, or `None` (the case is skipped) if its system is refused as
/// ill-conditioned, which happens on random data only with nearly as many
/// control points as data points; any other error fails the test.
fn fit_or_skip<const D: usize>(q: &[[f64; D]], options: &FitOptions) -> Option<CurveFit<D>> {
    match fit_curve(q, options) {
        Ok(fit) => Some(fit),
        Err(Error::IllConditionedFit { .. }) if options.control_points().is_some() => None,
        Err(e) => panic!("{options:?}: {e}"),
    }
}

proptest! {
    #![proptest_config(cases())]

    #[test]
    fn fits_pass_through_their_data_or_their_end_points(
        (q, options) in data_and_options::<2>()
    ) {
        let Some(fit) = fit_or_skip(&q, &options) else { return Ok(()) };
        // A backward-stable solve leaves a residual of a few ulps of the
        // products |N|·|P|, so the tolerance follows the control points.
        let tol = 1e-13 * scale(&q).max(scale(fit.curve.control_points()));
        let m = q.len() - 1;
        prop_assert_eq!(fit.params[0], 0.0);
        prop_assert_eq!(fit.params[m], 1.0);
        let knots: &KnotVector = fit.curve.knots();
        prop_assert_eq!(knots.count(), options.control_points().unwrap_or(q.len()));
        let at = fit.curve.sample(&fit.params).unwrap();
        for k in 0..=m {
            let exact = options.control_points().is_none() || k == 0 || k == m;
            if exact {
                let e = at[k].iter().zip(&q[k]).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
                prop_assert!(e <= tol, "point {k}: {:?} != {:?} ({options:?})", at[k], q[k]);
            }
        }
    }

    #[test]
    fn least_squares_with_as_many_control_points_as_data_is_interpolation(
        (q, options) in data_and_options::<2>()
    ) {
        let interpolation = FitOptions::new(options.degree(), None).unwrap().with_parametrization(options.parametrization());
        let full = FitOptions::new(options.degree(), Some(q.len())).unwrap().with_parametrization(options.parametrization());
        prop_assert_eq!(fit_curve(&q, &full).unwrap(), fit_curve(&q, &interpolation).unwrap());
    }

    #[test]
    fn least_squares_residuals_are_orthogonal_to_the_interior_basis(
        (q, options) in data_and_options::<3>()
    ) {
        // The normal equations of §9.4.1: Σₖ Nᵢ(ūₖ)·(Qₖ − C(ūₖ)) = 0 for the
        // free control points i = 1 … n − 1, summed over the interior data.
        let Some(fit) = fit_or_skip(&q, &options) else { return Ok(()) };
        let n = fit.curve.control_points().len();
        let m = q.len() - 1;
        let at = fit.curve.sample(&fit.params).unwrap();
        let tol = 1e-13 * scale(&q).max(scale(fit.curve.control_points())) * (m as f64);
        for i in 1..n.saturating_sub(1) {
            let mut g = [0.0; 3];
            for k in 1..m {
                let r = fit.curve.rational_basis(fit.params[k]).unwrap()[i];
                for d in 0..3 {
                    g[d] += r * (q[k][d] - at[k][d]);
                }
            }
            prop_assert!(g.iter().all(|x| x.abs() <= tol), "i {i}: gradient {g:?} ({options:?})");
        }
    }

    #[test]
    fn fits_move_with_the_data(
        (q, options) in data_and_options::<2>(),
        shift in prop::array::uniform2(-100.0..100.0f64)
    ) {
        // Parameters depend on differences only; a translated data set gives
        // translated control points (affine invariance of B-splines).
        let moved: Vec<[f64; 2]> = q.iter().map(|p| [p[0] + shift[0], p[1] + shift[1]]).collect();
        let Some(a) = fit_or_skip(&q, &options) else { return Ok(()) };
        let b = fit_curve(&moved, &options).unwrap();
        // Errors of the solve grow with the condition number.
        let tol = 1e-13 * a.condition * (scale(a.curve.control_points()) + 200.0);
        for (pa, pb) in a.curve.control_points().iter().zip(b.curve.control_points()) {
            prop_assert!((pa[0] + shift[0] - pb[0]).abs() <= tol && (pa[1] + shift[1] - pb[1]).abs() <= tol,
                "{pa:?} + {shift:?} != {pb:?}");
        }
    }

    #[test]
    fn valid_fuzzy_fit_is_always_a_valid_fuzzy_curve(
        (data, options) in fuzzy_data_and_options::<2>()
    ) {
        let fit = match fit_fuzzy(&data, &options, FuzzyFitMode::Valid) {
            Err(Error::IllConditionedFit { .. }) if options.control_points().is_some() => return Ok(()),
            other => other.unwrap(),
        };
        prop_assert!(fit.violations().is_empty(), "{:?}", fit.violations());
        let curve = fit.to_curve().unwrap();
        // The crisp layer: interpolated, or approximated with the ends fixed.
        let crisp: Vec<[f64; 2]> = data.iter().map(|p| p.crisp()).collect();
        let tol = 1e-13 * scale(&crisp).max(scale(fit.layer_control_points(Layer::Crisp)));
        let m = data.len() - 1;
        for (k, &t) in fit.params().iter().enumerate() {
            let at = curve.eval_layers(t).unwrap();
            let values = Layer::ALL.map(|l| at[l]);
            for d in 0..2 {
                prop_assert!(values.windows(2).all(|w| w[0][d] <= w[1][d]), "t {t}: {values:?}");
            }
            if options.control_points().is_none() || k == 0 || k == m {
                prop_assert!(close_point(&at[Layer::Crisp], &crisp[k], tol), "point {k}");
            }
        }
        if options.control_points().is_none() {
            prop_assert!(fit.deviations()[Layer::Crisp].max <= tol);
        }
    }

    #[test]
    fn valid_fit_equals_the_independent_one_when_that_is_valid(
        (data, options) in fuzzy_data_and_options::<2>()
    ) {
        let independent = match fit_fuzzy(&data, &options, FuzzyFitMode::Independent) {
            Err(Error::IllConditionedFit { .. }) if options.control_points().is_some() => return Ok(()),
            other => other.unwrap(),
        };
        let valid = fit_fuzzy(&data, &options, FuzzyFitMode::Valid).unwrap();
        prop_assert_eq!(independent.independent_violations(), valid.independent_violations());
        prop_assert_eq!(independent.violations(), independent.independent_violations().to_vec());
        let crisp: Vec<[f64; 2]> = data.iter().map(|p| p.crisp()).collect();
        let tol = 1e-13 * independent.condition()
            * scale(&crisp).max(scale(independent.layer_control_points(Layer::UpperRight)));
        if independent.violations().is_empty() {
            for layer in Layer::ALL {
                let (a, b) = (independent.layer_control_points(layer), valid.layer_control_points(layer));
                for (pa, pb) in a.iter().zip(b) {
                    prop_assert!(
                        (pa[0] - pb[0]).abs() <= tol && (pa[1] - pb[1]).abs() <= tol,
                        "{layer}: {pa:?} != {pb:?}"
                    );
                }
            }
        } else {
            prop_assert!(independent.to_curve().is_err());
        }
    }
}
