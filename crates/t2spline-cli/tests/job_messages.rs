//! Every bad job held in `fixtures/bad-jobs/` (at least one per rule of
//! docs/jobs.md, and the problems of the text itself) gives the same
//! problem lines from every front end that reads a job: `t2spline validate`,
//! `t2spline run` and the I/O library's `read_job`, each line
//! `FILE:LINE:COLUMN: PLACE: RULE`. The lines are those held next to each
//! fixture (`NAME.expected`, the file named `FILE`), so that a change of
//! words is a change of the fixtures, reviewed. Python gives the same
//! places and rules for the same jobs, as files and as dicts
//! (`python/tests/test_job_messages.py`).

use std::path::{Path, PathBuf};
use std::process::Command;

fn fixtures() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/bad-jobs");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    assert!(files.len() >= 60, "{} bad jobs", files.len());
    files
}

/// The error lines of `t2spline SUB FILE`, which must fail as invalid input
/// (exit code 2), without the `t2spline: ` prefix.
fn cli(sub: &str, path: &Path) -> Vec<String> {
    let out = Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args([sub, path.to_str().unwrap()])
        .output()
        .unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{sub} {}: {stderr}",
        path.display()
    );
    assert!(out.stdout.is_empty(), "{sub} {}", path.display());
    stderr
        .lines()
        .map(|l| l.strip_prefix("t2spline: ").unwrap_or(l).to_owned())
        .collect()
}

#[test]
fn every_bad_job_gives_the_same_lines_from_the_cli_and_the_library() {
    for path in fixtures() {
        let name = path.display().to_string();
        let library = t2spline_io::read_job(&path).unwrap_err().lines();
        assert!(!library.is_empty(), "{name}");
        assert_eq!(cli("validate", &path), library, "{name}");
        assert_eq!(cli("run", &path), library, "{name}");
        // Every line is placed in the file.
        for line in &library {
            let rest = line
                .strip_prefix(&format!("{name}:"))
                .unwrap_or_else(|| panic!("{line}"));
            let mut parts = rest.splitn(3, ':');
            let digits = |s: Option<&str>| {
                s.is_some_and(|s| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()))
            };
            assert!(digits(parts.next()) && digits(parts.next()), "{line}");
        }
        let expected = path.with_extension("expected");
        let want = std::fs::read_to_string(&expected)
            .unwrap_or_else(|e| panic!("{}: {e}", expected.display()));
        let got: Vec<String> = library
            .iter()
            .map(|l| l.replacen(&name, "FILE", 1))
            .collect();
        assert_eq!(got, want.lines().collect::<Vec<_>>(), "{name}");
    }
}

#[test]
fn a_job_that_is_json_but_for_nan_and_infinity_names_each_word_by_its_place() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/bad-jobs/non-finite-words.json");
    let rules: Vec<String> = cli("validate", &path)
        .iter()
        .map(|l| l.splitn(4, ": ").skip(1).collect::<Vec<_>>().join(": "))
        .collect();
    assert_eq!(
        rules,
        [
            "alpha: -inf is not a finite number (NaN and infinity are refused)",
            "points[1].x.crisp: NaN is not a finite number (NaN and infinity are refused)",
            "weights[1]: inf is not a finite number (NaN and infinity are refused)",
        ]
    );
}
