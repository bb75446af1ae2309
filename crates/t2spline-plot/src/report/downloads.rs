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

use crate::error::Error;

/// The result file and the CSV files of `result`, as `(name, text)`.
///
/// # Errors
/// [`Error::Io`] if a number is not finite (never for a validated job).
pub fn files_of(result: &RunOutput) -> Result<Vec<(String, String)>, Error> {
    t2spline_io::check_finite(result)?;
    let mut json = Vec::new();
    // Writing to memory cannot fail, and a result has only string keys.
    #[allow(clippy::expect_used)]
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

/// One file cut into templates: per stop its template and the numbers
/// that fill the template's holes.
struct Cut<'a> {
    templates: Vec<Vec<String>>,
    stops: Vec<(usize, Vec<&'a str>)>,
}

/// `texts` (one file at every stop) as templates (the text between the
/// numbers that change; stops whose text around the numbers agrees share
/// one) and, per stop, a template and its numbers.
fn cut(texts: &[String]) -> Cut<'_> {
    let cut: Vec<(Vec<&str>, Vec<&str>)> = texts.iter().map(|t| tokens(t)).collect();
    let mut groups: Vec<(&Vec<&str>, Vec<usize>)> = Vec::new();
    for (k, (lits, _)) in cut.iter().enumerate() {
        match groups.iter_mut().find(|(l, _)| *l == lits) {
            Some((_, members)) => members.push(k),
            None => groups.push((lits, vec![k])),
        }
    }
    let mut out = Cut {
        templates: Vec::new(),
        stops: vec![(0, Vec::new()); texts.len()],
    };
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
        out.templates.push(pieces);
        for &k in members {
            out.stops[k] = (t, holes.iter().map(|&i| cut[k].1[i]).collect());
        }
    }
    out
}

/// Downloadable files (name, text at each stop) in the form the page reads:
///
/// ```text
/// {"files": [{"name", "templates": [[piece, …], …]}, …],
///  "stops": [{"t": [template of each file], "v": [entry, …]}, …]}
/// ```
/// A template's pieces alternate with a stop's numbers, pieces first and
/// last. A stop's numbers for all its files, in file order, are its entries:
/// a string is the next number (and joins the stop's table of numbers); an
/// integer `d` repeats an earlier number, the one `d` places after the last
/// repeated in that table. The CSV files repeat the result file's curves, so
/// most of their numbers cost a small, regular integer.
#[must_use]
pub fn pack(files: &[(String, Vec<String>)]) -> Value {
    let cuts: Vec<Cut<'_>> = files.iter().map(|(_, texts)| cut(texts)).collect();
    let stops = files.first().map_or(0, |(_, t)| t.len());
    let packed_stops: Vec<Value> = (0..stops)
        .map(|k| {
            let mut table: std::collections::HashMap<&str, i64> = std::collections::HashMap::new();
            let (mut entries, mut count, mut last) = (Vec::new(), 0i64, 0i64);
            for c in &cuts {
                for &s in &c.stops[k].1 {
                    match table.get(s) {
                        Some(&i) if s.len() > 4 => {
                            entries.push(json!(i - last));
                            last = i;
                        }
                        _ => {
                            table.insert(s, count);
                            count += 1;
                            entries.push(json!(s));
                        }
                    }
                }
            }
            let t: Vec<usize> = cuts.iter().map(|c| c.stops[k].0).collect();
            json!({"t": t, "v": entries})
        })
        .collect();
    let files: Vec<Value> = files
        .iter()
        .zip(&cuts)
        .map(|((name, _), c)| json!({"name": name, "templates": c.templates}))
        .collect();
    json!({"files": files, "stops": packed_stops})
}

/// The text of file `name` at stop `k` from [`pack`]'s form, as the page
/// assembles it.
#[cfg(test)]
#[must_use]
pub fn unpack(packed: &Value, name: &str, k: usize) -> Option<String> {
    let stop = packed["stops"].get(k)?;
    let (mut table, mut values, mut last) = (Vec::new(), Vec::new(), 0i64);
    for e in stop["v"].as_array()? {
        match e.as_str() {
            Some(s) => {
                table.push(s.to_owned());
                values.push(s.to_owned());
            }
            None => {
                last += e.as_i64()?;
                values.push(table.get(usize::try_from(last).ok()?)?.clone());
            }
        }
    }
    let mut values = values.into_iter();
    for (f, file) in packed["files"].as_array()?.iter().enumerate() {
        let t = stop["t"].get(f)?.as_u64()? as usize;
        let pieces = file["templates"].get(t)?.as_array()?;
        let mut s = String::new();
        for (i, p) in pieces.iter().enumerate() {
            s.push_str(p.as_str()?);
            if i + 1 < pieces.len() {
                s.push_str(&values.next()?);
            }
        }
        if file["name"] == name {
            return Some(s);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texts_come_back_byte_for_byte() {
        let json = vec![
            "{\"a\": [1.5, -2e-7, null],\n \"s\": \"x 0.5 \\\" 7\", \"k\": 3}\n".to_owned(),
            "{\"a\": [1.255, -2e-7, 4],\n \"s\": \"x 0.5 \\\" 7\", \"k\": 3}\n".to_owned(),
            "{\"a\": [1.5, -3, null, 9],\n \"s\": \"x 0.5 \\\" 7\", \"k\": 3}\n".to_owned(),
        ];
        let csv = vec![
            "t,x_1\n0,1.5\n1,0.2\n".to_owned(),
            "t,x_1\n0,1.255\n1,0.25\n".to_owned(),
            "t,x_1\n0,1.5\n1,0.2\n".to_owned(),
        ];
        let files = vec![
            ("r.json".to_owned(), json.clone()),
            ("c.csv".to_owned(), csv.clone()),
        ];
        let packed = pack(&files);
        for k in 0..3 {
            assert_eq!(
                unpack(&packed, "r.json", k).as_deref(),
                Some(json[k].as_str()),
                "stop {k}"
            );
            assert_eq!(
                unpack(&packed, "c.csv", k).as_deref(),
                Some(csv[k].as_str()),
                "stop {k}"
            );
        }
        // The first two share a template with holes only where they differ;
        // the CSV's 1.255 repeats the result's (the first number of the stop).
        assert_eq!(packed["stops"][0]["t"], json!([0, 0]));
        assert_eq!(packed["stops"][1]["v"], json!(["1.255", "4", 0, "0.25"]));
        let (_, nums) = tokens(&json[0]);
        assert_eq!(
            nums,
            ["1.5", "-2e-7", "null", "3"],
            "no numbers inside strings"
        );
    }
}
