//! Property tests of the invariants of docs/method.md §1–§7 on random valid inputs.
//!
//! Generators come from `t2spline::strategies` (feature `proptest`, switched on
//! for tests by the crate's self dev-dependency). Every float comparison has an
//! explicit tolerance, and every message carries the inputs that broke it.

use proptest::prelude::*;
use t2spline::{
    strategies, Alpha, FuzzyCurve, KnotVector, Layer, Nt2Number, Nt2Point, NurbsCurve, Side,
    TypeReduction,
};

/// Cases per property: enough to meet repeated knots, zero spreads and
/// `alpha = h`, small enough that the file runs in a few seconds in debug.
const CASES: u32 = 256;

/// `|a − b| ≤ tol·max(1, |a|, |b|)`: absolute near 0, relative for large values.
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * 1f64.max(a.abs()).max(b.abs())
}

fn close_point<const D: usize>(a: &[f64; D], b: &[f64; D], tol: f64) -> bool {
    a.iter().zip(b).all(|(&x, &y)| close(x, y, tol))
}

/// The parameters every property visits: `t = lerp(s)`, both ends of the domain
/// and every knot inside it (where spans change and the basis is most fragile).
fn parameters(knots: &KnotVector, s: f64) -> Vec<f64> {
    let domain = knots.domain();
    let mut t = vec![domain.lerp(s), domain.start, domain.end];
    t.extend(knots.as_slice().iter().filter(|&&u| domain.contains(u)));
    t
}

/// The next float above `x` (`x ≥ 0`); `f64::next_up` is newer than our MSRV.
fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        f64::from_bits(1)
    } else {
        f64::from_bits(x.to_bits() + 1)
    }
}

/// The next float below `x` (`x > 0`).
fn next_down(x: f64) -> f64 {
    f64::from_bits(x.to_bits() - 1)
}

/// A level chosen by `kind` relative to the height `h`: exactly 0, h or 1, just
/// below or above h (by 1e-9 or by one ulp), or `random`. Choices that fall
/// outside `[0, 1]` become `random`.
fn alpha_near(kind: usize, h: f64, random: f64) -> f64 {
    let a = match kind {
        0 => 0.0,
        1 => h,
        2 => 1.0,
        3 => h - 1e-9,
        4 => h + 1e-9,
        5 => next_down(h),
        6 => next_up(h),
        _ => random,
    };
    if (0.0..=1.0).contains(&a) {
        a
    } else {
        random
    }
}

/// Kinds for [`alpha_near`]: the special ones and, half of the time, random.
fn alpha_kind() -> impl Strategy<Value = usize> {
    prop_oneof![1 => 0usize..7, 1 => Just(7usize)]
}

/// The lower height shared by every number of a `fuzzy_curve_common_height`.
fn common_height<const D: usize>(curve: &FuzzyCurve<D>) -> f64 {
    curve.coordinate_heights().expect("common height")[0].get()
}

/// The `n` B-spline basis functions `N_{i,p}(t)` from the recursive Cox–de Boor
/// definition (The NURBS Book, Eq. 2.5), written independently of the library:
///
/// ```text
/// N_{i,0}(t) = 1 if U[i] ≤ t < U[i+1], else 0
/// N_{i,p}(t) = (t − U[i])/(U[i+p] − U[i])·N_{i,p−1}(t)
///            + (U[i+p+1] − t)/(U[i+p+1] − U[i+1])·N_{i+1,p−1}(t),   0/0 := 0
/// ```
/// At the right end `t = U[n]` of the domain the half-open rule would give no
/// span (clamped) or one outside the domain (unclamped), so there the last
/// non-empty span `[U[j], U[j+1]]`, `j < n`, is taken closed (docs/method.md §6).
fn cox_de_boor(u: &[f64], degree: usize, count: usize, t: f64) -> Vec<f64> {
    let end = u[count];
    let last = (0..count)
        .filter(|&j| u[j] < u[j + 1])
        .max()
        .expect("a non-empty span");
    let mut n: Vec<f64> = (0..u.len() - 1)
        .map(|i| {
            let inside = if t == end {
                i == last
            } else {
                u[i] <= t && t < u[i + 1]
            };
            if inside {
                1.0
            } else {
                0.0
            }
        })
        .collect();
    let ratio = |num: f64, den: f64| if den > 0.0 { num / den } else { 0.0 };
    for p in 1..=degree {
        n = (0..u.len() - 1 - p)
            .map(|i| {
                ratio(t - u[i], u[i + p] - u[i]) * n[i]
                    + ratio(u[i + p + 1] - t, u[i + p + 1] - u[i + 1]) * n[i + 1]
            })
            .collect();
    }
    n.truncate(count);
    n
}

/// A number with equal left and right spreads `a ≥ b ≥ d ≥ 0` about `c`.
fn symmetric_number() -> impl Strategy<Value = Nt2Number> + Clone {
    (
        -10.0..10.0f64,
        [0.0..3.0f64, 0.0..3.0f64, 0.0..3.0f64],
        strategies::height(),
    )
        .prop_map(|(c, mut s, h)| {
            s.sort_by(f64::total_cmp);
            let [d, b, a] = s;
            Nt2Number::try_new(c, [c - a, c + a], [c - b, c + b], [c - d, c + d], h)
                .expect("sorted spreads about c are ordered")
        })
}

/// A crisp curve with knots from [`strategies::curve`] (clamped or not, coarse
/// or fine interior knots) or from [`strategies::grid_curve`] (repeated knots
/// anywhere, also at the ends of an unclamped domain).
fn any_curve<const D: usize>() -> impl Strategy<Value = NurbsCurve<D>> {
    prop_oneof![strategies::curve::<D>(), strategies::grid_curve::<D>()]
}

/// A fuzzy curve with the shape (degree, weights, knots) of [`any_curve`] and
/// control points made by `point`.
fn fuzzy_curve_like<const D: usize>(
    point: impl Strategy<Value = Nt2Point<D>> + Clone,
) -> impl Strategy<Value = FuzzyCurve<D>> {
    any_curve::<D>().prop_flat_map(move |c| {
        proptest::collection::vec(point.clone(), c.control_points().len()).prop_map(move |points| {
            FuzzyCurve::try_new(
                c.degree(),
                points,
                c.weights().to_vec(),
                Some(c.knots().as_slice().to_vec()),
            )
            .expect("the parts of a valid curve")
        })
    })
}

/// A fuzzy curve with independent heights, of either kind of shape.
fn any_fuzzy_curve<const D: usize>() -> impl Strategy<Value = FuzzyCurve<D>> {
    prop_oneof![
        strategies::fuzzy_curve::<D>(),
        fuzzy_curve_like(strategies::point::<D>()),
    ]
}

/// A fuzzy curve whose numbers share one lower height, of either kind of shape.
fn any_fuzzy_curve_common_height<const D: usize>() -> impl Strategy<Value = FuzzyCurve<D>> {
    prop_oneof![
        strategies::fuzzy_curve_common_height::<D>(),
        strategies::height().prop_flat_map(|h| fuzzy_curve_like(
            proptest::array::uniform(strategies::number_with_height(h)).prop_map(Nt2Point::new)
        )),
    ]
}

/// A value whose seven values are all `x`, with any height.
fn crisp_number() -> impl Strategy<Value = Nt2Number> + Clone {
    (-10.0..10.0f64, strategies::height()).prop_map(|(x, h)| {
        Nt2Number::try_new(x, [x, x], [x, x], [x, x], h).expect("equal values are ordered")
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// docs/method.md §6: `R_i(t) ≥ 0` and `Σ R_i(t) = 1` on the whole domain.
    #[test]
    fn rational_basis_is_a_partition_of_unity(c in any_curve::<2>(), s in 0.0..=1.0f64) {
        for t in parameters(c.knots(), s) {
            let r = c.rational_basis(t).expect("t in the domain");
            prop_assert!(r.iter().all(|&ri| ri >= -1e-15),
                "negative basis at t = {t}: {r:?}, knots {:?}, weights {:?}",
                c.knots().as_slice(), c.weights());
            let sum: f64 = r.iter().sum();
            prop_assert!((sum - 1.0).abs() <= 1e-12,
                "sum {sum} != 1 at t = {t}: {r:?}, knots {:?}, weights {:?}",
                c.knots().as_slice(), c.weights());
        }
    }

    /// docs/method.md §6: `R_i = w_i N_i / Σ w_r N_r` with `N_i` from the Cox–de Boor
    /// definition (an independent oracle for the span search and A2.2).
    #[test]
    fn rational_basis_matches_the_definition(c in any_curve::<2>(), s in 0.0..=1.0f64) {
        let (u, p, n) = (c.knots().as_slice(), c.degree(), c.control_points().len());
        for t in parameters(c.knots(), s) {
            let basis = cox_de_boor(u, p, n, t);
            let weighted: Vec<f64> = basis.iter().zip(c.weights()).map(|(b, w)| b * w).collect();
            let total: f64 = weighted.iter().sum();
            let got = c.rational_basis(t).expect("t in the domain");
            for (i, (g, w)) in got.iter().zip(&weighted).enumerate() {
                prop_assert!(close(*g, w / total, 1e-12),
                    "R_{i}({t}) = {g}, definition {}; knots {u:?}, weights {:?}",
                    w / total, c.weights());
            }
        }
    }

    /// docs/method.md §6: with all weights equal to `w` the curve is the non-rational
    /// B-spline `Σ N_i(t) P_i`.
    #[test]
    fn equal_weights_give_the_plain_b_spline(
        c in any_curve::<2>(), w in 0.2..5.0f64, s in 0.0..=1.0f64,
    ) {
        let (u, p, n) = (c.knots().as_slice(), c.degree(), c.control_points().len());
        let equal = NurbsCurve::try_new(c.control_points().to_vec(), vec![w; n], c.knots().clone())
            .expect("valid parts");
        for t in parameters(c.knots(), s) {
            let basis = cox_de_boor(u, p, n, t);
            let expect: [f64; 2] = std::array::from_fn(|d| {
                basis.iter().zip(c.control_points()).map(|(b, q)| b * q[d]).sum()
            });
            let got = equal.eval(t).expect("t in the domain");
            prop_assert!(close_point(&got, &expect, 1e-12),
                "C({t}) = {got:?}, plain B-spline {expect:?}; degree {p}, knots {u:?}, w = {w}, points {:?}",
                c.control_points());
        }
    }

    /// docs/method.md §1, §6: the seven layer curves keep the order exactly (no tolerance:
    /// the basis is non-negative and every layer is summed in the same order, so
    /// rounding is monotone too), with independent heights, in 2-D and 3-D.
    #[test]
    fn layer_curves_keep_the_seven_value_order(
        c2 in any_fuzzy_curve::<2>(),
        c3 in any_fuzzy_curve::<3>(),
        s in 0.0..=1.0f64,
    ) {
        fn check<const D: usize>(c: &FuzzyCurve<D>, s: f64) -> Result<(), TestCaseError> {
            for t in parameters(c.knots(), s) {
                let layers = c.eval_layers(t).expect("t in the domain");
                for d in 0..D {
                    let v = layers.map(|p| p[d]);
                    let v = v.as_array();
                    prop_assert!(v.windows(2).all(|w| w[0] <= w[1]),
                        "order broken at t = {t}, coordinate {d}: {v:?}; curve {c:?}");
                }
            }
            Ok(())
        }
        check(&c2, s)?;
        check(&c3, s)?;
    }

    /// docs/method.md §6: with one lower height, the alpha-cut, type reduction and
    /// defuzzification of the curve point `C̃(t)` equal the stage-2/3/4 curves
    /// (built from the control points) at `t`.
    #[test]
    fn stages_commute_with_evaluation_for_a_common_height(
        c in any_fuzzy_curve_common_height::<2>(),
        kind in alpha_kind(),
        random in 0.0..=1.0f64,
        s in 0.0..=1.0f64,
    ) {
        let h = common_height(&c);
        let alpha = alpha_near(kind, h, random);
        let solution = c.solve(Alpha::try_new(alpha).expect("alpha in [0, 1]"));
        let cut_curves = Layer::ALL.map(|l| solution.alpha_cut_curve(l));
        prop_assert_eq!(cut_curves[Layer::LowerLeft.index()].is_some(), alpha <= h,
            "lower cut curve exists iff alpha = {} <= h = {}", alpha, h);
        let [left, right] = [Side::Left, Side::Right].map(|side| solution.type_reduced_curve(side));
        let defuzzified = solution.defuzzified_curve();
        for t in parameters(c.knots(), s) {
            let point = c.eval(t).expect("t in the domain").expect("a common height");
            let cuts = point.alpha_cut(solution.alpha());
            for (layer, curve) in Layer::ALL.into_iter().zip(&cut_curves) {
                let of_point: Option<[f64; 2]> = cuts
                    .iter()
                    .map(|cut| cut.layer(layer))
                    .collect::<Option<Vec<_>>>()
                    .map(|v| [v[0], v[1]]);
                match (of_point, curve) {
                    (Some(p), Some(curve)) => {
                        let q = curve.eval(t).expect("t in the domain");
                        prop_assert!(close_point(&p, &q, 1e-9),
                            "{layer} at alpha = {alpha}, h = {h}, t = {t}: cut of C(t) {p:?}, curve of cuts {q:?}; curve {c:?}");
                    }
                    (None, None) => {}
                    (p, q) => prop_assert!(false,
                        "{layer} at alpha = {alpha}, h = {h}: cut of C(t) {p:?}, curve {q:?}"),
                }
            }
            let tfns = point.type_reduce(solution.alpha());
            let (l, r) = (tfns.map(|x| x.left()), tfns.map(|x| x.right()));
            let (lc, rc) = (left.eval(t).expect("in domain"), right.eval(t).expect("in domain"));
            prop_assert!(close_point(&l, &lc, 1e-9) && close_point(&r, &rc, 1e-9),
                "type reduction at alpha = {alpha}, h = {h}, t = {t}: of C(t) {l:?}/{r:?}, curves {lc:?}/{rc:?}; curve {c:?}");
            let d = point.defuzzify(solution.alpha());
            let dc = defuzzified.eval(t).expect("in domain");
            prop_assert!(close_point(&d, &dc, 1e-9),
                "defuzzified at alpha = {alpha}, h = {h}, t = {t}: of C(t) {d:?}, curve {dc:?}; curve {c:?}");
        }
    }

    /// docs/method.md §2: cuts are nested — for `α₁ ≤ α₂` each cut at `α₂` lies in the
    /// one at `α₁` — and ordered (lower ⊂ primary ⊂ upper, all containing
    /// `crisp`); the lower cut exists exactly when `α ≤ h`.
    #[test]
    fn cuts_shrink_as_alpha_grows(
        x in strategies::number(),
        kinds in (alpha_kind(), alpha_kind()),
        randoms in (0.0..=1.0f64, 0.0..=1.0f64),
    ) {
        let h = x.height().get();
        let mut alphas = [alpha_near(kinds.0, h, randoms.0), alpha_near(kinds.1, h, randoms.1)];
        alphas.sort_by(f64::total_cmp);
        let [a1, a2] = alphas;
        let cut = |a: f64| x.alpha_cut(Alpha::try_new(a).expect("alpha in [0, 1]"));
        let (c1, c2) = (cut(a1), cut(a2));
        let inside = |outer: t2spline::Interval, inner: t2spline::Interval| {
            outer.left() <= inner.left() + 1e-12 && inner.right() <= outer.right() + 1e-12
        };
        for (a, c) in [(a1, &c1), (a2, &c2)] {
            prop_assert_eq!(c.lower().is_some(), a <= h, "lower cut at alpha = {} with h = {}: {:?}", a, h, c);
            let crisp = t2spline::Interval::try_new(x.crisp(), x.crisp()).expect("a point");
            let innermost = c.lower().unwrap_or(crisp);
            prop_assert!(inside(c.upper(), c.primary()) && inside(c.primary(), innermost)
                && inside(innermost, crisp),
                "cut at alpha = {a} is not nested: {c:?}; number {x:?}");
        }
        prop_assert!(inside(c1.upper(), c2.upper()) && inside(c1.primary(), c2.primary()),
            "alpha {a1} -> {a2}: upper/primary cuts grow: {c1:?} -> {c2:?}; number {x:?}");
        if let (Some(l1), Some(l2)) = (c1.lower(), c2.lower()) {
            prop_assert!(inside(l1, l2),
                "alpha {a1} -> {a2}: lower cut grows: {l1:?} -> {l2:?}; number {x:?}");
        }
    }

    /// docs/method.md §3–§4 per number: `left ≤ crisp ≤ right`, and the centroid lies in
    /// `[left, right]` (exactly: the library clamps against rounding).
    #[test]
    fn type_reduction_brackets_crisp_and_defuzzified(
        x in strategies::number(), kind in alpha_kind(), random in 0.0..=1.0f64,
    ) {
        let alpha = alpha_near(kind, x.height().get(), random);
        let t = x.alpha_cut(Alpha::try_new(alpha).expect("alpha in [0, 1]")).type_reduce();
        let d = t.defuzzify();
        prop_assert!(t.left() <= t.crisp() && t.crisp() <= t.right() && t.crisp() == x.crisp(),
            "alpha = {alpha}: {t:?} for {x:?}");
        prop_assert!(t.left() <= d && d <= t.right(),
            "alpha = {alpha}: defuzzified {d} outside {t:?} for {x:?}");
    }

    /// docs/method.md §3–§4, §9 on curves: the defuzzified curve between the left and
    /// the right curve for every type reduction, and for the paper's also the
    /// left curve ≤ crisp curve ≤ right curve, at every `t` (exactly, by the
    /// same monotonicity as the layer order).
    #[test]
    fn type_reduced_curves_bracket_crisp_and_defuzzified(
        c in any_fuzzy_curve::<2>(), random in 0.0..=1.0f64, s in 0.0..=1.0f64,
        method in proptest::sample::select(TypeReduction::ALL.to_vec()),
    ) {
        let solution = c.solve_with(Alpha::try_new(random).expect("alpha in [0, 1]"), method);
        let curves = [
            solution.type_reduced_curve(Side::Left),
            solution.crisp_curve(),
            solution.defuzzified_curve(),
            solution.type_reduced_curve(Side::Right),
        ];
        for t in parameters(c.knots(), s) {
            let [l, crisp, d, r] = curves.each_ref().map(|k| k.eval(t).expect("in domain"));
            for i in 0..2 {
                let centred = method != TypeReduction::Paper || (l[i] <= crisp[i] && crisp[i] <= r[i]);
                prop_assert!(centred && l[i] <= d[i] && d[i] <= r[i],
                    "{method}, alpha = {random}, t = {t}, coordinate {i}: left {l:?}, crisp {crisp:?}, defuzzified {d:?}, right {r:?}; curve {c:?}");
            }
        }
    }

    /// docs/method.md §7, §9: symmetric spreads defuzzify to the crisp values under
    /// every type reduction, so the distance between the crisp and the
    /// defuzzified curve is 0 (up to rounding).
    #[test]
    fn symmetric_spreads_give_zero_distance(
        c in fuzzy_curve_like(proptest::array::uniform2(symmetric_number()).prop_map(Nt2Point::new)),
        random in 0.0..=1.0f64,
    ) {
        for method in TypeReduction::ALL {
            let d = c.solve_with(Alpha::try_new(random).expect("alpha in [0, 1]"), method).distance();
            prop_assert!(d.max < 1e-12 && d.rms < 1e-12, "{method}, alpha = {random}: {d:?}; curve {c:?}");
        }
    }

    /// docs/method.md §1, §4: a crisp input (all seven values equal, any height) gives the
    /// crisp curve back, exactly, at every alpha.
    #[test]
    fn crisp_input_gives_the_crisp_curve(
        c in fuzzy_curve_like(proptest::array::uniform2(crisp_number()).prop_map(Nt2Point::new)),
        random in 0.0..=1.0f64,
        s in 0.0..=1.0f64,
    ) {
        let solution = c.solve(Alpha::try_new(random).expect("alpha in [0, 1]"));
        let (crisp, defuzzified) = (solution.crisp_curve(), solution.defuzzified_curve());
        prop_assert_eq!(&defuzzified, &crisp, "alpha = {}", random);
        for t in parameters(c.knots(), s) {
            prop_assert_eq!(defuzzified.eval(t).expect("in domain"), crisp.eval(t).expect("in domain"),
                "alpha = {}, t = {}", random, t);
        }
        let d = solution.distance();
        prop_assert!(d.max == 0.0 && d.rms == 0.0, "alpha = {random}: {d:?}");
    }

    /// docs/method.md §2–§4: at `α = 1` every cut is the crisp value, so the defuzzified
    /// control points are exactly the crisp ones and the distance is exactly 0.
    #[test]
    fn alpha_one_gives_the_crisp_control_points(c in any_fuzzy_curve::<2>()) {
        let solution = c.solve(Alpha::try_new(1.0).expect("1 is a level"));
        let crisp: Vec<[f64; 2]> = c.points().iter().map(Nt2Point::crisp).collect();
        prop_assert_eq!(solution.defuzzified_points(), &crisp[..]);
        let d = solution.distance();
        prop_assert!(d.max == 0.0 && d.rms == 0.0, "{d:?}; curve {c:?}");
    }

    /// Affine invariance: mapping every one of the seven values of coordinate
    /// `d` by `x ↦ a_d·x + b_d` (`a_d > 0`, which keeps the order) maps the
    /// defuzzified curve by the same map.
    #[test]
    fn defuzzified_curve_is_affine_invariant(
        c in any_fuzzy_curve::<2>(),
        scale in [0.1..10.0f64, 0.1..10.0f64],
        shift in [-10.0..10.0f64, -10.0..10.0f64],
        random in 0.0..=1.0f64,
        s in 0.0..=1.0f64,
    ) {
        let map = |d: usize, x: f64| scale[d] * x + shift[d];
        let points = c
            .points()
            .iter()
            .map(|p| {
                Nt2Point::new(std::array::from_fn(|d| {
                    let x = p.coords()[d];
                    let v = x.layers().map(|v| map(d, v));
                    Nt2Number::try_new(
                        v[Layer::Crisp],
                        [v[Layer::UpperLeft], v[Layer::UpperRight]],
                        [v[Layer::PrimaryLeft], v[Layer::PrimaryRight]],
                        [v[Layer::LowerLeft], v[Layer::LowerRight]],
                        x.height().get(),
                    )
                    .expect("an increasing map keeps the order")
                }))
            })
            .collect();
        let mapped = FuzzyCurve::try_new(c.degree(), points, c.weights().to_vec(), Some(c.knots().as_slice().to_vec()))
            .expect("same shape");
        let alpha = Alpha::try_new(random).expect("alpha in [0, 1]");
        let (before, after) = (c.solve(alpha).defuzzified_curve(), mapped.solve(alpha).defuzzified_curve());
        for t in parameters(c.knots(), s) {
            let p = before.eval(t).expect("in domain");
            let expect = [map(0, p[0]), map(1, p[1])];
            let got = after.eval(t).expect("in domain");
            prop_assert!(close_point(&got, &expect, 1e-9),
                "alpha = {random}, t = {t}, scale {scale:?}, shift {shift:?}: mapped curve {got:?}, map of curve {expect:?}; curve {c:?}");
        }
    }
}
