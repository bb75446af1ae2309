//! Reading jobs and data files (within the size limit, as UTF-8) and writing
//! results: files all or nothing, standard output last, a closed pipe treated
//! as success.

use std::io::Write;
use std::path::{Path, PathBuf};

use t2spline::job::Job;
use t2spline_io::job::{read_text, read_text_from};
use t2spline_io::{parse_job, write_all_atomic, Error};

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

/// A path as messages show it: control characters escaped
/// ([`t2spline_io::printable`]), as the I/O crate's messages show file names,
/// so that a hostile name cannot write to the terminal.
pub fn shown(path: &Path) -> String {
    t2spline_io::printable(&path.display().to_string())
}

/// A job that this command does not take (a curve where a surface is
/// needed, …), named by its file: `FILE: message`, exit code 2.
pub fn unsuited(path: &Path, message: &str) -> anyhow::Error {
    Error::Invalid {
        file: job_name(path),
        problems: vec![t2spline_io::Problem {
            line_column: None,
            message: message.to_owned(),
        }],
    }
    .into()
}

/// The extension of `path` in lower case (`OUT.SVG` → `svg`), if any.
pub fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// Refuses, naming `option`, an output `path` whose extension (in any case)
/// is one of `files`, where the command writes something else: `wanted`
/// says what it writes and how to get the file the name asks for. A folder
/// that exists already is taken as it is.
///
/// # Errors
/// [`crate::exit::OptionError`] naming the option, the name and the rule.
pub fn refuse_extension(
    option: &'static str,
    path: &Path,
    files: &[&str],
    wanted: &str,
) -> anyhow::Result<()> {
    match extension(path) {
        Some(e) if files.contains(&e.as_str()) && !path.is_dir() => Err(crate::exit::OptionError {
            option,
            message: format!("`{}` ends in .{e}, but {wanted}", shown(path)),
        }
        .into()),
        _ => Ok(()),
    }
}

/// The text at `path`, or of standard input for `-`, within the size limit and
/// as UTF-8.
pub fn read_input(path: &Path) -> Result<String, Error> {
    if is_stdio(path) {
        read_text_from(std::io::stdin().lock(), &job_name(path))
    } else {
        read_text(path)
    }
}

/// Reads and validates the job at `path`, or from standard input for `-`.
pub fn read_job(path: &Path) -> Result<Job, Error> {
    parse_job(&read_input(path)?, &job_name(path))
}

/// Says `line` on standard error as `t2spline COMMAND: LINE`. A closed or
/// gone standard error (`2>&-`, `2>&1 | head`) is no reason to stop: the
/// command goes on to write its outputs.
pub fn note(command: &str, line: impl std::fmt::Display) {
    let _ = writeln!(std::io::stderr().lock(), "t2spline {command}: {line}");
}

/// Writes to standard output with `write`; a failure is an [`Error::Write`]
/// naming `<stdout>` (a closed pipe among them, which `main` treats as
/// success), and so is a standard output that was closed when the program
/// started (`t2spline run job.json >&-`; not one sent to `/dev/null`).
pub fn to_stdout(write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) -> Result<(), Error> {
    let failed = |source| Error::Write {
        path: PathBuf::from("<stdout>"),
        source,
    };
    if stdout_was_closed() {
        return Err(failed(std::io::Error::other("standard output is closed")));
    }
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    write(&mut out).and_then(|()| out.flush()).map_err(failed)
}

/// Whether standard output was closed when the program started
/// (`t2spline run job.json >&-`). Rust's runtime opens `/dev/null` in place
/// of a closed descriptor 1 before `main`, exactly as a shell's `1<>/dev/null`
/// or Python's `stdout=subprocess.DEVNULL` open it (read-write), so the
/// descriptor is looked at earlier still: by a function that the loader runs
/// among the program's initialisers (`.init_array` on ELF systems,
/// `__mod_init_func` on Apple's), before Rust's runtime starts. Standard
/// output sent to `/dev/null` in any way is open, and written.
#[cfg(unix)]
fn stdout_was_closed() -> bool {
    at_start::STDOUT_CLOSED.load(std::sync::atomic::Ordering::Relaxed)
}

#[cfg(not(unix))]
fn stdout_was_closed() -> bool {
    false
}

#[cfg(unix)]
mod at_start {
    use std::sync::atomic::{AtomicBool, Ordering};

    /// Whether descriptor 1 was closed at start; false where the
    /// initialiser does not run (a target without either section).
    pub(super) static STDOUT_CLOSED: AtomicBool = AtomicBool::new(false);

    /// Records whether descriptor 1 is open: `F_GETFD` fails (`EBADF`) on a
    /// closed descriptor only. A plain system call and an atomic store: it
    /// needs nothing of the runtime that has not started yet, and cannot
    /// panic.
    extern "C" fn record() {
        let closed = rustix::io::fcntl_getfd(rustix::stdio::stdout()).is_err();
        STDOUT_CLOSED.store(closed, Ordering::Relaxed);
    }

    // The one `unsafe` item of the workspace (the lint is `deny`, not
    // `forbid`, in this crate for it): a pointer to `record` in the section
    // of initialisers, which the loader calls once before `main`. Sound
    // because `record` is a safe `extern "C" fn` taking no arguments (the
    // C runtime may pass `argc, argv, envp`, which the C calling convention
    // lets a function ignore), touches only an atomic and a system call, and
    // returns normally.
    #[allow(unsafe_code)]
    #[used]
    #[cfg_attr(
        any(target_os = "macos", target_os = "ios"),
        link_section = "__DATA,__mod_init_func"
    )]
    #[cfg_attr(
        not(any(target_os = "macos", target_os = "ios")),
        link_section = ".init_array"
    )]
    static RECORD: extern "C" fn() = record;
}

/// The folders a run creates for its outputs, so that a failed run can remove
/// them again.
#[derive(Debug, Default)]
pub struct NewFolders {
    created: Vec<PathBuf>,
}

impl NewFolders {
    /// Creates `dir` and any missing ancestors, remembering which were new.
    pub fn create(&mut self, dir: &Path) -> Result<(), Error> {
        let mut missing: Vec<PathBuf> = dir
            .ancestors()
            .filter(|a| !a.as_os_str().is_empty() && !a.exists())
            .map(Path::to_owned)
            .collect();
        std::fs::create_dir_all(dir).map_err(|source| Error::Write {
            path: dir.to_owned(),
            source,
        })?;
        missing.reverse();
        self.created.extend(missing);
        Ok(())
    }

    /// Removes the folders created, deepest first, as far as they are empty.
    pub fn remove(self) {
        for dir in self.created.iter().rev() {
            let _ = std::fs::remove_dir(dir);
        }
    }
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
        let mut folders = NewFolders::default();
        let files = self.write_files(&mut folders);
        if files.is_err() {
            // Only folders this run created, and only if still empty.
            folders.remove();
        }
        files?;
        if !self.stdout.is_empty() {
            to_stdout(|w| w.write_all(&self.stdout))?;
        }
        Ok(())
    }

    fn write_files(&self, folders: &mut NewFolders) -> Result<(), Error> {
        for dir in &self.dirs {
            folders.create(dir)?;
        }
        let files: Vec<(&Path, &[u8])> = self
            .files
            .iter()
            .map(|(p, b)| (p.as_path(), b.as_slice()))
            .collect();
        write_all_atomic(&files)
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
