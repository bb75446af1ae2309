//! The files a reader can download at each stop: the result file of
//! `t2spline run --alpha A` and its CSV files, written by the same functions
//! (`write_json_pretty`, `render_csv`), byte for byte.
//!
//! At every stop these files have the same text around different numbers, so
//! each is stored as templates (the text between the numbers that change,
//! one template per regime, whose structure differs) and per stop the
//! numbers that change, as the writer wrote them. The page joins a template
//! with a stop's numbers; it computes nothing.

use serde_json::{json, Value};
use t2spline::job::RunOutput;

use crate::Error;

/// The result file and the CSV files of `result`, as `(name, text)`.
///
/// # Errors
/// [`Error::Io`] if a number is not finite (never for a validated job).
pub fn files_of(result: &RunOutput) -> Result<Vec<(String, String)>, Error> {
    t2spline_io::check_finite(result)?;
    let mut json = Vec::new();
    // Writing to memory cannot fail, and a result has only string keys.
    t2spline_io::write_json_pretty(&mut json, result).expect("a result as JSON in memory");
    let mut out = vec![(
        "result.json".to_owned(),
        String::from_utf8_lossy(&json).into_owned(),
    )];
    out.extend(
        t2spline_io::render_csv(result)
            .into_iter()
            .map(|(name, text)| (name.to_owned(), text)),
    );
    Ok(out)
}

/// A text cut at its numbers: the literal pieces around them and the
/// numbers (`null` counts as one), outside JSON strings.
fn tokens(text: &str) -> (Vec<&str>, Vec<&str>) {
    let b = text.as_bytes();
    let (mut lits, mut nums) = (Vec::new(), Vec::new());
    let (mut start, mut i, mut in_string) = (0, 0, false);
    while i < b.len() {
        let c = b[i];
        if in_string {
            match c {
                b'\\' => i += 1,
                b'"' => in_string = false,
                _ => {}
            }
            i += 1;
            continue;
        }
        let boundary =
            i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_' || b[i - 1] == b'.');
        let number =
            c.is_ascii_digit() || (c == b'-' && b.get(i + 1).is_some_and(u8::is_ascii_digit));
        if c == b'"' {
            in_string = true;
            i += 1;
        } else if boundary && number {
            let mut j = i + 1;
            while j < b.len() && matches!(b[j], b'0'..=b'9' | b'.' | b'e' | b'E' | b'+' | b'-') {
                j += 1;
            }
            lits.push(&text[start..i]);
            nums.push(&text[i..j]);
            start = j;
            i = j;
        } else if boundary
            && text[i..].starts_with("null")
            && !b.get(i + 4).is_some_and(|c| c.is_ascii_alphanumeric())
        {
            lits.push(&text[start..i]);
            nums.push(&text[i..i + 4]);
            start = i + 4;
            i += 4;
        } else {
            i += 1;
        }
    }
    lits.push(&text[start..]);
    (lits, nums)
}

/// `texts` (one file at every stop) as templates and, per stop, a template
/// index and the numbers that fill its holes:
/// `{"name", "templates": [[piece, …], …], "stops": [[template, [number, …]], …]}`;
/// a template's pieces and a stop's numbers alternate, pieces first and last.
#[must_use]
pub fn pack(name: &str, texts: &[String]) -> Value {
    let cut: Vec<(Vec<&str>, Vec<&str>)> = texts.iter().map(|t| tokens(t)).collect();
    // Stops whose literal text agrees share a template.
    let mut groups: Vec<(Vec<&str>, Vec<usize>)> = Vec::new();
    for (k, (lits, _)) in cut.iter().enumerate() {
        match groups.iter_mut().find(|(l, _)| l == lits) {
            Some((_, members)) => members.push(k),
            None => groups.push((lits.clone(), vec![k])),
        }
    }
    let mut templates = Vec::new();
    let mut stops = vec![Value::Null; texts.len()];
    for (t, (lits, members)) in groups.iter().enumerate() {
        let first = &cut[members[0]].1;
        let holes: Vec<usize> = (0..first.len())
            .filter(|&i| members.iter().any(|&k| cut[k].1[i] != first[i]))
            .collect();
        // Numbers that never change join the text around them.
        let mut pieces = vec![String::new()];
        for (i, lit) in lits.iter().enumerate() {
            if let Some(p) = pieces.last_mut() {
                p.push_str(lit);
            }
            if i < first.len() {
                if holes.binary_search(&i).is_ok() {
                    pieces.push(String::new());
                } else if let Some(p) = pieces.last_mut() {
                    p.push_str(first[i]);
                }
            }
        }
        templates.push(json!(pieces));
        for &k in members {
            let values: Vec<&str> = holes.iter().map(|&i| cut[k].1[i]).collect();
            stops[k] = json!([t, values]);
        }
    }
    json!({"name": name, "templates": templates, "stops": stops})
}

/// The text of stop `k` from [`pack`]'s form, as the page assembles it.
#[must_use]
pub fn unpack(packed: &Value, k: usize) -> Option<String> {
    let stop = packed["stops"].get(k)?;
    let pieces = packed["templates"]
        .get(stop[0].as_u64()? as usize)?
        .as_array()?;
    let values = stop[1].as_array()?;
    let mut s = String::new();
    for (i, p) in pieces.iter().enumerate() {
        s.push_str(p.as_str()?);
        if let Some(v) = values.get(i) {
            s.push_str(v.as_str()?);
        }
    }
    Some(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texts_come_back_byte_for_byte() {
        let texts = vec![
            "{\"a\": [1.5, -2e-7, null],\n \"s\": \"x 0.5 \\\" 7\", \"k\": 3}\n".to_owned(),
            "{\"a\": [1.25, -2e-7, 4],\n \"s\": \"x 0.5 \\\" 7\", \"k\": 3}\n".to_owned(),
            "{\"a\": [1.5, -3, null, 9],\n \"s\": \"x 0.5 \\\" 7\", \"k\": 3}\n".to_owned(),
            "t,x_1\n0,0.1\n1,0.2\n".to_owned(),
        ];
        let packed = pack("f", &texts);
        for (k, t) in texts.iter().enumerate() {
            assert_eq!(unpack(&packed, k).as_deref(), Some(t.as_str()), "stop {k}");
        }
        // The first two share a template with holes only where they differ.
        assert_eq!(packed["stops"][0], json!([0, ["1.5", "null"]]));
        assert_eq!(packed["stops"][1], json!([0, ["1.25", "4"]]));
        let (_, nums) = tokens(&texts[0]);
        assert_eq!(
            nums,
            ["1.5", "-2e-7", "null", "3"],
            "no numbers inside strings"
        );
    }
}
