//! Reading the job and writing results: files atomically, standard streams
//! with a closed pipe treated as success.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use anyhow::Context;
use t2spline_io::{write_all_atomic, Error, FitData, Job};

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
    Ok(read_job_text(path)?.0)
}

/// Reads and validates the job at `path` (or standard input for `-`), and
/// returns it with its text (the report shows it).
pub fn read_job_text(path: &Path) -> anyhow::Result<(Job, String)> {
    let text = if is_stdio(path) {
        read_stdin()?
    } else {
        std::fs::read_to_string(path).map_err(|source| Error::Read {
            path: path.to_owned(),
            source,
        })?
    };
    let job = Job::parse(&text, &job_name(path))?;
    Ok((job, text))
}

/// Reads and validates the data file at `path`, or from standard input for `-`.
pub fn read_data(path: &Path) -> anyhow::Result<FitData> {
    if is_stdio(path) {
        Ok(FitData::parse(&read_stdin()?, &job_name(path))?)
    } else {
        Ok(FitData::read(path)?)
    }
}

fn read_stdin() -> anyhow::Result<String> {
    let mut text = String::new();
    std::io::stdin()
        .read_to_string(&mut text)
        .context("standard input: cannot read")?;
    Ok(text)
}

/// Everything a command writes, gathered first and written at the end: the
/// files all or nothing ([`write_all_atomic`]), folders created only as needed
/// and removed again if the files could not be written, standard output last.
#[derive(Debug, Default)]
pub struct Outputs {
    dirs: Vec<PathBuf>,
    files: Vec<(PathBuf, Vec<u8>)>,
    stdout: Vec<u8>,
}

impl Outputs {
    /// `bytes` to the file `path`, or to standard output for `None` or `-`.
    pub fn to(&mut self, path: Option<&Path>, bytes: Vec<u8>) {
        match path {
            Some(p) if !is_stdio(p) => self.files.push((p.to_owned(), bytes)),
            _ => self.stdout.extend(bytes),
        }
    }

    /// A file inside `dir`, which is created if missing.
    pub fn in_dir(&mut self, dir: &Path, name: &str, bytes: Vec<u8>) {
        if !self.dirs.iter().any(|d| d == dir) {
            self.dirs.push(dir.to_owned());
        }
        self.files.push((dir.join(name), bytes));
    }

    /// Writes everything.
    pub fn commit(self) -> anyhow::Result<()> {
        let mut created = Vec::new();
        let result = self.write_files(&mut created);
        if result.is_err() {
            // Only folders this run created, and only if still empty.
            for dir in created.iter().rev() {
                let _ = std::fs::remove_dir(dir);
            }
        }
        result?;
        if !self.stdout.is_empty() {
            let mut out = std::io::stdout().lock();
            out.write_all(&self.stdout)?;
            out.flush()?;
        }
        Ok(())
    }

    fn write_files(&self, created: &mut Vec<PathBuf>) -> anyhow::Result<()> {
        for dir in &self.dirs {
            let mut missing: Vec<PathBuf> = dir
                .ancestors()
                .filter(|a| !a.as_os_str().is_empty() && !a.exists())
                .map(Path::to_owned)
                .collect();
            std::fs::create_dir_all(dir).map_err(|source| Error::Write {
                path: dir.clone(),
                source,
            })?;
            missing.reverse();
            created.extend(missing);
        }
        let files: Vec<(&Path, &[u8])> = self
            .files
            .iter()
            .map(|(p, b)| (p.as_path(), b.as_slice()))
            .collect();
        Ok(write_all_atomic(&files)?)
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
