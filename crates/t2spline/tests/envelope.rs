//! The envelope of a fuzzy surface (docs/method.md §12) against brute force:
//! random admissible nets (every height anywhere in its cut) and the vertex
//! nets (every height at one end) evaluated where the plan map takes each
//! plan point; nesting across levels and functions; the fast inversion of a
//! separable plan map against the general one.

mod terrain;

use proptest::prelude::*;
use t2spline::set::{EnvelopeLevel, PlanGrid, MEMBERSHIPS};
use t2spline::strategies::{cases, height, number_with_height, seeded_uniform};
use t2spline::{Alpha, Direction, FuzzySurface, Interval, Nt2Number, Nt2Point, NurbsSurface};
use terrain::{cumulative, net};

const TOLERANCE: f64 = 1e-9;

fn alpha(a: f64) -> Alpha {
    Alpha::try_new(a).expect("a level")
}

/// How a test terrain's plan map is laid out.
#[derive(Clone, Copy, Debug)]
struct Layout {
    /// x along v (columns) instead of u.
    swap: bool,
    /// x also moves with the column: not separable.
    shear: bool,
    /// Weights other than 1.
    rational: bool,
    /// x moved by rounding-sized amounts along a row (a fitted net): the
    /// separable map as a start for Newton's method.
    jitter: bool,
}

/// A surface with crisp, strictly increasing x and y on a net and fuzzy
/// heights of one lower height.
fn terrain() -> impl Strategy<Value = (FuzzySurface<3>, Layout)> {
    (1usize..=3, 1usize..=3, any::<[bool; 4]>(), height()).prop_flat_map(
        |(pu, pv, [swap, shear, rational, jitter], h)| {
            (
                pu + 1..=pu + 4,
                pv + 1..=pv + 4,
                Just((
                    pu,
                    pv,
                    Layout {
                        swap,
                        shear,
                        rational,
                        jitter,
                    },
                    h,
                )),
            )
                .prop_flat_map(|(nu, nv, (pu, pv, layout, h))| {
                    (
                        proptest::collection::vec(0.2..2.0f64, nu),
                        proptest::collection::vec(0.2..2.0f64, nv),
                        proptest::collection::vec(number_with_height(h), nu * nv),
                        proptest::collection::vec(0.3..3.0f64, nu * nv),
                    )
                        .prop_map(move |(du, dv, z, w)| {
                            let (a, b) = (cumulative(&du), cumulative(&dv));
                            let crisp = |x: f64| Nt2Number::try_crisp(x).expect("finite");
                            let points = (0..nu)
                                .map(|i| {
                                    (0..nv)
                                        .map(|j| {
                                            let (mut x, mut y) = (a[i], b[j]);
                                            if layout.jitter {
                                                x += 1e-10 * ((i * 7 + j * 3) % 5) as f64;
                                            }
                                            if layout.shear {
                                                x += 0.1 * b[j];
                                            }
                                            if layout.swap {
                                                (x, y) = (y, x);
                                            }
                                            Nt2Point::new([crisp(x), crisp(y), z[i * nv + j]])
                                        })
                                        .collect()
                                })
                                .collect();
                            let weights = (0..nu)
                                .map(|i| {
                                    (0..nv)
                                        .map(|j| if layout.rational { w[i * nv + j] } else { 1.0 })
                                        .collect()
                                })
                                .collect();
                            let s = FuzzySurface::try_new([pu, pv], points, weights, [None, None])
                                .expect("a valid net");
                            (s, layout)
                        })
                })
        },
    )
}

fn levels() -> Vec<Alpha> {
    [0.0, 0.3, 0.5, 0.8, 1.0].map(alpha).to_vec()
}

proptest! {
    #![proptest_config(cases(24, 64))]

    /// Random admissible nets stay inside the envelope where the plan map
    /// takes `(u, v)`; the two vertex nets attain its ends.
    #[test]
    fn admissible_nets_stay_inside_and_vertex_nets_attain_the_ends(
        (s, layout) in terrain(),
        st in [0.0..=1.0f64, 0.0..=1.0f64],
        seed in any::<u64>(),
    ) {
        let (u, v) = (s.domain(Direction::U).lerp(st[0]), s.domain(Direction::V).lerp(st[1]));
        let p = s.crisp_surface().eval(u, v).expect("in the domain");
        let levels = levels();
        let e = s.envelope_at(&[[p[0], p[1]]], &levels).expect("within limits");
        let mut random = seeded_uniform(seed);
        for (a, level) in levels.iter().zip(&e) {
            for m in MEMBERSHIPS {
                let Some(b) = level.get(m) else {
                    prop_assert!(net(&s, m, *a, |c| c.left()).is_none(), "{m:?} at {a:?} left out with cuts");
                    continue;
                };
                let (lo, hi) = (b.least[0], b.greatest[0]);
                prop_assert!(!lo.is_nan() && !hi.is_nan(), "{layout:?} {m:?} {a:?} at {p:?}: NODATA");
                let z_at = |n: NurbsSurface<3>| n.eval(u, v).expect("in the domain")[2];
                let least = z_at(net(&s, m, *a, |c| c.left()).expect("cuts"));
                let greatest = z_at(net(&s, m, *a, |c| c.right()).expect("cuts"));
                prop_assert!((least - lo).abs() <= TOLERANCE, "{layout:?} {m:?} {a:?}: least {lo} vs vertex net {least}");
                prop_assert!((greatest - hi).abs() <= TOLERANCE, "{layout:?} {m:?} {a:?}: greatest {hi} vs vertex net {greatest}");
                for _ in 0..6 {
                    let z = z_at(net(&s, m, *a, |c| c.left() + random() * c.width()).expect("cuts"));
                    prop_assert!(lo - TOLERANCE <= z && z <= hi + TOLERANCE, "{m:?} {a:?}: {z} outside [{lo}, {hi}]");
                }
            }
        }
    }

    /// Higher levels lie inside lower ones, and upper ⊇ primary ⊇ lower, at
    /// every cell; the separable fast path agrees with the general inversion.
    #[test]
    fn envelopes_nest_and_both_inversions_agree((s, layout) in terrain(), n in 2usize..12) {
        let grid = PlanGrid::try_new(s.plan_extent(), [n, n + 1]).expect("a grid");
        let levels = levels();
        let e = s.envelope(&grid, &levels).expect("within limits");
        prop_assert!(e.exact);
        // Within `slack` (the rounding of two sums, across levels); exactly
        // across functions at one level.
        let nested = |outer: Option<&t2spline::set::EnvelopeBounds>, inner: Option<&t2spline::set::EnvelopeBounds>, slack: f64| {
            let (Some(o), Some(i)) = (outer, inner) else { return true };
            (0..o.least.len()).all(|k| {
                i.least[k].is_nan()
                    || (o.least[k] <= i.least[k] + slack && i.greatest[k] <= o.greatest[k] + slack)
            })
        };
        for w in e.levels.windows(2) {
            for m in MEMBERSHIPS {
                prop_assert!(nested(w[0].get(m), w[1].get(m), 1e-12), "{m:?}: level {} not inside {}", w[1].alpha, w[0].alpha);
            }
        }
        for l in &e.levels {
            for b in [&l.upper, &l.primary, &l.lower].into_iter().flatten() {
                prop_assert!(b.least.iter().zip(&b.greatest).all(|(lo, hi)| lo.is_nan() || lo <= hi), "ends out of order at {}", l.alpha);
            }
            prop_assert!(nested(l.upper.as_ref(), l.primary.as_ref(), 0.0) && nested(l.primary.as_ref(), l.lower.as_ref(), 0.0));
        }
        let (xs, ys) = (grid.xs(), grid.ys());
        let points: Vec<[f64; 2]> = ys.iter().flat_map(|&y| xs.iter().map(move |&x| [x, y])).collect();
        let general = s.envelope_at(&points, &levels).expect("within limits");
        if !layout.shear {
            // A separable map covers its extent: every cell has data.
            prop_assert!(e.levels[0].upper.as_ref().is_some_and(|b| b.least.iter().all(|z| !z.is_nan())));
        }
        compare(&e.levels, &general)?;
    }
}

/// The two envelopes are equal within the tolerance, NODATA at the same cells.
fn compare(a: &[EnvelopeLevel], b: &[EnvelopeLevel]) -> Result<(), TestCaseError> {
    for (la, lb) in a.iter().zip(b) {
        for m in MEMBERSHIPS {
            let (Some(x), Some(y)) = (la.get(m), lb.get(m)) else {
                prop_assert_eq!(la.get(m).is_some(), lb.get(m).is_some());
                continue;
            };
            for (k, (p, q)) in x
                .least
                .iter()
                .zip(&y.least)
                .chain(x.greatest.iter().zip(&y.greatest))
                .enumerate()
            {
                prop_assert!(
                    (p.is_nan() && q.is_nan()) || (p - q).abs() <= 1e-8,
                    "{m:?} at {}: value {k}: {p} vs {q}",
                    la.alpha
                );
            }
        }
    }
    Ok(())
}

/// Where x and y are fuzzy, random admissible nets (x, y and z anywhere in
/// their cuts) pass above each plan point inside its envelope.
#[test]
fn fuzzy_plan_envelopes_hold_admissible_surfaces() {
    let n = |c: f64, s: f64| {
        Nt2Number::try_new(
            c,
            [c - s, c + s],
            [c - 0.6 * s, c + 0.6 * s],
            [c - 0.3 * s, c + 0.3 * s],
            1.0,
        )
        .expect("valid")
    };
    let net: Vec<Vec<Nt2Point<3>>> = (0..3)
        .map(|i| {
            (0..3)
                .map(|j| {
                    let (x, y) = (f64::from(i), f64::from(j));
                    Nt2Point::new([n(x, 0.1), n(y, 0.05), n((x - y).sin(), 0.5)])
                })
                .collect()
        })
        .collect();
    let s = FuzzySurface::try_new([2, 2], net, vec![vec![1.0; 3]; 3], [None, None]).expect("valid");
    assert!(!s.has_crisp_plan());
    let levels = [alpha(0.0), alpha(0.5)];
    let mut random = seeded_uniform(11);
    // Each point is a certified section search, seconds in a debug build: 2
    // points by default, 12 under T2SPLINE_LONG_TESTS=1.
    for _ in 0..t2spline::strategies::test_size(2, 12) {
        let a = levels[usize::from(random() < 0.5)];
        let (u, v) = (random(), random());
        let pick = |c: Interval, r: f64| c.left() + r * c.width();
        let rows: Vec<Vec<[f64; 3]>> = s
            .points()
            .chunks(3)
            .map(|row| {
                row.iter()
                    .map(|p| {
                        let cuts = p.alpha_cut(a);
                        [
                            pick(cuts[0].upper(), random()),
                            pick(cuts[1].upper(), random()),
                            pick(cuts[2].upper(), random()),
                        ]
                    })
                    .collect()
            })
            .collect();
        let admissible =
            NurbsSurface::try_clamped([2, 2], rows, vec![vec![1.0; 3]; 3]).expect("valid");
        let q = admissible.eval(u, v).expect("in the domain");
        let e = s.envelope_at(&[[q[0], q[1]]], &[a]).expect("within limits");
        let b = e[0].upper.as_ref().expect("a cut");
        let (lo, hi) = (b.least[0], b.greatest[0]);
        assert!(
            lo - 1e-6 <= q[2] && q[2] <= hi + 1e-6,
            "{q:?} at {a:?}: outside [{lo}, {hi}]"
        );
    }
}

/// The limits are checked before anything is computed.
#[test]
fn too_large_envelopes_are_refused() {
    let c = |x: f64| Nt2Number::try_crisp(x).expect("finite");
    let p = |x: f64, y: f64| Nt2Point::new([c(x), c(y), c(0.0)]);
    let net = vec![
        vec![p(0.0, 0.0), p(0.0, 1.0)],
        vec![p(1.0, 0.0), p(1.0, 1.0)],
    ];
    let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).expect("valid");
    let grid = PlanGrid::try_new([0.0, 0.0, 1.0, 1.0], [5000, 5000]).expect("a grid");
    let e = s
        .envelope(&grid, &[Alpha::ZERO; 1])
        .expect_err("150 million values");
    assert!(
        e.to_string()
            .contains("more than the limit of 100000000 values"),
        "{e}"
    );
}

proptest! {
    #![proptest_config(cases(4, 16))]

    /// Any surface (folded plan maps, fuzzy x and y, any heights) gives an
    /// envelope without panicking, its ends in order.
    #[test]
    fn any_surface_gives_an_ordered_envelope(s in t2spline::strategies::fuzzy_surface::<3>(), crisp_plan in proptest::bool::weighted(0.8)) {
        let s = if crisp_plan {
            // The same net with x and y at their crisp values.
            let [nu, nv] = s.shape();
            let c = |x: f64| Nt2Number::try_crisp(x).expect("finite");
            let rows = s.points().chunks(nv).map(|row| {
                row.iter().map(|p| {
                    let [x, y, z] = p.coords();
                    Nt2Point::new([c(x.crisp()), c(y.crisp()), *z])
                }).collect()
            }).collect::<Vec<Vec<_>>>();
            let weights = s.weights().chunks(nv).map(<[f64]>::to_vec).collect();
            let knots = [s.knots(Direction::U).as_slice().to_vec(), s.knots(Direction::V).as_slice().to_vec()];
            let [p, q] = s.degree();
            prop_assert_eq!(rows.len(), nu);
            FuzzySurface::try_new([p, q], rows, weights, knots.map(Some)).expect("the same net")
        } else {
            s
        };
        // A fuzzy plan costs a search of the set per cell and level, seconds
        // for these nets in a debug build: only at full size.
        if !crisp_plan && !t2spline::strategies::long_tests() {
            return Ok(());
        }
        let (shape, levels) = if crisp_plan {
            ([3, 3], vec![alpha(0.0), alpha(0.7)])
        } else {
            ([1, 1], vec![alpha(0.7)])
        };
        let Ok(grid) = PlanGrid::try_new(s.plan_extent(), shape) else {
            // A plan extent of no width (all x equal) has no grid.
            return Ok(());
        };
        let e = s.envelope(&grid, &levels).expect("within limits");
        for l in &e.levels {
            for b in [&l.upper, &l.primary, &l.lower].into_iter().flatten() {
                prop_assert!(b.least.iter().zip(&b.greatest).all(|(lo, hi)| (lo.is_nan() && hi.is_nan()) || lo <= hi));
            }
        }
    }
}

/// Over a crisp plan, a section at any plan point inside is the envelope
/// there: one interval per function, its ends the envelope's (the plan
/// point's parameters are found to the set view's slack, not only at the
/// nodes of the net).
#[test]
fn sections_over_a_crisp_plan_are_the_envelope_everywhere_inside() {
    let n = |c: f64, s: f64| {
        Nt2Number::try_new(
            c,
            [c - s, c + s],
            [c - 0.6 * s, c + 0.6 * s],
            [c - 0.3 * s, c + 0.3 * s],
            1.0,
        )
        .expect("valid")
    };
    let c = |x: f64| Nt2Number::try_crisp(x).expect("finite");
    let net: Vec<Vec<Nt2Point<3>>> = (0..4)
        .map(|i| {
            (0..3)
                .map(|j| {
                    let (x, y) = (100.0 * f64::from(i), 200.0 * f64::from(j));
                    Nt2Point::new([c(x), c(y), n(100.0 + (0.01 * (x - y)).sin(), 0.5)])
                })
                .collect()
        })
        .collect();
    let s = FuzzySurface::try_new([2, 2], net, vec![vec![1.0; 3]; 4], [None, None]).expect("valid");
    assert!(s.has_crisp_plan());
    let levels = [alpha(0.0), alpha(0.5)];
    for i in 1..7 {
        for j in 1..7 {
            let p = [300.0 * f64::from(i) / 7.0, 400.0 * f64::from(j) / 7.0];
            let sections = s.sections(p, &levels).expect("a section");
            let envelope = s.envelope_at(&[p], &levels).expect("an envelope");
            for (section, level) in sections.iter().zip(&envelope) {
                let intervals = section.upper.as_ref().expect("a cut");
                let bounds = level.upper.as_ref().expect("a cut");
                assert_eq!(intervals.len(), 1, "{p:?}: {intervals:?}");
                let [lo, hi] = intervals[0];
                assert!(
                    (lo - bounds.least[0]).abs() < 1e-9 && (hi - bounds.greatest[0]).abs() < 1e-9,
                    "{p:?} at {}: [{lo}, {hi}] against [{}, {}]",
                    section.alpha,
                    bounds.least[0],
                    bounds.greatest[0]
                );
            }
        }
    }
}
