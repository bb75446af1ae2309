//! The one rule of every command that writes files: no output is an input
//! (by its name, a symbolic link or an absolute path), no two outputs of one
//! run are one file, and no output lies inside a folder another output
//! writes. Each is refused with exit 2 before anything is written.
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn readings() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/beach-readings.csv")
}

fn run_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("the binary runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

/// Every file under `dir` with its bytes, sorted by path.
fn tree(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_owned()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            let meta = std::fs::symlink_metadata(&path).unwrap();
            if meta.is_dir() {
                stack.push(path);
            } else if meta.is_symlink() {
                out.push((
                    path.clone(),
                    std::fs::read_link(&path)
                        .unwrap()
                        .into_os_string()
                        .into_encoded_bytes(),
                ));
            } else {
                out.push((path.clone(), std::fs::read(&path).unwrap()));
            }
        }
    }
    out.sort();
    out
}

/// Runs each case in `dir` and asserts exit 2 naming `message`, with the
/// folder exactly as it was.
fn refused(dir: &Path, cases: &[(Vec<&str>, &str)]) {
    for (args, message) in cases {
        let before = tree(dir);
        let o = run_in(dir, args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(message), "{args:?}: {}", stderr(&o));
        assert_eq!(tree(dir), before, "{args:?} changed the folder");
    }
}

#[test]
fn export_never_overwrites_its_input() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(example(), d.join("job.json")).unwrap();
    std::fs::copy(example(), d.join("job.step")).unwrap();
    std::os::unix::fs::symlink("job.json", d.join("link.dxf")).unwrap();
    std::fs::create_dir(d.join("sub")).unwrap();
    let absolute = d.join("job.json");
    refused(
        d,
        &[
            (
                vec!["export", "job.json", "-o", "job.json", "--format", "obj"],
                "--output: job.json is the input file job.json",
            ),
            (
                vec!["export", "job.json", "-o", "link.dxf"],
                "is the input file",
            ),
            (
                vec!["export", "job.step", "-o", "job.step"],
                "is the input file",
            ),
            (
                vec!["export", "job.json", "-o", s(&absolute), "--format", "dxf"],
                "is the input file",
            ),
            (
                vec![
                    "export",
                    "./job.json",
                    "-o",
                    "sub/../job.json",
                    "--format",
                    "obj",
                ],
                "is the input file",
            ),
        ],
    );
    // A new name is written.
    let o = run_in(d, &["export", "job.json", "-o", "out.obj"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn fuzzify_never_overwrites_its_readings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(readings(), d.join("r.csv")).unwrap();
    std::os::unix::fs::symlink("r.csv", d.join("link.json")).unwrap();
    let absolute = d.join("r.csv");
    refused(
        d,
        &[
            (
                vec!["fuzzify", "r.csv", "-o", "r.csv"],
                "--output: r.csv is the input file r.csv",
            ),
            (
                vec!["fuzzify", "r.csv", "-o", "link.json"],
                "is the input file",
            ),
            (
                vec!["fuzzify", "r.csv", "-o", s(&absolute)],
                "is the input file",
            ),
            (
                vec!["fuzzify", s(&absolute), "-o", "r.csv"],
                "is the input file",
            ),
        ],
    );
    let o = run_in(d, &["fuzzify", "r.csv", "-o", "data.json"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn two_outputs_of_one_run_never_share_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(example(), d.join("J.json")).unwrap();
    std::fs::create_dir(d.join("out")).unwrap();
    std::os::unix::fs::symlink("same.json", d.join("alias.json")).unwrap();
    refused(
        d,
        &[
            (
                vec!["run", "J.json", "-o", "same.json", "--parquet", "same.json"],
                "--parquet: same.json is also the output of --output (same.json)",
            ),
            (
                vec![
                    "run",
                    "J.json",
                    "-o",
                    "alias.json",
                    "--parquet",
                    "same.json",
                ],
                "is also the output of --output",
            ),
            (
                vec![
                    "run",
                    "J.json",
                    "-o",
                    "out/r.json",
                    "--parquet",
                    "out/r.json",
                    "--csv",
                    "out",
                ],
                "--csv: out holds out/r.json, the output of --output",
            ),
            (
                // Refused by its name already: run -o writes JSON.
                vec!["run", "J.json", "-o", "cc/stage1-layers.csv", "--csv", "cc"],
                "--output: `cc/stage1-layers.csv` ends in .csv, but run -o writes the result as JSON",
            ),
            (
                vec![
                    "run",
                    "J.json",
                    "--csv",
                    "out",
                    "--parquet",
                    "out/r.parquet",
                ],
                "--parquet: out/r.parquet lies inside out, the output of --csv",
            ),
            (
                vec!["run", "J.json", "-o", "r.json", "--csv", "r.json/csv"],
                "lies inside r.json, the output of --output",
            ),
        ],
    );
    // A device takes several outputs: it is written through, never replaced.
    let o = run_in(
        d,
        &["run", "J.json", "-o", "/dev/null", "--parquet", "/dev/null"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    // Side by side, every output is written.
    let o = run_in(
        d,
        &[
            "run",
            "J.json",
            "-o",
            "out/r.json",
            "--parquet",
            "out/r.parquet",
            "--csv",
            "csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(d.join("out/r.json").is_file() && d.join("out/r.parquet").is_file());
}

#[test]
fn plot_and_report_never_overwrite_their_job() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Jobs named like the files the commands write into their folder.
    std::fs::copy(example(), d.join("report.html")).unwrap();
    let o = run_in(d, &["plot", "report.html", "-o", "figs", "--format", "svg"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let figure = String::from_utf8(o.stdout)
        .unwrap()
        .lines()
        .next()
        .unwrap()
        .to_owned();
    let name = Path::new(&figure)
        .file_name()
        .unwrap()
        .to_str()
        .unwrap()
        .to_owned();
    std::fs::copy(example(), d.join(&name)).unwrap();
    refused(
        d,
        &[
            (
                vec!["report", "report.html", "-o", "."],
                "--output: ./report.html is the input file report.html",
            ),
            (
                vec!["plot", &name, "-o", ".", "--format", "svg"],
                "is the input file",
            ),
        ],
    );
}

#[test]
fn many_jobs_never_write_one_file_twice() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir(d.join("jobs")).unwrap();
    std::fs::copy(example(), d.join("jobs/a.json")).unwrap();
    // Its CSV folder would be `out/a.json`, the result file of job `a`.
    std::fs::copy(example(), d.join("jobs/a.json.json")).unwrap();
    refused(
        d,
        &[(
            vec!["run", "--jobs", "jobs", "-o", "out", "--csv", "out"],
            "--csv: out/a.json is also the output of --output (out/a.json)",
        )],
    );
    // Results, CSV folders and Parquet files side by side in one folder.
    std::fs::remove_file(d.join("jobs/a.json.json")).unwrap();
    std::fs::copy(example(), d.join("jobs/b.json")).unwrap();
    let o = run_in(
        d,
        &[
            "run",
            "--jobs",
            "jobs",
            "-o",
            "out",
            "--csv",
            "out",
            "--parquet",
            "out",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(d.join("out/a.json").is_file() && d.join("out/b/stage1-layers.csv").is_file());
}
