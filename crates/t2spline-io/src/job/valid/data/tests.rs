//! The one-pass reading of data files against the validator alone: on the
//! shipped data file, data files made of the shipped curve jobs, the jobs
//! themselves, edits by hand and random edits, reading a data file must give
//! what the validator gives, the same [`FitData`] or the same problems.

use proptest::prelude::*;
use serde_json::Value;

use super::super::super::parse::{parse_data, parse_data_walking};
use super::super::tests::{corpus, counted, edit, places};
use crate::fit_data::FitData;
use crate::limits::{MAX_ORDER, MAX_POINTS};

/// Whether reading `text` as a data file gives what the validator gives,
/// and, when the one pass takes it, counts its values as the validator's
/// limits do.
fn same(text: &str) -> Result<(), String> {
    let (fast, walked) = (parse_data(text), parse_data_walking(text));
    if fast != walked {
        return Err(format!("read: {fast:?}\nvalidator: {walked:?}\n{text}"));
    }
    counted(text)
}

/// Data files of the repository: the shipped one, and the curve jobs of
/// the corpus without the keys a data file must not give (their
/// `type_reduction` kept).
fn valid() -> Vec<(String, String)> {
    let mut files = Vec::new();
    for (name, text) in corpus() {
        if name.ends_with("fit-measurements.json") {
            files.push((name, text));
            continue;
        }
        let Ok(Value::Object(mut job)) = serde_json::from_str::<Value>(&text) else {
            continue;
        };
        for key in ["weights", "knots"] {
            job.shift_remove(key);
        }
        let text = serde_json::to_string_pretty(&job).unwrap();
        if parse_data_walking(&text).is_ok() {
            files.push((format!("{name} as data"), text));
        }
    }
    assert!(files.len() >= 3, "{} data files", files.len());
    files
}

#[test]
fn valid_data_files_are_read_in_one_pass_and_built_as_the_validator_builds_them() {
    for (name, text) in valid() {
        let walked: FitData = parse_data_walking(&text).unwrap();
        assert_eq!(super::data(&text), Some(walked), "{name}");
        same(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}

#[test]
fn the_jobs_of_the_corpus_read_as_data_give_what_the_validator_gives() {
    for (name, text) in corpus() {
        same(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let bom = format!("\u{feff}{text}");
        same(&bom).unwrap_or_else(|e| panic!("{name} with a BOM: {e}"));
    }
}

/// A planar data point around `i`, of a height of its own when `own`.
fn point(i: usize, own: bool) -> String {
    let h = if own { r#", "lower_height": 0.25"# } else { "" };
    format!(
        r#"{{"x": {{"crisp": {i}, "upper": [-1, {i}.5], "primary": [-0.5, {i}.25], "lower": [-0.25, {i}.125]{h}}}, "y": {{"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.75, 1.25]}}}}"#
    )
}

/// A data file of `head` (keys and values, each followed by a comma) and
/// `n` planar points.
fn data(head: &str, n: usize) -> String {
    let points: Vec<String> = (0..n).map(|i| point(i, i == 1)).collect();
    format!(
        r#"{{{head} "lower_height": 0.5, "points": [{}]}}"#,
        points.join(", ")
    )
}

/// A net of one row of two spatial points, as a surface job gives them.
fn net() -> String {
    let zero = r#"{"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}"#;
    let spatial = |i| point(i, false).replacen(r#""y": "#, &format!(r#""z": {zero}, "y": "#), 1);
    format!(
        r#"{{"degree": 1, "lower_height": 0.5, "points": [[{}, {}]]}}"#,
        spatial(0),
        spatial(1)
    )
}

#[test]
fn edits_of_a_data_file_give_what_the_validator_gives() {
    let valid = data(r#""degree": 2,"#, 3);
    let most = MAX_ORDER - 1;
    // Valid, at the edges of the rules: each read in one pass.
    let edges = [
        valid.clone(),
        data(r#""order": 2,"#, 2),
        data(r#""degree": 1,"#, 2),
        data(&format!(r#""degree": {most},"#), MAX_ORDER),
        data(&format!(r#""order": {MAX_ORDER},"#), MAX_ORDER),
        data(r#""degree": 2, "description": "beach","#, 3),
        data(r#""degree": 2, "alpha": 0,"#, 3),
        data(r#""degree": 2, "alpha": 1,"#, 3),
        data(r#""degree": 2, "samples": 2,"#, 3),
        data(r#""degree": 2, "samples": 1000000,"#, 3),
        data(r#""degree": 2, "type_reduction": "paper","#, 3),
        data(r#""degree": 2, "type_reduction": "nie-tan","#, 3),
        valid.replace(r#""lower_height": 0.5"#, r#""lower_height": 1"#),
    ];
    for text in &edges {
        assert!(super::data(text).is_some(), "{text}");
        same(text).unwrap();
    }
    let cases = [
        // Keys a data file must not give, and one nobody knows.
        data(r#""degree": 2, "weights": [1, 1, 1],"#, 3),
        data(r#""degree": 2, "knots": [0, 0, 0, 1, 1, 1],"#, 3),
        data(r#""degree": 2, "type_reduction": "pape","#, 3),
        data(r#""degree": 2, "type_reduction": 1,"#, 3),
        data(r#""degree": 2, "colour": "red","#, 3),
        // Repeated keys, plainly and escaped.
        data(r#""degree": 2, "degree": 2,"#, 3),
        data(r#""degree": 2, "\u0061lpha": 0.5, "alpha": 0.5,"#, 3),
        valid.replace(r#""crisp": 1,"#, r#""crisp": 1, "crisp": 1,"#),
        // Order and degree: both, neither, of other types, at their limits.
        data(r#""degree": 2, "order": 3,"#, 3),
        data("", 3),
        data(r#""order": 3,"#, 3),
        data(r#""order": 3.0,"#, 3),
        data(r#""degree": "2","#, 3),
        data(r#""degree": [2, 2],"#, 3),
        data(r#""degree": -1,"#, 3),
        data(r#""degree": 0,"#, 3),
        data(r#""order": 0,"#, 3),
        data(r#""order": 1,"#, 3),
        data(r#""degree": 1,"#, 1),
        data(r#""degree": 3,"#, 3),
        data(&format!(r#""degree": {MAX_ORDER},"#), MAX_ORDER + 1),
        data(&format!(r#""order": {},"#, MAX_ORDER + 1), MAX_ORDER + 1),
        data(r#""degree": 1e30,"#, 3),
        // The other keys: of other types, at their limits.
        data(r#""degree": 2, "description": null,"#, 3),
        data(r#""degree": 2, "alpha": "0.5","#, 3),
        data(r#""degree": 2, "alpha": 1.5,"#, 3),
        data(r#""degree": 2, "samples": 1,"#, 3),
        data(r#""degree": 2, "samples": 5.0,"#, 3),
        data(r#""degree": 2, "samples": [5, 5],"#, 3),
        data(r#""degree": 2, "samples": 1000001,"#, 3),
        valid.replace(r#""lower_height": 0.5"#, r#""lower_height": 0"#),
        valid.replace(r#""lower_height": 0.5"#, r#""lower_height": 1.5"#),
        valid.replace(r#""lower_height": 0.5,"#, ""),
        // Points: none, of other shapes, of mixed coordinates, a surface's net.
        data(r#""degree": 2,"#, 0),
        r#"{"degree": 2, "lower_height": 0.5, "points": {}}"#.to_owned(),
        net(),
        valid.replacen(r#""y": {"crisp": 1"#, r#""z": {"crisp": 1"#, 1),
        valid.replacen(
            r#""y": {"crisp": 1"#,
            r#""z": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}, "y": {"crisp": 1"#,
            1,
        ),
        valid.replacen(r#""upper": [-1, 0.5]"#, r#""upper": [1, 0.5]"#, 1),
        valid.replacen(r#""upper": [-1, 0.5]"#, r#""upper": [-1, 0.5, 1]"#, 1),
        valid.replacen(r#""crisp": 0,"#, "", 1),
        format!("{valid} x"),
        format!("[{valid}]"),
        "{}".to_owned(),
        "null".to_owned(),
        String::new(),
    ];
    for text in cases {
        same(&text).unwrap();
    }
}

#[test]
fn the_limit_of_points_is_kept() {
    for n in [MAX_POINTS, MAX_POINTS + 1] {
        let text = data(r#""degree": 3,"#, n);
        same(&text).unwrap();
        assert_eq!(super::data(&text).is_some(), n == MAX_POINTS, "{n} points");
    }
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(250, 750))]

    #[test]
    fn edited_data_files_give_what_the_validator_gives(
        base in any::<usize>(),
        edits in proptest::collection::vec(
            (any::<usize>(), any::<usize>(), any::<usize>(), any::<bool>()),
            1..4,
        ),
    ) {
        let valid = valid();
        let (_, text) = &valid[base % valid.len()];
        let mut v: Value = serde_json::from_str(text).unwrap();
        for (place, how, pick, top) in edits {
            let mut all = Vec::new();
            places(&v, String::new(), &mut all);
            // Half the edits at the top level, whose keys are few among
            // the places of the points.
            if top {
                all.retain(|p| p.matches('/').count() <= 1);
            }
            let place = all[place % all.len()].clone();
            edit(&mut v, &place, how, pick);
        }
        let text = serde_json::to_string_pretty(&v).unwrap();
        prop_assert!(same(&text).is_ok(), "{}", same(&text).unwrap_err());
    }
}

#[test]
fn the_data_file_of_a_net_is_read_in_one_pass() {
    let n = |c: f64| serde_json::json!({"crisp": c, "upper": [c - 1.0, c + 1.0], "primary": [c - 0.5, c + 0.5], "lower": [c, c]});
    let point = |i: usize, j: usize| serde_json::json!({"x": n(j as f64), "y": n(i as f64), "z": n((i * j) as f64)});
    let rows: Vec<Value> = (0..3)
        .map(|i| Value::Array((0..4).map(|j| point(i, j)).collect()))
        .collect();
    for degree in [
        serde_json::json!({"order": [2, 3]}),
        serde_json::json!({"degree": [2, 1], "samples": 9}),
    ] {
        let mut file = degree.clone();
        file["lower_height"] = serde_json::json!(0.5);
        file["points"] = Value::Array(rows.clone());
        let text = serde_json::to_string_pretty(&file).unwrap();
        let walked = parse_data_walking(&text).unwrap();
        assert_eq!(super::data(&text), Some(walked), "{text}");
        same(&text).unwrap();
    }
    // Too few rows for the degree: the validator's message.
    let text =
        serde_json::json!({"degree": [3, 1], "lower_height": 0.5, "points": rows}).to_string();
    assert_eq!(super::data(&text), None);
    same(&text).unwrap();
}
