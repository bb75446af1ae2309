//! Property tests of the curve operations on random rational curves (degrees
//! 1–5, weights 0.2–5, clamped or not, repeated knots up to full multiplicity).

use proptest::prelude::*;
use t2spline::{strategies, NurbsCurve};

fn dist<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// The length of the control polygon piece by piece, a bound on the arc length
/// of a continuous curve (convex hull / variation diminishing).
fn polygon_length<const D: usize>(c: &NurbsCurve<D>) -> f64 {
    c.control_points()
        .windows(2)
        .map(|w| dist(&w[0], &w[1]))
        .sum()
}

/// The length of the polyline through `c` from `a` to `b`, its segments
/// halved until halving one lengthens it by at most 1e-8 of itself (the chord
/// error falls fourfold per halving, so what is left is a third of that), or
/// 24 times: a lower bound of the arc length that converges to it also where
/// the speed varies by orders of magnitude within a span (large weight
/// ratios), which no uniform polyline of fixed size resolves.
fn adaptive_polyline<const D: usize>(
    c: &NurbsCurve<D>,
    [a, b]: [f64; 2],
    [pa, pb]: [[f64; D]; 2],
    depth: usize,
) -> f64 {
    let m = 0.5 * (a + b);
    let pm = c.eval(m).unwrap();
    let (whole, halves) = (dist(&pa, &pb), dist(&pa, &pm) + dist(&pm, &pb));
    if depth >= 24 || halves - whole <= 1e-8 * halves {
        return halves;
    }
    adaptive_polyline(c, [a, m], [pa, pm], depth + 1)
        + adaptive_polyline(c, [m, b], [pm, pb], depth + 1)
}

/// Whether the curve is continuous (no interior knot of full multiplicity).
fn continuous<const D: usize>(c: &NurbsCurve<D>) -> bool {
    let u = c.knots().as_slice();
    let d = c.domain();
    u.iter()
        .all(|&v| !(d.start < v && v < d.end) || c.knots().multiplicity(v) <= c.degree())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn arc_length_lies_between_chord_and_polygon(c in strategies::curve::<2>()) {
        prop_assume!(continuous(&c) && c.knots().is_clamped());
        let d = c.domain();
        let chord = dist(&c.eval(d.start).unwrap(), &c.eval(d.end).unwrap());
        let length = c.arc_length();
        prop_assert!(length >= chord * (1.0 - 1e-12), "{} < chord {}", length, chord);
        prop_assert!(length <= polygon_length(&c) * (1.0 + 1e-12), "{} > polygon", length);
    }

    #[test]
    fn arc_length_matches_a_fine_polyline(c in strategies::curve::<3>()) {
        prop_assume!(continuous(&c));
        // Every knot is a vertex, so that corners are not cut.
        let mut ts = c.domain().uniform(2_001).unwrap();
        ts.extend(c.knots().as_slice().iter().filter(|&&u| c.domain().contains(u)));
        ts.sort_by(f64::total_cmp);
        ts.dedup();
        let points: Vec<_> = ts.iter().map(|&t| c.eval(t).unwrap()).collect();
        let polyline: f64 = ts
            .windows(2)
            .zip(points.windows(2))
            .map(|(t, p)| adaptive_polyline(&c, [t[0], t[1]], [p[0], p[1]], 0))
            .sum();
        let length = c.arc_length();
        // The polyline is shorter, and converges to the length.
        prop_assert!(polyline <= length * (1.0 + 1e-12));
        prop_assert!((length - polyline) <= 1e-4 * length + 1e-12, "{} vs {}", length, polyline);
    }

    #[test]
    fn param_at_length_inverts_arc_length(c in strategies::curve::<2>(), s in 0.0..=1.0f64) {
        let total = c.arc_length();
        prop_assume!(total > 1e-6);
        let t = c.param_at_length(s * total).unwrap();
        let back = c.arc_length_between(c.domain().start, t).unwrap();
        prop_assert!((back - s * total).abs() <= 1e-9 * total, "s = {}, t = {}: {} vs {}", s, t, back, s * total);
    }

    #[test]
    fn split_lengths_add_up(c in strategies::curve::<2>(), s in 0.05..0.95f64) {
        let t = c.domain().lerp(s);
        let [l, r] = c.split_at(t).unwrap();
        let (a, b, whole) = (l.arc_length(), r.arc_length(), c.arc_length());
        prop_assert!((a + b - whole).abs() <= 1e-9 * whole.max(1e-300), "{} + {} vs {}", a, b, whole);
    }

    #[test]
    fn closest_point_is_no_worse_than_sampling(c in strategies::curve::<2>(), p in proptest::array::uniform2(-15.0..15.0f64)) {
        let near = c.closest_point(p);
        prop_assert!((dist(&near.point, &p) - near.distance).abs() < 1e-12);
        let sampled = c.domain().uniform(2001).unwrap().into_iter().map(|t| dist(&c.eval(t).unwrap(), &p)).fold(f64::INFINITY, f64::min);
        prop_assert!(near.distance <= sampled + 1e-12, "{:?} vs sampled {}", near, sampled);
    }

    #[test]
    fn bounding_box_holds_the_curve_and_lies_in_the_control_box(c in strategies::curve::<3>()) {
        let b = c.bounding_box();
        for t in c.domain().uniform(2001).unwrap() {
            let p = c.eval(t).unwrap();
            prop_assert!(b.contains(&p, 1e-12), "{}: {:?} outside {:?}", t, p, b);
        }
        let lo = c.control_points().iter().fold([f64::INFINITY; 3], |m, p| std::array::from_fn(|d| m[d].min(p[d])));
        let hi = c.control_points().iter().fold([f64::NEG_INFINITY; 3], |m, p| std::array::from_fn(|d| m[d].max(p[d])));
        for d in 0..3 {
            prop_assert!(b.min[d] >= lo[d] - 1e-12 && b.max[d] <= hi[d] + 1e-12);
        }
    }

    #[test]
    fn tangent_is_a_unit_vector_along_the_first_derivative(c in strategies::curve::<2>(), s in 0.0..=1.0f64) {
        let t = c.domain().lerp(s);
        if let Ok(tangent) = c.tangent(t) {
            prop_assert!((tangent[0].hypot(tangent[1]) - 1.0).abs() < 1e-14);
            let d = c.derivatives(t, 1).unwrap()[1];
            let speed = d[0].hypot(d[1]);
            if speed > 1e-6 {
                prop_assert!((tangent[0] - d[0] / speed).abs() < 1e-14 && (tangent[1] - d[1] / speed).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn curvature_is_invariant_under_reparametrisation_by_splitting(c in strategies::curve::<2>(), s in 0.1..0.9f64, u in 0.0..=1.0f64) {
        // The pieces after a split have the same parameters, so curvature agrees.
        let t = c.domain().lerp(s);
        let [l, r] = c.split_at(t).unwrap();
        let x = c.domain().lerp(u);
        let piece = if x < t { &l } else { &r };
        if let (Ok(k1), Ok(k2)) = (c.curvature(x), piece.curvature(x)) {
            prop_assert!((k1 - k2).abs() <= 1e-6 * (1.0 + k1.abs()), "{} vs {}", k1, k2);
        }
    }

    #[test]
    fn insertion_then_elevation_keeps_the_curve(c in strategies::curve::<2>(), s in 0.0..=1.0f64, times in 1usize..3) {
        let u = c.domain().lerp(s);
        prop_assume!(c.knots().multiplicity(u) < c.order());
        let inserted = c.insert_knot(u, 1).unwrap();
        // Elevation (A5.9) loses accuracy as knots come close; see the
        // conditioning note of `NurbsCurve::elevate_degree`.
        let gap = 1e-4 * (c.domain().end - c.domain().start);
        prop_assume!(inserted.knots().as_slice().windows(2).all(|w| w[0] == w[1] || w[1] - w[0] >= gap));
        let d = inserted.elevate_degree(times).unwrap();
        let scale = c.control_points().iter().flatten().fold(1.0f64, |m, x| m.max(x.abs()));
        let tol = strategies::elevation_tolerance(inserted.knots(), c.weights(), scale);
        for t in c.domain().uniform(513).unwrap() {
            let (p, q) = (c.eval(t).unwrap(), d.eval(t).unwrap());
            prop_assert!(dist(&p, &q) <= tol, "t = {}: {:?} vs {:?}, tolerance {}", t, p, q, tol);
        }
    }
}
