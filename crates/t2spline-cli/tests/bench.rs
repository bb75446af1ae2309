//! `t2spline bench`, run for real: one line per case in the documented format,
//! a job's curve, and bad options (exit code 2, one line naming the option).

use std::path::{Path, PathBuf};

use assert_cmd::Command;

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

/// Runs `t2spline bench args…` and returns (exit code, stdout, stderr).
fn bench(args: &[&str]) -> (i32, String, String) {
    let out = Command::cargo_bin("t2spline")
        .expect("the binary is built for the tests")
        .arg("bench")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().expect("exited, not killed"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// Checks `bench <case> points=<N> threads=<T> seconds=<s> points_per_second=<N/s>`.
fn check_line(line: &str, case: &str, points: u64, threads: u64) {
    let f: Vec<&str> = line.split(' ').collect();
    assert_eq!(f.len(), 6, "{line}");
    assert_eq!(
        f[..4],
        [
            "bench",
            case,
            &format!("points={points}"),
            &format!("threads={threads}")
        ]
    );
    let seconds: f64 = f[4].strip_prefix("seconds=").unwrap().parse().unwrap();
    let rate: f64 = f[5]
        .strip_prefix("points_per_second=")
        .unwrap()
        .parse()
        .unwrap();
    assert!(seconds > 0.0, "{line}");
    // Seconds are printed in full, the rate to five digits.
    assert!(
        (rate * seconds / points as f64 - 1.0).abs() < 1e-3,
        "{line}"
    );
}

#[test]
fn all_cases_print_one_line_each() {
    let (code, out, err) = bench(&["--points", "2000", "--threads", "1"]);
    assert_eq!((code, err.as_str()), (0, ""));
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 5, "{out}");
    for (line, case) in lines.iter().zip(["crisp", "fuzzy", "sweep"]) {
        check_line(line, case, 2000, 1);
    }
    // Surfaces on the square grid nearest 2000 points: 45 × 45.
    for (line, case) in lines[3..].iter().zip(["surface", "surface-fuzzy"]) {
        check_line(line, case, 2025, 1);
    }
}

#[test]
fn one_case_on_a_job_curve_with_two_threads() {
    let job = example();
    let (code, out, err) = bench(&[
        "--case",
        "fuzzy",
        "--points",
        "5000",
        "--threads",
        "2",
        "--curve",
        job.to_str().unwrap(),
    ]);
    assert_eq!((code, err.as_str()), (0, ""));
    check_line(out.trim_end(), "fuzzy", 5000, 2);
}

#[test]
fn reuse_is_marked_on_the_line() {
    let (code, out, _) = bench(&[
        "--case",
        "crisp",
        "--points",
        "100",
        "--threads",
        "1",
        "--reuse",
    ]);
    assert_eq!(code, 0);
    assert!(out.trim_end().ends_with(" output=reused"), "{out}");
}

#[test]
fn compare_times_fresh_then_reused_and_prints_their_ratio() {
    let (code, out, err) = bench(&[
        "--case",
        "crisp",
        "--points",
        "1000",
        "--threads",
        "1",
        "--compare",
    ]);
    assert_eq!((code, err.as_str()), (0, ""));
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 3, "{out}");
    check_line(lines[0], "crisp", 1000, 1);
    assert!(!lines[0].ends_with("output=reused"), "{out}");
    assert!(lines[1].ends_with(" output=reused"), "{out}");
    let seconds = |line: &str| -> f64 {
        let field = line.split(' ').find_map(|f| f.strip_prefix("seconds="));
        field.unwrap().parse().unwrap()
    };
    let ratio: f64 = lines[2]
        .strip_prefix("ratio crisp fresh/reused=")
        .unwrap()
        .parse()
        .unwrap();
    let expected = seconds(lines[0]) / seconds(lines[1]);
    assert!((ratio - expected).abs() <= 1e-3 * expected + 5e-4, "{out}");
    // Both ways at once, or one: not `--reuse` with `--compare`.
    let (code, _, err) = bench(&["--case", "crisp", "--reuse", "--compare"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--compare"), "{err}");
}

#[test]
fn bad_options_are_one_line_errors() {
    for (args, message) in [
        (
            &["--threads", "0"][..],
            "t2spline: --threads: threads = 0: must be in 1 ..= 1024\n",
        ),
        (
            &["--points", "1"][..],
            "t2spline: --points: points = 1: at least 2 are needed\n",
        ),
    ] {
        let (code, out, err) = bench(args);
        assert_eq!(
            (code, out.as_str(), err.as_str()),
            (2, "", message),
            "{args:?}"
        );
    }
    let (code, _, err) = bench(&["--case", "wobbly"]);
    assert_eq!(code, 2);
    assert!(err.contains("wobbly"), "{err}");
    // A job that cannot be read is exit code 3 (README, "Exit codes").
    let (code, _, err) = bench(&["--curve", "does-not-exist.json"]);
    assert_eq!(code, 3);
    assert!(
        err.starts_with("t2spline: does-not-exist.json: cannot read"),
        "{err}"
    );
}
