//! Closed-form and hand-computed tests: the configuration of the paper's
//! Algorithm 1.1 (`examples/paper-alg-1-1.json`, built here with the core API),
//! the jump of type reduction at `alpha = h`, and circles as rational quadratics
//! (The NURBS Book, Ex. 7.1–7.2).

use approx::assert_abs_diff_eq;
use t2spline::{Alpha, Axis, FuzzyCurve, KnotVector, Layer, Nt2Number, Nt2Point, NurbsCurve, Side};

use std::f64::consts::FRAC_1_SQRT_2;

/// Tolerance for hand-computed values of size ≤ 6 after a few roundings.
const HAND: f64 = 1e-14;

/// The lower height of every number of the example (its top-level `lower_height`).
const H: f64 = 0.6;

fn number(crisp: f64, upper: [f64; 2], primary: [f64; 2], lower: [f64; 2]) -> Nt2Number {
    Nt2Number::try_new(crisp, upper, primary, lower, H).expect("the example's numbers are valid")
}

/// The four control points of `examples/paper-alg-1-1.json`.
fn example_points() -> Vec<Nt2Point<2>> {
    vec![
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
    ]
}

/// Order 3 (degree 2), weights (1, 1, 3, 1), default knots.
fn example() -> FuzzyCurve<2> {
    FuzzyCurve::try_new(2, example_points(), vec![1.0, 1.0, 3.0, 1.0], None)
        .expect("the example is valid")
}

fn alpha(a: f64) -> Alpha {
    Alpha::try_new(a).expect("a level in [0, 1]")
}

/// Hand-computed stage 2–4 values of one number of the example at one alpha.
struct Hand {
    point: usize,
    axis: Axis,
    alpha: f64,
    upper: [f64; 2],
    primary: [f64; 2],
    lower: Option<[f64; 2]>,
    left: f64,
    right: f64,
    defuzzified: f64,
}

/// `cut(e, s) = e + s·(crisp − e)`; upper and primary ends use `s = α`, lower
/// ends `s = α/h` when `α ≤ h` (docs/method.md §2). Type reduction averages two ends above
/// h, three at or below (docs/method.md §3); defuzzified = (left + crisp + right)/3 (§4).
#[rustfmt::skip]
fn hand_values() -> Vec<Hand> {
    vec![
        // Point 0, x: crisp 1, upper [0.4, 1.9], primary [0.6, 1.6], lower [0.8, 1.3].
        // α = 0.8 > h: upper  0.4 + 0.8·0.6 = 0.88,  1.9 − 0.8·0.9 = 1.18
        //              primary 0.6 + 0.8·0.4 = 0.92, 1.6 − 0.8·0.6 = 1.12
        //   left = (0.88 + 0.92)/2 = 0.9, right = (1.12 + 1.18)/2 = 1.15
        //   defuzzified = (0.9 + 1 + 1.15)/3 = 3.05/3
        Hand { point: 0, axis: Axis::X, alpha: 0.8, upper: [0.88, 1.18], primary: [0.92, 1.12],
               lower: None, left: 0.9, right: 1.15, defuzzified: 3.05 / 3.0 },
        // α = 0.3 ≤ h, s = 0.3/0.6 = 0.5:
        //   upper  0.4 + 0.3·0.6 = 0.58,  1.9 − 0.3·0.9 = 1.63
        //   primary 0.6 + 0.3·0.4 = 0.72, 1.6 − 0.3·0.6 = 1.42
        //   lower  0.8 + 0.5·0.2 = 0.9,   1.3 − 0.5·0.3 = 1.15
        //   left = (0.58 + 0.72 + 0.9)/3 = 2.2/3, right = (1.15 + 1.42 + 1.63)/3 = 4.2/3 = 1.4
        //   defuzzified = (2.2/3 + 1 + 1.4)/3 = (2.2 + 7.2)/9 = 9.4/9
        Hand { point: 0, axis: Axis::X, alpha: 0.3, upper: [0.58, 1.63], primary: [0.72, 1.42],
               lower: Some([0.9, 1.15]), left: 2.2 / 3.0, right: 1.4, defuzzified: 9.4 / 9.0 },
        // Point 0, y: crisp 1, upper [0.2, 1.5], primary [0.5, 1.35], lower [0.75, 1.2].
        // α = 0.8: upper  0.2 + 0.8·0.8 = 0.84,  1.5 − 0.8·0.5 = 1.1
        //          primary 0.5 + 0.8·0.5 = 0.9,  1.35 − 0.8·0.35 = 1.07
        //   left = 1.74/2 = 0.87, right = 2.17/2 = 1.085, defuzzified = 2.955/3 = 0.985
        Hand { point: 0, axis: Axis::Y, alpha: 0.8, upper: [0.84, 1.1], primary: [0.9, 1.07],
               lower: None, left: 0.87, right: 1.085, defuzzified: 0.985 },
        // α = 0.3, s = 0.5:
        //   upper  0.2 + 0.3·0.8 = 0.44,  1.5 − 0.3·0.5 = 1.35
        //   primary 0.5 + 0.3·0.5 = 0.65, 1.35 − 0.3·0.35 = 1.245
        //   lower  0.75 + 0.5·0.25 = 0.875, 1.2 − 0.5·0.2 = 1.1
        //   left = (0.44 + 0.65 + 0.875)/3 = 1.965/3 = 0.655
        //   right = (1.1 + 1.245 + 1.35)/3 = 3.695/3
        //   defuzzified = (1.965 + 3 + 3.695)/9 = 8.66/9
        Hand { point: 0, axis: Axis::Y, alpha: 0.3, upper: [0.44, 1.35], primary: [0.65, 1.245],
               lower: Some([0.875, 1.1]), left: 0.655, right: 3.695 / 3.0, defuzzified: 8.66 / 9.0 },
        // Point 2, x: crisp 5, upper [4.1, 5.6], primary [4.4, 5.45], lower [4.7, 5.2].
        // α = 0.8: upper  4.1 + 0.8·0.9 = 4.82,  5.6 − 0.8·0.6 = 5.12
        //          primary 4.4 + 0.8·0.6 = 4.88, 5.45 − 0.8·0.45 = 5.09
        //   left = 9.7/2 = 4.85, right = 10.21/2 = 5.105, defuzzified = 14.955/3 = 4.985
        Hand { point: 2, axis: Axis::X, alpha: 0.8, upper: [4.82, 5.12], primary: [4.88, 5.09],
               lower: None, left: 4.85, right: 5.105, defuzzified: 4.985 },
        // α = 0.3, s = 0.5:
        //   upper  4.1 + 0.3·0.9 = 4.37,  5.6 − 0.3·0.6 = 5.42
        //   primary 4.4 + 0.3·0.6 = 4.58, 5.45 − 0.3·0.45 = 5.315
        //   lower  4.7 + 0.5·0.3 = 4.85,  5.2 − 0.5·0.2 = 5.1
        //   left = (4.37 + 4.58 + 4.85)/3 = 13.8/3 = 4.6
        //   right = (5.1 + 5.315 + 5.42)/3 = 15.835/3
        //   defuzzified = (13.8 + 15 + 15.835)/9 = 44.635/9
        Hand { point: 2, axis: Axis::X, alpha: 0.3, upper: [4.37, 5.42], primary: [4.58, 5.315],
               lower: Some([4.85, 5.1]), left: 4.6, right: 15.835 / 3.0, defuzzified: 44.635 / 9.0 },
        // Point 2, y: crisp 4.5, upper [4.0, 5.4], primary [4.2, 5.1], lower [4.35, 4.8].
        // α = 0.8: upper  4.0 + 0.8·0.5 = 4.4,   5.4 − 0.8·0.9 = 4.68
        //          primary 4.2 + 0.8·0.3 = 4.44, 5.1 − 0.8·0.6 = 4.62
        //   left = 8.84/2 = 4.42, right = 9.3/2 = 4.65, defuzzified = 13.57/3
        Hand { point: 2, axis: Axis::Y, alpha: 0.8, upper: [4.4, 4.68], primary: [4.44, 4.62],
               lower: None, left: 4.42, right: 4.65, defuzzified: 13.57 / 3.0 },
        // α = 0.3, s = 0.5:
        //   upper  4.0 + 0.3·0.5 = 4.15,  5.4 − 0.3·0.9 = 5.13
        //   primary 4.2 + 0.3·0.3 = 4.29, 5.1 − 0.3·0.6 = 4.92
        //   lower  4.35 + 0.5·0.15 = 4.425, 4.8 − 0.5·0.3 = 4.65
        //   left = (4.15 + 4.29 + 4.425)/3 = 12.865/3
        //   right = (4.65 + 4.92 + 5.13)/3 = 14.7/3 = 4.9
        //   defuzzified = (12.865 + 13.5 + 14.7)/9 = 41.065/9
        Hand { point: 2, axis: Axis::Y, alpha: 0.3, upper: [4.15, 5.13], primary: [4.29, 4.92],
               lower: Some([4.425, 4.65]), left: 12.865 / 3.0, right: 4.9, defuzzified: 41.065 / 9.0 },
    ]
}

#[test]
fn example_stages_match_hand_computed_values() {
    let curve = example();
    for e in hand_values() {
        let (i, d) = (e.point, e.axis.index());
        let at = format!("point {i}, {}, alpha {}", e.axis, e.alpha);
        let solution = curve.solve(alpha(e.alpha));

        let check = |what: &str, got: f64, expect: f64| {
            assert!(
                (got - expect).abs() <= HAND,
                "{at}: {what} = {got}, by hand {expect}"
            );
        };

        // Stage 2: the alpha-cut.
        let cut = solution.alpha_cut_points()[i][d];
        check("upper.left'", cut.upper().left(), e.upper[0]);
        check("upper.right'", cut.upper().right(), e.upper[1]);
        check("primary.left'", cut.primary().left(), e.primary[0]);
        check("primary.right'", cut.primary().right(), e.primary[1]);
        match (cut.lower(), e.lower) {
            (Some(l), Some([left, right])) => {
                check("lower.left'", l.left(), left);
                check("lower.right'", l.right(), right);
            }
            (None, None) => {}
            (got, expect) => panic!("{at}: lower cut {got:?}, expected {expect:?}"),
        }
        // The stage-2 layer points agree with the per-number cut.
        let layer = solution
            .alpha_cut_layer(Layer::UpperLeft)
            .expect("upper cuts always exist");
        assert_eq!(layer[i][d], cut.upper().left(), "{at}");

        // Stage 3: type reduction.
        let tfn = solution.type_reduced_points()[i][d];
        check("left", tfn.left(), e.left);
        check("right", tfn.right(), e.right);
        assert_eq!(
            tfn.defuzzified(),
            solution.defuzzified_points()[i][d],
            "{at}"
        );
        assert_eq!(
            solution.type_reduced_side(Side::Left)[i][d],
            tfn.left(),
            "{at}"
        );
        assert_eq!(
            solution.type_reduced_side(Side::Right)[i][d],
            tfn.right(),
            "{at}"
        );

        // Stage 4: defuzzification.
        check(
            "defuzzified",
            solution.defuzzified_points()[i][d],
            e.defuzzified,
        );
    }
}

#[test]
fn example_has_the_default_clamped_knots() {
    assert_eq!(
        example().knots().as_slice(),
        &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
    );
    assert_eq!(example().order(), 3);
    assert_eq!(example().degree(), 2);
}

#[test]
fn clamped_curves_interpolate_the_end_control_points() {
    let curve = example();
    let crisp = curve.crisp_curve();
    assert_eq!(crisp.eval(0.0).unwrap(), [1.0, 1.0]);
    assert_eq!(crisp.eval(1.0).unwrap(), [6.0, 1.0]);
    // Every layer curve, and every stage curve, interpolates its own end points.
    let points = curve.points();
    let (first, last) = (points[0], points[3]);
    let (start, end) = (
        curve.eval_layers(0.0).unwrap(),
        curve.eval_layers(1.0).unwrap(),
    );
    for l in Layer::ALL {
        assert_eq!(start[l], first.layer(l), "{l} at t = 0");
        assert_eq!(end[l], last.layer(l), "{l} at t = 1");
    }
    for a in [0.3, 0.8] {
        let solution = curve.solve(alpha(a));
        let d = solution.defuzzified_points();
        let c = solution.defuzzified_curve();
        assert_eq!(c.eval(0.0).unwrap(), d[0], "alpha {a}");
        assert_eq!(c.eval(1.0).unwrap(), d[3], "alpha {a}");
    }
}

/// At `α = h` the lower cut is the single value `crisp` and type reduction
/// averages three ends; just above h it averages two. With `dU = crisp −
/// upper.left`, `dP = crisp − primary.left` (and `eU`, `eP` the right spreads):
///
/// ```text
/// left(h)    = crisp − (1 − h)(dU + dP)/3
/// left(h+ε)  = crisp − (1 − h − ε)(dU + dP)/2
/// left(h+ε) − left(h) = −(1 − h)(dU + dP)/6 + ε(dU + dP)/2
/// right(h+ε) − right(h) = (1 − h)(eU + eP)/6 − ε(eU + eP)/2
/// ```
/// E.g. point 0, x: dU + dP = 0.6 + 0.4 = 1, so the left end jumps by
/// −0.4/6 = −1/15 (0.8667 → 0.8); eU + eP = 0.9 + 0.6 = 1.5, so the right end
/// jumps by 0.4·1.5/6 = 0.1 (1.2 → 1.3). The cut ends themselves move by only
/// `ε·(crisp − e)`: they are continuous.
#[test]
fn type_reduction_jumps_at_alpha_equal_h_by_the_closed_form() {
    let curve = example();
    let above = H + 1e-9;
    // The difference of two close floats is exact (Sterbenz), so this ε is
    // the one the library sees.
    let eps = above - H;
    let (at, over) = (curve.solve(alpha(H)), curve.solve(alpha(above)));
    let mut jumps = vec![[[0.0; 2]; 2]; curve.points().len()];
    for (i, p) in curve.points().iter().enumerate() {
        for (d, x) in p.coords().iter().enumerate() {
            let c = x.crisp();
            let (du, dp) = (c - x.upper().left(), c - x.primary().left());
            let (eu, ep) = (x.upper().right() - c, x.primary().right() - c);
            let left_jump = -(1.0 - H) * (du + dp) / 6.0 + eps * (du + dp) / 2.0;
            let right_jump = (1.0 - H) * (eu + ep) / 6.0 - eps * (eu + ep) / 2.0;
            jumps[i][0][d] = left_jump;
            jumps[i][1][d] = right_jump;
            let (t0, t1) = (
                at.type_reduced_points()[i][d],
                over.type_reduced_points()[i][d],
            );
            let msg = format!("point {i}, coordinate {d}: {t0:?} -> {t1:?}");
            assert!(
                (t1.left() - t0.left() - left_jump).abs() < 1e-14,
                "{msg}, left jump {left_jump}"
            );
            assert!(
                (t1.right() - t0.right() - right_jump).abs() < 1e-14,
                "{msg}, right jump {right_jump}"
            );
            // Alpha-cut ends: continuous (they move by ε·(crisp − e)), and the
            // lower cut is `[crisp, crisp]` at h and absent above.
            let (c0, c1) = (at.alpha_cut_points()[i][d], over.alpha_cut_points()[i][d]);
            for (e, e0, e1) in [
                (x.upper().left(), c0.upper().left(), c1.upper().left()),
                (x.upper().right(), c0.upper().right(), c1.upper().right()),
                (x.primary().left(), c0.primary().left(), c1.primary().left()),
                (
                    x.primary().right(),
                    c0.primary().right(),
                    c1.primary().right(),
                ),
            ] {
                assert!(
                    (e1 - e0 - eps * (c - e)).abs() < 1e-14,
                    "{msg}: cut end of {e} moves {e0} -> {e1}"
                );
            }
            assert_eq!(
                c0.lower().map(|l| [l.left(), l.right()]),
                Some([c, c]),
                "{msg}"
            );
            assert_eq!(c1.lower(), None, "{msg}");
        }
    }
    // Point 0, x, the numbers of the doc comment.
    assert_abs_diff_eq!(jumps[0][0][0], -1.0 / 15.0, epsilon = 1e-8);
    assert_abs_diff_eq!(jumps[0][1][0], 0.1, epsilon = 1e-8);
    // On the type-reduced curves the jump is Σ R_i(t)·jump_i.
    let basis = curve.crisp_curve();
    for t in [0.0, 0.25, 0.5, 0.9, 1.0] {
        let r = basis.rational_basis(t).unwrap();
        for (side, s) in [(Side::Left, 0), (Side::Right, 1)] {
            let (y0, y1) = (
                at.type_reduced_curve(side).eval(t).unwrap(),
                over.type_reduced_curve(side).eval(t).unwrap(),
            );
            for d in 0..2 {
                let expect: f64 = r.iter().zip(&jumps).map(|(ri, j)| ri * j[s][d]).sum();
                assert!(
                    (y1[d] - y0[d] - expect).abs() < 1e-13,
                    "{side:?} curve at t = {t}, coordinate {d}: {} -> {}, expected jump {expect}",
                    y0[d],
                    y1[d]
                );
            }
        }
    }
    // The lower cut curves exist at h and not above.
    assert!(at.alpha_cut_curve(Layer::LowerLeft).is_some());
    assert!(over.alpha_cut_curve(Layer::LowerRight).is_none());
}

#[test]
fn alpha_one_gives_the_crisp_curve() {
    let curve = example();
    let solution = curve.solve(alpha(1.0));
    let (crisp, solved) = (solution.crisp_curve(), solution.defuzzified_curve());
    for t in curve.domain().uniform(1001).unwrap() {
        assert_eq!(solved.eval(t).unwrap(), crisp.eval(t).unwrap(), "t = {t}");
    }
    let d = solution.distance();
    assert_eq!((d.max, d.rms), (0.0, 0.0));
}

#[test]
fn example_distance_is_positive_and_below_its_maximum() {
    // Unequal spreads move the solution off the crisp curve (docs/method.md §7); the rms
    // of a continuous distance never exceeds its maximum.
    for a in [0.3, 0.8] {
        let d = example().solve(alpha(a)).distance();
        assert!(
            d.max > 0.0 && d.rms > 0.0 && d.rms <= d.max,
            "alpha {a}: {d:?}"
        );
    }
}

/// The quarter circle as a rational quadratic (The NURBS Book, Ex. 7.1).
#[test]
fn quarter_circle_has_radius_one() {
    let c = NurbsCurve::try_clamped(
        2,
        vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        vec![1.0, FRAC_1_SQRT_2, 1.0],
    )
    .unwrap();
    for t in c.domain().uniform(1001).unwrap() {
        let [x, y] = c.eval(t).unwrap();
        assert!((x.hypot(y) - 1.0).abs() <= 1e-15, "t = {t}: ({x}, {y})");
        assert!(
            x >= 0.0 && y >= 0.0,
            "t = {t}: ({x}, {y}) leaves the quadrant"
        );
    }
}

/// Radius of a closed circle curve at 1001 parameters, and that it closes.
fn assert_unit_circle(c: &NurbsCurve<2>, tol: f64) {
    assert_eq!(c.eval(0.0).unwrap(), [1.0, 0.0]);
    assert_eq!(c.eval(1.0).unwrap(), [1.0, 0.0]);
    for t in c.domain().uniform(1001).unwrap() {
        let [x, y] = c.eval(t).unwrap();
        assert!((x.hypot(y) - 1.0).abs() <= tol, "t = {t}: ({x}, {y})");
    }
    // Its length is 2π, and the point at length s lies at the angle s.
    let tau = std::f64::consts::TAU;
    let length = c.arc_length();
    assert!((length / tau - 1.0).abs() < 1e-12, "{length}");
    for k in 0..=8 {
        // τ itself may exceed the computed length by an ulp: accepted.
        let s = tau * k as f64 / 8.0;
        let t = c.param_at_length(s).unwrap();
        let [x, y] = c.eval(t).unwrap();
        let angle = y.atan2(x).rem_euclid(tau);
        let expect = (tau * k as f64 / 8.0) % tau;
        let diff = (angle - expect).abs().min(tau - (angle - expect).abs());
        assert!(diff < 1e-10, "k = {k}: angle {angle}");
    }
    assert!(matches!(
        c.param_at_length(7.0),
        Err(t2spline::Error::LengthOutside { .. })
    ));
    assert!(matches!(
        c.param_at_length(f64::NAN),
        Err(t2spline::Error::LengthOutside { .. })
    ));
    // Its length is 2π (adaptive quadrature, relative accuracy 1e-10 asked).
    let length = c.arc_length();
    assert!(
        (length / std::f64::consts::TAU - 1.0).abs() < 1e-12,
        "{length}"
    );
    // Interior double knots: the curve is continuous there (C¹ in fact).
    for k in [0.25, 0.5, 0.75, 1.0 / 3.0, 2.0 / 3.0] {
        if c.knots().multiplicity(k) == 2 {
            let (a, b) = (c.eval(k - 1e-12).unwrap(), c.eval(k).unwrap());
            assert!(
                (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9,
                "jump at {k}"
            );
        }
    }
}

/// The full circle from nine control points on a square (The NURBS Book,
/// Ex. 7.2 style): four quarter arcs joined at interior double knots.
#[test]
fn full_circle_from_a_square_has_radius_one() {
    let w = FRAC_1_SQRT_2;
    let points = vec![
        [1.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [-1.0, 1.0],
        [-1.0, 0.0],
        [-1.0, -1.0],
        [0.0, -1.0],
        [1.0, -1.0],
        [1.0, 0.0],
    ];
    let weights = vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0];
    let knots = KnotVector::try_new(
        vec![
            0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
        ],
        2,
        9,
    )
    .unwrap();
    let c = NurbsCurve::try_new(points, weights, knots).unwrap();
    assert_unit_circle(&c, 1e-15);
    // The joints are the control points on the circle.
    assert_eq!(c.eval(0.25).unwrap(), [0.0, 1.0]);
    assert_eq!(c.eval(0.5).unwrap(), [-1.0, 0.0]);
    assert_eq!(c.eval(0.75).unwrap(), [0.0, -1.0]);
}

/// The full circle from seven control points on an equilateral triangle of
/// circumradius 2 (The NURBS Book, Ex. 7.2): three 120° arcs, middle weights
/// cos 60° = 1/2.
#[test]
fn full_circle_from_a_triangle_has_radius_one() {
    let s = 3f64.sqrt();
    let points = vec![
        [1.0, 0.0],
        [1.0, s],
        [-0.5, s / 2.0],
        [-2.0, 0.0],
        [-0.5, -s / 2.0],
        [1.0, -s],
        [1.0, 0.0],
    ];
    let weights = vec![1.0, 0.5, 1.0, 0.5, 1.0, 0.5, 1.0];
    let (third, two_thirds) = (1.0 / 3.0, 2.0 / 3.0);
    let knots = KnotVector::try_new(
        vec![
            0.0, 0.0, 0.0, third, third, two_thirds, two_thirds, 1.0, 1.0, 1.0,
        ],
        2,
        7,
    )
    .unwrap();
    let c = NurbsCurve::try_new(points, weights, knots).unwrap();
    // √3 is rounded in the control points, yet the radius stays within 1e-15.
    assert_unit_circle(&c, 1e-15);
}

/// Spreads (left upper, primary, lower; right lower, primary, upper) from the
/// crisp value, the same for every control point of one coordinate.
type Spreads = ([f64; 3], [f64; 3]);

/// The defuzzified offset of a number with `spreads` (docs/method.md §2–§4):
///
/// ```text
/// α > h:  δ = (1 − α)·((eP + eU) − (dU + dP))/6
/// α ≤ h:  δ = ((1 − α/h)·(eL − dL) + (1 − α)·((eP + eU) − (dU + dP)))/9
/// ```
fn offset(([du, dp, dl], [el, ep, eu]): Spreads, a: f64, h: f64) -> f64 {
    if a > h {
        (1.0 - a) * ((ep + eu) - (du + dp)) / 6.0
    } else {
        ((1.0 - a / h) * (el - dl) + (1.0 - a) * ((ep + eu) - (du + dp))) / 9.0
    }
}

/// A fuzzy circle: every number of the nine-point circle has the same
/// asymmetric spreads per coordinate, so every defuzzified control point is the
/// crisp one moved by the same `(δx, δy)`. The basis sums to 1, so the
/// defuzzified curve is the circle moved by that vector, and the distance is
/// `|(δx, δy)|` everywhere: max = rms = the offset.
#[test]
fn fuzzy_circle_is_offset_by_the_closed_form() {
    let h = 0.5;
    let x_spreads: Spreads = ([0.6, 0.4, 0.2], [0.3, 0.6, 0.9]);
    let y_spreads: Spreads = ([0.3, 0.2, 0.1], [0.1, 0.25, 0.5]);
    let fuzzy = |c: f64, ([du, dp, dl], [el, ep, eu]): Spreads| {
        Nt2Number::try_new(c, [c - du, c + eu], [c - dp, c + ep], [c - dl, c + el], h).unwrap()
    };
    let w = FRAC_1_SQRT_2;
    let crisp = [
        [1.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [-1.0, 1.0],
        [-1.0, 0.0],
        [-1.0, -1.0],
        [0.0, -1.0],
        [1.0, -1.0],
        [1.0, 0.0],
    ];
    let points = crisp
        .iter()
        .map(|&[x, y]| Nt2Point::new([fuzzy(x, x_spreads), fuzzy(y, y_spreads)]))
        .collect();
    let curve = FuzzyCurve::try_new(
        2,
        points,
        vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0],
        Some(vec![
            0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
        ]),
    )
    .unwrap();
    // By hand:
    // α = 0.8 > h: δx = 0.2·((0.6 + 0.9) − (0.6 + 0.4))/6 = 0.2·0.5/6 = 1/60
    //              δy = 0.2·((0.25 + 0.5) − (0.3 + 0.2))/6 = 0.2·0.25/6 = 1/120
    // α = 0.3 ≤ h: 1 − α/h = 0.4, 1 − α = 0.7
    //              δx = (0.4·(0.3 − 0.2) + 0.7·0.5)/9 = 0.39/9
    //              δy = (0.4·(0.1 − 0.1) + 0.7·0.25)/9 = 0.175/9
    for (a, by_hand) in [
        (0.8, [1.0 / 60.0, 1.0 / 120.0]),
        (0.3, [0.39 / 9.0, 0.175 / 9.0]),
    ] {
        let delta = [offset(x_spreads, a, h), offset(y_spreads, a, h)];
        assert_abs_diff_eq!(delta[0], by_hand[0], epsilon = 1e-15);
        assert_abs_diff_eq!(delta[1], by_hand[1], epsilon = 1e-15);
        let expect = delta[0].hypot(delta[1]);

        let solution = curve.solve(alpha(a));
        let d = solution.distance();
        assert!(
            (d.max - expect).abs() < 1e-12 && (d.rms - expect).abs() < 1e-12,
            "alpha {a}: {d:?}, expected {expect}"
        );
        let solved = solution.defuzzified_curve();
        for t in curve.domain().uniform(1001).unwrap() {
            let [x, y] = solved.eval(t).unwrap();
            let r = (x - delta[0]).hypot(y - delta[1]);
            assert!((r - 1.0).abs() < 1e-12, "alpha {a}, t = {t}: radius {r}");
        }
    }
}
