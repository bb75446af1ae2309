//! The cut and fill between two fuzzy surfaces of one plan map
//! (docs/method.md §14, `FuzzySurface::measure_against`): two planes whose
//! difference crosses zero along a known line against the closed form;
//! random admissible pairs of nets (every height of either surface anywhere
//! in its cut), integrated by brute force, inside the intervals, and the
//! corner pairs `(l₁, r₂)`, `(r₁, l₂)` at their ends; nesting across levels
//! and functions; `cut − fill` the difference of the two surfaces' signed
//! volumes; a fuzzy x of the second surface refused (plans that differ:
//! `cut_fill_overlap.rs`).

mod brute;
mod terrain;

use proptest::prelude::*;
use t2spline::measure::{Level, PerMembership, SurfaceMeasureOptions, SurfaceMeasures};
use t2spline::set::MEMBERSHIPS;
use t2spline::strategies::{cases, height, number_with_height, seeded_uniform, test_size};
use t2spline::{Alpha, Error, FuzzySurface, Membership, Nt2Number, Nt2Point, NurbsSurface};
use terrain::{cumulative, net};

fn alpha(a: f64) -> Alpha {
    Alpha::try_new(a).expect("a level")
}

fn crisp(x: f64) -> Nt2Number {
    Nt2Number::try_crisp(x).expect("finite")
}

fn options(levels: &[f64]) -> SurfaceMeasureOptions {
    datum_options(levels, 0.0)
}

fn datum_options(levels: &[f64], datum: f64) -> SurfaceMeasureOptions {
    SurfaceMeasureOptions::new(levels.iter().map(|&a| alpha(a)).collect(), datum)
        .unwrap()
        .with_area(false)
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * a.abs().max(b.abs()).max(1.0)
}

/// A number `c` whose cuts at level 0 are `±s[0]`, `±s[1]`, `±s[2]` (upper,
/// primary, lower) wide, the lower function of height `h`.
fn spread(c: f64, s: [f64; 3], h: f64) -> Nt2Number {
    Nt2Number::try_new(
        c,
        [c - s[0], c + s[0]],
        [c - s[1], c + s[1]],
        [c - s[2], c + s[2]],
        h,
    )
    .expect("a number")
}

/// The surface of degree 1 over `[0, 2]²` with heights `z(x, y)` at the
/// corners.
fn square(z: impl Fn(f64, f64) -> Nt2Number) -> FuzzySurface<3> {
    let p = |x: f64, y: f64| Nt2Point::new([crisp(x), crisp(y), z(x, y)]);
    let net = vec![
        vec![p(0.0, 0.0), p(0.0, 2.0)],
        vec![p(2.0, 0.0), p(2.0, 2.0)],
    ];
    FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).expect("a net")
}

#[test]
fn two_planes_have_the_closed_form_cut_and_fill() {
    // z₁ = x + y ± (0.3, 0.15, 0.05), z₂ = 1 ± (0.2, 0.1, 0.05): shifted by
    // δ ∈ [−D, D], D the two spreads' sum, the difference z₁ − z₂ =
    // x + y − c (c = 1 − δ) is zero on the line x + y = c; below it the
    // triangle of legs c, so fill(c) = c³/6, and
    // cut − fill = ∫∫ (x + y − c) = 8 − 4c.
    let one = square(|x, y| spread(x + y, [0.3, 0.15, 0.05], 1.0));
    let two = square(|_, _| spread(1.0, [0.2, 0.1, 0.05], 1.0));
    let levels = [0.0, 0.25, 0.5, 0.75, 1.0];
    let m = one
        .measure_against(&two, &options(&levels))
        .expect("measured");
    let fill = |c: f64| c.powi(3) / 6.0;
    let cut = |c: f64| fill(c) + 8.0 - 4.0 * c;
    let (cuts, fills) = (m.cut.as_ref().expect("cut"), m.fill.as_ref().expect("fill"));
    for (f, spread) in [
        (Membership::Upper, 0.5),
        (Membership::Primary, 0.25),
        (Membership::Lower, 0.1),
    ] {
        assert_eq!(cuts.get(f).len(), levels.len(), "{f:?}");
        for (c, l) in cuts.get(f).iter().zip(fills.get(f)) {
            let d = spread * (1.0 - c.alpha);
            assert!(
                close(c.min, cut(1.0 + d), 1e-9) && close(c.max, cut(1.0 - d), 1e-9),
                "{f:?} cut {c:?}, want [{}, {}]",
                cut(1.0 + d),
                cut(1.0 - d)
            );
            assert!(
                close(l.min, fill(1.0 - d), 1e-9) && close(l.max, fill(1.0 + d), 1e-9),
                "{f:?} fill {l:?}, want [{}, {}]",
                fill(1.0 - d),
                fill(1.0 + d)
            );
            assert!(c.exact && l.exact, "{c:?} {l:?}");
            assert!(c.gap <= 1e-9 * 8.0 && l.gap <= 1e-9 * 8.0, "{c:?} {l:?}");
        }
    }
    // At level 1 both are crisp: cut 4 + 1/6, fill 1/6.
    let top = &cuts.upper[4];
    assert!(close(top.min, 4.0 + 1.0 / 6.0, 1e-12) && close(top.max, top.min, 1e-12));
    // The first surface's own volumes are those of `measure`.
    let alone = one.measure(&options(&levels)).expect("measured");
    assert_eq!(alone.volume_above, m.volume_above);
    assert_eq!(alone.volume_below, m.volume_below);
    assert!(alone.cut.is_none() && alone.fill.is_none());
}

#[test]
fn swapping_the_surfaces_swaps_cut_and_fill() {
    let one = square(|x, y| spread(x * y - 1.0, [0.4, 0.2, 0.1], 1.0));
    let two = square(|x, _| spread(x - 1.0, [0.3, 0.1, 0.0], 1.0));
    let o = options(&[0.0, 0.5, 1.0]);
    let ab = one.measure_against(&two, &o).expect("measured");
    let ba = two.measure_against(&one, &o).expect("measured");
    for f in MEMBERSHIPS {
        let pairs = [(&ab.cut, &ba.fill), (&ab.fill, &ba.cut)];
        for (x, y) in pairs {
            let (x, y) = (x.as_ref().expect("some"), y.as_ref().expect("some"));
            for (p, q) in x.get(f).iter().zip(y.get(f)) {
                assert!(close(p.min, q.min, 1e-12) && close(p.max, q.max, 1e-12));
            }
        }
    }
}

#[test]
fn a_function_without_a_cut_in_either_surface_is_left_out() {
    // The second surface's lower function reaches only 0.5.
    let one = square(|x, y| spread(x + y, [0.3, 0.15, 0.05], 1.0));
    let two = square(|_, _| spread(1.0, [0.2, 0.1, 0.05], 0.5));
    let m = one
        .measure_against(&two, &options(&[0.0, 0.25, 0.5, 0.75, 1.0]))
        .expect("measured");
    for list in [m.cut.as_ref().expect("cut"), m.fill.as_ref().expect("fill")] {
        let alphas = |f: Membership| list.get(f).iter().map(|l| l.alpha).collect::<Vec<_>>();
        assert_eq!(alphas(Membership::Upper).len(), 5);
        assert_eq!(alphas(Membership::Lower), vec![0.0, 0.25, 0.5]);
    }
}

#[test]
fn a_fuzzy_plan_in_the_second_surface_is_refused() {
    let one = square(|x, y| spread(x + y, [0.3, 0.15, 0.05], 1.0));
    let o = options(&[0.0]);
    let refused = |other: &FuzzySurface<3>, what: &str| {
        let e = one.measure_against(other, &o).expect_err("refused");
        assert!(matches!(e, Error::PlansDiffer { .. }), "{e}");
        assert!(e.to_string().contains(what), "{e}");
    };
    let w = vec![vec![1.0; 2]; 2];
    // A fuzzy x in the second surface.
    let fuzzy = spread(2.0, [0.1, 0.0, 0.0], 1.0);
    let q = |x: Nt2Number, y: f64| Nt2Point::new([x, crisp(y), crisp(0.0)]);
    let net = vec![
        vec![q(crisp(0.0), 0.0), q(crisp(0.0), 2.0)],
        vec![q(fuzzy, 0.0), q(crisp(2.0), 2.0)],
    ];
    let s = FuzzySurface::try_new([1, 1], net, w, [None, None]).expect("a net");
    refused(&s, "points[1][0].x of the second surface is fuzzy");
}

/// Two terrains of one plan (crisp increasing x and y, sheared or not,
/// rational or not), their heights drawn independently, each with its own
/// lower height.
fn pair() -> impl Strategy<Value = (FuzzySurface<3>, FuzzySurface<3>)> {
    (
        1usize..=2,
        1usize..=2,
        any::<[bool; 2]>(),
        height(),
        height(),
    )
        .prop_flat_map(|(pu, pv, [shear, rational], h1, h2)| {
            (pu + 1..=pu + 2, pv + 1..=pv + 2).prop_flat_map(move |(nu, nv)| {
                (
                    proptest::collection::vec(0.3..2.0f64, nu),
                    proptest::collection::vec(0.3..2.0f64, nv),
                    proptest::collection::vec(number_with_height(h1), nu * nv),
                    proptest::collection::vec(number_with_height(h2), nu * nv),
                    proptest::collection::vec(0.5..2.0f64, nu * nv),
                )
                    .prop_map(move |(du, dv, z1, z2, w)| {
                        let (a, b) = (cumulative(&du), cumulative(&dv));
                        let surface = |z: &[Nt2Number]| {
                            let points = (0..nu)
                                .map(|i| {
                                    (0..nv)
                                        .map(|j| {
                                            let x = a[i] + if shear { 0.1 * b[j] } else { 0.0 };
                                            Nt2Point::new([crisp(x), crisp(b[j]), z[i * nv + j]])
                                        })
                                        .collect()
                                })
                                .collect();
                            let weights = (0..nu)
                                .map(|i| {
                                    (0..nv)
                                        .map(|j| if rational { w[i * nv + j] } else { 1.0 })
                                        .collect()
                                })
                                .collect();
                            FuzzySurface::try_new([pu, pv], points, weights, [None, None])
                                .expect("a valid net")
                        };
                        (surface(&z1), surface(&z2))
                    })
            })
        })
}

/// `[cut, fill]` of two crisp surfaces of one plan by brute force: each
/// evaluated on its own at the nodes of `cells × cells` cells of 4 × 4
/// Gauss nodes per span rectangle, `|J|` from the first one's partials.
fn brute(one: &NurbsSurface<3>, two: &NurbsSurface<3>, cells: usize) -> [f64; 2] {
    let mut out = [0.0; 2];
    brute::gauss_cells(one, cells, |u, v, w| {
        let d = one.derivatives(u, v, 1).expect("in the domain");
        let p = two.eval(u, v).expect("in the domain");
        let (su, sv) = (d[1][0], d[0][1]);
        let w = w * (su[0] * sv[1] - su[1] * sv[0]).abs();
        let diff = d[0][0][2] - p[2];
        out[0] += diff.max(0.0) * w;
        out[1] += (-diff).max(0.0) * w;
    });
    out
}

/// `[cut, fill]` under function `f` at `a`, where both surfaces have a cut.
fn at(m: &SurfaceMeasures, f: Membership, a: f64) -> Option<[Level; 2]> {
    let find = |p: &Option<PerMembership<Vec<Level>>>| {
        p.as_ref()?.get(f).iter().find(|l| l.alpha == a).copied()
    };
    Some([find(&m.cut)?, find(&m.fill)?])
}

/// The largest height of either surface's box, less the least: the scale
/// of a difference.
fn depth(one: &FuzzySurface<3>, two: &FuzzySurface<3>) -> f64 {
    let (a, b) = (one.bounding_box(), two.bounding_box());
    (a.max[2].max(b.max[2]) - a.min[2].min(b.min[2])).max(1e-9)
}

proptest! {
    // Brute force at 8 × 8 cells per span is the slow part: one case by
    // default, 16 under T2SPLINE_LONG_TESTS=1.
    #![proptest_config(cases(2, 16))]

    /// Random admissible pairs of nets inside the intervals; the corner
    /// pairs `(l₁, r₂)` and `(r₁, l₂)` at the exact ends.
    #[test]
    fn admissible_pairs_lie_inside_and_corner_pairs_attain_the_ends(
        (one, two) in pair(), seed in 1u64..1000,
    ) {
        let levels = [0.0, 0.5, 1.0];
        let m = one.measure_against(&two, &options(&levels)).expect("one plan");
        let plan = m.plan_area[0];
        // Brute force's own error (the corner of max(·, 0)).
        let slack = 5e-3 * plan * depth(&one, &two);
        let mut uniform = seeded_uniform(seed);
        for f in MEMBERSHIPS {
            for &a in &levels {
                let Some([cut, fill]) = at(&m, f, a) else { continue };
                prop_assert!(cut.exact && fill.exact, "{f:?} {a}: {cut:?} {fill:?}");
                let ends = |s: &FuzzySurface<3>, right: bool| {
                    net(s, f, alpha(a), |c| if right { c.right() } else { c.left() })
                };
                let (Some(l1), Some(r1), Some(l2), Some(r2)) =
                    (ends(&one, false), ends(&one, true), ends(&two, false), ends(&two, true))
                else {
                    prop_assert!(false, "{f:?} {a}: a cut in the result but not in a surface");
                    continue;
                };
                let (low, high) = (brute(&l1, &r2, 8), brute(&r1, &l2, 8));
                prop_assert!((cut.min - low[0]).abs() <= slack, "{f:?} {a}: {cut:?} vs {}", low[0]);
                prop_assert!((cut.max - high[0]).abs() <= slack, "{f:?} {a}: {cut:?} vs {}", high[0]);
                prop_assert!((fill.min - high[1]).abs() <= slack, "{f:?} {a}: {fill:?} vs {}", high[1]);
                prop_assert!((fill.max - low[1]).abs() <= slack, "{f:?} {a}: {fill:?} vs {}", low[1]);
                for _ in 0..test_size(3, 20) {
                    let vertex = uniform() < 0.3;
                    let mut pick = |c: t2spline::Interval| {
                        let t = uniform();
                        let t = if vertex { t.round() } else { t };
                        c.left() + t * (c.right() - c.left())
                    };
                    let (Some(p), Some(q)) = (net(&one, f, alpha(a), &mut pick), net(&two, f, alpha(a), &mut pick))
                    else { continue };
                    let [c, l] = brute(&p, &q, 8);
                    prop_assert!(cut.min - slack <= c && c <= cut.max + slack, "{f:?} {a}: cut {c} outside {cut:?}");
                    prop_assert!(fill.min - slack <= l && l <= fill.max + slack, "{f:?} {a}: fill {l} outside {fill:?}");
                }
            }
        }
    }

    /// `cut − fill` at the corner pairs is the difference of the two
    /// surfaces' signed volumes `V_above − V_below` (any datum) at their
    /// extreme nets: `cut(l₁, r₂) − fill(l₁, r₂) = S(l₁) − S(r₂)`, and
    /// `cut(r₁, l₂) − fill(r₁, l₂) = S(r₁) − S(l₂)`.
    #[test]
    fn cut_less_fill_is_the_difference_of_the_signed_volumes(
        (one, two) in pair(), datum in -5.0..5.0f64,
    ) {
        let levels = [0.0, 0.3, 0.6, 1.0];
        let o = datum_options(&levels, datum);
        let m = one.measure_against(&two, &o).expect("one plan");
        let other = two.measure(&o).expect("measured");
        let tolerance = 1e-8 * m.plan_area[0] * (depth(&one, &two) + datum.abs());
        for f in MEMBERSHIPS {
            for &a in &levels {
                let Some([cut, fill]) = at(&m, f, a) else { continue };
                let find = |s: &SurfaceMeasures, p: fn(&SurfaceMeasures) -> &PerMembership<Vec<Level>>| {
                    p(s).get(f).iter().find(|l| l.alpha == a).copied().expect("a level")
                };
                let (a1, b1) = (find(&m, |s| &s.volume_above), find(&m, |s| &s.volume_below));
                let (a2, b2) = (find(&other, |s| &s.volume_above), find(&other, |s| &s.volume_below));
                // S(l) = V_above(l) − V_below(l) = min V_above − max V_below.
                let least = (a1.min - b1.max) - (a2.max - b2.min);
                let largest = (a1.max - b1.min) - (a2.min - b2.max);
                prop_assert!((cut.min - fill.max - least).abs() <= tolerance,
                    "{f:?} {a}: {} vs {least}", cut.min - fill.max);
                prop_assert!((cut.max - fill.min - largest).abs() <= tolerance,
                    "{f:?} {a}: {} vs {largest}", cut.max - fill.min);
            }
        }
    }

    /// Intervals at a higher level inside those at a lower one, and
    /// upper ⊇ primary ⊇ lower at each level.
    #[test]
    fn cut_and_fill_nest((one, two) in pair()) {
        let levels = [0.0, 0.25, 0.5, 0.75, 1.0];
        let m = one.measure_against(&two, &options(&levels)).expect("one plan");
        for list in [m.cut.as_ref().expect("cut"), m.fill.as_ref().expect("fill")] {
            for f in MEMBERSHIPS {
                for pair in list.get(f).windows(2) {
                    prop_assert!(pair[0].bracket().contains(&pair[1].bracket(), 0.0), "{f:?}: {pair:?}");
                }
            }
            for (outer, inner) in [(&list.upper, &list.primary), (&list.primary, &list.lower)] {
                for i in inner {
                    let o = outer.iter().find(|o| o.alpha == i.alpha).expect("an outer level");
                    prop_assert!(o.bracket().contains(&i.bracket(), 0.0), "{o:?} ⊉ {i:?}");
                }
            }
        }
    }
}
