//! `t2spline run a.json b.json … -o DIR` and `--jobs DIR`: one result per
//! job, the same bytes as a run of each job alone, past bad jobs (each
//! reported with its file, line and column), a summary table, and the exit
//! code of the worst failure.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn spiral() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/spiral-3d.json")
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A folder with `a.json` (the example), `b.json` (a misspelt key on line
/// 3) and `c.json` (a 3-D job).
fn jobs() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(example(), dir.path().join("a.json")).unwrap();
    std::fs::write(
        dir.path().join("b.json"),
        "{\n  \"order\": 2,\n  \"alhpa\": 0.5\n}\n",
    )
    .unwrap();
    std::fs::copy(spiral(), dir.path().join("c.json")).unwrap();
    std::fs::write(dir.path().join("notes.txt"), "not a job").unwrap();
    dir
}

/// What `run JOB args…` writes on its own: the JSON, and the CSV files.
fn alone(job: &Path, args: &[&str]) -> (Vec<u8>, Vec<(String, Vec<u8>)>) {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("csv");
    let mut all = vec!["run", s(job), "--csv", s(&csv)];
    all.extend(args);
    let o = run(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    (o.stdout, files(&csv))
}

fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut f: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            (
                e.file_name().to_string_lossy().into_owned(),
                std::fs::read(e.path()).unwrap(),
            )
        })
        .collect();
    f.sort();
    f
}

#[test]
fn every_good_job_is_written_and_every_bad_one_reported() {
    let input = jobs();
    let out = tempfile::tempdir().unwrap();
    let o_dir = out.path().join("results");
    let [a, b, c] = ["a", "b", "c"].map(|n| input.path().join(format!("{n}.json")));
    let o = run(&[
        "run",
        s(&a),
        s(&b),
        s(&c),
        "-o",
        s(&o_dir),
        "--csv",
        s(&o_dir),
        "--parquet",
        s(&o_dir),
        "--samples",
        "33",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains(&format!("t2spline: {}:3:3: alhpa", s(&b))),
        "the bad job with its line and column: {err}"
    );
    assert!(
        err.ends_with(&format!(
            "t2spline: 1 of 3 jobs failed, the others were written (see {})\n",
            s(&o_dir.join("summary.csv"))
        )),
        "{err}"
    );
    for (name, job) in [("a", &a), ("c", &c)] {
        let (json, csv) = alone(job, &["--samples", "33"]);
        assert_eq!(
            std::fs::read(o_dir.join(format!("{name}.json"))).unwrap(),
            json,
            "{name}"
        );
        assert_eq!(files(&o_dir.join(name)), csv, "{name}");
        let parquet = std::fs::read(o_dir.join(format!("{name}.parquet"))).unwrap();
        assert!(parquet.starts_with(b"PAR1") && parquet.ends_with(b"PAR1"));
    }
    assert!(!o_dir.join("b.json").exists() && !o_dir.join("b").exists());
    let summary = std::fs::read_to_string(o_dir.join("summary.csv")).unwrap();
    let lines: Vec<&str> = summary.lines().collect();
    assert_eq!(
        lines[0],
        "name,file,status,type_reduction,regime,alpha,h,error_max,error_max_at,error_max_at_v,error_rms,description,message"
    );
    assert!(
        lines[1].starts_with(&format!("a,{},ok,paper,alpha > h,0.8,0.6,0.0224", s(&a))),
        "{}",
        lines[1]
    );
    assert!(
        lines[2].starts_with(&format!("b,{},invalid,,,,,,,,,,", s(&b))),
        "{}",
        lines[2]
    );
    assert!(lines[2].contains(":3:3: alhpa"), "{}", lines[2]);
    assert!(
        lines[3].starts_with(&format!("c,{},ok,", s(&c))),
        "{}",
        lines[3]
    );
    assert_eq!(lines.len(), 4);
    assert!(std::fs::read(o_dir.join("summary.parquet"))
        .unwrap()
        .starts_with(b"PAR1"));
}

/// Runs the jobs of `folder` into a new folder, which it returns with the
/// names of the files there, sorted.
fn run_folder(folder: &Path) -> (tempfile::TempDir, Vec<String>) {
    let out = tempfile::tempdir().unwrap();
    let o = run(&["run", "--jobs", s(folder), "-o", s(out.path())]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut names: Vec<String> = std::fs::read_dir(out.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    (out, names)
}

#[test]
fn a_folder_of_jobs_runs_in_name_order() {
    let input = jobs();
    std::fs::remove_file(input.path().join("b.json")).unwrap();
    let (out, names) = run_folder(input.path());
    assert_eq!(names, ["a.json", "c.json", "summary.csv"]);
    let (json, _) = alone(&input.path().join("a.json"), &[]);
    assert_eq!(std::fs::read(out.path().join("a.json")).unwrap(), json);
}

/// The jobs of a folder are its `*.json` files, links to files among them;
/// a folder or a FIFO named `*.json` and files of other names are not jobs.
#[cfg(unix)]
#[test]
fn a_folder_of_jobs_follows_links_and_skips_what_is_not_a_file() {
    let input = jobs();
    std::fs::remove_file(input.path().join("b.json")).unwrap();
    let elsewhere = tempfile::tempdir().unwrap();
    std::fs::copy(input.path().join("a.json"), elsewhere.path().join("x.json")).unwrap();
    std::os::unix::fs::symlink(
        elsewhere.path().join("x.json"),
        input.path().join("linked.json"),
    )
    .unwrap();
    std::fs::create_dir(input.path().join("folder.json")).unwrap();
    std::fs::write(input.path().join("notes.txt"), "not a job").unwrap();
    let fifo = input.path().join("pipe.json");
    assert!(std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let (out, names) = run_folder(input.path());
    assert_eq!(names, ["a.json", "c.json", "linked.json", "summary.csv"]);
    assert_eq!(
        std::fs::read(out.path().join("linked.json")).unwrap(),
        std::fs::read(out.path().join("a.json")).unwrap()
    );
}

/// A link named `*.json` that leads nowhere is a job that cannot be read,
/// reported by its name, not skipped without a word.
#[cfg(unix)]
#[test]
fn a_dangling_link_in_a_folder_of_jobs_is_reported() {
    let input = jobs();
    std::fs::remove_file(input.path().join("b.json")).unwrap();
    std::os::unix::fs::symlink("gone.json", input.path().join("dangling.json")).unwrap();
    let out = tempfile::tempdir().unwrap();
    let o = run(&["run", "--jobs", s(input.path()), "-o", s(out.path())]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("dangling.json: cannot read"),
        "{}",
        stderr(&o)
    );
    assert!(
        stderr(&o).contains("1 of 3 jobs failed, the others were written"),
        "{}",
        stderr(&o)
    );
    let summary = std::fs::read_to_string(out.path().join("summary.csv")).unwrap();
    assert!(summary.contains("dangling,"), "{summary}");
    assert!(out.path().join("a.json").is_file());
}

#[test]
fn when_every_job_fails_no_result_is_said_to_be_written() {
    let input = jobs();
    std::fs::remove_file(input.path().join("a.json")).unwrap();
    std::fs::remove_file(input.path().join("c.json")).unwrap();
    std::fs::write(input.path().join("d.json"), "{}").unwrap();
    let out = tempfile::tempdir().unwrap();
    let o = run(&["run", "--jobs", s(input.path()), "-o", s(out.path())]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let last = stderr(&o).lines().last().unwrap().to_owned();
    assert!(
        last.starts_with("t2spline: 2 of 2 jobs failed, no job's results were written (see "),
        "{last}"
    );
    assert!(
        !stderr(&o).contains("the others were written"),
        "{}",
        stderr(&o)
    );
}

/// Control characters in a job's name reach no terminal: each line names the
/// job once, escaped as every other message escapes names.
#[cfg(unix)]
#[test]
fn hostile_job_names_are_printed_escaped_once() {
    let input = tempfile::tempdir().unwrap();
    let red = input.path().join("\u{1b}[31mred.json");
    std::fs::write(&red, "{\n  \"order\": 2,\n  \"alhpa\": 0.5\n}\n").unwrap();
    let blue = input.path().join("\u{1b}[34mblue.json");
    std::fs::copy(example(), &blue).unwrap();
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "run",
        "--jobs",
        s(input.path()),
        "-o",
        s(out.path()),
        "--type-reduction",
        "centroid",
        "--alpha",
        "0.5",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let text = stderr(&o);
    assert!(!text.contains('\u{1b}'), "{text:?}");
    let escaped = format!("{}/\\u001b[31mred.json", input.path().display());
    for line in text.lines().filter(|l| l.contains("red.json")) {
        assert!(line.starts_with(&format!("t2spline: {escaped}:")), "{line}");
        assert_eq!(line.matches("red.json").count(), 1, "{line}");
    }
    assert!(
        text.contains(&format!("{escaped}:3:3: alhpa: unknown key")),
        "{text}"
    );
    // The note on an alpha the reduction does not use names the job escaped.
    assert!(
        text.contains("\\u001b[34mblue.json: note: type reduction centroid"),
        "{text}"
    );
    // Outputs that are inputs are named escaped too.
    let o = run(&["run", "--jobs", s(input.path()), "-o", s(input.path())]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("is the input file"), "{}", stderr(&o));
    assert!(!stderr(&o).contains('\u{1b}'), "{:?}", stderr(&o));
}

#[test]
fn the_exit_code_is_the_worst_failure() {
    let input = jobs();
    let out = tempfile::tempdir().unwrap();
    let missing = input.path().join("missing.json");
    let o = run(&[
        "run",
        "--jobs",
        s(input.path()),
        s(&missing),
        "-o",
        s(out.path()),
    ]);
    // An invalid job (2) and an unreadable one (3): 3.
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("missing.json: cannot read"),
        "{}",
        stderr(&o)
    );
    assert!(stderr(&o).contains("2 of 4 jobs failed"), "{}", stderr(&o));
    let summary = std::fs::read_to_string(out.path().join("summary.csv")).unwrap();
    assert!(summary.contains(",unreadable,"), "{summary}");
}

#[test]
fn usage_errors_come_before_any_job_runs() {
    let input = jobs();
    let a = input.path().join("a.json");
    let c = input.path().join("c.json");
    let other = tempfile::tempdir().unwrap();
    let a2 = other.path().join("a.json");
    std::fs::copy(example(), &a2).unwrap();
    let original = std::fs::read(&a).unwrap();
    let cases: [(Vec<&str>, &str); 4] = [
        (vec!["run", s(&a), s(&c)], "give a folder for them, -o DIR"),
        (
            vec!["run", s(&a), s(&a2), "-o", s(other.path())],
            "would both write a.json",
        ),
        (
            vec!["run", s(&a), "-", "-o", s(other.path())],
            "standard input",
        ),
        // The outputs of a folder of jobs written into that folder.
        (
            vec!["run", "--jobs", s(input.path()), "-o", s(input.path())],
            "is the input file",
        ),
    ];
    for (args, message) in cases {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(message), "{args:?}: {}", stderr(&o));
    }
    assert_eq!(std::fs::read(&a).unwrap(), original);
}
