//! Parquet output read back with the `parquet` crate's reader: the columns
//! are the CSV files' columns (each curve once, the alpha-cut layers
//! prefixed), every value is the CSV's value bit for bit, and the key-value
//! metadata holds every other key of the result file as its JSON.
#![cfg(feature = "parquet")]

use std::collections::BTreeMap;

use parquet::basic::Type as Physical;
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::RowAccessor;
use proptest::prelude::*;
use t2spline::job::{Job, Model, Overrides, RunOutput, Samples, Settings};
use t2spline::{strategies, Alpha, TypeReduction};
use t2spline_io::{
    render_csv, write_json_pretty, write_parquet, write_summary_parquet, JobSummary,
};

/// The columns of a Parquet file: name → values (a `None` per null).
type Columns = Vec<(String, Vec<Option<f64>>)>;

/// Reads every column of a file of doubles, and its key-value metadata.
fn read(bytes: Vec<u8>) -> (Columns, BTreeMap<String, String>) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("t.parquet");
    std::fs::write(&path, bytes).unwrap();
    let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
    let meta = reader.metadata().file_metadata();
    let kv = meta
        .key_value_metadata()
        .map(|kv| {
            kv.iter()
                .map(|p| (p.key.clone(), p.value.clone().unwrap_or_default()))
                .collect()
        })
        .unwrap_or_default();
    let schema = meta.schema_descr();
    let mut columns: Columns = (0..schema.num_columns())
        .map(|i| {
            let c = schema.column(i);
            assert_eq!(c.physical_type(), Physical::DOUBLE, "{}", c.name());
            (c.name().to_owned(), Vec::new())
        })
        .collect();
    for row in reader.get_row_iter(None).unwrap() {
        let row = row.unwrap();
        for (i, (_, values)) in columns.iter_mut().enumerate() {
            values.push(row.get_double(i).ok());
        }
    }
    (columns, kv)
}

/// The CSV files' columns by name, read back (each name once; stage 2's
/// non-crisp layers as `alpha_cut_…`).
fn csv_columns(result: &RunOutput) -> Columns {
    let mut out: Columns = Vec::new();
    for (file, text) in render_csv(result) {
        let mut lines = text.lines();
        let header: Vec<String> = lines
            .next()
            .unwrap()
            .split(',')
            .map(str::to_owned)
            .collect();
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        for (i, name) in header.iter().enumerate() {
            let name = if file == "stage2-alpha-cut.csv"
                && !["t", "u", "v"].contains(&name.as_str())
                && !name.starts_with("crisp_")
            {
                format!("alpha_cut_{name}")
            } else {
                name.clone()
            };
            if !out.iter().any(|(n, _)| *n == name) {
                out.push((name, rows.iter().map(|r| Some(r[i])).collect()));
            }
        }
    }
    out
}

/// Asserts that the Parquet file of `result` holds the CSV's columns and
/// the JSON file's other keys.
fn check(result: &RunOutput) {
    let mut bytes = Vec::new();
    write_parquet(&mut bytes, result).unwrap();
    let (columns, kv) = read(bytes);
    let mut want = csv_columns(result);
    let names = |c: &Columns| c.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    // Same names; the order is the Parquet file's (stages 1–4, derivatives).
    let mut sorted = names(&columns);
    sorted.sort();
    let mut sorted_want = names(&want);
    sorted_want.sort();
    assert_eq!(sorted, sorted_want);
    for (name, values) in &columns {
        let at = want.iter().position(|(n, _)| n == name).unwrap();
        let (_, expected) = want.swap_remove(at);
        let bits = |v: &[Option<f64>]| v.iter().map(|x| x.map(f64::to_bits)).collect::<Vec<_>>();
        assert_eq!(bits(values), bits(&expected), "column {name}");
    }
    // Every top-level key of the result file but the samples, as its JSON.
    let mut json = Vec::new();
    write_json_pretty(&mut json, result).unwrap();
    let json: serde_json::Value = serde_json::from_slice(&json).unwrap();
    let object = json.as_object().unwrap();
    let keys: Vec<&String> = object
        .keys()
        .filter(|k| *k != "curves" && *k != "surfaces")
        .collect();
    assert_eq!(kv.len(), keys.len(), "{:?} against {keys:?}", kv.keys());
    for key in keys {
        let value: serde_json::Value = serde_json::from_str(&kv[key]).unwrap();
        assert_eq!(&value, &object[key], "{key}");
    }
}

fn settings(job: &Job, a: f64, samples: Samples, derivatives: Option<usize>) -> Settings {
    job.settings(&Overrides {
        alpha: Some(a),
        type_reduction: Some(t2spline::TypeReduction::Paper),
        samples: Some(samples.counts()),
        derivatives: derivatives.map(|k| k as i64),
    })
    .unwrap()
}

#[test]
fn the_example_with_derivatives() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/paper-alg-1-1.json"
    );
    let job = t2spline_io::read_job(std::path::Path::new(path)).unwrap();
    for (a, d) in [(0.8, None), (0.3, Some(2))] {
        let result = job.run(&settings(&job, a, Samples::Along(33), d)).unwrap();
        check(&result);
    }
    let result = job
        .run(&settings(&job, 0.8, Samples::Along(5), None))
        .unwrap();
    let mut bytes = Vec::new();
    write_parquet(&mut bytes, &result).unwrap();
    let (columns, kv) = read(bytes);
    let names: Vec<&str> = columns.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names[..3], ["t", "upper_left_x", "upper_left_y"]);
    // alpha 0.8 > h = 0.6: no lower cut.
    assert!(names.contains(&"alpha_cut_primary_left_x"));
    assert!(!names.iter().any(|n| n.starts_with("alpha_cut_lower")));
    assert_eq!(
        names[names.len() - 3..],
        ["defuzzified_x", "defuzzified_y", "distance"]
    );
    assert_eq!(kv["regime"], "\"alpha > h\"");
    assert_eq!(kv["alpha"], "0.8");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn random_curves_and_surfaces(
        model in prop_oneof![
            strategies::fuzzy_curve::<2>().prop_map(Model::Planar),
            strategies::fuzzy_curve::<3>().prop_map(Model::Spatial),
            strategies::fuzzy_surface::<3>().prop_map(Model::Surface),
        ],
        a in 0.0..=1.0f64,
        su in 2usize..9,
        sv in 2usize..9,
        type_reduction in proptest::sample::select(TypeReduction::ALL.to_vec()),
    ) {
        let samples = if model.is_surface() { Samples::Grid([su, sv]) } else { Samples::Along(su) };
        // Every reduction: `alpha_used`, and a null regime for all but the paper's.
        let job = Job {
            description: Some("a, \"quoted\" one".into()),
            alpha: Some(Alpha::try_new(a).unwrap()),
            type_reduction,
            samples,
            ..Job::new(model)
        };
        check(&job.run(&job.settings(&Overrides::default()).unwrap()).unwrap());
    }
}

#[test]
fn a_summary_with_nulls() {
    let row = |name: &str, ok: bool| JobSummary {
        name: name.into(),
        file: format!("jobs/{name}.json"),
        status: if ok { "ok" } else { "invalid" }.into(),
        type_reduction: ok.then(|| "paper".into()),
        regime: ok.then(|| "alpha > h".into()),
        alpha: ok.then_some(0.8),
        h: ok.then_some(0.6),
        error_max: ok.then_some(0.044),
        error_max_at: ok.then_some(0.25),
        error_max_at_v: None,
        error_rms: ok.then_some(1e-20),
        description: ok.then(|| "a line".into()),
        message: (!ok).then(|| "jobs/b.json:1:2: alhpa: unknown key".into()),
    };
    let mut bytes = Vec::new();
    write_summary_parquet(&mut bytes, &[row("a", true), row("b", false)]).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("s.parquet");
    std::fs::write(&path, bytes).unwrap();
    let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
    let rows: Vec<_> = reader
        .get_row_iter(None)
        .unwrap()
        .map(|r| r.unwrap().to_string())
        .collect();
    assert_eq!(
        rows,
        [
            r#"{name: "a", file: "jobs/a.json", status: "ok", type_reduction: "paper", regime: "alpha > h", alpha: 0.8, h: 0.6, error_max: 0.044, error_max_at: 0.25, error_max_at_v: null, error_rms: 1E-20, description: "a line", message: null}"#,
            r#"{name: "b", file: "jobs/b.json", status: "invalid", type_reduction: null, regime: null, alpha: null, h: null, error_max: null, error_max_at: null, error_max_at_v: null, error_rms: null, description: null, message: "jobs/b.json:1:2: alhpa: unknown key"}"#
        ]
    );
}
