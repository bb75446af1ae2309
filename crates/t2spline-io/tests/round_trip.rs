//! JSON round trips: a job through `Job::to_json` (compact and pretty) and back
//! through the validator, and a result through serde; every f64 exactly.

use proptest::prelude::*;
use t2spline::{strategies, Alpha, FuzzyCurve};
use t2spline_io::{to_json_pretty, Job, JobCurve, RunResult, MAX_SAMPLES};

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
fn job<const D: usize>(curve: impl Fn(FuzzyCurve<D>) -> JobCurve) -> impl Strategy<Value = Job> {
    (
        strategies::fuzzy_curve::<D>(),
        alpha(),
        samples(),
        description(),
    )
        .prop_map(move |(c, alpha, samples, description)| Job {
            description,
            alpha,
            samples,
            curve: curve(c),
        })
}

fn any_job() -> impl Strategy<Value = Job> {
    prop_oneof![job::<2>(JobCurve::Planar), job::<3>(JobCurve::Spatial)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn job_json_round_trips(job in any_job()) {
        let compact = job.to_json().to_string();
        let back = Job::parse(&compact, "job.json");
        prop_assert!(back.is_ok(), "{:?}\n{compact}", back.err().map(|e| e.lines()));
        prop_assert_eq!(back.unwrap(), job.clone(), "{}", compact);

        let pretty = to_json_pretty(&job.to_json());
        let back = Job::parse(&pretty, "job.json");
        prop_assert!(back.is_ok(), "{:?}\n{pretty}", back.err().map(|e| e.lines()));
        prop_assert_eq!(back.unwrap(), job, "{}", pretty);
    }

    #[test]
    fn result_json_round_trips_exactly(
        job in any_job(),
        a in 0.0..=1.0f64,
        samples in 2usize..40,
    ) {
        let result = RunResult::compute(&job, Alpha::try_new(a).unwrap(), samples);
        let text = to_json_pretty(&serde_json::to_value(&result).unwrap());
        let back: RunResult = serde_json::from_str(&text).unwrap();
        prop_assert_eq!(back, result, "{}", text);
    }
}

#[test]
fn the_example_job_round_trips_and_its_result_too() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/paper-alg-1-1.json"
    );
    let job = Job::read(std::path::Path::new(path)).unwrap();
    assert_eq!(job.curve.dimension(), 2);
    assert_eq!(job.samples, 101);
    assert_eq!(job.alpha.map(Alpha::get), Some(0.8));
    assert_eq!(Job::parse(&job.to_json().to_string(), "x").unwrap(), job);

    let result = RunResult::compute(&job, job.alpha.unwrap(), job.samples);
    let text = to_json_pretty(&serde_json::to_value(&result).unwrap());
    let back: RunResult = serde_json::from_str(&text).unwrap();
    assert_eq!(back, result);
    assert_eq!(back.description, job.description);
}
