//! NaN and infinity where a number belongs: JSON cannot hold them, but
//! `json.dumps` (a job given to Python as a dict) and other writers put the
//! words `NaN`, `Infinity` and `-Infinity` in their place. A text that is
//! JSON but for those words is not a syntax error to its writer: each word
//! is a problem named by its place and the rule
//! ([`NOT_FINITE_RULE`](super::schema::NOT_FINITE_RULE)), at the line and
//! column where the validator places a value (the key of an object member,
//! else the value): `points[1].x.crisp: NaN is not a finite number (NaN and
//! infinity are refused)`. The same lines for a file read by the command
//! line and for a dict given to Python.

use std::collections::HashSet;
use std::ops::Range;

use super::position::scan;
use super::schema::NOT_FINITE_RULE;
use crate::error::Problem;
use crate::limits::more_problems;

/// The problems of the words `NaN`, `Infinity` and `-Infinity` in `text`
/// (without a byte-order mark) when it is JSON but for them: each named by
/// its place and the rule, at most [`MAX_PROBLEMS`](crate::limits::MAX_PROBLEMS),
/// then a count of the others. Empty when the text has none of the words, or
/// is not JSON even without them (a syntax error, reported as such).
///
/// # Examples
/// ```
/// let text = "{\"alpha\": NaN,\n \"weights\": [1, -Infinity]}";
/// let lines: Vec<String> = t2spline_io::job::non_finite(text)
///     .iter()
///     .map(|p| format!("{:?}: {}", p.line_column, p.message))
///     .collect();
/// assert_eq!(lines, [
///     "Some((1, 2)): alpha: NaN is not a finite number (NaN and infinity are refused)",
///     "Some((2, 17)): weights[1]: -inf is not a finite number (NaN and infinity are refused)",
/// ]);
/// assert!(t2spline_io::job::non_finite("{\"alpha\": NaN,}").is_empty()); // a syntax error
/// ```
#[must_use]
pub fn non_finite(text: &str) -> Vec<Problem> {
    if !text.contains("NaN") && !text.contains("Infinity") {
        return Vec::new();
    }
    let found = scan(text, &HashSet::new());
    if found.words.is_empty() || !json_without(text, &found.words) {
        return Vec::new();
    }
    let mut problems: Vec<Problem> = found
        .non_finite
        .iter()
        .map(|w| {
            let place = if w.path.is_empty() {
                String::new()
            } else {
                format!("{}: ", w.path)
            };
            Problem {
                line_column: Some(w.at),
                message: format!("{place}{} {NOT_FINITE_RULE}", w.shown),
            }
        })
        .collect();
    if found.more_non_finite > 0 {
        problems.push(Problem {
            line_column: None,
            message: more_problems(found.more_non_finite, false),
        });
    }
    problems
}

/// Whether `text` is JSON with each of the `words` (byte ranges, in
/// order) read as a number.
fn json_without(text: &str, words: &[Range<usize>]) -> bool {
    let mut plain = String::with_capacity(text.len());
    let mut from = 0;
    for w in words {
        plain.push_str(text.get(from..w.start).unwrap_or_default());
        plain.push('0');
        from = w.end;
    }
    plain.push_str(text.get(from..).unwrap_or_default());
    serde_json::from_str::<serde::de::IgnoredAny>(&plain).is_ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &str) -> Vec<String> {
        non_finite(text)
            .iter()
            .map(|p| match p.line_column {
                Some((l, c)) => format!("{l}:{c}: {}", p.message),
                None => p.message.clone(),
            })
            .collect()
    }

    #[test]
    fn each_word_is_named_at_its_key_or_element() {
        let text = "{\n  \"points\": [\n    {\n      \"x\": {\n        \"crisp\": NaN,\n        \"upper\": [\n          -Infinity,\n          Infinity\n        ]\n      }\n    }\n  ],\n  \"weights\": [1, Infinity]\n}";
        assert_eq!(
            lines(text),
            [
                "5:9: points[0].x.crisp: NaN is not a finite number (NaN and infinity are refused)",
                "7:11: points[0].x.upper[0]: -inf is not a finite number (NaN and infinity are refused)",
                "8:11: points[0].x.upper[1]: inf is not a finite number (NaN and infinity are refused)",
                "13:18: weights[1]: inf is not a finite number (NaN and infinity are refused)",
            ]
        );
    }

    #[test]
    fn words_inside_strings_and_negative_numbers_are_not_numbers() {
        assert!(lines("{\"description\": \"NaN \\\" Infinity\", \"alpha\": -0.5}").is_empty());
        assert!(lines("{\"NaN\": [1, -2]}").is_empty());
        // An odd key is written as the validator writes it.
        assert_eq!(
            lines("{\"a\\u00e9\": NaN}"),
            ["1:2: [\"a\u{e9}\"]: NaN is not a finite number (NaN and infinity are refused)"]
        );
    }

    #[test]
    fn a_text_broken_besides_the_words_is_left_to_the_syntax_error() {
        assert!(lines("{\"alpha\": NaN,}").is_empty());
        assert!(lines("{\"alpha\": NaNa}").is_empty());
        assert!(lines("{\"alpha\": Infinity").is_empty());
        assert_eq!(
            lines("NaN"),
            ["1:1: NaN is not a finite number (NaN and infinity are refused)"]
        );
    }

    #[test]
    fn past_the_limit_the_others_are_counted() {
        let many = vec!["NaN"; crate::limits::MAX_PROBLEMS + 3].join(", ");
        let got = lines(&format!("[{many}]"));
        assert_eq!(got.len(), crate::limits::MAX_PROBLEMS + 1);
        assert_eq!(
            got.last().map(String::as_str),
            Some(crate::limits::more_problems(3, false).as_str())
        );
    }
}
