//! The fuzzy curve as a set (docs/method.md §10): membership grades against a
//! brute-force scan of the fuzzy point at each parameter, regions against
//! their boxes, the facts of the definition, and closed-form cases.

use proptest::prelude::*;
use t2spline::set::{Grades, MEMBERSHIPS};
use t2spline::{Alpha, FuzzyCurve, Layer, Membership, Nt2Number, Nt2Point};

const H: f64 = 0.6;

/// The shipped example (`examples/paper-alg-1-1.json`).
fn example() -> FuzzyCurve<2> {
    t2spline::strategies::paper_example()
}

fn alpha(a: f64) -> Alpha {
    Alpha::try_new(a).expect("a level")
}

/// The independent reference: the fuzzy point of the curve at each of many
/// parameters (stage 1's evaluation, numbers with one height) and the
/// triangles of docs/method.md §1, `max over t of min over c`.
fn brute<const D: usize>(curve: &FuzzyCurve<D>, p: &[f64; D], steps: usize) -> [f64; 3] {
    let d = curve.domain();
    let mut best = [0.0_f64; 3];
    for j in 0..=steps {
        let t = d.lerp(j as f64 / steps as f64);
        let at = curve.eval(t).expect("in the domain").expect("one height");
        for (k, m) in MEMBERSHIPS.iter().enumerate() {
            let g = at
                .coords()
                .iter()
                .zip(p)
                .map(|(x, &v)| x.membership(*m, v))
                .fold(f64::INFINITY, f64::min);
            best[k] = best[k].max(g);
        }
    }
    best
}

fn as_array(g: Grades) -> [f64; 3] {
    [g.upper, g.primary, g.lower]
}

#[test]
fn grades_of_the_example_match_a_dense_scan() {
    let c = example();
    let mut random = t2spline::strategies::seeded_uniform(7);
    for _ in 0..24 {
        let p = [0.0 + 7.5 * random(), 0.0 + 5.5 * random()];
        let fast = as_array(c.membership(&p).expect("finite"));
        let slow = brute(&c, &p, 20_000);
        for k in 0..3 {
            // The scan can only fall short of the sup, by at most the grade's
            // change over half a step (below 1e-3 here).
            assert!(fast[k] >= slow[k] - 1e-12, "{p:?} {k}: {fast:?} < {slow:?}");
            assert!(fast[k] <= slow[k] + 1e-3, "{p:?} {k}: {fast:?} > {slow:?}");
        }
    }
}

#[test]
fn crisp_points_have_grades_one_one_h() {
    let c = example();
    let crisp = c.crisp_curve();
    for j in 0..=50 {
        let p = crisp.eval(j as f64 / 50.0).expect("in the domain");
        let g = c.membership(&p).expect("finite");
        assert!(
            (g.upper - 1.0).abs() < 1e-9 && (g.primary - 1.0).abs() < 1e-9,
            "{g:?}"
        );
        assert!((g.lower - H).abs() < 1e-9, "{g:?}");
    }
}

#[test]
fn grades_of_a_far_point_are_zero() {
    let g = example().membership(&[100.0, -3.0]).expect("finite");
    assert_eq!(as_array(g), [0.0; 3]);
}

#[test]
fn a_bad_query_point_is_named() {
    let e = example()
        .memberships(&[[1.0, 1.0], [f64::INFINITY, 0.0]])
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "query point 1: x = inf is not a finite number"
    );
}

#[test]
fn the_example_region_holds_every_box_and_nothing_far_from_one() {
    let c = example();
    for (m, a) in [
        (Membership::Upper, 0.0),
        (Membership::Primary, 0.5),
        (Membership::Lower, 0.3),
    ] {
        let r = c
            .region(m, alpha(a), None)
            .expect("a region")
            .expect("a cut");
        let s = c.solve(alpha(a));
        let (left, right) = match m {
            Membership::Upper => (Layer::UpperLeft, Layer::UpperRight),
            Membership::Primary => (Layer::PrimaryLeft, Layer::PrimaryRight),
            Membership::Lower => (Layer::LowerLeft, Layer::LowerRight),
        };
        let (l, rr) = (
            s.alpha_cut_curve(left).expect("cut"),
            s.alpha_cut_curve(right).expect("cut"),
        );
        // Every box corner (and centre) of 2001 parameters lies inside.
        let mut boxes = Vec::new();
        for j in 0..=2000 {
            let t = j as f64 / 2000.0;
            let (a, b) = (l.eval(t).expect("in"), rr.eval(t).expect("in"));
            for p in [
                [a[0], a[1]],
                [a[0], b[1]],
                [b[0], a[1]],
                [b[0], b[1]],
                [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])],
            ] {
                assert!(r.contains(p), "{m:?} {t}: {p:?} outside");
            }
            boxes.push((a, b));
        }
        // Every vertex of the outline (every 7th) lies within the tolerance of
        // some box: the distance to the box at t, scanned over the 2001
        // parameters and refined by ternary search around the nearest.
        let gap = |a: [f64; 2], b: [f64; 2], v: &[f64; 2]| {
            let dx = (a[0] - v[0]).max(v[0] - b[0]).max(0.0);
            let dy = (a[1] - v[1]).max(v[1] - b[1]).max(0.0);
            dx.hypot(dy)
        };
        let at = |t: f64, v: &[f64; 2]| gap(l.eval(t).expect("in"), rr.eval(t).expect("in"), v);
        for g in r.polygons() {
            for v in g.exterior.iter().chain(g.holes.iter().flatten()).step_by(7) {
                let (k, _) = boxes
                    .iter()
                    .enumerate()
                    .map(|(k, (a, b))| (k, gap(*a, *b, v)))
                    .fold((0, f64::INFINITY), |m, x| if x.1 < m.1 { x } else { m });
                let (mut lo, mut hi) = (
                    (k.max(1) - 1) as f64 / 2000.0,
                    ((k + 1).min(2000)) as f64 / 2000.0,
                );
                for _ in 0..60 {
                    let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
                    if at(m1, v) <= at(m2, v) {
                        hi = m2
                    } else {
                        lo = m1
                    }
                }
                let near = at(0.5 * (lo + hi), v);
                assert!(
                    near <= r.tolerance(),
                    "{m:?}: {v:?} is {near} from every box"
                );
            }
        }
    }
}

#[test]
fn the_example_upper_region_at_zero_has_the_area_of_its_boxes() {
    // The union of the boxes has area 18.9186 (the band between the upper
    // layer curves has 10.14); the outline, within
    // 6e-6 of it, adds at most its perimeter (about 25) times that.
    let r = example()
        .region(Membership::Upper, Alpha::ZERO, None)
        .expect("a region")
        .expect("a cut");
    assert_eq!(r.polygons().len(), 1);
    assert!((r.area() - 18.9186).abs() < 2e-4, "{}", r.area());
}

#[test]
fn regions_shrink_as_alpha_grows_and_vanish_into_the_curve() {
    let c = example();
    let mut last = f64::INFINITY;
    for a in [0.0, 0.2, 0.4, 0.6, 0.8, 1.0] {
        let r = c
            .region(Membership::Upper, alpha(a), None)
            .expect("ok")
            .expect("cut");
        assert!(r.area() < last, "{a}: {} ≥ {last}", r.area());
        last = r.area();
    }
    // At alpha 1 only the band of the tolerance around the crisp curve (length 8.95).
    assert!(last < 8.95 * 2.0 * c.default_tolerance(), "{last}");
    // The lower function has no cut above h.
    assert!(c
        .region(Membership::Lower, alpha(0.7), None)
        .expect("ok")
        .is_none());
}

/// The unit circle as a rational quadratic of 9 control points (The NURBS
/// Book, Ex. 7.2), each coordinate ±0.1 at level 0 (±0.05 primary, ±0.02
/// lower with height 0.5): its region is a ring of radii about 0.9 and 1.1.
fn fuzzy_circle() -> FuzzyCurve<2> {
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let square = [
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
    let n = |c: f64| {
        Nt2Number::try_new(
            c,
            [c - 0.1, c + 0.1],
            [c - 0.05, c + 0.05],
            [c - 0.02, c + 0.02],
            0.5,
        )
        .expect("valid")
    };
    let points = square
        .iter()
        .map(|p| Nt2Point::new([n(p[0]), n(p[1])]))
        .collect();
    let weights = vec![1.0, s, 1.0, s, 1.0, s, 1.0, s, 1.0];
    let knots = vec![
        0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
    ];
    FuzzyCurve::try_new(2, points, weights, Some(knots)).expect("valid")
}

#[test]
fn a_closed_curve_has_an_annulus() {
    let circle = fuzzy_circle();
    let r = circle
        .region(Membership::Upper, Alpha::ZERO, None)
        .expect("ok")
        .expect("cut");
    assert_eq!(r.polygons().len(), 1);
    assert_eq!(r.polygons()[0].holes.len(), 1, "an annulus");
    assert!(!r.contains([0.0, 0.0]) && !r.contains([0.5, 0.5]));
    assert!(r.contains([1.0, 0.0]) && r.contains([0.0, -1.05]));
    // The membership agrees: the centre is in no box, the circle in all.
    assert_eq!(circle.membership(&[0.0, 0.0]).expect("finite").upper, 0.0);
    assert!((circle.membership(&[0.0, 1.0]).expect("finite").upper - 1.0).abs() < 1e-9);
}

#[test]
fn crisp_numbers_give_the_curve_itself() {
    let n = |c: f64| Nt2Number::try_crisp(c).expect("valid");
    let points = vec![
        Nt2Point::new([n(0.0), n(0.0)]),
        Nt2Point::new([n(1.0), n(2.0)]),
        Nt2Point::new([n(3.0), n(0.0)]),
    ];
    let c = FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 1.0], None).expect("valid");
    let r = c
        .region(Membership::Upper, Alpha::ZERO, None)
        .expect("ok")
        .expect("cut");
    // A band of the tolerance's width around a curve of length below 5.
    assert!(r.area() < 5.0 * 2.0 * r.tolerance(), "{}", r.area());
    let on = c.crisp_curve().eval(0.3).expect("in");
    assert!(r.contains(on));
    assert!(!r.contains([on[0], on[1] + 10.0 * r.tolerance()]));
}

/// A polyline of degree 1 along the x axis through points of heights 0.9,
/// 0.9 and 0.4: the first span counts points 0 and 1, the second 1 and 2.
fn two_heights() -> FuzzyCurve<2> {
    let n = |c: f64, h: f64| {
        Nt2Number::try_new(
            c,
            [c - 1.0, c + 1.0],
            [c - 0.5, c + 0.5],
            [c - 0.2, c + 0.2],
            h,
        )
        .expect("valid")
    };
    let points = vec![
        Nt2Point::new([n(0.0, 0.9), n(0.0, 0.9)]),
        Nt2Point::new([n(1.0, 0.9), n(0.0, 0.9)]),
        Nt2Point::new([n(2.0, 0.4), n(0.0, 0.4)]),
    ];
    FuzzyCurve::try_new(1, points, vec![1.0; 3], None).expect("valid")
}

#[test]
fn per_number_heights_cap_the_lower_grade_by_the_points_that_count() {
    let c = two_heights();
    let g = |x: f64| c.membership(&[x, 0.0]).expect("finite").lower;
    assert!((g(0.5) - 0.9).abs() < 1e-12, "{}", g(0.5));
    // x = 1.1: the first span's box at t = 1/2 reaches it up to
    // 0.2·(1 − alpha/0.9) = 0.1, alpha = 0.45; the second span caps at 0.4.
    assert!((g(1.1) - 0.45).abs() < 1e-9, "{}", g(1.1));
    assert!((g(1.5) - 0.4).abs() < 1e-12, "{}", g(1.5));
    // At level 0.6 the lower region is the first span's only.
    let r = c
        .region(Membership::Lower, alpha(0.6), None)
        .expect("ok")
        .expect("cut");
    assert!(r.contains([0.5, 0.0]) && !r.contains([1.9, 0.0]));
}

#[test]
fn a_space_curve_projects_onto_its_planes() {
    let n = |c: f64| {
        Nt2Number::try_new(c, [c - 0.5, c + 0.5], [c - 0.25, c + 0.25], [c, c], 1.0).expect("valid")
    };
    let points = vec![
        Nt2Point::new([n(0.0), n(0.0), n(0.0)]),
        Nt2Point::new([n(2.0), n(1.0), n(4.0)]),
    ];
    let c = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None).expect("valid");
    let [xy, xz, yz] = c
        .region_projections(Membership::Upper, Alpha::ZERO, Some(1e-6))
        .expect("ok")
        .map(|r| r.expect("cut").area());
    // Boxes of side 1 sliding along a segment: side² + side·(|Δa| + |Δb|).
    // The outline, grown by at most 1e-6, adds at most its perimeter times that.
    assert!((xy - (1.0 + 3.0)).abs() < 2e-5, "{xy}");
    assert!((xz - (1.0 + 6.0)).abs() < 2e-5, "{xz}");
    assert!((yz - (1.0 + 5.0)).abs() < 2e-5, "{yz}");
}

#[test]
fn sections_of_the_example_nest_and_meet_the_membership() {
    let c = example();
    let levels: Vec<Alpha> = (0..=10).map(|k| alpha(k as f64 / 10.0)).collect();
    let s = c.sections(3.0, &levels, None).expect("ok");
    let mut last: Option<Vec<[f64; 2]>> = None;
    for level in &s {
        let up = level.upper.as_ref().expect("a cut");
        if let Some(prev) = &last {
            for iv in up {
                assert!(
                    prev.iter()
                        .any(|p| p[0] <= iv[0] + 1e-9 && iv[1] <= p[1] + 1e-9),
                    "nesting"
                );
            }
        }
        // The ends of each interval have the grade of the level.
        for iv in up {
            for y in *iv {
                let g = c.membership(&[3.0, y]).expect("finite").upper;
                assert!(
                    (g - level.alpha).abs() < 1e-4,
                    "{} at y = {y}: {g}",
                    level.alpha
                );
            }
        }
        last = Some(up.clone());
        assert_eq!(level.lower.is_some(), level.alpha <= H);
    }
}

#[test]
fn the_membership_grid_agrees_with_the_point_grades() {
    let c = example();
    let g = c
        .membership_grid([0.0, 7.5], [0.0, 5.5], [150, 110])
        .expect("ok");
    let mut worst = 0.0_f64;
    for j in (0..110).step_by(7) {
        for i in (0..150).step_by(7) {
            let exact = c.membership(&[g.xs[i], g.ys[j]]).expect("finite");
            let k = j * 150 + i;
            worst = worst
                .max((g.upper[k] - exact.upper).abs())
                .max((g.lower[k] - exact.lower).abs());
        }
    }
    // To within the grade's change over half a cell (0.025 wide).
    assert!(worst < 0.05, "{worst}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn grades_are_ordered_and_match_the_scan(
        c in t2spline::strategies::fuzzy_curve_common_height::<2>(),
        s in 0.0..1.0_f64, dx in -1.0..1.0_f64, dy in -1.0..1.0_f64,
    ) {
        let t = c.domain().lerp(s);
        let at = c.eval_layers(t).expect("in");
        let (lo, hi) = (at[Layer::UpperLeft], at[Layer::UpperRight]);
        let p = [at[Layer::Crisp][0] + dx * (hi[0] - lo[0]), at[Layer::Crisp][1] + dy * (hi[1] - lo[1])];
        let g = c.membership(&p).expect("finite");
        prop_assert!(g.lower <= g.primary && g.primary <= g.upper && g.upper <= 1.0 && g.lower >= 0.0);
        let slow = brute(&c, &p, 2000);
        for (k, fast) in as_array(g).into_iter().enumerate() {
            prop_assert!(fast >= slow[k] - 1e-9, "{k}: {fast} < {}", slow[k]);
        }
    }
}

#[test]
fn a_region_section_is_the_station_section_and_crosses_an_annulus_twice() {
    // At x = 0 the ring is met twice: y in about [-1.1, -0.9] and [0.9, 1.1].
    let circle = fuzzy_circle();
    let r = circle
        .region(Membership::Upper, Alpha::ZERO, None)
        .expect("ok")
        .expect("cut");
    let cut = r.section(0.0);
    assert_eq!(cut.len(), 2, "{cut:?}");
    let station = circle.sections(0.0, &[Alpha::ZERO], None).expect("ok");
    let exact = station[0].upper.as_ref().expect("a cut");
    assert_eq!(exact.len(), 2, "{exact:?}");
    for (outline, exact) in cut.iter().zip(exact) {
        // The outline holds the region and lies within the tolerance of it.
        assert!(outline[0] <= exact[0] + 1e-12 && exact[1] <= outline[1] + 1e-12);
        assert!(exact[0] - outline[0] <= r.tolerance() && outline[1] - exact[1] <= r.tolerance());
        assert!(r.contains([0.0, 0.5 * (outline[0] + outline[1])]));
    }
    assert!(!r.contains([0.0, 0.0]));
    // A line that misses the region meets nothing.
    assert!(r.section(5.0).is_empty());
}

#[test]
fn the_top_of_each_membership_function_is_its_largest_level_with_a_cut() {
    let c = example();
    assert_eq!(c.membership_top(Membership::Upper), 1.0);
    assert_eq!(c.membership_top(Membership::Primary), 1.0);
    assert_eq!(c.membership_top(Membership::Lower), H);
    // Per-number heights: spans whose least heights are 0.9 and 0.4; the
    // lower function has cuts up to 0.9.
    let c = two_heights();
    assert_eq!(c.membership_top(Membership::Lower), 0.9);
    assert!(c
        .region(Membership::Lower, alpha(0.9), None)
        .expect("ok")
        .is_some());
    assert!(c
        .region(Membership::Lower, alpha(0.95), None)
        .expect("ok")
        .is_none());
}

#[test]
fn a_tolerance_coarser_than_the_curve_is_refused_at_every_scale() {
    let mut unit_areas = Vec::new();
    for scale in [1e-140, 1.0, 1e140] {
        let scaled = |c: f64| c * scale;
        let n = |c: f64| {
            Nt2Number::try_new(
                scaled(c),
                [scaled(c - 1.0), scaled(c + 1.0)],
                [scaled(c - 0.5), scaled(c + 0.5)],
                [scaled(c - 0.25), scaled(c + 0.25)],
                0.5,
            )
            .unwrap()
        };
        let c = FuzzyCurve::try_new(
            1,
            vec![
                Nt2Point::new([n(0.0), n(0.0)]),
                Nt2Point::new([n(4.0), n(3.0)]),
            ],
            vec![1.0, 1.0],
            None,
        )
        .unwrap();
        // The box of the upper cuts at level 0 is 6 × 5 (times the scale).
        let most = 6.0 * scale * (1.0 - 1e-12);
        let e = c
            .region(Membership::Upper, alpha(0.5), Some(most * 1.5))
            .unwrap_err();
        assert!(
            matches!(e, t2spline::Error::ToleranceTooCoarse { .. }),
            "{e}"
        );
        let e = c.section(scaled(2.0), Membership::Upper, alpha(0.5), Some(1e155));
        assert!(
            matches!(e, Err(t2spline::Error::ToleranceTooCoarse { .. })),
            "{e:?}"
        );
        // The coarsest allowed gives a finite region holding the fine one.
        let coarse = c
            .region(Membership::Upper, alpha(0.5), Some(most))
            .unwrap()
            .unwrap();
        let fine = c
            .region(Membership::Upper, alpha(0.5), None)
            .unwrap()
            .unwrap();
        assert!(
            coarse.area().is_finite() && coarse.area() >= fine.area(),
            "{scale}"
        );
        assert!(fine.area() > 0.0 && fine.area().is_finite(), "{scale}");
        unit_areas.push(fine.area() / (scale * scale));
    }
    // The same region up to scaling: areas scale as the square, to the
    // outline's tolerance (1e-6 of the diagonal).
    for a in &unit_areas {
        assert!(
            (a - unit_areas[1]).abs() <= 1e-6 * unit_areas[1],
            "{unit_areas:?}"
        );
    }
}
