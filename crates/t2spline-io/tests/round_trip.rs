//! JSON round trips: a job of a curve or a surface through `job_json`
//! (compact and pretty) and back through the validator, and a result through
//! serde; every f64 exactly.

use proptest::prelude::*;
use t2spline::job::{Job, Model, Overrides, Samples, MAX_SAMPLES};
use t2spline::{strategies, Alpha, FuzzyCurve, TypeReduction};
use t2spline_io::to_json_pretty;

/// Descriptions with quotes, escapes and non-ASCII text, and arbitrary ones.
fn description() -> impl Strategy<Value = Option<String>> {
    prop_oneof![
        Just(None),
        Just(Some(String::new())),
        Just(Some(
            "quotes \" and \\ backslash, tab\t, newline\n, {braces}".to_owned()
        )),
        Just(Some(
            "ünïcödé — α ≤ h, 日本語, emoji 🎯, nul \u{0} ok".to_owned()
        )),
        any::<String>().prop_map(Some),
    ]
}

/// No alpha, the ends of [0, 1], or any level.
fn alpha() -> impl Strategy<Value = Option<Alpha>> {
    prop_oneof![
        Just(None),
        Just(Some(0.0)),
        Just(Some(1.0)),
        (0.0..=1.0f64).prop_map(Some),
    ]
    .prop_map(|a| a.map(|a| Alpha::try_new(a).expect("in [0, 1]")))
}

/// From the least to the most samples a job may ask for.
fn samples() -> impl Strategy<Value = usize> {
    prop_oneof![Just(2usize), Just(MAX_SAMPLES), 2usize..=MAX_SAMPLES]
}

/// A valid job whose curve has dimension `D`.
fn job<const D: usize>(model: impl Fn(FuzzyCurve<D>) -> Model) -> impl Strategy<Value = Job> {
    (
        strategies::fuzzy_curve::<D>(),
        alpha(),
        samples(),
        description(),
        proptest::sample::select(TypeReduction::ALL.to_vec()),
    )
        .prop_map(
            move |(c, alpha, samples, description, type_reduction)| Job {
                description,
                alpha,
                type_reduction,
                samples: Samples::Along(samples),
                closed: None,
                units: None,
                model: model(c),
            },
        )
}

fn any_job() -> impl Strategy<Value = Job> {
    prop_oneof![job::<2>(Model::Planar), job::<3>(Model::Spatial)]
}

/// Grids from the least to the most samples a surface job may ask for.
fn grid() -> impl Strategy<Value = [usize; 2]> {
    prop_oneof![
        Just([2usize, 2]),
        Just([2, MAX_SAMPLES / 2]),
        Just([1000, 1000]),
        (2usize..=1000, 2usize..=1000).prop_map(|(u, v)| [u, v]),
    ]
}

/// A valid surface job (docs/method.md §8).
fn surface_job() -> impl Strategy<Value = Job> {
    (
        strategies::fuzzy_surface::<3>(),
        alpha(),
        grid(),
        description(),
        proptest::sample::select(TypeReduction::ALL.to_vec()),
    )
        .prop_map(|(s, alpha, samples, description, type_reduction)| Job {
            description,
            alpha,
            type_reduction,
            samples: Samples::Grid(samples),
            closed: None,
            units: None,
            model: Model::Surface(s),
        })
}

/// The job, written by `job_json` (compact and pretty), reads back equal.
fn round_trips(job: Job) -> Result<(), TestCaseError> {
    let compact = t2spline_io::job_json(&job).to_string();
    let back = t2spline_io::parse_job(&compact, "job.json");
    prop_assert!(
        back.is_ok(),
        "{:?}\n{compact}",
        back.err().map(|e| e.lines())
    );
    prop_assert_eq!(back.unwrap(), job.clone(), "{}", compact);

    let pretty = to_json_pretty(&t2spline_io::job_json(&job));
    let back = t2spline_io::parse_job(&pretty, "job.json");
    prop_assert!(
        back.is_ok(),
        "{:?}\n{pretty}",
        back.err().map(|e| e.lines())
    );
    prop_assert_eq!(back.unwrap(), job, "{}", pretty);
    Ok(())
}

proptest! {
    #![proptest_config(strategies::cases(64, 128))]

    #[test]
    fn job_json_round_trips(job in any_job()) {
        round_trips(job)?;
    }

    #[test]
    fn surface_job_json_round_trips(job in surface_job()) {
        round_trips(job)?;
    }

    #[test]
    fn result_json_round_trips_exactly(
        job in any_job(),
        a in 0.0..=1.0f64,
        samples in 2u64..40,
    ) {
        // The job's own type reduction: `alpha_used` and a null regime too.
        let settings = job
            .settings(&Overrides { alpha: Some(a), samples: Some(vec![samples]), ..Overrides::default() })
            .unwrap();
        let result = job.run(&settings).unwrap();
        let (text, back) = written(&result);
        prop_assert_eq!(back, serde_json::to_value(&result).unwrap(), "{}", text);
    }
}

proptest! {
    // A surface run computes the distance over the whole domain (a scan and
    // a search per span rectangle): fewer cases than for curves.
    #![proptest_config(strategies::cases(8, 16))]

    #[test]
    fn surface_result_json_round_trips_exactly(
        job in surface_job(),
        a in 0.0..=1.0f64,
        su in 2u64..9,
        sv in 2u64..9,
    ) {
        let settings = job
            .settings(&Overrides { alpha: Some(a), samples: Some(vec![su, sv]), ..Overrides::default() })
            .unwrap();
        let result = job.run(&settings).unwrap();
        let (text, back) = written(&result);
        prop_assert_eq!(back, serde_json::to_value(&result).unwrap(), "{}", text);
    }
}

#[test]
fn the_example_job_round_trips_and_its_result_too() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/paper-alg-1-1.json"
    );
    let job = t2spline_io::read_job(std::path::Path::new(path)).unwrap();
    assert_eq!(job.model.dimension(), 2);
    assert_eq!(job.samples, Samples::Along(101));
    assert_eq!(job.alpha.map(Alpha::get), Some(0.8));
    assert_eq!(
        t2spline_io::parse_job(&t2spline_io::job_json(&job).to_string(), "x").unwrap(),
        job
    );

    let settings = job
        .settings(&Overrides {
            type_reduction: Some(t2spline::TypeReduction::Paper),
            ..Overrides::default()
        })
        .unwrap();
    let result = job.run(&settings).unwrap();
    let (_, back) = written(&result);
    assert_eq!(back, serde_json::to_value(&result).unwrap());
    assert_eq!(back["description"].as_str(), job.description.as_deref());
}

/// The result file's text, streamed as `t2spline run` writes it, and the JSON
/// values it reads back to (exactly, as serde_json is built with
/// `float_roundtrip`).
fn written(result: &t2spline::job::RunOutput) -> (String, serde_json::Value) {
    let mut text = Vec::new();
    t2spline_io::write_json_pretty(&mut text, result).unwrap();
    let text = String::from_utf8(text).unwrap();
    let back = serde_json::from_str(&text).unwrap();
    (text, back)
}
