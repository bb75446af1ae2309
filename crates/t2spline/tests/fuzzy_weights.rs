//! Curves with fuzzy weights (docs/method.md §16): each stage's curve is the
//! rational B-spline through that stage's values of the points and of the
//! weights; crisp numbers as weights change nothing; what does not take
//! fuzzy weights says so.

use t2spline::sampling::Params;
use t2spline::{
    Alpha, Error, FuzzyCurve, Layer, Nt2Number, Nt2Point, NurbsCurve, Side, TypeReduction,
};

fn number(c: f64, spread: f64) -> Nt2Number {
    Nt2Number::try_new(
        c,
        [c - spread, c + 2.0 * spread],
        [c - 0.5 * spread, c + spread],
        [c - 0.2 * spread, c + 0.3 * spread],
        0.5,
    )
    .unwrap()
}

fn points() -> Vec<Nt2Point<2>> {
    [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.0]]
        .iter()
        .map(|&[x, y]| Nt2Point::new([number(x, 0.3), number(y, 0.2)]))
        .collect()
}

fn weights() -> Vec<Nt2Number> {
    vec![
        number(1.0, 0.2),
        number(2.0, 0.8),
        number(0.7, 0.3),
        number(1.5, 0.4),
    ]
}

fn curve() -> FuzzyCurve<2> {
    FuzzyCurve::try_new(2, points(), vec![1.0; 4], None)
        .unwrap()
        .with_weight_numbers(weights())
        .unwrap()
}

/// The rational B-spline of `points` with `weights` and the curve's knots.
fn reference(points: Vec<[f64; 2]>, weights: Vec<f64>) -> NurbsCurve<2> {
    NurbsCurve::try_new(points, weights, curve().knots().clone()).unwrap()
}

fn assert_same(a: &NurbsCurve<2>, b: &NurbsCurve<2>) {
    for t in a.domain().uniform(33).unwrap() {
        let (p, q) = (a.eval(t).unwrap(), b.eval(t).unwrap());
        assert!(
            (p[0] - q[0]).abs() < 1e-13 && (p[1] - q[1]).abs() < 1e-13,
            "{t}: {p:?} {q:?}"
        );
    }
}

#[test]
fn every_stage_pairs_the_values_of_points_and_weights() {
    let c = curve();
    assert_eq!(c.weights(), &[1.0, 2.0, 0.7, 1.5]);
    for layer in Layer::ALL {
        let expected = reference(
            c.points().iter().map(|p| p.layer(layer)).collect(),
            weights().iter().map(|w| w.layer(layer)).collect(),
        );
        assert_same(&c.layer_curve(layer), &expected);
        let at = c.eval_layers(0.4).unwrap()[layer];
        let e = expected.eval(0.4).unwrap();
        assert!((at[0] - e[0]).abs() < 1e-13 && (at[1] - e[1]).abs() < 1e-13);
    }
    for method in TypeReduction::ALL {
        let alpha = Alpha::try_new(0.3).unwrap();
        let s = c.solve_with(alpha, method);
        let w: Vec<Nt2Number> = weights();
        let reduced: Vec<_> = w.iter().map(|w| w.reduce(method, alpha)).collect();
        assert_same(
            &s.defuzzified_curve(),
            &reference(
                s.defuzzified_points().to_vec(),
                reduced.iter().map(|r| r.defuzzified()).collect(),
            ),
        );
        assert_eq!(
            s.defuzzified_weights().unwrap(),
            reduced.iter().map(|r| r.defuzzified()).collect::<Vec<_>>()
        );
        for side in [Side::Left, Side::Right] {
            let ws: Vec<f64> = reduced
                .iter()
                .map(|r| {
                    if side == Side::Left {
                        r.left()
                    } else {
                        r.right()
                    }
                })
                .collect();
            assert_same(
                &s.type_reduced_curve(side),
                &reference(s.type_reduced_side(side), ws.clone()),
            );
            assert_eq!(s.type_reduced_weights(side).unwrap(), ws);
        }
        for layer in [Layer::UpperLeft, Layer::PrimaryRight, Layer::LowerLeft] {
            let cut: Vec<f64> = w
                .iter()
                .map(|w| w.alpha_cut(alpha).layer(layer).unwrap())
                .collect();
            assert_same(
                &s.alpha_cut_curve(layer).unwrap(),
                &reference(s.alpha_cut_layer(layer).unwrap(), cut.clone()),
            );
            assert_eq!(s.alpha_cut_weights(layer), Some(Some(cut)));
        }
    }
}

#[test]
fn crisp_numbers_as_weights_leave_the_curve_as_it_was() {
    let crisp: Vec<Nt2Number> = [1.0, 2.0, 0.7, 1.5]
        .iter()
        .map(|&w| Nt2Number::try_new(w, [w, w], [w, w], [w, w], 0.5).unwrap())
        .collect();
    let plain = FuzzyCurve::try_new(2, points(), vec![1.0, 2.0, 0.7, 1.5], None).unwrap();
    let numbered = FuzzyCurve::try_new(2, points(), vec![1.0; 4], None)
        .unwrap()
        .with_weight_numbers(crisp)
        .unwrap();
    assert_eq!(plain, numbered);
    assert!(numbered.weight_numbers().is_none());
}

#[test]
fn sampled_stages_agree_with_the_stage_curves_and_the_distance_with_brute_force() {
    let c = curve();
    let alpha = Alpha::try_new(0.2).unwrap();
    let s = c.solve(alpha);
    let sweep = c.sample_sweep(Params::Uniform(201), &[alpha]).unwrap();
    let ts = c.domain().uniform(201).unwrap();
    let level = &sweep.levels()[0];
    for (i, &t) in ts.iter().enumerate() {
        for layer in Layer::ALL {
            let p = sweep.layers()[layer].point(i).unwrap();
            let q = c.layer_curve(layer).eval(t).unwrap();
            assert!((p[0] - q[0]).abs() < 1e-12 && (p[1] - q[1]).abs() < 1e-12);
        }
        let p = level.defuzzified().point(i).unwrap();
        let q = s.defuzzified_curve().eval(t).unwrap();
        assert!((p[0] - q[0]).abs() < 1e-12 && (p[1] - q[1]).abs() < 1e-12);
    }
    // The distance: at least every sampled distance, and not above the
    // largest of a fine scan by more than rounding.
    let d = s.distance();
    let (crisp, solved) = (s.crisp_curve(), s.defuzzified_curve());
    let scan = c
        .domain()
        .uniform(20_001)
        .unwrap()
        .into_iter()
        .map(|t| {
            let (a, b) = (crisp.eval(t).unwrap(), solved.eval(t).unwrap());
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .fold(0.0, f64::max);
    assert!(
        d.max >= scan - 1e-14 && d.max <= scan * (1.0 + 1e-6),
        "{} vs {scan}",
        d.max
    );
    assert!(d.rms > 0.0 && d.rms <= d.max);
}

#[test]
fn the_bounding_box_holds_every_admissible_curve() {
    let c = curve();
    let b = c.bounding_box();
    // Vertex choices of points and weights in their upper cuts at level 0.
    let mut seed = 7u64;
    let mut pick = |lo: f64, hi: f64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        if seed >> 63 == 0 {
            lo
        } else {
            hi
        }
    };
    for _ in 0..200 {
        let pts: Vec<[f64; 2]> = c
            .points()
            .iter()
            .map(|p| {
                let (l, r) = (p.layer(Layer::UpperLeft), p.layer(Layer::UpperRight));
                [pick(l[0], r[0]), pick(l[1], r[1])]
            })
            .collect();
        let ws: Vec<f64> = weights()
            .iter()
            .map(|w| pick(w.layer(Layer::UpperLeft), w.layer(Layer::UpperRight)))
            .collect();
        let k = reference(pts, ws);
        for t in k.domain().uniform(41).unwrap() {
            let p = k.eval(t).unwrap();
            assert!((0..2).all(|d| b.min[d] <= p[d] && p[d] <= b.max[d]));
        }
    }
}

#[test]
fn what_takes_crisp_weights_only_says_so() {
    let c = curve();
    let alpha = Alpha::ZERO;
    let says = |e: Error, what: &str| {
        assert_eq!(
            e.to_string(),
            format!("{what} is not available for a model with fuzzy weights")
        );
    };
    says(c.insert_knot(0.5, 1).unwrap_err(), "knot insertion");
    says(c.elevate_degree(1).unwrap_err(), "degree elevation");
    says(c.split_at(0.5).unwrap_err(), "splitting");
    says(c.segment(0.1, 0.5).unwrap_err(), "a segment");
    says(c.membership(&[1.0, 1.0]).unwrap_err(), "membership");
    says(
        c.region(t2spline::Membership::Upper, alpha, None)
            .unwrap_err(),
        "a region",
    );
    says(
        c.section(1.0, t2spline::Membership::Upper, alpha, None)
            .unwrap_err(),
        "a section of a curve",
    );
    assert!(c
        .length_bracket(t2spline::Membership::Upper, alpha)
        .is_none());
}

#[test]
fn a_weight_whose_least_value_is_not_positive_is_refused() {
    let bad = vec![
        number(1.0, 0.2),
        number(0.5, 0.5),
        number(0.7, 0.3),
        number(1.5, 0.4),
    ];
    let e = FuzzyCurve::try_new(2, points(), vec![1.0; 4], None)
        .unwrap()
        .with_weight_numbers(bad)
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights[1] = 0 must be finite and greater than 0"
    );
    let e = FuzzyCurve::try_new(2, points(), vec![1.0; 4], None)
        .unwrap()
        .with_weight_numbers(weights()[..3].to_vec())
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights: expected 4 (one per control point), got 3"
    );
}
