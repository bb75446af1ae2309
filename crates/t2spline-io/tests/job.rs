//! Job files (docs/jobs.md): every rule a file can break is reported as one line
//! naming the file, the place and the rule, and all problems at once.

use serde_json::{json, Value};
use t2spline::job::{Job, Model, Samples, DEFAULT_SAMPLES, MAX_SAMPLES};
use t2spline::{Alpha, TypeReduction};

// ---------------------------------------------------------------------------
// Fixtures
// ---------------------------------------------------------------------------

/// A valid fuzzy number around `c` with no height of its own.
fn number(c: f64) -> Value {
    json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]})
}

/// The number whose order rules the tests break one at a time: crisp 1,
/// upper [0.4, 1.9], primary [0.6, 1.6], lower [0.8, 1.3].
fn sample_number() -> Value {
    json!({"crisp": 1.0, "upper": [0.4, 1.9], "primary": [0.6, 1.6], "lower": [0.8, 1.3]})
}

fn point(x: f64, y: f64) -> Value {
    json!({"x": number(x), "y": number(y)})
}

fn point3(x: f64, y: f64, z: f64) -> Value {
    json!({"x": number(x), "y": number(y), "z": number(z)})
}

/// A valid 2-D job of order 2 with three points.
fn base() -> Value {
    json!({
        "order": 2,
        "alpha": 0.5,
        "lower_height": 0.5,
        "samples": 5,
        "points": [point(0.0, 0.0), point(1.0, 2.0), point(2.0, 1.0)]
    })
}

/// `base()` changed by `f`.
fn with(f: impl FnOnce(&mut serde_json::Map<String, Value>)) -> Value {
    let mut v = base();
    f(v.as_object_mut().expect("base is an object"));
    v
}

/// The value at a JSON pointer inside `v`, for editing; the last key is
/// created in its object if missing.
fn at<'v>(v: &'v mut Value, pointer: &str) -> &'v mut Value {
    let (parent, key) = pointer.rsplit_once('/').expect("a JSON pointer");
    let parent = v
        .pointer_mut(parent)
        .unwrap_or_else(|| panic!("no {parent} in the fixture"));
    match parent {
        Value::Object(o) => o.entry(key).or_insert(Value::Null),
        Value::Array(a) => &mut a[key.parse::<usize>().expect("an index")],
        _ => panic!("{pointer}: the parent is not a container"),
    }
}

fn parse(v: &Value) -> Result<Job, t2spline_io::Error> {
    t2spline_io::parse_job(&v.to_string(), "job.json")
}

/// The error lines of an invalid job given as text, as printed:
/// `job.json:LINE:COLUMN: place: rule`.
fn located_problems(text: &str) -> Vec<String> {
    match t2spline_io::parse_job(text, "job.json") {
        Ok(job) => panic!("expected problems, the job is valid: {job:?}\n{text}"),
        Err(e) => e.lines(),
    }
}

/// The error lines of an invalid job given as text, without the line and
/// column after the file name (`job.json: place: rule`); the positions
/// themselves are tested in `limits.rs`.
fn text_problems(text: &str) -> Vec<String> {
    located_problems(text)
        .into_iter()
        .map(|line| without_position(&line))
        .collect()
}

/// `job.json:12:5: rest` → `job.json: rest`.
fn without_position(line: &str) -> String {
    let number = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    match line.splitn(4, ':').collect::<Vec<_>>()[..] {
        [file, l, c, rest] if number(l) && number(c) => format!("{file}:{rest}"),
        _ => line.to_owned(),
    }
}

/// The error lines of an invalid job.
fn problems(v: &Value) -> Vec<String> {
    text_problems(&v.to_string())
}

/// Asserts that the job has exactly the given problem lines.
#[track_caller]
fn assert_problems(v: &Value, expected: &[&str]) {
    let got = problems(v);
    assert_eq!(got, expected, "job: {v}");
}

/// Asserts that the job has exactly one problem, and returns it.
#[track_caller]
fn one_problem(v: &Value) -> String {
    let got = problems(v);
    assert_eq!(got.len(), 1, "expected one problem, got {got:#?}\njob: {v}");
    got.into_iter().next().unwrap()
}

// ---------------------------------------------------------------------------
// Defaults and overrides (the JSON round trips are in `round_trip.rs`)
// ---------------------------------------------------------------------------

#[test]
fn defaults_apply_and_three_dimensional_points_are_read() {
    let v = json!({
        "degree": 1,
        "lower_height": 1,
        "points": [point3(0.0, 0.0, 0.0), point3(1.0, 1.0, 1.0), point3(2.0, 0.0, 3.0)]
    });
    let job = parse(&v).unwrap();
    assert_eq!(job.samples, Samples::Along(DEFAULT_SAMPLES));
    assert_eq!(job.alpha, None);
    assert_eq!(job.description, None);
    let Model::Spatial(c) = &job.model else {
        panic!("expected 3-D: {job:?}")
    };
    assert_eq!(c.order(), 2);
    assert_eq!(c.weights(), &[1.0, 1.0, 1.0]);
    assert_eq!(c.knots().as_slice(), &[0.0, 0.0, 0.5, 1.0, 1.0]);
}

#[test]
fn a_number_height_overrides_the_top_level_one() {
    let mut v = base();
    *at(&mut v, "/points/1/y/lower_height") = json!(0.25);
    let job = parse(&v).unwrap();
    let Model::Planar(c) = &job.model else {
        panic!("expected 2-D")
    };
    assert_eq!(c.points()[1].coords()[1].height().get(), 0.25);
    assert_eq!(c.points()[1].coords()[0].height().get(), 0.5);
    // Without a top-level default every number needs its own.
    let mut v = base();
    v.as_object_mut().unwrap().remove("lower_height");
    for i in 0..3 {
        for axis in ["x", "y"] {
            *at(&mut v, &format!("/points/{i}/{axis}/lower_height")) = json!(1.0);
        }
    }
    assert!(parse(&v).is_ok());
}

// ---------------------------------------------------------------------------
// JSON syntax and structure
// ---------------------------------------------------------------------------

#[test]
fn syntax_errors_give_line_and_column() {
    // The trailing comma is on line 3, directly before the closing brace.
    let text = "{\n  \"order\": 2,\n  \"alpha\": 0.5,}\n";
    let got = located_problems(text);
    assert_eq!(got.len(), 1, "{got:?}");
    assert!(
        got[0].starts_with("job.json:3:16: JSON syntax error: trailing comma"),
        "{got:?}"
    );
    // serde's own " at line … column …" suffix is not repeated.
    assert!(!got[0].contains("at line"), "{got:?}");

    let got = located_problems("{\"order\": 2,\n\"alpha\": 0.5\n");
    assert_eq!(got.len(), 1, "{got:?}");
    assert!(got[0].starts_with("job.json:3:"), "{got:?}");
    assert!(got[0].contains("JSON syntax error: EOF"), "{got:?}");

    let got = located_problems("");
    assert!(
        got[0].starts_with("job.json:1:1: JSON syntax error"),
        "{got:?}"
    );

    let got = located_problems("{\"order\": 2} trailing");
    assert!(
        got[0].starts_with("job.json:1:14: JSON syntax error: trailing characters"),
        "{got:?}"
    );
}

#[test]
fn the_root_must_be_an_object() {
    for (text, kind) in [
        ("[1, 2]", "an array"),
        ("3", "a number"),
        ("null", "null"),
        ("\"job\"", "a string"),
    ] {
        assert_eq!(
            text_problems(text),
            [format!(
                "job.json: job: expected the job (a JSON object), got {kind}"
            )]
        );
    }
}

#[test]
fn unknown_top_level_keys_are_errors_with_a_suggestion_when_close() {
    let v = with(|o| {
        o.insert("alhpa".into(), json!(0.5));
    });
    assert_problems(
        &v,
        &["job.json: alhpa: unknown key (did you mean `alpha`?)"],
    );
    let v = with(|o| {
        o.insert("sample".into(), json!(3));
    });
    assert_problems(
        &v,
        &["job.json: sample: unknown key (did you mean `samples`?)"],
    );
    let v = with(|o| {
        o.insert("colour".into(), json!("red"));
    });
    assert_problems(
        &v,
        &["job.json: colour: unknown key (known keys: description, order, degree, weights, knots, alpha, type_reduction, lower_height, samples, closed, units, points)"],
    );
}

#[test]
fn unknown_keys_inside_points_and_numbers_name_their_place() {
    let mut v = base();
    *at(&mut v, "/points/2/w") = json!(1);
    *at(&mut v, "/points/1/x/lowr") = json!([0, 1]);
    *at(&mut v, "/points/0/y/weight") = json!(2);
    assert_problems(
        &v,
        &[
            "job.json: points[0].y.weight: unknown key (known keys: crisp, upper, primary, lower, lower_height)",
            "job.json: points[1].x.lowr: unknown key (did you mean `lower`?)",
            "job.json: points[2].w: unknown key (known keys: x, y, z)",
        ],
    );
}

#[test]
fn a_description_must_be_a_string() {
    let v = with(|o| {
        o.insert("description".into(), json!(42));
    });
    assert_problems(
        &v,
        &["job.json: description: expected a string, got a number"],
    );
    let v = with(|o| {
        o.insert("description".into(), json!(["a"]));
    });
    assert_problems(
        &v,
        &["job.json: description: expected a string, got an array"],
    );
    let v = with(|o| {
        o.insert("description".into(), json!("ü \"q\""));
    });
    assert_eq!(parse(&v).unwrap().description.as_deref(), Some("ü \"q\""));
}

// ---------------------------------------------------------------------------
// order / degree
// ---------------------------------------------------------------------------

#[test]
fn order_or_degree_exactly_one() {
    let v = with(|o| {
        o.remove("order");
    });
    assert_problems(
        &v,
        &["job.json: order: missing: give `order` (k) or `degree` (k - 1)"],
    );
    let v = with(|o| {
        o.insert("degree".into(), json!(1));
    });
    assert_problems(
        &v,
        &["job.json: order, degree: give exactly one of them (order = degree + 1)"],
    );
    let v = with(|o| {
        o.remove("order");
        o.insert("degree".into(), json!(1));
    });
    assert_eq!(parse(&v).unwrap(), parse(&base()).unwrap());
}

#[test]
fn order_must_be_a_whole_number_at_least_one() {
    let v = with(|o| {
        o.insert("order".into(), json!(0));
    });
    assert_problems(
        &v,
        &["job.json: order: order = 0: the order must be at least 1"],
    );
    let v = with(|o| {
        o.insert("order".into(), json!(2.5));
    });
    assert_problems(
        &v,
        &["job.json: order: expected a whole number >= 0, got 2.5"],
    );
    let v = with(|o| {
        o.insert("order".into(), json!(-1));
    });
    assert_problems(
        &v,
        &["job.json: order: expected a whole number >= 0, got -1"],
    );
    let v = with(|o| {
        o.insert("order".into(), json!("2"));
    });
    assert_problems(
        &v,
        &["job.json: order: expected a whole number, got a string"],
    );
    let v = with(|o| {
        o.insert("degree".into(), json!(0.5));
        o.remove("order");
    });
    assert_problems(
        &v,
        &["job.json: degree: expected a whole number >= 0, got 0.5"],
    );
}

#[test]
fn a_whole_number_written_with_a_fraction_is_accepted() {
    let v = with(|o| {
        o.insert("order".into(), json!(3.0));
        o.insert("samples".into(), json!(7.0));
    });
    let job = parse(&v).unwrap();
    let Model::Planar(c) = &job.model else {
        panic!("expected 2-D")
    };
    assert_eq!(c.order(), 3);
    assert_eq!(job.samples, Samples::Along(7));
}

#[test]
fn a_huge_degree_is_an_error_not_a_panic() {
    for degree in [json!(u64::MAX), json!(u64::MAX - 1), json!(9.0e15)] {
        let v = with(|o| {
            o.remove("order");
            o.insert("degree".into(), degree.clone());
        });
        let p = one_problem(&v);
        assert!(
            p.starts_with("job.json: points: a curve of order ")
                || p.starts_with("job.json: degree: "),
            "{p}"
        );
    }
    let v = with(|o| {
        o.insert("order".into(), json!(u64::MAX));
    });
    let p = one_problem(&v);
    assert!(
        p.starts_with("job.json: order: order = 18446744073709551615 is more than the limit"),
        "{p}"
    );
}

// ---------------------------------------------------------------------------
// alpha and lower_height
// ---------------------------------------------------------------------------

#[test]
fn alpha_must_be_a_number_in_the_unit_interval() {
    for (a, line) in [
        (json!(1.5), "job.json: alpha = 1.5 is outside [0, 1]"),
        (json!(-0.1), "job.json: alpha = -0.1 is outside [0, 1]"),
        (
            json!("0.5"),
            "job.json: alpha: expected a number, got a string",
        ),
        (json!(null), "job.json: alpha: expected a number, got null"),
    ] {
        let v = with(|o| {
            o.insert("alpha".into(), a.clone());
        });
        assert_problems(&v, &[line]);
    }
    for a in [0.0, 1.0] {
        let v = with(|o| {
            o.insert("alpha".into(), json!(a));
        });
        assert_eq!(parse(&v).unwrap().alpha.map(Alpha::get), Some(a));
    }
}

// ---------------------------------------------------------------------------
// type_reduction (docs/method.md §9)
// ---------------------------------------------------------------------------

#[test]
fn type_reduction_is_one_of_four_names_and_defaults_to_the_paper() {
    assert_eq!(parse(&base()).unwrap().type_reduction, TypeReduction::Paper);
    for method in TypeReduction::ALL {
        let v = with(|o| {
            o.insert("type_reduction".into(), json!(method.name()));
        });
        assert_eq!(parse(&v).unwrap().type_reduction, method);
    }
    // Alpha may be left out of a job whose reduction does not use it: the
    // file is valid either way (the run decides whether alpha is needed).
    let v = with(|o| {
        o.remove("alpha");
        o.insert("type_reduction".into(), json!("centroid"));
    });
    assert_eq!(parse(&v).unwrap().alpha, None);
    for (value, line) in [
        (
            json!("nietan"),
            "job.json: type_reduction: unknown type reduction `nietan` (did you mean `nie-tan`?)",
        ),
        (
            json!("Centroid"),
            "job.json: type_reduction: unknown type reduction `Centroid` (did you mean `centroid`?)",
        ),
        (
            json!("karnik-mendel"),
            "job.json: type_reduction: unknown type reduction `karnik-mendel` (known: paper, centroid, nie-tan, alpha-planes)",
        ),
        (
            json!("x".repeat(100)),
            &format!(
                "job.json: type_reduction: unknown type reduction `{}…` (known: paper, centroid, nie-tan, alpha-planes)",
                "x".repeat(40)
            ),
        ),
        (
            json!(2),
            "job.json: type_reduction: expected a string, got a number",
        ),
        (
            json!(null),
            "job.json: type_reduction: expected a string, got null",
        ),
    ] {
        let v = with(|o| {
            o.insert("type_reduction".into(), value.clone());
        });
        assert_problems(&v, &[line]);
    }
    // A misspelt key is an unknown key with a suggestion, like any other.
    let v = with(|o| {
        o.insert("type_reducton".into(), json!("centroid"));
    });
    assert_problems(
        &v,
        &["job.json: type_reducton: unknown key (did you mean `type_reduction`?)"],
    );
}

#[test]
fn an_unknown_type_reduction_names_its_line_and_column() {
    let text = "{\n  \"order\": 2,\n  \"type_reduction\": \"centriod\",\n  \"points\": []\n}";
    let lines = located_problems(text);
    assert_eq!(
        lines[0],
        "job.json:3:3: type_reduction: unknown type reduction `centriod` (did you mean `centroid`?)"
    );
}

#[test]
fn the_top_level_height_must_lie_in_zero_one_and_is_reported_once() {
    for (h, line) in [
        (json!(0), "job.json: lower_height = 0 is outside (0, 1]"),
        (json!(1.5), "job.json: lower_height = 1.5 is outside (0, 1]"),
        (json!(-1), "job.json: lower_height = -1 is outside (0, 1]"),
        (
            json!(true),
            "job.json: lower_height: expected a number, got a boolean",
        ),
    ] {
        let v = with(|o| {
            o.insert("lower_height".into(), h.clone());
        });
        assert_problems(&v, &[line]);
    }
}

#[test]
fn a_number_height_must_lie_in_zero_one() {
    let mut v = base();
    *at(&mut v, "/points/2/x/lower_height") = json!(1.25);
    *at(&mut v, "/points/0/y/lower_height") = json!(0);
    *at(&mut v, "/points/1/y/lower_height") = json!("high");
    assert_problems(
        &v,
        &[
            "job.json: points[0].y: lower_height = 0 is outside (0, 1]",
            "job.json: points[1].y.lower_height: expected a number, got a string",
            "job.json: points[2].x: lower_height = 1.25 is outside (0, 1]",
        ],
    );
}

#[test]
fn a_number_without_any_height_is_an_error() {
    let mut v = with(|o| {
        o.remove("lower_height");
    });
    for i in 0..3 {
        *at(&mut v, &format!("/points/{i}/x/lower_height")) = json!(0.5);
    }
    *at(&mut v, "/points/0/y/lower_height") = json!(0.5);
    *at(&mut v, "/points/2/y/lower_height") = json!(0.5);
    assert_problems(
        &v,
        &["job.json: points[1].y: no lower_height: give it in the number or at the top level of the job"],
    );
}

// ---------------------------------------------------------------------------
// Numbers and points
// ---------------------------------------------------------------------------

#[test]
fn each_of_the_six_order_rules_names_point_coordinate_and_rule() {
    let cases = [
        (
            "/upper",
            json!([0.7, 1.9]),
            "upper.left <= primary.left",
            "0.7 > 0.6",
        ),
        (
            "/primary",
            json!([0.9, 1.6]),
            "primary.left <= lower.left",
            "0.9 > 0.8",
        ),
        (
            "/lower",
            json!([1.1, 1.3]),
            "lower.left <= crisp",
            "1.1 > 1",
        ),
        (
            "/lower",
            json!([0.8, 0.9]),
            "crisp <= lower.right",
            "1 > 0.9",
        ),
        (
            "/primary",
            json!([0.6, 1.2]),
            "lower.right <= primary.right",
            "1.3 > 1.2",
        ),
        (
            "/upper",
            json!([0.4, 1.5]),
            "primary.right <= upper.right",
            "1.6 > 1.5",
        ),
    ];
    for (key, value, rule, values) in cases {
        let mut v = base();
        *at(&mut v, "/points/1/y") = sample_number();
        assert!(parse(&v).is_ok(), "the sample number is valid");
        *at(&mut v, &format!("/points/1/y{key}")) = value;
        assert_problems(
            &v,
            &[&format!(
                "job.json: points[1].y: the order {rule} is broken: {values}"
            )],
        );
    }
}

#[test]
fn equal_neighbours_and_crisp_numbers_are_valid() {
    let mut v = base();
    *at(&mut v, "/points/0/x") =
        json!({"crisp": 2, "upper": [2, 2], "primary": [2, 2], "lower": [2, 2]});
    *at(&mut v, "/points/1/y") =
        json!({"crisp": 1, "upper": [1, 3], "primary": [1, 3], "lower": [1, 1]});
    assert!(parse(&v).is_ok());
}

#[test]
fn coordinate_values_must_be_numbers() {
    let mut v = base();
    *at(&mut v, "/points/0/x/crisp") = json!("1");
    *at(&mut v, "/points/1/y/upper/0") = json!(null);
    *at(&mut v, "/points/2/x/primary") = json!({"left": 0});
    *at(&mut v, "/points/2/y/lower/1") = json!([1]);
    assert_problems(
        &v,
        &[
            "job.json: points[0].x.crisp: expected a number, got a string",
            "job.json: points[1].y.upper[0]: expected a number, got null",
            "job.json: points[2].x.primary: expected [left, right], an array of two numbers, got an object",
            "job.json: points[2].y.lower[1]: expected a number, got an array",
        ],
    );
}

#[test]
fn pairs_need_exactly_two_entries() {
    let mut v = base();
    *at(&mut v, "/points/0/x/upper") = json!([0.4]);
    *at(&mut v, "/points/1/y/upper") = json!([0.4, 1.0, 1.9]);
    *at(&mut v, "/points/2/y/lower") = json!([]);
    assert_problems(
        &v,
        &[
            "job.json: points[0].x.upper: expected [left, right], an array of two numbers, got an array of 1 values",
            "job.json: points[1].y.upper: expected [left, right], an array of two numbers, got an array of 3 values",
            "job.json: points[2].y.lower: expected [left, right], an array of two numbers, got an array of 0 values",
        ],
    );
}

#[test]
fn missing_parts_of_a_number_are_named() {
    let mut v = base();
    at(&mut v, "/points/1/x")
        .as_object_mut()
        .unwrap()
        .remove("crisp");
    at(&mut v, "/points/2/y")
        .as_object_mut()
        .unwrap()
        .remove("lower");
    assert_problems(
        &v,
        &[
            "job.json: points[1].x.crisp: missing",
            "job.json: points[2].y.lower: missing",
        ],
    );
}

#[test]
fn points_must_all_have_the_same_coordinates() {
    let mut v = base();
    *at(&mut v, "/points/2") = point3(2.0, 1.0, 0.0);
    assert_problems(
        &v,
        &["job.json: points[2]: has coordinates [x, y, z] but points[0] has [x, y]: every point needs the same coordinates"],
    );
}

#[test]
fn a_point_needs_x_and_y() {
    let mut v = base();
    at(&mut v, "/points/1").as_object_mut().unwrap().remove("y");
    let mut z_only = json!({"z": number(1.0)});
    std::mem::swap(at(&mut v, "/points/2"), &mut z_only);
    assert_problems(
        &v,
        &[
            "job.json: points[1]: has coordinates [x]; a point needs x and y, and optionally z",
            "job.json: points[2]: has coordinates [z]; a point needs x and y, and optionally z",
        ],
    );
}

#[test]
fn points_and_numbers_must_be_objects() {
    let mut v = base();
    *at(&mut v, "/points/0") = json!([1, 2]);
    *at(&mut v, "/points/1/y") = json!("2.0");
    assert_problems(
        &v,
        &[
            "job.json: points[0]: expected a point (a JSON object), got an array",
            "job.json: points[1].y: expected a fuzzy number (a JSON object, or a number for a crisp one), got a string",
        ],
    );
    let v = with(|o| {
        o.insert("points".into(), json!({"0": point(0.0, 0.0)}));
    });
    assert_problems(
        &v,
        &["job.json: points: expected an array of points, got an object"],
    );
    let v = with(|o| {
        o.remove("points");
    });
    assert_problems(
        &v,
        &["job.json: points: missing: a job needs its fuzzy control points"],
    );
}

#[test]
fn too_few_points_for_the_order() {
    let v = with(|o| {
        o.insert("order".into(), json!(4));
    });
    assert_problems(
        &v,
        &["job.json: points: a curve of order 4 needs at least 4 control points, got 3"],
    );
    let v = with(|o| {
        o.insert("points".into(), json!([]));
    });
    assert_problems(
        &v,
        &["job.json: points: a curve of order 2 needs at least 2 control points, got 0"],
    );
}

// ---------------------------------------------------------------------------
// weights and knots
// ---------------------------------------------------------------------------

#[test]
fn weights_need_one_positive_number_per_point() {
    let v = with(|o| {
        o.insert("weights".into(), json!([1, 2]));
    });
    assert_problems(
        &v,
        &["job.json: weights: expected 3 (one per control point), got 2"],
    );
    let v = with(|o| {
        o.insert("weights".into(), json!([1, 0, -2.5]));
    });
    assert_problems(
        &v,
        &[
            "job.json: weights[1] = 0 must be finite and greater than 0",
            "job.json: weights[2] = -2.5 must be finite and greater than 0",
        ],
    );
    let v = with(|o| {
        o.insert("weights".into(), json!([1, "2", 3]));
    });
    assert_problems(
        &v,
        &["job.json: weights[1]: expected a number, got a string"],
    );
    let v = with(|o| {
        o.insert("weights".into(), json!(1));
    });
    assert_problems(
        &v,
        &["job.json: weights: expected an array of numbers, got a number"],
    );
    let v = with(|o| {
        o.insert("weights".into(), json!([1, 3, 0.5]));
    });
    let Model::Planar(c) = parse(&v).unwrap().model else {
        panic!("2-D")
    };
    assert_eq!(c.weights(), &[1.0, 3.0, 0.5]);
}

#[test]
fn knots_follow_the_rules_of_spec_6() {
    // Three points of order 2: five knots.
    let cases = [
        (
            json!([0, 0, 1, 1]),
            "job.json: knots: expected 5 values (control points + order), got 4",
        ),
        (
            json!([0, 0, 0.7, 0.5, 1]),
            "job.json: knots[3] = 0.5 is less than knots[2] = 0.7: knots must not decrease",
        ),
        (
            json!([0, 0, 0, 1, 1]),
            "job.json: knots[0..3]: the value 0 repeats 3 times, more than the order 2",
        ),
        (
            json!([0, 1, 1, 1, 2]),
            "job.json: knots[1..4]: the value 1 repeats 3 times, more than the order 2",
        ),
        (
            json!([0, 0, 1, "x", 1]),
            "job.json: knots[3]: expected a number, got a string",
        ),
        (
            json!("clamped"),
            "job.json: knots: expected an array of numbers, got a string",
        ),
    ];
    for (knots, line) in cases {
        let v = with(|o| {
            o.insert("knots".into(), knots.clone());
        });
        assert_problems(&v, &[line]);
    }
    // An empty domain: order 3 and three points, U[2] = U[3].
    let v = with(|o| {
        o.insert("order".into(), json!(3));
        o.insert("knots".into(), json!([0, 0, 1, 1, 1, 2]));
    });
    assert_problems(
        &v,
        &["job.json: knots: the domain [knots[2], knots[3]] = [1, 1] is empty; it needs knots[2] < knots[3]"],
    );
    // Full multiplicity inside is allowed, and a vector that is not clamped too.
    for knots in [[0.0, 0.0, 0.5, 1.0, 1.0], [-1.0, 0.0, 0.5, 1.0, 3.0]] {
        let v = with(|o| {
            o.insert("knots".into(), json!(knots));
        });
        let Model::Planar(c) = parse(&v).unwrap().model else {
            panic!("2-D")
        };
        assert_eq!(c.knots().as_slice(), &knots);
    }
}

// ---------------------------------------------------------------------------
// samples
// ---------------------------------------------------------------------------

#[test]
fn samples_are_a_whole_number_from_two_to_the_limit() {
    let cases = [
        (
            json!(1),
            "job.json: samples: samples = 1: at least 2 are needed (both ends of the domain)"
                .to_owned(),
        ),
        (
            json!(0),
            "job.json: samples: samples = 0: at least 2 are needed (both ends of the domain)"
                .to_owned(),
        ),
        (
            json!(2.5),
            "job.json: samples: expected a whole number >= 0, got 2.5".to_owned(),
        ),
        (
            json!(-3),
            "job.json: samples: expected a whole number >= 0, got -3".to_owned(),
        ),
        (
            json!("101"),
            "job.json: samples: expected a whole number, got a string".to_owned(),
        ),
        (
            json!(MAX_SAMPLES + 1),
            format!(
                "job.json: samples: samples = {} is more than the limit {MAX_SAMPLES}",
                MAX_SAMPLES + 1
            ),
        ),
    ];
    for (n, line) in cases {
        let v = with(|o| {
            o.insert("samples".into(), n.clone());
        });
        assert_problems(&v, &[line.as_str()]);
    }
    for n in [2, MAX_SAMPLES] {
        let v = with(|o| {
            o.insert("samples".into(), json!(n));
        });
        assert_eq!(parse(&v).unwrap().samples, Samples::Along(n));
    }
}

// ---------------------------------------------------------------------------
// Everything at once
// ---------------------------------------------------------------------------

#[test]
fn every_problem_of_a_file_is_listed() {
    let text = r#"{
  "description": 7,
  "order": 2.5,
  "alhpa": 0.5,
  "alpha": 2,
  "samples": 1,
  "weights": [1, 0, 1, 1],
  "lower_height": 0.5,
  "points": [
    {"x": {"crisp": 1, "upper": [0.7, 1.9], "primary": [0.6, 1.6], "lower": [0.8, 1.3]},
     "y": {"crisp": 1, "upper": [0.4], "primary": [0.6, 1.6], "lower": [0.8, 1.3], "lower_height": 2}},
    {"x": {"crisp": 1, "upper": [0.4, 1.9], "primary": [0.6, 1.6], "lower": [0.8, 1.3]}},
    {"x": {"crisp": 1, "upper": [0.4, 1.9], "primary": [0.6, 1.6], "lower": [0.8, 1.3]},
     "y": {"crisp": 1, "upper": [0.4, 1.9], "primary": [0.6, 1.6], "lower": [0.8, 1.3]},
     "z": {"crisp": 1, "upper": [0.4, 1.9], "primary": [0.6, 1.6], "lower": [0.8, 1.3]}}
  ]
}"#;
    let got = text_problems(text);
    let expected = [
        "job.json: alhpa: unknown key (did you mean `alpha`?)",
        "job.json: description: expected a string, got a number",
        "job.json: order: expected a whole number >= 0, got 2.5",
        "job.json: alpha = 2 is outside [0, 1]",
        "job.json: samples: samples = 1: at least 2 are needed (both ends of the domain)",
        "job.json: points[0].x: the order upper.left <= primary.left is broken: 0.7 > 0.6",
        "job.json: points[0].y.upper: expected [left, right], an array of two numbers, got an array of 1 values",
        "job.json: points[1]: has coordinates [x]; a point needs x and y, and optionally z",
        "job.json: points[2]: has coordinates [x, y, z] but points[0] has [x, y]: every point needs the same coordinates",
    ];
    assert_eq!(got, expected, "{got:#?}");
    assert_eq!(got.len(), 9);
}

#[test]
fn curve_rules_are_checked_even_when_other_parts_are_broken() {
    // A bad sample count, a bad top-level height and a broken point do not
    // hide the zero weight and the decreasing knots.
    let mut v = with(|o| {
        o.insert("samples".into(), json!(1));
        o.insert("lower_height".into(), json!(2));
        o.insert("weights".into(), json!([1, 0, 1]));
        o.insert("knots".into(), json!([0, 0, 0.7, 0.5, 1]));
    });
    *at(&mut v, "/points/0/x/crisp") = json!(null);
    let got = problems(&v);
    assert_eq!(
        got,
        [
            "job.json: lower_height = 2 is outside (0, 1]",
            "job.json: samples: samples = 1: at least 2 are needed (both ends of the domain)",
            "job.json: points[0].x.crisp: expected a number, got null",
            "job.json: weights[1] = 0 must be finite and greater than 0",
            "job.json: knots[3] = 0.5 is less than knots[2] = 0.7: knots must not decrease",
        ],
        "{got:#?}"
    );
}

#[test]
fn every_line_names_the_file() {
    let e = t2spline_io::parse_job("{\"order\": 0, \"x\": 1}", "dir/my job.json").unwrap_err();
    let lines = e.lines();
    assert_eq!(lines.len(), 3, "{lines:?}");
    assert!(
        lines.iter().all(|l| l.starts_with("dir/my job.json:")
            && without_position(l).starts_with("dir/my job.json: ")),
        "{lines:?}"
    );
    assert_eq!(e.to_string(), lines.join("\n"));
}

#[test]
fn reading_a_missing_file_names_it_and_the_reason_once() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("absent.json");
    let e = t2spline_io::read_job(&path).unwrap_err();
    assert!(matches!(e, t2spline_io::Error::Read { .. }), "{e:?}");
    let lines = e.lines();
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(&format!("{}: cannot read: ", path.display())),
        "{lines:?}"
    );
    // The reason (the io::Error) appears once: as the source, and in lines().
    let reason = std::error::Error::source(&e)
        .expect("the io error")
        .to_string();
    assert_eq!(lines[0].matches(&reason).count(), 1, "{lines:?}");
}

// ---------------------------------------------------------------------------
// Bare numbers
// ---------------------------------------------------------------------------

/// The crisp number `x` written out in full, with height `h`.
fn crisp_object(x: f64, h: f64) -> Value {
    json!({"crisp": x, "upper": [x, x], "primary": [x, x], "lower": [x, x], "lower_height": h})
}

#[test]
fn a_bare_number_is_a_crisp_number_with_the_jobs_height_else_1() {
    for (height, h) in [(Some(0.5), 0.5), (None, 1.0)] {
        let job = |bare: bool| {
            let c = |x: f64| if bare { json!(x) } else { crisp_object(x, h) };
            let mut v = json!({
                "order": 2,
                "points": [
                    {"x": c(0.0), "y": c(-1.0)},
                    {"x": number(1.0), "y": c(2.0)},
                    {"x": c(2.0), "y": c(1.0)}
                ]
            });
            // A number without a height takes the job's; one is given.
            *at(&mut v, "/points/1/x") = crisp_object(1.0, 0.5);
            if let Some(h) = height {
                *at(&mut v, "/lower_height") = json!(h);
            }
            v
        };
        let (bare, full) = (parse(&job(true)), parse(&job(false)));
        assert_eq!(bare.expect("bare numbers are crisp"), full.expect("valid"));
    }
    // In a surface's net and in a data file too; integers as well.
    let surface = json!({
        "order": [2, 2],
        "points": [
            [{"x": 0, "y": 0, "z": 1}, {"x": 0, "y": 1, "z": number(2.0)}],
            [{"x": 1, "y": 0, "z": -3}, {"x": 1, "y": 1, "z": 4.5}]
        ],
        "lower_height": 0.5
    });
    let Model::Surface(s) = parse(&surface).expect("a surface").model else {
        panic!("a surface job")
    };
    assert_eq!(s.points()[2].coords()[2].upper().left(), -3.0);
    let data = json!({"degree": 1, "points": [{"x": 0, "y": 0}, {"x": 1, "y": number(1.0)}], "lower_height": 1});
    t2spline_io::parse_data(&data.to_string(), "data.json").expect("bare numbers in data");
}

#[test]
fn a_bare_number_breaks_rules_at_its_place() {
    let mut v = base();
    *at(&mut v, "/points/1/y") = json!(1e200);
    *at(&mut v, "/points/2/x") = json!(true);
    let got = problems(&v);
    assert_eq!(got.len(), 2, "{got:#?}");
    assert!(got[0].starts_with("job.json: points[1].y"), "{got:#?}");
    assert_eq!(
        got[0],
        "job.json: points[1].y: crisp = 1e200 is outside [-1e150, 1e150]"
    );
    assert_eq!(
        got[1],
        "job.json: points[2].x: expected a fuzzy number (a JSON object, or a number for a crisp one), got a boolean"
    );
}

// ---------------------------------------------------------------------------
// Closed curves
// ---------------------------------------------------------------------------

#[test]
fn closed_is_a_boolean_that_the_curve_must_keep() {
    let v = with(|o| {
        o.insert("closed".into(), json!(true));
    });
    let e = one_problem(&v);
    assert!(
        e.starts_with("job.json: closed: the curve does not close: it starts at (0, 0) and ends at (2, 1): a closed curve with clamped knots repeats its first control point as its last"),
        "{e}"
    );
    let v = with(|o| {
        o.insert("closed".into(), json!("yes"));
    });
    assert_problems(
        &v,
        &["job.json: closed: expected true or false, got a string"],
    );
    // The last point repeats the first: closed, and written back.
    let v = with(|o| {
        o.insert("closed".into(), json!(true));
        o.insert(
            "points".into(),
            json!([
                point(0.0, 0.0),
                point(1.0, 2.0),
                point(2.0, 1.0),
                point(0.0, 0.0)
            ]),
        );
    });
    let job = parse(&v).expect("closes");
    assert_eq!(job.closed, Some(true));
    let again = t2spline_io::job_json(&job);
    assert_eq!(again["closed"], json!(true));
    assert_eq!(parse(&again).expect("again"), job);
    let v = with(|o| {
        o.insert("closed".into(), json!(false));
    });
    assert_eq!(parse(&v).expect("open").closed, Some(false));
}

#[test]
fn a_surface_has_no_closed() {
    let v = json!({
        "order": [2, 2],
        "closed": true,
        "points": [[point3(0.0, 0.0, 0.0), point3(0.0, 1.0, 0.0)], [point3(1.0, 0.0, 0.0), point3(1.0, 1.0, 1.0)]],
        "lower_height": 0.5
    });
    assert_problems(
        &v,
        &["job.json: closed: a surface job has no `closed`: it is for curves (docs/method.md §11)"],
    );
}

#[test]
fn units_name_a_unit_of_length() {
    let v = with(|o| {
        o.insert("units".into(), json!("ft"));
    });
    let job = parse(&v).expect("valid");
    assert_eq!(job.units, Some(t2spline::job::LengthUnit::Foot));
    assert_eq!(t2spline_io::job_json(&job)["units"], json!("ft"));
    let v = with(|o| {
        o.insert("units".into(), json!("feet"));
    });
    assert_problems(
        &v,
        &["job.json: units: expected one of mm, cm, m, in, ft (the unit of the coordinates, for CAD files), got \"feet\""],
    );
}
