//! Where things are in a job file: JSON paths (`points[2].y.upper[0]`) mapped
//! to line and column, and duplicate keys.
//!
//! The validator walks a `serde_json::Value`, which keeps no positions. Rather
//! than a second JSON parser with positions, this is a small scan over text that
//! `serde_json` has already accepted: it only has to skip strings, numbers and
//! literals and follow brackets, so it needs no error handling of its own beyond
//! stopping where the text stops making sense. It also finds duplicate keys,
//! which `serde_json` silently resolves by keeping the last one.
//!
//! Lines and columns start at 1; a column counts characters (Unicode scalar
//! values), as editors do, not bytes.

use std::collections::{HashMap, HashSet};
use std::fmt::Write;

use super::place::{child, parent};
use crate::limits::MAX_PROBLEMS;

/// A line and a column, both from 1.
pub type LineColumn = (usize, usize);

/// A key that appears twice in one object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Duplicate {
    /// The member's path.
    pub path: String,
    /// Where the second (or later) copy of the key is.
    pub at: LineColumn,
    /// Where the first copy is.
    pub first: LineColumn,
}

/// A number written as a word that JSON does not have: `NaN`, `Infinity`,
/// `-Infinity` (as `json.dumps` and other writers put them).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct NonFinite {
    /// The path of the value.
    pub path: String,
    /// Where its place is: the key of an object member, else the value.
    pub at: LineColumn,
    /// The number, as messages show it: `NaN`, `inf` or `-inf`.
    pub shown: &'static str,
}

/// What a scan found.
#[derive(Debug, Default)]
pub(crate) struct Scan {
    /// The position of every wanted path that exists: of the key, for an
    /// object member; of the value, for an array element and the root (`""`).
    pub positions: HashMap<String, LineColumn>,
    /// The first [`MAX_PROBLEMS`] repeated keys, in file order.
    pub duplicates: Vec<Duplicate>,
    /// How many more repeated keys there were.
    pub more_duplicates: usize,
    /// The first [`MAX_PROBLEMS`] words `NaN`, `Infinity` and `-Infinity`
    /// where a value belongs, in file order.
    pub non_finite: Vec<NonFinite>,
    /// How many more there were.
    pub more_non_finite: usize,
    /// Where every one of those words is in the text, in bytes.
    pub words: Vec<std::ops::Range<usize>>,
}

impl Scan {
    /// The position of `path`, or of its nearest ancestor that exists (a missing
    /// key is reported at the object that lacks it); `(1, 1)` if none does.
    pub(crate) fn locate(&self, path: &str) -> LineColumn {
        let mut p = path;
        loop {
            if let Some(&at) = self.positions.get(p) {
                return at;
            }
            match parent(p) {
                Some(up) => p = up,
                None => return (1, 1),
            }
        }
    }
}

/// The line and column of the JSON path `path` in `text` (JSON that
/// `serde_json` accepts), or of its nearest ancestor that exists: for a missing
/// key, the object that lacks it.
///
/// # Examples
/// ```
/// # use t2spline_io::job::locate;
/// let text = "{\n  \"points\": [\n    {\"x\": 1}, {\"x\": 2}\n  ]\n}";
/// assert_eq!(locate(text, "points[1].x"), (3, 16));
/// assert_eq!(locate(text, "alpha"), (1, 1)); // missing: the top-level object
/// ```
#[must_use]
pub fn locate(text: &str, path: &str) -> LineColumn {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    scan(text, &HashSet::from([path.to_owned()])).locate(path)
}

/// Scans `text` (JSON that `serde_json` accepted, or JSON but for the words
/// `NaN`, `Infinity` and `-Infinity`) for the positions of the `wanted` paths
/// and of all their ancestors, for duplicate keys and for those words.
pub(crate) fn scan(text: &str, wanted: &HashSet<String>) -> Scan {
    // Ancestors too, so that `locate` can fall back from a missing key.
    let mut all: HashSet<&str> = HashSet::new();
    for path in wanted {
        let mut p = Some(path.as_str());
        while let Some(q) = p {
            if !all.insert(q) {
                break;
            }
            p = parent(q);
        }
    }
    let mut s = Scanner {
        bytes: text.as_bytes(),
        i: 0,
        line: 1,
        column: 1,
        path: String::new(),
        at: (1, 1),
        wanted: all,
        out: Scan::default(),
    };
    s.skip_space();
    s.at = s.here();
    s.record(s.at);
    // `None`: the text ended early or broke the grammar; keep what was found.
    let _ = s.value(0);
    s.out
}

/// What [`oversized`] found first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Oversized {
    /// An array with more than the allowed entries, at its `[`.
    Array(LineColumn),
    /// An object with more than the allowed members, at its `{`.
    Object(LineColumn),
    /// More values than allowed in all, where the count passed the limit.
    Values(LineColumn),
}

/// The first array longer than `max_array`, object larger than `max_keys` or
/// value beyond `max_values` in all, if any: one pass over the bytes that only
/// follows strings, brackets and commas, run before the text is parsed into a
/// tree. Values are counted as containers plus separators (an upper bound).
/// The text need not be valid JSON; broken text is counted as far as it goes.
pub(crate) fn oversized(
    text: &str,
    max_array: usize,
    max_keys: usize,
    max_values: usize,
) -> Option<Oversized> {
    // Per open container: is it an array, entries so far, where it opened.
    let mut stack: Vec<(bool, usize, usize)> = Vec::new();
    let mut values = 1usize;
    let mut in_string = false;
    let mut escaped = false;
    for (i, b) in text.bytes().enumerate() {
        if in_string {
            match (escaped, b) {
                (true, _) => escaped = false,
                (false, b'\\') => escaped = true,
                (false, b'"') => in_string = false,
                _ => {}
            }
            continue;
        }
        match b {
            b'"' => in_string = true,
            b'[' | b'{' => {
                stack.push((b == b'[', 1, i));
                values += 1;
            }
            b']' | b'}' => {
                stack.pop();
            }
            b',' => {
                values += 1;
                if let Some((array, count, start)) = stack.last_mut() {
                    *count += 1;
                    if *array && *count > max_array {
                        return Some(Oversized::Array(line_column_at(text, *start)));
                    }
                    if !*array && *count > max_keys {
                        return Some(Oversized::Object(line_column_at(text, *start)));
                    }
                }
            }
            _ => continue,
        }
        if values > max_values {
            return Some(Oversized::Values(line_column_at(text, i)));
        }
    }
    None
}

/// Line and column (in characters) of the byte at `index`.
fn line_column_at(text: &str, index: usize) -> LineColumn {
    let before = &text[..index];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
    (line, column)
}

/// Nesting the scan follows; `serde_json` refuses more than 128 before.
const MAX_DEPTH: usize = 256;

struct Scanner<'a, 'w> {
    bytes: &'a [u8],
    i: usize,
    line: usize,
    column: usize,
    path: String,
    /// The position of the current path (see [`Scan::positions`]).
    at: LineColumn,
    wanted: HashSet<&'w str>,
    out: Scan,
}

impl Scanner<'_, '_> {
    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.i).copied()
    }

    /// Moves one byte on, counting lines and characters.
    fn bump(&mut self) {
        if let Some(b) = self.peek() {
            self.i += 1;
            if b == b'\n' {
                self.line += 1;
                self.column = 1;
            } else if b & 0xc0 != 0x80 {
                // Not a UTF-8 continuation byte: a new character starts.
                self.column += 1;
            }
        }
    }

    fn skip_space(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.bump();
        }
    }

    fn expect(&mut self, b: u8) -> Option<()> {
        self.skip_space();
        (self.peek()? == b).then(|| self.bump())
    }

    fn here(&self) -> LineColumn {
        (self.line, self.column)
    }

    /// Notes `at` as the position of the current path if it is wanted.
    fn record(&mut self, at: LineColumn) {
        if self.wanted.contains(self.path.as_str()) {
            self.out.positions.entry(self.path.clone()).or_insert(at);
        }
    }

    /// One value at the current position (after white space).
    fn value(&mut self, depth: usize) -> Option<()> {
        if depth > MAX_DEPTH {
            return None;
        }
        match self.peek()? {
            b'{' => self.object(depth),
            b'[' => self.array(depth),
            b'"' => self.string().map(drop),
            _ => {
                let start = self.i;
                while matches!(self.peek(), Some(b) if b.is_ascii_alphanumeric() || matches!(b, b'+' | b'-' | b'.'))
                {
                    self.bump();
                }
                self.word(start);
                Some(())
            }
        }
    }

    /// Notes the literal from byte `start` to here if it is a word for a
    /// number that is not finite.
    fn word(&mut self, start: usize) {
        let shown = match self.bytes.get(start..self.i) {
            Some(b"NaN") => "NaN",
            Some(b"Infinity") => "inf",
            Some(b"-Infinity") => "-inf",
            _ => return,
        };
        self.out.words.push(start..self.i);
        if self.out.non_finite.len() >= MAX_PROBLEMS {
            self.out.more_non_finite += 1;
            return;
        }
        self.out.non_finite.push(NonFinite {
            path: self.path.clone(),
            at: self.at,
            shown,
        });
    }

    fn object(&mut self, depth: usize) -> Option<()> {
        self.bump();
        let mut seen: HashMap<String, LineColumn> = HashMap::new();
        self.skip_space();
        if self.peek()? == b'}' {
            self.bump();
            return Some(());
        }
        loop {
            self.skip_space();
            let at = self.here();
            let key = self.string()?;
            let outer = self.path.len();
            let path = child(&self.path, &key);
            self.path = path;
            self.record(at);
            if self.out.duplicates.len() >= MAX_PROBLEMS && seen.contains_key(&key) {
                self.out.more_duplicates += 1;
            } else if let Some(&first) = seen.get(&key) {
                self.out.duplicates.push(Duplicate {
                    path: self.path.clone(),
                    at,
                    first,
                });
            } else {
                seen.insert(key, at);
            }
            self.expect(b':')?;
            self.skip_space();
            self.at = at;
            self.value(depth + 1)?;
            self.path.truncate(outer);
            self.skip_space();
            match self.peek()? {
                b',' => self.bump(),
                b'}' => {
                    self.bump();
                    return Some(());
                }
                _ => return None,
            }
        }
    }

    fn array(&mut self, depth: usize) -> Option<()> {
        self.bump();
        self.skip_space();
        if self.peek()? == b']' {
            self.bump();
            return Some(());
        }
        let outer = self.path.len();
        for i in 0.. {
            self.skip_space();
            let _ = write!(self.path, "[{i}]");
            self.at = self.here();
            self.record(self.at);
            self.value(depth + 1)?;
            self.path.truncate(outer);
            self.skip_space();
            match self.peek()? {
                b',' => self.bump(),
                b']' => {
                    self.bump();
                    return Some(());
                }
                _ => return None,
            }
        }
        None
    }

    /// A string literal, decoded.
    fn string(&mut self) -> Option<String> {
        if self.peek()? != b'"' {
            return None;
        }
        self.bump();
        let start = self.i;
        let mut escaped = false;
        loop {
            match self.peek()? {
                b'"' => break,
                b'\\' => {
                    escaped = true;
                    self.bump();
                    self.bump();
                }
                _ => self.bump(),
            }
        }
        let raw = std::str::from_utf8(self.bytes.get(start..self.i)?).ok()?;
        self.bump();
        if escaped {
            // serde_json accepted the text, so the literal decodes.
            serde_json::from_str(&format!("\"{raw}\"")).ok()
        } else {
            Some(raw.to_owned())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn positions(text: &str, paths: &[&str]) -> Scan {
        let wanted = paths.iter().map(|p| (*p).to_owned()).collect();
        scan(text, &wanted)
    }

    #[test]
    fn finds_keys_elements_and_the_root() {
        let text = "\n {\"a\": [1, {\"b\": 2}],\n  \"é\": \"x\", \"c\": [[], [3]]}";
        let s = positions(text, &["", "a", "a[1].b", "[\"é\"]", "c[1][0]", "c[0]"]);
        assert_eq!(s.locate(""), (2, 2));
        assert_eq!(s.locate("a"), (2, 3));
        assert_eq!(s.locate("a[1].b"), (2, 13));
        assert_eq!(s.locate("[\"é\"]"), (3, 3));
        assert_eq!(s.locate("c[0]"), (3, 19));
        assert_eq!(s.locate("c[1][0]"), (3, 24));
        // Missing: the nearest ancestor.
        assert_eq!(s.locate("a[1].zzz"), (2, 12));
        assert_eq!(s.locate("q"), (2, 2));
    }

    #[test]
    fn finds_duplicate_keys_with_escapes() {
        let text = "{\"alpha\": 1, \"b\": {\"x\": 1}, \"\\u0061lpha\": 2}";
        let s = positions(text, &[]);
        assert_eq!(
            s.duplicates,
            [Duplicate {
                path: "alpha".into(),
                at: (1, 29),
                first: (1, 2)
            }]
        );
    }

    #[test]
    fn oversized_containers_are_found_before_parsing() {
        let big = |t: &str, a, k, v| oversized(t, a, k, v);
        assert_eq!(big("[1, 2, 3]", 3, 9, 99), None);
        assert_eq!(big("[1, 2, 3]", 2, 9, 99), Some(Oversized::Array((1, 1))));
        // Commas in strings do not count; objects count their members.
        assert_eq!(big("{\"a\": 1, \"b\": \"x,y,z\\\",\"}", 1, 2, 99), None);
        assert_eq!(
            big("{\"a\": 1, \"b\": 2, \"c\": 3}", 9, 2, 99),
            Some(Oversized::Object((1, 1)))
        );
        assert_eq!(
            big("{\n \"k\": [[1, 2], [3, 4, 5]]}", 2, 9, 99),
            Some(Oversized::Array((2, 16)))
        );
        // All values: 1 + 3 containers + 4 commas = 8.
        assert_eq!(big("[[1, 2], [3, 4], 5]", 9, 9, 8), None);
        assert_eq!(
            big("[[1, 2], [3, 4], 5]", 9, 9, 7),
            Some(Oversized::Values((1, 16)))
        );
        // Broken text: counted as far as it goes.
        assert_eq!(big("[0,0,0,0", 3, 9, 99), Some(Oversized::Array((1, 1))));
        assert_eq!(big("\"unterminated [0,0,0", 1, 1, 99), None);
    }

    #[test]
    fn broken_text_gives_what_was_found_without_panicking() {
        for text in [
            "",
            "{",
            "{\"a\": [1, 2",
            "{\"a\" 1}",
            "[\"\\",
            "\"abc",
            "{\"a\": 1,}",
        ] {
            let s = positions(text, &["a", "a[1]"]);
            assert!(s.positions.len() <= 3, "{text}");
        }
    }
}
