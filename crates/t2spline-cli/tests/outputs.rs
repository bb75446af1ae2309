//! Outputs that are not plain new files: devices and FIFOs written through,
//! symbolic links followed, hard links refused, inputs never overwritten, a
//! reused CSV folder, a closed standard output (and one on `/dev/null`,
//! which is open), and temporary files removed
//! when the program is stopped by a signal.
#![cfg(unix)]

use std::os::unix::fs::FileTypeExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_t2spline"))
}

fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("the binary runs")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The result of the example on standard output: what every output must hold.
fn expected() -> Vec<u8> {
    let o = run(&["run", s(&example())]);
    assert!(o.status.success(), "{}", stderr(&o));
    o.stdout
}

/// The names in a folder, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut n: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    n.sort();
    n
}

#[test]
fn a_fifo_gets_the_result_and_stays_a_fifo() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    let o = run(&["run", s(&example()), "-o", s(&fifo)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(reader.join().unwrap(), expected());
    let kind = std::fs::symlink_metadata(&fifo).unwrap().file_type();
    assert!(kind.is_fifo(), "{kind:?}");
    assert_eq!(names(dir.path()), ["pipe"], "no file left beside it");
}

#[test]
fn a_character_device_stays_a_device() {
    // A device node of our own (the same as /dev/null), so that a failure
    // of this test cannot replace the system's /dev/null.
    let dir = tempfile::tempdir().unwrap();
    let null = dir.path().join("null");
    let made = Command::new("mknod")
        .args([s(&null), "c", "1", "3"])
        .stderr(Stdio::null())
        .status();
    if !made.is_ok_and(|m| m.success()) {
        eprintln!("SKIPPED: mknod needs root");
        return;
    }
    let csv = dir.path().join("csv");
    let o = run(&["run", s(&example()), "-o", s(&null), "--csv", s(&csv)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let kind = std::fs::symlink_metadata(&null).unwrap().file_type();
    assert!(kind.is_char_device(), "{kind:?}");
    assert_eq!(names(dir.path()), ["csv", "null"]);
}

#[test]
fn a_symbolic_link_is_followed_and_kept() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.json");
    std::fs::write(&real, "old").unwrap();
    let link = dir.path().join("link.json");
    std::os::unix::fs::symlink("real.json", &link).unwrap();
    let o = run(&["run", s(&example()), "-o", s(&link)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert_eq!(std::fs::read(&real).unwrap(), expected());
    assert_eq!(names(dir.path()), ["link.json", "real.json"]);
}

#[test]
fn a_hard_linked_output_is_refused_with_exit_4() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.json");
    std::fs::write(&a, "old").unwrap();
    std::fs::hard_link(&a, dir.path().join("b.json")).unwrap();
    let o = run(&["run", s(&example()), "-o", s(&a)]);
    assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("a.json: cannot write: the file has 2 hard links"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read(dir.path().join("b.json")).unwrap(), b"old");
    assert_eq!(names(dir.path()), ["a.json", "b.json"]);
}

#[test]
fn an_output_never_overwrites_its_input() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    std::fs::copy(example(), &job).unwrap();
    let original = std::fs::read(&job).unwrap();
    let link = dir.path().join("link.json");
    std::os::unix::fs::symlink("job.json", &link).unwrap();
    for args in [
        vec!["run", s(&job), "-o", s(&job)],
        vec!["run", s(&job), "-o", s(&link)],
        vec!["run", s(&link), "--parquet", s(&job)],
        vec!["fit", s(&job), "-o", s(&job)],
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("is the input file"),
            "{args:?}: {}",
            stderr(&o)
        );
        assert_eq!(std::fs::read(&job).unwrap(), original, "{args:?}");
    }
    // A job named like a CSV file in the CSV folder.
    let inside = dir.path().join("stage1-layers.csv");
    std::fs::copy(example(), &inside).unwrap();
    let o = run(&["run", s(&inside), "--csv", s(dir.path())]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

#[test]
fn a_reused_csv_folder_holds_this_runs_files_only() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("csv");
    std::fs::create_dir(&csv).unwrap();
    std::fs::write(csv.join("notes.txt"), "mine").unwrap();
    let with = run(&["run", s(&example()), "--derivatives", "2", "--csv", s(&csv)]);
    assert!(with.status.success(), "{}", stderr(&with));
    assert!(csv.join("derivatives.csv").exists());
    let without = run(&["run", s(&example()), "--csv", s(&csv)]);
    assert!(without.status.success(), "{}", stderr(&without));
    assert_eq!(
        names(&csv),
        [
            "notes.txt",
            "stage1-layers.csv",
            "stage2-alpha-cut.csv",
            "stage3-type-reduced.csv",
            "stage4-defuzzified.csv"
        ]
    );
}

/// Runs `t2spline args…` from a shell with standard output closed.
fn with_stdout_closed(args: &str) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("exec \"$0\" {args} >&-"))
        .arg(env!("CARGO_BIN_EXE_t2spline"))
        .output()
        .unwrap()
}

#[test]
fn a_closed_standard_output_is_exit_4() {
    let job = s(&example()).to_owned();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fit-measurements.json");
    for args in [
        format!("run {job}"),
        format!("validate {job}"),
        format!("fit -q {}", s(&data)),
    ] {
        let o = with_stdout_closed(&args);
        assert_eq!(o.status.code(), Some(4), "{args}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("<stdout>: cannot write: standard output is closed"),
            "{args}: {}",
            stderr(&o)
        );
    }
    // Standard output sent to /dev/null by the shell is written, not closed.
    let o = Command::new("sh")
        .arg("-c")
        .arg(format!("exec \"$0\" validate {job} >/dev/null"))
        .arg(env!("CARGO_BIN_EXE_t2spline"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// Runs `t2spline args…` from a shell with standard output redirected by
/// `redirect`.
fn with_stdout(redirect: &str, args: &str) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("exec \"$0\" {args} {redirect}"))
        .arg(env!("CARGO_BIN_EXE_t2spline"))
        .output()
        .unwrap()
}

/// `/dev/null` opened read-write on descriptor 1 (`1<>/dev/null`, and
/// Python's `subprocess.DEVNULL`) looks exactly like what Rust's runtime puts
/// in place of a closed one; it is open, and every command writes into it.
#[test]
fn a_standard_output_on_dev_null_is_open_however_it_was_opened() {
    let job = s(&example()).to_owned();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fit-measurements.json");
    let dir = tempfile::tempdir().unwrap();
    let (plots, report) = (dir.path().join("plots"), dir.path().join("report"));
    for args in [
        format!("run {job}"),
        format!("validate {job}"),
        format!("fit -q {}", s(&data)),
        format!("plot {job} -o {} --format svg", s(&plots)),
        format!("report {job} -o {}", s(&report)),
    ] {
        for redirect in ["1<>/dev/null", ">/dev/null"] {
            let o = with_stdout(redirect, &args);
            assert_eq!(
                o.status.code(),
                Some(0),
                "{args} {redirect}: {}",
                stderr(&o)
            );
            assert_eq!(stderr(&o), "", "{args} {redirect}");
        }
    }
    assert!(plots.join("stage1-fuzzy.svg").is_file());
    assert!(report.join("report.html").is_file());
}

/// The `.t2spline-*.tmp` files under `dir`.
fn temporaries(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    for entry in walk(dir) {
        let name = entry.file_name().unwrap().to_string_lossy().into_owned();
        if name.starts_with(".t2spline-") && name.ends_with(".tmp") {
            found.push(entry);
        }
    }
    found
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(walk(&p));
        } else {
            out.push(p);
        }
    }
    out
}

/// A result replacing an existing file is written under a temporary name;
/// Ctrl-C or `SIGTERM` while it is written removes that file and leaves the
/// old result as it was.
#[test]
fn a_signal_while_writing_removes_the_temporary_files() {
    use std::os::unix::process::ExitStatusExt;
    for (signal, number) in [("TERM", 15), ("INT", 2)] {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out.json");
        std::fs::write(&out, "the last run's result").unwrap();
        // Large enough to be caught while writing, even in an optimised build.
        let mut child = bin()
            .args(["run", s(&example()), "--samples", "1000000"])
            .args(["-o", s(&out)])
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let start = std::time::Instant::now();
        while temporaries(dir.path()).is_empty() {
            assert!(child.try_wait().unwrap().is_none(), "ended before writing");
            assert!(
                start.elapsed().as_secs() < 300,
                "no temporary file appeared"
            );
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        let sent = Command::new("kill")
            .args([&format!("-{signal}"), &child.id().to_string()])
            .status()
            .unwrap();
        assert!(sent.success());
        let status = child.wait().unwrap();
        assert_eq!(status.signal(), Some(number), "{status:?}");
        assert_eq!(walk(dir.path()), std::slice::from_ref(&out), "SIG{signal}");
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            "the last run's result",
            "SIG{signal}"
        );
    }
}

/// On Linux a new output has no name until it is complete, so that even
/// `SIGKILL`, which no handler sees, leaves nothing behind.
#[cfg(target_os = "linux")]
#[test]
fn a_killed_run_leaves_no_file_behind() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let csv = dir.path().join("csv");
    let mut child = bin()
        .args(["run", s(&example()), "--samples", "1000000"])
        .args(["-o", s(&out), "--csv", s(&csv)])
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Writing has begun when the program holds a file open in the folder.
    let fds = PathBuf::from(format!("/proc/{}/fd", child.id()));
    let writing = || {
        std::fs::read_dir(&fds)
            .into_iter()
            .flatten()
            .flatten()
            .any(|fd| std::fs::read_link(fd.path()).is_ok_and(|to| to.starts_with(dir.path())))
    };
    let start = std::time::Instant::now();
    while !writing() {
        assert!(child.try_wait().unwrap().is_none(), "ended before writing");
        assert!(start.elapsed().as_secs() < 300, "no output was opened");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap();
    let status = child.wait().unwrap();
    assert_eq!(status.signal(), Some(9), "{status:?}");
    assert_eq!(walk(dir.path()), Vec::<PathBuf>::new());
}
