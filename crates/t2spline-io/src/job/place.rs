//! How a problem names its place in a job or data file: the JSON path of
//! the value concerned (`points[1].x.crisp`, `weights[2]`, `knots.v`,
//! `["odd key"]`), written alike by every reader of the job text (the
//! validator, the scan for positions and for NaN and infinity) and so by
//! every front end, the command line and Python alike.

use crate::printable::push_escaped;

/// The longest key shown in a path before it is cut with `…`.
const MAX_KEY_CHARS: usize = 40;

/// The path of member `key` of the object at `prefix`: `prefix.key` for plain
/// keys, and `prefix["…"]` (escaped, at most 40 characters) for
/// any other, so that a path never carries control characters to a terminal and
/// a key such as `"y.upper"` cannot pose as a nested path.
///
/// # Examples
/// ```
/// use t2spline_io::job::{child, element};
/// assert_eq!(child(&element("points", 1), "x"), "points[1].x");
/// assert_eq!(child("points[1]", "y.upper"), r#"points[1]["y.upper"]"#);
/// assert_eq!(child("", "alpha"), "alpha");
/// ```
#[must_use]
pub fn child(prefix: &str, key: &str) -> String {
    let plain = !key.is_empty()
        && key.len() <= MAX_KEY_CHARS
        && key.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')
        && !key.as_bytes().first().is_some_and(u8::is_ascii_digit);
    match (plain, prefix.is_empty()) {
        (true, true) => key.to_owned(),
        (true, false) => format!("{prefix}.{key}"),
        (false, _) => format!("{prefix}[{}]", quote(key)),
    }
}

/// The path of element `i` of the array at `prefix`: `weights[2]`.
#[must_use]
pub fn element(prefix: &str, i: usize) -> String {
    format!("{prefix}[{i}]")
}

/// `key` as a JSON string literal safe to print: quotes, backslashes, control
/// characters (C0, DEL, C1) and bidirectional-text controls escaped, and cut
/// after [`MAX_KEY_CHARS`] characters.
pub(crate) fn quote(key: &str) -> String {
    let mut out = String::from("\"");
    for (i, c) in key.chars().enumerate() {
        if i == MAX_KEY_CHARS {
            out.push('…');
            break;
        }
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c => push_escaped(&mut out, c),
        }
    }
    out.push('"');
    out
}

/// The path one level up: `a.b[2]` → `a.b` → `a` → `""`; `None` above the root.
/// Quoted keys (`a["x.y"]`) are cut at the `[` that opens them.
pub(super) fn parent(path: &str) -> Option<&str> {
    if path.is_empty() {
        return None;
    }
    let cut = if path.ends_with("\"]") {
        path.rfind("[\"")
    } else {
        path.rfind(['.', '['])
    };
    Some(&path[..cut.unwrap_or(0)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn odd_keys_are_quoted_escaped_and_cut() {
        assert_eq!(child("", "alpha"), "alpha");
        assert_eq!(child("p", "y.upper"), "p[\"y.upper\"]");
        assert_eq!(
            child("p", "\u{1b}[31m\u{202e}"),
            "p[\"\\u001b[31m\\u202e\"]"
        );
        assert_eq!(child("", "3d"), "[\"3d\"]");
        let long = "k".repeat(100);
        assert_eq!(child("", &long), format!("[\"{}…\"]", "k".repeat(40)));
        assert_eq!(parent("p[\"a.b[1]\"]"), Some("p"));
        assert_eq!(parent("points[2].y"), Some("points[2]"));
        assert_eq!(parent("points"), Some(""));
        assert_eq!(parent(""), None);
    }
}
