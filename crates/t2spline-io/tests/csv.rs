//! CSV export: headers, row counts, the stage-2 file with and without the lower
//! layers, and numbers that read back to the exact values of the result.

use proptest::prelude::*;
use serde_json::json;
use t2spline::job::{Job, Model, Points, RunOutput, Samples};
use t2spline::{strategies, Alpha, Layer};
use t2spline_io::{render_csv, write_csv, CSV_FILES};

/// The job's result at `alpha` and `samples`.
fn compute(job: &Job, alpha: Alpha, samples: usize) -> RunOutput {
    job.run(
        &job.settings(&t2spline::job::Overrides {
            alpha: Some(alpha.get()),
            type_reduction: Some(t2spline::TypeReduction::Paper),
            samples: Some(vec![samples as u64]),
            derivatives: None,
        })
        .unwrap(),
    )
    .unwrap()
}

/// A job of order 2 with three points in `dims` dimensions, every number of
/// height `h`, sampled at `samples` parameters.
fn job(dims: usize, h: f64, samples: usize) -> Job {
    let number = |c: f64| json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]});
    let point = |i: usize| {
        let c = i as f64;
        let mut p = json!({"x": number(c), "y": number(c * c)});
        if dims == 3 {
            p["z"] = number(-c);
        }
        p
    };
    let v = json!({
        "order": 2, "lower_height": h, "samples": samples, "weights": [1, 2, 1],
        "points": [point(0), point(1), point(2)]
    });
    t2spline_io::parse_job(&v.to_string(), "job.json").unwrap()
}

fn alpha(a: f64) -> Alpha {
    Alpha::try_new(a).unwrap()
}

/// The contents of one of the rendered files.
fn file<'r>(files: &'r [(&'static str, String)], name: &str) -> &'r str {
    files
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| text.as_str())
        .unwrap_or_else(|| {
            panic!(
                "no {name} among {:?}",
                files.iter().map(|f| f.0).collect::<Vec<_>>()
            )
        })
}

/// Header and rows of a CSV text (our numbers and names hold no commas or
/// quotes, which the header check below makes sure of).
fn table(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("a header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    (header, rows)
}

/// Column names for curves `names` in `dims` dimensions, after `t`.
fn columns(names: &[&str], dims: usize) -> Vec<String> {
    let mut out = vec!["t".to_owned()];
    for name in names {
        out.extend(
            ["x", "y", "z"][..dims]
                .iter()
                .map(|a| format!("{name}_{a}")),
        );
    }
    out
}

const SEVEN: [&str; 7] = [
    "upper_left",
    "primary_left",
    "lower_left",
    "crisp",
    "lower_right",
    "primary_right",
    "upper_right",
];

#[test]
fn four_files_in_the_documented_order() {
    let r = compute(&job(2, 0.5, 5), alpha(0.3), 5);
    let names: Vec<_> = render_csv(&r).into_iter().map(|(n, _)| n).collect();
    let documented: Vec<_> = CSV_FILES.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, documented);
    assert_eq!(
        names,
        [
            "stage1-layers.csv",
            "stage2-alpha-cut.csv",
            "stage3-type-reduced.csv",
            "stage4-defuzzified.csv"
        ]
    );
}

#[test]
fn headers_and_row_counts_in_two_and_three_dimensions() {
    for dims in [2, 3] {
        let samples = 7;
        let r = compute(&job(dims, 0.5, samples), alpha(0.3), samples);
        let files = render_csv(&r);
        let expected = [
            ("stage1-layers.csv", columns(&SEVEN, dims)),
            ("stage2-alpha-cut.csv", columns(&SEVEN, dims)),
            (
                "stage3-type-reduced.csv",
                columns(&["left", "crisp", "right"], dims),
            ),
            ("stage4-defuzzified.csv", {
                let mut c = columns(&["crisp", "defuzzified"], dims);
                c.push("distance".into());
                c
            }),
        ];
        for (name, header) in expected {
            let text = file(&files, name);
            assert!(!text.contains('"'), "{name}: nothing needs quoting\n{text}");
            let (got, rows) = table(text);
            assert_eq!(got, header, "{dims}-D {name}");
            assert_eq!(rows.len(), samples, "{dims}-D {name}: one row per sample");
            assert!(rows.iter().all(|row| row.len() == header.len()), "{name}");
            assert_eq!(text.lines().count(), samples + 1);
        }
    }
}

#[test]
fn stage2_leaves_out_the_lower_layers_above_the_height() {
    let h = 0.5;
    let names = |a: f64| {
        let r = compute(&job(2, h, 3), alpha(a), 3);
        table(file(&render_csv(&r), "stage2-alpha-cut.csv")).0
    };
    let without_lower = columns(
        &[
            "upper_left",
            "primary_left",
            "crisp",
            "primary_right",
            "upper_right",
        ],
        2,
    );
    assert_eq!(names(0.8), without_lower, "alpha > h");
    assert_eq!(names(1.0), without_lower, "alpha = 1 > h");
    assert_eq!(
        names(h),
        columns(&SEVEN, 2),
        "alpha = h: the lower cut exists"
    );
    assert_eq!(names(0.2), columns(&SEVEN, 2), "alpha < h");
    assert_eq!(names(0.0), columns(&SEVEN, 2), "alpha = 0");
}

#[test]
fn stage2_with_mixed_heights_has_lower_layers_only_below_every_height() {
    // One number of height 0.25, the rest 0.5 (from the top level).
    let mut v = t2spline_io::job_json(&job(2, 0.5, 3));
    v["points"][1]["y"]["lower_height"] = json!(0.25);
    let job = t2spline_io::parse_job(&v.to_string(), "job.json").unwrap();
    let names = |a: f64| {
        let r = compute(&job, alpha(a), 3);
        table(file(&render_csv(&r), "stage2-alpha-cut.csv")).0
    };
    assert_eq!(names(0.25), columns(&SEVEN, 2));
    assert_eq!(names(0.3).len(), 1 + 5 * 2, "0.25 < alpha <= 0.5: mixed");
    assert_eq!(names(0.6).len(), 1 + 5 * 2);
}

/// The values of a column, read back as f64.
fn column(header: &[String], rows: &[Vec<String>], name: &str) -> Vec<f64> {
    let i = header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"));
    rows.iter()
        .map(|row| {
            row[i]
                .parse::<f64>()
                .unwrap_or_else(|e| panic!("{name}: {:?}: {e}", row[i]))
        })
        .collect()
}

/// Asserts that columns `{name}_x …` hold exactly `points`.
#[track_caller]
fn assert_curve(header: &[String], rows: &[Vec<String>], name: &str, points: &Points) {
    for (a, axis) in ["x", "y", "z"][..points.dimension()].iter().enumerate() {
        let got = column(header, rows, &format!("{name}_{axis}"));
        let want = points.coord(a);
        // Bit for bit: the CSV holds the shortest text that reads back exactly.
        let same = got
            .iter()
            .zip(want)
            .all(|(g, w)| g.to_bits() == w.to_bits());
        assert!(
            same && got.len() == want.len(),
            "{name}_{axis}: {got:?} != {want:?}"
        );
    }
}

/// Every number of every file equals the result's value, bit for bit.
fn check_values(r: &RunOutput) {
    let files = render_csv(r);
    let c = &r.samples;
    let params_equal = |header: &[String], rows: &[Vec<String>]| {
        let t = column(header, rows, "t");
        t.iter()
            .zip(c.params.along())
            .all(|(a, b)| a.to_bits() == b.to_bits())
    };

    let (h, rows) = table(file(&files, "stage1-layers.csv"));
    assert!(params_equal(&h, &rows));
    for layer in Layer::ALL {
        let points = c.layers.get(layer).unwrap_or(&c.crisp);
        assert_curve(&h, &rows, layer.name(), points);
    }

    let (h, rows) = table(file(&files, "stage2-alpha-cut.csv"));
    assert!(params_equal(&h, &rows));
    for layer in Layer::ALL {
        match c.alpha_cut.get(layer) {
            Some(Some(points)) => assert_curve(&h, &rows, layer.name(), points),
            Some(None) => assert!(!h.iter().any(|n| n.starts_with(layer.name()))),
            None => assert_curve(&h, &rows, "crisp", &c.crisp),
        }
    }

    let (h, rows) = table(file(&files, "stage3-type-reduced.csv"));
    assert!(params_equal(&h, &rows));
    assert_curve(&h, &rows, "left", &c.type_reduced.left);
    assert_curve(&h, &rows, "crisp", &c.crisp);
    assert_curve(&h, &rows, "right", &c.type_reduced.right);

    let (h, rows) = table(file(&files, "stage4-defuzzified.csv"));
    assert!(params_equal(&h, &rows));
    assert_curve(&h, &rows, "crisp", &c.crisp);
    assert_curve(&h, &rows, "defuzzified", &c.defuzzified);
    let distance = column(&h, &rows, "distance");
    for (i, d) in distance.iter().enumerate() {
        let want = c
            .crisp
            .coords()
            .iter()
            .zip(c.defuzzified.coords())
            .map(|(a, b)| (a[i] - b[i]) * (a[i] - b[i]))
            .sum::<f64>()
            .sqrt();
        assert_eq!(d.to_bits(), want.to_bits(), "distance at row {i}");
        assert!(
            *d <= r.error.max * (1.0 + 1e-9) + 1e-12,
            "{d} > error.max {}",
            r.error.max
        );
    }
}

#[test]
fn csv_values_read_back_to_the_result_values() {
    for dims in [2, 3] {
        for a in [0.0, 0.3, 0.5, 0.9] {
            check_values(&compute(&job(dims, 0.5, 9), alpha(a), 9));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn csv_values_read_back_for_random_curves(
        curve in prop_oneof![
            strategies::fuzzy_curve::<2>().prop_map(Model::Planar),
            strategies::fuzzy_curve::<3>().prop_map(Model::Spatial),
        ],
        a in 0.0..=1.0f64,
        samples in 2usize..30,
    ) {
        let job = Job { description: None, alpha: None, type_reduction: t2spline::TypeReduction::Paper, samples: Samples::Along(samples), closed: None, units: None, model: curve };
        check_values(&compute(&job, alpha(a), samples));
    }
}

#[test]
fn write_csv_creates_the_folder_and_the_four_files() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("new/nested");
    let r = compute(&job(3, 1.0, 4), alpha(0.5), 4);
    let written = write_csv(&out, &r).unwrap();
    assert_eq!(written.len(), 4);
    for ((name, text), path) in render_csv(&r).iter().zip(&written) {
        assert_eq!(path, &out.join(name));
        assert_eq!(&std::fs::read_to_string(path).unwrap(), text);
    }
    // Nothing else (no temporary files) is left in the folder.
    assert_eq!(std::fs::read_dir(&out).unwrap().count(), 4);
}

#[test]
fn write_csv_into_a_file_is_an_error_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let blocker = dir.path().join("file");
    std::fs::write(&blocker, "x").unwrap();
    let r = compute(&job(2, 1.0, 3), alpha(0.5), 3);
    let e = write_csv(&blocker, &r).unwrap_err();
    let lines = e.lines();
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(&format!("{}: cannot write: ", blocker.display())),
        "{lines:?}"
    );
    assert_eq!(std::fs::read_to_string(&blocker).unwrap(), "x");
}

proptest! {
    #![proptest_config(strategies::cases(8, 16))]

    /// A surface: `u, v` over the grid with `v` fastest, then every surface's
    /// points in the same order, bit for bit.
    #[test]
    fn csv_of_random_surfaces(
        surface in strategies::fuzzy_surface::<3>(),
        a in 0.0..=1.0f64,
        su in 2usize..7,
        sv in 2usize..7,
    ) {
        let samples = Samples::Grid([su, sv]);
        let job = Job { samples, ..Job::new(Model::Surface(surface)) };
        let r = job.run(&job.settings(&t2spline::job::Overrides { alpha: Some(alpha(a).get()), type_reduction: Some(t2spline::TypeReduction::Paper), samples: Some(samples.counts()), derivatives: None }).unwrap())
        .unwrap();
        let t2spline::job::Parameters::Grid { u, v } = &r.samples.params else {
            panic!("a grid")
        };
        let files = render_csv(&r);
        let (h, rows) = table(file(&files, "stage3-type-reduced.csv"));
        prop_assert_eq!(&h[..2], ["u", "v"]);
        prop_assert_eq!(rows.len(), su * sv);
        let (cu, cv) = (column(&h, &rows, "u"), column(&h, &rows, "v"));
        for (i, (a, b)) in cu.iter().zip(&cv).enumerate() {
            prop_assert_eq!(a.to_bits(), u[i / sv].to_bits());
            prop_assert_eq!(b.to_bits(), v[i % sv].to_bits());
        }
        assert_curve(&h, &rows, "left", &r.samples.type_reduced.left);
        assert_curve(&h, &rows, "crisp", &r.samples.crisp);
        assert_curve(&h, &rows, "right", &r.samples.type_reduced.right);
    }
}
