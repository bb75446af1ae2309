//! `Job::geometry` (the exact curves that CAD files carry) against `Job::run`'s
//! samples, and `fuzzify` (readings into fuzzy numbers) on any readings.

use proptest::prelude::*;
use t2spline::fit::{fuzzify, percentile, FuzzifyRule};
use t2spline::job::{Geometry, Job, Model, Overrides, Points};
use t2spline::strategies::fuzzy_curve;
use t2spline::NurbsCurve;

/// The value of a curve given as pieces at `t`: the piece whose domain holds
/// `t`, the right one at a jump (SPEC §6).
fn eval(pieces: &[NurbsCurve<3>], t: f64) -> [f64; 3] {
    let last = pieces.len() - 1;
    let piece = pieces
        .iter()
        .enumerate()
        .find(|(i, p)| {
            let d = p.domain();
            d.start <= t && (t < d.end || (*i == last && t <= d.end))
        })
        .map(|(_, p)| p)
        .unwrap_or_else(|| panic!("no piece holds t = {t}"));
    piece.eval(t).unwrap()
}

/// Every curve of the geometry at every sample parameter, against the run.
fn agrees(job: &Job, geometry: &Geometry, tolerance: f64) -> Result<(), TestCaseError> {
    let settings = job
        .settings(&Overrides {
            alpha: Some(0.3),
            samples: Some(41),
            ..Overrides::default()
        })
        .unwrap();
    let out = job.run(&settings).unwrap();
    let curves = &out.curves;
    let reference = |name: &str| -> &Points {
        match name {
            "crisp" => &curves.crisp,
            "defuzzified" => &curves.defuzzified,
            "upper_left" => &curves.layers.upper_left,
            "primary_left" => &curves.layers.primary_left,
            "lower_left" => &curves.layers.lower_left,
            "lower_right" => &curves.layers.lower_right,
            "primary_right" => &curves.layers.primary_right,
            "upper_right" => &curves.layers.upper_right,
            other => panic!("unexpected curve {other}"),
        }
    };
    prop_assert_eq!(geometry.curves.len(), 8);
    for curve in &geometry.curves {
        let want = reference(curve.name);
        // Pieces are continuous: no interior knot of full multiplicity.
        for piece in &curve.pieces {
            let u = piece.knots().as_slice();
            let d = piece.domain();
            for &v in u.iter().filter(|&&v| d.start < v && v < d.end) {
                prop_assert!(piece.knots().multiplicity(v) <= piece.degree());
            }
        }
        for (i, &t) in curves.params.iter().enumerate() {
            let got = eval(&curve.pieces, t);
            for (axis, &value) in got.iter().enumerate() {
                let expected = want.coord(axis).get(i).copied().unwrap_or(0.0);
                let scale = 1.0 + expected.abs();
                prop_assert!(
                    (value - expected).abs() <= tolerance * scale,
                    "{} at t = {t}, axis {axis}: {value} vs {expected}",
                    curve.name
                );
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn exact_curves_are_the_run_s_curves_in_2d(c in fuzzy_curve::<2>()) {
        let job = Job::new(Model::Planar(c));
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
    fn exact_curves_are_the_run_s_curves_in_3d(c in fuzzy_curve::<3>()) {
        let job = Job::new(Model::Spatial(c));
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
        let p: Vec<f64> = q.iter().map(|&q| percentile(&x, q)).collect();
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
