//! The temporary files of [`Staged`](crate::Staged) outputs, written beside
//! their targets and given the target's name only when complete.
//!
//! A file that replaces an existing one is written as a named
//! `.t2spline-*.tmp` and renamed over it at the end. On Linux a new file
//! has no name at all while it is written (`O_TMPFILE`): if the process dies
//! in any way, even by `SIGKILL` or a power cut, the kernel frees it and
//! nothing is left behind; it gets its name with one `linkat` (through
//! `/proc/self/fd`), which also saves the rename. Where a file system or
//! system cannot make such files (FAT, some network and FUSE file systems,
//! no `/proc`), a new file is written under a temporary name too.
//!
//! Every named temporary file is created and registered under one lock, and
//! renamed (or removed) and unregistered under it again, so a signal handler
//! that takes the lock sees every temporary file that exists and none that
//! has become an output.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

use tempfile::NamedTempFile;

/// The paths of the named temporary files that exist now.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    // A panic elsewhere while holding the lock leaves a usable list.
    LIVE.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The error of a temporary file used after its rename (which consumes it).
fn renamed() -> std::io::Error {
    std::io::Error::other("the temporary file was already renamed")
}

/// The folder of the file at `path`: its parent, or `.` for a bare name.
pub(crate) fn folder(path: &Path) -> &Path {
    path.parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// Names a named temporary file: `.t2spline-XXXXXX.tmp`, created with the
/// permissions of a new file (`0666` less the umask).
fn builder() -> tempfile::Builder<'static, 'static> {
    let mut builder = tempfile::Builder::new();
    builder.prefix(".t2spline-").suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    builder
}

/// What a temporary file is.
#[derive(Debug)]
enum Kind {
    /// A file with a name in the target's folder, registered in [`LIVE`].
    Named(NamedTempFile),
    /// A file without a name in the target's folder (Linux `O_TMPFILE`).
    #[cfg(target_os = "linux")]
    Unnamed(File),
}

/// A temporary output file, registered while it has a name.
#[derive(Debug)]
pub(crate) struct Temporary {
    /// `None` once renamed.
    kind: Option<Kind>,
}

impl Temporary {
    /// Creates a temporary file beside `target`, for a new output without a
    /// name where the system can; for an output `replacing` a file, or where
    /// the system cannot, named `.t2spline-*.tmp` and registered.
    pub(crate) fn create(target: &Path, replacing: bool) -> std::io::Result<Self> {
        let dir = folder(target);
        #[cfg(not(target_os = "linux"))]
        let _ = replacing;
        #[cfg(target_os = "linux")]
        if let Some(file) = (!replacing).then(|| unnamed::create(dir)).flatten() {
            return Ok(Temporary {
                kind: Some(Kind::Unnamed(file)),
            });
        }
        let mut live = live();
        let file = builder().tempfile_in(dir)?;
        live.push(file.path().to_owned());
        Ok(Temporary {
            kind: Some(Kind::Named(file)),
        })
    }

    /// The open file. Only `persist` takes the file, and it consumes `self`,
    /// so the error is never returned.
    pub(crate) fn file(&self) -> std::io::Result<&File> {
        match self.kind.as_ref().ok_or_else(renamed)? {
            Kind::Named(file) => Ok(file.as_file()),
            #[cfg(target_os = "linux")]
            Kind::Unnamed(file) => Ok(file),
        }
    }

    /// Gives the file the name `path` (replacing a file there) and
    /// unregisters it.
    pub(crate) fn persist(mut self, path: &Path) -> std::io::Result<()> {
        // Under the lock, so that a signal handler waits for the name to be
        // given (and then keeps any other from being given).
        let mut live = live();
        // Only `persist` takes the file, and it consumes `self`.
        match self.kind.take().ok_or_else(renamed)? {
            Kind::Named(file) => {
                let temporary = file.path().to_owned();
                let result = file.persist(path).map(drop).map_err(|e| {
                    // Not renamed: removed now, as a dropped `Staged` would.
                    drop(e.file);
                    e.error
                });
                live.retain(|p| *p != temporary);
                result
            }
            #[cfg(target_os = "linux")]
            Kind::Unnamed(file) => unnamed::name(&file, path),
        }
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if let Some(Kind::Named(file)) = self.kind.take() {
            let mut live = live();
            let temporary = file.path().to_owned();
            drop(file); // removes it
            live.retain(|p| *p != temporary);
        }
        // An unnamed file is freed when it is closed.
    }
}

/// Files without a name until they are complete.
#[cfg(target_os = "linux")]
mod unnamed {
    use std::fs::File;
    use std::os::fd::AsRawFd;
    use std::path::Path;
    use std::sync::OnceLock;

    use rustix::fs::{linkat, open, AtFlags, Mode, OFlags, CWD};
    use rustix::io::Errno;

    /// Whether `/proc/self/fd` is there to name a file by (it is not in
    /// some containers and chroots).
    fn proc_fd() -> bool {
        static PRESENT: OnceLock<bool> = OnceLock::new();
        *PRESENT.get_or_init(|| Path::new("/proc/self/fd").is_dir())
    }

    /// A new file without a name in `dir`, with the permissions of a new
    /// file (`0666` less the umask); `None` where the file system cannot
    /// make one (then a named temporary file is used).
    pub(super) fn create(dir: &Path) -> Option<File> {
        if !proc_fd() {
            return None;
        }
        let flags = OFlags::TMPFILE | OFlags::WRONLY | OFlags::CLOEXEC;
        open(dir, flags, Mode::from_bits_truncate(0o666))
            .ok()
            .map(File::from)
    }

    /// Gives `file` the name `path`: one link if `path` does not exist,
    /// else a link under a temporary name beside it renamed over `path`.
    pub(super) fn name(file: &File, path: &Path) -> std::io::Result<()> {
        let fd = format!("/proc/self/fd/{}", file.as_raw_fd());
        let link = |to: &Path| linkat(CWD, fd.as_str(), CWD, to, AtFlags::SYMLINK_FOLLOW);
        match link(path) {
            Err(Errno::EXIST) => {}
            other => return other.map_err(std::io::Error::from),
        }
        // Removed again if the rename fails.
        let temporary = super::builder().make_in(super::folder(path), |to| {
            link(to).map_err(std::io::Error::from)
        })?;
        temporary.persist(path).map(drop).map_err(|e| e.error)
    }
}

/// Removes every named temporary output file of the process and keeps new
/// ones from being made or named, for a handler of Ctrl-C or `SIGTERM` that
/// is about to end the process: outputs already renamed into place stay,
/// those still being written disappear (files without a name go with the
/// process), none is left half written under its own name or as
/// `.t2spline-*.tmp`. Returns how many files were removed.
///
/// Anything that writes an output after this call waits forever, so the
/// caller must end the process.
pub fn remove_temporary_files() -> usize {
    let mut live = live();
    let removed = live
        .drain(..)
        .filter(|p| std::fs::remove_file(p).is_ok())
        .count();
    // Held until the process ends, so that no new temporary file appears.
    std::mem::forget(live);
    removed
}

#[cfg(test)]
mod tests {
    use std::io::Write;

    use super::*;

    /// The names in `dir`, sorted.
    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    fn write(t: &Temporary, bytes: &[u8]) {
        let mut file = t.file().unwrap();
        file.write_all(bytes).unwrap();
    }

    #[test]
    fn a_new_file_has_no_name_until_it_is_complete() {
        let dir = tempfile::tempdir().unwrap();
        let t = Temporary::create(&dir.path().join("out.json"), false).unwrap();
        write(&t, b"new");
        #[cfg(target_os = "linux")]
        assert_eq!(names(dir.path()), Vec::<String>::new());
        t.persist(&dir.path().join("out.json")).unwrap();
        assert_eq!(names(dir.path()), ["out.json"]);
        assert_eq!(std::fs::read(dir.path().join("out.json")).unwrap(), b"new");
    }

    /// A file that appears under the target's name while the output is
    /// written is replaced, as a file there from the start would be.
    #[test]
    fn a_target_that_appeared_meanwhile_is_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("out.json");
        let t = Temporary::create(&dir.path().join("out.json"), false).unwrap();
        write(&t, b"new");
        std::fs::write(&target, b"old").unwrap();
        t.persist(&target).unwrap();
        assert_eq!(names(dir.path()), ["out.json"]);
        assert_eq!(std::fs::read(&target).unwrap(), b"new");
    }

    #[test]
    fn a_replacing_file_is_named_until_renamed_and_removed_when_dropped() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("out.json"), b"old").unwrap();
        let t = Temporary::create(&dir.path().join("out.json"), true).unwrap();
        write(&t, b"new");
        let during = names(dir.path());
        assert_eq!(during.len(), 2, "{during:?}");
        assert!(during
            .iter()
            .any(|n| n.starts_with(".t2spline-") && n.ends_with(".tmp")));
        drop(t);
        assert_eq!(names(dir.path()), ["out.json"]);
        assert_eq!(std::fs::read(dir.path().join("out.json")).unwrap(), b"old");
    }

    #[test]
    fn a_dropped_new_file_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let t = Temporary::create(&dir.path().join("out.json"), false).unwrap();
        write(&t, b"never named");
        drop(t);
        assert_eq!(names(dir.path()), Vec::<String>::new());
    }
}
