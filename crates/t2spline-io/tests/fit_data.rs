//! Data files for `t2spline fit`: validation messages, and the job file a fit
//! writes (it must parse back with `parse_job`, carry the data file's keys,
//! and hold exactly the fitted numbers).

use proptest::prelude::*;
use serde_json::{json, Value};
use t2spline::fit::{
    fit_fuzzy, FitOptions, FitSummary, FuzzyData, FuzzyFitMode, OrderViolation, Parametrization,
};
use t2spline::job::Model;
use t2spline::{strategies, Layer, Nt2Point};
use t2spline_io::{to_json_pretty, FitData};

/// What `t2spline fit` makes of a data file: the core's fit at the file's
/// degree, and the job file written back (or the broken inequalities).
#[derive(Debug)]
struct Fitted {
    summary: FitSummary,
    job: Result<Value, Vec<OrderViolation>>,
}

fn fit(
    data: &FitData,
    options: &FitOptions,
    mode: FuzzyFitMode,
) -> Result<Fitted, t2spline_io::Error> {
    let given = *options;
    let options = FitOptions::new(data.degree, given.control_points())
        .map_err(|e| data.fit_error(&e))?
        .with_parametrization(given.parametrization());
    let options = if given.is_closed() {
        options.closed()
    } else {
        options
    };
    let outcome = data
        .points
        .fit(&options, mode)
        .map_err(|e| data.fit_error(&e))?;
    Ok(Fitted {
        summary: outcome.summary,
        job: outcome
            .model
            .map(|m| data.job_json(&m, options.is_closed())),
    })
}

/// A fuzzy number with spreads `s`, `2s`, `3s` on the left and `r`, `2r`, `3r`
/// on the right.
fn number(c: f64, s: f64, r: f64) -> Value {
    json!({"crisp": c, "upper": [c - 3.0 * s, c + 3.0 * r], "primary": [c - 2.0 * s, c + 2.0 * r],
           "lower": [c - s, c + r]})
}

fn profile() -> Value {
    let points: Vec<Value> = [
        (0.0, 1.0),
        (1.0, 2.5),
        (2.5, 3.0),
        (4.0, 2.0),
        (5.0, 2.2),
        (7.0, 0.5),
    ]
    .iter()
    .enumerate()
    .map(|(k, &(x, y))| {
        let k = k as f64;
        json!({"x": number(x, 0.05, 0.05), "y": number(y, 0.1 + 0.2 * (k % 2.0), 0.05 + 0.01 * k)})
    })
    .collect();
    json!({
        "description": "a profile",
        "order": 4,
        "alpha": 0.7,
        "lower_height": 0.6,
        "samples": 51,
        "points": points,
    })
}

fn parse(v: &Value) -> Result<FitData, t2spline_io::Error> {
    t2spline_io::parse_data(&v.to_string(), "data.json")
}

/// The error lines, without the line and column after the file name (the
/// positions are tested in `limits.rs`).
fn lines(v: &Value) -> Vec<String> {
    let number = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    parse(v)
        .unwrap_err()
        .lines()
        .into_iter()
        .map(|line| match line.splitn(4, ':').collect::<Vec<_>>()[..] {
            [file, l, c, rest] if number(l) && number(c) => format!("{file}:{rest}"),
            _ => line,
        })
        .collect()
}

#[test]
fn fitted_job_parses_back_and_carries_the_data_keys() {
    let data = parse(&profile()).unwrap();
    assert_eq!((data.degree, data.degree_key), (3, "order"));
    for mode in [FuzzyFitMode::Valid, FuzzyFitMode::Independent] {
        let outcome = fit(&data, &FitOptions::interpolation(99).unwrap(), mode).unwrap();
        let Ok(job_json) = outcome.job else {
            assert_eq!(mode, FuzzyFitMode::Independent);
            continue;
        };
        let keys: Vec<&str> = job_json
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        assert_eq!(
            keys,
            [
                "description",
                "order",
                "weights",
                "knots",
                "alpha",
                "lower_height",
                "samples",
                "points"
            ]
        );
        assert_eq!(job_json["order"], json!(4));
        assert_eq!(job_json["weights"], json!(vec![1.0; 6]));
        assert_eq!(job_json["description"], json!("a profile"));
        assert_eq!(job_json["samples"], json!(51));
        // Every number inherits the top-level height: none repeats it.
        assert!(job_json["points"][0]["x"].get("lower_height").is_none());
        let text = to_json_pretty(&job_json);
        let job = t2spline_io::parse_job(&text, "job.json").unwrap();
        assert_eq!(job.samples, t2spline::job::Samples::Along(51));
        assert_eq!(job.alpha.map(|a| a.get()), Some(0.7));
        // The numbers read back are exactly the fitted ones.
        let FuzzyData::Planar(points) = &data.points else {
            panic!("2-D data")
        };
        let fit = fit_fuzzy(points, &FitOptions::interpolation(3).unwrap(), mode).unwrap();
        let Model::Planar(curve) = &job.model else {
            panic!("2-D job")
        };
        assert_eq!(curve.knots(), fit.knots());
        for layer in Layer::ALL {
            let got: Vec<[f64; 2]> = curve.points().iter().map(|p| p.layer(layer)).collect();
            assert_eq!(got, fit.layer_control_points(layer), "{layer}");
        }
    }
}

#[test]
fn degree_key_samples_and_alpha_are_carried_only_when_given() {
    let mut v = profile();
    let o = v.as_object_mut().unwrap();
    o.remove("order");
    o.remove("samples");
    o.remove("alpha");
    o.remove("description");
    o.insert("degree".into(), json!(2));
    let data = parse(&v).unwrap();
    let job = fit(
        &data,
        &FitOptions::interpolation(2).unwrap(),
        FuzzyFitMode::Valid,
    )
    .unwrap()
    .job
    .unwrap();
    let keys: Vec<&str> = job
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(
        keys,
        ["degree", "weights", "knots", "lower_height", "points"]
    );
    assert_eq!(job["degree"], json!(2));
}

#[test]
fn a_type_reduction_is_read_and_carried_to_the_job() {
    let mut v = profile();
    v["type_reduction"] = json!("nie-tan");
    let data = parse(&v).unwrap();
    assert_eq!(data.type_reduction, Some(t2spline::TypeReduction::NieTan));
    let job = fit(
        &data,
        &FitOptions::interpolation(3).unwrap(),
        FuzzyFitMode::Valid,
    )
    .unwrap()
    .job
    .unwrap();
    let keys: Vec<&str> = job
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(
        keys,
        [
            "description",
            "order",
            "weights",
            "knots",
            "alpha",
            "type_reduction",
            "lower_height",
            "samples",
            "points"
        ]
    );
    assert_eq!(job["type_reduction"], json!("nie-tan"));
    let parsed = t2spline_io::parse_job(&job.to_string(), "job.json").unwrap();
    assert_eq!(parsed.type_reduction, t2spline::TypeReduction::NieTan);
    // Refused as a job's would be.
    v["type_reduction"] = json!("nie_tan");
    assert_eq!(
        lines(&v),
        ["data.json: type_reduction: unknown type reduction `nie_tan` (did you mean `nie-tan`?)"]
    );
}

#[test]
fn an_unknown_key_is_offered_only_the_keys_a_data_file_accepts() {
    let mut v = profile();
    v["colour"] = json!("red");
    v["knots"] = json!([0, 1]);
    assert_eq!(
        lines(&v),
        [
            "data.json: knots: not allowed in a data file: the fit makes the weights (all 1) and the knots",
            "data.json: colour: unknown key (known keys: description, order, degree, alpha, type_reduction, lower_height, samples, points)",
        ]
    );
}

#[test]
fn mixed_heights_give_per_number_heights() {
    let mut v = profile();
    v["points"][2]["x"]["lower_height"] = json!(0.3);
    let data = parse(&v).unwrap();
    let outcome = fit(
        &data,
        &FitOptions::interpolation(3).unwrap(),
        FuzzyFitMode::Valid,
    )
    .unwrap();
    assert_eq!(outcome.summary.mixed_heights.len(), 1);
    assert_eq!(outcome.summary.mixed_heights[0].1.get(), 0.3);
    let job = outcome.job.unwrap();
    for p in job["points"].as_array().unwrap() {
        assert_eq!(p["x"]["lower_height"], json!(0.3));
        assert!(p["y"].get("lower_height").is_none());
    }
    assert!(t2spline_io::parse_job(&job.to_string(), "job.json").is_ok());
}

#[test]
fn spatial_data_and_least_squares() {
    let points: Vec<Value> = (0..12)
        .map(|k| {
            let t = f64::from(k) / 11.0;
            json!({"x": number(t.cos(), 0.01, 0.02), "y": number(t.sin(), 0.02, 0.01),
                   "z": number(t, 0.01 * f64::from(k % 3), 0.01)})
        })
        .collect();
    let v = json!({"degree": 3, "lower_height": 1.0, "points": points});
    let data = parse(&v).unwrap();
    let options = FitOptions::approximation(3, 6)
        .unwrap()
        .with_parametrization(Parametrization::Centripetal);
    let outcome = fit(&data, &options, FuzzyFitMode::Valid).unwrap();
    assert_eq!(outcome.summary.control_points, 6);
    let job = t2spline_io::parse_job(&outcome.job.unwrap().to_string(), "job.json").unwrap();
    assert_eq!(job.model.dimension(), 3);
}

#[test]
fn data_file_problems_name_their_place() {
    let mut v = profile();
    v["weights"] = json!([1, 1]);
    v["lower_hieght"] = json!(0.5);
    v["points"][3]["y"]["lower"] = json!([2.1, 1.9]);
    assert_eq!(
        lines(&v),
        [
            "data.json: weights: not allowed in a data file: the fit makes the weights (all 1) and the knots",
            "data.json: lower_hieght: unknown key (did you mean `lower_height`?)",
            "data.json: points[3].y: the order lower.left <= crisp is broken: 2.1 > 2",
            "data.json: points[3].y: the order crisp <= lower.right is broken: 2 > 1.9",
        ]
    );
    let v = json!({"order": 1, "points": [{"x": number(0.0, 0.1, 0.1), "y": number(0.0, 0.1, 0.1)}], "lower_height": 1});
    assert_eq!(
        lines(&v),
        ["data.json: order: degree 0 cannot be fitted: a piecewise-constant curve does not pass through its data; give degree 1 or more"]
    );
    let v = json!({"degree": 3, "lower_height": 1, "points": [{"x": number(0.0, 0.1, 0.1), "y": number(0.0, 0.1, 0.1)}]});
    assert_eq!(
        lines(&v),
        ["data.json: points: a curve of degree 3 needs at least 4 data points, got 1"]
    );
    assert_eq!(
        lines(&json!({"degree": 3})),
        ["data.json: points: missing: a data file needs its fuzzy data points"]
    );
}

#[test]
fn repeated_data_points_are_refused_with_their_names() {
    let mut v = profile();
    v["points"][3] = v["points"][2].clone();
    let data = parse(&v).unwrap();
    let e = fit(
        &data,
        &FitOptions::interpolation(3).unwrap(),
        FuzzyFitMode::Valid,
    )
    .unwrap_err();
    assert_eq!(
        e.lines(),
        ["data.json: points[2] and points[3]: consecutive data points at the same crisp position get the same parameter; remove or merge the repeat, or use uniform parameters"]
    );
}

/// A data file holding `points`.
fn data_json<const D: usize>(points: &[Nt2Point<D>], degree: usize) -> Value {
    let points: Vec<Value> = points
        .iter()
        .map(|p| {
            let mut o = serde_json::Map::new();
            for (axis, x) in t2spline::Axis::first::<D>().unwrap().iter().zip(p.coords()) {
                o.insert(
                    axis.name().into(),
                    json!({"crisp": x.crisp(), "upper": [x.upper().left(), x.upper().right()],
                           "primary": [x.primary().left(), x.primary().right()],
                           "lower": [x.lower().left(), x.lower().right()],
                           "lower_height": x.height().get()}),
                );
            }
            Value::Object(o)
        })
        .collect();
    json!({"degree": degree, "points": points})
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn valid_fits_always_write_jobs_that_parse(
        points in strategies::fuzzy_data::<2>(2..=20),
        degree in 1usize..=5,
        parametrization in prop::sample::select(Parametrization::ALL.to_vec()),
    ) {
        let degree = degree.min(points.len() - 1);
        let data = t2spline_io::parse_data(&data_json(&points, degree).to_string(), "data.json").unwrap();
        let options = FitOptions::interpolation(degree).unwrap().with_parametrization(parametrization);
        let outcome = fit(&data, &options, FuzzyFitMode::Valid).unwrap();
        let text = to_json_pretty(&outcome.job.unwrap());
        let job = t2spline_io::parse_job(&text, "job.json");
        prop_assert!(job.is_ok(), "{:?}", job.err().map(|e| e.lines()));
    }
}

#[test]
fn order_errors_list_at_most_the_problem_limit() {
    let data = parse(&profile()).unwrap();
    let violations: Vec<OrderViolation> = (0..1500)
        .map(|k| OrderViolation {
            control_point: k,
            axis: t2spline::Axis::X,
            rule: "primary.left <= lower.left",
            left: 1.0,
            right: 0.5,
        })
        .collect();
    let lines = data.order_error(&violations, "advice").lines();
    let limit = t2spline_io::job::MAX_PROBLEMS;
    // The count, `limit` violations, the rest counted, the advice.
    assert_eq!(lines.len(), limit + 3, "{:?}", &lines[..3]);
    assert!(lines[0].contains("at 1500 place(s)"), "{}", lines[0]);
    assert_eq!(
        lines[limit + 1],
        format!("data.json: … and {} more place(s)", 1500 - limit)
    );
    assert_eq!(lines[limit + 2], "data.json: advice");
}
