//! Text from outside (file names, keys) made safe to print on a terminal.

use std::fmt::Write;

/// Characters that reorder the text around them on display (Trojan Source).
pub(crate) fn is_bidi_control(c: char) -> bool {
    matches!(c, '\u{061c}' | '\u{200e}' | '\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

/// Appends `c` to `out`, a control character (C0, DEL, C1) or bidirectional
/// control as `\u{…}`-style escape `\uXXXX`.
pub(crate) fn push_escaped(out: &mut String, c: char) {
    if c.is_control() || is_bidi_control(c) {
        // Writing to a String cannot fail.
        let _ = write!(out, "\\u{:04x}", u32::from(c));
    } else {
        out.push(c);
    }
}

/// A file name or other outside text as it may be printed: control
/// characters and bidirectional controls escaped (`\u001b`), so that a
/// hostile name cannot move the cursor, recolour or clear a terminal, or hide
/// part of a message. Other characters, backslashes included, are kept.
///
/// # Examples
/// ```
/// assert_eq!(t2spline_io::printable("\u{1b}]0;pwned\u{7}.json"), "\\u001b]0;pwned\\u0007.json");
/// assert_eq!(t2spline_io::printable("jobs/été.json"), "jobs/été.json");
/// ```
#[must_use]
pub fn printable(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        push_escaped(&mut out, c);
    }
    out
}
