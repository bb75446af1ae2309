//! The one-pass reading against the validator alone: on the shipped jobs,
//! the fuzz seeds and random edits of them, reading a job must give what the
//! validator gives, the same job or the same problems.

use proptest::prelude::*;
use serde_json::{json, Value};

use super::super::parse::{parse, parse_walking};
use super::super::position::{oversized, Oversized};
use super::super::schema::TOP_KEYS;
use super::raw;
use crate::limits::{MAX_ARRAY, MAX_VALUES};

/// Jobs of the repository: the examples, the fixtures (the bad jobs too)
/// and the fuzz seeds.
pub(super) fn corpus() -> Vec<(String, String)> {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let mut files = Vec::new();
    for dir in [
        "examples",
        "fixtures",
        "fixtures/bad-jobs",
        "fuzz/seeds/job",
    ] {
        for entry in std::fs::read_dir(format!("{root}/{dir}")).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "json") {
                let text = std::fs::read_to_string(&path).unwrap();
                files.push((path.display().to_string(), text));
            }
        }
    }
    assert!(files.len() >= 15, "{} files", files.len());
    files
}

/// The shipped jobs that are valid (not the data file of `fit`).
const VALID: [&str; 4] = [
    "examples/paper-alg-1-1.json",
    "examples/fuzzy-terrain.json",
    "examples/fuzzy-cylinder.json",
    "fixtures/spiral-3d.json",
];

/// Whether reading `text` gives what the validator gives, and, when the
/// one pass takes the text, counts its values as the validator's limits do.
fn same(text: &str) -> Result<(), String> {
    let (fast, walked) = (parse(text), parse_walking(text));
    if fast != walked {
        return Err(format!("read: {fast:?}\nvalidator: {walked:?}\n{text}"));
    }
    counted(text)
}

/// Whether, when the one pass reads `text`, it counts its values as the
/// validator's limits do.
pub(super) fn counted(text: &str) -> Result<(), String> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if let Some(job) = raw::read(text) {
        let counted = |limit| oversized(text, usize::MAX, usize::MAX, limit);
        if counted(job.values).is_some()
            || !matches!(counted(job.values - 1), Some(Oversized::Values(_)))
        {
            return Err(format!("{} values counted in\n{text}", job.values));
        }
    }
    Ok(())
}

#[test]
fn valid_jobs_are_read_in_one_pass_and_built_as_the_validator_builds_them() {
    let corpus = corpus();
    for name in VALID {
        let (_, text) = corpus.iter().find(|(p, _)| p.ends_with(name)).unwrap();
        let walked = parse_walking(text).unwrap();
        assert_eq!(super::job(text), Some(walked), "{name}");
    }
}

#[test]
fn the_corpus_gives_what_the_validator_gives() {
    for (name, text) in corpus() {
        same(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let bom = format!("\u{feff}{text}");
        same(&bom).unwrap_or_else(|e| panic!("{name} with a BOM: {e}"));
    }
}

/// Text a tree cannot hold, and values the one pass refuses though the
/// validator accepts them.
#[test]
fn edits_of_the_text_give_what_the_validator_gives() {
    let point = r#"{"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.25, 0.25]}, "y": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.75, 1.25]}}"#;
    let job =
        |head: &str| format!(r#"{{{head} "lower_height": 0.5, "points": [{point}, {point}]}}"#);
    let valid = job(r#""order": 2,"#);
    assert!(super::job(&valid).is_some());
    let cases = [
        job(r#""order": 2, "order": 2,"#),
        job(r#""order": 2, "\u0061lpha": 0.5, "alpha": 0.5,"#),
        job(r#""\u006frder": 2,"#),
        job(r#""order": 2.0,"#),
        job(r#""degree": 1.0,"#),
        job(r#""order": 1e30,"#),
        job(r#""order": 2, "samples": 5.0,"#),
        job(r#""order": 2, "description": null,"#),
        job(r#""order": 2, "weights": [1, 1.0e0],"#),
        job(r#""order": 2, "weights": [[1, 1]],"#),
        job(r#""order": 2, "knots": {"u": [0, 0, 1, 1]},"#),
        job(r#""order": [2, 2],"#),
        job(r#""order": 2, "samples": [5, 5],"#),
        valid.replace(r#""crisp": 0,"#, r#""crisp": 0, "crisp": 0,"#),
        valid.replace(
            r#""x": {"crisp": 0"#,
            r#""x": {"crisp": 0, "lower_height": 2"#,
        ),
        valid.replace(r#""y": {"crisp": 1"#, r#""z": {}, "y": {"crisp": 1"#),
        // Every number with a height of its own, the top level's still read.
        valid
            .replace(r#""lower_height": 0.5"#, r#""lower_height": 2"#)
            .replace(r#""crisp": "#, r#""lower_height": 0.5, "crisp": "#),
        // Bare numbers: crisp, with the job's height; out of range.
        valid.replace(
            r#"{"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.25, 0.25]}"#,
            "-0",
        ),
        valid.replace(
            r#"{"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.25, 0.25]}"#,
            "1e300",
        ),
        valid.replace(r#""lower_height": 0.5, "#, "").replace(
            r#"{"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.25, 0.25]}"#,
            "18446744073709551615",
        ),
        // Closure: asked of an open curve, declined, not a boolean.
        job(r#""order": 2, "closed": true,"#),
        job(r#""order": 2, "closed": false,"#),
        job(r#""order": 2, "closed": 1,"#),
        job(r#""order": 2, "closed": null,"#),
        job(r#""order": 2, "units": "in","#),
        job(r#""order": 2, "units": "inch","#),
        job(r#""order": 2, "units": 1,"#),
        format!("{valid} x"),
        format!("{valid},"),
        format!("\n\t {valid}\r\n"),
        format!("[{valid}]"),
        "{}".to_owned(),
        "[]".to_owned(),
        "null".to_owned(),
        String::new(),
        format!("{}{}", "[".repeat(200), "]".repeat(200)),
    ];
    for text in cases {
        same(&text).unwrap();
    }
}

#[test]
fn the_one_pass_keeps_the_limits_of_arrays_and_values() {
    let list = |n: usize| format!("[{}1]", "1, ".repeat(n - 1));
    let weights = |w: String| format!(r#"{{"weights": {w}}}"#);
    // The root, the object, the array and a separator before each but the first.
    assert_eq!(
        raw::read(&weights(list(MAX_ARRAY))).unwrap().values,
        MAX_ARRAY + 2
    );
    assert!(raw::read(&weights(list(MAX_ARRAY + 1))).is_none());
    // Rows of 100 000 weights, each allowed: 2 values, then 100 001 a row.
    let rows = |n: usize| weights(format!("[{}]", vec![list(100_000); n].join(", ")));
    let most = (MAX_VALUES - 2) / 100_001;
    assert_eq!(raw::read(&rows(most)).unwrap().values, 2 + most * 100_001);
    assert!(raw::read(&rows(most + 1)).is_none());
}

/// A net of `n × n` crisp points at 0 of `orders`, without a height.
fn net(n: usize, orders: usize) -> String {
    let number = r#"{"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}"#;
    let point = format!(r#"{{"x": {number}, "y": {number}, "z": {number}}}"#);
    let row = format!("[{}]", vec![point; n].join(", "));
    let rows = vec![row; n].join(",\n");
    format!(r#"{{"order": [{orders}, {orders}], "points": [{rows}]}}"#)
}

#[test]
fn the_limits_of_a_net_are_kept() {
    let lower_height = |t: String| t.replacen('{', r#"{"lower_height": 1, "#, 1);
    let within = lower_height(net(56, 32));
    assert!(super::job(&within).is_some());
    // 57 × 57 of orders 32 × 32: beyond the work of a surface.
    same(&lower_height(net(57, 32))).unwrap();
    assert!(super::job(&lower_height(net(57, 32))).is_none());
}

#[test]
fn a_curve_of_more_points_than_the_limit_is_refused() {
    use super::raw::{Points, RawNumber};
    use crate::limits::MAX_POINTS;
    let zero = RawNumber {
        crisp: 0.0,
        upper: [0.0; 2],
        primary: [0.0; 2],
        lower: [0.0; 2],
        height: None,
        bare: false,
    };
    let points = |n| Points {
        numbers: vec![zero; 2 * n],
        dimension: 2,
        net: None,
    };
    let curve = |n| super::curve(0, &points(n), Some(1.0), None, None);
    assert!(curve(MAX_POINTS).is_some());
    assert!(curve(MAX_POINTS + 1).is_none());
}

/// The values an edit puts in: of every type, at and beyond the rules'
/// bounds, and parts of jobs.
fn palette() -> Vec<Value> {
    vec![
        json!(0),
        json!(1),
        json!(2),
        json!(3),
        json!(-1),
        json!(0.5),
        json!(3.0),
        json!(1e30),
        json!(1e300),
        json!(-1e300),
        json!(33),
        json!(2_000_000),
        json!("paper"),
        json!("nie-tan"),
        json!("x"),
        json!(null),
        json!(true),
        json!([]),
        json!([1]),
        json!([1, 2]),
        json!([2, 1]),
        json!([3, 3]),
        json!([[1, 1], [1, 1]]),
        json!({}),
        json!({"u": [0, 0, 0, 1, 1, 1]}),
        json!({"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.75, 1.25]}),
        json!({"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.75, 1.25], "lower_height": 0.4}),
    ]
}

/// The keys an edit adds: the top level's, and those of points, numbers
/// and knots, and one that no object knows.
fn keys() -> Vec<&'static str> {
    let inner = [
        "x", "y", "z", "crisp", "upper", "primary", "lower", "u", "v", "colour",
    ];
    TOP_KEYS.iter().copied().chain(inner).collect()
}

/// Every place in `v`, as JSON pointers.
pub(super) fn places(v: &Value, at: String, out: &mut Vec<String>) {
    match v {
        Value::Object(o) => {
            for (k, x) in o {
                places(x, format!("{at}/{k}"), out);
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                places(x, format!("{at}/{i}"), out);
            }
        }
        _ => {}
    }
    out.push(at);
}

/// Edits the value at `place`: replaces it, removes a member or an element,
/// adds a member, repeats an element, or reverses an array (`how` picks,
/// `pick` chooses the value, key or entry).
pub(super) fn edit(v: &mut Value, place: &str, how: usize, pick: usize) {
    let palette = palette();
    let value = palette[pick % palette.len()].clone();
    let Some(target) = v.pointer_mut(place) else {
        return;
    };
    match (how % 5, target) {
        (1, Value::Object(o)) if !o.is_empty() => {
            let key = o.keys().nth(pick % o.len()).unwrap().clone();
            o.shift_remove(&key);
        }
        (2, Value::Object(o)) => {
            let keys = keys();
            o.insert(keys[pick % keys.len()].to_owned(), value);
        }
        (1, Value::Array(a)) if !a.is_empty() => {
            a.remove(pick % a.len());
        }
        (2, Value::Array(a)) if !a.is_empty() => {
            let copy = a[pick % a.len()].clone();
            a.push(copy);
        }
        (3, Value::Array(a)) => a.reverse(),
        (_, target) => *target = value,
    }
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(750, 1500))]

    #[test]
    fn edited_jobs_give_what_the_validator_gives(
        base in 0..VALID.len(),
        edits in proptest::collection::vec((any::<usize>(), any::<usize>(), any::<usize>()), 1..4),
    ) {
        let corpus = corpus();
        let (_, text) = corpus.iter().find(|(p, _)| p.ends_with(VALID[base])).unwrap();
        let mut v: Value = serde_json::from_str(text).unwrap();
        for (place, how, pick) in edits {
            let mut all = Vec::new();
            places(&v, String::new(), &mut all);
            let place = all[place % all.len()].clone();
            edit(&mut v, &place, how, pick);
        }
        let text = serde_json::to_string_pretty(&v).unwrap();
        prop_assert!(same(&text).is_ok(), "{}", same(&text).unwrap_err());
    }
}
