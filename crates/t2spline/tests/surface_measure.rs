//! Volumes, plan areas and surface areas of a fuzzy surface
//! (docs/method.md §14) against closed forms and brute force: random
//! admissible nets (every height anywhere in its cut) and the vertex nets lie
//! inside the reported intervals, the extreme nets attain the exact ends,
//! and the intervals nest across levels and functions.

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

/// The plane `z = x + y − 1` over `[0, 2]²` (degree 1), each height's cuts
/// `±0.5`, `±0.25`, `±0.1` wide at level 0 (or crisp).
fn tilted_plane(fuzzy: bool) -> FuzzySurface<3> {
    let z = |c: f64| {
        if fuzzy {
            Nt2Number::try_new(
                c,
                [c - 0.5, c + 0.5],
                [c - 0.25, c + 0.25],
                [c - 0.1, c + 0.1],
                1.0,
            )
            .expect("a number")
        } else {
            crisp(c)
        }
    };
    let p = |x: f64, y: f64| Nt2Point::new([crisp(x), crisp(y), z(x + y - 1.0)]);
    let net = vec![
        vec![p(0.0, 0.0), p(0.0, 2.0)],
        vec![p(2.0, 0.0), p(2.0, 2.0)],
    ];
    FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).expect("a net")
}

fn options(levels: &[f64], datum: f64) -> SurfaceMeasureOptions {
    SurfaceMeasureOptions::new(levels.iter().map(|&a| alpha(a)).collect(), datum).unwrap()
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * a.abs().max(b.abs()).max(1.0)
}

#[test]
fn a_crisp_tilted_plane_has_its_closed_form_volumes_and_areas() {
    let m = tilted_plane(false)
        .measure(&options(&[0.0, 1.0], 0.0))
        .expect("measured");
    // Below z = 0: the triangle x + y < 1, legs 1.
    let (below, above) = (1.0 / 6.0, 1.0 / 6.0 + 4.0);
    for l in &m.volume_below.upper {
        assert!(
            close(l.min, below, 1e-9) && close(l.max, below, 1e-9),
            "{l:?}"
        );
        assert!(l.exact && l.gap <= 1e-9 * below, "{l:?}");
    }
    for l in &m.volume_above.primary {
        assert!(
            close(l.min, above, 1e-9) && close(l.max, above, 1e-9),
            "{l:?}"
        );
    }
    for l in &m.plan_area_below.lower {
        assert!(close(l.min, 0.5, 1e-9) && close(l.max, 0.5, 1e-9), "{l:?}");
    }
    let area = m.area.as_ref().expect("the area");
    for l in &area.upper {
        let want = 4.0 * 3f64.sqrt();
        assert!(
            close(l.min, want, 1e-9) && close(l.max, want, 1e-9),
            "{l:?}"
        );
        assert!(l.exact, "{l:?}");
    }
    assert!(close(m.plan_area[0], 4.0, 1e-12), "{:?}", m.plan_area);
}

#[test]
fn a_fuzzy_tilted_plane_moves_its_shoreline_as_the_closed_form_says() {
    let m = tilted_plane(true)
        .measure(&options(&[0.0, 0.5, 1.0], 0.0))
        .expect("measured");
    // All heights up by d: below z = 0 is the triangle x + y < 1 − d.
    let below = |d: f64| (1.0 - d).powi(3) / 6.0;
    let above = |d: f64| below(d) + 4.0 + 4.0 * d;
    let flooded = |d: f64| (1.0 - d).powi(2) / 2.0;
    for (list, spread) in [
        (&m.volume_below.upper, 0.5),
        (&m.volume_below.primary, 0.25),
        (&m.volume_below.lower, 0.1),
    ] {
        for l in list {
            let d = spread * (1.0 - l.alpha);
            assert!(
                close(l.min, below(d), 1e-9) && close(l.max, below(-d), 1e-9),
                "{l:?}"
            );
            assert!(l.exact, "{l:?}");
        }
    }
    for l in &m.volume_above.upper {
        let d = 0.5 * (1.0 - l.alpha);
        assert!(
            close(l.min, above(-d), 1e-9) && close(l.max, above(d), 1e-9),
            "{l:?}"
        );
    }
    for l in &m.plan_area_below.upper {
        let d = 0.5 * (1.0 - l.alpha);
        assert!(
            close(l.min, flooded(d), 1e-9) && close(l.max, flooded(-d), 1e-9),
            "{l:?}"
        );
    }
    // A uniform shift keeps the plane's area; other nets bend it.
    let area = m.area.as_ref().expect("the area");
    for l in &area.upper {
        assert!(
            l.min <= 4.0 * 3f64.sqrt() + 1e-9 && 4.0 * 3f64.sqrt() <= l.max + 1e-9,
            "{l:?}"
        );
    }
}

#[test]
fn a_fuzzy_plan_and_a_fold_are_refused_naming_the_place() {
    let p = |x: f64, y: f64| Nt2Point::new([crisp(x), crisp(y), crisp(x * y)]);
    let net = vec![
        vec![p(0.0, 0.0), p(0.0, 1.0), p(0.0, 2.0)],
        vec![p(1.0, 0.0), p(3.0, 1.0), p(1.0, 2.0)],
        vec![p(2.0, 0.0), p(2.0, 1.0), p(2.0, 2.0)],
    ];
    // The middle point pulled past the right edge: x folds back along u.
    let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 3]; 3], [None, None]).expect("net");
    let e = s.measure(&options(&[0.0], 0.0)).expect_err("a fold");
    assert!(matches!(e, Error::NotAGraph { .. }), "{e}");
    assert!(e.to_string().contains("folds"), "{e}");
}

/// A terrain: crisp increasing x and y (sheared or not), random heights.
fn terrain() -> impl Strategy<Value = FuzzySurface<3>> {
    (1usize..=2, 1usize..=2, any::<[bool; 2]>(), height()).prop_flat_map(
        |(pu, pv, [shear, rational], h)| {
            (pu + 1..=pu + 2, pv + 1..=pv + 2).prop_flat_map(move |(nu, nv)| {
                (
                    proptest::collection::vec(0.3..2.0f64, nu),
                    proptest::collection::vec(0.3..2.0f64, nv),
                    proptest::collection::vec(number_with_height(h), nu * nv),
                    proptest::collection::vec(0.5..2.0f64, nu * nv),
                )
                    .prop_map(move |(du, dv, z, w)| {
                        let (a, b) = (cumulative(&du), cumulative(&dv));
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
                    })
            })
        },
    )
}

/// `[V_below, V_above, A_below, surface area]` of a crisp surface by brute
/// force: every span rectangle cut into `cells × cells` cells, 4 × 4 Gauss
/// nodes each, with the partials of `NurbsSurface::derivatives`.
fn brute(s: &NurbsSurface<3>, datum: f64, cells: usize) -> [f64; 4] {
    let mut out = [0.0; 4];
    brute::gauss_cells(s, cells, |u, v, w| {
        let d = s.derivatives(u, v, 1).expect("in the domain");
        let (su, sv, z) = (d[1][0], d[0][1], d[0][0][2]);
        let n = [
            su[1] * sv[2] - su[2] * sv[1],
            su[2] * sv[0] - su[0] * sv[2],
            su[0] * sv[1] - su[1] * sv[0],
        ];
        let j = n[2].abs() * w;
        out[0] += (datum - z).max(0.0) * j;
        out[1] += (z - datum).max(0.0) * j;
        out[2] += if z < datum { j } else { 0.0 };
        out[3] += (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() * w;
    });
    out
}

/// The quantities' levels under function `m`, at `alpha`: the volumes and
/// the plan area, and the surface area when it was measured.
fn at(m: &SurfaceMeasures, f: Membership, a: f64) -> Option<Vec<Level>> {
    let find = |p: &PerMembership<Vec<Level>>| p.get(f).iter().find(|l| l.alpha == a).copied();
    let mut out = vec![
        find(&m.volume_below)?,
        find(&m.volume_above)?,
        find(&m.plan_area_below)?,
    ];
    if let Some(area) = m.area.as_ref() {
        out.push(find(area)?);
    }
    Some(out)
}

proptest! {
    // A case measures a net with its surface area at 3 levels: 10 to 40
    // seconds in a debug build (the saved regressions run too), so one case
    // without the surface area by default and 4 with it under
    // T2SPLINE_LONG_TESTS=1; longer runs in release:
    // PROPTEST_CASES=48 cargo test --release --test surface_measure.
    #![proptest_config(cases(1, 4))]

    /// Random admissible nets and vertex nets inside the intervals; the
    /// extreme nets at the exact ends of the volumes and plan area.
    #[test]
    fn admissible_nets_lie_inside_and_extreme_nets_attain_the_ends(
        s in terrain(), datum_at in 0.1..0.9f64, seed in 1u64..1000,
    ) {
        let crisp_net = s.crisp_surface();
        let b = crisp_net.bounding_box();
        let datum = b.min[2] + datum_at * (b.max[2] - b.min[2]);
        let levels = [0.0, 0.5, 1.0];
        // The surface area (most of a debug build's time) under
        // T2SPLINE_LONG_TESTS=1 only, which CI sets.
        let o = options(&levels, datum).with_area(test_size(0, 1) == 1);
        let m = s.measure(&o).expect("a terrain is a graph");
        let plan = m.plan_area[0];
        let scale = plan * (s.bounding_box().max[2] - s.bounding_box().min[2]).max(1e-9);
        // Brute force's own error (the corners of max(·, 0) and [·]).
        let slack = [5e-3 * scale, 5e-3 * scale, 2e-2 * plan, 1e-5 * plan.max(1.0)];
        let mut uniform = seeded_uniform(seed);
        for f in MEMBERSHIPS {
            for &a in &levels {
                let Some(q) = at(&m, f, a) else { continue };
                for l in &q[..3] {
                    prop_assert!(l.exact, "{f:?} {a}: {l:?} not to the tolerance");
                }
                let nets = [
                    net(&s, f, alpha(a), |c| c.left()),
                    net(&s, f, alpha(a), |c| c.right()),
                ];
                let [Some(left), Some(right)] = nets else { continue };
                let (l, r) = (brute(&left, datum, 8), brute(&right, datum, 8));
                // Ends attained: V_below, A_below at (right, left); V_above at (left, right).
                for (k, least, largest) in [(0, r[0], l[0]), (1, l[1], r[1]), (2, r[2], l[2])] {
                    prop_assert!((q[k].min - least).abs() <= slack[k], "{k} {f:?} {a}: {:?} vs {least}", q[k]);
                    prop_assert!((q[k].max - largest).abs() <= slack[k], "{k} {f:?} {a}: {:?} vs {largest}", q[k]);
                }
                for _ in 0..test_size(2, 20) {
                    let vertex = uniform() < 0.3;
                    let Some(c) = net(&s, f, alpha(a), |c| {
                        let t = uniform();
                        let t = if vertex { t.round() } else { t };
                        c.left() + t * (c.right() - c.left())
                    }) else { continue };
                    let v = brute(&c, datum, 8);
                    let mut slack = slack;
                    if q.len() > 3 {
                        // A rational net's area needs more cells: the
                        // brute force's own error, estimated by halving them.
                        slack[3] += (v[3] - brute(&c, datum, 4)[3]).abs();
                    }
                    for k in 0..q.len() {
                        prop_assert!(q[k].min - slack[k] <= v[k] && v[k] <= q[k].max + slack[k],
                            "{k} {f:?} {a}: {} outside {:?}", v[k], q[k]);
                    }
                }
            }
        }
    }

    /// Intervals at a higher level inside those at a lower one, and
    /// upper ⊇ primary ⊇ lower at each level.
    #[test]
    fn intervals_nest(s in terrain(), datum_at in 0.0..1.0f64) {
        let b = s.crisp_surface().bounding_box();
        let datum = b.min[2] + datum_at * (b.max[2] - b.min[2]);
        let levels = [0.0, 0.25, 0.5, 0.75, 1.0];
        // The surface area (the slow part) under T2SPLINE_LONG_TESTS=1 only.
        let o = options(&levels, datum).with_area(test_size(0, 1) == 1);
        let m = s.measure(&o).expect("measured");
        let mut lists = vec![&m.volume_below, &m.volume_above, &m.plan_area_below];
        lists.extend(m.area.as_ref());
        for list in lists {
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
