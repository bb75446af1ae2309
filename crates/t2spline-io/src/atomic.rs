//! Output files that are either complete or absent.
//!
//! Every output is written to a temporary file in its own folder (so that the
//! final rename stays on one file system and is atomic), flushed to disk, and
//! only then renamed over the target, or linked to its name where it is new
//! (a file without a name until then, on Linux: see `temporary.rs`). A run
//! that writes several files stages all of them first and renames them only
//! when every one is complete, so a failure while writing (a full disk, a
//! missing folder) leaves every existing output as it was. Temporary files are removed on failure, and on Ctrl-C
//! or `SIGTERM` by a front end that calls [`remove_temporary_files`](crate::remove_temporary_files).
//!
//! What a path names decides how it is written (see `target.rs`): a symbolic
//! link is followed and the file it names replaced (the link stays); a
//! device or FIFO is written through after the files are renamed (as
//! standard output is); a file with several hard links is refused.
//!
//! A file with several hard links is refused because both ways of writing it
//! are wrong: replacing it cuts the links, and writing in place changes every
//! name (a snapshot made of hard links among them) and is not atomic. A device
//! or FIFO is written through rather than replaced, since replacing
//! `/dev/null` with a regular file, as a rename does, breaks the system for
//! everyone. What could make a rename fail (a target that is a folder, a
//! missing or read-only folder) is found while staging.
//!
//! A flush to disk per file costs a disk round trip (about 9 ms here), more
//! than a small job, so a run of many jobs stages with
//! [`Staged::deferring_sync`] and flushes each file system once at the end
//! ([`sync_file_systems`](crate::sync_file_systems)): a program failure still
//! leaves nothing half written, a power failure during the run may leave the
//! last jobs' files incomplete. A committer thread doing group commits (flush,
//! then rename, in batches) was weighed: it keeps the crash guarantee at the
//! cost of a second thread and of results appearing late.

use std::fmt;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use crate::error::Error;
use crate::target::{resolve, Target};
use crate::temporary::{folder, Temporary};

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

/// A writer of one output, kept until the files are committed.
type Deferred<'a> = Box<dyn FnOnce(&mut (dyn Write + Send)) -> std::io::Result<()> + 'a>;

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
/// Outputs that are devices or FIFOs (`-o /dev/null`, a named pipe) are
/// written through, not replaced, and last, after the files are renamed, as
/// standard output is.
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
pub struct Staged<'a> {
    /// Target (the end of any links), the path as given, the temporary file.
    files: Vec<(PathBuf, PathBuf, Temporary)>,
    /// Devices and FIFOs: the path as given, the path written, the writer.
    streams: Vec<(PathBuf, PathBuf, Deferred<'a>)>,
    /// Files of an earlier run that this one does not write.
    stale: Vec<PathBuf>,
    /// Whether a commit flushes every file to disk before renaming it.
    durable: bool,
}

impl Default for Staged<'_> {
    fn default() -> Self {
        Staged {
            files: Vec::new(),
            streams: Vec::new(),
            stale: Vec::new(),
            durable: true,
        }
    }
}

impl fmt::Debug for Staged<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Staged")
            .field("files", &self.files)
            .field(
                "streams",
                &self.streams.iter().map(|s| &s.0).collect::<Vec<_>>(),
            )
            .field("stale", &self.stale)
            .field("durable", &self.durable)
            .finish()
    }
}

impl<'a> Staged<'a> {
    /// Outputs whose commit renames without flushing each file to disk
    /// first: for a front end that writes many outputs and flushes them all
    /// at once afterwards ([`sync_file_systems`](crate::sync_file_systems)).
    /// A failure of the program still leaves nothing half written; a power
    /// failure before the final flush may.
    #[must_use]
    pub fn deferring_sync() -> Self {
        Staged {
            durable: false,
            ..Staged::default()
        }
    }

    /// Writes one output into a temporary file beside `path` with `write`
    /// (through a buffer); a device or FIFO is written with it at
    /// [`Staged::commit`] instead. The writer is `Send` so that writers
    /// that need it (Parquet's) can take it.
    ///
    /// # Errors
    /// [`Error::Write`] naming `path` if the temporary file cannot be created or
    /// written, if `path` is a folder, or a file with several hard links;
    /// `path` is untouched.
    pub fn add(
        &mut self,
        path: &Path,
        write: impl FnOnce(&mut (dyn Write + Send)) -> std::io::Result<()> + 'a,
    ) -> Result<(), Error> {
        match resolve(path).map_err(|e| write_error(path, e))? {
            Target::Stream(stream) => {
                self.streams
                    .push((path.to_owned(), stream, Box::new(write)));
                Ok(())
            }
            Target::File {
                path: target,
                permissions,
            } => self.stage(path, target, permissions, write),
        }
    }

    /// Like [`Staged::add`], but `write` runs now even where `path` is a
    /// device or FIFO, and its value is returned: for an output written
    /// while the work that fills it is done (the one table of a run of many
    /// jobs). A file is written into its temporary file as by `add`; a
    /// device or FIFO is written into memory now and through at
    /// [`Staged::commit`], after the files, as `add` writes it.
    ///
    /// # Errors
    /// Those of [`Staged::add`].
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::Staged;
    /// use std::io::Write;
    /// let dir = tempfile::tempdir()?;
    /// let path = dir.path().join("rows.txt");
    /// let mut out = Staged::default();
    /// let rows = out.add_now(&path, |w| {
    ///     (1..=3).try_for_each(|i| writeln!(w, "{i}")).map(|()| 3)
    /// })?;
    /// assert_eq!(rows, 3);
    /// assert!(!path.exists(), "renamed into place at the commit only");
    /// out.commit()?;
    /// assert_eq!(std::fs::read_to_string(&path)?, "1\n2\n3\n");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn add_now<R>(
        &mut self,
        path: &Path,
        write: impl FnOnce(&mut (dyn Write + Send)) -> std::io::Result<R>,
    ) -> Result<R, Error> {
        match resolve(path).map_err(|e| write_error(path, e))? {
            Target::Stream(stream) => {
                let mut bytes = Vec::new();
                let value = write(&mut bytes).map_err(|e| write_error(path, e))?;
                let through = move |w: &mut (dyn Write + Send)| w.write_all(&bytes);
                self.streams
                    .push((path.to_owned(), stream, Box::new(through)));
                Ok(value)
            }
            Target::File {
                path: target,
                permissions,
            } => self.stage(path, target, permissions, write),
        }
    }

    /// Writes the temporary file of `target` (the file `shown` names) with
    /// `write`, through a buffer, and keeps it for the commit.
    fn stage<R>(
        &mut self,
        shown: &Path,
        target: PathBuf,
        permissions: Option<std::fs::Permissions>,
        write: impl FnOnce(&mut (dyn Write + Send)) -> std::io::Result<R>,
    ) -> Result<R, Error> {
        let failed = |e| write_error(shown, e);
        let file = Temporary::create(&target, permissions.is_some()).map_err(failed)?;
        if let Some(permissions) = permissions {
            file.file()
                .and_then(|f| f.set_permissions(permissions))
                .map_err(failed)?;
        }
        let mut w = BufWriter::new(file.file().map_err(failed)?);
        let value = write(&mut w).map_err(failed)?;
        w.flush().map_err(failed)?;
        drop(w);
        self.files.push((target, shown.to_owned(), file));
        Ok(value)
    }

    /// Removes `path` at [`Staged::commit`] if it exists and is a file: an
    /// output of an earlier run that this run does not write (a reused CSV
    /// folder's `derivatives.csv`), so that the folder holds this run's files
    /// only.
    pub fn remove_stale(&mut self, path: &Path) {
        self.stale.push(path.to_owned());
    }

    /// Flushes every staged file to disk (unless [`Staged::deferring_sync`]),
    /// renames each into place, flushes the folders so that the renames
    /// survive a crash, removes the stale files, and writes the devices and
    /// FIFOs.
    ///
    /// # Errors
    /// [`Error::Write`] naming the first file that could not be written,
    /// flushed or renamed, or removed.
    pub fn commit(self) -> Result<(), Error> {
        if self.durable {
            for (_, shown, file) in &self.files {
                file.file()
                    .and_then(|f| f.sync_all())
                    .map_err(|e| write_error(shown, e))?;
            }
        }
        let mut dirs: Vec<PathBuf> = Vec::new();
        for (target, shown, file) in self.files {
            file.persist(&target).map_err(|e| write_error(&shown, e))?;
            let dir = folder(&target).to_owned();
            if !dirs.contains(&dir) {
                dirs.push(dir);
            }
        }
        // Best effort: not every platform or file system can sync a folder.
        if self.durable {
            for dir in dirs {
                if let Ok(d) = File::open(&dir) {
                    let _ = d.sync_all();
                }
            }
        }
        for path in self.stale {
            if std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
                std::fs::remove_file(&path).map_err(|e| write_error(&path, e))?;
            }
        }
        for (shown, stream, write) in self.streams {
            let failed = |e| write_error(&shown, e);
            let file = std::fs::OpenOptions::new()
                .write(true)
                .open(&stream)
                .map_err(failed)?;
            let mut w = BufWriter::new(file);
            write(&mut w).and_then(|()| w.flush()).map_err(failed)?;
        }
        Ok(())
    }
}

/// Flushes the files at `paths` to disk, for outputs committed by a
/// [`Staged::deferring_sync`]: on Linux one `syncfs` per file system of their
/// folders (one flush for a thousand files, where one per file would cost a
/// disk round trip each), elsewhere each file in turn.
///
/// # Errors
/// [`Error::Write`] naming a path whose folder or file cannot be opened or
/// flushed.
pub fn sync_file_systems(paths: &[PathBuf]) -> Result<(), Error> {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::fs::MetadataExt;
        // Each folder once: a thousand outputs of a run share a few.
        let mut folders = std::collections::BTreeMap::new();
        for path in paths {
            folders.entry(folder(path)).or_insert(path);
        }
        let mut devices = Vec::new();
        for (dir, path) in folders {
            let folder = File::open(dir).map_err(|e| write_error(path, e))?;
            let device = folder.metadata().map_err(|e| write_error(path, e))?.dev();
            if !devices.contains(&device) {
                rustix::fs::syncfs(&folder).map_err(|e| write_error(path, e.into()))?;
                devices.push(device);
            }
        }
    }
    #[cfg(not(target_os = "linux"))]
    for path in paths {
        File::open(path)
            .and_then(|f| f.sync_all())
            .map_err(|e| write_error(path, e))?;
    }
    Ok(())
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

    #[cfg(unix)]
    #[test]
    fn a_symbolic_link_keeps_pointing_to_the_new_content() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("real.json");
        let link = dir.path().join("link.json");
        std::fs::write(&file, b"old").unwrap();
        std::os::unix::fs::symlink("real.json", &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read(&file).unwrap(), b"new");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
    }

    /// A FIFO named `pipe` in `dir`, made by `mkfifo`.
    #[cfg(unix)]
    fn make_fifo(dir: &Path) -> PathBuf {
        let fifo = dir.join("pipe");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        fifo
    }

    #[cfg(unix)]
    #[test]
    fn a_fifo_is_written_through_after_the_files() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = make_fifo(dir.path());
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read(fifo).unwrap())
        };
        let file = dir.path().join("a.csv");
        let mut staged = Staged::default();
        staged.add(&fifo, |w| w.write_all(b"through")).unwrap();
        staged.add(&file, |w| w.write_all(b"file")).unwrap();
        staged.commit().unwrap();
        assert_eq!(reader.join().unwrap(), b"through");
        assert_eq!(std::fs::read(&file).unwrap(), b"file");
        assert!(!std::fs::symlink_metadata(&fifo).unwrap().is_file());
    }

    #[cfg(unix)]
    #[test]
    fn written_now_a_fifo_gets_its_bytes_after_the_files() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = make_fifo(dir.path());
        let file = dir.path().join("a.csv");
        let mut staged = Staged::default();
        // No reader yet: writing the FIFO now would block.
        let n = staged
            .add_now(&fifo, |w| w.write_all(b"now").map(|()| 3))
            .unwrap();
        assert_eq!(n, 3);
        let m = staged
            .add_now(&file, |w| w.write_all(b"file").map(|()| 4))
            .unwrap();
        assert_eq!(m, 4);
        assert!(!file.exists());
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read(fifo).unwrap())
        };
        staged.commit().unwrap();
        assert_eq!(reader.join().unwrap(), b"now");
        assert_eq!(std::fs::read(&file).unwrap(), b"file");
    }

    #[test]
    fn written_now_a_failing_writer_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.parquet");
        let mut staged = Staged::default();
        let e = staged
            .add_now(&path, |w| -> std::io::Result<()> {
                w.write_all(b"half")?;
                Err(std::io::Error::other("disk on fire"))
            })
            .unwrap_err();
        assert!(e.to_string().contains("out.parquet"), "{e}");
        drop(staged);
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }

    #[cfg(unix)]
    #[test]
    fn a_hard_linked_file_is_refused_and_left_as_it_was() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.json");
        std::fs::write(&file, b"old").unwrap();
        std::fs::hard_link(&file, dir.path().join("b.json")).unwrap();
        let e = write_atomic(&file, b"new").unwrap_err();
        assert!(
            e.lines()[0].contains("a.json: cannot write: the file has 2 hard links"),
            "{e:?}"
        );
        assert_eq!(std::fs::read(dir.path().join("b.json")).unwrap(), b"old");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
    }

    #[test]
    fn stale_files_go_at_the_commit_only() {
        let dir = tempfile::tempdir().unwrap();
        let stale = dir.path().join("derivatives.csv");
        std::fs::write(&stale, b"old").unwrap();
        let mut staged = Staged::default();
        staged.remove_stale(&stale);
        staged.remove_stale(&dir.path().join("absent.csv"));
        staged
            .add(&dir.path().join("a.csv"), |w| w.write_all(b"a"))
            .unwrap();
        drop(staged);
        assert!(stale.exists(), "removed without a commit");
        let mut staged = Staged::default();
        staged.remove_stale(&stale);
        staged
            .add(&dir.path().join("a.csv"), |w| w.write_all(b"a"))
            .unwrap();
        staged.commit().unwrap();
        assert!(!stale.exists());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn deferred_outputs_are_complete_and_flushed_later() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.json");
        let mut staged = Staged::deferring_sync();
        staged.add(&path, |w| w.write_all(b"{}")).unwrap();
        staged.commit().unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"{}");
        sync_file_systems(&[path]).unwrap();
    }
}
