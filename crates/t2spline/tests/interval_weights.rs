//! Curves with uncertain weights (docs/method.md §15): the envelope, the
//! support function, membership and sections at one parameter against brute
//! force over every vertex choice (every weight at an end of its cut, every
//! point at a corner of its box), against sampled admissible choices, and
//! against the crisp-weight curve; nesting as property tests.
//!
//! The independent reference for membership and sections in the plane is the
//! convex hull of the vertex choices' points: the set at `t` is the convex
//! hull of these points (docs/method.md §15, "the set is convex"), so a point
//! is a member iff it lies in that polygon and a section is where the
//! polygon crosses the line.

use proptest::prelude::*;
use t2spline::interval_weights::{weighted_average_range, IntervalCurve, IntervalTerms};
use t2spline::reduction::discrete::SampledSet;
use t2spline::strategies::{cases, seeded_uniform, test_size};
use t2spline::{Alpha, Axis, Error, Layer, NurbsCurve};

type Rng = Box<dyn FnMut() -> f64>;

fn rng(seed: u64) -> Rng {
    Box::new(seeded_uniform(seed))
}

/// Random terms with `n` terms in `D` coordinates: basis values summing to
/// 1 (some 0 now and then), weight cuts in (0, 5], coordinate cuts in
/// [-10, 10], some crisp.
fn random_terms<const D: usize>(r: &mut Rng, n: usize) -> IntervalTerms<D> {
    let mut basis: Vec<f64> = (0..n).map(|_| if r() < 0.1 { 0.0 } else { r() }).collect();
    if basis.iter().all(|&b| b == 0.0) {
        basis[0] = 1.0;
    }
    let sum: f64 = basis.iter().sum();
    basis.iter_mut().for_each(|b| *b /= sum);
    let weights: Vec<[f64; 2]> = (0..n)
        .map(|_| {
            let a = 0.05 + 2.0 * r();
            let b = if r() < 0.15 { a } else { a + 3.0 * r() };
            [a, b]
        })
        .collect();
    let points: Vec<[[f64; 2]; D]> = (0..n)
        .map(|_| {
            std::array::from_fn(|_| {
                let a = 20.0 * r() - 10.0;
                let b = if r() < 0.15 { a } else { a + 4.0 * r() };
                [a, b]
            })
        })
        .collect();
    IntervalTerms::try_new(&basis, &weights, &points).expect("valid terms")
}

/// The point of one choice, summed plainly.
fn point<const D: usize>(terms: &IntervalTerms<D>, w: &[f64], p: &[[f64; D]]) -> [f64; D] {
    let den: f64 = terms.basis().iter().zip(w).map(|(n, w)| n * w).sum();
    std::array::from_fn(|k| {
        terms
            .basis()
            .iter()
            .zip(w)
            .zip(p)
            .map(|((n, w), c)| n * w * c[k])
            .sum::<f64>()
            / den
    })
}

/// Every vertex choice's point: `(2·2^D)^n` of them.
fn vertices<const D: usize>(terms: &IntervalTerms<D>) -> Vec<[f64; D]> {
    let n = terms.basis().len();
    let per = 2usize << D;
    let total = per.pow(n as u32);
    let mut out = Vec::with_capacity(total);
    for mut code in 0..total {
        let mut w = vec![0.0; n];
        let mut p = vec![[0.0; D]; n];
        for i in 0..n {
            let c = code % per;
            code /= per;
            w[i] = terms.weights()[i][c & 1];
            p[i] = std::array::from_fn(|k| terms.points()[i][k][(c >> (k + 1)) & 1]);
        }
        out.push(point(terms, &w, &p));
    }
    out
}

/// A random admissible choice (ends now and then) and its point.
fn sample<const D: usize>(terms: &IntervalTerms<D>, r: &mut Rng) -> [f64; D] {
    let mut pick = |[a, b]: [f64; 2]| {
        let u = r();
        if u < 0.2 {
            a
        } else if u < 0.4 {
            b
        } else {
            a + (b - a) * r()
        }
    };
    let w: Vec<f64> = terms.weights().iter().map(|&c| pick(c)).collect();
    let p: Vec<[f64; D]> = terms
        .points()
        .iter()
        .map(|c| std::array::from_fn(|k| pick(c[k])))
        .collect();
    point(terms, &w, &p)
}

fn extent<const D: usize>(terms: &IntervalTerms<D>) -> f64 {
    terms
        .envelope()
        .iter()
        .map(|i| i.width().max(i.left().abs()).max(i.right().abs()))
        .fold(1e-300, f64::max)
}

/// The convex hull, counter-clockwise (Andrew's monotone chain), without
/// collinear points.
fn hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut p = points.to_vec();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut lower: Vec<[f64; 2]> = Vec::new();
    for &q in &p {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], q) <= 0.0 {
            lower.pop();
        }
        lower.push(q);
    }
    let mut upper: Vec<[f64; 2]> = Vec::new();
    for &q in p.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], q) <= 0.0 {
            upper.pop();
        }
        upper.push(q);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// The least signed distance of `q` from the hull's edge lines: positive
/// inside, negative outside.
fn hull_depth(h: &[[f64; 2]], q: [f64; 2]) -> f64 {
    (0..h.len())
        .map(|i| {
            let (a, b) = (h[i], h[(i + 1) % h.len()]);
            let e = [b[0] - a[0], b[1] - a[1]];
            ((e[0]) * (q[1] - a[1]) - (e[1]) * (q[0] - a[0])) / e[0].hypot(e[1])
        })
        .fold(f64::INFINITY, f64::min)
}

/// Where the hull crosses `x = x0`: `[least y, largest y]`.
fn hull_section(h: &[[f64; 2]], x0: f64) -> Option<[f64; 2]> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..h.len() {
        let (a, b) = (h[i], h[(i + 1) % h.len()]);
        if a[0].min(b[0]) <= x0 && x0 <= a[0].max(b[0]) {
            let ys = if a[0] == b[0] {
                [a[1], b[1]]
            } else {
                let y = a[1] + (b[1] - a[1]) * (x0 - a[0]) / (b[0] - a[0]);
                [y, y]
            };
            for y in ys {
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
    }
    (lo <= hi).then_some([lo, hi])
}

#[test]
fn envelope_contains_every_sample_and_its_ends_are_vertices() {
    let mut r = rng(1);
    for case in 0..test_size(60, 400) {
        let n = 1 + case % 4;
        let terms = random_terms::<2>(&mut r, n);
        let env = terms.envelope();
        let tol = 1e-12 * extent(&terms);
        for _ in 0..200 {
            let q = sample(&terms, &mut r);
            for k in 0..2 {
                assert!(
                    env[k].left() - tol <= q[k] && q[k] <= env[k].right() + tol,
                    "{case} {k}: {q:?} outside {env:?}"
                );
            }
        }
        let all = vertices(&terms);
        for (k, axis) in [Axis::X, Axis::Y].into_iter().enumerate() {
            let lo = all.iter().map(|v| v[k]).fold(f64::INFINITY, f64::min);
            let hi = all.iter().map(|v| v[k]).fold(f64::NEG_INFINITY, f64::max);
            assert!(
                (env[k].left() - lo).abs() <= tol,
                "{case} {k}: {} vs {lo}",
                env[k].left()
            );
            assert!(
                (env[k].right() - hi).abs() <= tol,
                "{case} {k}: {} vs {hi}",
                env[k].right()
            );
            // The reported switch points are vertex choices that attain the ends.
            let [least, largest] = terms.envelope_vertices(axis).expect("an axis");
            for (v, end) in [(least, env[k].left()), (largest, env[k].right())] {
                for (i, w) in v.weights().iter().enumerate() {
                    assert!(
                        terms.weights()[i].contains(w),
                        "{case}: weight {w} not an end"
                    );
                }
                let p = point(&terms, v.weights(), v.corners());
                assert!((p[k] - end).abs() <= tol, "{case} {k}: {p:?} vs {end}");
                assert!((v.point()[k] - end).abs() <= tol);
            }
        }
    }
}

#[test]
fn envelope_in_three_dimensions_is_the_extremes_of_the_vertices() {
    let mut r = rng(2);
    for case in 0..test_size(20, 120) {
        let n = 1 + case % 3;
        let terms = random_terms::<3>(&mut r, n);
        let env = terms.envelope();
        let tol = 1e-12 * extent(&terms);
        let all = vertices(&terms);
        for k in 0..3 {
            let lo = all.iter().map(|v| v[k]).fold(f64::INFINITY, f64::min);
            let hi = all.iter().map(|v| v[k]).fold(f64::NEG_INFINITY, f64::max);
            assert!((env[k].left() - lo).abs() <= tol && (env[k].right() - hi).abs() <= tol);
        }
    }
}

#[test]
fn support_is_the_largest_projection_of_a_vertex() {
    let mut r = rng(3);
    for case in 0..test_size(60, 400) {
        let n = 1 + case % 4;
        let terms = random_terms::<2>(&mut r, n);
        let all = vertices(&terms);
        let tol = 1e-12 * extent(&terms);
        for _ in 0..8 {
            let a = std::f64::consts::TAU * r();
            let d = [a.cos(), a.sin()];
            let brute = all
                .iter()
                .map(|v| d[0] * v[0] + d[1] * v[1])
                .fold(f64::NEG_INFINITY, f64::max);
            let h = terms.support(d).expect("a direction");
            assert!((h - brute).abs() <= 2.0 * tol, "{case}: {h} vs {brute}");
            let v = terms.support_vertex(d).expect("a direction").point();
            assert!((d[0] * v[0] + d[1] * v[1] - brute).abs() <= 2.0 * tol);
            // Homogeneous of degree 1.
            let h3 = terms
                .support([3.0 * d[0], 3.0 * d[1]])
                .expect("a direction");
            assert!((h3 - 3.0 * h).abs() <= 6.0 * tol);
        }
    }
}

#[test]
fn crisp_weights_give_the_crisp_weight_curves_of_the_ends() {
    let mut r = rng(4);
    for case in 0..test_size(40, 300) {
        let degree = 1 + case % 4;
        let count = degree + 1 + case % 3;
        let weights: Vec<f64> = (0..count).map(|_| 0.2 + 3.0 * r()).collect();
        let cuts: Vec<[[f64; 2]; 2]> = (0..count)
            .map(|_| {
                std::array::from_fn(|_| {
                    let a = 10.0 * r() - 5.0;
                    [a, a + 2.0 * r()]
                })
            })
            .collect();
        let curve = IntervalCurve::try_new(
            degree,
            cuts.clone(),
            weights.iter().map(|&w| [w, w]).collect(),
            None,
        )
        .expect("a curve");
        let end = |side: usize| {
            NurbsCurve::try_clamped(
                degree,
                cuts.iter().map(|c| [c[0][side], c[1][side]]).collect(),
                weights.clone(),
            )
            .expect("a crisp curve")
        };
        let (left, right) = (end(0), end(1));
        for j in 0..=10 {
            let t = j as f64 / 10.0;
            let env = curve.envelope(t).expect("in the domain");
            let (l, h) = (left.eval(t).expect("t"), right.eval(t).expect("t"));
            for k in 0..2 {
                let tol = 1e-14 * (1.0 + l[k].abs() + h[k].abs());
                assert!(
                    (env[k].left() - l[k]).abs() <= tol,
                    "{case} {t} {k}: {env:?} {l:?}"
                );
                assert!(
                    (env[k].right() - h[k]).abs() <= tol,
                    "{case} {t} {k}: {env:?} {h:?}"
                );
            }
            // A crisp curve (crisp points too) is one point: the set is that point.
            let q = left.eval(t).expect("t");
            let point_curve = IntervalCurve::try_new(
                degree,
                cuts.iter().map(|c| [[c[0][0]; 2], [c[1][0]; 2]]).collect(),
                weights.iter().map(|&w| [w, w]).collect(),
                None,
            )
            .expect("a curve");
            assert!(point_curve.contains(t, q).expect("finite"));
            assert!(!point_curve
                .contains(t, [q[0] + 1e-6, q[1]])
                .expect("finite"));
        }
    }
}

#[test]
fn crisp_weights_give_the_alpha_cut_curves_of_a_run() {
    // The shipped example at alpha = 0.4: its cuts with its crisp weights as
    // interval curves; the envelope at t is today's stage-2 upper (and
    // primary) cut curves at t.
    let curve = t2spline::strategies::paper_example();
    for a in [0.0, 0.4, 0.6, 1.0] {
        let alpha = Alpha::try_new(a).expect("a level");
        let solution = curve.solve(alpha);
        for (membership, left, right) in [
            (0, Layer::UpperLeft, Layer::UpperRight),
            (1, Layer::PrimaryLeft, Layer::PrimaryRight),
        ] {
            let cuts: Vec<[[f64; 2]; 2]> = curve
                .points()
                .iter()
                .map(|p| {
                    std::array::from_fn(|k| {
                        let cut = p.coords()[k].alpha_cut(alpha);
                        let c = if membership == 0 {
                            cut.upper()
                        } else {
                            cut.primary()
                        };
                        [c.left(), c.right()]
                    })
                })
                .collect();
            let weights: Vec<[f64; 2]> = curve.weights().iter().map(|&w| [w, w]).collect();
            let interval = IntervalCurve::try_new(
                curve.degree(),
                cuts,
                weights,
                Some(curve.knots().as_slice().to_vec()),
            )
            .expect("a curve");
            let (lc, rc) = (
                solution
                    .alpha_cut_curve(left)
                    .expect("upper and primary cuts exist"),
                solution
                    .alpha_cut_curve(right)
                    .expect("upper and primary cuts exist"),
            );
            for j in 0..=20 {
                let t = j as f64 / 20.0;
                let env = interval.envelope(t).expect("in the domain");
                let (l, r) = (lc.eval(t).expect("t"), rc.eval(t).expect("t"));
                for k in 0..2 {
                    assert!(
                        (env[k].left() - l[k]).abs() <= 1e-14 * (1.0 + l[k].abs()),
                        "{a} {t} {k}"
                    );
                    assert!(
                        (env[k].right() - r[k]).abs() <= 1e-14 * (1.0 + r[k].abs()),
                        "{a} {t} {k}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_km_range_is_the_discrete_centroid_of_the_reductions() {
    // Sorted values with lmf ≤ umf are a sampled interval type-2 set: its
    // centroid by KM, EKM and EIASC (reduction::discrete) is the same
    // weighted-average range.
    let mut r = rng(8);
    for case in 0..test_size(200, 2000) {
        let n = 1 + case % 9;
        let mut x: Vec<f64> = (0..n).map(|_| 10.0 * r() - 5.0).collect();
        x.sort_by(f64::total_cmp);
        let lmf: Vec<f64> = (0..n).map(|_| 0.05 + r()).collect();
        let umf: Vec<f64> = lmf.iter().map(|a| a + 2.0 * r()).collect();
        let weights: Vec<[f64; 2]> = lmf.iter().zip(&umf).map(|(&a, &b)| [a, b]).collect();
        let ours = weighted_average_range(&x, &weights).expect("valid");
        let set = SampledSet::try_new(&x, &lmf, &umf).expect("a sampled set");
        for c in [set.km(), set.ekm(), set.eiasc()] {
            assert!(
                (ours.left() - c.left()).abs() <= 1e-13 * (1.0 + c.left().abs()),
                "{case}"
            );
            assert!(
                (ours.right() - c.right()).abs() <= 1e-13 * (1.0 + c.right().abs()),
                "{case}"
            );
        }
    }
}

#[test]
fn membership_agrees_with_the_hull_of_the_vertices() {
    let mut r = rng(5);
    let (mut inside, mut outside) = (0, 0);
    for case in 0..test_size(60, 400) {
        let n = 1 + case % 4;
        let terms = random_terms::<2>(&mut r, n);
        let h = hull(&vertices(&terms));
        if h.len() < 3 {
            continue;
        }
        let env = terms.envelope();
        let size = extent(&terms);
        for _ in 0..60 {
            let q: [f64; 2] = std::array::from_fn(|k| {
                let w = env[k].width().max(1e-3);
                env[k].left() - 0.2 * w + 1.4 * w * r()
            });
            let depth = hull_depth(&h, q);
            if depth.abs() <= 1e-9 * size {
                continue;
            }
            let member = terms.contains(q).expect("finite");
            assert_eq!(member, depth > 0.0, "{case}: {q:?} depth {depth}");
            if member {
                inside += 1;
            } else {
                outside += 1;
                // The separating direction is a real one: d·q > max over vertices.
                let d = terms
                    .separating_direction(q)
                    .expect("finite")
                    .expect("outside");
                let reach = h
                    .iter()
                    .map(|v| d[0] * v[0] + d[1] * v[1])
                    .fold(f64::MIN, f64::max);
                assert!(d[0] * q[0] + d[1] * q[1] > reach);
            }
        }
        // Every point reached by a sampled choice and every vertex is a member.
        for _ in 0..40 {
            let q = sample(&terms, &mut r);
            assert!(terms.contains(q).expect("finite"), "{case}: sampled {q:?}");
        }
        for &v in &h {
            assert!(terms.contains(v).expect("finite"), "{case}: vertex {v:?}");
        }
        // Outside the envelope: never a member.
        for k in 0..2 {
            let mut q = sample(&terms, &mut r);
            q[k] = env[k].right() + 1e-6 * size;
            assert!(!terms.contains(q).expect("finite"));
            q[k] = env[k].left() - 1e-6 * size;
            assert!(!terms.contains(q).expect("finite"));
        }
    }
    assert!(
        inside > 100 && outside > 100,
        "{inside} inside, {outside} outside"
    );
}

#[test]
fn the_box_of_the_envelopes_is_not_the_set() {
    // Points (0, 0) and (1, 1), weights in [1, 3]: the set is a segment on
    // the diagonal; the corner (1/4, 3/4) of the envelopes' box is not in it.
    let terms = IntervalTerms::try_new(
        &[0.5, 0.5],
        &[[1.0, 3.0]; 2],
        &[[[0.0, 0.0]; 2], [[1.0, 1.0]; 2]],
    )
    .expect("valid");
    let [x, y] = terms.envelope();
    for (found, expected) in [
        (x.left(), 0.25),
        (x.right(), 0.75),
        (y.left(), 0.25),
        (y.right(), 0.75),
    ] {
        assert!((found - expected).abs() < 1e-15, "{found} vs {expected}");
    }
    assert!(terms.contains([0.25, 0.25]).expect("finite"));
    assert!(terms.contains([0.6, 0.6]).expect("finite"));
    assert!(!terms.contains([0.25, 0.75]).expect("finite"));
    assert!(!terms.contains([0.5, 0.5 + 1e-9]).expect("finite"));
}

#[test]
fn membership_in_three_dimensions() {
    let mut r = rng(6);
    for case in 0..test_size(30, 200) {
        let n = 1 + case % 4;
        let terms = random_terms::<3>(&mut r, n);
        for _ in 0..30 {
            let q = sample(&terms, &mut r);
            assert!(terms.contains(q).expect("finite"), "{case}: sampled {q:?}");
        }
        // A plane curve lifted to a crisp height: its set is the plane set at
        // that height, so membership is the plane's hull test.
        let flat = IntervalTerms::<3>::try_new(
            terms.basis(),
            terms.weights(),
            &terms
                .points()
                .iter()
                .map(|p| [p[0], p[1], [1.5, 1.5]])
                .collect::<Vec<_>>(),
        )
        .expect("valid");
        let plane = IntervalTerms::<2>::try_new(
            terms.basis(),
            terms.weights(),
            &terms
                .points()
                .iter()
                .map(|p| [p[0], p[1]])
                .collect::<Vec<_>>(),
        )
        .expect("valid");
        let h = hull(&vertices(&plane));
        if h.len() < 3 {
            continue;
        }
        let env = plane.envelope();
        let size = extent(&plane);
        for _ in 0..30 {
            let q: [f64; 2] = std::array::from_fn(|k| {
                let w = env[k].width().max(1e-3);
                env[k].left() - 0.2 * w + 1.4 * w * r()
            });
            let depth = hull_depth(&h, q);
            if depth.abs() <= 1e-9 * size {
                continue;
            }
            assert_eq!(
                flat.contains([q[0], q[1], 1.5]).expect("finite"),
                depth > 0.0,
                "{case}: {q:?}"
            );
            assert!(!flat.contains([q[0], q[1], 1.5 + 1e-6]).expect("finite"));
        }
    }
}

#[test]
fn sections_are_where_the_hull_crosses_the_line() {
    let mut r = rng(7);
    let mut narrower = 0;
    for case in 0..test_size(60, 400) {
        let n = 1 + case % 4;
        let terms = random_terms::<2>(&mut r, n);
        let h = hull(&vertices(&terms));
        if h.len() < 3 {
            continue;
        }
        let env = terms.envelope();
        let size = extent(&terms);
        for j in 0..12 {
            let x0 = if j == 0 {
                env[0].left()
            } else if j == 1 {
                env[0].right()
            } else {
                env[0].left() + env[0].width() * r()
            };
            let s = terms
                .section(Axis::X, x0, Axis::Y)
                .expect("axes")
                .expect("reached");
            // The hull's own x range may differ from the envelope's by rounding.
            let (hx0, hx1) = h
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v[0]), b.max(v[0]))
                });
            let [lo, hi] =
                hull_section(&h, x0.clamp(hx0, hx1)).expect("the hull reaches the envelope's x");
            let tol = 1e-10 * size;
            // The ends of a vertical edge are ill-conditioned in x0: only the
            // interior is held to the tolerance.
            if j >= 2 {
                assert!(
                    (s.left() - lo).abs() <= tol,
                    "{case} x0 = {x0}: {s:?} vs [{lo}, {hi}]"
                );
                assert!(
                    (s.right() - hi).abs() <= tol,
                    "{case} x0 = {x0}: {s:?} vs [{lo}, {hi}]"
                );
            }
            // Never narrower than the truth.
            assert!(
                s.left() <= lo + tol && s.right() >= hi - tol,
                "{case}: {s:?} vs [{lo}, {hi}]"
            );
            assert!(
                env[1].left() <= s.left() && s.right() <= env[1].right(),
                "{case}: {s:?} {env:?}"
            );
            if s.width() < env[1].width() * (1.0 - 1e-6) {
                narrower += 1;
            }
        }
        assert_eq!(
            terms
                .section(Axis::X, env[0].right() + 1e-6 * size, Axis::Y)
                .expect("axes"),
            None
        );
        // Reversed roles: the section of x along y.
        let x1 = env[1].left() + env[1].width() * r();
        let s = terms
            .section(Axis::Y, x1, Axis::X)
            .expect("axes")
            .expect("reached");
        let swapped: Vec<[f64; 2]> = h.iter().map(|v| [v[1], v[0]]).collect();
        let [lo, hi] = hull_section(&hull(&swapped), x1).expect("reached");
        assert!((s.left() - lo).abs() <= 1e-10 * size && (s.right() - hi).abs() <= 1e-10 * size);
    }
    assert!(
        narrower > 50,
        "{narrower} sections narrower than the y envelope"
    );
}

#[test]
fn a_section_strictly_inside_the_envelope() {
    // Points (0, 0) and (1, 2) with weights in [1, 3]: the set is the segment
    // from (1/4, 1/2) to (3/4, 3/2). At x = 1/2 only y = 1, though the y
    // envelope is [1/2, 3/2]: its ends need x = 1/4 and x = 3/4.
    let terms = IntervalTerms::try_new(
        &[0.5, 0.5],
        &[[1.0, 3.0]; 2],
        &[[[0.0, 0.0]; 2], [[1.0, 1.0], [2.0, 2.0]]],
    )
    .expect("valid");
    let y = terms.envelope()[1];
    assert!(
        (y.left() - 0.5).abs() < 1e-15 && (y.right() - 1.5).abs() < 1e-15,
        "{y:?}"
    );
    let s = terms
        .section(Axis::X, 0.5, Axis::Y)
        .expect("axes")
        .expect("reached");
    assert!(
        (s.left() - 1.0).abs() < 1e-12 && (s.right() - 1.0).abs() < 1e-12,
        "{s:?}"
    );
    // With a fuzzy y on the second point, [1.5, 2.5]: at x = 1/2 the weights are
    // equal (θ₁ = θ₂), so y = (0 + P₂ᵧ)/2 ∈ [3/4, 5/4]; the envelope is [1/2, 15/8].
    let terms = IntervalTerms::try_new(
        &[0.5, 0.5],
        &[[1.0, 3.0]; 2],
        &[[[0.0, 0.0]; 2], [[1.0, 1.0], [1.5, 2.5]]],
    )
    .expect("valid");
    let y = terms.envelope()[1];
    assert!(
        (y.left() - 0.375).abs() < 1e-15 && (y.right() - 1.875).abs() < 1e-15,
        "{y:?}"
    );
    let s = terms
        .section(Axis::X, 0.5, Axis::Y)
        .expect("axes")
        .expect("reached");
    assert!(
        (s.left() - 0.75).abs() < 1e-12 && (s.right() - 1.25).abs() < 1e-12,
        "{s:?}"
    );
}

#[test]
fn weighted_average_range_is_the_km_interval() {
    let r = weighted_average_range(&[1.0, 2.0, 3.0], &[[0.2, 0.6], [0.5, 1.0], [0.2, 0.6]])
        .expect("valid");
    assert!((r.left() - 22.0 / 13.0).abs() < 1e-15 && (r.right() - 30.0 / 13.0).abs() < 1e-15);
}

#[test]
fn bad_input_is_an_error_naming_its_place() {
    let ok_points = [[[0.0, 1.0], [0.0, 1.0]]; 2];
    let e = |basis: &[f64], weights: &[[f64; 2]], points: &[[[f64; 2]; 2]]| {
        IntervalTerms::try_new(basis, weights, points)
            .expect_err("invalid")
            .to_string()
    };
    assert_eq!(
        e(&[0.5, 0.5], &[[1.0, 1.0], [0.0, 1.0]], &ok_points),
        "weights[1] = 0 must be finite and greater than 0"
    );
    assert_eq!(
        e(&[0.5, 0.5], &[[1.0, 1.0], [-1.0, 1.0]], &ok_points),
        "weights[1] = -1 must be finite and greater than 0"
    );
    assert_eq!(
        e(&[0.5, 0.5], &[[1.0, f64::NAN], [1.0, 1.0]], &ok_points),
        "weights[0] = NaN must be finite and greater than 0"
    );
    assert_eq!(
        e(&[0.5, 0.5], &[[1.0, 1.0], [3.0, 2.0]], &ok_points),
        "weights[1] = [3, 2] is out of order: its left end is above its right end"
    );
    assert_eq!(
        e(&[0.5, 0.5], &[[1.0, 1e151], [1.0, 1.0]], &ok_points),
        "weights[0] = 1e151 is outside [1e-150, 1e150]"
    );
    assert_eq!(
        e(
            &[0.5, 0.5],
            &[[1.0, 1.0]; 2],
            &[[[0.0, 1.0], [2.0, 1.0]], [[0.0, 1.0]; 2]]
        ),
        "points[0].y: the order left <= right is broken: 2 > 1"
    );
    assert_eq!(
        e(
            &[0.5, 0.5],
            &[[1.0, 1.0]; 2],
            &[[[0.0, 1.0]; 2], [[f64::NAN, 1.0], [0.0, 1.0]]]
        ),
        "points[1].x: left = NaN is not a finite number"
    );
    assert_eq!(
        e(&[0.5, f64::NAN], &[[1.0, 1.0]; 2], &ok_points),
        "basis[1] = NaN must be a finite number at least 0"
    );
    assert_eq!(
        e(&[0.0, 0.0], &[[1.0, 1.0]; 2], &ok_points),
        "basis[0] = 0 is 0, as every basis value is; at least one must be greater than 0"
    );
    assert_eq!(
        e(&[0.5], &[[1.0, 1.0]; 2], &ok_points),
        "weights: expected 1, got 2"
    );
    // The limit counts terms with a basis value above 0.
    let many = vec![[[0.0, 1.0]; 2]; 200];
    let mut basis = vec![0.0; 200];
    assert!(matches!(
        IntervalTerms::try_new(&vec![0.005; 200], &[[1.0, 2.0]; 200], &many),
        Err(Error::TooManyTerms {
            count: 200,
            limit: 128
        })
    ));
    basis[7] = 0.5;
    basis[8] = 0.5;
    let sparse =
        IntervalTerms::try_new(&basis, &[[1.0, 2.0]; 200], &many).expect("two terms count");
    assert!(sparse.contains([0.5, 0.5]).expect("finite"));
    let terms = IntervalTerms::try_new(&[0.5, 0.5], &[[1.0, 2.0]; 2], &ok_points).expect("valid");
    assert!(matches!(
        terms.contains([f64::NAN, 0.0]),
        Err(Error::QueryPoint { axis: Axis::X, .. })
    ));
    assert!(terms.section(Axis::X, f64::INFINITY, Axis::Y).is_err());
    assert!(terms.support([f64::NAN, 1.0]).is_err());
    // The curve: parameters outside the domain, counts, knots.
    let curve =
        IntervalCurve::try_new(1, ok_points.to_vec(), vec![[1.0, 2.0]; 2], None).expect("valid");
    assert!(matches!(
        curve.envelope(1.5),
        Err(Error::OutOfDomain { .. })
    ));
    assert!(matches!(
        curve.envelope(f64::NAN),
        Err(Error::OutOfDomain { .. })
    ));
    assert!(matches!(
        IntervalCurve::try_new(1, ok_points.to_vec(), vec![[1.0, 2.0]; 3], None),
        Err(Error::WeightCount {
            expected: 2,
            found: 3
        })
    ));
    assert!(IntervalCurve::try_new(3, ok_points.to_vec(), vec![[1.0, 2.0]; 2], None).is_err());
    assert!(IntervalCurve::try_new(1, ok_points.to_vec(), vec![[2.0, 1.0]; 2], None).is_err());
}

#[test]
fn the_curve_hands_the_span_terms_on() {
    let points: Vec<[[f64; 2]; 2]> = (0..5)
        .map(|i| {
            [
                [i as f64, i as f64 + 0.5],
                [(i * i) as f64 * 0.3, (i * i) as f64 * 0.3 + 1.0],
            ]
        })
        .collect();
    let weights: Vec<[f64; 2]> = (0..5).map(|i| [1.0, 1.0 + i as f64]).collect();
    let curve = IntervalCurve::try_new(2, points.clone(), weights.clone(), None).expect("valid");
    for t in [0.0, 0.2, 1.0 / 3.0, 0.5, 0.9, 1.0] {
        let terms = curve.terms(t).expect("in the domain");
        assert_eq!(terms.basis().len(), 3);
        let sum: f64 = terms.basis().iter().sum();
        assert!((sum - 1.0).abs() < 1e-15);
        // The same set as with all five terms and zero basis values elsewhere.
        let span = curve.knots().find_span(t);
        let mut basis = vec![0.0; 5];
        for (j, &b) in terms.basis().iter().enumerate() {
            basis[span - 2 + j] = b;
        }
        let all = IntervalTerms::try_new(&basis, &weights, &points).expect("valid");
        for (a, b) in terms.envelope().iter().zip(all.envelope()) {
            assert!((a.left() - b.left()).abs() < 1e-13 && (a.right() - b.right()).abs() < 1e-13);
        }
    }
}

/// Terms in the plane from proptest's draws, with a second set of cuts
/// inside the first (each end moved inwards by a fraction of the width).
#[allow(clippy::type_complexity)]
fn nested_terms() -> impl Strategy<Value = (IntervalTerms<2>, IntervalTerms<2>)> {
    (1usize..=4).prop_flat_map(|n| {
        (
            prop::collection::vec(0.01f64..1.0, n),
            prop::collection::vec((0.05f64..3.0, 0.0f64..3.0, 0.0f64..1.0, 0.0f64..1.0), n),
            prop::collection::vec(
                ((-10.0f64..10.0, 0.0f64..4.0), (-10.0f64..10.0, 0.0f64..4.0)),
                n,
            ),
            prop::collection::vec((0.0f64..1.0, 0.0f64..1.0, 0.0f64..1.0, 0.0f64..1.0), n),
        )
            .prop_map(|(basis, w, p, shrink)| {
                let shrunk = |[a, b]: [f64; 2], s: f64, t: f64| {
                    let lo = a + (b - a) * 0.5 * s;
                    let hi = (b - (b - a) * 0.5 * t).max(lo);
                    [lo, hi]
                };
                let outer_w: Vec<[f64; 2]> = w.iter().map(|&(a, d, _, _)| [a, a + d]).collect();
                let inner_w: Vec<[f64; 2]> = w
                    .iter()
                    .zip(&outer_w)
                    .map(|(&(_, _, s, t), &c)| shrunk(c, s, t))
                    .collect();
                let outer_p: Vec<[[f64; 2]; 2]> = p
                    .iter()
                    .map(|&((x, dx), (y, dy))| [[x, x + dx], [y, y + dy]])
                    .collect();
                let inner_p: Vec<[[f64; 2]; 2]> = outer_p
                    .iter()
                    .zip(&shrink)
                    .map(|(c, &(a, b, s, t))| [shrunk(c[0], a, b), shrunk(c[1], s, t)])
                    .collect();
                (
                    IntervalTerms::try_new(&basis, &outer_w, &outer_p).expect("valid"),
                    IntervalTerms::try_new(&basis, &inner_w, &inner_p).expect("valid"),
                )
            })
    })
}

proptest! {
    #![proptest_config(cases(64, 1024))]

    /// Shrinking any cut shrinks the envelope and every section, and a member
    /// of the smaller set is a member of the larger.
    #[test]
    fn shrinking_cuts_shrinks_the_set((outer, inner) in nested_terms(), u in 0.0f64..1.0, qs in prop::collection::vec((0.0f64..1.0, 0.0f64..1.0), 16)) {
        let (eo, ei) = (outer.envelope(), inner.envelope());
        let tol = 1e-12 * extent(&outer);
        for k in 0..2 {
            prop_assert!(eo[k].left() <= ei[k].left() + tol && ei[k].right() <= eo[k].right() + tol);
        }
        let x0 = ei[0].left() + ei[0].width() * u;
        let si = inner.section(Axis::X, x0, Axis::Y).expect("axes");
        let so = outer.section(Axis::X, x0, Axis::Y).expect("axes");
        if let Some(si) = si {
            let so = so.expect("the larger set reaches x0 too");
            prop_assert!(so.left() <= si.left() + 1e-10 * extent(&outer), "{:?} {:?}", so, si);
            prop_assert!(si.right() <= so.right() + 1e-10 * extent(&outer), "{:?} {:?}", so, si);
        }
        for (a, b) in qs {
            let q = [
                eo[0].left() + eo[0].width() * a,
                eo[1].left() + eo[1].width() * b,
            ];
            if inner.contains(q).expect("finite") {
                prop_assert!(outer.contains(q).expect("finite"));
            }
            if !outer.contains(q).expect("finite") {
                prop_assert!(!inner.contains(q).expect("finite"));
            }
        }
        // A sampled point of the smaller set is in both.
        let mut r = rng(qs_seed(u));
        let q = sample(&inner, &mut r);
        prop_assert!(inner.contains(q).expect("finite") && outer.contains(q).expect("finite"));
    }
}

fn qs_seed(u: f64) -> u64 {
    u.to_bits()
}

/// Any `f64`, the awkward ones (NaN, ±∞, 0, subnormal, the range's ends)
/// more often than chance would draw them.
fn awkward() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(5e-324),
        Just(1e-150),
        Just(1e150),
        Just(-1e150),
        Just(f64::MAX),
        -10.0f64..10.0,
        0.0f64..5.0,
    ]
}

proptest! {
    #![proptest_config(cases(256, 4096))]

    /// Hostile input: every function returns, never panics, and what it
    /// returns is finite.
    #[test]
    fn never_panics(
        n in 1usize..5,
        values in prop::collection::vec(awkward(), 40),
        q in (awkward(), awkward(), awkward()),
        at in awkward(),
    ) {
        let v = |i: usize| values[i % values.len()];
        let basis: Vec<f64> = (0..n).map(v).collect();
        let weights: Vec<[f64; 2]> = (0..n).map(|i| [v(4 + 2 * i), v(5 + 2 * i)]).collect();
        let points: Vec<[[f64; 2]; 3]> = (0..n)
            .map(|i| std::array::from_fn(|k| [v(12 + 6 * i + 2 * k), v(13 + 6 * i + 2 * k)]))
            .collect();
        if let Ok(terms) = IntervalTerms::try_new(&basis, &weights, &points) {
            for range in terms.envelope() {
                prop_assert!(range.left().is_finite() && range.right().is_finite());
            }
            if let Ok(h) = terms.support([q.0, q.1, q.2]) {
                prop_assert!(h.is_finite());
            }
            let _ = terms.contains([q.0, q.1, q.2]);
            for (along, of) in [(Axis::X, Axis::Y), (Axis::Z, Axis::X)] {
                if let Ok(Some(s)) = terms.section(along, at, of) {
                    prop_assert!(s.left().is_finite() && s.right().is_finite());
                }
            }
        }
        let degree = n - 1;
        let flat: Vec<[[f64; 2]; 2]> = points.iter().map(|p| [p[0], p[1]]).collect();
        if let Ok(curve) = IntervalCurve::try_new(degree, flat, weights, None) {
            let _ = curve.envelope(at);
            let _ = curve.contains(at, [q.0, q.1]);
            let _ = curve.section(at, Axis::X, q.2, Axis::Y);
        }
    }
}
