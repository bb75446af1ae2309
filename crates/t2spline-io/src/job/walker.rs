//! The validator's state and its walkers of JSON values: objects, keys,
//! numbers, whole numbers, arrays of numbers and pairs, each reporting what
//! it finds wrong at its JSON path. Shared by the rules of curves
//! ([`parse`](super::parse)) and of surfaces ([`surface`](super::surface)).

use serde_json::{Map, Value};

use super::place::{child, element};
use crate::limits::MAX_PROBLEMS;

/// The validator's state: the first [`MAX_PROBLEMS`] problems, as (JSON path,
/// message), how many more there were, and how messages name the root.
pub(super) struct Walker {
    pub(super) problems: Vec<(String, String)>,
    pub(super) more: usize,
    /// `"job"` or `"data"`.
    pub(super) root: &'static str,
    /// Top-level keys of a job that this file refuses with a message of its
    /// own (a data file's `weights` and `knots`): not reported again as
    /// unknown, and never offered as known keys.
    pub(super) refused: &'static [&'static str],
}

impl Default for Walker {
    fn default() -> Self {
        Walker {
            problems: Vec::new(),
            more: 0,
            root: "job",
            refused: &[],
        }
    }
}

impl Walker {
    /// Whether the list is full; a problem then only counts.
    pub(super) fn full(&mut self) -> bool {
        let full = self.problems.len() >= MAX_PROBLEMS;
        self.more += usize::from(full);
        full
    }

    /// A problem at `path`, shown as `path: rule` (the root as `job` or
    /// `data`).
    pub(super) fn report(&mut self, path: &str, rule: impl std::fmt::Display) {
        if !self.full() {
            let shown = if path.is_empty() { self.root } else { path };
            self.problems
                .push((path.to_owned(), format!("{shown}: {rule}")));
        }
    }

    /// A problem at `path` whose message names its place itself (the errors
    /// of the core crate).
    pub(super) fn located(&mut self, path: &str, message: impl std::fmt::Display) {
        if !self.full() {
            self.problems.push((path.to_owned(), message.to_string()));
        }
    }

    pub(super) fn object<'v>(
        &mut self,
        v: &'v Value,
        key: &str,
        what: &str,
    ) -> Option<&'v Map<String, Value>> {
        let o = v.as_object();
        if o.is_none() {
            self.report(
                key,
                format!("expected {what} (a JSON object), got {}", kind(v)),
            );
        }
        o
    }

    pub(super) fn unknown_keys(
        &mut self,
        o: &Map<String, Value>,
        prefix: &str,
        known: &[&'static str],
    ) {
        let refused: &[&str] = if prefix.is_empty() { self.refused } else { &[] };
        for k in o
            .keys()
            .filter(|k| !known.contains(&k.as_str()) && !refused.contains(&k.as_str()))
        {
            let path = child(prefix, k);
            match suggestion(k, known) {
                Some(s) => self.report(&path, format!("unknown key (did you mean `{s}`?)")),
                None => self.report(
                    &path,
                    format!("unknown key (known keys: {})", known.join(", ")),
                ),
            }
        }
    }

    pub(super) fn boolean(&mut self, v: &Value, key: &str) -> Option<bool> {
        let b = v.as_bool();
        if b.is_none() {
            self.report(key, format!("expected true or false, got {}", kind(v)));
        }
        b
    }

    pub(super) fn number(&mut self, v: &Value, key: &str) -> Option<f64> {
        let x = v.as_f64();
        if x.is_none() {
            self.report(key, format!("expected a number, got {}", kind(v)));
        }
        x
    }

    /// A whole number ≥ 0; `3.0` is accepted as 3, as spreadsheets write it,
    /// and a whole number beyond `u64` (`1e30`) saturates, to be refused by a
    /// limit.
    pub(super) fn whole(&mut self, v: &Value, key: &str) -> Option<u64> {
        if let Some(n) = v.as_u64() {
            return Some(n);
        }
        match v.as_f64() {
            // `as` saturates at u64::MAX.
            Some(x) if x >= 0.0 && x.fract() == 0.0 => Some(x as u64),
            Some(x) => {
                self.report(
                    key,
                    format!("expected a whole number >= 0, got {}", t2spline::Num(x)),
                );
                None
            }
            None => {
                self.report(key, format!("expected a whole number, got {}", kind(v)));
                None
            }
        }
    }

    pub(super) fn numbers(&mut self, v: &Value, key: &str) -> Option<Vec<f64>> {
        let Some(items) = v.as_array() else {
            self.report(
                key,
                format!("expected an array of numbers, got {}", kind(v)),
            );
            return None;
        };
        let xs: Vec<Option<f64>> = items
            .iter()
            .enumerate()
            .map(|(i, x)| self.number(x, &element(key, i)))
            .collect();
        xs.into_iter().collect()
    }

    pub(super) fn pair(&mut self, v: &Value, key: &str) -> Option<[f64; 2]> {
        match v.as_array().map(Vec::as_slice) {
            Some([l, r]) => {
                let l = self.number(l, &element(key, 0));
                let r = self.number(r, &element(key, 1));
                Some([l?, r?])
            }
            _ => {
                self.report(
                    key,
                    format!(
                        "expected [left, right], an array of two numbers, got {}",
                        describe(v)
                    ),
                );
                None
            }
        }
    }
}

/// What kind of JSON value `v` is, for messages.
pub(super) fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The known key closest to `key` by edit distance, if it is a likely typo.
pub(super) fn suggestion(key: &str, known: &[&'static str]) -> Option<&'static str> {
    // Edit distance costs len(key)·len(known): a megabyte-long key is no typo.
    if key.chars().count() > 32 {
        return None;
    }
    known
        .iter()
        .map(|k| (edit_distance(key, k), *k))
        .filter(|(d, k)| *d <= 2 && *d < k.len())
        .min()
        .map(|(_, k)| k)
}

/// Levenshtein distance with adjacent transpositions counting 1 (optimal string
/// alignment), so that `alhpa` is one step from `alpha`.
// Every index lies in the table (`i ≤ a.len()`, `j ≤ b.len()`) or in the
// words (`i − 1 < a.len()`, and `i − 2`, `j − 2` only when `i, j > 1`).
#[allow(clippy::indexing_slicing)]
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            d[i][j] = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d[i][j] = d[i][j].min(d[i - 2][j - 2] + 1);
            }
        }
    }
    d[a.len()][b.len()]
}

/// A number as the file wrote it, near enough: `3`, `1e300`.
pub(super) fn written(v: &Value) -> String {
    match (v.as_u64(), v.as_f64()) {
        (Some(n), _) => n.to_string(),
        (None, Some(x)) => t2spline::Num(x).to_string(),
        _ => v.to_string(),
    }
}

/// Short description of a value that should have been a pair.
pub(super) fn describe(v: &Value) -> String {
    match v.as_array() {
        Some(a) => format!("an array of {} values", a.len()),
        None => kind(v).to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edit_distance_counts_transpositions_once() {
        assert_eq!(edit_distance("alhpa", "alpha"), 1);
        assert_eq!(edit_distance("wieghts", "weights"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
        let known = &["alpha", "samples", "points"];
        assert_eq!(suggestion("sample", known), Some("samples"));
        assert_eq!(suggestion("colour", known), None);
    }
}
