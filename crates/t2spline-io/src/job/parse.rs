//! The job-file validator: walks the JSON value and collects every problem.
//!
//! Parsing goes through `serde_json::Value` rather than derived structs so that
//! one pass can report *every* problem (serde stops at the first) and name each
//! by its place in the file. Each problem is found at a JSON path
//! (`points[2].y.upper[0]`); one scan of the text ([`position`](super::position))
//! then turns the paths into lines and columns and finds duplicate keys.

use std::collections::HashSet;

use serde_json::{Map, Value};
use t2spline::fit::FuzzyData;
use t2spline::job::{check_samples, Job, Model, Samples, DEFAULT_SAMPLES};
use t2spline::{
    Alpha, Axis, FuzzyCurve, Height, KnotVector, Nt2Number, Nt2Point, Place, TypeReduction,
};

use super::limits::{
    check_order, MAX_ARRAY, MAX_KEYS, MAX_NESTING, MAX_POINTS, MAX_PROBLEMS, MAX_VALUES,
};
use super::position::{self, child, element, Oversized};
use crate::fit_data::FitData;
use crate::{printable, Problem};

const TOP_KEYS: &[&str] = &[
    "description",
    "order",
    "degree",
    "weights",
    "knots",
    "alpha",
    "type_reduction",
    "lower_height",
    "samples",
    "points",
];
/// The keys of a data file for `t2spline fit`: those of a job but the two the
/// fit computes.
const DATA_KEYS: &[&str] = &[
    "description",
    "order",
    "degree",
    "alpha",
    "lower_height",
    "samples",
    "points",
];
const POINT_KEYS: &[&str] = &["x", "y", "z"];
const NUMBER_KEYS: &[&str] = &["crisp", "upper", "primary", "lower", "lower_height"];

/// Parses `text` as a job, or returns every problem found, each with its line
/// and column.
pub(super) fn parse(text: &str) -> Result<Job, Vec<Problem>> {
    walk(text, Walker::job)
}

/// Parses `text` as a data file for fitting, or returns every problem found,
/// each with its line and column.
pub(crate) fn parse_data(text: &str) -> Result<FitData, Vec<Problem>> {
    walk(text, Walker::data)
}

/// Parses `text` as JSON and reads it with `read`, collecting every problem
/// (at most [`MAX_PROBLEMS`], then a count) and placing each at its line and
/// column.
fn walk<T>(
    text: &str,
    read: impl FnOnce(&mut Walker, &Value) -> Option<T>,
) -> Result<T, Vec<Problem>> {
    // Spreadsheet programs start UTF-8 files with a byte-order mark; editors
    // do not show it, so columns are counted without it.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if let Some(found) = position::oversized(text, MAX_ARRAY, MAX_KEYS, MAX_VALUES) {
        let (at, message) = match found {
            Oversized::Array(at) => (
                at,
                format!(
                    "an array of more than {MAX_ARRAY} entries: no job or data file needs more \
                 ({MAX_POINTS} points, {MAX_ARRAY} knots)"
                ),
            ),
            Oversized::Object(at) => (
                at,
                format!(
                    "an object of more than {MAX_KEYS} keys: no job or data file needs more than 9"
                ),
            ),
            Oversized::Values(at) => (
                at,
                format!(
                    "more than {MAX_VALUES} JSON values: a 3-D job of {MAX_POINTS} points needs \
                 at most 3.9 million"
                ),
            ),
        };
        return Err(vec![Problem {
            line_column: Some(at),
            message,
        }]);
    }
    let value: Value = serde_json::from_str(text).map_err(|e| vec![syntax_problem(text, &e)])?;
    let mut w = Walker::default();
    let out = read(&mut w, &value);
    let wanted: HashSet<String> = w.problems.iter().map(|(path, _)| path.clone()).collect();
    let scan = position::scan(text, &wanted);
    let mut problems: Vec<Problem> = scan
        .duplicates
        .iter()
        .take(MAX_PROBLEMS)
        .map(|d| Problem {
            line_column: Some(d.at),
            message: format!(
                "{}: duplicate key (first at line {}, column {}); each key may appear once",
                d.path, d.first.0, d.first.1
            ),
        })
        .collect();
    let room = MAX_PROBLEMS - problems.len();
    let more = scan.duplicates.len().saturating_sub(MAX_PROBLEMS)
        + scan.more_duplicates
        + w.more
        + w.problems.len().saturating_sub(room);
    problems.extend(
        w.problems
            .into_iter()
            .take(room)
            .map(|(path, message)| Problem {
                line_column: Some(scan.locate(&path)),
                message,
            }),
    );
    if more > 0 {
        problems.push(Problem {
            line_column: None,
            message: format!(
                "… and {more} more problems (only the first {MAX_PROBLEMS} are listed)"
            ),
        });
    }
    match out {
        Some(out) if problems.is_empty() => Ok(out),
        _ => Err(problems),
    }
}

/// A JSON syntax error with its line and column (in characters), without
/// serde's own suffix, and in plain words for the errors a hostile file meets.
fn syntax_problem(text: &str, e: &serde_json::Error) -> Problem {
    let full = e.to_string();
    let suffix = format!(" at line {} column {}", e.line(), e.column());
    let message = full.strip_suffix(&suffix).unwrap_or(&full);
    let message = match message {
        "recursion limit exceeded" => {
            format!("arrays and objects nest deeper than {MAX_NESTING} levels (a job needs 4)")
        }
        "number out of range" => {
            "number out of range: beyond ±1.8e308, the range of a 64-bit float".to_owned()
        }
        m if looks_like_csv(text) => format!(
            "JSON syntax error: {m}; this looks like CSV (comma- or semicolon-separated values), not a JSON file: `t2spline fuzzify READINGS.csv -o DATA.json` turns repeated readings into a data file, and `t2spline fit READINGS.csv` fits them"
        ),
        m => format!("JSON syntax error: {m}"),
    };
    // serde_json counts bytes; editors count characters.
    let line = text
        .split('\n')
        .nth(e.line().saturating_sub(1))
        .unwrap_or("");
    let bytes = &line.as_bytes()[..e.column().min(line.len())];
    let column = String::from_utf8_lossy(bytes).chars().count().max(1);
    Problem {
        line_column: Some((e.line().max(1), column)),
        message,
    }
}

/// Whether `text` looks like a table of comma- or semicolon-separated values:
/// its first line is not JSON's `{` or `[` and has a separator, and the second
/// line (if any) has as many.
fn looks_like_csv(text: &str) -> bool {
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let Some(first) = lines.next() else {
        return false;
    };
    if first.starts_with(['{', '[']) {
        return false;
    }
    let count = |line: &str, sep: char| line.matches(sep).count();
    [',', ';'].into_iter().any(|sep| {
        let n = count(first, sep);
        n > 0
            && lines
                .clone()
                .next()
                .is_none_or(|second| count(second, sep) == n)
    })
}

/// What kind of JSON value `v` is, for messages.
fn kind(v: &Value) -> &'static str {
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
fn suggestion(key: &str, known: &[&'static str]) -> Option<&'static str> {
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

/// The fuzzy numbers of one point, per axis, once parsed.
type RawPoint = Vec<(Axis, Option<Nt2Number>)>;

/// The validator's state: the first [`MAX_PROBLEMS`] problems, as (JSON path,
/// message), how many more there were, and how messages name the root.
struct Walker {
    problems: Vec<(String, String)>,
    more: usize,
    /// `"job"` or `"data"`.
    root: &'static str,
}

impl Default for Walker {
    fn default() -> Self {
        Walker {
            problems: Vec::new(),
            more: 0,
            root: "job",
        }
    }
}

impl Walker {
    /// Whether the list is full; a problem then only counts.
    fn full(&mut self) -> bool {
        let full = self.problems.len() >= MAX_PROBLEMS;
        self.more += usize::from(full);
        full
    }

    /// A problem at `path`, shown as `path: rule` (the root as `job` or
    /// `data`).
    fn report(&mut self, path: &str, rule: impl std::fmt::Display) {
        if !self.full() {
            let shown = if path.is_empty() { self.root } else { path };
            self.problems
                .push((path.to_owned(), format!("{shown}: {rule}")));
        }
    }

    /// A problem at `path` whose message names its place itself (the errors
    /// of the core crate).
    fn located(&mut self, path: &str, message: impl std::fmt::Display) {
        if !self.full() {
            self.problems.push((path.to_owned(), message.to_string()));
        }
    }

    fn object<'v>(
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

    fn unknown_keys(&mut self, o: &Map<String, Value>, prefix: &str, known: &[&'static str]) {
        for k in o.keys().filter(|k| !known.contains(&k.as_str())) {
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

    fn number(&mut self, v: &Value, key: &str) -> Option<f64> {
        let x = v.as_f64();
        if x.is_none() {
            self.report(key, format!("expected a number, got {}", kind(v)));
        }
        x
    }

    /// A whole number ≥ 0; `3.0` is accepted as 3, as spreadsheets write it,
    /// and a whole number beyond `u64` (`1e30`) saturates, to be refused by a
    /// limit.
    fn whole(&mut self, v: &Value, key: &str) -> Option<u64> {
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

    fn numbers(&mut self, v: &Value, key: &str) -> Option<Vec<f64>> {
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

    fn pair(&mut self, v: &Value, key: &str) -> Option<[f64; 2]> {
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

    /// The keys a job and a data file share, checked against `known`.
    /// `missing_points` says what `points` holds, for its message.
    fn header(
        &mut self,
        o: &Map<String, Value>,
        known: &[&'static str],
        missing_points: &str,
    ) -> Header {
        self.unknown_keys(o, "", known);
        let description = match o.get("description") {
            None => None,
            Some(Value::String(s)) => Some(s.clone()),
            Some(v) => {
                self.report("description", format!("expected a string, got {}", kind(v)));
                None
            }
        };
        let degree = self.degree(o);
        let alpha = o.get("alpha").and_then(|v| {
            let a = self.number(v, "alpha")?;
            Alpha::try_new(a).map_err(|e| self.located("alpha", e)).ok()
        });
        // `Err(())`: a top-level height was given but is invalid (reported here
        // once, not again for every number that inherits it).
        let height: Result<Option<f64>, ()> = match o.get("lower_height") {
            None => Ok(None),
            Some(v) => match self.number(v, "lower_height").map(Height::try_new) {
                Some(Ok(h)) => Ok(Some(h.get())),
                Some(Err(e)) => {
                    self.located("lower_height", e);
                    Err(())
                }
                None => Err(()),
            },
        };
        let samples = match o.get("samples") {
            None => Some(None),
            Some(v) => self.whole(v, "samples").and_then(|n| {
                check_samples(n, &written(v))
                    .map_err(|rule| self.report("samples", rule))
                    .ok()
                    .map(Some)
            }),
        };
        let points = match o.get("points") {
            None => {
                self.report("points", format!("missing: {missing_points}"));
                None
            }
            Some(v) => self.points(v, height),
        };
        Header {
            description,
            degree_key: if o.contains_key("degree") {
                "degree"
            } else {
                "order"
            },
            degree,
            alpha,
            lower_height: height.ok().flatten(),
            samples,
            points,
            count: o.get("points").and_then(Value::as_array).map(Vec::len),
        }
    }

    fn job(&mut self, root: &Value) -> Option<Job> {
        let o = self.object(root, "", "the job")?;
        let header = self.header(o, TOP_KEYS, "a job needs its fuzzy control points");
        let type_reduction = match o.get("type_reduction") {
            None => Some(TypeReduction::Paper),
            Some(v) => self.type_reduction(v),
        };
        let weights = o.get("weights").and_then(|v| self.numbers(v, "weights"));
        let knots = o.get("knots").and_then(|v| self.numbers(v, "knots"));
        // Curve-level rules (SPEC §6), checked against the number of entries in
        // `points` even when some of them are invalid.
        let n = header.count;
        let weights = match (weights, o.contains_key("weights")) {
            (Some(w), _) => Some(w),
            (None, false) => n.map(|n| vec![1.0; n]),
            (None, true) => None,
        };
        if let (Some(degree), Some(n)) = (header.degree, n) {
            self.curve_rules(degree, n, weights.as_deref(), knots.as_deref());
        }
        // A key that failed to parse is None here and has been reported.
        if !self.problems.is_empty() {
            return None;
        }
        let (degree, points, samples, weights, type_reduction) = (
            header.degree?,
            header.points?,
            header.samples?,
            weights?,
            type_reduction?,
        );
        let model = match points {
            Points::Planar(p) => FuzzyCurve::try_new(degree, p, weights, knots).map(Model::Planar),
            Points::Spatial(p) => {
                FuzzyCurve::try_new(degree, p, weights, knots).map(Model::Spatial)
            }
        };
        match model {
            Ok(model) => Some(Job {
                description: header.description,
                alpha: header.alpha,
                type_reduction,
                samples: Samples::Along(samples.unwrap_or(DEFAULT_SAMPLES)),
                model,
            }),
            Err(e) => {
                // Every rule FuzzyCurve checks was checked above; keep the
                // message should the two ever disagree.
                self.located(&curve_error_path(&e), e);
                None
            }
        }
    }

    /// `type_reduction`: one of the [`TypeReduction::name`]s (SPEC §10).
    fn type_reduction(&mut self, v: &Value) -> Option<TypeReduction> {
        let Some(name) = v.as_str() else {
            self.report(
                "type_reduction",
                format!("expected a string, got {}", kind(v)),
            );
            return None;
        };
        let parsed = name.parse().ok();
        if parsed.is_none() {
            let names = TypeReduction::ALL.map(TypeReduction::name);
            let hint = match suggestion(name, &names) {
                Some(s) => format!("did you mean `{s}`?"),
                None => format!("known: {}", names.join(", ")),
            };
            // A name is short; a long value is shown by its start.
            let shown: String = name.chars().take(40).collect();
            let more = if shown.len() < name.len() { "…" } else { "" };
            self.report(
                "type_reduction",
                format!(
                    "unknown type reduction `{}{more}` ({hint})",
                    printable(&shown)
                ),
            );
        }
        parsed
    }

    /// A data file: the keys of a job but `weights` and `knots`, at least
    /// `degree + 1` points, and a degree of at least 1.
    fn data(&mut self, root: &Value) -> Option<FitData> {
        self.root = "data";
        let o = self.object(root, "", "the data file")?;
        for key in ["weights", "knots"] {
            if o.contains_key(key) {
                self.report(
                    key,
                    "not allowed in a data file: the fit makes the weights (all 1) and the knots",
                );
            }
        }
        let mut known = DATA_KEYS.to_vec();
        known.extend(["weights", "knots"]);
        let header = self.header(o, &known, "a data file needs its fuzzy data points");
        if let (Some(degree), Some(count)) = (header.degree, header.count) {
            if degree == 0 {
                self.report(header.degree_key, t2spline::Error::ZeroDegreeFit);
            } else if count < degree + 1 {
                self.located(
                    "points",
                    t2spline::Error::TooFewDataPoints { degree, count },
                );
            }
        }
        if !self.problems.is_empty() {
            return None;
        }
        Some(FitData {
            // Set by the caller, which knows the file's name.
            source: String::new(),
            description: header.description,
            degree_key: header.degree_key,
            degree: header.degree?,
            alpha: header.alpha,
            lower_height: header.lower_height,
            samples: header.samples?,
            points: match header.points? {
                Points::Planar(p) => FuzzyData::Planar(p),
                Points::Spatial(p) => FuzzyData::Spatial(p),
            },
        })
    }

    /// The rules that tie points, weights and knots together (SPEC §6).
    fn curve_rules(
        &mut self,
        degree: usize,
        n: usize,
        weights: Option<&[f64]>,
        knots: Option<&[f64]>,
    ) {
        // A degree of u64::MAX is valid JSON; saturating keeps it an error
        // (too few points) rather than an overflow.
        let order = degree.saturating_add(1);
        if n < order {
            self.report(
                "points",
                t2spline::Error::TooFewControlPoints { order, count: n },
            );
            return;
        }
        let weight_problems = weights.map(|w| t2spline::nurbs::weight_problems(w, n));
        let knot_problems = knots.map(|u| KnotVector::problems(u, degree, n));
        for e in weight_problems.into_iter().chain(knot_problems).flatten() {
            self.located(&curve_error_path(&e), e);
        }
    }

    /// The degree, from `order` or `degree`, within [`MAX_ORDER`](super::limits::MAX_ORDER).
    fn degree(&mut self, o: &Map<String, Value>) -> Option<usize> {
        let (key, v) = match (o.get("order"), o.get("degree")) {
            (Some(_), Some(_)) => {
                self.located(
                    "degree",
                    "order, degree: give exactly one of them (order = degree + 1)",
                );
                return None;
            }
            (None, None) => {
                self.report("order", "missing: give `order` (k) or `degree` (k - 1)");
                return None;
            }
            (Some(v), None) => ("order", v),
            (None, Some(v)) => ("degree", v),
        };
        let given = self.whole(v, key)?;
        if key == "order" && given == 0 {
            self.report("order", "order = 0: the order must be at least 1");
            return None;
        }
        let order = check_order(key, given, &written(v))
            .map_err(|rule| self.report(key, rule))
            .ok()?;
        Some(order - 1)
    }

    fn points(&mut self, v: &Value, height: Result<Option<f64>, ()>) -> Option<Points> {
        let Some(items) = v.as_array() else {
            self.report(
                "points",
                format!("expected an array of points, got {}", kind(v)),
            );
            return None;
        };
        if items.len() > MAX_POINTS {
            self.report(
                "points",
                format!("{} points is more than the limit {MAX_POINTS}", items.len()),
            );
            return None;
        }
        let mut dimension: Option<(usize, Vec<&'static str>)> = None;
        let mut parsed: Vec<Option<RawPoint>> = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            let key = element("points", i);
            let Some(o) = self.object(item, &key, "a point") else {
                parsed.push(None);
                continue;
            };
            self.unknown_keys(o, &key, POINT_KEYS);
            let axes: Vec<Axis> = [Axis::X, Axis::Y, Axis::Z]
                .into_iter()
                .filter(|a| o.contains_key(a.name()))
                .collect();
            let names: Vec<&'static str> = axes.iter().map(|a| a.name()).collect();
            let mut usable = true;
            if !(names == ["x", "y"] || names == ["x", "y", "z"]) {
                self.report(
                    &key,
                    format!(
                        "has coordinates [{}]; a point needs x and y, and optionally z",
                        names.join(", ")
                    ),
                );
                usable = false;
            } else {
                match &dimension {
                    None => dimension = Some((i, names.clone())),
                    Some((first, first_names)) if *first_names != names => {
                        self.report(&key, format!(
                            "has coordinates [{}] but points[{first}] has [{}]: every point needs the same coordinates",
                            names.join(", "),
                            first_names.join(", ")
                        ));
                        usable = false;
                    }
                    Some(_) => {}
                }
            }
            // The numbers are checked even in an unusable point, so that one
            // run reports all their problems too.
            let point: RawPoint = axes
                .into_iter()
                .map(|axis| (axis, self.number_of(&o[axis.name()], i, axis, height)))
                .collect();
            if !usable {
                parsed.push(None);
                continue;
            }
            parsed.push(Some(point));
        }
        let points: Vec<RawPoint> = parsed.into_iter().collect::<Option<_>>()?;
        if points.iter().flatten().any(|(_, x)| x.is_none()) {
            return None;
        }
        let numbers = |p: &RawPoint| {
            p.iter()
                .map(|(_, x)| x.expect("checked above"))
                .collect::<Vec<_>>()
        };
        match dimension.map(|(_, names)| names.len()) {
            Some(3) => Some(Points::Spatial(
                points
                    .iter()
                    .map(|p| Nt2Point::new(array(numbers(p))))
                    .collect(),
            )),
            _ => Some(Points::Planar(
                points
                    .iter()
                    .map(|p| Nt2Point::new(array(numbers(p))))
                    .collect(),
            )),
        }
    }

    /// One fuzzy number at `points[i].axis`.
    fn number_of(
        &mut self,
        v: &Value,
        i: usize,
        axis: Axis,
        height: Result<Option<f64>, ()>,
    ) -> Option<Nt2Number> {
        let key = child(&element("points", i), axis.name());
        let o = self.object(v, &key, "a fuzzy number")?;
        self.unknown_keys(o, &key, NUMBER_KEYS);
        let mut get = |name: &str| {
            let v = o.get(name);
            if v.is_none() {
                self.report(&child(&key, name), "missing");
            }
            v
        };
        let (crisp, upper, primary, lower) =
            (get("crisp"), get("upper"), get("primary"), get("lower"));
        let crisp = crisp.and_then(|v| self.number(v, &child(&key, "crisp")));
        let upper = upper.and_then(|v| self.pair(v, &child(&key, "upper")));
        let primary = primary.and_then(|v| self.pair(v, &child(&key, "primary")));
        let lower = lower.and_then(|v| self.pair(v, &child(&key, "lower")));
        let own = o
            .get("lower_height")
            .map(|v| self.number(v, &child(&key, "lower_height")));
        // `stand_in`: there is no valid height (reported, here or at the top
        // level); the order is still checked, with a valid height in its place.
        let (h, stand_in) = match (own, height) {
            (Some(own), _) => (own?, false),
            (None, Ok(Some(h))) => (h, false),
            (None, Ok(None)) => {
                self.report(
                    &key,
                    "no lower_height: give it in the number or at the top level of the job",
                );
                (1.0, true)
            }
            (None, Err(())) => (1.0, true),
        };
        let (crisp, upper, primary, lower) = (crisp?, upper?, primary?, lower?);
        for e in Nt2Number::problems(crisp, upper, primary, lower, h) {
            let path = match &e {
                t2spline::Error::NotFinite { what, .. }
                | t2spline::Error::OutOfRange { what, .. } => value_path(&key, what),
                _ => key.clone(),
            };
            self.located(&path, e.at(Place::new(i, axis)));
        }
        if stand_in {
            return None;
        }
        Nt2Number::try_new(crisp, upper, primary, lower, h).ok()
    }
}

/// The path of one of the values of the number at `number`, by its SPEC name
/// (`upper.left` → `upper[0]`, `lower_height` → `lower_height`).
fn value_path(number: &str, what: &str) -> String {
    match what.split_once('.') {
        Some((pair, side)) => element(&child(number, pair), usize::from(side == "right")),
        None => child(number, what),
    }
}

/// The place in the job file of a curve-level error of the core crate.
fn curve_error_path(e: &t2spline::Error) -> String {
    use t2spline::Error as E;
    match *e {
        E::TooFewControlPoints { .. } => "points".to_owned(),
        E::WeightCount { .. } => "weights".to_owned(),
        E::Weight { index, .. } | E::WeightOutOfRange { index, .. } => element("weights", index),
        E::KnotCount { .. } | E::EmptyDomain { .. } => "knots".to_owned(),
        E::KnotNotFinite { index, .. }
        | E::KnotOutOfRange { index, .. }
        | E::KnotDecreasing { index, .. }
        | E::KnotMultiplicity { first: index, .. } => element("knots", index),
        _ => String::new(),
    }
}

/// A number as the file wrote it, near enough: `3`, `1e300`.
fn written(v: &Value) -> String {
    match (v.as_u64(), v.as_f64()) {
        (Some(n), _) => n.to_string(),
        (None, Some(x)) => t2spline::Num(x).to_string(),
        _ => v.to_string(),
    }
}

/// Short description of a value that should have been a pair.
fn describe(v: &Value) -> String {
    match v.as_array() {
        Some(a) => format!("an array of {} values", a.len()),
        None => kind(v).to_owned(),
    }
}

/// A vector of exactly `D` numbers as an array; the caller guarantees the length.
fn array<const D: usize>(v: Vec<Nt2Number>) -> [Nt2Number; D] {
    v.try_into().expect("the dimension was checked to be D")
}

/// What a job and a data file share, as parsed (`None`: missing or invalid,
/// and reported).
struct Header {
    description: Option<String>,
    /// `"order"` or `"degree"`: the key the file used.
    degree_key: &'static str,
    degree: Option<usize>,
    alpha: Option<Alpha>,
    lower_height: Option<f64>,
    /// `Some(None)`: not given.
    samples: Option<Option<usize>>,
    points: Option<Points>,
    /// The number of entries of `points`, valid or not.
    count: Option<usize>,
}

/// The control points of either dimension.
enum Points {
    Planar(Vec<Nt2Point<2>>),
    Spatial(Vec<Nt2Point<3>>),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edit_distance_counts_transpositions_once() {
        assert_eq!(edit_distance("alhpa", "alpha"), 1);
        assert_eq!(edit_distance("wieghts", "weights"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(suggestion("sample", TOP_KEYS), Some("samples"));
        assert_eq!(suggestion("colour", TOP_KEYS), None);
    }
}
