//! What an output path names: a new file, a file to replace, or a stream (a
//! device, a FIFO) to write through, after following symbolic links.

use std::fs::{Metadata, Permissions};
use std::io;
use std::path::{Path, PathBuf};

/// How many symbolic links are followed before giving up, as Linux does
/// (`ELOOP` after 40).
const MAX_LINKS: usize = 40;

/// Where an output goes.
#[derive(Debug)]
pub(crate) enum Target {
    /// A regular file to create or replace (by renaming a complete temporary
    /// file over it); `path` is the file itself, the end of any symbolic
    /// links, so that a link keeps pointing to the new content.
    File {
        /// The file to create or replace.
        path: PathBuf,
        /// The permissions of the file replaced, kept by the new one.
        permissions: Option<Permissions>,
    },
    /// A character or block device, a FIFO or a socket: written through, not
    /// replaced (`/dev/null` stays the device, a FIFO's reader gets the bytes).
    Stream(PathBuf),
}

/// Resolves `path` to the [`Target`] an output to it writes.
///
/// # Errors
/// An `io::Error` for a folder (`IsADirectory`), a chain of more than 40
/// symbolic links, a regular file with more than one name (hard links: it is
/// neither replaced, which would cut the link, nor written in place, which
/// would change every name and could leave it half written), and for
/// metadata that cannot be read.
pub(crate) fn resolve(path: &Path) -> io::Result<Target> {
    let mut path = path.to_owned();
    for _ in 0..=MAX_LINKS {
        let meta = match std::fs::symlink_metadata(&path) {
            Ok(meta) => meta,
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                return Ok(Target::File {
                    path,
                    permissions: None,
                })
            }
            Err(e) => return Err(e),
        };
        if meta.file_type().is_symlink() {
            let link = std::fs::read_link(&path)?;
            path = match path.parent() {
                Some(dir) if link.is_relative() => dir.join(link),
                _ => link,
            };
            continue;
        }
        return existing(path, &meta);
    }
    Err(io::Error::other(format!(
        "more than {MAX_LINKS} symbolic links in a chain"
    )))
}

/// The target for an existing path that is not a symbolic link.
fn existing(path: PathBuf, meta: &Metadata) -> io::Result<Target> {
    if meta.is_dir() {
        return Err(io::ErrorKind::IsADirectory.into());
    }
    if !meta.is_file() {
        return Ok(Target::Stream(path));
    }
    let links = hard_links(meta);
    if links > 1 {
        return Err(io::Error::other(format!(
            "the file has {links} hard links; replacing it would cut them and writing in place would change every name: remove it or choose another name"
        )));
    }
    Ok(Target::File {
        path,
        permissions: Some(meta.permissions()),
    })
}

#[cfg(unix)]
fn hard_links(meta: &Metadata) -> u64 {
    std::os::unix::fs::MetadataExt::nlink(meta)
}

#[cfg(not(unix))]
fn hard_links(_: &Metadata) -> u64 {
    1
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn kinds_of_path() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.json");
        std::fs::write(&file, "x").unwrap();
        let new = dir.path().join("new.json");
        assert!(
            matches!(resolve(&new).unwrap(), Target::File { path, permissions: None } if path == new)
        );
        assert!(matches!(
            resolve(&file).unwrap(),
            Target::File {
                permissions: Some(_),
                ..
            }
        ));
        let fifo = dir.path().join("fifo");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        assert!(matches!(resolve(&fifo).unwrap(), Target::Stream(_)));
        let e = resolve(dir.path()).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::IsADirectory);
    }

    #[test]
    fn links_are_followed_to_their_end() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.json");
        std::fs::write(&file, "x").unwrap();
        std::os::unix::fs::symlink("a.json", dir.path().join("b")).unwrap();
        std::os::unix::fs::symlink(dir.path().join("b"), dir.path().join("c")).unwrap();
        match resolve(&dir.path().join("c")).unwrap() {
            Target::File { path, .. } => {
                assert_eq!(
                    std::fs::canonicalize(path).unwrap(),
                    std::fs::canonicalize(&file).unwrap()
                );
            }
            t => panic!("{t:?}"),
        }
        // A dangling link: the file it names is created.
        std::os::unix::fs::symlink("missing.json", dir.path().join("d")).unwrap();
        match resolve(&dir.path().join("d")).unwrap() {
            Target::File { path, permissions } => {
                assert!(path.ends_with("missing.json") && permissions.is_none());
            }
            t => panic!("{t:?}"),
        }
        // A loop.
        std::os::unix::fs::symlink("e", dir.path().join("e")).unwrap();
        let e = resolve(&dir.path().join("e")).unwrap_err();
        assert!(e.to_string().contains("symbolic links"), "{e}");
    }

    #[test]
    fn a_hard_linked_file_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.json");
        std::fs::write(&file, "x").unwrap();
        std::fs::hard_link(&file, dir.path().join("b.json")).unwrap();
        let e = resolve(&file).unwrap_err();
        assert!(e.to_string().contains("2 hard links"), "{e}");
    }
}
