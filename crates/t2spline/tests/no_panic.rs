//! No public constructor or operation of the core panics: each is called with
//! arbitrary arguments (dimensions 1 to 5 where the type is generic, NaN and
//! infinities, empty and mismatched lists, parameters outside the domain,
//! huge degrees, orders and counts) under `catch_unwind`, and must return,
//! with a value or an error.
//!
//! The fuzz targets (`fuzz/`) and `arbitrary_bytes.rs` check that results are
//! right; this file checks only that every call returns, over the whole
//! public surface, so a new panic anywhere fails here first.

#[path = "no_panic/returns.rs"]
mod returns;

use proptest::prelude::*;
use returns::returns;
use t2spline::fit::{
    fit_curve, fuzzify, fuzzify_number, percentile, FitOptions, FuzzifyRule, Parametrization,
};
use t2spline::job::{Job, Model, Overrides, Samples, MAX_DERIVATIVE_ORDER, MAX_SAMPLES};
use t2spline::nurbs::basis::try_basis_functions;
use t2spline::nurbs::derivatives::try_basis_derivatives;
use t2spline::reduction::discrete::SampledSet;
use t2spline::sampling::{Params, Sampler};
use t2spline::{
    Alpha, Axis, Direction, Error, FuzzyCurve, FuzzySurface, KnotVector, Layer, Nt2Number,
    Nt2Point, NurbsCurve, NurbsSurface, TypeReduction,
};

/// Any float, with the special values and the ends of the input range often.
fn float() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -4.0..4.0f64,
        2 => (0..=8i32).prop_map(|k| f64::from(k) / 8.0),
        1 => any::<f64>(),
        1 => prop::sample::select(vec![
            f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -0.0, 1.0, 1e150, -1e150, 1e300,
            f64::MIN_POSITIVE, 5e-324, f64::MAX,
        ]),
    ]
}

/// Small counts mostly, sometimes huge ones.
fn count() -> impl Strategy<Value = usize> {
    prop_oneof![
        8 => 0..8usize,
        1 => prop::sample::select(vec![64, 65, 1 << 20, usize::MAX / 2, usize::MAX]),
    ]
}

fn floats(max: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(float(), 0..max)
}

/// `values` made to fit a curve of `count` control points most of the time
/// (`fit`): weights in range and non-decreasing knots of the right length,
/// so that the operations, not only the constructors, see arbitrary input.
fn fitted(values: &[f64], len: usize, fit: bool, default: f64) -> Vec<f64> {
    if !fit {
        return values.to_vec();
    }
    let mut out: Vec<f64> = (0..len.min(1 << 10))
        .map(|i| match values.get(i) {
            Some(&v) if v.is_finite() && v.abs() > 0.1 && v.abs() < 10.0 => v.abs(),
            _ => default + i as f64 * 0.25,
        })
        .collect();
    if default == 0.0 {
        out.sort_by(f64::total_cmp);
    }
    out
}

/// Points of dimension `D` from a flat list (the last incomplete point dropped).
fn points<const D: usize>(flat: &[f64]) -> Vec<[f64; D]> {
    flat.chunks_exact(D)
        .map(|c| std::array::from_fn(|i| c[i]))
        .collect()
}

/// A fuzzy number from seven arbitrary values and a height, or a valid one
/// around the crisp value when those are refused.
fn number(v: &[f64]) -> Nt2Number {
    let at = |i: usize| v.get(i).copied().unwrap_or(0.0);
    returns("Nt2Number::try_new", || {
        Nt2Number::try_new(at(0), [at(1), at(2)], [at(3), at(4)], [at(5), at(6)], at(7))
    })
    .or_else(|_| {
        let c = if at(0).is_finite() && at(0).abs() < 1e3 {
            at(0)
        } else {
            0.0
        };
        Nt2Number::try_new(
            c,
            [c - 1.0, c + 1.0],
            [c - 0.5, c + 0.5],
            [c - 0.2, c + 0.2],
            0.5,
        )
    })
    .unwrap_or_else(|e| panic!("a valid number was refused: {e}"))
}

fn fuzzy_points<const D: usize>(flat: &[f64]) -> Vec<Nt2Point<D>> {
    flat.chunks_exact(8 * D)
        .map(|c| Nt2Point::new(std::array::from_fn(|d| number(&c[8 * d..8 * d + 8]))))
        .collect()
}

/// Every operation of a curve of dimension `D` on arbitrary arguments.
fn curve_operations<const D: usize>(
    degree: usize,
    flat: &[f64],
    weights: &[f64],
    knots: &[f64],
    t: &[f64],
    n: usize,
    fit: bool,
) {
    let cps = points::<D>(flat);
    let count = cps.len();
    let weights = &fitted(weights, count, fit, 1.0)[..];
    let knots = &fitted(
        knots,
        count.saturating_add(degree).saturating_add(1),
        fit,
        0.0,
    )[..];
    returns("KnotVector::try_new", || {
        KnotVector::try_new(knots.to_vec(), degree, count)
    })
    .ok();
    returns("KnotVector::clamped_uniform", || {
        KnotVector::clamped_uniform(degree, count)
    })
    .ok();
    let clamped = returns("NurbsCurve::try_clamped", || {
        NurbsCurve::<D>::try_clamped(degree, cps.clone(), weights.to_vec())
    });
    let given = returns("NurbsCurve::try_new", || {
        KnotVector::try_new(knots.to_vec(), degree, count)
            .and_then(|k| NurbsCurve::<D>::try_new(cps.clone(), weights.to_vec(), k))
    });
    if D > 3 {
        assert_eq!(
            NurbsCurve::<D>::try_clamped(0, vec![[0.0; D]], vec![1.0]).unwrap_err(),
            Error::Dimension { dimension: D }
        );
    }
    let target: [f64; D] = std::array::from_fn(|i| t.get(i).copied().unwrap_or(0.5));
    for curve in [clamped, given].into_iter().flatten() {
        let k = curve.knots();
        for &u in t {
            returns("eval", || curve.eval(u)).ok();
            returns("rational_basis", || curve.rational_basis(u)).ok();
            returns("derivatives", || curve.derivatives(u, n)).ok();
            returns("tangent", || curve.tangent(u)).ok();
            returns("curvature", || curve.curvature(u)).ok();
            returns("insert_knot", || curve.insert_knot(u, n)).ok();
            returns("split_at", || curve.split_at(u)).ok();
            returns("segment", || curve.segment(u, u + 0.25)).ok();
            returns("arc_length_between", || curve.arc_length_between(u, 0.5)).ok();
            returns("param_at_length", || curve.param_at_length(u)).ok();
            returns("Domain::check", || curve.domain().check(u)).ok();
            returns("find_span", || k.find_span(u));
            returns("multiplicity", || k.multiplicity(u));
            returns("try_basis_functions", || {
                try_basis_functions(k.as_slice(), degree, n, u)
            })
            .ok();
            returns("try_basis_derivatives", || {
                try_basis_derivatives(k.as_slice(), degree, n, u, n)
            })
            .ok();
        }
        returns("sample", || curve.sample(t)).ok();
        returns("sample_soa", || curve.sample_soa(t)).ok();
        returns("sample_soa uniform", || {
            curve.sample_soa(Params::Uniform(n.min(64)))
        })
        .ok();
        for huge in [usize::MAX, usize::MAX / 8 + 1] {
            let e = returns("sample_soa huge", || {
                curve.sample_soa(Params::Uniform(huge))
            });
            assert_eq!(e.unwrap_err(), Error::Memory { values: huge });
        }
        returns("refine_knots", || curve.refine_knots(t)).ok();
        returns("elevate_degree", || curve.elevate_degree(n)).ok();
        returns("clamped", || curve.clamped());
        returns("arc_length", || curve.arc_length());
        returns("bounding_box", || curve.bounding_box());
        returns("closest_point", || curve.closest_point(target));
        returns("uniform", || curve.domain().uniform(n.min(64)).unwrap());
        returns("Sampler::try_new", || {
            Sampler::try_new(k, curve.weights(), &[t.to_vec()]).and_then(|s| s.sample(t))
        })
        .ok();
    }
}

/// Every operation of a fuzzy curve of dimension `D`.
#[allow(clippy::too_many_arguments)] // what proptest draws, one by one
fn fuzzy_curve_operations<const D: usize>(
    degree: usize,
    flat: &[f64],
    weights: &[f64],
    knots: Option<Vec<f64>>,
    t: &[f64],
    n: usize,
    alpha: f64,
    fit: bool,
) {
    let pts = fuzzy_points::<D>(flat);
    let count = pts.len();
    let weights = &fitted(weights, count, fit, 1.0)[..];
    let knots = knots.map(|k| fitted(&k, count.saturating_add(degree).saturating_add(1), fit, 0.0));
    let curve = returns("FuzzyCurve::try_new", || {
        FuzzyCurve::<D>::try_new(degree, pts.clone(), weights.to_vec(), knots)
    });
    let Ok(curve) = curve else { return };
    let alpha = Alpha::try_new(alpha).unwrap_or(Alpha::try_new(0.5).unwrap());
    for &u in t {
        returns("eval_layers", || curve.eval_layers(u)).ok();
        returns("FuzzyCurve::eval", || curve.eval(u)).ok();
        returns("FuzzyCurve::insert_knot", || curve.insert_knot(u, n)).ok();
        returns("FuzzyCurve::split_at", || curve.split_at(u)).ok();
        returns("FuzzyCurve::segment", || curve.segment(u, u + 0.5)).ok();
        returns("FuzzyCurve::derivatives", || curve.derivatives(u, n)).ok();
    }
    // The set view: grades of arbitrary points, a region and its sections.
    let point: [f64; D] = std::array::from_fn(|c| t.get(c).copied().unwrap_or(0.5));
    returns("FuzzyCurve::membership", || curve.membership(&point)).ok();
    for plane in t2spline::set::Plane::ALL {
        for m in t2spline::set::MEMBERSHIPS {
            returns("FuzzyCurve::region_in", || {
                curve.region_in(plane, m, alpha, None)
            })
            .ok();
        }
    }
    // The quantities measured on the curve, at arbitrary parameters, orders
    // and levels.
    let mut levels = t2spline::measure::uniform_levels(3).unwrap();
    levels.push(alpha);
    if let Ok(options) = t2spline::measure::MeasureOptions::new(levels, t.to_vec(), n) {
        returns("FuzzyCurve::measure", || curve.measure(&options)).ok();
    }
    for m in t2spline::set::MEMBERSHIPS {
        returns("FuzzyCurve::length_bracket", || {
            curve.length_bracket(m, alpha)
        });
        for &u in t {
            returns("FuzzyCurve::derivative_bracket", || {
                curve.derivative_bracket(u, n, m, alpha)
            })
            .ok();
            returns("FuzzyCurve::curvature_bracket", || {
                curve.curvature_bracket(u, m, alpha)
            })
            .ok();
        }
    }
    returns("FuzzyCurve::refine_knots", || curve.refine_knots(t)).ok();
    returns("FuzzyCurve::elevate_degree", || curve.elevate_degree(n)).ok();
    returns("axes", || curve.axes());
    returns("bounding_box", || curve.bounding_box());
    returns("sample_layers", || curve.sample_layers(t)).ok();
    returns("sample_sweep", || curve.sample_sweep(t, &[alpha])).ok();
    let solution = returns("solve", || curve.solve(alpha));
    returns("distance", || solution.distance());
    returns("sample_stages", || solution.sample_stages(t)).ok();
    let mut out = vec![vec![0.0; t.len()]; n.min(30)];
    let mut slices: Vec<&mut [f64]> = out.iter_mut().map(Vec::as_mut_slice).collect();
    returns("sample_layers_into_slices", || {
        curve.sample_layers_into_slices(t, &mut slices)
    })
    .ok();
    if let Some(p) = pts.first() {
        for axis in Axis::ALL {
            assert_eq!(p.coord(axis).is_some(), axis.index() < D);
        }
    }
}

/// Every operation of a surface of dimension `D`.
fn surface_operations<const D: usize>(
    degree: [usize; 2],
    rows: usize,
    flat: &[f64],
    weights: &[f64],
    t: &[f64],
    n: usize,
) {
    let cps = points::<D>(flat);
    let weights = &fitted(weights, cps.len(), true, 1.0)[..];
    let rows = rows.max(1);
    let per_row = (cps.len() / rows).max(1);
    let net: Vec<Vec<[f64; D]>> = cps.chunks(per_row).take(rows).map(<[_]>::to_vec).collect();
    let wnet: Vec<Vec<f64>> = weights
        .chunks(per_row)
        .take(rows)
        .map(<[_]>::to_vec)
        .collect();
    let surface = returns("NurbsSurface::try_clamped", || {
        NurbsSurface::<D>::try_clamped(degree, net.clone(), wnet.clone())
    });
    let Ok(s) = surface else { return };
    for (&u, &v) in t.iter().zip(t.iter().rev()) {
        returns("surface eval", || s.eval(u, v)).ok();
        returns("surface rational_basis", || s.rational_basis(u, v)).ok();
        returns("surface derivatives", || s.derivatives(u, v, n)).ok();
        returns("control_point", || s.control_point(n, n.wrapping_sub(1))).ok();
        for d in [Direction::U, Direction::V] {
            returns("isocurve", || s.isocurve(d, u)).ok();
            returns("surface insert_knot", || s.insert_knot(d, u, n)).ok();
            returns("surface split_at", || s.split_at(d, u)).ok();
        }
        returns("surface segment", || s.segment([u, v], [v, u])).ok();
    }
    for d in [Direction::U, Direction::V] {
        returns("surface refine_knots", || s.refine_knots(d, t)).ok();
        returns("surface elevate_degree", || s.elevate_degree(d, n)).ok();
    }
    returns("sample_grid", || s.sample_grid(t, t)).ok();
    // NaN, ∞ and huge targets are errors.
    let target: [f64; D] = std::array::from_fn(|d| t.get(d).copied().unwrap_or(0.5));
    let near = returns("surface closest_point", || s.closest_point(target));
    assert_eq!(near.is_err(), !target.iter().all(|x| x.abs() <= 1e150));
    returns("surface bounding_box", || s.bounding_box());
    // The quantities of surfaces in space only.
    if let Some(s) = (&s as &dyn std::any::Any).downcast_ref::<NurbsSurface<3>>() {
        for (&u, &v) in t.iter().zip(t.iter().rev()) {
            returns("surface normal", || s.normal(u, v)).ok();
            returns("surface curvature", || s.curvature(u, v)).ok();
        }
    }
    let huge = Params::Uniform(1 << 33);
    assert!(returns("sample_grid huge", || s.sample_grid(huge, huge)).is_err());
}

fn fuzzy_surface_operations<const D: usize>(rows: usize, flat: &[f64], t: &[f64], alpha: f64) {
    let pts = fuzzy_points::<D>(flat);
    let per_row = pts.len().div_ceil(rows.max(1)).max(1);
    let net: Vec<Vec<Nt2Point<D>>> = pts.chunks(per_row).map(<[_]>::to_vec).collect();
    let weights: Vec<Vec<f64>> = net.iter().map(|r| vec![1.0; r.len()]).collect();
    let surface = returns("FuzzySurface::try_new", || {
        FuzzySurface::<D>::try_new([1, 1], net.clone(), weights.clone(), [None, None])
    });
    let Ok(s) = surface else { return };
    let alpha = Alpha::try_new(alpha).unwrap_or(Alpha::try_new(0.5).unwrap());
    returns("FuzzySurface::sample_layers", || s.sample_layers(t, t)).ok();
    let solution = returns("FuzzySurface::solve", || s.solve(alpha));
    returns("SurfaceSolution::distance", || solution.distance());
    let target: [f64; D] = std::array::from_fn(|d| t.get(d).copied().unwrap_or(0.5));
    returns("FuzzySurface::closest_points", || s.closest_points(target)).ok();
    returns("FuzzySurface::bounding_box", || s.bounding_box());
    returns("FuzzySurface::membership", || s.membership(&target)).ok();
    if let Some(s) = (&s as &dyn std::any::Any).downcast_ref::<FuzzySurface<3>>() {
        for (&u, &v) in t.iter().zip(t.iter().rev()) {
            returns("FuzzySurface::curvatures", || s.curvatures(u, v)).ok();
        }
        returns("FuzzySurface::sections", || {
            s.sections([target[0], target[1]], &[alpha])
        })
        .ok();
    }
}

/// Calls `$f::<D>` for D = 1 ..= 5.
macro_rules! every_dimension {
    ($f:ident($($arg:expr),*)) => {{
        $f::<1>($($arg),*);
        $f::<2>($($arg),*);
        $f::<3>($($arg),*);
        $f::<4>($($arg),*);
        $f::<5>($($arg),*);
    }};
}

// Every operation of a fuzzy curve in five dimensions takes seconds in
// debug: 8 cases by default, 48 under T2SPLINE_LONG_TESTS=1.
proptest! {
    #![proptest_config(t2spline::strategies::cases(8, 48))]

    #[test]
    fn fuzzy_curves_never_panic(
        degree in count(), flat in floats(120), weights in floats(6), knots in prop::option::of(floats(12)),
        t in floats(5), n in count(), alpha in float(), fit in prop::bool::weighted(0.8),
    ) {
        every_dimension!(fuzzy_curve_operations(degree, &flat, &weights, knots.clone(), &t, n, alpha, fit));
    }
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(32, 96))]

    #[test]
    fn fuzzy_surfaces_never_panic(rows in 0..4usize, flat in floats(200), t in floats(4), alpha in float()) {
        every_dimension!(fuzzy_surface_operations(rows, &flat, &t, alpha));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn numbers_never_panic(v in floats(9), alpha in float(), n in count()) {
        let x = number(&v);
        returns("Nt2Number::try_new", || {
            Nt2Number::try_new(v.first().copied().unwrap_or(0.0), [alpha, alpha], [alpha, 1.0], [0.0, alpha], alpha)
        }).ok();
        returns("Alpha::try_new", || Alpha::try_new(alpha)).ok();
        if let Ok(a) = Alpha::try_new(alpha) {
            returns("alpha_cut", || x.alpha_cut(a).type_reduce().defuzzify());
            for method in [TypeReduction::Paper, TypeReduction::Centroid, TypeReduction::NieTan, TypeReduction::AlphaPlanes] {
                returns("reduce", || x.reduce(method, a));
            }
        }
        returns("layer", || Layer::ALL.map(|l| x.layer(l)));
        let _ = returns("discrete::sample", || {
            t2spline::reduction::discrete::sample(&x, n.min(1 << 12))
        });
        assert!(t2spline::reduction::discrete::sample(&x, usize::MAX).is_err());
        let third = v.len() / 3;
        returns("SampledSet::try_new", || {
            SampledSet::try_new(&v[..third], &v[third..2 * third], &v[2 * third..]).map(|s| (s.km(), s.ekm(), s.eiasc(), s.nie_tan()))
        }).ok();
        returns("percentile", || percentile(&v, alpha));
        let mut readings = v.clone();
        returns("fuzzify_number", || {
            FuzzifyRule::try_new(alpha, 0.5).and_then(|r| fuzzify_number(&mut readings, &r))
        }).ok();
    }

    #[test]
    fn curves_never_panic(
        degree in count(), flat in floats(40), weights in floats(10), knots in floats(16),
        t in floats(6), n in count(), fit in prop::bool::weighted(0.8),
    ) {
        every_dimension!(curve_operations(degree, &flat, &weights, &knots, &t, n, fit));
    }

    #[test]
    fn surfaces_never_panic(
        du in prop_oneof![4 => 0..3usize, 1 => count()], dv in prop_oneof![4 => 0..3usize, 1 => count()], rows in 0..5usize, flat in floats(60), weights in floats(20),
        t in floats(4), n in count(),
    ) {
        every_dimension!(surface_operations([du, dv], rows, &flat, &weights, &t, n));
    }

    #[test]
    fn fits_never_panic(
        degree in count(), flat in floats(30), control in count(), tolerance in float(),
        stations in prop::collection::vec(floats(9), 0..5),
    ) {
        fn fits<const D: usize>(degree: usize, flat: &[f64], control: usize, tolerance: f64, stations: &[Vec<f64>]) {
            let q = points::<D>(flat);
            for p in [Parametrization::ChordLength, Parametrization::Centripetal, Parametrization::Uniform] {
                for count in [None, Some(control)] {
                    if let Ok(options) = returns("FitOptions::new", || FitOptions::new(degree, count)) {
                        returns("fit_curve", || fit_curve(&q, &options.with_parametrization(p))).ok();
                    }
                }
            }
            let readings: Vec<Vec<[f64; D]>> = stations.iter().map(|s| points::<D>(s)).collect();
            returns("fuzzify", || FuzzifyRule::try_new(tolerance, 0.5).and_then(|r| fuzzify(&readings, &r))).ok();
        }
        every_dimension!(fits(degree, &flat, control, tolerance, &stations));
    }

    /// Settings made by hand (their fields are public) are checked again by
    /// `Job::run`.
    #[test]
    fn runs_with_any_settings_never_panic(
        alpha in 0.0..=1.0f64, samples in count(), u in count(), derivatives in prop::option::of(count()),
    ) {
        let pts = fuzzy_points::<2>(&[0.0; 32]);
        let curve = FuzzyCurve::try_new(1, pts, vec![1.0; 2], None).unwrap();
        let job = Job::new(Model::Planar(curve));
        for samples in [Samples::Along(samples), Samples::Grid([samples, u])] {
            let valid = returns("Job::settings", || job.settings(&Overrides {
                alpha: Some(alpha),
                samples: Some(samples.counts()),
                derivatives: derivatives.map(|k| k as i64),
                ..Overrides::default()
            }));
            // Settings are made only by `Job::settings`: a curve takes one
            // count, at most the limit, and derivatives within theirs.
            let along = matches!(samples, Samples::Along(n) if (2..=MAX_SAMPLES).contains(&n));
            let orders = derivatives.is_none_or(|k| {
                (1..=MAX_DERIVATIVE_ORDER).contains(&k) && matches!(samples, Samples::Along(n) if k.saturating_mul(n) <= MAX_SAMPLES)
            });
            prop_assert_eq!(valid.is_ok(), along && orders, "{:?} {:?}", samples, derivatives);
            if let Ok(settings) = valid {
                let out = returns("Job::run", || job.run(&settings));
                prop_assert!(out.is_ok(), "{:?}", settings);
            }
        }
    }
}

/// Settings made for one job run another only where they fit it: a curve's
/// settings given to a surface job (and the reverse) are an error naming
/// the samples, not a panic.
#[test]
fn settings_of_another_kind_of_job_are_errors() {
    let pts = fuzzy_points::<2>(&[0.0; 32]);
    let curve = Job::new(Model::Planar(
        FuzzyCurve::try_new(1, pts, vec![1.0; 2], None).unwrap(),
    ));
    let n = Nt2Number::try_new(0.0, [-1.0, 1.0], [-0.5, 0.5], [-0.2, 0.2], 0.5).unwrap();
    let net = vec![vec![Nt2Point::new([n; 3]); 2]; 2];
    let surface = Job::new(Model::Surface(
        FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).unwrap(),
    ));
    let given = Overrides {
        alpha: Some(0.5),
        ..Overrides::default()
    };
    let (of_curve, of_surface) = (
        curve.settings(&given).unwrap(),
        surface.settings(&given).unwrap(),
    );
    assert!(curve.run(&of_curve).is_ok() && surface.run(&of_surface).is_ok());
    for e in [
        surface.run(&of_curve).unwrap_err(),
        curve.run(&of_surface).unwrap_err(),
    ] {
        assert_eq!(e.setting(), Some(t2spline::job::Setting::Samples), "{e}");
    }
}

/// `NurbsCurve::<4>::try_new` reached `Axis::first::<4>`, which indexed past
/// the three axes; a fourth coordinate is now refused by the constructor.
#[test]
fn a_curve_of_four_coordinates_is_an_error() {
    let knots = KnotVector::clamped_uniform(1, 2).unwrap();
    let e = NurbsCurve::<4>::try_new(vec![[0.0; 4], [1.0; 4]], vec![1.0, 1.0], knots).unwrap_err();
    assert_eq!(e, Error::Dimension { dimension: 4 });
    assert_eq!(Axis::first::<0>(), Err(Error::Dimension { dimension: 0 }));
    let n = Nt2Number::try_new(0.0, [-1.0, 1.0], [-0.5, 0.5], [0.0, 0.0], 0.5).unwrap();
    let e = FuzzyCurve::<5>::try_new(0, vec![Nt2Point::new([n; 5])], vec![1.0], None).unwrap_err();
    assert_eq!(e.to_string(), "a point has 1, 2 or 3 coordinates, not 5");
}

/// Derivatives at parameters outside the domain were computed from a result
/// read back from a file and panicked; they are computed in `Job::run` now,
/// only at the run's own parameters, and settings outside the rules (as a
/// result read back could carry) cannot be made.
#[test]
fn derivatives_of_settings_outside_the_rules_are_errors() {
    let pts = fuzzy_points::<2>(&[0.0; 32]);
    let curve = FuzzyCurve::try_new(1, pts, vec![1.0; 2], None).unwrap();
    let job = Job::new(Model::Planar(curve.clone()));
    for (samples, derivatives) in [(1, 1), (3, 0), (3, i64::MAX), (u64::MAX, 1)] {
        let settings = job.settings(&Overrides {
            alpha: Some(0.5),
            samples: Some(vec![samples]),
            derivatives: Some(derivatives),
            ..Overrides::default()
        });
        assert!(settings.is_err(), "{samples} {derivatives}");
    }
    let crisp = curve.crisp_curve();
    for t in [-0.5, 1.5, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(crisp.derivatives(t, 2), Err(Error::OutOfDomain { .. })),
            "{t}"
        );
    }
}
