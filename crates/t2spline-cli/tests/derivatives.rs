//! `t2spline run --derivatives K`: result keys, values against the library,
//! CSV, and bad values of K.

use assert_cmd::Command;
use serde_json::Value;

const EXAMPLE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../examples/paper-alg-1-1.json"
);

fn t2spline() -> Command {
    Command::cargo_bin("t2spline").expect("the binary is built")
}

fn run(args: &[&str]) -> Value {
    let out = t2spline()
        .arg("run")
        .arg(EXAMPLE)
        .args(args)
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON result")
}

fn points(v: &Value) -> Vec<Vec<f64>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| {
            p.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        })
        .collect()
}

#[test]
fn derivatives_and_arc_lengths_match_the_library() {
    let r = run(&["--derivatives", "3", "--samples", "7"]);
    let job = t2spline_io::read_job(std::path::Path::new(EXAMPLE)).unwrap();
    let t2spline::job::Model::Planar(curve) = &job.model else {
        panic!("the example is planar")
    };
    let crisp = curve.crisp_curve();
    let defuzzified = curve.solve(job.alpha.unwrap()).defuzzified_curve();
    let params: Vec<f64> = r["curves"]["params"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_f64().unwrap())
        .collect();
    assert_eq!(params.len(), 7);
    for (name, c) in [("crisp", &crisp), ("defuzzified", &defuzzified)] {
        let orders = r["curves"]["derivatives"][name].as_array().unwrap();
        assert_eq!(orders.len(), 3, "{name}: one list per order 1..3");
        for (k, order) in orders.iter().enumerate() {
            let got = points(order);
            assert_eq!(got.len(), params.len());
            for (t, p) in params.iter().zip(&got) {
                let expect = c.derivatives(*t, k + 1).unwrap()[k + 1];
                assert_eq!(
                    p.as_slice(),
                    expect.as_slice(),
                    "{name}, order {}, t = {t}",
                    k + 1
                );
            }
        }
        let length = r["curves"]["arc_length"][name].as_f64().unwrap();
        assert_eq!(length, c.arc_length());
        // The length exceeds the chord and every sampled polyline.
        let polyline: f64 = c
            .sample(&c.domain().uniform(10_001).unwrap())
            .unwrap()
            .windows(2)
            .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
            .sum();
        assert!(
            length >= polyline && length - polyline < 1e-6 * length,
            "{length} vs {polyline}"
        );
    }
}

#[test]
fn keys_are_absent_without_the_flag() {
    let r = run(&["--samples", "3"]);
    assert!(r["curves"].get("derivatives").is_none());
    assert!(r["curves"].get("arc_length").is_none());
}

#[test]
fn derivatives_go_to_their_own_csv_file() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("csv");
    t2spline()
        .arg("run")
        .arg(EXAMPLE)
        .args(["--samples", "4", "--derivatives", "2", "--csv"])
        .arg(&csv)
        .assert()
        .success();
    let text = std::fs::read_to_string(csv.join("derivatives.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "t,crisp_d1_x,crisp_d1_y,crisp_d2_x,crisp_d2_y,defuzzified_d1_x,defuzzified_d1_y,defuzzified_d2_x,defuzzified_d2_y"
    );
    assert_eq!(lines.count(), 4);
}

#[test]
fn bad_orders_are_one_line_errors_with_exit_code_2_and_no_output() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    for (k, samples, message) in [
        ("0", "101", "t2spline: --derivatives: 0: the highest derivative order must be at least 1\n"),
        ("-2", "101", "t2spline: --derivatives: -2: the highest derivative order must be at least 1\n"),
        ("17", "101", "t2spline: --derivatives: 17 is more than the highest order offered, 16\n"),
        (
            "3",
            "500000",
            "t2spline: --derivatives: 3 orders at 500000 samples make 1500000 derivative vectors per curve, more than the limit 1000000; lower the derivative order or the number of samples\n",
        ),
    ] {
        t2spline()
            .arg("run")
            .arg(EXAMPLE)
            .args(["--derivatives", k, "--samples", samples, "-o"])
            .arg(&out)
            .assert()
            .code(2)
            .stdout("")
            .stderr(message.to_owned());
        assert!(!out.exists(), "{k}: an output file was written");
    }
    t2spline()
        .arg("run")
        .arg(EXAMPLE)
        .args(["--derivatives", "two"])
        .assert()
        .code(2)
        .stderr(predicates::str::contains(
            "invalid value 'two' for '--derivatives <K>'",
        ));
}
