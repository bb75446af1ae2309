//! The fuzzy contour of a fuzzy surface (docs/method.md §13) against brute
//! force: every crossing of the height by random admissible nets (every
//! height anywhere in its cut) and by the vertex nets lies in the band's
//! polygons; the crisp contour lies in the upper band; bands nest across
//! functions and levels; every kept cell comes within the stated height
//! tolerance of the height.

mod terrain;

use proptest::prelude::*;
use t2spline::set::{PlanGrid, Region, MEMBERSHIPS};
use t2spline::strategies::{cases, height, number_with_height, seeded_uniform};
use t2spline::{Alpha, Direction, FuzzySurface, Nt2Number, Nt2Point, NurbsSurface};
use terrain::{cumulative, net};

/// A terrain: crisp, strictly increasing x and y on a net (x along u or
/// along v), weights 1 or random, fuzzy heights of one lower height.
fn terrain() -> impl Strategy<Value = FuzzySurface<3>> {
    (1usize..=3, 1usize..=3, any::<[bool; 2]>(), height()).prop_flat_map(
        |(pu, pv, [swap, rational], h)| {
            (pu + 1..=pu + 4, pv + 1..=pv + 4).prop_flat_map(move |(nu, nv)| {
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
                                        let (x, y) = if swap { (b[j], a[i]) } else { (a[i], b[j]) };
                                        Nt2Point::new([crisp(x), crisp(y), z[i * nv + j]])
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

/// The distance from `p` to the nearest edge of the region's rings.
fn distance_to_outline(r: &Region, p: [f64; 2]) -> f64 {
    let mut d = f64::INFINITY;
    for g in r.polygons() {
        for ring in std::iter::once(&g.exterior).chain(&g.holes) {
            for (a, b) in ring.iter().zip(ring.iter().cycle().skip(1)) {
                let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
                let len2 = ex * ex + ey * ey;
                let t = if len2 > 0.0 {
                    (((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                d = d.min((p[0] - a[0] - t * ex).hypot(p[1] - a[1] - t * ey));
            }
        }
    }
    d
}

/// Whether `p` is in the region or within `slack` of its outline.
fn holds(r: &Region, p: [f64; 2], slack: f64) -> bool {
    r.contains(p) || distance_to_outline(r, p) <= slack
}

/// The plan points where `n` crosses `z0` between neighbours of a `k × k`
/// sample in `(u, v)`, each with the plan distance between its neighbours.
fn crossings(n: &NurbsSurface<3>, s: &FuzzySurface<3>, z0: f64, k: usize) -> Vec<([f64; 2], f64)> {
    let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
    let p: Vec<[f64; 3]> = (0..k)
        .flat_map(|i| (0..k).map(move |j| (i, j)))
        .map(|(i, j)| {
            let (u, v) = (
                du.lerp(i as f64 / (k - 1) as f64),
                dv.lerp(j as f64 / (k - 1) as f64),
            );
            n.eval(u, v).expect("in the domain")
        })
        .collect();
    let mut out = Vec::new();
    for i in 0..k {
        for j in 0..k {
            let a = p[i * k + j];
            for b in [
                (i + 1 < k).then(|| p[(i + 1) * k + j]),
                (j + 1 < k).then(|| p[i * k + j + 1]),
            ]
            .into_iter()
            .flatten()
            {
                let (fa, fb) = (a[2] - z0, b[2] - z0);
                if (fa <= 0.0) == (fb <= 0.0) && fa != 0.0 && fb != 0.0 {
                    continue;
                }
                let t = if fa == fb {
                    0.0
                } else {
                    (fa / (fa - fb)).clamp(0.0, 1.0)
                };
                let q = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                out.push((q, (b[0] - a[0]).hypot(b[1] - a[1])));
            }
        }
    }
    out
}

proptest! {
    #![proptest_config(cases(24, 64))]

    /// Every crossing of `z0` by random admissible nets and by the vertex
    /// nets lies in the band (to the distance between the brute force's
    /// samples, where its crossing is interpolated); the crisp contour lies
    /// in the upper band.
    #[test]
    fn every_crossing_of_an_admissible_surface_lies_in_the_band(
        s in terrain(),
        pick in 0usize..3,
        a in prop_oneof![Just(0.0), 0.0..=1.0f64, Just(1.0)],
        at in [0.0..=1.0f64, 0.0..=1.0f64],
        seed in any::<u64>(),
    ) {
        let (m, a) = (MEMBERSHIPS[pick], Alpha::try_new(a).expect("a level"));
        let (u, v) = (s.domain(Direction::U).lerp(at[0]), s.domain(Direction::V).lerp(at[1]));
        let z0 = s.crisp_surface().eval(u, v).expect("in the domain")[2];
        let extent = s.plan_extent();
        // The default grid, at most 160 cells a side to keep the test short.
        let shape = s.contour_shape(extent).map(|n| n.min(160));
        let grid = PlanGrid::try_new(extent, shape).expect("a grid");
        let contour = s.contour(&grid, z0, &[a]).expect("within limits");
        let scale = (extent[2] - extent[0]).max(extent[3] - extent[1]);
        let Some(band) = contour.levels[0].get(m) else {
            prop_assert!(net(&s, m, a, |c| c.left()).is_none(), "{m:?} at {a:?} left out with cuts");
            return Ok(());
        };
        let mut random = seeded_uniform(seed);
        let mut nets = Vec::new();
        if let (Some(l), Some(r)) = (net(&s, m, a, |c| c.left()), net(&s, m, a, |c| c.right())) {
            nets.push(l);
            nets.push(r);
        }
        for _ in 0..25 {
            if let Some(n) = net(&s, m, a, |c| c.left() + random() * c.width()) {
                nets.push(n);
            }
        }
        for n in &nets {
            for (p, step) in crossings(n, &s, z0, 40) {
                prop_assert!(holds(band, p, step + 1e-9 * scale), "{m:?} at {a:?}, z0 = {z0}: crossing {p:?} outside the band (step {step}, distance {}, envelope {:?}, grid {:?} heights {:?})", distance_to_outline(band, p), s.envelope_at(&[p], &[a]).map(|e| e[0].get(m).cloned()), grid, s.points().iter().map(|q| { let c = q.coords(); [c[0].crisp(), c[1].crisp(), c[2].crisp()] }).collect::<Vec<_>>());
            }
        }
        let upper = contour.levels[0].upper.as_ref().expect("the upper band");
        for line in &contour.crisp {
            for &p in line {
                prop_assert!(holds(upper, p, 1e-9 * scale), "crisp contour point {p:?} outside the upper band");
            }
        }
    }

    /// Bands nest: lower ⊆ primary ⊆ upper at a level, a level's inside
    /// the lower levels'; every kept cell's envelope comes within the height
    /// tolerance of `z0`, checked on a 5 × 5 sample inside up to 30 cells.
    #[test]
    fn bands_nest_and_kept_cells_come_near_the_height(
        s in terrain(),
        at in [0.0..=1.0f64, 0.0..=1.0f64],
    ) {
        let (u, v) = (s.domain(Direction::U).lerp(at[0]), s.domain(Direction::V).lerp(at[1]));
        let z0 = s.crisp_surface().eval(u, v).expect("in the domain")[2];
        let extent = s.plan_extent();
        let grid = PlanGrid::try_new(extent, [24, 20]).expect("a grid");
        let levels: Vec<Alpha> = [0.0, 0.4, 0.8].map(|a| Alpha::try_new(a).expect("a level")).to_vec();
        let contour = s.contour(&grid, z0, &levels).expect("within limits");
        let (xs, ys) = (grid.xs(), grid.ys());
        let [dx, dy] = grid.cell_size();
        let inside = |outer: Option<&Region>, inner: Option<&Region>| {
            let (Some(o), Some(i)) = (outer, inner) else { return true };
            ys.iter().all(|&y| xs.iter().all(|&x| !i.contains([x, y]) || o.contains([x, y])))
        };
        for l in &contour.levels {
            prop_assert!(inside(l.upper.as_ref(), l.primary.as_ref()) && inside(l.primary.as_ref(), l.lower.as_ref()), "functions do not nest at {}", l.alpha);
        }
        for w in contour.levels.windows(2) {
            for m in MEMBERSHIPS {
                prop_assert!(inside(w[0].get(m), w[1].get(m)), "{m:?}: {} not inside {}", w[1].alpha, w[0].alpha);
            }
        }
        let level = &contour.levels[0];
        let band = level.upper.as_ref().expect("the upper band at 0");
        let kept: Vec<[f64; 2]> = ys.iter().flat_map(|&y| xs.iter().map(move |&x| [x, y])).filter(|&p| band.contains(p)).collect();
        // At most 30 kept cells, spread over the band, to keep the test short.
        let stride = kept.len().div_ceil(30).max(1);
        let env = s.envelope_at(
            &kept.into_iter().step_by(stride)
                .flat_map(|[x, y]| (0..25).map(move |k| [x + dx * ((k % 5) as f64 / 4.0 - 0.5), y + dy * ((k / 5) as f64 / 4.0 - 0.5)]))
                .collect::<Vec<_>>(),
            &levels[..1],
        ).expect("within limits");
        let b = env[0].upper.as_ref().expect("upper");
        let slack = contour.height_tolerance + 1e-9 * (1.0 + z0.abs());
        for (cell, (lo, hi)) in b.least.chunks(25).zip(b.greatest.chunks(25)).enumerate() {
            let lo = lo.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = hi.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(lo - slack <= z0 && z0 <= hi + slack, "kept cell {cell}: [{lo}, {hi}] misses {z0} by more than {slack}");
        }
    }
}

/// A height no surface reaches gives empty bands and no crisp contour; a
/// height the net spans gives a crisp contour.
#[test]
fn out_of_reach_heights_give_empty_bands() {
    let crisp = |x: f64| Nt2Number::try_crisp(x).expect("finite");
    let z = Nt2Number::try_new(0.0, [-1.0, 1.0], [-0.5, 0.5], [-0.25, 0.25], 0.5).expect("valid");
    let p = |x: f64, y: f64| Nt2Point::new([crisp(x), crisp(y), z]);
    let net = vec![
        vec![p(0.0, 0.0), p(0.0, 2.0)],
        vec![p(2.0, 0.0), p(2.0, 2.0)],
    ];
    let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).expect("valid");
    let grid = PlanGrid::try_new(s.plan_extent(), [8, 8]).expect("a grid");
    let c = s
        .contour(&grid, 5.0, &[Alpha::ZERO])
        .expect("within limits");
    assert!(c.levels[0]
        .upper
        .as_ref()
        .is_some_and(|r| r.polygons().is_empty()));
    assert!(c.crisp.is_empty());
    let c = s
        .contour(&grid, 0.75, &[Alpha::ZERO])
        .expect("within limits");
    let upper = c.levels[0].upper.as_ref().expect("upper");
    assert!(
        (upper.area() - 4.0).abs() < 1e-9,
        "the plane's whole plan: {}",
        upper.area()
    );
    assert!(c.levels[0]
        .primary
        .as_ref()
        .is_some_and(|r| r.polygons().is_empty()));
    assert!(s.contour(&grid, f64::NAN, &[Alpha::ZERO]).is_err());
}
