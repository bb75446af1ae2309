//! `measure` (quantities measured on a fuzzy curve, docs/method.md §11):
//! the file's shape on the shipped example, the output file written
//! atomically, exit codes and messages naming the flag and the rule, no
//! output file when the input is bad; a surface's volumes, plan area and
//! surface area (§14), and the cut and fill against a resurvey.

use std::path::{Path, PathBuf};

mod common;
use common::{run, s};

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn terrain() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-terrain.json")
}

/// `examples/fuzzy-terrain.json` resurveyed: a pit dug, its spoil heaped.
fn resurvey() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/fuzzy-terrain-resurvey.json")
}

/// `args` followed by `-o OUT` must exit 2 with a message holding `words`,
/// and leave no OUT.
fn refused(args: &[&str], words: &str) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let mut all = vec!["measure"];
    all.extend(args);
    all.extend(["-o", s(&out)]);
    let (code, stdout, stderr) = run(&all);
    assert_eq!(code, 2, "{args:?}: {stderr}");
    assert_eq!(stdout, "");
    assert!(stderr.starts_with("t2spline: "), "{stderr}");
    assert!(stderr.contains(words), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!out.exists(), "{args:?} wrote its output");
}

#[test]
fn the_example_measured_into_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("m.json");
    let (code, stdout, stderr) = run(&[
        "measure",
        s(&example()),
        "--levels",
        "11",
        "--at",
        "0.25,0.5",
        "-o",
        s(&out),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stdout, "");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(v["levels"].as_array().unwrap().len(), 11);
    let upper = v["length"]["upper"].as_array().unwrap();
    assert_eq!(upper.len(), 11);
    // The level 0.5: lengths from 7.2953 to 10.6953.
    assert_eq!(upper[5]["alpha"], 0.5);
    let (lo, hi) = (
        upper[5]["min"].as_f64().unwrap(),
        upper[5]["max"].as_f64().unwrap(),
    );
    assert!(
        (lo - 7.2953).abs() < 5e-5 && (hi - 10.6953).abs() < 5e-5,
        "{lo} {hi}"
    );
    assert_eq!(upper[5]["exact"], true);
    // The lower function up to its height 0.6.
    assert_eq!(v["length"]["lower"].as_array().unwrap().len(), 7);
    assert_eq!(v["area"]["kind"], "under");
    let at = v["at"].as_array().unwrap();
    assert_eq!(at.len(), 2);
    assert_eq!(at[1]["t"], 0.5);
    let d = &at[1]["derivative"]["upper"][0];
    assert_eq!(d["min"].as_array().unwrap().len(), 2);
    assert!(at[1]["tangent_angle"]["upper"][0]["defined"]
        .as_bool()
        .unwrap());
    assert!(at[1]["curvature"]["primary"][10]["max"].as_f64().unwrap() > 0.0);
}

#[test]
fn bad_flags_name_the_flag_and_write_nothing() {
    let e = example();
    let job = s(&e);
    refused(
        &[job, "--at", "1.5"],
        "--at: at[0] = 1.5 is outside the domain [0, 1]",
    );
    refused(
        &[job, "--at", "0.5,x"],
        "--at: item 2 `x` is not a finite number",
    );
    refused(&[job, "--at", "nan"], "--at: item 1");
    refused(&[job, "--levels", "1"], "--levels: 1 is outside 2 ..= 51");
    refused(&[job, "--levels", "5000"], "--levels");
    refused(&[job, "--order", "0"], "--order: 0 is outside 1 ..= 64");
}

#[test]
fn a_surface_is_measured_from_its_datum() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("m.json");
    let t = terrain();
    let (code, stdout, stderr) = run(&[
        "measure",
        s(&t),
        "--levels",
        "2",
        "--datum",
        "103",
        "--no-area",
        "-o",
        s(&out),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stdout, "");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(v["levels"], serde_json::json!([0.0, 1.0]));
    assert_eq!(v["datum"], 103.0);
    assert_eq!(v["tolerance"], 1e-9);
    assert!(v.get("area").is_none(), "--no-area: {v}");
    let plan = v["plan_area"][0].as_f64().unwrap();
    // The patch covers 500 m x 400 m.
    assert!((plan - 200_000.0).abs() < 1e-6, "{plan}");
    for key in ["volume_below", "volume_above", "plan_area_below"] {
        for f in ["upper", "primary", "lower"] {
            let levels = v[key][f].as_array().expect("a list per function");
            assert!(!levels.is_empty(), "{key}.{f}");
            for l in levels {
                let (min, max) = (l["min"].as_f64().unwrap(), l["max"].as_f64().unwrap());
                assert!(0.0 <= min && min <= max, "{key}.{f}: {l}");
                assert_eq!(l["exact"], true, "{key}.{f}: {l}");
                assert!(
                    l["gap"].as_f64().unwrap() <= 1e-9 * max.max(plan),
                    "{key}.{f}: {l}"
                );
            }
        }
        // The level 0 interval holds the level 1 one.
        let u = &v[key]["upper"];
        assert!(
            u[0]["min"].as_f64() <= u[1]["min"].as_f64()
                && u[1]["max"].as_f64() <= u[0]["max"].as_f64(),
            "{key}: {u}"
        );
    }
    let flooded = v["plan_area_below"]["upper"][0]["max"].as_f64().unwrap();
    assert!(0.0 < flooded && flooded < plan, "{flooded}");
}

#[test]
fn a_surface_area_at_one_level() {
    let (code, stdout, stderr) = run(&["measure", s(&terrain()), "--alpha", "1"]);
    assert_eq!(code, 0, "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let a = &v["area"]["upper"][0];
    let (min, max) = (a["min"].as_f64().unwrap(), a["max"].as_f64().unwrap());
    // At level 1 every height is its crisp value: one surface, a little
    // more than its plan.
    assert!(200_000.0 < min && (max - min) <= 1e-6 * max, "{a}");
}

#[test]
fn surface_flags_are_checked() {
    let t = terrain();
    let job = s(&t);
    refused(&[job, "--datum", "nan"], "--datum");
    refused(
        &[job, "--at", "0.5"],
        "--at: parameters are measured on curves; this job is a surface",
    );
    let e = example();
    refused(
        &[s(&e), "--datum", "1"],
        "--datum: this applies to surfaces; this job is a curve",
    );
}

#[test]
fn a_bad_job_names_its_place() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("bad.json");
    std::fs::write(&job, "{\"order\": 2, \"alhpa\": 1, \"points\": []}").unwrap();
    let (code, _, stderr) = run(&["measure", s(&job)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("bad.json:1:"), "{stderr}");
}

#[test]
fn the_output_may_not_be_the_job() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    std::fs::copy(example(), &job).unwrap();
    let before = std::fs::read(&job).unwrap();
    let (code, _, stderr) = run(&["measure", s(&job), "-o", s(&job)]);
    assert_ne!(code, 0);
    assert!(stderr.contains("--output"), "{stderr}");
    assert_eq!(std::fs::read(&job).unwrap(), before);
}

#[test]
fn the_levels_are_alpha_or_levels_or_the_job_s_alpha() {
    let job = example();
    let levels = |args: &[&str]| -> Vec<f64> {
        let mut all = vec!["measure", s(&job)];
        all.extend_from_slice(args);
        let (code, stdout, stderr) = run(&all);
        assert_eq!(code, 0, "{args:?}: {stderr}");
        let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        v["levels"]
            .as_array()
            .unwrap()
            .iter()
            .map(|a| a.as_f64().unwrap())
            .collect()
    };
    // The example's alpha is 0.8.
    assert_eq!(levels(&[]), [0.8]);
    assert_eq!(levels(&["--alpha", "0.5"]), [0.5]);
    assert_eq!(levels(&["--levels", "3"]), [0.0, 0.5, 1.0]);
    refused(
        &[s(&example()), "--alpha", "2"],
        "--alpha: alpha = 2 is outside [0, 1]",
    );
}

#[test]
fn negative_parameters_in_a_list_are_values() {
    // `--at -0.5,0.25`: a list that starts with a minus sign is a value;
    // -0.5 is outside the example's domain [0, 1] and named as such.
    refused(&[s(&example()), "--at", "-0.5,0.25"], "--at");
    let (code, _, stderr) = run(&["measure", s(&example()), "--at", "-0.5,0.25"]);
    assert_eq!(code, 2);
    assert!(!stderr.contains("unexpected argument"), "{stderr}");
}

#[test]
fn cut_and_fill_against_the_last_survey() {
    let dir = tempfile::tempdir().unwrap();
    let file = |name: &str| dir.path().join(name);
    let (out, alone, last) = (file("m.json"), file("a.json"), file("b.json"));
    let (new, old) = (resurvey(), terrain());
    let measured = |job: &Path, out: &Path, more: &[&str]| {
        let mut args = vec![
            "measure",
            s(job),
            "--levels",
            "3",
            "--no-area",
            "-o",
            s(out),
        ];
        args.extend(more);
        let (code, stdout, stderr) = run(&args);
        assert_eq!((code, stdout.as_str()), (0, ""), "{stderr}");
        serde_json::from_slice::<serde_json::Value>(&std::fs::read(out).unwrap()).unwrap()
    };
    let v = measured(&new, &out, &["--against", s(&old)]);
    let a = measured(&new, &alone, &[]);
    let b = measured(&old, &last, &[]);
    // The surface's own keys as without --against, and only cut and fill more.
    for key in [
        "levels",
        "datum",
        "tolerance",
        "plan_area",
        "volume_below",
        "volume_above",
    ] {
        assert_eq!(v[key], a[key], "{key}");
    }
    let keys = |x: &serde_json::Value| x.as_object().unwrap().keys().cloned().collect::<Vec<_>>();
    let mut more = keys(&a);
    more.extend(["cut".to_owned(), "fill".to_owned()]);
    more.sort();
    let mut got = keys(&v);
    got.sort();
    assert_eq!(got, more);
    // cut − fill = ∫∫ z₁ − ∫∫ z₂, the difference of the signed volumes
    // V_above − V_below, at the corner nets: (l₁, r₂) for the least,
    // (r₁, l₂) for the largest.
    let at = |x: &serde_json::Value, key: &str, f: &str, i: usize, end: &str| {
        x[key][f][i][end].as_f64().unwrap()
    };
    for f in ["upper", "primary"] {
        for i in 0..3 {
            let least = (at(&v, "volume_above", f, i, "min") - at(&v, "volume_below", f, i, "max"))
                - (at(&b, "volume_above", f, i, "max") - at(&b, "volume_below", f, i, "min"));
            let largest = (at(&v, "volume_above", f, i, "max")
                - at(&v, "volume_below", f, i, "min"))
                - (at(&b, "volume_above", f, i, "min") - at(&b, "volume_below", f, i, "max"));
            let (cut, fill) = (
                [at(&v, "cut", f, i, "min"), at(&v, "cut", f, i, "max")],
                [at(&v, "fill", f, i, "min"), at(&v, "fill", f, i, "max")],
            );
            // 1e-9 of the plan area times the heights (~116 m).
            let tolerance = 1e-9 * 200_000.0 * 120.0;
            assert!((cut[0] - fill[1] - least).abs() < tolerance, "{f} {i}");
            assert!((cut[1] - fill[0] - largest).abs() < tolerance, "{f} {i}");
        }
    }
    // At level 1 (crisp heights) one number each: the heap (up to 1.2 m
    // over part of the plan) and the pit (up to 2 m), each well below its
    // largest shift times the plan area.
    let crisp = |key: &str| {
        let l = &v[key]["upper"][2];
        assert_eq!(l["alpha"], 1.0);
        assert_eq!(l["exact"], true, "{key}: {l}");
        let (min, max) = (l["min"].as_f64().unwrap(), l["max"].as_f64().unwrap());
        assert!((max - min).abs() <= 1e-9 * max, "{key}: {l}");
        min
    };
    let (cut, fill) = (crisp("cut"), crisp("fill"));
    assert!(1_000.0 < cut && cut < 1.2 * 200_000.0 / 4.0, "{cut}");
    assert!(fill > cut && fill < 2.0 * 200_000.0 / 4.0, "{fill} {cut}");
    for key in ["cut", "fill"] {
        for f in ["upper", "primary", "lower"] {
            let levels = v[key][f].as_array().expect("a list per function");
            for (l, next) in levels.iter().zip(levels.iter().skip(1)) {
                // Nested: the level 0 interval holds the level 0.5 one.
                assert!(
                    l["min"].as_f64() <= next["min"].as_f64(),
                    "{key}.{f}: {l} {next}"
                );
                assert!(
                    next["max"].as_f64() <= l["max"].as_f64(),
                    "{key}.{f}: {l} {next}"
                );
                assert_eq!(l["exact"], true, "{key}.{f}: {l}");
            }
        }
        // The lower function reaches 0.6: levels 0 and 0.5 only.
        assert_eq!(v[key]["lower"].as_array().unwrap().len(), 2, "{key}");
    }
    // The same survey against itself: no cut and no fill at level 1.
    let (code, stdout, stderr) = run(&[
        "measure",
        s(&old),
        "--alpha",
        "1",
        "--no-area",
        "--against",
        s(&old),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let same: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    for key in ["cut", "fill"] {
        assert_eq!(same[key]["upper"][0]["max"], 0.0, "{key}: {same}");
    }
}

#[test]
fn against_a_curve_a_fuzzy_plan_or_no_overlap_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (new, old, curve) = (resurvey(), terrain(), example());
    refused(
        &[s(&new), "--against", s(&curve)],
        "paper-alg-1-1.json: not a surface job; cut and fill are measured between two surfaces",
    );
    refused(
        &[s(&curve), "--against", s(&old)],
        "--against: this applies to surfaces; this job is a curve",
    );
    refused(
        &["-", "--against", "-"],
        "--against: standard input is read once, and the job reads it already",
    );
    // The resurvey moved far away (no overlap), and with a fuzzy x.
    let mut job: serde_json::Value = serde_json::from_slice(&std::fs::read(&new).unwrap()).unwrap();
    let far = job.clone();
    let mut far = far;
    for row in far["points"].as_array_mut().unwrap() {
        for p in row.as_array_mut().unwrap() {
            let x = p["x"]["crisp"].as_f64().unwrap() + 1e6;
            p["x"]["crisp"] = x.into();
            for f in ["upper", "primary", "lower"] {
                p["x"][f] = serde_json::json!([x, x]);
            }
        }
    }
    let moved = dir.path().join("survey-2019.json");
    std::fs::write(&moved, serde_json::to_vec(&far).unwrap()).unwrap();
    refused(
        &[s(&old), "--against", s(&moved)],
        &format!(
            "--against {}: its plan cannot be compared with {}'s (the plans do not overlap); cut and fill need crisp x and y in both surfaces and plans that overlap",
            moved.display(),
            old.display()
        ),
    );
    for f in ["upper", "primary", "lower"] {
        job["points"][2][3]["x"][f] = serde_json::json!([199.0, 201.0]);
    }
    std::fs::write(&moved, serde_json::to_vec(&job).unwrap()).unwrap();
    refused(
        &[s(&old), "--against", s(&moved)],
        "(points[2][3].x of the second surface is fuzzy)",
    );
    // The output may not overwrite the second job.
    let copy = dir.path().join("old.json");
    std::fs::copy(&old, &copy).unwrap();
    let before = std::fs::read(&copy).unwrap();
    let (code, _, stderr) = run(&["measure", s(&new), "--against", s(&copy), "-o", s(&copy)]);
    assert_ne!(code, 0);
    assert!(stderr.contains("--output"), "{stderr}");
    assert_eq!(std::fs::read(&copy).unwrap(), before);
}
