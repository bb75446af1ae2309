//! The promises of reading and running a job, as one function of arbitrary
//! bytes: used by the libFuzzer target `fuzz/fuzz_targets/job.rs` (which
//! includes this file) and by the proptest run over arbitrary and mutated bytes
//! in `tests/limits.rs` (which runs in CI).
//!
//! Every input gets a correct result or a clear error:
//!
//! - no panic, anywhere;
//! - an error is [`Error::Invalid`] with at least one problem; every line
//!   starts with the file name; a line and column, when given, lie inside the
//!   text; no message carries a control character (a hostile key cannot write
//!   escape sequences to a terminal) or a 300-digit number;
//! - the same holds for the text read as a data file of `t2spline fit`;
//! - a valid job, of a curve or of a surface, writes back to canonical JSON
//!   that parses to the same job;
//! - its result has only finite numbers, parameters from the start to exactly
//!   the end of the domain (in u and in v for a surface), every sampled curve
//!   or surface with one point per parameter (a grid `su × sv` for a surface)
//!   and control points in the shape of the model (the net's for a surface),
//!   seven ordered layers at every sample, `rms ≤ max` with the maximum
//!   reached inside the domain; its JSON reads back, and its CSV files have
//!   one row per sample (per grid point) and no `NaN` or `inf`.

#![allow(dead_code)]

use t2spline::job::{Job, Model, Parameter, Parameters, Samples, Spline};
use t2spline::{Alpha, Layer};
use t2spline_io::job::read_text_from;
use t2spline_io::{check_finite, render_csv, write_json_pretty, Error};

/// The most samples a checked run computes (the job's own count can be up to
/// a million; the checks do not need that many).
const SAMPLES: usize = 17;

/// Checks every promise for `data` as the content of a job file.
pub fn check_job_bytes(data: &[u8]) {
    let text = match read_text_from(data, "fuzz.json") {
        Ok(text) => text,
        Err(e) => return check_error(&e, None),
    };
    match t2spline_io::parse_job(&text, "fuzz.json") {
        Err(e) => check_error(&e, Some(&text)),
        Ok(job) => check_job(&job),
    }
    // The same text as a data file for `t2spline fit` (the same validator).
    if let Err(e) = t2spline_io::parse_data(&text, "fuzz.json") {
        check_error(&e, Some(&text));
    }
}

/// Checks the error of an invalid input.
pub fn check_error(e: &Error, text: Option<&str>) {
    let Error::Invalid { file, problems } = e else {
        panic!("reading bytes can only find them invalid: {e:?}");
    };
    assert_eq!(file, "fuzz.json");
    assert!(!problems.is_empty(), "an error without a problem");
    let text = text.map(|t| t.strip_prefix('\u{feff}').unwrap_or(t));
    for p in problems {
        assert!(
            !p.message.chars().any(char::is_control),
            "control character in {:?}",
            p.message
        );
        assert!(
            !without_quoted_keys(&p.message).contains(&"0".repeat(40)),
            "a number written out in full: {}",
            p.message
        );
        if let (Some((line, column)), Some(text)) = (p.line_column, text) {
            assert!(line >= 1 && column >= 1, "{p:?}");
            let lines: Vec<&str> = text.split('\n').collect();
            let Some(l) = lines.get(line - 1) else {
                panic!("line {line} of {}: {p:?}", lines.len());
            };
            assert!(
                column <= l.chars().count() + 1,
                "column {column} of {}: {p:?}",
                l.chars().count()
            );
        }
    }
    for line in e.lines() {
        assert!(line.starts_with("fuzz.json"), "{line}");
    }
}

/// The message without its quoted keys (`["…"]`), which show what the file
/// wrote, digits and all.
fn without_quoted_keys(message: &str) -> String {
    let mut out = String::new();
    let mut rest = message;
    while let Some(start) = rest.find("[\"") {
        out.push_str(&rest[..start]);
        rest = match rest[start..].find("\"]") {
            Some(end) => &rest[start + end + 2..],
            None => "",
        };
    }
    out.push_str(rest);
    out
}

/// Checks a valid job: canonical round trip, and a run.
pub fn check_job(job: &Job) {
    let canonical = t2spline_io::job_json(job).to_string();
    match t2spline_io::parse_job(&canonical, "canonical.json") {
        Ok(again) => assert_eq!(&again, job, "{canonical}"),
        Err(e) => panic!("the canonical form does not parse: {e}\n{canonical}"),
    }
    let alpha = job
        .alpha
        .unwrap_or_else(|| Alpha::try_new(0.5).expect("0.5 is a level"));
    let samples = match job.samples {
        Samples::Along(n) => Samples::Along(n.min(SAMPLES)),
        Samples::Grid([u, v]) => Samples::Grid([u.min(SAMPLES), v.min(SAMPLES)]),
    };
    let result = job
        .run(
            &job.settings(&t2spline::job::Overrides {
                alpha: Some(alpha.get()),
                type_reduction: Some(t2spline::TypeReduction::Paper),
                samples: Some(samples.counts()),
                derivatives: None,
            })
            .unwrap(),
        )
        .unwrap();
    if let Err(e) = check_finite(&result) {
        panic!("{e}");
    }
    let c = &result.samples;
    let count = samples.count();
    assert_eq!(c.params.count(), count);
    // Parameters from the start to exactly the end of the domain.
    let ranges: Vec<(&[f64], [f64; 2])> = match (&c.params, &result.spline) {
        (Parameters::Along(t), Spline::Curve { domain, .. }) => vec![(t, *domain)],
        (Parameters::Grid { u, v }, Spline::Surface { domain, .. }) => {
            vec![(u, domain[0]), (v, domain[1])]
        }
        _ => panic!("parameters of another kind than the spline"),
    };
    for (params, [a, b]) in &ranges {
        assert_eq!(params.first(), Some(a));
        assert_eq!(params.last(), Some(b));
    }
    // The maximum of the distance is reached inside the domain.
    let at: Vec<f64> = match result.error.max_at {
        Parameter::T(t) => vec![t],
        Parameter::Uv(uv) => uv.to_vec(),
    };
    assert_eq!(at.len(), ranges.len());
    for (t, (_, [a, b])) in at.iter().zip(&ranges) {
        assert!((a..=b).contains(&t), "max_at {t} outside [{a}, {b}]");
    }
    // Grids of samples and nets of control points in the model's shape.
    let (grid, net) = match (&samples, &job.model) {
        (Samples::Grid(grid), Model::Surface(s)) => (Some(*grid), Some(s.shape())),
        (Samples::Along(_), Model::Planar(_) | Model::Spatial(_)) => (None, None),
        _ => panic!("samples of another kind than the model"),
    };
    for points in [
        &c.crisp,
        &c.defuzzified,
        &c.type_reduced.left,
        &c.type_reduced.right,
    ] {
        assert_eq!((points.grid(), points.len()), (grid, count));
    }
    let p = &result.control_points;
    for points in [
        &p.crisp,
        &p.defuzzified,
        &p.type_reduced_left,
        &p.type_reduced_right,
    ] {
        assert_eq!(points.grid(), net);
        assert_eq!(points.len(), job.model.control_point_count());
    }
    for i in 0..count {
        for k in 0..result.dimension {
            let layer = |l: Layer| c.layer(l).coord(k)[i];
            let v: Vec<f64> = Layer::ALL.iter().map(|&l| layer(l)).collect();
            assert!(v.windows(2).all(|w| w[0] <= w[1]), "sample {i}: {v:?}");
        }
    }
    let e = &result.error;
    assert!(e.rms <= e.max * (1.0 + 1e-12), "{e:?}");
    let mut json = Vec::new();
    write_json_pretty(&mut json, &result).expect("in memory");
    let back: serde_json::Value = serde_json::from_slice(&json).expect("the result is JSON");
    assert!(back.is_object());
    for (name, csv) in render_csv(&result) {
        assert_eq!(csv.lines().count(), count + 1, "{name}");
        assert!(
            !csv.contains("NaN") && !csv.contains("inf"),
            "{name}: {csv}"
        );
    }
}
