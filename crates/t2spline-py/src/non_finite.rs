//! NaN and infinity in a job given as a dict: `json.dumps` writes them as
//! the bare words `NaN`, `Infinity` and `-Infinity`, which are not JSON, so
//! the validator would see a syntax error in a text the user never wrote.
//! They are found here first, each named by its place in the job and the
//! rule, at its line and column of the `json.dumps(job, indent=2)` text as
//! every other problem of a dict job: `<dict>:47:9: points[1].x.crisp: NaN
//! is not a finite number (NaN and infinity are refused)`.

use t2spline_io::job::MAX_PROBLEMS;
use t2spline_io::Problem;

/// An object (with the key of the member being read, and whether a key comes
/// next) or an array (with the index of the element being read).
enum Frame {
    Object {
        key: String,
        expect_key: bool,
        at: (usize, usize),
    },
    Array {
        index: usize,
        at: (usize, usize),
    },
}

/// The path of the value being read, as the validator writes places:
/// `points[1].x.crisp`.
fn path(stack: &[Frame]) -> String {
    let mut out = String::new();
    for frame in stack {
        match frame {
            Frame::Object { key, .. } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(key);
            }
            Frame::Array { index, .. } => out.push_str(&format!("[{index}]")),
        }
    }
    out
}

/// The problems of the non-finite numbers in `text`, the JSON that
/// `json.dumps` wrote for a dict job (valid JSON but for those words); none
/// for a text without them. As the validator's, each is placed at the key of
/// its object member or at its array element, and at most
/// [`MAX_PROBLEMS`] are listed.
pub(crate) fn problems(text: &str) -> Vec<Problem> {
    if !text.contains("NaN") && !text.contains("Infinity") {
        return Vec::new();
    }
    let mut found = Vec::new();
    let mut count = 0usize;
    let mut stack: Vec<Frame> = Vec::new();
    let (mut line, mut column) = (1usize, 0usize);
    let mut chars = text.chars().peekable();
    // The start of the last element of an array (set at `[` and `,`).
    let mut element_start = false;
    while let Some(c) = chars.next() {
        if c == '\n' {
            (line, column) = (line + 1, 0);
            continue;
        }
        column += 1;
        let here = (line, column);
        if element_start && !c.is_whitespace() {
            element_start = false;
            if let Some(Frame::Array { at, .. }) = stack.last_mut() {
                *at = here;
            }
        }
        match c {
            '"' => {
                // A string: the key of a member, or a value.
                let mut raw = String::from('"');
                while let Some(s) = chars.next() {
                    column += 1;
                    raw.push(s);
                    match s {
                        '\\' => {
                            if let Some(e) = chars.next() {
                                column += 1;
                                raw.push(e);
                            }
                        }
                        '"' => break,
                        _ => {}
                    }
                }
                if let Some(Frame::Object {
                    key,
                    expect_key: expect @ true,
                    at,
                }) = stack.last_mut()
                {
                    *key = serde_json::from_str::<String>(&raw).unwrap_or(raw);
                    *expect = false;
                    *at = here;
                }
            }
            '{' => stack.push(Frame::Object {
                key: String::new(),
                expect_key: true,
                at: here,
            }),
            '[' => {
                stack.push(Frame::Array { index: 0, at: here });
                element_start = true;
            }
            '}' | ']' => {
                stack.pop();
            }
            ',' => match stack.last_mut() {
                Some(Frame::Array { index, .. }) => {
                    *index += 1;
                    element_start = true;
                }
                Some(Frame::Object { expect_key, .. }) => *expect_key = true,
                None => {}
            },
            'N' | 'I' | '-' => {
                let negative = c == '-';
                if negative && chars.peek() != Some(&'I') {
                    continue;
                }
                let word = if c == 'N' { "NaN" } else { "Infinity" };
                let rest = word.len() - usize::from(!negative);
                for _ in 0..rest {
                    chars.next();
                }
                column += rest;
                count += 1;
                if found.len() < MAX_PROBLEMS {
                    let value = match (c, negative) {
                        ('N', _) => "NaN",
                        (_, true) => "-inf",
                        _ => "inf",
                    };
                    let at = match stack.last() {
                        Some(Frame::Object { at, .. } | Frame::Array { at, .. }) => *at,
                        None => here,
                    };
                    let place = match path(&stack) {
                        p if p.is_empty() => String::new(),
                        p => format!("{p}: "),
                    };
                    found.push(Problem {
                        line_column: Some(at),
                        message: format!(
                            "{place}{value} is not a finite number (NaN and infinity are refused)"
                        ),
                    });
                }
            }
            _ => {}
        }
    }
    if count > found.len() {
        found.push(Problem {
            line_column: None,
            message: t2spline_io::job::more_problems(count - found.len(), false),
        });
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &str) -> Vec<String> {
        problems(text)
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
        assert_eq!(
            lines("{\"a\\u00e9\": NaN}"),
            ["1:2: a\u{e9}: NaN is not a finite number (NaN and infinity are refused)"]
        );
    }
}
