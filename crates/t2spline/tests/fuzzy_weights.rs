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
    says(
        c.region(t2spline::Membership::Upper, alpha, None)
            .unwrap_err(),
        "a region",
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

/// A tiny deterministic generator, so that failures replay.
struct Lcg(u64);

impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn between(&mut self, [a, b]: [f64; 2]) -> f64 {
        a + (b - a) * self.unit()
    }
}

/// The cut of `x` under `m` at `alpha`, if any.
fn cut_of(x: &Nt2Number, m: t2spline::Membership, alpha: Alpha) -> Option<[f64; 2]> {
    use t2spline::Membership as M;
    let c = x.alpha_cut(alpha);
    let (l, r) = match m {
        M::Upper => (Layer::UpperLeft, Layer::UpperRight),
        M::Primary => (Layer::PrimaryLeft, Layer::PrimaryRight),
        M::Lower => (Layer::LowerLeft, Layer::LowerRight),
    };
    Some([c.layer(l)?, c.layer(r)?])
}

/// The largest level (to 1e-9) at which `q` lies in the exact set at `t`
/// (`IntervalTerms`, the one-parameter mathematics tested on its own).
fn level_at(c: &FuzzyCurve<2>, m: t2spline::Membership, t: f64, q: [f64; 2]) -> f64 {
    let p = c.degree();
    let span = c.knots().find_span(t);
    let basis =
        t2spline::nurbs::basis::try_basis_functions(c.knots().as_slice(), p, span, t).unwrap();
    let w = c.weight_numbers().unwrap();
    let inside = |a: f64| -> bool {
        let alpha = Alpha::try_new(a).unwrap();
        let mut ws = Vec::new();
        let mut ps = Vec::new();
        let mut ns = Vec::new();
        for (k, &n) in basis.iter().enumerate() {
            let i = span - p + k;
            if n == 0.0 {
                continue;
            }
            let (Some(wc), Some(x), Some(y)) = (
                cut_of(&w[i], m, alpha),
                cut_of(&c.points()[i].coords()[0], m, alpha),
                cut_of(&c.points()[i].coords()[1], m, alpha),
            ) else {
                return false;
            };
            ws.push(wc);
            ps.push([x, y]);
            ns.push(n);
        }
        t2spline::interval_weights::IntervalTerms::try_new(&ns, &ws, &ps)
            .unwrap()
            .contains(q)
            .unwrap()
    };
    if !inside(0.0) {
        return 0.0;
    }
    let (mut lo, mut hi) = (0.0, 1.0);
    if inside(1.0) {
        return 1.0;
    }
    for _ in 0..32 {
        let mid = 0.5 * (lo + hi);
        if inside(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The best level over a grid of 801 parameters, each of the three best
/// zoomed into by rounds of 100 parameters over a window 25 times smaller
/// (a grade can peak sharply in `t`).
fn best_level(c: &FuzzyCurve<2>, m: t2spline::Membership, q: [f64; 2]) -> f64 {
    let coarse: Vec<(f64, f64)> = (0..=800)
        .map(|k| {
            let t = f64::from(k) / 800.0;
            (level_at(c, m, t, q), t)
        })
        .collect();
    let mut order: Vec<usize> = (0..coarse.len()).collect();
    order.sort_by(|&a, &b| coarse[b].0.total_cmp(&coarse[a].0));
    let mut best = coarse[order[0]].0;
    for &k in order.iter().take(3) {
        let (mut centre, mut half) = (coarse[k].1, 2.0 / 800.0);
        for _ in 0..4 {
            let mut round = (f64::NEG_INFINITY, centre);
            for j in 0..=100 {
                let t = (centre - half + 2.0 * half * f64::from(j) / 100.0).clamp(0.0, 1.0);
                let g = level_at(c, m, t, q);
                if g > round.0 {
                    round = (g, t);
                }
            }
            best = best.max(round.0);
            centre = round.1;
            half /= 25.0;
        }
    }
    best
}

#[test]
fn membership_with_fuzzy_weights_holds_every_admissible_curve_and_is_not_above_the_truth() {
    use t2spline::Membership as M;
    let c = curve();
    let mut rng = Lcg(11);
    // Every point reached by a choice inside the cuts at alpha grades at
    // least alpha under that function.
    for _ in 0..60 {
        let m = [M::Upper, M::Primary, M::Lower][(rng.unit() * 3.0) as usize % 3];
        let alpha = Alpha::try_new(rng.unit() * if m == M::Lower { 0.5 } else { 1.0 }).unwrap();
        let t = rng.unit();
        let pts: Vec<[f64; 2]> = c
            .points()
            .iter()
            .map(|p| {
                let [x, y] = p.coords();
                [
                    rng.between(cut_of(x, m, alpha).unwrap()),
                    rng.between(cut_of(y, m, alpha).unwrap()),
                ]
            })
            .collect();
        let ws: Vec<f64> = weights()
            .iter()
            .map(|w| rng.between(cut_of(w, m, alpha).unwrap()))
            .collect();
        let q = reference(pts, ws).eval(t).unwrap();
        let g = c.membership(&q).unwrap().get(m);
        assert!(
            g >= alpha.get() - 1e-9,
            "{m:?} at {alpha:?}: {q:?} grades {g}"
        );
    }
    // The certified grade is at least the grade at every parameter of a
    // fine grid (brute force), and not far above the best of them.
    for _ in 0..12 {
        let q = [rng.between([-0.5, 4.5]), rng.between([-0.3, 2.8])];
        let grades = c.membership(&q).unwrap();
        for m in [M::Upper, M::Primary, M::Lower] {
            let brute = best_level(&c, m, q);
            let g = grades.get(m);
            assert!(g >= brute - 1e-9, "{m:?} {q:?}: {g} below {brute}");
            assert!(g <= brute + 1e-6, "{m:?} {q:?}: {g} far above {brute}");
        }
    }
}

#[test]
fn the_envelope_is_reached_at_vertex_choices_and_holds_every_choice() {
    use t2spline::Membership as M;
    let c = curve();
    let p = c.degree();
    let mut rng = Lcg(5);
    for k in 0..40 {
        let t = f64::from(k) / 39.0;
        let m = [M::Upper, M::Primary, M::Lower][k as usize % 3];
        let alpha = Alpha::try_new(if m == M::Lower { 0.3 } else { 0.6 }).unwrap();
        let env = c.envelope_at(t, m, alpha).unwrap().unwrap();
        let span = c.knots().find_span(t);
        let n =
            t2spline::nurbs::basis::try_basis_functions(c.knots().as_slice(), p, span, t).unwrap();
        let terms: Vec<usize> = (0..=p).map(|j| span - p + j).collect();
        let w: Vec<[f64; 2]> = terms
            .iter()
            .map(|&i| cut_of(&weights()[i], m, alpha).unwrap())
            .collect();
        for (axis, range) in env.iter().enumerate() {
            let cuts: Vec<[f64; 2]> = terms
                .iter()
                .map(|&i| cut_of(&c.points()[i].coords()[axis], m, alpha).unwrap())
                .collect();
            // Every weight at an end of its cut: the extremes.
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for mask in 0..(1u32 << terms.len()) {
                let ws: Vec<f64> = (0..terms.len())
                    .map(|j| w[j][((mask >> j) & 1) as usize])
                    .collect();
                let den: f64 = (0..terms.len()).map(|j| ws[j] * n[j]).sum();
                let at = |side: usize| {
                    (0..terms.len())
                        .map(|j| ws[j] * n[j] * cuts[j][side])
                        .sum::<f64>()
                        / den
                };
                lo = lo.min(at(0));
                hi = hi.max(at(1));
            }
            assert!(
                (range.left() - lo).abs() < 1e-12,
                "{t} {m:?}: {} vs {lo}",
                range.left()
            );
            assert!(
                (range.right() - hi).abs() < 1e-12,
                "{t} {m:?}: {} vs {hi}",
                range.right()
            );
            // Any choice inside the cuts lies inside.
            for _ in 0..20 {
                let ws: Vec<f64> = w.iter().map(|&b| rng.between(b)).collect();
                let xs: Vec<f64> = cuts.iter().map(|&b| rng.between(b)).collect();
                let den: f64 = (0..terms.len()).map(|j| ws[j] * n[j]).sum();
                let x = (0..terms.len()).map(|j| ws[j] * n[j] * xs[j]).sum::<f64>() / den;
                assert!(range.left() - 1e-12 <= x && x <= range.right() + 1e-12);
            }
        }
    }
    // Above the lower height (0.5) there is no lower envelope.
    assert!(c
        .envelope_at(0.5, M::Lower, Alpha::try_new(0.7).unwrap())
        .unwrap()
        .is_none());
}

#[test]
fn with_crisp_weights_the_envelope_is_the_curves_of_the_cut_ends() {
    let c = FuzzyCurve::try_new(2, points(), vec![1.0, 2.0, 0.7, 1.5], None).unwrap();
    let alpha = Alpha::try_new(0.4).unwrap();
    let s = c.solve(alpha);
    let (left, right) = (
        s.alpha_cut_curve(Layer::UpperLeft).unwrap(),
        s.alpha_cut_curve(Layer::UpperRight).unwrap(),
    );
    for t in c.domain().uniform(21).unwrap() {
        let env = c
            .envelope_at(t, t2spline::Membership::Upper, alpha)
            .unwrap()
            .unwrap();
        let (l, r) = (left.eval(t).unwrap(), right.eval(t).unwrap());
        for axis in 0..2 {
            assert!((env[axis].left() - l[axis]).abs() < 1e-13);
            assert!((env[axis].right() - r[axis]).abs() < 1e-13);
        }
    }
}

/// The exact section at `t` (`IntervalTerms::section`, tested on its own).
fn section_at(
    c: &FuzzyCurve<2>,
    m: t2spline::Membership,
    alpha: Alpha,
    t: f64,
    x0: f64,
) -> Option<[f64; 2]> {
    let p = c.degree();
    let span = c.knots().find_span(t);
    let basis =
        t2spline::nurbs::basis::try_basis_functions(c.knots().as_slice(), p, span, t).unwrap();
    let w = c.weight_numbers().unwrap();
    let (mut ns, mut ws, mut ps) = (Vec::new(), Vec::new(), Vec::new());
    for (k, &n) in basis.iter().enumerate() {
        let i = span - p + k;
        if n == 0.0 {
            continue;
        }
        ns.push(n);
        ws.push(cut_of(&w[i], m, alpha)?);
        let [x, y] = c.points()[i].coords();
        ps.push([cut_of(x, m, alpha)?, cut_of(y, m, alpha)?]);
    }
    t2spline::interval_weights::IntervalTerms::try_new(&ns, &ws, &ps)
        .unwrap()
        .section(t2spline::Axis::X, x0, t2spline::Axis::Y)
        .unwrap()
        .map(|iv| [iv.left(), iv.right()])
}

#[test]
fn sections_with_fuzzy_weights_hold_every_parameters_section_within_the_tolerance() {
    use t2spline::Membership as M;
    let c = curve();
    let tol = 1e-6;
    for (x0, m, a) in [
        (1.0, M::Upper, 0.0),
        (2.0, M::Upper, 0.5),
        (2.0, M::Primary, 0.2),
        (3.3, M::Lower, 0.3),
        (0.2, M::Upper, 0.1),
        (3.9, M::Primary, 0.0),
    ] {
        let alpha = Alpha::try_new(a).unwrap();
        let got = c.section(x0, m, alpha, Some(tol)).unwrap().unwrap();
        // Brute force: the exact section on a fine grid of parameters, and
        // finer around the parameters of the least and the largest value
        // (near where the line first touches a set, an end moves like the
        // square root of the parameter).
        let at = |t: f64| section_at(&c, m, alpha, t, x0);
        let grid: Vec<(f64, [f64; 2])> = (0..=20_000)
            .filter_map(|k| {
                let t = f64::from(k) / 20_000.0;
                at(t).map(|iv| (t, iv))
            })
            .collect();
        let mut exact: Vec<[f64; 2]> = grid.iter().map(|&(_, iv)| iv).collect();
        for side in [0, 1] {
            let sign = if side == 0 { 1.0 } else { -1.0 };
            let Some(&(mut centre, _)) = grid
                .iter()
                .min_by(|a, b| (sign * a.1[side]).total_cmp(&(sign * b.1[side])))
            else {
                continue;
            };
            let mut half = 2.0 / 20_000.0;
            for _ in 0..5 {
                let mut best = (f64::INFINITY, centre);
                for j in 0..=200 {
                    let t = (centre - half + 2.0 * half * f64::from(j) / 200.0).clamp(0.0, 1.0);
                    if let Some(iv) = at(t) {
                        exact.push(iv);
                        if sign * iv[side] < best.0 {
                            best = (sign * iv[side], t);
                        }
                    }
                }
                centre = best.1;
                half /= 20.0;
            }
        }
        assert!(!exact.is_empty(), "{x0} {m:?}");
        // Every parameter's section lies in the answer.
        for iv in &exact {
            assert!(
                got.iter()
                    .any(|g| g[0] <= iv[0] + 1e-12 && iv[1] <= g[1] + 1e-12),
                "{x0} {m:?}: {iv:?} not in {got:?}"
            );
        }
        // Every end of the answer is within the tolerance (and the grid's
        // error) of a value some parameter attains.
        let lo = exact.iter().map(|iv| iv[0]).fold(f64::INFINITY, f64::min);
        let hi = exact
            .iter()
            .map(|iv| iv[1])
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(
            got.first().unwrap()[0] >= lo - tol - 1e-7,
            "{x0} {m:?}: {got:?} vs {lo}"
        );
        assert!(
            got.last().unwrap()[1] <= hi + tol + 1e-7,
            "{x0} {m:?}: {got:?} vs {hi}"
        );
    }
    // Above every lower height: no lower cut.
    assert_eq!(
        c.section(2.0, M::Lower, Alpha::try_new(0.8).unwrap(), Some(tol))
            .unwrap(),
        None
    );
}
