//! The one rule of every command that writes files, checked before anything
//! is written: no output is an input (`export job.json -o job.json`), no two
//! outputs of one run are one file (`run J -o r.json --parquet r.json`), and
//! no output lies inside a folder that another output writes, or holds one
//! (`run J -o cc/stage1-layers.csv --csv cc`).
//!
//! Paths are compared as the file system resolves them: symbolic links
//! followed (a dangling one to the file it would create), an output that does
//! not exist yet by the canonical path of its nearest existing folder and the
//! rest of its name; an existing input is also matched by device and inode,
//! so that a hard link to it is it too.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use crate::exit::OptionError;
use crate::output::{is_stdio, shown};

/// How many symbolic links are followed from one path, as Linux's `ELOOP`.
const MAX_LINKS: usize = 40;

/// The identity of an existing file: device and inode.
#[cfg(unix)]
type FileId = (u64, u64);
#[cfg(not(unix))]
type FileId = ();

#[cfg(unix)]
fn file_id(meta: &std::fs::Metadata) -> Option<FileId> {
    use std::os::unix::fs::MetadataExt;
    Some((meta.dev(), meta.ino()))
}

#[cfg(not(unix))]
fn file_id(_: &std::fs::Metadata) -> Option<FileId> {
    None
}

/// A path as the file system resolves it, and the file's identity if it
/// exists.
#[derive(Debug)]
struct Resolved {
    key: PathBuf,
    id: Option<FileId>,
    /// A device, FIFO or socket: written through, never replaced, so that
    /// two outputs may share one (`-o /dev/null --parquet /dev/null`).
    stream: bool,
}

impl Resolved {
    fn new(key: PathBuf, meta: Option<&std::fs::Metadata>) -> Resolved {
        Resolved {
            key,
            id: meta.and_then(file_id),
            stream: meta.is_some_and(|m| !m.is_file() && !m.is_dir()),
        }
    }
}

/// Canonical paths of folders, each looked up once (many outputs of a run of
/// many jobs share their folder), with whether something exists there
/// (`false`: nothing inside it exists either, and is not looked for).
#[derive(Debug, Default)]
struct Resolver {
    folders: HashMap<PathBuf, (PathBuf, bool)>,
}

impl Resolver {
    /// The canonical form of the folder `dir` (`""`: the current folder),
    /// and whether it exists.
    fn folder(&mut self, dir: &Path) -> (PathBuf, bool) {
        let dir = if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        };
        if let Some(known) = self.folders.get(dir) {
            return known.clone();
        }
        let found = match (dir.parent(), dir.file_name()) {
            (Some(parent), Some(name)) => {
                let (folder, exists) = self.folder(parent);
                let here = folder.join(name);
                if !exists {
                    (here, false)
                } else {
                    match std::fs::symlink_metadata(dir) {
                        // Only a link needs the whole path resolved again.
                        Ok(meta) if meta.file_type().is_symlink() => {
                            match std::fs::canonicalize(dir) {
                                Ok(c) => (c, true),
                                Err(_) => (here, false),
                            }
                        }
                        Ok(_) => (here, true),
                        Err(_) => (here, false),
                    }
                }
            }
            // `/`, `.`, or a name ending in `..`: resolved whole.
            _ => match std::fs::canonicalize(dir) {
                Ok(c) => (c, true),
                Err(_) => (absolute(dir), false),
            },
        };
        self.folders.insert(dir.to_owned(), found.clone());
        found
    }

    /// `path` resolved (see the module's documentation).
    fn resolve(&mut self, path: &Path) -> Resolved {
        self.resolve_within(path, MAX_LINKS)
    }

    fn resolve_within(&mut self, path: &Path, links: usize) -> Resolved {
        let (Some(parent), Some(name)) = (path.parent(), path.file_name()) else {
            // `/`, `.` or `..`: a folder, never a file created by name.
            let key = std::fs::canonicalize(path).unwrap_or_else(|_| absolute(path));
            return Resolved::new(key, std::fs::metadata(path).ok().as_ref());
        };
        let (folder, exists) = self.folder(parent);
        if !exists {
            return Resolved::new(folder.join(name), None);
        }
        match std::fs::symlink_metadata(path) {
            Ok(meta) if meta.file_type().is_symlink() => match std::fs::canonicalize(path) {
                Ok(key) => {
                    let meta = std::fs::metadata(&key).ok();
                    Resolved::new(key, meta.as_ref())
                }
                // A dangling link names the file that writing through it
                // creates.
                Err(_) => match std::fs::read_link(path) {
                    Ok(target) if links > 0 => self.resolve_within(&folder.join(target), links - 1),
                    _ => Resolved::new(folder.join(name), None),
                },
            },
            Ok(meta) => Resolved::new(folder.join(name), Some(&meta)),
            Err(_) => Resolved::new(folder.join(name), None),
        }
    }
}

/// `path` made absolute against the current folder, without resolving it.
fn absolute(path: &Path) -> PathBuf {
    std::path::absolute(path).unwrap_or_else(|_| path.to_owned())
}

/// An output, as given, and the option that names it.
#[derive(Clone, Debug)]
struct Claim {
    option: &'static str,
    path: PathBuf,
}

/// The inputs and outputs of one command, every output checked against the
/// inputs and against the outputs claimed before it.
#[derive(Debug, Default)]
pub struct Claims {
    resolver: Resolver,
    inputs: HashMap<PathBuf, PathBuf>,
    input_ids: HashMap<FileId, PathBuf>,
    files: HashMap<PathBuf, Claim>,
    folders: HashMap<PathBuf, Claim>,
    /// Every folder that holds a claimed file, with one such file.
    above_files: HashMap<PathBuf, Claim>,
    /// Every folder that holds a claimed folder, with one such folder.
    above_folders: HashMap<PathBuf, Claim>,
}

impl Claims {
    /// The claims of a command that reads the files among `inputs` (standard
    /// input is none).
    pub fn new<'p>(inputs: impl IntoIterator<Item = &'p Path>) -> Claims {
        let mut claims = Claims::default();
        for path in inputs.into_iter().filter(|p| !is_stdio(p)) {
            let r = claims.resolver.resolve(path);
            if let Some(id) = r.id {
                claims.input_ids.insert(id, path.to_owned());
            }
            claims.inputs.insert(r.key, path.to_owned());
        }
        claims
    }

    /// The output file `path` of `option` (standard output, `-`, is no file).
    ///
    /// A device or FIFO is checked against the inputs only: it is written
    /// through, never replaced, and may take several outputs.
    ///
    /// # Errors
    /// An [`OptionError`] of `option` if `path` is an input, the file of an
    /// output claimed before, or inside a folder claimed before, or holds one.
    pub fn file(&mut self, option: &'static str, path: &Path) -> Result<(), OptionError> {
        if is_stdio(path) {
            return Ok(());
        }
        let r = self.resolver.resolve(path);
        self.not_input(option, path, &r)?;
        if r.stream {
            return Ok(());
        }
        let refuse = |message: String| Err(OptionError { option, message });
        if let Some(other) = self.files.get(&r.key).or_else(|| self.folders.get(&r.key)) {
            return refuse(same(path, other));
        }
        if let Some(other) = r.key.ancestors().find_map(|a| self.folders.get(a)) {
            return refuse(inside(path, other));
        }
        if let Some(other) = self.above_folders.get(&r.key) {
            return refuse(holds(path, other));
        }
        let claim = Claim {
            option,
            path: path.to_owned(),
        };
        above(&mut self.above_files, &r.key, &claim);
        self.files.insert(r.key, claim);
        Ok(())
    }

    /// The output folder `dir` of `option`, into which its writer writes the
    /// files `writes` (by name): no other output may lie inside it, and none
    /// of `writes` may be an input.
    ///
    /// # Errors
    /// An [`OptionError`] of `option` if `dir` or one of its files is an
    /// input, `dir` is or lies inside the file or folder of an output claimed
    /// before, or holds one.
    pub fn folder<'n>(
        &mut self,
        option: &'static str,
        dir: &Path,
        writes: impl IntoIterator<Item = &'n str>,
    ) -> Result<(), OptionError> {
        let r = self.resolver.resolve(dir);
        self.not_input(option, dir, &r)?;
        let refuse = |message: String| Err(OptionError { option, message });
        if let Some(other) = self.files.get(&r.key).or_else(|| self.folders.get(&r.key)) {
            return refuse(same(dir, other));
        }
        if let Some(other) = r.key.ancestors().find_map(|a| self.files.get(a)) {
            return refuse(inside(dir, other));
        }
        if let Some(other) = r.key.ancestors().find_map(|a| self.folders.get(a)) {
            return refuse(inside(dir, other));
        }
        if let Some(other) = self
            .above_files
            .get(&r.key)
            .or_else(|| self.above_folders.get(&r.key))
        {
            return refuse(holds(dir, other));
        }
        for name in writes {
            let file = dir.join(name);
            let resolved = self.resolver.resolve(&file);
            self.not_input(option, &file, &resolved)?;
        }
        let claim = Claim {
            option,
            path: dir.to_owned(),
        };
        above(&mut self.above_folders, &r.key, &claim);
        self.folders.insert(r.key, claim);
        Ok(())
    }

    /// An error if `path` (resolved as `r`) is an input.
    fn not_input(
        &self,
        option: &'static str,
        path: &Path,
        r: &Resolved,
    ) -> Result<(), OptionError> {
        let input = self
            .inputs
            .get(&r.key)
            .or_else(|| r.id.as_ref().and_then(|id| self.input_ids.get(id)));
        match input {
            Some(input) => Err(OptionError {
                option,
                message: format!(
                    "{} is the input file {}: an output never overwrites its input",
                    shown(path),
                    shown(input)
                ),
            }),
            None => Ok(()),
        }
    }
}

/// Records `claim` as held by every folder above `key`.
fn above(map: &mut HashMap<PathBuf, Claim>, key: &Path, claim: &Claim) {
    for folder in key.ancestors().skip(1) {
        if map.contains_key(folder) {
            // And so are the folders above it.
            break;
        }
        map.insert(folder.to_owned(), claim.clone());
    }
}

fn same(path: &Path, other: &Claim) -> String {
    format!(
        "{} is also the output of {} ({}): two outputs of one run never share a file",
        shown(path),
        other.option,
        shown(&other.path)
    )
}

fn inside(path: &Path, other: &Claim) -> String {
    format!(
        "{} lies inside {}, the output of {}: no output of one run lies inside another's",
        shown(path),
        shown(&other.path),
        other.option
    )
}

fn holds(path: &Path, other: &Claim) -> String {
    format!(
        "{} holds {}, the output of {}: no output of one run lies inside another's",
        shown(path),
        shown(&other.path),
        other.option
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir() -> tempfile::TempDir {
        tempfile::tempdir().unwrap()
    }

    #[test]
    fn an_output_is_not_an_input_by_any_name() {
        let d = dir();
        let job = d.path().join("job.json");
        std::fs::write(&job, "{}").unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink("job.json", d.path().join("link.dxf")).unwrap();
        let mut c = Claims::new([job.as_path()]);
        let e = c.file("--output", &job).unwrap_err();
        assert!(e.message.contains("is the input file"), "{e}");
        #[cfg(unix)]
        assert!(c.file("--output", &d.path().join("link.dxf")).is_err());
        // The same file by another spelling of its folder.
        let odd = d.path().join(".").join("sub/..").join("job.json");
        std::fs::create_dir(d.path().join("sub")).unwrap();
        assert!(c.file("--output", &odd).is_err());
        assert!(c.file("--output", &d.path().join("new.json")).is_ok());
        // A folder whose writer writes the input's name.
        let e = c.folder("--csv", d.path(), ["job.json"]).unwrap_err();
        assert_eq!(e.option, "--csv");
        assert!(c
            .folder("--csv", &d.path().join("out"), ["job.json"])
            .is_ok());
    }

    #[test]
    fn two_outputs_never_share_a_file_or_a_folder() {
        let d = dir();
        let p = |s: &str| d.path().join(s);
        let mut c = Claims::new([]);
        c.file("--output", &p("r.json")).unwrap();
        let e = c.file("--parquet", &p("r.json")).unwrap_err();
        assert!(e.message.contains("is also the output of --output"), "{e}");
        // A file that does not exist yet, in a folder that does not either.
        c.file("--output", &p("new/a.json")).unwrap();
        assert!(c.file("--parquet", &p("new/./a.json")).is_err());
        // A folder holding a file claimed before, or inside one.
        let e = c.folder("--csv", &p("new"), []).unwrap_err();
        assert!(e.message.contains("holds"), "{e}");
        assert!(c.folder("--csv", &p("r.json/x"), []).is_err());
        c.folder("--csv", &p("cc"), ["stage1-layers.csv"]).unwrap();
        let e = c.file("--parquet", &p("cc/stage1-layers.csv")).unwrap_err();
        assert!(e.message.contains("lies inside"), "{e}");
        assert!(c.file("--parquet", &p("cc/deep/other.parquet")).is_err());
        assert!(c.folder("--plot", &p("cc/sub"), []).is_err());
        assert!(c.folder("--plot", &p(""), []).is_err());
        // Beside them, all is well.
        assert!(c.file("--parquet", &p("cc.parquet")).is_ok());
        assert!(c.file("--parquet", &p("-")).is_ok());
    }

    #[cfg(unix)]
    #[test]
    fn links_are_followed_even_when_dangling() {
        let d = dir();
        let p = |s: &str| d.path().join(s);
        std::os::unix::fs::symlink("target.json", p("dangling.json")).unwrap();
        std::fs::create_dir(p("real")).unwrap();
        std::os::unix::fs::symlink("real", p("alias")).unwrap();
        let mut c = Claims::new([]);
        c.file("--output", &p("dangling.json")).unwrap();
        assert!(c.file("--parquet", &p("target.json")).is_err());
        c.folder("--csv", &p("alias"), []).unwrap();
        assert!(c.file("--parquet", &p("real/x.parquet")).is_err());
    }
}
