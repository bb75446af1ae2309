//! Closed curves (docs/method.md §11): the periodic construction and the
//! clamped one both close; an enclosed area is positive whichever way the
//! curve runs; a curve that closes in its crisp layer only is closed by the
//! chord between its ends, and says so. The reference is brute force: the
//! shoelace formula on the polygon of 20 000 points of each admissible
//! curve (which is closed by the chord from its last point to its first).

use t2spline::measure::{AreaKind, MeasureOptions};
use t2spline::strategies::seeded_uniform;
use t2spline::{Alpha, Error, FuzzyCurve, Membership, Nt2Number, Nt2Point, NurbsCurve};

fn alpha(a: f64) -> Alpha {
    Alpha::try_new(a).expect("a level")
}

/// A number around `c` with spreads `s`, `s/2`, `s/4`.
fn number(c: f64, s: f64) -> Nt2Number {
    Nt2Number::try_new(
        c,
        [c - s, c + s],
        [c - s / 2.0, c + s / 2.0],
        [c - s / 4.0, c + s / 4.0],
        0.8,
    )
    .expect("a number")
}

/// The usual periodic construction: `n` points on the circle of radius 5
/// (clockwise when `clockwise`), the first `p` repeated at the end, uniform
/// unclamped knots; every coordinate spread `s`.
fn periodic_circle(n: usize, p: usize, s: f64, clockwise: bool) -> FuzzyCurve<2> {
    let sign = if clockwise { -1.0 } else { 1.0 };
    let mut points: Vec<Nt2Point<2>> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            Nt2Point::new([number(5.0 * t.cos(), s), number(sign * 5.0 * t.sin(), s)])
        })
        .collect();
    points.extend(points[..p].to_vec());
    let m = points.len();
    let knots = (0..m + p + 1).map(|k| k as f64).collect();
    FuzzyCurve::try_new(p, points, vec![1.0; m], Some(knots)).expect("a curve")
}

/// The signed area of the polygon of 20 000 points of `c`, closed by the
/// chord from its last point to its first.
fn shoelace(c: &NurbsCurve<2>) -> f64 {
    let d = c.domain();
    let n = 20_000;
    let pts: Vec<[f64; 2]> = (0..=n)
        .map(|i| {
            c.eval(d.start + (d.end - d.start) * i as f64 / n as f64)
                .expect("inside")
        })
        .collect();
    let mut sum = 0.0;
    for (i, a) in pts.iter().enumerate() {
        let b = pts[(i + 1) % pts.len()];
        sum += a[0] * b[1] - a[1] * b[0];
    }
    0.5 * sum
}

/// An admissible crisp curve under `m` at `a`: each value drawn in its cut
/// (at an end with `vertex`); the last `wrap` points copy the first when
/// they are one point.
fn admissible(
    c: &FuzzyCurve<2>,
    m: Membership,
    a: Alpha,
    wrap: usize,
    draw: &mut impl FnMut() -> f64,
    vertex: bool,
) -> NurbsCurve<2> {
    let n = c.points().len();
    let mut points: Vec<[f64; 2]> = Vec::with_capacity(n);
    for (i, p) in c.points().iter().enumerate() {
        if i + wrap >= n {
            points.push(points[i + wrap - n]);
            continue;
        }
        points.push(std::array::from_fn(|k| {
            let cut = p.coords()[k].alpha_cut(a);
            let iv = match m {
                Membership::Upper => cut.upper(),
                Membership::Primary => cut.primary(),
                Membership::Lower => cut.lower().expect("a cut"),
            };
            let t = if vertex { draw().round() } else { draw() };
            iv.left() + t * (iv.right() - iv.left())
        }));
    }
    NurbsCurve::try_new(points, c.weights().to_vec(), c.knots().clone()).expect("valid")
}

#[test]
fn the_periodic_construction_encloses_a_positive_area_either_way() {
    for clockwise in [false, true] {
        let crisp = periodic_circle(8, 3, 0.0, clockwise);
        let closure = crisp.closure().expect("it closes");
        assert_eq!((closure.wrap, closure.merged), (3, true));
        assert_eq!(crisp.area_kind(), AreaKind::Enclosed);
        let b = crisp
            .area_bracket(Membership::Upper, alpha(0.5))
            .expect("a cut");
        let truth = shoelace(&crisp.crisp_curve()).abs();
        assert!(truth > 60.0, "{truth}");
        assert!(
            (b.min - truth).abs() <= 1e-7 * truth && (b.max - truth).abs() <= 1e-7 * truth,
            "{b:?} vs {truth}"
        );
    }
}

#[test]
fn admissible_closed_curves_lie_inside_the_enclosed_area() {
    let mut draw = seeded_uniform(7);
    // Periodic, wrapped points one point; and clamped with the last point's
    // spreads wider than the first's (closed in the crisp layer only).
    let periodic = periodic_circle(7, 2, 0.4, true);
    let mut clamped_points: Vec<Nt2Point<2>> = (0..9)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 8.0;
            Nt2Point::new([number(4.0 * t.cos(), 0.3), number(4.0 * t.sin(), 0.3)])
        })
        .collect();
    clamped_points[8] = Nt2Point::new([number(4.0, 0.5), number(0.0, 0.5)]);
    let clamped = FuzzyCurve::try_new(2, clamped_points, vec![1.0; 9], None).expect("a curve");
    let closure = clamped.closure().expect("closes in the crisp layer");
    assert!(!closure.merged && closure.note().is_some(), "{closure:?}");
    let m = clamped
        .measure(&MeasureOptions::uniform(3).expect("levels"))
        .expect("measured");
    let area = m.area.expect("a plane curve");
    assert_eq!(area.kind, AreaKind::Enclosed);
    assert!(area.note.expect("a note").contains("chord"));
    for (c, wrap) in [(&periodic, 2), (&clamped, 0)] {
        let sign = shoelace(&c.crisp_curve()).signum();
        for m in [Membership::Upper, Membership::Primary, Membership::Lower] {
            for a in [0.0, 0.5, 0.8] {
                let b = c.area_bracket(m, alpha(a)).expect("a cut");
                assert!(b.min > 0.0, "{b:?}");
                for k in 0..12 {
                    let net = admissible(c, m, alpha(a), wrap, &mut draw, k % 3 == 0);
                    let s = sign * shoelace(&net);
                    assert!(b.holds(s, 1e-6), "{m:?} {a}: {s} outside {b:?}");
                }
            }
        }
    }
}

#[test]
fn closed_is_asked_or_declined() {
    let line = FuzzyCurve::try_new(
        1,
        vec![
            Nt2Point::new([number(0.0, 0.1), number(0.0, 0.1)]),
            Nt2Point::new([number(1.0, 0.1), number(0.0, 0.1)]),
            Nt2Point::new([number(1.0, 0.1), number(1.0, 0.1)]),
        ],
        vec![1.0; 3],
        None,
    )
    .expect("a curve");
    let o = MeasureOptions::uniform(2).expect("levels");
    let o = o.closed(Some(true));
    let e = line.measure(&o).expect_err("open");
    assert!(matches!(e, Error::NotClosed { .. }), "{e}");
    assert_eq!(
        e.to_string(),
        "the curve does not close: it starts at (0, 0) and ends at (1, 1)"
    );
    // A closed curve measured as open: the area under it.
    let circle = periodic_circle(8, 3, 0.2, false);
    let o = o.closed(Some(false));
    let m = circle.measure(&o).expect("measured");
    assert_eq!(m.area.expect("plane").kind, AreaKind::Under);
    let o = o.closed(None);
    let m = circle.measure(&o).expect("measured");
    let area = m.area.expect("plane");
    assert_eq!(area.kind, AreaKind::Enclosed);
    assert!(area.note.is_none());
}
