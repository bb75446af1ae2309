//! Reading the job and writing results: files atomically, standard streams
//! with a closed pipe treated as success.

use std::io::{Read, Write};
use std::path::Path;

use anyhow::Context;
use t2spline_io::{write_atomic, Job};

/// Whether the path names a standard stream.
pub fn is_stdio(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// How messages name the job file: as given, or `<stdin>` for `-`.
pub fn job_name(path: &Path) -> String {
    if is_stdio(path) {
        "<stdin>".to_owned()
    } else {
        path.display().to_string()
    }
}

/// Reads and validates the job at `path`, or from standard input for `-`.
pub fn read_job(path: &Path) -> anyhow::Result<Job> {
    if is_stdio(path) {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .context("standard input: cannot read")?;
        Ok(Job::parse(&text, &job_name(path))?)
    } else {
        Ok(Job::read(path)?)
    }
}

/// Writes `bytes` to `path` atomically, or to standard output when `path` is
/// `None` or `-`.
pub fn write(path: Option<&Path>, bytes: &[u8]) -> anyhow::Result<()> {
    match path {
        Some(p) if !is_stdio(p) => Ok(write_atomic(p, bytes)?),
        _ => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes)?;
            out.flush()?;
            Ok(())
        }
    }
}

/// Whether the error is a write to a pipe whose reader has gone (`t2spline run
/// job.json | head`), which ends the program quietly with success.
pub fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}
