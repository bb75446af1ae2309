//! Reading job text from a file or a stream, within [`MAX_FILE_BYTES`], as
//! UTF-8.
//!
//! A regular file is measured before it is read; anything else (a pipe,
//! standard input, `/dev/zero`) is read to at most one byte past the limit.
//! A UTF-8 byte-order mark, as spreadsheet programs write, is accepted; UTF-16
//! text and bytes that are not UTF-8 are refused with their place.

// The input decides sizes and indices here: no indexing that can panic.
#![cfg_attr(not(test), deny(clippy::indexing_slicing))]

use std::io::Read;
use std::path::Path;

use crate::error::{Error, Problem};
use crate::limits::{file_too_large, MAX_FILE_BYTES};

/// Reads the text of the job file at `path`.
///
/// # Errors
/// [`Error::Read`] if the file cannot be opened or read; [`Error::Invalid`] if
/// it is larger than [`MAX_FILE_BYTES`] (checked before reading) or is not
/// UTF-8 text (naming the line and column of the first bad byte).
///
/// # Examples
/// ```
/// let dir = tempfile::tempdir()?;
/// let path = dir.path().join("job.json");
/// std::fs::write(&path, b"\xef\xbb\xbf{}")?; // with a byte-order mark
/// assert_eq!(t2spline_io::job::read_text(&path)?, "{}");
/// std::fs::write(&path, b"{\n \"description\": \"caf\xe9\"}")?; // Latin-1
/// let e = t2spline_io::job::read_text(&path).unwrap_err();
/// assert!(e.to_string().ends_with("job.json:2:21: not UTF-8 text (byte 0xe9); save the file as UTF-8"), "{e}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn read_text(path: &Path) -> Result<String, Error> {
    let name = path.display().to_string();
    let failed = |source| Error::Read {
        path: path.to_owned(),
        source,
    };
    let file = std::fs::File::open(path).map_err(failed)?;
    let metadata = file.metadata().map_err(failed)?;
    if metadata.is_file() && metadata.len() > MAX_FILE_BYTES {
        return Err(whole_file(&name, file_too_large(Some(metadata.len()))));
    }
    // The size known, the text is read in one call and the end found by a
    // second, where an empty buffer would grow through a dozen reads.
    let size = usize::try_from(metadata.len()).unwrap_or(0);
    read_limited(file, &name, size).map_err(|e| match e {
        Error::Read { source, .. } => failed(source),
        other => other,
    })
}

/// Reads job text from `reader` (standard input, say), naming it `name` in
/// messages, with the limits and checks of [`read_text`].
///
/// # Errors
/// [`Error::Read`] (with `name` as its path) if reading fails, and the
/// [`Error::Invalid`] cases of [`read_text`].
pub fn read_text_from(reader: impl Read, name: &str) -> Result<String, Error> {
    read_limited(reader, name, 0)
}

/// Reads `reader` to its end or to one byte past [`MAX_FILE_BYTES`], with
/// room for `expected` bytes at the start (a file's size, else 0).
fn read_limited(reader: impl Read, name: &str, expected: usize) -> Result<String, Error> {
    let mut bytes = Vec::new();
    // A file larger than the limit was refused before; a wrong size (a file
    // growing, `/proc`) only means more reads.
    let limit = usize::try_from(MAX_FILE_BYTES).unwrap_or(usize::MAX);
    let _ = bytes.try_reserve_exact(expected.min(limit).saturating_add(1));
    reader
        .take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|source| Error::Read {
            path: name.into(),
            source,
        })?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(whole_file(name, file_too_large(None)));
    }
    decode(bytes, name)
}

/// A problem with the whole input rather than one place in it.
fn whole_file(name: &str, rule: String) -> Error {
    Error::Invalid {
        file: name.to_owned(),
        problems: vec![Problem::new(rule)],
    }
}

/// The bytes as UTF-8 text without a byte-order mark.
fn decode(bytes: Vec<u8>, name: &str) -> Result<String, Error> {
    if bytes.starts_with(&[0xff, 0xfe]) || bytes.starts_with(&[0xfe, 0xff]) {
        return Err(whole_file(
            name,
            "the file is UTF-16 text; save it as UTF-8".to_owned(),
        ));
    }
    let body = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(&bytes);
    match std::str::from_utf8(body) {
        Ok(text) => Ok(text.to_owned()),
        Err(e) => {
            let (good, bad) = body
                .split_at_checked(e.valid_up_to())
                .unwrap_or((body, &[]));
            // `good` is valid UTF-8 by construction.
            let before = std::str::from_utf8(good).unwrap_or_default();
            let line = before.matches('\n').count() + 1;
            let column = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
            let byte = bad.first().copied().unwrap_or_default();
            Err(Error::Invalid {
                file: name.to_owned(),
                problems: vec![Problem {
                    line_column: Some((line, column)),
                    message: format!("not UTF-8 text (byte {byte:#04x}); save the file as UTF-8"),
                }],
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn streams_past_the_limit_are_refused_without_reading_them_all() {
        // An endless stream of spaces: reading stops one byte past the limit.
        let endless = std::io::repeat(b' ');
        let e = read_text_from(endless, "<stdin>").unwrap_err();
        assert_eq!(
            e.to_string(),
            "<stdin>: the input is larger than the limit of 64 MiB (67108864 bytes)"
        );
    }

    #[test]
    fn utf16_and_bad_bytes_are_named() {
        let e = read_text_from(&b"\xff\xfe{\0}\0"[..], "j.json").unwrap_err();
        assert_eq!(
            e.to_string(),
            "j.json: the file is UTF-16 text; save it as UTF-8"
        );
        let e = read_text_from(&b"{\"a\": \"\xc3\xa9\xc3\"}"[..], "j.json").unwrap_err();
        assert_eq!(
            e.to_string(),
            "j.json:1:9: not UTF-8 text (byte 0xc3); save the file as UTF-8"
        );
    }

    #[test]
    fn a_large_file_is_refused_before_it_is_read() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("big.json");
        // A sparse file: its size is known without writing 65 MB.
        let f = std::fs::File::create(&path).unwrap();
        f.set_len(MAX_FILE_BYTES + 10).unwrap();
        let e = read_text(&path).unwrap_err();
        assert!(
            e.to_string().ends_with(&format!(
                "big.json: the file has {} bytes, more than the limit of 64 MiB (67108864 bytes)",
                MAX_FILE_BYTES + 10
            )),
            "{e}"
        );
    }
}
