//! Arc length of curves whose weights span orders of magnitude, against a
//! polyline through the curve's own points (a lower bound) and against an
//! independent reference: recursive subdivision of the curve by knot
//! insertion, where each piece's length lies between its chord and its
//! control polygon (the rational curve is the limit of its subdivided
//! polygons, each shorter than the last by the triangle inequality).

use t2spline::nurbs::LENGTH_TOLERANCE;
use t2spline::strategies::{seeded_uniform, test_size};
use t2spline::{Error, KnotVector, NurbsCurve};

/// A curve of degree `degree` through `n` control points on a random walk
/// (steps up to 1 in each coordinate), weights log-uniform in
/// `[10^-e, 10^e]`.
fn curve(n: usize, degree: usize, e: f64, seed: u64) -> NurbsCurve<2> {
    let mut r = seeded_uniform(seed);
    let mut at = [0.0, 0.0];
    let points = (0..n)
        .map(|_| {
            at = [at[0] + 2.0 * r() - 1.0, at[1] + 2.0 * r() - 1.0];
            at
        })
        .collect();
    let weights = (0..n).map(|_| 10f64.powf(e * (2.0 * r() - 1.0))).collect();
    NurbsCurve::try_clamped(degree, points, weights).unwrap()
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The length of a polygon.
fn polygon(points: &[[f64; 2]]) -> f64 {
    points.windows(2).map(|w| distance(w[0], w[1])).sum()
}

/// The length of the polyline through the curve at `n + 1` uniform
/// parameters: a lower bound of the arc length.
fn polyline(c: &NurbsCurve<2>, n: usize) -> f64 {
    let points: Vec<[f64; 2]> = c
        .domain()
        .uniform(n + 1)
        .unwrap()
        .into_iter()
        .map(|t| c.eval(t).unwrap())
        .collect();
    polygon(&points)
}

/// `(Σ chords, Σ polygons, Σ Gravesen estimates)` over pieces made by
/// halving until each piece's control polygon exceeds its chord by at most
/// `relative` times the length of the whole control polygon. Each knot span
/// is cut out first and given the parameters `[0, 1]`, so that halving is
/// not stopped by the resolution of a narrow span's parameters. The chords
/// and polygons bound the length; Gravesen's estimate
/// `(2·chord + (p − 1)·polygon)/(p + 1)` (J. Gravesen, *Comput. Aided Geom.
/// Des.* 14, 1997) converges much faster as the pieces shrink.
fn subdivision_length(c: &NurbsCurve<2>, relative: f64) -> (f64, f64, f64) {
    let p = c.degree() as f64;
    let tolerance = relative * polygon(c.control_points());
    let (mut chords, mut polygons, mut estimate) = (0.0, 0.0, 0.0);
    let mut stack: Vec<NurbsCurve<2>> = c
        .knots()
        .spans()
        .map(|(_, [a, b])| {
            let piece = c.segment(a, b).unwrap();
            let q = piece.control_points().to_vec();
            NurbsCurve::try_clamped(c.degree(), q, piece.weights().to_vec()).unwrap()
        })
        .collect();
    while let Some(piece) = stack.pop() {
        let q = piece.control_points();
        let chord = distance(q[0], q[q.len() - 1]);
        let polygon = polygon(q);
        let d = piece.domain();
        let mid = d.start + (d.end - d.start) / 2.0;
        if polygon - chord <= tolerance || !(d.start < mid && mid < d.end) {
            chords += chord;
            polygons += polygon;
            estimate += (2.0 * chord + (p - 1.0) * polygon) / (p + 1.0);
        } else {
            let [left, right] = piece.split_at(mid).unwrap();
            stack.push(left);
            stack.push(right);
        }
    }
    (chords, polygons, estimate)
}

#[test]
fn the_subdivision_reference_is_exact_on_closed_forms() {
    // The quarter circle, π/2, and the parabola through (0,0), (1,1), (2,0),
    // √2 + asinh(1).
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let circle = NurbsCurve::try_clamped(
        2,
        vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        vec![1.0, w, 1.0],
    )
    .unwrap();
    let parabola =
        NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], vec![1.0; 3]).unwrap();
    for (c, exact) in [
        (circle, std::f64::consts::FRAC_PI_2),
        (parabola, 2f64.sqrt() + 1f64.asinh()),
    ] {
        let (chords, polygons, estimate) = subdivision_length(&c, 1e-14);
        assert!(
            chords <= exact && exact <= polygons,
            "{chords} {exact} {polygons}"
        );
        assert!(
            (estimate / exact - 1.0).abs() < 1e-13,
            "{estimate} vs {exact}"
        );
    }
}

/// Checks `c.arc_length()` against the polyline bound, the subdivision
/// bounds and estimate, and `param_at_length` against `arc_length_between`.
fn check_length(c: &NurbsCurve<2>, what: &str) {
    let length = c.arc_length();
    let lower = polyline(c, 200_000);
    let (chords, polygons, estimate) = subdivision_length(c, 1e-14);
    let slack = 1.0 + LENGTH_TOLERANCE;
    assert!(
        length * slack >= lower,
        "{what}: {length} below the polyline's {lower}"
    );
    assert!(
        length * slack >= chords && length <= polygons * slack,
        "{what}: {length} outside [{chords}, {polygons}]"
    );
    assert!(
        (length / estimate - 1.0).abs() < LENGTH_TOLERANCE,
        "{what}: {length} vs the subdivision's {estimate}"
    );
    // Where the curve crosses from one control point to the next between two
    // adjacent floats, no parameter has the length asked for: then the
    // parameters next to t must bracket it.
    let d = c.domain();
    let tol = LENGTH_TOLERANCE * length;
    let up = |t: f64| f64::from_bits(t.to_bits() + 1).min(d.end);
    let down = |t: f64| f64::from_bits(t.to_bits() - 1).max(d.start);
    for s in [0.1, 0.5, 0.93] {
        let t = c.param_at_length(s * length).unwrap();
        let back = c.arc_length_between(d.start, t).unwrap();
        let before = c.arc_length_between(d.start, down(t)).unwrap();
        let after = c.arc_length_between(d.start, up(t)).unwrap();
        assert!(
            (back - s * length).abs() <= tol
                || (before - tol <= s * length && s * length <= after + tol),
            "{what}: L(a, t({s}·L)) = {back} ({before}, {after}) vs {}",
            s * length
        );
    }
}

/// Checks curves of 12 control points of each degree, seeds 1 to 3, with
/// weights in `[10^-e, 10^e]`.
/// Seeds 1 and 2 under `T2SPLINE_LONG_TESTS=1`, seed 1 (the curves the
/// comments below name) by default.
fn check_lengths(e: f64, degrees: &[usize]) {
    for &degree in degrees {
        for seed in 1..=test_size(1, 2) as u64 {
            let what = format!("degree {degree}, seed {seed}");
            check_length(&curve(12, degree, e, seed), &what);
        }
    }
}

#[test]
fn weights_from_1e_minus_3_to_1e3_give_the_full_length() {
    // Before, degree 1 came out 8% short of the polyline (6.37 against 6.95
    // for seed 1): the speed peaks within 10⁻⁶ of a knot, between the nodes.
    check_lengths(3.0, &[1, 2, 3]);
}

#[test]
fn weights_from_1e_minus_12_to_1e12_give_the_full_length() {
    // Before, 4.34 against the polyline's 4.67 (degree 3, seed 1).
    check_lengths(12.0, &[1, 3]);
}

#[test]
fn a_segment_within_a_span_of_1e_minus_14_is_measured() {
    // Knots of multiplicity 2 around [0.5, 0.5 + 1e-14]: a whole quadratic
    // segment, of length about 3, is traversed within a span only 90 floats
    // wide. Before, 6.1857 against 6.2043.
    let u = KnotVector::try_new(
        vec![
            0.0,
            0.0,
            0.0,
            0.5,
            0.5,
            0.5 + 1e-14,
            0.5 + 1e-14,
            1.0,
            1.0,
            1.0,
        ],
        2,
        7,
    )
    .unwrap();
    let points = vec![
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
        [2.0, 3.0],
        [3.0, 1.0],
        [4.0, 1.0],
        [4.0, 0.0],
    ];
    check_length(
        &NurbsCurve::try_new(points, vec![1.0; 7], u).unwrap(),
        "narrow span",
    );
}

#[test]
fn lengths_within_rounding_of_the_total_give_the_ends() {
    let c = curve(8, 2, 1.0, 5);
    let (d, total) = (c.domain(), c.arc_length());
    assert_eq!(c.param_at_length(total).unwrap(), d.end);
    assert_eq!(c.param_at_length(total * (1.0 + 1e-12)).unwrap(), d.end);
    assert_eq!(c.param_at_length(-1e-12 * total).unwrap(), d.start);
    for outside in [total * (1.0 + 1e-9), -1e-9 * total, f64::NAN] {
        assert!(
            matches!(c.param_at_length(outside), Err(Error::LengthOutside { .. })),
            "{outside}"
        );
    }
}
