//! The `t2spline` binary on surface jobs (docs/method.md §8), run for real: the result
//! keys and their shapes, values equal to the library's at every grid point,
//! `validate`, `--samples U,V`, `--alpha`, `--csv DIR`, the refusals of
//! `--derivatives`, `plot` and `report`, and every kind of bad input as a
//! located line with exit code 2.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::{json, Value};
use t2spline::job::Model;
use t2spline::{Alpha, FuzzySurface, Layer, NurbsSurface, Side};
use t2spline_io::job::locate;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_t2spline"))
}

/// Runs `t2spline args…` and returns (exit code, stdout, stderr).
fn run(args: &[&str]) -> (i32, String, String) {
    let out = bin().args(args).output().expect("the binary runs");
    (
        out.status.code().expect("exited, not killed"),
        String::from_utf8(out.stdout).expect("UTF-8"),
        String::from_utf8(out.stderr).expect("UTF-8"),
    )
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// A fuzzy number around `c` whose right spreads exceed its left ones.
fn number(c: f64) -> Value {
    json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]})
}

/// A surface job: a 4 × 3 net of orders 3 × 2, weights and knots in u of
/// its own, the default knots in v, alpha below the lower height.
fn job() -> Value {
    let points: Vec<Value> = (0..4)
        .map(|i| {
            let row: Vec<Value> = (0..3)
                .map(|j| {
                    let (x, y) = (i as f64, j as f64);
                    json!({"x": number(x), "y": number(y), "z": number((x - 1.5) * (y - 1.0))})
                })
                .collect();
            Value::Array(row)
        })
        .collect();
    json!({
        "description": "a saddle of fuzzy points",
        "order": [3, 2],
        "weights": [[1, 1, 1], [1, 2, 1], [0.5, 1, 1], [1, 1, 3]],
        "knots": {"u": [0, 0, 0, 0.3, 1, 1, 1]},
        "alpha": 0.4,
        "lower_height": 0.6,
        "samples": [5, 4],
        "points": points
    })
}

fn job_file(dir: &Path) -> PathBuf {
    write(
        dir,
        "saddle.json",
        &serde_json::to_string_pretty(&job()).unwrap(),
    )
}

/// The numbers of a JSON array of arrays … of numbers, flattened, with the
/// shape checked against `shape`.
fn grid_values(v: &Value, shape: &[usize]) -> Vec<f64> {
    match shape.split_first() {
        None => vec![v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))],
        Some((&n, rest)) => {
            let items = v.as_array().unwrap_or_else(|| panic!("not an array: {v}"));
            assert_eq!(items.len(), n, "{v}");
            items.iter().flat_map(|x| grid_values(x, rest)).collect()
        }
    }
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 * b.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

// ---------------------------------------------------------------------------
// The result
// ---------------------------------------------------------------------------

#[test]
fn run_writes_the_result_keys_of_spec_9() {
    let dir = tempfile::tempdir().unwrap();
    let (code, stdout, stderr) = run(&["run", s(&job_file(dir.path()))]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    let r: Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(r["description"], "a saddle of fuzzy points");
    assert_eq!(r["dimension"], 3);
    assert_eq!(r["order"], json!([3, 2]));
    assert_eq!(r["degree"], json!([2, 1]));
    assert_eq!(
        r["knots"],
        json!({"u": [0.0, 0.0, 0.0, 0.3, 1.0, 1.0, 1.0], "v": [0.0, 0.0, 0.5, 1.0, 1.0]})
    );
    assert_eq!(r["domain"], json!({"u": [0.0, 1.0], "v": [0.0, 1.0]}));
    assert_eq!(
        r["weights"],
        json!([
            [1.0, 1.0, 1.0],
            [1.0, 2.0, 1.0],
            [0.5, 1.0, 1.0],
            [1.0, 1.0, 3.0]
        ])
    );
    assert_eq!(r["alpha"], 0.4);
    assert_eq!(r["regime"], "alpha <= h");
    // Control points: [row][column][coordinate].
    for key in [
        "crisp",
        "type_reduced_left",
        "type_reduced_right",
        "defuzzified",
    ] {
        grid_values(&r["control_points"][key], &[4, 3, 3]);
    }
    // Samples: surfaces.params.{u, v}, every surface [a][b][coordinate].
    let surfaces = &r["surfaces"];
    assert!(r.get("curves").is_none());
    assert_eq!(
        numbers(&surfaces["params"]["u"]),
        [0.0, 0.25, 0.5, 0.75, 1.0]
    );
    let v = numbers(&surfaces["params"]["v"]);
    assert_eq!(v.len(), 4);
    assert_eq!((v[0], v[3]), (0.0, 1.0));
    for key in ["crisp", "defuzzified"] {
        grid_values(&surfaces[key], &[5, 4, 3]);
    }
    for layer in [
        "upper_left",
        "primary_left",
        "lower_left",
        "lower_right",
        "primary_right",
        "upper_right",
    ] {
        grid_values(&surfaces["layers"][layer], &[5, 4, 3]);
        grid_values(&surfaces["alpha_cut"][layer], &[5, 4, 3]);
    }
    for side in ["left", "right"] {
        grid_values(&surfaces["type_reduced"][side], &[5, 4, 3]);
    }
    // error.max_at is a pair (u, v) inside the domain.
    let at = numbers(&r["error"]["max_at"]);
    assert_eq!(at.len(), 2);
    assert!(at.iter().all(|t| (0.0..=1.0).contains(t)), "{at:?}");
    let (max, rms) = (
        r["error"]["max"].as_f64().unwrap(),
        r["error"]["rms"].as_f64().unwrap(),
    );
    assert!(0.0 < rms && rms <= max, "{max} {rms}");
}

/// Every sampled surface of the result equals the library's evaluation of
/// the same surface (the fuzzy surface's `eval_layers`, the solution's
/// surfaces) at every grid point to 1e-12, and the distance is the
/// solution's.
#[test]
fn the_result_equals_the_library_at_every_grid_point() {
    let dir = tempfile::tempdir().unwrap();
    let path = job_file(dir.path());
    let (code, stdout, stderr) = run(&["run", s(&path)]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    let r: Value = serde_json::from_str(&stdout).unwrap();
    let job = t2spline_io::read_job(&path).unwrap();
    let Model::Surface(fuzzy) = &job.model else {
        panic!("a surface job")
    };
    let solution = fuzzy.solve(Alpha::try_new(0.4).unwrap());
    let surfaces = &r["surfaces"];
    let (u, v) = (
        numbers(&surfaces["params"]["u"]),
        numbers(&surfaces["params"]["v"]),
    );
    let check = |key: &Value, eval: &dyn Fn(f64, f64) -> [f64; 3], what: &str| {
        let got = grid_values(key, &[u.len(), v.len(), 3]);
        for (a, &ua) in u.iter().enumerate() {
            for (b, &vb) in v.iter().enumerate() {
                let want = eval(ua, vb);
                for k in 0..3 {
                    close(
                        got[(a * v.len() + b) * 3 + k],
                        want[k],
                        &format!("{what} at ({ua}, {vb})[{k}]"),
                    );
                }
            }
        }
    };
    let layers = |layer: Layer| move |u: f64, v: f64| fuzzy_layers(fuzzy, u, v)[layer];
    check(&surfaces["crisp"], &layers(Layer::Crisp), "crisp");
    for layer in Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp) {
        check(
            &surfaces["layers"][layer.name()],
            &layers(layer),
            layer.name(),
        );
        let cut = solution
            .alpha_cut_surface(layer)
            .expect("alpha below every height");
        check(&surfaces["alpha_cut"][layer.name()], &eval(&cut), "cut");
    }
    check(
        &surfaces["type_reduced"]["left"],
        &eval(&solution.type_reduced_surface(Side::Left)),
        "left",
    );
    check(
        &surfaces["type_reduced"]["right"],
        &eval(&solution.type_reduced_surface(Side::Right)),
        "right",
    );
    check(
        &surfaces["defuzzified"],
        &eval(&solution.defuzzified_surface()),
        "defuzzified",
    );
    // Control points, row by row.
    let defuzzified = grid_values(&r["control_points"]["defuzzified"], &[4, 3, 3]);
    let want: Vec<f64> = solution
        .defuzzified_points()
        .iter()
        .flatten()
        .copied()
        .collect();
    assert_eq!(defuzzified, want);
    let d = solution.distance();
    close(r["error"]["max"].as_f64().unwrap(), d.max, "max");
    close(r["error"]["rms"].as_f64().unwrap(), d.rms, "rms");
    assert_eq!(numbers(&r["error"]["max_at"]), d.max_at);
}

fn fuzzy_layers(s: &FuzzySurface<3>, u: f64, v: f64) -> t2spline::Layers<[f64; 3]> {
    s.eval_layers(u, v).unwrap()
}

fn eval(s: &NurbsSurface<3>) -> impl Fn(f64, f64) -> [f64; 3] + '_ {
    move |u, v| s.eval(u, v).unwrap()
}

#[test]
fn samples_u_v_and_alpha_override_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = job_file(dir.path());
    let grid = |args: &[&str]| {
        let mut all = vec!["run", s(&path)];
        all.extend(args);
        let (code, stdout, stderr) = run(&all);
        assert_eq!((code, stderr.as_str()), (0, ""), "{args:?}");
        let r: Value = serde_json::from_str(&stdout).unwrap();
        let p = &r["surfaces"]["params"];
        (numbers(&p["u"]).len(), numbers(&p["v"]).len(), r)
    };
    assert_eq!(grid(&[]).0, 5);
    let (su, sv, _) = grid(&["--samples", "3,7"]);
    assert_eq!((su, sv), (3, 7));
    let (su, sv, _) = grid(&["--samples", "6"]);
    assert_eq!((su, sv), (6, 6));
    let (_, _, r) = grid(&["--alpha", "0.9"]);
    assert_eq!(
        (r["alpha"].as_f64(), r["regime"].as_str()),
        (Some(0.9), Some("alpha > h"))
    );
    for (samples, message) in [
        ("1,5", "t2spline: --samples: samples = 1: at least 2 are needed (both ends of the domain)\n"),
        ("2000,501", "t2spline: --samples: samples = 2000 × 501 = 1002000 grid points is more than the limit 1000000\n"),
        ("3,3,3", "t2spline: --samples: a surface is sampled at one number of parameters for both directions, or two (u, v), got 3 numbers\n"),
    ] {
        let (code, stdout, stderr) = run(&["run", s(&path), "--samples", samples]);
        assert_eq!((code, stdout.as_str(), stderr.as_str()), (2, "", message));
    }
}

#[test]
fn validate_prints_one_summary_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = job_file(dir.path());
    let (code, stdout, stderr) = run(&["validate", s(&path)]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    assert_eq!(
        stdout,
        format!(
            "{}: ok: 3-D surface, 4 × 3 control points, orders 3 × 2, alpha 0.4, 5 × 4 samples\n",
            s(&path)
        )
    );
}

/// `--csv DIR`: four files, each with `u, v` and then the columns of its
/// surfaces, one row per grid point (v fastest), equal to the JSON result.
#[test]
fn csv_files_of_a_surface_have_one_row_per_grid_point() {
    let dir = tempfile::tempdir().unwrap();
    let path = job_file(dir.path());
    let csv = dir.path().join("tables");
    let (code, stdout, stderr) = run(&["run", s(&path), "--csv", s(&csv), "--samples", "3,4"]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    let r: Value = serde_json::from_str(&stdout).unwrap();
    let mut names: Vec<String> = std::fs::read_dir(&csv)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "stage1-layers.csv",
            "stage2-alpha-cut.csv",
            "stage3-type-reduced.csv",
            "stage4-defuzzified.csv"
        ]
    );
    let (u, v) = (
        numbers(&r["surfaces"]["params"]["u"]),
        numbers(&r["surfaces"]["params"]["v"]),
    );
    let text = std::fs::read_to_string(csv.join("stage4-defuzzified.csv")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0],
        "u,v,crisp_x,crisp_y,crisp_z,defuzzified_x,defuzzified_y,defuzzified_z,distance"
    );
    assert_eq!(lines.len(), 1 + 3 * 4);
    let crisp = grid_values(&r["surfaces"]["crisp"], &[3, 4, 3]);
    let solution = grid_values(&r["surfaces"]["defuzzified"], &[3, 4, 3]);
    for (a, &ua) in u.iter().enumerate() {
        for (b, &vb) in v.iter().enumerate() {
            let i = a * 4 + b;
            let row: Vec<f64> = lines[1 + i]
                .split(',')
                .map(|x| x.parse().unwrap())
                .collect();
            assert_eq!(row[..2], [ua, vb]);
            assert_eq!(row[2..5], crisp[i * 3..i * 3 + 3]);
            assert_eq!(row[5..8], solution[i * 3..i * 3 + 3]);
            let d = (0..3)
                .map(|k| (row[5 + k] - row[2 + k]).powi(2))
                .sum::<f64>()
                .sqrt();
            close(row[8], d, "distance");
        }
    }
    let layers = std::fs::read_to_string(csv.join("stage1-layers.csv")).unwrap();
    assert!(
        layers.starts_with("u,v,upper_left_x,upper_left_y,upper_left_z,primary_left_x,"),
        "{layers}"
    );
    assert_eq!(layers.lines().count(), 13);
}

// ---------------------------------------------------------------------------
// Refusals
// ---------------------------------------------------------------------------

#[test]
fn derivatives_are_refused_for_surfaces() {
    let dir = tempfile::tempdir().unwrap();
    let (code, stdout, stderr) = run(&["run", s(&job_file(dir.path())), "--derivatives", "2"]);
    assert_eq!(
        (code, stdout.as_str(), stderr.as_str()),
        (
            2,
            "",
            "t2spline: --derivatives: derivatives are offered for curves; this job is a surface\n"
        )
    );
}

/// Figures of surfaces: `plot` writes the six figures (and, the saddle's
/// plan being fuzzy, says why it draws no terrain figures), `report` one page;
/// a point past the net is refused naming `--point`, counting the net's
/// points row by row.
#[test]
fn plot_and_report_draw_surface_jobs() {
    let dir = tempfile::tempdir().unwrap();
    let path = job_file(dir.path());
    let out = dir.path().join("plot");
    let (code, stdout, stderr) = run(&["plot", s(&path), "-o", s(&out), "--format", "svg"]);
    assert_eq!(
        (code, stderr.as_str()),
        (0, "t2spline plot: note: the terrain figures (envelope-width, shoreline, terrain-measures) are left out: points[0][0].x is fuzzy: volumes and areas are measured over a crisp plan (x and y crisp at every control point)\n"),
        "{stdout}"
    );
    assert_eq!(stdout.lines().count(), 6, "{stdout}");
    let out = dir.path().join("report");
    let (code, _, stderr) = run(&["report", s(&path), "-o", s(&out)]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    assert!(out.join("report.html").exists());
    let (code, _, stderr) = run(&["plot", s(&path), "-o", s(&out), "--point", "1000"]);
    assert_eq!(code, 2);
    assert!(
        stderr.starts_with("t2spline: --point: point 1000 does not exist"),
        "{stderr}"
    );
}

/// A surface job with fuzzy weights (docs/method.md §16): `run` writes the
/// weights of every stage and the surface of each stage with its own
/// weights; `plot` and `report` draw it, leaving out the terrain figures
/// with a note; what refuses fuzzy weights says so with exit code 2.
#[test]
fn a_surface_with_fuzzy_weights_runs_plots_and_reports() {
    let dir = tempfile::tempdir().unwrap();
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/fuzzy-weights-surface.json");
    let result = dir.path().join("result.json");
    let (code, _, stderr) = run(&["run", s(&path), "-o", s(&result)]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    let r: Value = serde_json::from_str(&std::fs::read_to_string(&result).unwrap()).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let job = t2spline_io::parse_job(&text, "job.json").unwrap();
    let Model::Surface(surface) = &job.model else {
        panic!("a surface")
    };
    let solution = surface.solve(Alpha::try_new(0.5).unwrap());
    assert_eq!(
        numbers(&r["weight_stages"]["defuzzified"]),
        solution.defuzzified_weights().unwrap()
    );
    let [u, v] = [
        numbers(&r["surfaces"]["params"]["u"]),
        numbers(&r["surfaces"]["params"]["v"]),
    ];
    let (right, upper) = (
        solution.type_reduced_surface(Side::Right),
        surface.layer_surface(Layer::UpperRight),
    );
    let (right, upper) = (eval(&right), eval(&upper));
    for (a, &u) in u.iter().enumerate() {
        for (b, &v) in v.iter().enumerate() {
            let got = numbers(&r["surfaces"]["type_reduced"]["right"][a][b]);
            let want = right(u, v);
            (0..3).for_each(|d| close(got[d], want[d], "type-reduced right"));
            let got = numbers(&r["surfaces"]["layers"]["upper_right"][a][b]);
            let want = upper(u, v);
            (0..3).for_each(|d| close(got[d], want[d], "upper right layer"));
        }
    }
    let out = dir.path().join("plot");
    let (code, stdout, stderr) = run(&["plot", s(&path), "-o", s(&out), "--format", "svg"]);
    assert_eq!(
        (code, stderr.as_str()),
        (0, "t2spline plot: note: the terrain figures (envelope-width, shoreline, terrain-measures) are left out: the envelope, contour and measures of a surface with fuzzy weights are not available yet (docs/method.md §16)\n"),
        "{stdout}"
    );
    assert_eq!(stdout.lines().count(), 6, "{stdout}");
    let out = dir.path().join("report");
    let (code, _, stderr) = run(&["report", s(&path), "-o", s(&out)]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    assert!(out.join("report.html").exists());
    let (code, _, stderr) = run(&["measure", s(&path)]);
    assert_eq!(
        (code, stderr.as_str()),
        (
            2,
            "t2spline: a surface measure is not available for a model with fuzzy weights\n"
        )
    );
}

/// A problem a test expects: its JSON path and its message.
type Problem = (&'static str, &'static str);

/// Each kind of bad input of a surface job: `run` and `validate` exit with 2
/// and print the problem at its line and column.
#[test]
fn every_kind_of_bad_surface_input_is_a_located_line_with_exit_code_2() {
    let dir = tempfile::tempdir().unwrap();
    let pretty = |v: &Value| serde_json::to_string_pretty(v).unwrap();
    let with = |f: &dyn Fn(&mut Value)| {
        let mut v = job();
        f(&mut v);
        pretty(&v)
    };
    // (case, text, the JSON path of the problem, the message); the paths are
    // placed by the reader's own scan, whose positions `t2spline-io` tests.
    let cases: Vec<(&str, String, Vec<Problem>)> = vec![
        (
            "ragged",
            with(&|v| {
                v["points"][2].as_array_mut().unwrap().pop();
                v["weights"][2].as_array_mut().unwrap().pop();
            }),
            vec![("points[2]", "points[2]: 2 columns, row 0 has 3: every row of the net needs as many points")],
        ),
        (
            "weights",
            with(&|v| v["weights"][1] = json!([1, 2])),
            vec![("weights[1]", "weights[1]: 2 columns, points[1] has 3")],
        ),
        (
            "planar",
            with(&|v| {
                v["points"][1][0].as_object_mut().unwrap().remove("z");
            }),
            vec![("points[1][0]", "points[1][0]: has coordinates [x, y]; the points of a surface need x, y and z")],
        ),
        (
            "knots",
            with(&|v| v["knots"]["v"] = json!([0, 0, 1, 1])),
            vec![("knots.v", "knots.v: expected 5 values (columns + order in v), got 4")],
        ),
        (
            "one point",
            with(&|v| {
                v["points"] = json!([[v["points"][0][0].clone()]]);
                v.as_object_mut().unwrap().remove("weights");
                v.as_object_mut().unwrap().remove("knots");
            }),
            vec![
                ("points", "points: a surface of order 3 in u needs at least 3 control points along u, got 1"),
                ("points", "points: a surface of order 2 in v needs at least 2 control points along v, got 1"),
            ],
        ),
        (
            "knot key",
            with(&|v| v["knots"]["w"] = json!([0, 1])),
            vec![("knots.w", "knots.w: unknown key (known keys: u, v)")],
        ),
        (
            "order number",
            with(&|v| v["order"] = json!(3)),
            vec![("order", "order: a surface (points given as rows of a net) has one order per direction: give a pair [u, v], got 3")],
        ),
        (
            "samples",
            with(&|v| v["samples"] = json!([4, 1])),
            vec![("samples[1]", "samples[1]: samples = 1: at least 2 are needed (both ends of the domain)")],
        ),
    ];
    for (case, text, problems) in cases {
        let path = write(dir.path(), &format!("{case}.json"), &text);
        let want: Vec<String> = problems
            .iter()
            .map(|(place, message)| {
                let (line, column) = locate(&text, place);
                assert!(line > 1, "{case}: {place} is not in the file");
                format!("t2spline: {}:{line}:{column}: {message}", s(&path))
            })
            .collect();
        for sub in ["run", "validate"] {
            let (code, stdout, stderr) = run(&[sub, s(&path)]);
            let lines: Vec<&str> = stderr.lines().collect();
            assert_eq!((code, stdout.as_str()), (2, ""), "{case}, {sub}: {stderr}");
            assert_eq!(lines, want, "{case}, {sub}:\n{text}");
        }
    }
}
