//! Output files that are either complete or absent.

use std::io::Write;
use std::path::Path;

use crate::Error;

/// Writes `bytes` to `path` atomically: into a temporary file in the same folder,
/// flushed to disk, then renamed over `path`. If anything fails, `path` is left
/// as it was (absent, or with its old content) and the temporary file is removed.
///
/// # Errors
/// [`Error::Write`] naming `path`.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    write_all_atomic(&[(path, bytes)])
}

/// Writes several files all or nothing, as far as the file system allows: every
/// file is first written in full to a temporary file beside its destination and
/// flushed; only when all of them succeeded are they renamed into place. A
/// failure while writing (a missing folder, a full disk) leaves every
/// destination as it was.
///
/// # Errors
/// [`Error::Write`] naming the first file that could not be written.
pub fn write_all_atomic(files: &[(&Path, &[u8])]) -> Result<(), Error> {
    let staged = files
        .iter()
        .map(|&(path, bytes)| stage(path, bytes).map(|tmp| (path, tmp)))
        .collect::<Result<Vec<_>, _>>()?;
    for (path, tmp) in staged {
        tmp.persist(path).map_err(|e| write_error(path, e.error))?;
    }
    Ok(())
}

/// A flushed temporary file holding `bytes`, in the folder of `path`; removed
/// when dropped unless persisted.
fn stage(path: &Path, bytes: &[u8]) -> Result<tempfile::NamedTempFile, Error> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    builder.prefix(".t2spline-").suffix(".tmp");
    if let Some(p) = permissions_for(path) {
        builder.permissions(p);
    }
    let mut file = builder.tempfile_in(dir).map_err(|e| write_error(path, e))?;
    file.write_all(bytes).map_err(|e| write_error(path, e))?;
    file.as_file()
        .sync_all()
        .map_err(|e| write_error(path, e))?;
    Ok(file)
}

/// The permissions the written file gets: those of the file it replaces, or
/// else what a plain `File::create` gives (on Unix read-write for all, less the
/// umask), not the owner-only mode tempfile uses for private temporary files.
fn permissions_for(path: &Path) -> Option<std::fs::Permissions> {
    if let Ok(meta) = std::fs::metadata(path) {
        return Some(meta.permissions());
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        // The mode is passed to open(2), which applies the umask.
        Some(std::fs::Permissions::from_mode(0o666))
    }
    #[cfg(not(unix))]
    None
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

    #[cfg(unix)]
    #[test]
    fn new_files_get_the_usual_mode_and_replaced_files_keep_theirs() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
        let plain = dir.path().join("plain");
        std::fs::File::create(&plain).unwrap();
        let ours = dir.path().join("ours.json");
        write_atomic(&ours, b"x").unwrap();
        assert_eq!(mode(&ours), mode(&plain), "mode differs from File::create");
        std::fs::set_permissions(&ours, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_atomic(&ours, b"y").unwrap();
        assert_eq!(mode(&ours), 0o640);
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
}
