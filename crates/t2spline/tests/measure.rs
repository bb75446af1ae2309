//! Quantities measured on a fuzzy curve (docs/method.md §11): closed forms,
//! the shipped example, nesting, brute-force vertex enumeration for few
//! control points, and soundness: admissible control points (random ones
//! inside the cuts, and vertices) never give a value outside the reported
//! interval. The references are computed another way: lengths by
//! `NurbsCurve::arc_length`, derivatives and curvature by
//! `NurbsCurve::derivatives` and `curvature`, areas by Gauss–Legendre
//! quadrature of `y·x'` on the crisp curve operations.

use proptest::prelude::*;
use t2spline::measure::{AreaKind, Bracket, MeasureOptions};
use t2spline::{Alpha, FuzzyCurve, Membership, Nt2Number, Nt2Point, NurbsCurve};

const MEMBERSHIPS: [Membership; 3] = [Membership::Upper, Membership::Primary, Membership::Lower];

/// The shipped example (`examples/paper-alg-1-1.json`).
fn example() -> FuzzyCurve<2> {
    t2spline::strategies::paper_example()
}

fn alpha(a: f64) -> Alpha {
    Alpha::try_new(a).expect("a level")
}

/// The cut `[lo, hi]` of every coordinate of every point.
fn cuts<const D: usize>(
    curve: &FuzzyCurve<D>,
    m: Membership,
    a: Alpha,
) -> Option<Vec<[[f64; 2]; D]>> {
    curve
        .points()
        .iter()
        .map(|p| {
            let mut out = [[0.0; 2]; D];
            for (o, x) in out.iter_mut().zip(p.coords()) {
                let cut = x.alpha_cut(a);
                let iv = match m {
                    Membership::Upper => cut.upper(),
                    Membership::Primary => cut.primary(),
                    Membership::Lower => cut.lower()?,
                };
                *o = [iv.left(), iv.right()];
            }
            Some(out)
        })
        .collect()
}

/// The crisp curve through `points` with the fuzzy curve's weights and knots.
fn crisp_with<const D: usize>(curve: &FuzzyCurve<D>, points: Vec<[f64; D]>) -> NurbsCurve<D> {
    NurbsCurve::try_new(points, curve.weights().to_vec(), curve.knots().clone()).expect("valid")
}

/// `∫ y·x' dt` (open) or `½ ∫ (x·y' − y·x') dt`, by 20-point Gauss–Legendre
/// on 16 equal parts of every knot span.
fn area_of(c: &NurbsCurve<2>, enclosed: bool) -> f64 {
    let (x, w) = gauss_legendre(20);
    let mut total = 0.0;
    for (_, [a, b]) in c.knots().spans() {
        let parts = 16;
        for k in 0..parts {
            let (lo, hi) = (
                a + (b - a) * k as f64 / parts as f64,
                a + (b - a) * (k + 1) as f64 / parts as f64,
            );
            for (xi, wi) in x.iter().zip(&w) {
                let t = (lo + hi) / 2.0 + (hi - lo) / 2.0 * xi;
                let d = c.derivatives(t, 1).expect("in the domain");
                let f = if enclosed {
                    0.5 * (d[0][0] * d[1][1] - d[0][1] * d[1][0])
                } else {
                    d[0][1] * d[1][0]
                };
                total += wi * (hi - lo) / 2.0 * f;
            }
        }
    }
    total
}

/// Gauss–Legendre nodes by Newton's method on the Legendre recurrence.
fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    (1..=n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 - 0.25) / (n as f64 + 0.5)).cos();
            let eval = |x: f64| {
                let (mut p, mut q) = (x, 1.0);
                for k in 2..=n {
                    let k = k as f64;
                    (p, q) = (((2.0 * k - 1.0) * x * p - (k - 1.0) * q) / k, p);
                }
                (p, n as f64 * (x * p - q) / (x * x - 1.0))
            };
            for _ in 0..100 {
                let (p, dp) = eval(x);
                x -= p / dp;
            }
            let dp = eval(x).1;
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .unzip()
}

/// Every vertex of the box (coordinates at their cut ends).
fn vertices<const D: usize>(cut: &[[[f64; 2]; D]]) -> Vec<Vec<[f64; D]>> {
    let vars = cut.len() * D;
    (0..1u64 << vars)
        .map(|bits| {
            cut.iter()
                .enumerate()
                .map(|(i, p)| std::array::from_fn(|c| p[c][((bits >> (i * D + c)) & 1) as usize]))
                .collect()
        })
        .collect()
}

fn span(values: impl Iterator<Item = f64>) -> [f64; 2] {
    values.fold([f64::INFINITY, f64::NEG_INFINITY], |[a, b], v| {
        [a.min(v), b.max(v)]
    })
}

#[test]
fn the_example_upper_cut_at_one_half_has_lengths_from_7_2953_to_10_6953() {
    let c = example();
    let b = c
        .length_bracket(Membership::Upper, alpha(0.5))
        .expect("a cut");
    assert!(b.exact, "{b:?}");
    assert!((b.min - 7.2953).abs() < 5e-5, "{b:?}");
    assert!((b.max - 10.6953).abs() < 5e-5, "{b:?}");
    assert!(b.gap <= 1e-9 * b.max, "{b:?}");
    // The largest is the largest of the 256 vertices.
    let cut = cuts(&c, Membership::Upper, alpha(0.5)).unwrap();
    let [_, hi] = span(
        vertices(&cut)
            .into_iter()
            .map(|v| crisp_with(&c, v).arc_length()),
    );
    assert!((b.max - hi).abs() <= 1e-9 * hi, "{} vs {hi}", b.max);
    // The layer curves' lengths are not bounds: they lie well inside.
    for layer in t2spline::Layer::ALL {
        let l = c.layer_curve(layer).arc_length();
        assert!(l > b.min + 1.0 && l < b.max - 1.0, "{layer:?}: {l}");
    }
}

#[test]
fn a_straight_segment_with_spread_along_it() {
    // From (0, 0) to (4, 0); each end may move s along the line.
    for s in [0.0, 0.5, 1.0] {
        let n = |c: f64, s: f64| {
            Nt2Number::try_new(c, [c - s, c + s], [c - s / 2.0, c + s / 2.0], [c, c], 1.0).unwrap()
        };
        let points = vec![
            Nt2Point::new([n(0.0, s), n(0.0, 0.0)]),
            Nt2Point::new([n(4.0, s), n(0.0, 0.0)]),
        ];
        let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None).unwrap();
        for a in [0.0, 0.25, 1.0] {
            let spread = s * (1.0 - a);
            let b = line.length_bracket(Membership::Upper, alpha(a)).unwrap();
            assert!(b.exact);
            assert!((b.min - (4.0 - 2.0 * spread)).abs() < 1e-9, "{b:?}");
            assert!((b.max - (4.0 + 2.0 * spread)).abs() < 1e-9, "{b:?}");
            // Along the x axis: no area under it, tangent angle 0, no curvature.
            let area = line.area_bracket(Membership::Upper, alpha(a)).unwrap();
            assert!(area.min.abs() < 1e-12 && area.max.abs() < 1e-12, "{area:?}");
            let angle = line
                .tangent_angle_bracket(0.5, Membership::Upper, alpha(a))
                .unwrap()
                .unwrap()
                .unwrap();
            assert!(angle.min.abs() < 1e-15 && angle.max.abs() < 1e-15);
            let k = line
                .curvature_bracket(0.5, Membership::Upper, alpha(a))
                .unwrap()
                .unwrap();
            assert!(k.min == 0.0 && k.max < 1e-12, "{k:?}");
        }
    }
}

#[test]
fn a_crisp_curve_gives_points_equal_to_its_crisp_measures() {
    let c = example();
    let points: Vec<Nt2Point<2>> = c
        .points()
        .iter()
        .map(|p| Nt2Point::new(p.crisp().map(|x| Nt2Number::try_crisp(x).unwrap())))
        .collect();
    let crisp = FuzzyCurve::try_new(2, points, c.weights().to_vec(), None).unwrap();
    let curve = c.crisp_curve();
    let l = curve.arc_length();
    let area = area_of(&curve, false);
    for m in MEMBERSHIPS {
        for a in [0.0, 0.5, 1.0] {
            let b = crisp.length_bracket(m, alpha(a)).unwrap();
            assert!(
                (b.min - l).abs() < 1e-9 * l && (b.max - l).abs() < 1e-9 * l,
                "{b:?} vs {l}"
            );
            let s = crisp.area_bracket(m, alpha(a)).unwrap();
            assert!(
                (s.min - area).abs() < 1e-10 * area && (s.max - area).abs() < 1e-10 * area,
                "{s:?} vs {area}"
            );
            let d = crisp
                .derivative_bracket(0.3, 2, m, alpha(a))
                .unwrap()
                .unwrap();
            let reference = curve.derivatives(0.3, 2).unwrap()[2];
            for k in 0..2 {
                assert!((d[k][0] - reference[k]).abs() < 1e-12 * reference[k].abs().max(1.0));
                assert!((d[k][1] - reference[k]).abs() < 1e-12 * reference[k].abs().max(1.0));
            }
            let k = crisp.curvature_bracket(0.3, m, alpha(a)).unwrap().unwrap();
            let kappa = curve.curvature(0.3).unwrap();
            assert!(
                (k.min - kappa).abs() < 1e-12 * kappa && (k.max - kappa).abs() < 1e-12 * kappa,
                "{k:?} vs {kappa}"
            );
        }
    }
}

#[test]
fn a_circle_of_fuzzy_radius() {
    // The full circle as nine rational quadratic control points, radius
    // between 1.8 and 2.2; coordinates 0 are crisp.
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let unit = [
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
    let (r, s) = (2.0, 0.2);
    let number = |u: f64| {
        let c = r * u;
        let d = s * u.abs();
        Nt2Number::try_new(c, [c - d, c + d], [c - d, c + d], [c, c], 1.0).unwrap()
    };
    let points: Vec<Nt2Point<2>> = unit
        .iter()
        .map(|u| Nt2Point::new([number(u[0]), number(u[1])]))
        .collect();
    let knots = vec![
        0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
    ];
    let circle = FuzzyCurve::try_new(
        2,
        points,
        vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0],
        Some(knots),
    )
    .unwrap();
    assert_eq!(circle.area_kind(), AreaKind::Enclosed);
    let tau = std::f64::consts::TAU;
    for a in [0.0, 0.5, 1.0] {
        let spread = s * (1.0 - a);
        let b = circle.length_bracket(Membership::Upper, alpha(a)).unwrap();
        // The smallest circle is the shortest curve; the largest circle is
        // admissible, so the longest is at least as long.
        assert!((b.min - tau * (r - spread)).abs() < 1e-8, "{a}: {b:?}");
        assert!(b.max >= tau * (r + spread) * (1.0 - 1e-12), "{a}: {b:?}");
        let area = circle.area_bracket(Membership::Upper, alpha(a)).unwrap();
        assert!(
            area.min <= 0.5 * tau * (r - spread).powi(2) + 1e-9,
            "{area:?}"
        );
        assert!(
            area.max >= 0.5 * tau * (r + spread).powi(2) - 1e-9,
            "{area:?}"
        );
        if a == 1.0 {
            assert!(
                (area.min - 0.5 * tau * r * r).abs() < 1e-9 && (area.max - area.min).abs() < 1e-9
            );
        }
    }
}

#[test]
fn a_curve_that_can_stand_still_has_lengths_from_zero() {
    // Every control point is the same fuzzy point: the crisp curve stands
    // still, and every cut holds a curve of length 0.
    let n = Nt2Number::try_new(1.0, [0.0, 2.0], [0.5, 1.5], [0.8, 1.2], 0.5).unwrap();
    let p = Nt2Point::new([n, n]);
    let c = FuzzyCurve::try_new(2, vec![p, p, p], vec![1.0; 3], None).unwrap();
    let m = c.measure(&MeasureOptions::uniform(3).unwrap()).unwrap();
    for f in [&m.length.upper, &m.length.primary, &m.length.lower] {
        for level in f {
            let b = level.bracket();
            assert!(b.min == 0.0 && b.max >= 0.0, "{level:?}");
            // The crisp curve's length, 0, is inside; at level 1 nothing moves.
            assert!(b.holds(0.0, 0.0), "{level:?}");
            if level.alpha == 1.0 {
                assert!(b.max < 1e-12, "{level:?}");
            }
        }
    }
}

#[test]
fn quantities_nest_over_levels_and_functions() {
    let c = example();
    let options = MeasureOptions::new(
        t2spline::measure::uniform_levels(11).unwrap(),
        vec![0.0, 0.3, 0.75, 1.0],
        1,
    )
    .unwrap();
    let m = c.measure(&options).unwrap();
    assert_eq!(m.length.upper.len(), 11);
    // The lower function up to its height 0.6: levels 0 … 0.6.
    assert_eq!(m.length.lower.len(), 7);
    let area = m.area.as_ref().unwrap();
    let length = [
        m.length.upper.clone(),
        m.length.primary.clone(),
        m.length.lower.clone(),
    ];
    let areas = [area.upper.clone(), area.primary.clone(), area.lower.clone()];
    for list in [&length, &areas] {
        for f in list {
            for w in f.windows(2) {
                assert!(w[0].bracket().contains(&w[1].bracket(), 1e-12), "{w:?}");
            }
        }
        for (o, i) in list[0]
            .iter()
            .zip(&list[1])
            .chain(list[1].iter().zip(&list[2]))
        {
            assert_eq!(o.alpha, i.alpha);
            assert!(o.bracket().contains(&i.bracket(), 1e-12), "{o:?} {i:?}");
        }
    }
    for at in &m.at {
        for f in [
            &at.curvature.upper,
            &at.curvature.primary,
            &at.curvature.lower,
        ] {
            for w in f.windows(2) {
                if let (Some(a), Some(b), Some(c), Some(d)) =
                    (w[0].min, w[0].max, w[1].min, w[1].max)
                {
                    assert!(a <= c * (1.0 + 1e-12) && b >= d * (1.0 - 1e-12), "{w:?}");
                }
            }
        }
    }
}

/// A small random fuzzy curve of two to four points, degree 1 or 2.
fn small_curve() -> impl Strategy<Value = FuzzyCurve<2>> {
    (
        2usize..=4,
        1usize..=2,
        prop::collection::vec((-3.0..3.0f64, 0.0..1.0f64, 0.0..1.0f64, 0.1..1.0f64), 8),
        prop::collection::vec(0.5..3.0f64, 4),
    )
        .prop_map(|(n, degree, values, weights)| {
            let degree = degree.min(n - 1);
            let points = (0..n)
                .map(|i| {
                    Nt2Point::new(std::array::from_fn(|c| {
                        let (x, l, r, shrink) = values[2 * i + c];
                        let x = x + 2.0 * i as f64 * (1 - c) as f64;
                        Nt2Number::try_new(
                            x,
                            [x - l, x + r],
                            [x - l * shrink, x + r * shrink],
                            [x - l * shrink * shrink, x + r * shrink * shrink],
                            0.7,
                        )
                        .unwrap()
                    }))
                })
                .collect();
            FuzzyCurve::try_new(degree, points, weights[..n].to_vec(), None).unwrap()
        })
}

/// Checks every quantity against the vertices and `draws` random points.
fn check_sound(
    c: &FuzzyCurve<2>,
    m: Membership,
    a: Alpha,
    draws: &[Vec<f64>],
    exact_vertices: bool,
) {
    let Some(cut) = cuts(c, m, a) else { return };
    let length = c.length_bracket(m, a).unwrap();
    let area = c.area_bracket(m, a).unwrap();
    let t = 0.37;
    let derivative = c.derivative_bracket(t, 1, m, a).unwrap().unwrap();
    let curvature = c.curvature_bracket(t, m, a).unwrap();
    let angle = c.tangent_angle_bracket(t, m, a).unwrap().unwrap();
    let mut curves: Vec<Vec<[f64; 2]>> = vertices(&cut);
    let nv = curves.len();
    for d in draws {
        curves.push(
            cut.iter()
                .enumerate()
                .map(|(i, p)| {
                    std::array::from_fn(|k| {
                        p[k][0] + d[(2 * i + k) % d.len()] * (p[k][1] - p[k][0])
                    })
                })
                .collect(),
        );
    }
    let closed = c.area_kind() == AreaKind::Enclosed;
    let (mut lengths, mut areas) = (Vec::new(), Vec::new());
    for (j, points) in curves.into_iter().enumerate() {
        let curve = crisp_with(c, points);
        let l = curve.arc_length();
        let s = area_of(&curve, closed);
        assert!(length.holds(l, 1e-9), "length {l} outside {length:?}");
        assert!(area.holds(s, 1e-9), "area {s} outside {area:?}");
        let d = curve.derivatives(t, 2).unwrap();
        for k in 0..2 {
            assert!(d[1][k] >= derivative[k][0] - 1e-12 && d[1][k] <= derivative[k][1] + 1e-12);
        }
        if let Some(b) = angle {
            let mut phi = d[1][1].atan2(d[1][0]);
            if phi < b.min - 1e-12 {
                phi += std::f64::consts::TAU;
            }
            assert!(b.holds(phi, 1e-12), "angle {phi} outside {b:?}");
        }
        if let (Some(b), Ok(k)) = (curvature, curve.curvature(t)) {
            // `NurbsCurve::curvature` takes `‖C'‖²‖C''‖² − (C'·C'')²`, which
            // cancels: its rounding is about `√ε·‖C''‖/‖C'‖²`.
            let speed = d[1][0].hypot(d[1][1]);
            let slack = 1e-7 * d[2][0].hypot(d[2][1]) / (speed * speed);
            assert!(
                k >= b.min - slack - 1e-9 * k && k <= b.max + slack + 1e-9 * k,
                "curvature {k} outside {b:?}"
            );
        }
        if j < nv {
            lengths.push(l);
            areas.push(s);
        }
    }
    if exact_vertices {
        // The maximum length and both area extremes are at vertices: equal
        // to the brute force where exact, and within the gap otherwise (a
        // vertex curve with a cusp, whose speed has a corner).
        let [_, lmax] = span(lengths.into_iter());
        if length.exact {
            assert!(
                (length.max - lmax).abs() <= 1e-9 * lmax,
                "{length:?} vs {lmax}"
            );
        } else {
            assert!(
                length.max >= lmax && length.max - length.gap <= lmax * (1.0 + 1e-9),
                "{length:?} vs {lmax}"
            );
        }
        let [smin, smax] = span(areas.into_iter());
        let scale = smin.abs().max(smax.abs()).max(1.0);
        assert!(
            (area.min - smin).abs() <= 1e-9 * scale && (area.max - smax).abs() <= 1e-9 * scale,
            "{area:?} vs [{smin}, {smax}]"
        );
    }
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(4, 8))]

    #[test]
    fn exact_extremes_equal_every_vertex_and_no_admissible_curve_escapes(
        c in small_curve(),
        a in 0.0..1.0f64,
        draws in prop::collection::vec(prop::collection::vec(0.0..1.0f64, 8), 40),
    ) {
        for m in MEMBERSHIPS {
            check_sound(&c, m, alpha(a), &draws, true);
        }
    }
}

#[test]
fn the_example_holds_every_admissible_curve_drawn() {
    // 400 random admissible curves per function at three levels (3 600
    // in all) under T2SPLINE_LONG_TESTS=1, 150 (1350) by default, and all 256
    // vertices.
    let c = example();
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let draws: Vec<Vec<f64>> = (0..t2spline::strategies::test_size(150, 400))
        .map(|_| (0..8).map(|_| next()).collect())
        .collect();
    for m in MEMBERSHIPS {
        for a in [0.0, 0.5, 0.6] {
            check_sound(&c, m, alpha(a), &draws, true);
        }
    }
}

#[test]
fn brackets_are_never_narrower_than_the_values_found_by_searching() {
    // The least length by a dense search of the box (random points and
    // coordinate steps): never below the certified minimum, and close to it.
    let c = example();
    let b = c.length_bracket(Membership::Primary, alpha(0.2)).unwrap();
    let cut = cuts(&c, Membership::Primary, alpha(0.2)).unwrap();
    let mut best: Vec<[f64; 2]> = c.points().iter().map(|p| p.crisp()).collect();
    let mut value = crisp_with(&c, best.clone()).arc_length();
    let mut step = 0.25;
    while step > 1e-7 {
        let mut improved = false;
        for i in 0..best.len() {
            for k in 0..2 {
                for dir in [-1.0, 1.0] {
                    let mut trial = best.clone();
                    let [lo, hi] = cut[i][k];
                    trial[i][k] = (trial[i][k] + dir * step * (hi - lo)).clamp(lo, hi);
                    let v = crisp_with(&c, trial.clone()).arc_length();
                    if v < value {
                        value = v;
                        best = trial;
                        improved = true;
                    }
                }
            }
        }
        if !improved {
            step /= 2.0;
        }
    }
    assert!(value >= b.min - 1e-12, "{value} below {b:?}");
    assert!(value <= b.min + 1e-6 * value, "{value} far above {b:?}");
}

#[test]
fn bracket_of_a_point() {
    let b = Bracket::point(2.0);
    assert!(b.exact && b.holds(2.0, 0.0) && !b.holds(2.1, 0.0));
}

#[test]
fn levels_are_answered_whatever_their_order() {
    // Nesting tightens each level by its neighbours in alpha, not in the
    // order asked: levels given high to low, or shuffled with a repeat, get
    // at each alpha what the increasing order gives.
    let c = example();
    let at = |levels: &[f64]| {
        let levels = levels
            .iter()
            .map(|&a| t2spline::Alpha::try_new(a).unwrap())
            .collect();
        c.measure(&MeasureOptions::new(levels, Vec::new(), 1).unwrap())
            .unwrap()
    };
    for levels in [
        vec![0.9, 0.1],
        vec![0.5, 0.9, 0.1, 0.3],
        vec![0.3, 0.9, 0.3, 0.1],
    ] {
        let mut increasing = levels.clone();
        increasing.sort_by(f64::total_cmp);
        let sorted = at(&increasing);
        let m = at(&levels);
        let area = m.area.as_ref().unwrap();
        let want_area = sorted.area.as_ref().unwrap();
        for (got, want) in [
            (&m.length.upper, &sorted.length.upper),
            (&m.length.primary, &sorted.length.primary),
            (&m.length.lower, &sorted.length.lower),
            (&area.upper, &want_area.upper),
            (&area.lower, &want_area.lower),
        ] {
            for level in got {
                let same = want
                    .iter()
                    .find(|w| w.alpha == level.alpha)
                    .expect("the level");
                assert!(
                    (level.min - same.min).abs() <= 1e-9 * same.min.abs().max(1.0)
                        && (level.max - same.max).abs() <= 1e-9 * same.max.abs().max(1.0),
                    "{levels:?} at {}: {level:?} != {same:?}",
                    level.alpha
                );
            }
        }
    }
}
