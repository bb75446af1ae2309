//! Runs with every type reduction (docs/method.md §7, §9): a job's stages 3–4 are its
//! numbers reduced one by one, alpha is used by the paper's reduction only,
//! and the sampled stage curves follow the chosen reduction.

use t2spline::job::{Job, Model, Overrides, RunOutput, Samples};
use t2spline::{
    Alpha, Error, FuzzyCurve, FuzzySurface, Layer, Nt2Number, Nt2Point, Side, TypeReduction,
};

/// A number with unequal sides: `spreads` are the upper, primary and lower
/// feet's distances to `crisp`, left then right.
fn n(crisp: f64, left: [f64; 3], right: [f64; 3], h: f64) -> Nt2Number {
    Nt2Number::try_new(
        crisp,
        [crisp - left[0], crisp + right[0]],
        [crisp - left[1], crisp + right[1]],
        [crisp - left[2], crisp + right[2]],
        h,
    )
    .unwrap()
}

/// A 2-D curve of four points with mixed heights and one number whose
/// centroid lies wholly right of its crisp value.
fn planar() -> FuzzyCurve<2> {
    let points = vec![
        Nt2Point::new([
            n(1.0, [0.6, 0.4, 0.2], [0.9, 0.6, 0.3], 0.6),
            n(1.0, [0.8, 0.5, 0.25], [0.5, 0.35, 0.2], 0.5),
        ]),
        Nt2Point::new([
            n(2.0, [0.1, 0.05, 0.0], [3.0, 2.0, 1.0], 0.5),
            n(4.0, [0.4, 0.3, 0.1], [0.7, 0.5, 0.2], 0.6),
        ]),
        Nt2Point::new([
            n(5.0, [0.5, 0.5, 0.5], [0.5, 0.5, 0.5], 0.7),
            n(4.5, [1.0, 0.6, 0.1], [0.2, 0.1, 0.05], 0.6),
        ]),
        Nt2Point::new([
            n(6.0, [0.3, 0.2, 0.1], [0.6, 0.2, 0.1], 0.9),
            n(1.0, [0.6, 0.4, 0.2], [0.9, 0.6, 0.3], 0.6),
        ]),
    ];
    FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 3.0, 1.0], None).unwrap()
}

/// A 3-D curve: the planar one with a third coordinate.
fn spatial() -> FuzzyCurve<3> {
    let c = planar();
    let points = c
        .points()
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let [x, y] = *p.coords();
            Nt2Point::new([x, y, n(i as f64, [0.2, 0.1, 0.0], [0.6, 0.3, 0.1], 0.4)])
        })
        .collect();
    FuzzyCurve::try_new(3, points, vec![1.0, 2.0, 1.0, 1.0], None).unwrap()
}

/// A 3 × 2 surface of asymmetric numbers.
fn surface() -> FuzzySurface<3> {
    let p = |x: f64, y: f64, z: f64| {
        Nt2Point::new([
            n(x, [0.3, 0.2, 0.1], [0.9, 0.5, 0.2], 0.6),
            n(y, [0.1, 0.05, 0.0], [2.0, 1.0, 0.5], 0.5),
            n(z, [0.5, 0.4, 0.1], [0.2, 0.1, 0.05], 0.8),
        ])
    };
    let net = vec![
        vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.5)],
        vec![p(1.0, 0.0, 0.2), p(1.0, 1.0, 1.0)],
        vec![p(2.0, 0.0, 0.4), p(2.0, 1.0, 0.3)],
    ];
    let weights = vec![vec![1.0, 2.0], vec![1.0, 1.0], vec![0.5, 1.0]];
    FuzzySurface::try_new([2, 1], net, weights, [None, None]).unwrap()
}

fn models() -> Vec<Model> {
    vec![
        Model::Planar(planar()),
        Model::Spatial(spatial()),
        Model::Surface(surface()),
    ]
}

fn run(job: &Job, method: TypeReduction, alpha: Option<f64>) -> Result<RunOutput, Error> {
    let samples = if job.model.is_surface() {
        vec![9, 7]
    } else {
        vec![33]
    };
    job.run(&job.settings(&Overrides {
        alpha,
        type_reduction: Some(method),
        samples: Some(samples),
        ..Overrides::default()
    })?)
}

#[test]
fn control_points_are_every_numbers_reduction_bit_for_bit() {
    for model in models() {
        let job = Job::new(model);
        let numbers = job.model.numbers();
        for method in TypeReduction::ALL {
            for alpha in [0.0, 0.55, 0.8, 1.0] {
                let out = run(&job, method, Some(alpha)).unwrap();
                // Stage 2 is cut at alpha only for the paper's reduction.
                let level = if method.uses_alpha() { alpha } else { 0.0 };
                assert_eq!(out.alpha, level, "{method}");
                let a = Alpha::try_new(level).unwrap();
                let cp = &out.control_points;
                for (i, point) in numbers.iter().enumerate() {
                    for (d, x) in point.iter().enumerate() {
                        let r = x.reduce(method, a);
                        let at = format!(
                            "{}, {method}, alpha {alpha}, point {i}, axis {d}",
                            job.model.summary()
                        );
                        assert_eq!(
                            cp.type_reduced_left.coord(d)[i].to_bits(),
                            r.left().to_bits(),
                            "{at}"
                        );
                        assert_eq!(
                            cp.type_reduced_right.coord(d)[i].to_bits(),
                            r.right().to_bits(),
                            "{at}"
                        );
                        assert_eq!(
                            cp.defuzzified.coord(d)[i].to_bits(),
                            r.defuzzified().to_bits(),
                            "{at}"
                        );
                        let cut = x.alpha_cut(a);
                        assert_eq!(
                            cp.alpha_cut.upper_left.coord(d)[i],
                            cut.layer(Layer::UpperLeft),
                            "{at}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn the_result_names_the_reduction_and_whether_alpha_was_used() {
    let job = Job::new(Model::Planar(planar()));
    for method in TypeReduction::ALL {
        let out = run(&job, method, Some(0.8)).unwrap();
        assert_eq!(out.type_reduction, method);
        assert_eq!(out.alpha_used, method == TypeReduction::Paper);
        assert_eq!(out.regime.is_some(), method == TypeReduction::Paper);
    }
}

#[test]
fn alpha_is_needed_by_the_paper_only() {
    let job = Job::new(Model::Planar(planar()));
    assert_eq!(
        run(&job, TypeReduction::Paper, None).unwrap_err(),
        Error::MissingAlpha
    );
    for method in [
        TypeReduction::Centroid,
        TypeReduction::NieTan,
        TypeReduction::AlphaPlanes,
    ] {
        let without = run(&job, method, None).unwrap();
        let with = run(&job, method, Some(0.8)).unwrap();
        assert_eq!(without, with, "{method}: alpha must not change the run");
        let s = job
            .settings(&Overrides {
                alpha: Some(0.8),
                type_reduction: Some(method),
                ..Overrides::default()
            })
            .unwrap();
        assert_eq!(s.unused_alpha(), Some(Alpha::try_new(0.8).unwrap()));
        assert_eq!(s.alpha(), Alpha::ZERO);
        // An alpha out of range is an error with every reduction.
        let bad = job.settings(&Overrides {
            alpha: Some(1.5),
            type_reduction: Some(method),
            ..Overrides::default()
        });
        assert!(matches!(bad, Err(Error::Setting { .. })), "{method}");
    }
    // The job's own reduction applies unless overridden.
    let job = Job {
        type_reduction: TypeReduction::NieTan,
        ..job
    };
    let s = job.settings(&Overrides::default()).unwrap();
    assert_eq!(
        (s.type_reduction(), s.unused_alpha()),
        (TypeReduction::NieTan, None)
    );
    let s = job
        .settings(&Overrides {
            alpha: Some(0.3),
            type_reduction: Some(TypeReduction::Paper),
            ..Overrides::default()
        })
        .unwrap();
    assert_eq!(
        (s.type_reduction(), s.alpha().get()),
        (TypeReduction::Paper, 0.3)
    );
}

#[test]
fn sampled_stage_curves_follow_the_reduction_off_crisp() {
    // Point 1's x has a centroid wholly right of crisp: a left curve clamped
    // to the crisp curve, as the paper's bounds would do, would show here.
    let c = planar();
    let x = c.points()[1].coords()[0];
    assert!(x.centroid().left() > x.crisp(), "{:?}", x.centroid());
    let job = Job::new(Model::Planar(c.clone()));
    for method in TypeReduction::ALL {
        let out = run(&job, method, Some(0.8)).unwrap();
        let solution = c.solve_with(Alpha::try_new(out.alpha).unwrap(), method);
        let params = out.samples.params.along();
        for (side, sampled) in [
            (Side::Left, &out.samples.type_reduced.left),
            (Side::Right, &out.samples.type_reduced.right),
        ] {
            let curve = solution.type_reduced_curve(side);
            for (k, &t) in params.iter().enumerate() {
                let exact = curve.eval(t).unwrap();
                for (d, e) in exact.iter().enumerate() {
                    let got = sampled.coord(d)[k];
                    assert!(
                        (got - e).abs() <= 1e-13 * (1.0 + e.abs()),
                        "{method} {side:?} t = {t}: {got} vs {e}"
                    );
                }
            }
        }
        let solved = solution.defuzzified_curve();
        for (k, &t) in params.iter().enumerate() {
            let exact = solved.eval(t).unwrap();
            for (d, e) in exact.iter().enumerate() {
                let got = out.samples.defuzzified.coord(d)[k];
                assert!(
                    (got - e).abs() <= 1e-13 * (1.0 + e.abs()),
                    "{method} t = {t}: {got} vs {e}"
                );
            }
        }
        let distance = solution.distance();
        assert_eq!(
            (out.error.max, out.error.rms),
            (distance.max, distance.rms),
            "{method}"
        );
    }
    // Somewhere the centroid's left curve is right of the crisp curve.
    let out = run(&job, TypeReduction::Centroid, None).unwrap();
    let (left, crisp) = (
        out.samples.type_reduced.left.coord(0),
        out.samples.crisp.coord(0),
    );
    assert!(left.iter().zip(crisp).any(|(l, c)| l > c));
}

#[test]
fn every_reduction_gives_its_own_distance_and_symmetric_spreads_none() {
    for model in models() {
        let job = Job::new(model);
        let distances: Vec<f64> = TypeReduction::ALL
            .iter()
            .map(|&m| run(&job, m, Some(0.8)).unwrap().error.max)
            .collect();
        assert!(distances.iter().all(|&d| d > 1e-3), "{distances:?}");
        for (i, a) in distances.iter().enumerate() {
            for b in &distances[i + 1..] {
                assert_ne!(a, b, "{}: {distances:?}", job.model.summary());
            }
        }
    }
    // Symmetric spreads: every reduction gives the crisp curve or surface back.
    let symmetric = |x: &Nt2Number| {
        let c = x.crisp();
        let l = [
            c - x.upper().left(),
            c - x.primary().left(),
            c - x.lower().left(),
        ];
        n(c, l, l, x.height().get())
    };
    let curve = planar();
    let points: Vec<_> = curve
        .points()
        .iter()
        .map(|p| Nt2Point::new(p.coords().map(|x| symmetric(&x))))
        .collect();
    let curve = FuzzyCurve::try_new(2, points, curve.weights().to_vec(), None).unwrap();
    let s = surface();
    let [_, nv] = s.shape();
    let net = s
        .points()
        .chunks(nv)
        .map(|row| {
            row.iter()
                .map(|p| Nt2Point::new(p.coords().map(|x| symmetric(&x))))
                .collect()
        })
        .collect();
    let weights = s.weights().chunks(nv).map(<[f64]>::to_vec).collect();
    let s = FuzzySurface::try_new([2, 1], net, weights, [None, None]).unwrap();
    for model in [Model::Planar(curve), Model::Surface(s)] {
        let job = Job::new(model);
        for method in TypeReduction::ALL {
            let out = run(&job, method, Some(0.8)).unwrap();
            assert!(
                out.error.max < 1e-13 && out.error.rms < 1e-13,
                "{method}: {:?}",
                out.error
            );
        }
    }
}

#[test]
fn surface_runs_sample_every_reduction_on_the_grid() {
    let s = surface();
    let job = Job {
        samples: Samples::Grid([5, 4]),
        ..Job::new(Model::Surface(s.clone()))
    };
    for method in TypeReduction::ALL {
        let settings = job
            .settings(&Overrides {
                alpha: Some(0.7),
                type_reduction: Some(method),
                ..Overrides::default()
            })
            .unwrap();
        let out = job.run(&settings).unwrap();
        let solution = s.solve_with(settings.alpha(), method);
        let surface = solution.defuzzified_surface();
        let t2spline::job::Parameters::Grid { u, v } = &out.samples.params else {
            panic!("a surface has a grid");
        };
        for (a, &uu) in u.iter().enumerate() {
            for (b, &vv) in v.iter().enumerate() {
                let exact = surface.eval(uu, vv).unwrap();
                for (d, e) in exact.iter().enumerate() {
                    let got = out.samples.defuzzified.coord(d)[a * v.len() + b];
                    assert!(
                        (got - e).abs() <= 1e-13 * (1.0 + e.abs()),
                        "{method} ({uu}, {vv}): {got} vs {e}"
                    );
                }
            }
        }
    }
}
