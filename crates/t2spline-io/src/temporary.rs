//! The temporary files of every [`Staged`](crate::Staged) output of the
//! process, so that a program interrupted by a signal can remove them.
//!
//! A temporary file is created and registered under one lock, and renamed
//! (or removed) and unregistered under it again, so a signal handler that
//! takes the lock sees every temporary file that exists and none that has
//! become an output.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

use tempfile::NamedTempFile;

/// The paths of the temporary files that exist now.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    // A panic elsewhere while holding the lock leaves a usable list.
    LIVE.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The error of a temporary file used after its rename (which consumes it).
fn renamed() -> std::io::Error {
    std::io::Error::other("the temporary file was already renamed")
}

/// A temporary output file, registered while it exists.
#[derive(Debug)]
pub(crate) struct Temporary {
    /// `None` once renamed.
    file: Option<NamedTempFile>,
}

impl Temporary {
    /// Creates a temporary file with `builder` in `dir`, registered.
    pub(crate) fn create(builder: &tempfile::Builder<'_, '_>, dir: &Path) -> std::io::Result<Self> {
        let mut live = live();
        let file = builder.tempfile_in(dir)?;
        live.push(file.path().to_owned());
        Ok(Temporary { file: Some(file) })
    }

    /// The open file. Only `persist` takes the file, and it consumes `self`,
    /// so the error is never returned.
    pub(crate) fn file(&self) -> std::io::Result<&std::fs::File> {
        self.file
            .as_ref()
            .map(NamedTempFile::as_file)
            .ok_or_else(renamed)
    }

    /// Renames the file to `path` and unregisters it.
    pub(crate) fn persist(mut self, path: &Path) -> std::io::Result<()> {
        let mut live = live();
        // Only `persist` takes the file, and it consumes `self`.
        let file = self.file.take().ok_or_else(renamed)?;
        let temporary = file.path().to_owned();
        let result = file.persist(path).map(drop).map_err(|e| {
            // Not renamed: removed now, as a dropped `Staged` would.
            drop(e.file);
            e.error
        });
        live.retain(|p| *p != temporary);
        result
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if let Some(file) = self.file.take() {
            let mut live = live();
            let temporary = file.path().to_owned();
            drop(file); // removes it
            live.retain(|p| *p != temporary);
        }
    }
}

/// Removes every temporary output file of the process and keeps new ones
/// from being made, for a handler of Ctrl-C or `SIGTERM` that is about to
/// end the process: outputs already renamed into place stay, those still
/// being written disappear, none is left half written under its own name or
/// as `.t2spline-*.tmp`. Returns how many files were removed.
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
