//! The rules every delimited readings file shares: the separator, splitting
//! into records within a limit of rows, numbers (a decimal comma in a
//! semicolon file) and text from the file in messages.

use t2spline::{Num, MAX_MAGNITUDE};

use super::tokens;
use crate::error::Problem;

/// The most rows (readings) a readings file may have: 4 million, about what
/// a 64 MiB file of short rows holds.
pub const MAX_ROWS: usize = 4_000_000;

/// The separator of a file: a semicolon if its first line has one, else a
/// comma.
pub(super) fn delimiter(text: &str) -> char {
    let first = text.lines().next().unwrap_or("");
    if first.contains(';') {
        ';'
    } else {
        ','
    }
}

/// The records of `text` (the header and at most `max_rows` rows after it;
/// blank lines do not count), or the one problem that stops the reading: a
/// quote not closed, or more rows than the limit.
pub(super) fn records(
    text: &str,
    delimiter: char,
    max_rows: usize,
) -> Result<Vec<tokens::Record>, Problem> {
    tokens::records(text, delimiter, max_rows.saturating_add(1)).map_err(|e| match e {
        tokens::Fault::Quote(e) => Problem {
            line_column: Some((e.line, e.column)),
            message: e.message.to_owned(),
        },
        tokens::Fault::TooMany => Problem::new(format!(
            "more than the limit of {max_rows} readings (rows after the header; blank lines do not count)"
        )),
    })
}

/// The header's names: trimmed, in lower case.
pub(super) fn names(header: &tokens::Record) -> Vec<String> {
    header
        .fields
        .iter()
        .map(|f| f.text.trim().to_ascii_lowercase())
        .collect()
}

/// The header as written, shortened, for a message.
pub(super) fn given(header: &tokens::Record, delimiter: char) -> String {
    let given = header
        .fields
        .iter()
        .map(|f| f.text.as_str())
        .collect::<Vec<_>>()
        .join(&delimiter.to_string());
    shorten(&given)
}

/// A value: a finite number within the range; in a semicolon file, a
/// decimal comma counts as a decimal point.
pub(super) fn number(delimiter: char, text: &str) -> Result<f64, String> {
    let text = text.trim();
    let decimal = if delimiter == ';' && text.contains(',') && !text.contains('.') {
        text.replacen(',', ".", 1)
    } else {
        text.to_owned()
    };
    match decimal.parse::<f64>() {
        Ok(x) if x.is_finite() && x.abs() <= MAX_MAGNITUDE => Ok(x),
        Ok(x) if x.is_finite() => Err(format!("{} is outside [-1e150, 1e150]", Num(x))),
        // A number beyond the range of a float (`1e309`) reads as
        // infinite; `inf` and `NaN` are not numbers of a reading.
        Ok(x) if x.is_infinite() && !decimal.to_ascii_lowercase().contains("inf") => {
            Err(format!("{} is outside [-1e150, 1e150]", shorten(text)))
        }
        _ if text.is_empty() => Err("empty; every reading needs a number".into()),
        _ => Err(format!("`{}` is not a number", shorten(text))),
    }
}

/// Text from the file in a message: at most 40 characters, control
/// characters escaped, so that a hostile file cannot write to a terminal.
pub(super) fn shorten(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars().take(40) {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    if text.chars().count() > 40 {
        out.push('…');
    }
    out
}

/// `problems`, at most [`MAX_PROBLEMS`](crate::limits::MAX_PROBLEMS) of them,
/// then a count of the rest ("at least" when the reader stopped at
/// [`MAX_PROBLEMS_FOUND`](crate::limits::MAX_PROBLEMS_FOUND)).
pub(super) fn capped(mut problems: Vec<Problem>) -> Vec<Problem> {
    let limit = crate::limits::MAX_PROBLEMS;
    if problems.len() > limit {
        let more = problems.len() - limit;
        let stopped = problems.len() > crate::limits::MAX_PROBLEMS_FOUND;
        problems.truncate(limit);
        problems.push(Problem::new(crate::limits::more_problems(more, stopped)));
    }
    problems
}
