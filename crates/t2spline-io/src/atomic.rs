//! Output files that are either complete or absent.
//!
//! Every output is written to a temporary file in its own folder (so that the
//! final rename stays on one file system and is atomic), flushed to disk, and
//! only then renamed over the target. A run that writes several files stages
//! all of them first and renames them only when every one is complete, so a
//! failure while writing (a full disk, a missing folder) leaves every existing
//! output as it was. Temporary files are removed on failure and when the
//! program is interrupted between staging and renaming they are left as
//! `.t2spline-*.tmp`, never under an output's name.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;

use crate::Error;

/// Writes `bytes` to `path` atomically: into a temporary file in the same folder,
/// flushed to disk, then renamed over `path`. If anything fails, `path` is left
/// as it was (absent, or with its old content) and the temporary file is removed.
/// A new file gets the usual permissions (`0666` less the umask); a replaced
/// one keeps its own.
///
/// # Errors
/// [`Error::Write`] naming `path`.
///
/// # Examples
/// ```
/// let dir = tempfile::tempdir()?;
/// let path = dir.path().join("out.json");
/// t2spline_io::write_atomic(&path, b"{}")?;
/// assert_eq!(std::fs::read(&path)?, b"{}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let mut staged = Staged::default();
    staged.add(path, |w| w.write_all(bytes))?;
    staged.commit()
}

/// Writes several files all or nothing, as far as the file system allows: every
/// file is first written in full to a temporary file beside its destination and
/// flushed; only when all of them succeeded are they renamed into place (see
/// [`Staged`]). A failure while writing (a missing folder, a full disk) leaves
/// every destination as it was.
///
/// # Errors
/// [`Error::Write`] naming the first file that could not be written.
pub fn write_all_atomic(files: &[(&Path, &[u8])]) -> Result<(), Error> {
    let mut staged = Staged::default();
    for &(path, bytes) in files {
        staged.add(path, |w| w.write_all(bytes))?;
    }
    staged.commit()
}

/// Several output files written all-or-nothing: [`Staged::add`] writes each one
/// completely into a temporary file beside its target, [`Staged::commit`]
/// renames them all into place. Dropping a `Staged` without committing removes
/// the temporary files and leaves every target untouched.
///
/// The renames of a commit are atomic one by one. Everything that would make
/// a rename fail is found while staging (a missing or unwritable folder, a
/// target that is a folder); should one fail nonetheless (the folder was
/// removed in between), the files renamed before it stay replaced.
///
/// # Examples
/// ```
/// # use t2spline_io::Staged;
/// use std::io::Write;
/// let dir = tempfile::tempdir()?;
/// let mut out = Staged::default();
/// out.add(&dir.path().join("a.csv"), |w| w.write_all(b"t\n0\n"))?;
/// // The second file fails: its folder does not exist. Nothing is written.
/// assert!(out.add(&dir.path().join("no/b.csv"), |w| w.write_all(b"t\n")).is_err());
/// drop(out);
/// assert_eq!(std::fs::read_dir(dir.path())?.count(), 0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Default)]
pub struct Staged {
    files: Vec<(PathBuf, NamedTempFile)>,
}

impl Staged {
    /// Writes one output into a temporary file beside `path` with `write`
    /// (through a buffer), and flushes it to disk.
    ///
    /// # Errors
    /// [`Error::Write`] naming `path` if the temporary file cannot be created or
    /// written; `path` is untouched.
    pub fn add(
        &mut self,
        path: &Path,
        write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
    ) -> Result<(), Error> {
        let failed = |e| write_error(path, e);
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let old = std::fs::metadata(path).ok();
        // Renaming onto a folder would fail only at commit, after other files
        // may have been renamed; refuse it now, while nothing has changed.
        if old.as_ref().is_some_and(std::fs::Metadata::is_dir) {
            return Err(failed(std::io::ErrorKind::IsADirectory.into()));
        }
        let old = old.filter(std::fs::Metadata::is_file);
        let mut builder = tempfile::Builder::new();
        builder.prefix(".t2spline-").suffix(".tmp");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            builder.permissions(std::fs::Permissions::from_mode(0o666));
        }
        let file = builder.tempfile_in(dir).map_err(failed)?;
        if let Some(old) = old {
            file.as_file()
                .set_permissions(old.permissions())
                .map_err(failed)?;
        }
        let mut w = BufWriter::new(file.as_file());
        write(&mut w).map_err(failed)?;
        w.flush().map_err(failed)?;
        drop(w);
        file.as_file().sync_all().map_err(failed)?;
        self.files.push((path.to_owned(), file));
        Ok(())
    }

    /// Renames every staged file into place, then flushes the folders so that
    /// the renames survive a crash.
    ///
    /// # Errors
    /// [`Error::Write`] naming the first file that could not be renamed.
    pub fn commit(self) -> Result<(), Error> {
        let mut dirs: Vec<PathBuf> = Vec::new();
        for (path, file) in self.files {
            file.persist(&path)
                .map_err(|e| write_error(&path, e.error))?;
            let dir = path
                .parent()
                .filter(|d| !d.as_os_str().is_empty())
                .unwrap_or(Path::new("."))
                .to_owned();
            if !dirs.contains(&dir) {
                dirs.push(dir);
            }
        }
        // Best effort: not every platform or file system can sync a folder.
        for dir in dirs {
            if let Ok(d) = File::open(&dir) {
                let _ = d.sync_all();
            }
        }
        Ok(())
    }
}

/// [`Error::Write`] for `path`. tempfile's errors end in
/// ` at path "<temporary file>"`; the user named `path`, which the message
/// carries, so only the reason is kept.
fn write_error(path: &Path, e: std::io::Error) -> Error {
    let text = e.to_string();
    let source = match text.rfind(" at path \"") {
        Some(i) => std::io::Error::new(e.kind(), &text[..i]),
        None => e,
    };
    Error::Write {
        path: path.to_owned(),
        source,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replaces_content_and_leaves_no_temporary_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.json");
        write_atomic(&path, b"old").unwrap();
        write_atomic(&path, b"new").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"new");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn a_missing_folder_is_an_error_naming_the_file_not_the_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/out.json");
        let e = write_atomic(&path, b"x").unwrap_err();
        let lines = e.lines().join("\n");
        assert!(lines.contains("no/such/out.json: cannot write"), "{lines}");
        assert!(lines.contains("No such file or directory"), "{lines}");
        assert!(
            !lines.contains(".t2spline-"),
            "names the temporary file: {lines}"
        );
    }

    #[test]
    fn a_failing_file_leaves_the_others_unwritten() {
        let dir = tempfile::tempdir().unwrap();
        let good = dir.path().join("good.csv");
        let bad = dir.path().join("missing/bad.json");
        let e = write_all_atomic(&[(&good, b"a"), (&bad, b"b")]).unwrap_err();
        assert!(e.to_string().contains("bad.json"), "{e}");
        assert!(!good.exists());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }

    #[test]
    fn a_failing_writer_leaves_the_old_file_and_no_temporary_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.json");
        write_atomic(&path, b"old").unwrap();
        let mut staged = Staged::default();
        let e = staged
            .add(&path, |w| {
                w.write_all(b"half")?;
                Err(std::io::Error::other("disk on fire"))
            })
            .unwrap_err();
        assert!(e.to_string().contains("out.json"), "{e}");
        drop(staged);
        assert_eq!(std::fs::read(&path).unwrap(), b"old");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[cfg(unix)]
    #[test]
    fn permissions_are_kept_or_the_usual_ones() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.json");
        write_atomic(&path, b"a").unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
        // A new output has the mode of any new file (0666 less the umask), not
        // the 0600 of a temporary file.
        let plain = dir.path().join("plain");
        std::fs::write(&plain, b"a").unwrap();
        assert_eq!(mode(&path), mode(&plain));
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_atomic(&path, b"b").unwrap();
        assert_eq!(mode(&path), 0o640);
    }
}
