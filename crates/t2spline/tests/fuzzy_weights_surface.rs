//! Surfaces with fuzzy weights (docs/method.md §16): each stage's surface is
//! the rational B-spline surface through that stage's values of the net and
//! of the weights; crisp numbers as weights change nothing; what does not
//! take fuzzy weights says so.

use t2spline::measure::SurfaceMeasureOptions;
use t2spline::sampling::Params;
use t2spline::set::PlanGrid;
use t2spline::{
    Alpha, Direction, Error, FuzzySurface, Layer, Nt2Number, Nt2Point, NurbsSurface, Side,
    TypeReduction,
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

/// A 3 × 4 net over `[0, 2] × [0, 3]` with fuzzy heights (and x, y fuzzy
/// a little).
fn net() -> Vec<Vec<Nt2Point<3>>> {
    let z = [
        [0.0, 0.5, 0.2, 0.0],
        [0.3, 1.5, 1.0, 0.4],
        [0.0, 0.6, 0.8, 0.1],
    ];
    (0..3)
        .map(|i| {
            (0..4)
                .map(|j| {
                    Nt2Point::new([
                        number(i as f64, 0.05),
                        number(j as f64, 0.05),
                        number(z[i][j], 0.3),
                    ])
                })
                .collect()
        })
        .collect()
}

/// Row by row, one per net point.
fn weights() -> Vec<Nt2Number> {
    [1.0, 2.0, 0.7, 1.5, 1.2, 3.0, 0.8, 1.0, 1.0, 0.6, 2.5, 1.0]
        .iter()
        .enumerate()
        .map(|(k, &w)| number(w, 0.1 + 0.05 * k as f64 * w / 3.0))
        .collect()
}

fn surface() -> FuzzySurface<3> {
    FuzzySurface::try_new([2, 2], net(), vec![vec![1.0; 4]; 3], [None, None])
        .unwrap()
        .with_weight_numbers(weights())
        .unwrap()
}

/// The rational B-spline surface of `points` with `weights` (both row by
/// row) and the surface's knots, made through the checked constructor.
fn reference(points: Vec<[f64; 3]>, weights: Vec<f64>) -> NurbsSurface<3> {
    let s = surface();
    NurbsSurface::try_new(
        points.chunks(4).map(<[_]>::to_vec).collect(),
        weights.chunks(4).map(<[_]>::to_vec).collect(),
        Direction::BOTH.map(|d| s.knots(d).clone()),
    )
    .unwrap()
}

fn close(p: [f64; 3], q: [f64; 3], tolerance: f64) -> bool {
    (0..3).all(|d| (p[d] - q[d]).abs() < tolerance)
}

fn assert_same(a: &NurbsSurface<3>, b: &NurbsSurface<3>) {
    for u in a.domain(Direction::U).uniform(13).unwrap() {
        for v in a.domain(Direction::V).uniform(13).unwrap() {
            let (p, q) = (a.eval(u, v).unwrap(), b.eval(u, v).unwrap());
            assert!(close(p, q, 1e-13), "({u}, {v}): {p:?} {q:?}");
        }
    }
}

#[test]
fn every_stage_pairs_the_values_of_points_and_weights() {
    let s = surface();
    let crisp: Vec<f64> = weights().iter().map(Nt2Number::crisp).collect();
    assert_eq!(s.weights(), crisp.as_slice());
    assert_eq!(s.weight_numbers().unwrap(), weights().as_slice());
    for layer in Layer::ALL {
        let expected = reference(
            s.points().iter().map(|p| p.layer(layer)).collect(),
            weights().iter().map(|w| w.layer(layer)).collect(),
        );
        assert_same(&s.layer_surface(layer), &expected);
        let at = s.eval_layers(0.4, 0.7).unwrap()[layer];
        assert!(close(at, expected.eval(0.4, 0.7).unwrap(), 1e-13));
    }
    // Layers with weights of their own are no fuzzy point.
    assert_eq!(s.eval(0.4, 0.7).unwrap(), None);
    let alpha = Alpha::try_new(0.3).unwrap();
    for method in TypeReduction::ALL {
        let solution = s.solve_with(alpha, method);
        let w = weights();
        let reduced: Vec<_> = w.iter().map(|w| w.reduce(method, alpha)).collect();
        let defuzzified: Vec<f64> = reduced.iter().map(|r| r.defuzzified()).collect();
        assert_same(
            &solution.defuzzified_surface(),
            &reference(solution.defuzzified_points().to_vec(), defuzzified.clone()),
        );
        assert_eq!(solution.defuzzified_weights().unwrap(), defuzzified);
        for side in [Side::Left, Side::Right] {
            let ws: Vec<f64> = reduced
                .iter()
                .map(|r| match side {
                    Side::Left => r.left(),
                    Side::Right => r.right(),
                })
                .collect();
            assert_same(
                &solution.type_reduced_surface(side),
                &reference(solution.type_reduced_side(side), ws.clone()),
            );
            assert_eq!(solution.type_reduced_weights(side).unwrap(), ws);
        }
        for layer in [Layer::UpperLeft, Layer::PrimaryRight, Layer::LowerLeft] {
            let cut: Vec<f64> = w
                .iter()
                .map(|w| w.alpha_cut(alpha).layer(layer).unwrap())
                .collect();
            assert_same(
                &solution.alpha_cut_surface(layer).unwrap(),
                &reference(solution.alpha_cut_layer(layer).unwrap(), cut.clone()),
            );
            assert_eq!(solution.alpha_cut_weights(layer), Some(Some(cut)));
        }
        assert_same(
            &solution.crisp_surface(),
            &reference(
                s.points().iter().map(|p| p.crisp()).collect(),
                crisp.clone(),
            ),
        );
    }
}

#[test]
fn crisp_numbers_as_weights_leave_the_surface_as_it_was() {
    let values = [1.0, 2.0, 0.7, 1.5, 1.2, 3.0, 0.8, 1.0, 1.0, 0.6, 2.5, 1.0];
    let crisp: Vec<Nt2Number> = values
        .iter()
        .map(|&w| Nt2Number::try_new(w, [w, w], [w, w], [w, w], 0.5).unwrap())
        .collect();
    let rows: Vec<Vec<f64>> = values.chunks(4).map(<[_]>::to_vec).collect();
    let plain = FuzzySurface::try_new([2, 2], net(), rows, [None, None]).unwrap();
    let numbered = FuzzySurface::try_new([2, 2], net(), vec![vec![1.0; 4]; 3], [None, None])
        .unwrap()
        .with_weight_numbers(crisp)
        .unwrap();
    assert_eq!(plain, numbered);
    assert!(numbered.weight_numbers().is_none());
    // And what refuses fuzzy weights takes them.
    assert!(numbered.insert_knot(Direction::U, 0.5, 1).is_ok());
}

#[test]
fn sampled_stages_agree_with_the_stage_surfaces() {
    let s = surface();
    let alpha = Alpha::try_new(0.2).unwrap();
    let solution = s.solve(alpha);
    let (su, sv) = (21, 17);
    let sweep = s
        .sample_sweep(Params::Uniform(su), Params::Uniform(sv), &[alpha])
        .unwrap();
    let stages = solution
        .sample_stages(Params::Uniform(su), Params::Uniform(sv))
        .unwrap();
    let us = s.domain(Direction::U).uniform(su).unwrap();
    let vs = s.domain(Direction::V).uniform(sv).unwrap();
    let level = &sweep.samples().levels()[0];
    let mut slices = vec![0.0; 7 * 3 * su * sv];
    {
        let mut out: Vec<&mut [f64]> = slices.chunks_mut(su * sv).collect();
        s.sample_layers_into_slices(Params::Uniform(su), Params::Uniform(sv), &mut out)
            .unwrap();
    }
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            let k = a * sv + b;
            for (l, layer) in Layer::ALL.into_iter().enumerate() {
                let want = s.layer_surface(layer).eval(u, v).unwrap();
                let p = sweep.samples().layers()[layer].point(k).unwrap();
                assert!(close(p, want, 1e-12), "{layer:?} ({u}, {v})");
                let q: [f64; 3] = std::array::from_fn(|d| slices[(l * 3 + d) * su * sv + k]);
                assert!(close(q, want, 1e-12));
            }
            let want = solution.defuzzified_surface().eval(u, v).unwrap();
            assert!(close(level.defuzzified().point(k).unwrap(), want, 1e-12));
            assert!(close(
                stages.samples().defuzzified().point(k).unwrap(),
                want,
                1e-12
            ));
            for side in [Side::Left, Side::Right] {
                let want = solution.type_reduced_surface(side).eval(u, v).unwrap();
                assert!(close(
                    level.type_reduced(side).point(k).unwrap(),
                    want,
                    1e-12
                ));
            }
            let want = solution
                .alpha_cut_surface(Layer::UpperRight)
                .unwrap()
                .eval(u, v)
                .unwrap();
            let cut = level.alpha_cut(Layer::UpperRight).unwrap();
            assert!(close(cut.point(k).unwrap(), want, 1e-12));
        }
    }
}

#[test]
fn the_distance_agrees_with_brute_force() {
    let s = surface();
    for alpha in [0.0, 0.4] {
        let solution = s.solve(Alpha::try_new(alpha).unwrap());
        let d = solution.distance();
        let (crisp, solved) = (solution.crisp_surface(), solution.defuzzified_surface());
        let gap = |u: f64, v: f64| {
            let (p, q) = (crisp.eval(u, v).unwrap(), solved.eval(u, v).unwrap());
            (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>().sqrt()
        };
        // A fine scan: its largest value is a lower bound of the maximum,
        // and the maximum is not above it by more than the scan's step can
        // hide on these smooth patches.
        let n = 301;
        let us = s.domain(Direction::U).uniform(n).unwrap();
        let vs = s.domain(Direction::V).uniform(n).unwrap();
        let (mut scan, mut sum, mut weight) = (0.0_f64, 0.0, 0.0);
        let end = |i: usize| if i == 0 || i + 1 == n { 0.5 } else { 1.0 };
        for (a, &u) in us.iter().enumerate() {
            for (b, &v) in vs.iter().enumerate() {
                let g = gap(u, v);
                scan = scan.max(g);
                let w = end(a) * end(b);
                sum += w * g * g;
                weight += w;
            }
        }
        assert!(
            d.max >= scan - 1e-14 && d.max <= scan * (1.0 + 1e-3),
            "{alpha}: {} vs {scan}",
            d.max
        );
        assert!((gap(d.max_at[0], d.max_at[1]) - d.max).abs() <= 1e-12 * d.max);
        // The trapezoidal rule on 301² points is within 1e-3 of the mean.
        let rms = (sum / weight).sqrt();
        assert!((d.rms / rms - 1.0).abs() < 1e-3, "{} vs {rms}", d.rms);
        // The sampled sweep measures the same two surfaces.
        let sweep = s
            .distance_sweep(&[Alpha::try_new(alpha).unwrap()], [n, n])
            .unwrap();
        let [max, sampled_rms] = sweep.summary()[0];
        assert!((max - scan).abs() <= 1e-12 * scan, "{max} vs {scan}");
        assert!((sampled_rms / rms - 1.0).abs() < 1e-9);
    }
}

#[test]
fn the_bounding_box_holds_every_admissible_surface() {
    let s = surface();
    let b = s.bounding_box();
    let mut seed = 11u64;
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
    for _ in 0..100 {
        let pts: Vec<[f64; 3]> = s
            .points()
            .iter()
            .map(|p| {
                let (l, r) = (p.layer(Layer::UpperLeft), p.layer(Layer::UpperRight));
                std::array::from_fn(|d| pick(l[d], r[d]))
            })
            .collect();
        let ws: Vec<f64> = weights()
            .iter()
            .map(|w| pick(w.layer(Layer::UpperLeft), w.layer(Layer::UpperRight)))
            .collect();
        let k = reference(pts, ws);
        for u in k.domain(Direction::U).uniform(9).unwrap() {
            for v in k.domain(Direction::V).uniform(9).unwrap() {
                let p = k.eval(u, v).unwrap();
                assert!(b.contains(&p, 1e-12), "{p:?}");
            }
        }
    }
}

#[test]
fn what_takes_crisp_weights_only_says_so() {
    let s = surface();
    let says = |e: Error, what: &str| {
        assert_eq!(
            e.to_string(),
            format!("{what} is not available for a model with fuzzy weights")
        );
    };
    let d = Direction::U;
    says(s.insert_knot(d, 0.5, 1).unwrap_err(), "knot insertion");
    says(s.refine_knots(d, &[0.3]).unwrap_err(), "knot refinement");
    says(s.elevate_degree(d, 1).unwrap_err(), "degree elevation");
    says(s.split_at(d, 0.5).unwrap_err(), "splitting");
    says(s.segment([0.0, 0.5], [0.0, 0.5]).unwrap_err(), "a segment");
    says(s.isocurve(d, 0.5).unwrap_err(), "an isocurve");
    says(s.membership(&[1.0, 1.0, 0.5]).unwrap_err(), "membership");
    says(s.memberships(&[[1.0, 1.0, 0.5]]).unwrap_err(), "membership");
    says(
        s.sections([1.0, 1.0], &[Alpha::ZERO]).unwrap_err(),
        "a section of a surface",
    );
    let grid = PlanGrid::try_new(s.plan_extent(), [4, 4]).unwrap();
    says(
        s.envelope(&grid, &[Alpha::ZERO]).unwrap_err(),
        "an envelope",
    );
    says(
        s.envelope_at(&[[1.0, 1.0]], &[Alpha::ZERO]).unwrap_err(),
        "an envelope",
    );
    says(
        s.contour(&grid, 0.5, &[Alpha::ZERO]).unwrap_err(),
        "a contour",
    );
    let options = SurfaceMeasureOptions::uniform(2).unwrap();
    says(s.measure(&options).unwrap_err(), "a surface measure");
    let plain = FuzzySurface::try_new([2, 2], net(), vec![vec![1.0; 4]; 3], [None, None]).unwrap();
    says(
        plain.measure_against(&s, &options).unwrap_err(),
        "a surface measure",
    );
    // Per layer, everything still works.
    assert!(s.closest_points([1.0, 1.0, 2.0]).is_ok());
    assert!(s.derivatives(0.3, 0.6, 2).is_ok());
    assert!(s.curvatures(0.3, 0.6).is_ok());
}

#[test]
fn a_weight_whose_least_value_is_not_positive_is_refused() {
    let mut bad = weights();
    bad[5] = number(0.5, 0.5);
    let e = FuzzySurface::try_new([2, 2], net(), vec![vec![1.0; 4]; 3], [None, None])
        .unwrap()
        .with_weight_numbers(bad)
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights[5] = 0 must be finite and greater than 0"
    );
    let e = FuzzySurface::try_new([2, 2], net(), vec![vec![1.0; 4]; 3], [None, None])
        .unwrap()
        .with_weight_numbers(weights()[..11].to_vec())
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights: expected 12 (one per control point), got 11"
    );
}
