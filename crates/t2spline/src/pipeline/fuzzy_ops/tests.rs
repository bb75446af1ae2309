//! Fuzzy operations: valid results, unchanged geometry in every layer and every
//! stage, and no repair of the order beyond rounding.

use proptest::prelude::*;

use super::*;
use crate::fuzzy::Alpha;
use crate::nurbs::NurbsCurve;
use crate::strategies;

/// The largest absolute value of any layer coordinate: the scale of rounding.
fn scale<const D: usize>(c: &FuzzyCurve<D>) -> f64 {
    c.points()
        .iter()
        .flat_map(|p| Layer::ALL.map(|l| p.layer(l)))
        .flatten()
        .fold(1.0, |m, x| m.max(x.abs()))
}

/// Every layer curve and the stage 2–4 curves at `alpha` agree at 257 t.
fn assert_same_geometry<const D: usize>(
    a: &FuzzyCurve<D>,
    b: &FuzzyCurve<D>,
    alpha: Alpha,
) -> Result<(), TestCaseError> {
    assert_same_geometry_within(a, b, alpha, 1e-12 * scale(a))
}

/// [`assert_same_geometry`] with tolerance `tol`.
fn assert_same_geometry_within<const D: usize>(
    a: &FuzzyCurve<D>,
    b: &FuzzyCurve<D>,
    alpha: Alpha,
    tol: f64,
) -> Result<(), TestCaseError> {
    let (sa, sb) = (a.solve(alpha), b.solve(alpha));
    let (da, db) = (sa.defuzzified_curve(), sb.defuzzified_curve());
    for t in a.domain().uniform(257).unwrap() {
        let (la, lb) = (a.eval_layers(t).unwrap(), b.eval_layers(t).unwrap());
        for l in Layer::ALL {
            for d in 0..D {
                prop_assert!(
                    (la[l][d] - lb[l][d]).abs() <= tol,
                    "t = {}, {}: {:?} vs {:?}",
                    t,
                    l,
                    la[l],
                    lb[l]
                );
            }
        }
        let (pa, pb) = (da.eval(t).unwrap(), db.eval(t).unwrap());
        for d in 0..D {
            prop_assert!(
                (pa[d] - pb[d]).abs() <= tol,
                "defuzzified at {}: {:?} vs {:?}",
                t,
                pa,
                pb
            );
        }
    }
    Ok(())
}

/// The crisp layer of `fuzzy` is bit for bit `crisp`.
fn assert_crisp_layer<const D: usize>(
    fuzzy: &FuzzyCurve<D>,
    crisp: &NurbsCurve<D>,
) -> Result<(), TestCaseError> {
    prop_assert_eq!(fuzzy.knots(), crisp.knots());
    prop_assert_eq!(fuzzy.weights(), crisp.weights());
    let points: Vec<[f64; D]> = fuzzy.points().iter().map(|p| p.crisp()).collect();
    prop_assert_eq!(points.as_slice(), crisp.control_points());
    Ok(())
}

/// Whether distinct knots are at least `1e-4` of the domain apart: degree
/// elevation (A5.9) removes knots, which loses accuracy in proportion to the
/// inverse gap between neighbouring knots (see `degree_elevation.rs`).
fn well_separated(u: &KnotVector) -> bool {
    let d = u.domain();
    let gap = 1e-4 * (d.end - d.start);
    u.as_slice()
        .windows(2)
        .all(|w| w[0] == w[1] || w[1] - w[0] >= gap)
}

/// A parameter in the domain, often an existing knot.
fn param<const D: usize>(c: &FuzzyCurve<D>, s: f64, pick: usize) -> f64 {
    let u = c.knots().as_slice();
    let candidate = u[pick % u.len()];
    if pick % 3 == 0 && c.domain().contains(candidate) {
        candidate
    } else {
        c.domain().lerp(s)
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn insertion_keeps_order_and_geometry(
        c in strategies::fuzzy_curve_common_height::<2>(),
        s in 0.0..=1.0f64, pick in 0usize..40, times in 1usize..4, a in 0.0..=1.0f64,
    ) {
        let u = param(&c, s, pick);
        let room = c.order() - c.knots().multiplicity(u);
        let times = times.min(room);
        let (d, repaired) = c.map_rows(|k, r| insert(k, r, u, times)).unwrap();
        prop_assert_eq!(repaired, 0.0);
        assert_crisp_layer(&d, &c.crisp_curve().insert_knot(u, times).unwrap())?;
        assert_same_geometry(&c, &d, Alpha::try_new(a).unwrap())?;
    }

    #[test]
    fn refinement_keeps_order_and_geometry(
        c in strategies::fuzzy_curve_common_height::<3>(),
        s in proptest::collection::vec(0.0..=1.0f64, 1..6), a in 0.0..=1.0f64,
    ) {
        let mut x: Vec<f64> = s.iter().map(|&s| c.domain().lerp(s)).collect();
        x.retain(|&u| c.knots().multiplicity(u) < c.order());
        x.dedup();
        let (d, repaired) = c.map_rows(|k, r| refine(k, r, &x)).unwrap();
        prop_assert_eq!(repaired, 0.0);
        assert_crisp_layer(&d, &c.crisp_curve().refine_knots(&x).unwrap())?;
        assert_same_geometry(&c, &d, Alpha::try_new(a).unwrap())?;
    }

    #[test]
    fn splitting_keeps_order_and_geometry(
        c in strategies::fuzzy_curve_common_height::<2>(),
        s in 0.01..0.99f64, pick in 0usize..40, a in 0.0..=1.0f64,
    ) {
        let t = param(&c, s, pick);
        let domain = c.domain();
        prop_assume!(domain.start < t && t < domain.end);
        let [left, right] = c.split_at(t).unwrap();
        let [cl, cr] = c.crisp_curve().split_at(t).unwrap();
        assert_crisp_layer(&left, &cl)?;
        assert_crisp_layer(&right, &cr)?;
        let (_, repaired) = c.map_rows(|k, r| segment(k, r, domain.start, t)).unwrap();
        prop_assert_eq!(repaired, 0.0);
        let tol = 1e-12 * scale(&c);
        let alpha = Alpha::try_new(a).unwrap();
        let (whole, l, r) = (c.solve(alpha).defuzzified_curve(), left.solve(alpha).defuzzified_curve(), right.solve(alpha).defuzzified_curve());
        for x in domain.uniform(129).unwrap() {
            let piece = if x < t { (&left, &l) } else { (&right, &r) };
            let (la, lb) = (c.eval_layers(x).unwrap(), piece.0.eval_layers(x).unwrap());
            for layer in Layer::ALL {
                for d in 0..2 {
                    prop_assert!((la[layer][d] - lb[layer][d]).abs() <= tol, "x = {}, {}", x, layer);
                }
            }
            let (pa, pb) = (whole.eval(x).unwrap(), piece.1.eval(x).unwrap());
            prop_assert!((pa[0] - pb[0]).abs() <= tol && (pa[1] - pb[1]).abs() <= tol);
        }
    }

    #[test]
    fn elevation_keeps_order_and_geometry(
        c in strategies::fuzzy_curve_common_height::<2>(), times in 1usize..3, a in 0.0..=1.0f64,
    ) {
        prop_assume!(well_separated(c.knots()));
        let (d, repaired) = c.map_rows(|k, r| Ok(elevate(k, r, times))).unwrap();
        let tol = strategies::elevation_tolerance(c.knots(), c.weights(), scale(&c));
        prop_assert!(repaired <= tol, "repaired {} > {}", repaired, tol);
        prop_assert_eq!(d.degree(), c.degree() + times);
        assert_crisp_layer(&d, &c.crisp_curve().elevate_degree(times).unwrap())?;
        assert_same_geometry_within(&c, &d, Alpha::try_new(a).unwrap(), tol)?;
    }

    #[test]
    fn bounding_box_comes_from_the_outer_layers(c in strategies::fuzzy_curve::<2>()) {
        let b = c.bounding_box();
        let lo = c.layer_curve(Layer::UpperLeft).bounding_box();
        let hi = c.layer_curve(Layer::UpperRight).bounding_box();
        prop_assert_eq!(b.min, lo.min);
        prop_assert_eq!(b.max, hi.max);
    }
}

#[test]
fn mixed_heights_are_refused_with_their_place() {
    let n = |c: f64, h: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c, c], [c, c], h).unwrap();
    let points = vec![
        Nt2Point::new([n(0.0, 0.5), n(0.0, 0.5)]),
        Nt2Point::new([n(1.0, 0.5), n(1.0, 0.5)]),
        Nt2Point::new([n(2.0, 0.5), n(1.0, 0.9)]),
    ];
    let c = FuzzyCurve::try_new(1, points, vec![1.0; 3], None).unwrap();
    let e = c.elevate_degree(1).unwrap_err();
    assert_eq!(
        e,
        Error::MixedHeights {
            place: Place::new(2, Axis::Y),
            height: 0.9,
            expected: 0.5
        }
    );
    assert!(c.split_at(0.5).is_err() && c.refine_knots(&[0.2]).is_err());
    // Derivatives, lengths and boxes need no new control points.
    assert!(c.derivatives(0.5, 3).is_ok());
    assert!(c.arc_lengths()[Layer::Crisp] > 0.0);
}

#[test]
fn order_repair_clamps_outward_from_crisp() {
    let mut v = Layers::from_fn(|l| l.index() as f64);
    v[Layer::LowerLeft] = 3.0 + 1e-16 * 4.0;
    v[Layer::PrimaryRight] = 4.0 - 1e-15;
    let worst = repair_order(&mut v);
    assert_eq!(v[Layer::LowerLeft], 3.0);
    assert_eq!(v[Layer::PrimaryRight], 4.0);
    assert!(worst > 0.0 && worst < 1e-14);
}
