//! `Job::geometry` (the exact curves and surfaces that CAD files carry)
//! against `Job::run`'s samples, and `fuzzify` (readings into fuzzy numbers) on any readings.

use proptest::prelude::*;
use t2spline::fit::{fuzzify, percentile, FuzzifyRule};
use t2spline::job::{Geometry, Job, Model, Overrides, Parameters, Points, Sampled};
use t2spline::strategies::{fuzzy_curve, fuzzy_surface};
use t2spline::{Direction, NurbsCurve, NurbsSurface, TypeReduction};

/// The piece among `domains` that holds `t`: the right one at a shared end
/// (a jump is taken from the right, docs/method.md §6), the last one at the end.
fn holding(domains: &[(f64, f64)], t: f64) -> usize {
    let last = domains.len() - 1;
    domains
        .iter()
        .enumerate()
        .position(|(i, &(a, b))| a <= t && (t < b || (i == last && t <= b)))
        .unwrap_or_else(|| panic!("no piece holds {t} in {domains:?}"))
}

/// The value of a curve given as pieces at `t`.
fn eval(pieces: &[NurbsCurve<3>], t: f64) -> [f64; 3] {
    let domains: Vec<_> = pieces
        .iter()
        .map(|p| (p.domain().start, p.domain().end))
        .collect();
    pieces[holding(&domains, t)].eval(t).unwrap()
}

/// The value of a surface given as patches (rows along u, each along v).
fn eval_surface(patches: &[NurbsSurface<3>], u: f64, v: f64) -> [f64; 3] {
    let mut us: Vec<(f64, f64)> = patches
        .iter()
        .map(|p| (p.domain(Direction::U).start, p.domain(Direction::U).end))
        .collect();
    us.dedup();
    let mut vs: Vec<(f64, f64)> = patches
        .iter()
        .map(|p| (p.domain(Direction::V).start, p.domain(Direction::V).end))
        .collect();
    vs.sort_by(|a, b| a.0.total_cmp(&b.0));
    vs.dedup();
    let (i, j) = (holding(&us, u), holding(&vs, v));
    patches[i * vs.len() + j].eval(u, v).unwrap()
}

/// The run's sampled points of one named curve or surface.
fn reference<'a>(s: &'a Sampled, name: &str) -> &'a Points {
    match name {
        "crisp" => &s.crisp,
        "defuzzified" => &s.defuzzified,
        "upper_left" => &s.layers.upper_left,
        "primary_left" => &s.layers.primary_left,
        "lower_left" => &s.layers.lower_left,
        "lower_right" => &s.layers.lower_right,
        "primary_right" => &s.layers.primary_right,
        "upper_right" => &s.layers.upper_right,
        other => panic!("unexpected name {other}"),
    }
}

fn close(
    got: [f64; 3],
    want: &Points,
    i: usize,
    tolerance: f64,
    what: &str,
) -> Result<(), TestCaseError> {
    for (axis, &value) in got.iter().enumerate() {
        let expected: f64 = want.coord(axis).get(i).copied().unwrap_or(0.0);
        let scale = 1.0 + expected.abs();
        prop_assert!(
            (value - expected).abs() <= tolerance * scale,
            "{what}, axis {axis}: {value} vs {expected}"
        );
    }
    Ok(())
}

/// Any type reduction (docs/method.md §9): the defuzzified curve is the reduction's.
fn reduction() -> impl Strategy<Value = TypeReduction> {
    proptest::sample::select(TypeReduction::ALL.to_vec())
}

/// Every curve or surface of the geometry at every sample, against the run
/// (with the job's type reduction).
fn agrees(job: &Job, geometry: &Geometry, tolerance: f64) -> Result<(), TestCaseError> {
    let samples = if job.model.is_surface() {
        vec![9, 7]
    } else {
        vec![41]
    };
    let settings = job
        .settings(&Overrides {
            alpha: Some(0.3),
            samples: Some(samples),
            ..Overrides::default()
        })
        .unwrap();
    let out = job.run(&settings).unwrap();
    let sampled = &out.samples;
    prop_assert_eq!(geometry.curves.len() + geometry.surfaces.len(), 8);
    for curve in &geometry.curves {
        // Pieces are continuous: no interior knot of full multiplicity.
        for piece in &curve.pieces {
            let d = piece.domain();
            for &v in piece
                .knots()
                .as_slice()
                .iter()
                .filter(|&&v| d.start < v && v < d.end)
            {
                prop_assert!(piece.knots().multiplicity(v) <= piece.degree());
            }
        }
        let want = reference(sampled, curve.name);
        for (i, &t) in sampled.params.along().iter().enumerate() {
            close(
                eval(&curve.pieces, t),
                want,
                i,
                tolerance,
                &format!("{} at t = {t}", curve.name),
            )?;
        }
    }
    for surface in &geometry.surfaces {
        let Parameters::Grid { u, v } = &sampled.params else {
            panic!("a surface is sampled on a grid")
        };
        let want = reference(sampled, surface.name);
        for (a, &ua) in u.iter().enumerate() {
            for (b, &vb) in v.iter().enumerate() {
                let got = eval_surface(&surface.patches, ua, vb);
                close(
                    got,
                    want,
                    a * v.len() + b,
                    tolerance,
                    &format!("{} at ({ua}, {vb})", surface.name),
                )?;
            }
        }
    }
    Ok(())
}

// A surface job runs in a fraction of a second in debug: 16 cases by
// default, 32 under T2SPLINE_LONG_TESTS=1.
proptest! {
    #![proptest_config(t2spline::strategies::cases(16, 32))]

    #[test]
    fn exact_surfaces_are_the_run_s_surfaces(
        s in fuzzy_surface::<3>(),
        type_reduction in reduction(),
    ) {
        let job = Job { type_reduction, ..Job::new(Model::Surface(s)) };
        let settings = job.settings(&Overrides { alpha: Some(0.3), ..Overrides::default() }).unwrap();
        let g = job.geometry(&settings).unwrap();
        prop_assert!(g.curves.is_empty());
        agrees(&job, &g, 1e-12)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn exact_curves_are_the_run_s_curves_in_2d(
        c in fuzzy_curve::<2>(),
        type_reduction in reduction(),
    ) {
        let job = Job { type_reduction, ..Job::new(Model::Planar(c)) };
        let settings = job.settings(&Overrides { alpha: Some(0.3), ..Overrides::default() }).unwrap();
        let g = job.geometry(&settings).unwrap();
        prop_assert_eq!(g.dimension, 2);
        agrees(&job, &g, 1e-12)?;
        // Clamping (knot insertion) changes only rounding.
        agrees(&job, &g.clamped(), 1e-11)?;
        for piece in g.clamped().curves.iter().flat_map(|c| &c.pieces) {
            prop_assert!(piece.knots().is_clamped());
        }
    }

    #[test]
    fn exact_curves_are_the_run_s_curves_in_3d(
        c in fuzzy_curve::<3>(),
        type_reduction in reduction(),
    ) {
        let job = Job { type_reduction, ..Job::new(Model::Spatial(c)) };
        let settings = job.settings(&Overrides { alpha: Some(0.3), ..Overrides::default() }).unwrap();
        let g = job.geometry(&settings).unwrap();
        agrees(&job, &g, 1e-12)?;
        agrees(&job, &g.clamped(), 1e-11)?;
    }

    #[test]
    fn percentiles_grow_with_q_and_stay_within_the_readings(
        mut x in proptest::collection::vec(-1e6..1e6f64, 2..40),
        q in proptest::collection::vec(0.0..=100.0f64, 2..10),
    ) {
        x.sort_by(f64::total_cmp);
        let mut q = q;
        q.sort_by(f64::total_cmp);
        let p: Vec<f64> = q.iter().map(|&q| percentile(&x, q).unwrap()).collect();
        prop_assert!(p.iter().all(|v| x[0] <= *v && *v <= x[x.len() - 1]), "{p:?}");
        prop_assert!(p.windows(2).all(|w| w[0] <= w[1]), "{q:?} -> {p:?}");
    }

    #[test]
    fn any_finite_readings_make_valid_fuzzy_points(
        stations in proptest::collection::vec(
            proptest::collection::vec(proptest::array::uniform2(-1e3..1e3f64), 2..25), 1..8),
        tolerance in 0.0..1.0f64,
        h in 0.01..=1.0f64,
    ) {
        let rule = FuzzifyRule::try_new(tolerance, h).unwrap();
        let points = fuzzify(&stations, &rule).unwrap();
        for (p, readings) in points.iter().zip(&stations) {
            for (axis, x) in p.coords().iter().enumerate() {
                let lo = readings.iter().map(|r| r[axis]).fold(f64::INFINITY, f64::min);
                let hi = readings.iter().map(|r| r[axis]).fold(f64::NEG_INFINITY, f64::max);
                prop_assert_eq!(x.upper().left(), lo - tolerance);
                prop_assert_eq!(x.upper().right(), hi + tolerance);
                prop_assert_eq!(x.height().get(), h);
            }
        }
    }
}
