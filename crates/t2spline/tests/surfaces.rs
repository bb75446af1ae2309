//! Fuzzy rational B-spline surfaces (docs/method.md §8): the invariants of docs/method.md §1 and
//! §6–§7 at every `(u, v)`, the operations against the original surface, and
//! the quarter cylinder as a closed form, crisp and with a fuzzy radius.

use proptest::prelude::*;
use t2spline::{
    strategies, Alpha, Direction, FuzzySurface, Layer, Nt2Number, Nt2Point, NurbsSurface, Side,
    TypeReduction,
};

mod probes;
use probes::probes;

fn fractions() -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(0.0..=1.0f64, 1..5)
}

fn direction() -> impl Strategy<Value = Direction> {
    prop_oneof![Just(Direction::U), Just(Direction::V)]
}

/// The largest absolute control value of a fuzzy surface (at least 1).
fn scale<const D: usize>(s: &FuzzySurface<D>) -> f64 {
    s.points()
        .iter()
        .flat_map(|p| Layer::ALL.map(|l| p.layer(l)))
        .flatten()
        .fold(1.0, |m: f64, x| m.max(x.abs()))
}

fn close<const D: usize>(a: &[f64; D], b: &[f64; D], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

/// The same surface rebuilt from its parts with other fuzzy points.
fn with_points<const D: usize>(
    s: &FuzzySurface<D>,
    f: impl Fn(&Nt2Point<D>) -> Nt2Point<D>,
) -> FuzzySurface<D> {
    let [nu, nv] = s.shape();
    let points = (0..nu)
        .map(|i| (0..nv).map(|j| f(&s.points()[i * nv + j])).collect())
        .collect();
    let weights = (0..nu)
        .map(|i| s.weights()[i * nv..(i + 1) * nv].to_vec())
        .collect();
    let knots = Direction::BOTH.map(|d| Some(s.knots(d).as_slice().to_vec()));
    FuzzySurface::try_new(s.degree(), points, weights, knots).unwrap()
}

/// A number with symmetric spreads: the left spreads mirrored to the right.
fn symmetric(x: &Nt2Number) -> Nt2Number {
    let c = x.crisp();
    let (u, p, l) = (
        c - x.upper().left(),
        c - x.primary().left(),
        c - x.lower().left(),
    );
    Nt2Number::try_new(
        c,
        [c - u, c + u],
        [c - p, c + p],
        [c - l, c + l],
        x.height().get(),
    )
    .unwrap()
}

// The distance of a surface by every type reduction, where no patch can be
// skipped (the difference is 0 everywhere): seconds a case in debug, so 4
// cases by default, 16 under T2SPLINE_LONG_TESTS=1.
proptest! {
    #![proptest_config(strategies::cases(4, 16))]

    #[test]
    fn symmetric_spreads_give_zero_distance(s in strategies::fuzzy_surface::<3>(), a in 0.0..=1.0f64) {
        let s = with_points(&s, |p| Nt2Point::new(p.coords().map(|x| symmetric(&x))));
        for method in TypeReduction::ALL {
            let d = s.solve_with(Alpha::try_new(a).unwrap(), method).distance();
            prop_assert!(d.max <= 1e-14 * scale(&s) && d.rms <= d.max, "{}: {:?}", method, d);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn rational_basis_is_a_partition_of_unity(s in strategies::surface::<3>(), fu in fractions(), fv in fractions()) {
        for &u in &probes(s.knots(Direction::U), &fu) {
            for &v in &probes(s.knots(Direction::V), &fv) {
                let r: Vec<f64> = s.rational_basis(u, v).unwrap().into_iter().flatten().collect();
                prop_assert!(r.iter().all(|&x| x >= 0.0), "negative basis at ({}, {}): {:?}", u, v, r);
                prop_assert!((r.iter().sum::<f64>() - 1.0).abs() <= 1e-12, "sum at ({}, {})", u, v);
            }
        }
    }

    #[test]
    fn layer_surfaces_keep_the_seven_value_order_exactly(s in strategies::fuzzy_surface::<3>(), fu in fractions(), fv in fractions()) {
        for &u in &probes(s.knots(Direction::U), &fu) {
            for &v in &probes(s.knots(Direction::V), &fv) {
                let l = s.eval_layers(u, v).unwrap();
                for d in 0..3 {
                    let values = Layer::ALL.map(|layer| l[layer][d]);
                    prop_assert!(values.windows(2).all(|w| w[0] <= w[1]), "({}, {}) axis {}: {:?}", u, v, d, values);
                }
            }
        }
    }

    #[test]
    fn stages_commute_with_evaluation_for_a_common_height(
        s in strategies::fuzzy_surface_common_height::<3>(), fu in fractions(), fv in fractions(), a in 0.0..=1.0f64,
    ) {
        let alpha = Alpha::try_new(a).unwrap();
        let solution = s.solve(alpha);
        let tol = 1e-12 * scale(&s);
        for &u in &probes(s.knots(Direction::U), &fu) {
            for &v in &probes(s.knots(Direction::V), &fv) {
                let p = s.eval(u, v).unwrap().expect("one height per coordinate");
                let cut = p.alpha_cut(alpha);
                for layer in Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp) {
                    let of_point: Option<Vec<f64>> = cut.iter().map(|c| c.layer(layer)).collect();
                    let of_surface = solution.alpha_cut_surface(layer).map(|x| x.eval(u, v).unwrap());
                    match (of_point, of_surface) {
                        (Some(a), Some(b)) => prop_assert!(close(&[a[0], a[1], a[2]], &b, tol), "{} at ({}, {})", layer, u, v),
                        (None, None) => {}
                        (a, b) => prop_assert!(false, "{}: {:?} vs {:?}", layer, a, b),
                    }
                }
                let t = p.type_reduce(alpha);
                let left = solution.type_reduced_surface(Side::Left).eval(u, v).unwrap();
                let right = solution.type_reduced_surface(Side::Right).eval(u, v).unwrap();
                prop_assert!(close(&t.map(|x| x.left()), &left, tol));
                prop_assert!(close(&t.map(|x| x.right()), &right, tol));
                let d = solution.defuzzified_surface().eval(u, v).unwrap();
                prop_assert!(close(&p.defuzzify(alpha), &d, tol), "defuzzified at ({}, {})", u, v);
            }
        }
    }

    #[test]
    fn alpha_one_gives_the_crisp_surface(s in strategies::fuzzy_surface::<3>()) {
        let solution = s.solve(Alpha::try_new(1.0).unwrap());
        let crisp: Vec<[f64; 3]> = s.points().iter().map(Nt2Point::crisp).collect();
        prop_assert_eq!(solution.defuzzified_points(), &crisp[..]);
        prop_assert_eq!(solution.defuzzified_surface(), s.crisp_surface());
        prop_assert_eq!(solution.distance().max, 0.0);
    }

    #[test]
    fn operations_leave_the_surface_unchanged(
        s in strategies::surface::<3>(), d in direction(), at in 0.05..0.95f64, times in 1usize..=2,
    ) {
        let size = s.control_points().iter().flatten().fold(1.0, |m: f64, x| m.max(x.abs()));
        let k = s.knots(d);
        let t = k.domain().lerp(at);
        let room = k.degree() + 1 - k.multiplicity(t);
        let mut results = vec![("insertion", s.insert_knot(d, t, times.min(room)).unwrap(), 1e-12 * size)];
        results.push(("refinement", s.refine_knots(d, &[t, k.domain().lerp(at / 2.0)]).unwrap_or_else(|_| s.clone()), 1e-12 * size));
        let e = s.elevate_degree(d, times).unwrap();
        let tol = strategies::elevation_tolerance(k, s.weights(), size).max(1e-12 * size);
        results.push(("elevation", e, tol));
        for (what, r, tol) in &results {
            for &u in &probes(s.knots(Direction::U), &[0.3, 0.71]) {
                for &v in &probes(s.knots(Direction::V), &[0.2, 0.9]) {
                    let (a, b) = (s.eval(u, v).unwrap(), r.eval(u, v).unwrap());
                    prop_assert!(close(&a, &b, *tol), "{} in {} at ({}, {}): {:?} vs {:?}", what, d, u, v, a, b);
                }
            }
        }
        let [low, high] = s.split_at(d, t).unwrap();
        for &u in &probes(s.knots(Direction::U), &[0.3, 0.71]) {
            for &v in &probes(s.knots(Direction::V), &[0.2, 0.9]) {
                let x = [u, v][d.index()];
                let piece = if x < t { &low } else { &high };
                let (a, b) = (s.eval(u, v).unwrap(), piece.eval(u, v).unwrap());
                prop_assert!(close(&a, &b, 1e-12 * size), "split in {} at ({}, {})", d, u, v);
            }
        }
    }

    #[test]
    fn fuzzy_operations_keep_every_layer_and_the_order(
        s in strategies::fuzzy_surface_common_height::<3>(), d in direction(), at in 0.05..0.95f64,
    ) {
        let t = s.knots(d).domain().lerp(at);
        let size = scale(&s);
        let room = s.knots(d).degree() + 1 - s.knots(d).multiplicity(t);
        let inserted = s.insert_knot(d, t, room.min(1)).unwrap();
        let elevated = s.elevate_degree(d, 1).unwrap();
        let tol = strategies::elevation_tolerance(s.knots(d), s.weights(), size).max(1e-12 * size);
        for (r, tol) in [(&inserted, 1e-12 * size), (&elevated, tol)] {
            for &u in &probes(s.knots(Direction::U), &[0.4]) {
                for &v in &probes(s.knots(Direction::V), &[0.6]) {
                    let (a, b) = (s.eval_layers(u, v).unwrap(), r.eval_layers(u, v).unwrap());
                    for layer in Layer::ALL {
                        prop_assert!(close(&a[layer], &b[layer], tol), "{} at ({}, {})", layer, u, v);
                    }
                    // The result is again a valid fuzzy surface: ordered layers.
                    for dim in 0..3 {
                        let values = Layer::ALL.map(|layer| b[layer][dim]);
                        prop_assert!(values.windows(2).all(|w| w[0] <= w[1]));
                    }
                }
            }
        }
    }

    #[test]
    fn isocurves_equal_the_surface(s in strategies::surface::<3>(), d in direction(), at in 0.0..=1.0f64, f in fractions()) {
        let t = s.knots(d).domain().lerp(at);
        let c = s.isocurve(d, t).unwrap();
        let size = s.control_points().iter().flatten().fold(1.0, |m: f64, x| m.max(x.abs()));
        for &x in &probes(s.knots(d.other()), &f) {
            let (u, v) = if d == Direction::U { (t, x) } else { (x, t) };
            let (a, b) = (c.eval(x).unwrap(), s.eval(u, v).unwrap());
            prop_assert!(close(&a, &b, 1e-12 * size), "({}, {}): {:?} vs {:?}", u, v, a, b);
        }
    }
}

/// The quarter cylinder of radius `r` about the z axis (height 1), rational
/// quadratic in u with weights 1, √2/2, 1 and linear in v, with every
/// coordinate turned into a fuzzy number by `number`.
fn fuzzy_quarter_cylinder(r: f64, number: impl Fn(f64) -> Nt2Number) -> FuzzySurface<3> {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let corner = [[r, 0.0], [r, r], [0.0, r]];
    let points = corner
        .iter()
        .map(|&[x, y]| {
            (0..2)
                .map(|k| {
                    Nt2Point::new([
                        number(x),
                        number(y),
                        Nt2Number::try_crisp(k as f64).unwrap(),
                    ])
                })
                .collect()
        })
        .collect();
    FuzzySurface::try_new(
        [2, 1],
        points,
        vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]],
        [None, None],
    )
    .unwrap()
}

#[test]
fn quarter_cylinder_has_every_point_at_radius_r() {
    for r in [1.0, 0.25, 40.0] {
        let s = fuzzy_quarter_cylinder(r, |c| Nt2Number::try_crisp(c).unwrap()).crisp_surface();
        let g = s
            .sample_grid(
                t2spline::sampling::Params::Uniform(51),
                t2spline::sampling::Params::Uniform(5),
            )
            .unwrap();
        for [x, y, _] in g.samples().points() {
            assert!((x.hypot(y) / r - 1.0).abs() < 2e-16 * 4.0, "{r}: {x}, {y}");
        }
    }
}

/// With a fuzzy radius whose spreads are fixed fractions of each coordinate
/// (`c·(1 − 0.3)`, `c·(1 + 0.45)`, … and one lower height), every stage acts on
/// a control value `c` as multiplication by a constant: the alpha-cut layer
/// `ℓ` gives `c·(1 + σ_ℓ(α))`, type reduction `c·(1 − λ)` and `c·(1 + ρ)`, and
/// defuzzification `c·κ` with `κ = 1 + (ρ − λ)/3`. The x and y control values
/// of the cylinder are all scaled by the same factor, and a rational surface is
/// linear in its control points, so every stage's surface is exactly a
/// cylinder about the same axis: of radius `(1 + σ_ℓ)·r`, `(1 − λ)·r`,
/// `(1 + ρ)·r`, `κ·r`. The distance to the crisp surface is `|κ − 1|·r` at every
/// `(u, v)` (z is crisp), so max = rms = `|κ − 1|·r`.
#[test]
fn fuzzy_radius_gives_cylinders_of_the_stage_radii() {
    let h = 0.6;
    let number = |c: f64| {
        Nt2Number::try_new(
            c,
            [c * 0.7, c * 1.45],
            [c * 0.8, c * 1.3],
            [c * 0.9, c * 1.15],
            h,
        )
        .unwrap()
    };
    let r = 2.0;
    let s = fuzzy_quarter_cylinder(r, number);
    for a in [0.0, 0.3, 0.6, 0.8, 1.0] {
        let alpha = Alpha::try_new(a).unwrap();
        // The factors, from the number 1 (the stages of c are c times those of 1).
        let one = number(1.0).alpha_cut(alpha);
        let t = one.type_reduce();
        let kappa = t.defuzzify();
        let solution = s.solve(alpha);
        let radius_of = |surface: &NurbsSurface<3>| {
            let g = surface
                .sample_grid(
                    t2spline::sampling::Params::Uniform(41),
                    t2spline::sampling::Params::Uniform(3),
                )
                .unwrap();
            g.samples()
                .points()
                .map(|[x, y, _]| x.hypot(y))
                .collect::<Vec<f64>>()
        };
        let expect = |surface: &NurbsSurface<3>, factor: f64, what: &str| {
            for radius in radius_of(surface) {
                assert!(
                    (radius - factor * r).abs() < 1e-14 * r,
                    "alpha {a}, {what}: {radius} vs {}",
                    factor * r
                );
            }
        };
        for layer in Layer::ALL {
            match (solution.alpha_cut_surface(layer), one.layer(layer)) {
                (Some(surface), Some(factor)) => expect(&surface, factor, layer.name()),
                (None, None) => assert!(layer.is_lower() && a > h),
                _ => panic!(
                    "alpha {a}, {layer}: the cut exists for the surface but not for the number"
                ),
            }
        }
        expect(&solution.type_reduced_surface(Side::Left), t.left(), "left");
        expect(
            &solution.type_reduced_surface(Side::Right),
            t.right(),
            "right",
        );
        expect(&solution.defuzzified_surface(), kappa, "defuzzified");
        let d = solution.distance();
        let want = (kappa - 1.0).abs() * r;
        assert!(
            (d.max - want).abs() <= 1e-13 * r && (d.rms - want).abs() <= 1e-13 * r,
            "alpha {a}: {d:?} vs {want}"
        );
    }
}

#[test]
fn mixed_heights_are_refused_by_operations_with_the_net_place() {
    let n = |c: f64, h: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c, c], [c, c], h).unwrap();
    let p = |h: f64| Nt2Point::new([n(0.0, 0.5), n(0.0, 0.5), n(0.0, h)]);
    let net = vec![vec![p(0.5), p(0.5)], vec![p(0.5), p(0.7)]];
    let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).unwrap();
    let e = s.insert_knot(Direction::U, 0.5, 1).unwrap_err();
    assert_eq!(
        e.to_string(),
        "points[1][1].z: lower_height 0.7 differs from 0.5 of points[0].z; this operation needs one lower height per coordinate"
    );
    assert!(s.eval(0.5, 0.5).unwrap().is_none());
}
