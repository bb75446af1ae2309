//! Hostile input: every kind of problem is reported at its line and
//! column, every limit is enforced before the memory or time it guards is
//! spent, and arbitrary bytes get a result or a clear error (the checks of the
//! job fuzz target, run here by proptest so that CI runs them).

mod oracle;
mod positions;

use positions::at;
use proptest::prelude::*;
use serde_json::{json, Value};
use t2spline_io::job::{
    locate, read_text, read_text_from, MAX_ARRAY, MAX_FILE_BYTES, MAX_KEYS, MAX_NESTING, MAX_ORDER,
    MAX_POINTS, MAX_PROBLEMS,
};
use t2spline_io::{check_finite, render_csv, write_json_pretty, Error};

// ---------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------

/// The lines of the error of an invalid job.
fn lines(text: &str) -> Vec<String> {
    match t2spline_io::parse_job(text, "job.json") {
        Ok(_) => panic!("the job is valid:\n{text}"),
        Err(e) => e.lines(),
    }
}

/// A valid number around `c`.
fn number(c: f64) -> Value {
    json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]})
}

/// A valid job of `n` points, order 2, as a JSON value.
fn job(n: usize) -> Value {
    let points: Vec<Value> = (0..n)
        .map(|i| json!({"x": number(i as f64), "y": number((i * i) as f64)}))
        .collect();
    json!({"order": 2, "alpha": 0.5, "lower_height": 0.5, "samples": 5, "points": points})
}

// ---------------------------------------------------------------------------
// Every kind of problem, at its line and column
// ---------------------------------------------------------------------------

/// One file with a problem of (nearly) every kind; each line of the error
/// names the file, the line and column of the key or element concerned (for a
/// missing key: of the object that lacks it), the place and the rule.
#[test]
fn every_kind_of_problem_names_its_line_and_column() {
    let text = r#"{
  "order": 3,
  "alhpa": 0.5,
  "lower_height": 0.5,
  "samples": 1,
  "weights": [1, 0, 1, 1e200],
  "knots": [0, 0, 0, 0.7, 0.5, 1, 1],
  "points": [
    {"x": {"crisp": 1, "upper": [1e151, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
     "y": {"crisp": 1, "upper": [0, 2], "primary": [0.5], "lower": [0.8, 1.2]}},
    {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2], "lower_height": 2},
     "y": {"crisp": 1, "upper": [0, 2], "primary": [0.5, "1.5"], "lower": [0.8, 1.2]}},
    {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
     "y": {"crisp": 3, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]}},
    {"x": {"upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
     "y": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]}}
  ],
  "samples": 7
}"#;
    let expected = [
        format!(
            "{}: samples: duplicate key (first at line 5, column 3); each key may appear once",
            at(text, "\"samples\"", 1)
        ),
        format!(
            "{}: alhpa: unknown key (did you mean `alpha`?)",
            at(text, "\"alhpa\"", 0)
        ),
        format!(
            "{}: points[0].x: upper.left = 1e151 is outside [-1e150, 1e150]",
            at(text, "1e151", 0)
        ),
        format!(
            "{}: points[0].y.primary: expected [left, right], an array of two numbers, got an array of 1 values",
            at(text, "\"primary\"", 1)
        ),
        format!(
            "{}: points[1].x: lower_height = 2 is outside (0, 1]",
            at(text, "\"lower_height\"", 1)
        ),
        format!(
            "{}: points[1].y.primary[1]: expected a number, got a string",
            at(text, "\"1.5\"", 0)
        ),
        format!(
            "{}: points[2].y: the order crisp <= lower.right is broken: 3 > 1.2",
            at(text, "\"y\"", 2)
        ),
        format!(
            "{}: points[3].x.crisp: missing",
            at(text, "\"x\": {\"upper\"", 0)
        ),
        format!(
            "{}: weights[1] = 0 must be finite and greater than 0",
            at(text, "0, 1, 1e200", 0)
        ),
        format!(
            "{}: weights[3] = 1e200 is outside [1e-150, 1e150]",
            at(text, "1e200", 0)
        ),
        format!(
            "{}: knots[4] = 0.5 is less than knots[3] = 0.7: knots must not decrease",
            at(text, "0.5, 1, 1]", 0)
        ),
    ];
    let got: Vec<String> = lines(text)
        .iter()
        .map(|l| {
            l.strip_prefix("job.json:")
                .expect("names the file")
                .to_owned()
        })
        .collect();
    assert_eq!(got, expected, "\n{}", got.join("\n"));
}

#[test]
fn syntax_nesting_and_number_range_errors_are_placed_by_the_reader() {
    let text = "{\n  \"order\": 3,\n  \"alpha\": 0.5,}\n";
    assert_eq!(
        lines(text),
        ["job.json:3:16: JSON syntax error: trailing comma"]
    );
    // 127 levels are read; the 128th is refused where it opens.
    let deep = format!("{}{}", "[".repeat(MAX_NESTING), "]".repeat(MAX_NESTING));
    let e = lines(&deep);
    assert!(
        e[0].starts_with("job.json:1:1: job: expected the job"),
        "{e:?}"
    );
    let deeper = "[".repeat(100_000);
    assert_eq!(
        lines(&deeper),
        [format!(
            "job.json:1:{}: arrays and objects nest deeper than 127 levels (a job needs 4)",
            MAX_NESTING + 1
        )]
    );
    let e = lines("{\"order\": 2,\n \"alpha\": 1e400}");
    assert_eq!(
        e,
        ["job.json:2:15: number out of range: beyond ±1.8e308, the range of a 64-bit float"]
    );
    // Columns count characters, not bytes.
    let e = lines("{\"description\": \"ünïcödé\", \"x\" 1}");
    assert_eq!(e, ["job.json:1:32: JSON syntax error: expected `:`"]);
}

#[test]
fn a_missing_key_is_placed_at_the_object_that_lacks_it() {
    let text = "\n\n   {\"order\": 2}";
    assert_eq!(
        lines(text),
        ["job.json:3:4: points: missing: a job needs its fuzzy control points"]
    );
    assert_eq!(locate(text, "alpha"), (3, 4));
    assert_eq!(locate(text, "order"), (3, 5));
}

#[test]
fn curve_rules_are_placed_at_their_key() {
    let mut v = job(2);
    v["order"] = json!(3);
    let text = serde_json::to_string_pretty(&v).unwrap();
    assert_eq!(
        lines(&text),
        [format!(
            "job.json:{}: points: a curve of order 3 needs at least 3 control points, got 2",
            at(&text, "\"points\"", 0)
        )]
    );
    let mut v = job(3);
    v["knots"] = json!([0, 0, 1, 1]);
    let text = serde_json::to_string_pretty(&v).unwrap();
    assert_eq!(
        lines(&text),
        [format!(
            "job.json:{}: knots: expected 5 values (control points + order), got 4",
            at(&text, "\"knots\"", 0)
        )]
    );
}

#[test]
fn data_files_for_fit_are_placed_the_same_way() {
    let e = t2spline_io::parse_data("[]", "data.json").unwrap_err();
    assert_eq!(
        e.lines(),
        ["data.json:1:1: data: expected the data file (a JSON object), got an array"]
    );
    let e =
        t2spline_io::parse_data("{\n \"degree\": 40,\n \"points\": []}", "data.json").unwrap_err();
    assert_eq!(
        e.lines()[0],
        "data.json:2:2: degree: degree = 40 is more than the limit 31 (order 32)"
    );
}

#[test]
fn a_byte_order_mark_is_accepted_and_not_counted() {
    let text = format!("\u{feff}{}", job(3));
    assert!(t2spline_io::parse_job(&text, "bom.json").is_ok());
    let e = t2spline_io::parse_job("\u{feff}{\"order\": 2, \"x\": 1}", "bom.json").unwrap_err();
    assert!(
        e.lines()[0].starts_with("bom.json:1:14: x: unknown key"),
        "{e}"
    );
}

// ---------------------------------------------------------------------------
// Hostile keys and numbers in messages
// ---------------------------------------------------------------------------

#[test]
fn hostile_keys_cannot_reach_the_terminal_raw() {
    let long = "k".repeat(1_000_000);
    let text = format!(
        "{{\"order\": 2, \"\\u001b[31mred\\u202e\": 1, \"{long}\": 2, \"y.upper\": 3, \"points\": []}}"
    );
    let e = lines(&text);
    assert_eq!(
        e[0],
        "job.json:1:14: [\"\\u001b[31mred\\u202e\"]: unknown key (known keys: description, order, degree, weights, knots, alpha, type_reduction, lower_height, samples, closed, units, points)"
    );
    let long_at = at(&text, &format!("\"{long}\""), 0);
    assert!(
        e[1].starts_with(&format!(
            "job.json:{long_at}: [\"{}…\"]: unknown key",
            "k".repeat(40)
        )),
        "{}",
        &e[1][..100]
    );
    assert!(e[1].len() < 300, "the long key is cut");
    let dotted_at = at(&text, "\"y.upper\"", 0);
    assert!(
        e[2].starts_with(&format!("job.json:{dotted_at}: [\"y.upper\"]: unknown key")),
        "{}",
        e[2]
    );
    assert!(e.iter().all(|l| !l.chars().any(char::is_control)));
}

#[test]
fn huge_numbers_are_written_in_exponent_form() {
    let mut v = job(2);
    v["samples"] = json!(1e300);
    v["points"][0]["x"]["upper"][0] = json!(-1.5e307);
    let e = lines(&v.to_string());
    assert!(
        e.iter()
            .any(|l| l.ends_with("samples: samples = 1e300 is more than the limit 1000000")),
        "{e:?}"
    );
    assert!(
        e.iter()
            .any(|l| l.ends_with("points[0].x: upper.left = -1.5e307 is outside [-1e150, 1e150]")),
        "{e:?}"
    );
}

// ---------------------------------------------------------------------------
// Limits
// ---------------------------------------------------------------------------

#[test]
fn too_many_points_are_refused_before_they_are_read() {
    // The points need not even be points: the count is checked first.
    let text = format!(
        "{{\"order\": 2, \"points\": [{}0]}}",
        "0,".repeat(MAX_POINTS)
    );
    assert_eq!(
        lines(&text),
        [format!(
            "job.json:1:14: points: {} points is more than the limit {MAX_POINTS}",
            MAX_POINTS + 1
        )]
    );
}

#[test]
fn an_array_longer_than_any_job_needs_is_refused_before_parsing() {
    let text = format!(
        "{{\"order\": 2,\n \"weights\": [{}0], \"points\": []}}",
        "0,".repeat(MAX_ARRAY)
    );
    assert_eq!(
        lines(&text),
        ["job.json:2:13: an array of more than 100032 entries: no job or data file needs more (100000 points, 100032 knots)"]
    );
    // One entry fewer is read (and found wrong for other reasons).
    let text = format!(
        "{{\"order\": 2, \"weights\": [{}0]}}",
        "0,".repeat(MAX_ARRAY - 1)
    );
    assert!(lines(&text)[0].contains("points: missing"));
}

#[test]
fn an_order_beyond_the_limit_is_refused_without_allocating_it() {
    for (key, value, rule) in [
        (
            "order",
            json!(MAX_ORDER + 1),
            "order = 33 is more than the limit 32 (degree 31)",
        ),
        (
            "order",
            json!(1e9),
            "order = 1000000000 is more than the limit 32 (degree 31)",
        ),
        (
            "degree",
            json!(1e30),
            "degree = 1e30 is more than the limit 31 (order 32)",
        ),
        (
            "degree",
            json!(u64::MAX),
            "degree = 18446744073709551615 is more than the limit 31 (order 32)",
        ),
    ] {
        let mut v = job(3);
        v.as_object_mut().unwrap().remove("order");
        v[key] = value;
        let e = lines(&v.to_string());
        assert_eq!(e.len(), 1, "{e:?}");
        assert!(e[0].ends_with(&format!("{key}: {rule}")), "{e:?}");
    }
    // The largest order is accepted.
    let mut v = job(MAX_ORDER);
    v["order"] = json!(MAX_ORDER);
    assert!(t2spline_io::parse_job(&v.to_string(), "j").is_ok());
}

#[test]
fn at_most_twenty_problems_are_listed() {
    // 2000 points that are not objects, and 30 copies of one unknown key.
    let text = format!(
        "{{\"order\": 2, {} \"points\": [{}0]}}",
        "\"a\": 1, ".repeat(30),
        "0, ".repeat(1999)
    );
    let e = lines(&text);
    assert_eq!(e.len(), MAX_PROBLEMS + 1);
    // 29 repeated keys, 1 unknown key (`a` is reported once: serde_json keeps
    // one copy) and 2000 points: 2030 problems, of which 20 are listed.
    assert_eq!(
        e[MAX_PROBLEMS],
        "job.json: … and 2010 more problems (only the first 20 are listed)"
    );
    assert_eq!(
        e[0],
        "job.json:1:22: a: duplicate key (first at line 1, column 14); each key may appear once"
    );
}

#[test]
fn objects_with_too_many_keys_and_files_with_too_many_values_are_refused_before_parsing() {
    let keys: String = (0..=MAX_KEYS).map(|i| format!("\"k{i}\": 0, ")).collect();
    let text = format!("{{\n  \"order\": 2, \"points\": [], \"x\": {{{keys}\"end\": 0}}}}");
    assert_eq!(
        lines(&text),
        ["job.json:2:34: an object of more than 64 keys: no job or data file needs more than 9"]
    );
    // 41 arrays of 100 000 zeros: each array is allowed, the sum is not.
    let chunk = format!("[{}0]", "0,".repeat(99_999));
    let text = format!("{{\"knots\": [{}]}}", vec![chunk; 41].join(","));
    let e = lines(&text);
    assert_eq!(e.len(), 1);
    assert!(
        e[0].ends_with(
            ": more than 4000000 JSON values: a 3-D job of 100000 points needs at most 3.9 million"
        ),
        "{}",
        e[0]
    );
}

#[test]
fn samples_beyond_the_limit_are_refused() {
    let mut v = job(3);
    v["samples"] = json!(1_000_001);
    let e = lines(&v.to_string());
    assert!(
        e[0].ends_with("samples: samples = 1000001 is more than the limit 1000000"),
        "{e:?}"
    );
}

#[test]
fn input_past_the_size_limit_is_refused_unread() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.json");
    std::fs::File::create(&path)
        .unwrap()
        .set_len(MAX_FILE_BYTES + 1)
        .unwrap();
    let e = read_text(&path).unwrap_err();
    assert!(matches!(e, Error::Invalid { .. }), "{e:?}");
    let e = read_text_from(std::io::repeat(b'{'), "<stdin>").unwrap_err();
    assert!(
        e.to_string().contains("larger than the limit of 64 MiB"),
        "{e}"
    );
    // Exactly at the limit is read.
    let text = " ".repeat(usize::try_from(MAX_FILE_BYTES).unwrap());
    assert_eq!(
        read_text_from(text.as_bytes(), "x").unwrap().len(),
        text.len()
    );
}

// ---------------------------------------------------------------------------
// No NaN or infinity in any output
// ---------------------------------------------------------------------------

/// Paths of every `null` in a JSON value.
fn nulls(v: &Value, path: &str, out: &mut Vec<String>) {
    match v {
        Value::Null => out.push(path.to_owned()),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .for_each(|(i, x)| nulls(x, &format!("{path}[{i}]"), out)),
        Value::Object(o) => o
            .iter()
            .for_each(|(k, x)| nulls(x, &format!("{path}.{k}"), out)),
        _ => {}
    }
}

/// Jobs at the limits of every range: the result JSON has `null` only where a
/// lower alpha-cut does not exist, and the CSV files no `NaN` or `inf`.
#[test]
fn extreme_jobs_write_only_finite_numbers() {
    let scales = [1e150 / 13.0, 1e-150, 1e-300, 5e-324];
    for scale in scales {
        for weights in [
            json!([1e-150, 1e150, 1e-150, 1e150]),
            json!([1e-12, 1e12, 1, 1e12]),
        ] {
            let mut v = job(4);
            for p in v["points"].as_array_mut().unwrap() {
                for axis in ["x", "y"] {
                    let n = &mut p[axis];
                    for key in ["crisp", "upper", "primary", "lower"] {
                        n[key] = match &n[key] {
                            Value::Array(a) => json!(a
                                .iter()
                                .map(|x| x.as_f64().unwrap() * scale)
                                .collect::<Vec<_>>()),
                            x => json!(x.as_f64().unwrap() * scale),
                        };
                    }
                }
            }
            v["weights"] = weights.clone();
            v["knots"] = json!([0, 0, 1e-140, 1e-140, 1, 1]);
            for alpha in [0.0, 0.5, 0.7, 1.0] {
                let job = t2spline_io::parse_job(&v.to_string(), "j")
                    .unwrap_or_else(|e| panic!("{e}\n{v}"));
                let r = job
                    .run(
                        &job.settings(&t2spline::job::Overrides {
                            alpha: Some(alpha),
                            type_reduction: Some(t2spline::TypeReduction::Paper),
                            samples: Some(vec![33]),
                            derivatives: None,
                        })
                        .unwrap(),
                    )
                    .unwrap();
                check_finite(&r).unwrap();
                let mut out = Vec::new();
                write_json_pretty(&mut out, &r).unwrap();
                let back: Value = serde_json::from_slice(&out).unwrap();
                let mut found = Vec::new();
                nulls(&back, "", &mut found);
                assert!(
                    found.iter().all(|p| p.contains(".alpha_cut.lower_")),
                    "scale {scale:e}, alpha {alpha}: {found:?}"
                );
                for (name, csv) in render_csv(&r) {
                    assert!(!csv.contains("NaN") && !csv.contains("inf"), "{name}");
                }
            }
        }
    }
}

/// The last check catches a non-finite number wherever it is, by name.
#[test]
fn a_non_finite_result_is_refused_by_name() {
    let job = t2spline_io::parse_job(&job(3).to_string(), "j").unwrap();
    let mut r = job
        .run(
            &job.settings(&t2spline::job::Overrides {
                alpha: Some(0.5),
                type_reduction: Some(t2spline::TypeReduction::Paper),
                samples: Some(vec![5]),
                derivatives: None,
            })
            .unwrap(),
        )
        .unwrap();
    r.samples.type_reduced.right.coord_mut(1)[3] = f64::INFINITY;
    let e = check_finite(&r).unwrap_err();
    assert!(
        e.to_string().starts_with(
            "internal error: curves.type_reduced.right[3][1] = inf is not a finite number"
        ),
        "{e}"
    );
}

// ---------------------------------------------------------------------------
// Arbitrary bytes: the fuzz target's checks under proptest
// ---------------------------------------------------------------------------

/// The job files the mutations start from: curves of 2 and 3 dimensions and
/// surfaces.
fn seeds() -> Vec<String> {
    let example = include_str!("../../../examples/paper-alg-1-1.json").to_owned();
    let mut spatial = job(5);
    for p in spatial["points"].as_array_mut().unwrap() {
        p["z"] = number(1.0);
    }
    spatial["knots"] = json!([0, 0, 0.5, 0.5, 0.75, 1, 1]);
    spatial["weights"] = json!([1e-12, 1, 1e12, 1, 2]);
    let surface = include_str!("../../../fuzz/seeds/job/surface.json").to_owned();
    let extreme_surface = include_str!("../../../fuzz/seeds/job/surface-extreme.json").to_owned();
    vec![
        example,
        job(3).to_string(),
        serde_json::to_string_pretty(&spatial).unwrap(),
        surface,
        extreme_surface,
    ]
}

/// A mutation: overwrite, insert or delete a few bytes, or splice in a JSON
/// token that matters to the validator.
#[derive(Clone, Debug)]
enum Mutation {
    Set(usize, u8),
    Insert(usize, &'static str),
    Delete(usize, usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let token = prop::sample::select(vec![
        "\"order\": 1e30, ",
        "\"alpha\"",
        "null",
        "1e151",
        "-0",
        "[]",
        "{}",
        "\"degree\": 2, ",
        "5e-324",
        "1e400",
        "\"\u{1b}\"",
        "\u{feff}",
        ",",
        "]",
        "}",
        "\"samples\": 0, ",
        "\"z\": ",
        "[2, 2]",
        "[[",
        "\"u\": ",
        "\"v\": [0, 1]",
    ]);
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Set(i, b)),
        (any::<usize>(), token).prop_map(|(i, t)| Mutation::Insert(i, t)),
        (any::<usize>(), 1usize..40).prop_map(|(i, n)| Mutation::Delete(i, n)),
    ]
}

fn apply(text: &str, mutations: &[Mutation]) -> Vec<u8> {
    let mut b = text.as_bytes().to_vec();
    for m in mutations {
        let len = b.len().max(1);
        match *m {
            Mutation::Set(i, x) => {
                if !b.is_empty() {
                    b[i % len] = x;
                }
            }
            Mutation::Insert(i, t) => {
                let at = i % (b.len() + 1);
                b.splice(at..at, t.bytes());
            }
            Mutation::Delete(i, n) => {
                let at = i % len;
                let end = (at + n).min(b.len());
                b.drain(at.min(b.len())..end);
            }
        }
    }
    b
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(1000, 2000))]

    #[test]
    fn arbitrary_bytes_get_a_result_or_a_clear_error(data in proptest::collection::vec(any::<u8>(), 0..400)) {
        oracle::check_job_bytes(&data);
    }

    #[test]
    fn mutated_jobs_get_a_result_or_a_clear_error(
        seed in 0usize..5, mutations in proptest::collection::vec(mutation(), 1..6),
    ) {
        let text = &seeds()[seed];
        oracle::check_job_bytes(&apply(text, &mutations));
    }
}

/// Every input the fuzzer ever failed on (`fuzz/regressions/job/`), and every
/// seed of its corpus (`fuzz/seeds/job/`), passes every check now.
#[test]
fn fuzz_regressions_and_seeds_pass() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let mut count = 0;
    for dir in ["regressions/job", "seeds/job"] {
        for entry in std::fs::read_dir(root.join(dir)).expect("the fuzz folders exist") {
            let data = std::fs::read(entry.unwrap().path()).unwrap();
            oracle::check_job_bytes(&data);
            count += 1;
        }
    }
    assert!(count >= 9, "{count} files");
}

/// The seeds themselves are valid and pass every check.
#[test]
fn the_seeds_pass() {
    for s in seeds() {
        assert!(t2spline_io::parse_job(&s, "seed").is_ok(), "{s}");
        oracle::check_job_bytes(s.as_bytes());
    }
}
