//! The job-file validator: walks the JSON value and collects every problem.
//!
//! Parsing goes through `serde_json::Value` rather than derived structs so that
//! one pass can report *every* problem (serde stops at the first) and name each
//! by its place in the file. Each problem is found at a JSON path
//! (`points[2].y.upper[0]`); one scan of the text ([`position`](super::position))
//! then turns the paths into lines and columns and finds duplicate keys.
//!
//! A job file, and a data file for fitting, is first offered to the
//! one-pass reading of [`valid`](super::valid), which takes a file with no
//! problem at all about ten times faster; every other file comes here, so
//! that every message is this validator's.

use std::collections::HashSet;

use serde_json::{Map, Value};
use t2spline::fit::FuzzyData;
use t2spline::job::{Job, Model, Samples, DEFAULT_SAMPLES};
use t2spline::{Alpha, FuzzyCurve, KnotVector, Nt2Point, Place};

use super::common::{closure_gap, knot_error_path};
use super::non_finite::non_finite;
use super::place::element;
use super::point::{complete, RawPoint};
use super::position::{self, Oversized};
use super::schema::{CLOSURE_RULE, DATA_KEYS, FIT_MAKES, FIT_MAKES_RULE, TOP_KEYS};
use super::surface;
use super::valid;
use super::walker::{kind, Walker};
use super::weights::CurveWeights;
use crate::error::Problem;
use crate::fit_data::FitData;
use crate::limits::{MAX_ARRAY, MAX_KEYS, MAX_NESTING, MAX_POINTS, MAX_PROBLEMS, MAX_VALUES};

/// Parses `text` as a job, or returns every problem found, each with its line
/// and column.
pub(super) fn parse(text: &str) -> Result<Job, Vec<Problem>> {
    walk(text, valid::job, Walker::job)
}

/// [`parse`] by the validator alone, without the one-pass reading of a
/// valid job, to test that the two agree.
#[cfg(test)]
pub(super) fn parse_walking(text: &str) -> Result<Job, Vec<Problem>> {
    walk(text, |_| None, Walker::job)
}

/// Parses `text` as a data file for fitting, or returns every problem found,
/// each with its line and column.
pub(crate) fn parse_data(text: &str) -> Result<FitData, Vec<Problem>> {
    walk(text, valid::data, Walker::data)
}

/// [`parse_data`] by the validator alone, without the one-pass reading of
/// a valid data file, to test that the two agree.
#[cfg(test)]
pub(super) fn parse_data_walking(text: &str) -> Result<FitData, Vec<Problem>> {
    walk(text, |_| None, Walker::data)
}

/// Reads `text` with `valid`, which takes a file with no problem at all in
/// one pass (keeping the limits on sizes itself); else checks those limits,
/// parses the text as JSON and reads it with `read`, collecting every
/// problem (at most [`MAX_PROBLEMS`], then a count) and placing each at its
/// line and column.
fn walk<T>(
    text: &str,
    valid: impl FnOnce(&str) -> Option<T>,
    read: impl FnOnce(&mut Walker, &Value) -> Option<T>,
) -> Result<T, Vec<Problem>> {
    // Spreadsheet programs start UTF-8 files with a byte-order mark; editors
    // do not show it, so columns are counted without it.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if let Some(out) = valid(text) {
        return Ok(out);
    }
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
    let value: Value = serde_json::from_str(text).map_err(|e| {
        // JSON but for `NaN` or `Infinity` in place of numbers: those words
        // are the problems, named as a dict's are from Python.
        let words = non_finite(text);
        if words.is_empty() {
            vec![syntax_problem(text, &e)]
        } else {
            words
        }
    })?;
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
            message: crate::limits::more_problems(more, false),
        });
    }
    match out {
        Some(out) if problems.is_empty() => Ok(out),
        _ => Err(problems),
    }
}

/// The fuzzy curve of degree `degree` through `points` with `weights`,
/// crisp or fuzzy (docs/method.md §16).
fn weighted<const D: usize>(
    degree: usize,
    points: Vec<Nt2Point<D>>,
    weights: CurveWeights,
    knots: Option<Vec<f64>>,
) -> Result<FuzzyCurve<D>, t2spline::Error> {
    match weights {
        CurveWeights::Crisp(w) => FuzzyCurve::try_new(degree, points, w, knots),
        CurveWeights::Fuzzy(w) => {
            let crisp = w.iter().map(t2spline::Nt2Number::crisp).collect();
            FuzzyCurve::try_new(degree, points, crisp, knots)?.with_weight_numbers(w)
        }
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
    let bytes = line.as_bytes().get(..e.column()).unwrap_or(line.as_bytes());
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

impl Walker {
    /// The keys a job and a data file of a curve share, checked against
    /// `known`. `missing_points` says what `points` holds, for its message.
    fn header(
        &mut self,
        o: &Map<String, Value>,
        known: &[&'static str],
        missing_points: &str,
    ) -> Header {
        let (common, degree) = self.common(o, known, |w| w.degree(o));
        let samples = match o.get("samples") {
            None => Some(None),
            Some(v) if v.is_array() => {
                self.report(
                    "samples",
                    "a pair [u, v] is for a surface, whose points are rows of a net; a curve takes one number of samples",
                );
                None
            }
            Some(v) => self.samples_in(v, "samples").map(Some),
        };
        let points = match o.get("points") {
            None => {
                self.report("points", format!("missing: {missing_points}"));
                None
            }
            Some(v) => self.points(v, common.height),
        };
        Header {
            description: common.description,
            degree_key: if o.contains_key("degree") {
                "degree"
            } else {
                "order"
            },
            degree,
            alpha: common.alpha,
            lower_height: common.height.ok().flatten(),
            height: common.height,
            samples,
            points,
            count: o.get("points").and_then(Value::as_array).map(Vec::len),
        }
    }

    fn job(&mut self, root: &Value) -> Option<Job> {
        let o = self.object(root, "", "the job")?;
        if surface::is_surface(o) {
            return self.surface_job(o);
        }
        let header = self.header(o, TOP_KEYS, "a job needs its fuzzy control points");
        let type_reduction = self.type_reduction(o);
        let closed = o.get("closed").and_then(|v| self.boolean(v, "closed"));
        let units = self.units(o);
        let weights = o
            .get("weights")
            .and_then(|v| self.curve_weights(v, header.height));
        let knots = o.get("knots").and_then(|v| {
            if v.is_object() {
                self.report(
                    "knots",
                    "an object of knot vectors (u, v) is for a surface, whose points are rows of a net; a curve's knots are one array of numbers",
                );
                return None;
            }
            self.numbers(v, "knots")
        });
        // Curve-level rules (docs/method.md §6), checked against the number of entries in
        // `points` even when some of them are invalid.
        let n = header.count;
        let weights = match (weights, o.contains_key("weights")) {
            (Some(w), _) => Some(w),
            (None, false) => n.map(|n| CurveWeights::Crisp(vec![1.0; n])),
            (None, true) => None,
        };
        if let (Some(degree), Some(n)) = (header.degree, n) {
            let crisp = weights.as_ref().map(CurveWeights::crisp);
            self.curve_rules(degree, n, crisp.as_deref(), knots.as_deref());
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
            Points::Planar(p) => weighted(degree, p, weights, knots).map(Model::Planar),
            Points::Spatial(p) => weighted(degree, p, weights, knots).map(Model::Spatial),
        };
        if let (Ok(model), Some(true)) = (&model, closed) {
            if let Err(e) = closure_gap(model) {
                self.report("closed", format!("{e}: {CLOSURE_RULE}"));
                return None;
            }
        }
        match model {
            Ok(model) => Some(Job {
                description: header.description,
                alpha: header.alpha,
                type_reduction,
                samples: Samples::Along(samples.unwrap_or(DEFAULT_SAMPLES)),
                closed,
                units,
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

    /// A data file: the keys of a job but `weights` and `knots` (refused, and
    /// never offered as known keys), at least
    /// `degree + 1` points, and a degree of at least 1.
    fn data(&mut self, root: &Value) -> Option<FitData> {
        self.root = "data";
        let o = self.object(root, "", "the data file")?;
        for key in FIT_MAKES {
            if o.contains_key(*key) {
                self.report(key, FIT_MAKES_RULE);
            }
        }
        self.refused = FIT_MAKES;
        if surface::is_surface(o) {
            return self.data_net(o, DATA_KEYS);
        }
        let header = self.header(o, DATA_KEYS, "a data file needs its fuzzy data points");
        // Carried to the job only when given.
        let type_reduction = if o.contains_key("type_reduction") {
            self.type_reduction(o).map(Some)
        } else {
            Some(None)
        };
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
            degree_v: None,
            alpha: header.alpha,
            type_reduction: type_reduction?,
            lower_height: header.lower_height,
            samples: header.samples?,
            points: match header.points? {
                Points::Planar(p) => FuzzyData::Planar(p),
                Points::Spatial(p) => FuzzyData::Spatial(p),
            },
        })
    }

    /// The rules that tie points, weights and knots together (docs/method.md §6).
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

    /// The degree of a curve, from `order` or `degree`.
    fn degree(&mut self, o: &Map<String, Value>) -> Option<usize> {
        let (key, v) = self.order_key(o)?;
        if v.is_array() {
            self.report(
                key,
                format!("a pair [u, v] is for a surface, whose points are rows of a net; a curve has one {key}"),
            );
            return None;
        }
        self.degree_of(key, key, v)
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
            let coordinates = |w: &mut Self, names: &[&'static str]| {
                if !(names == ["x", "y"] || names == ["x", "y", "z"]) {
                    w.report(
                        &key,
                        format!(
                            "has coordinates [{}]; a point needs x and y, and optionally z",
                            names.join(", ")
                        ),
                    );
                    return false;
                }
                match &dimension {
                    None => dimension = Some((i, names.to_vec())),
                    Some((first, first_names)) if first_names != names => {
                        w.report(&key, format!(
                            "has coordinates [{}] but points[{first}] has [{}]: every point needs the same coordinates",
                            names.join(", "),
                            first_names.join(", ")
                        ));
                        return false;
                    }
                    Some(_) => {}
                }
                true
            };
            let point = self.point(item, &key, |axis| Place::new(i, axis), height, coordinates);
            parsed.push(point);
        }
        let points: Vec<RawPoint> = parsed.into_iter().collect::<Option<_>>()?;
        match dimension.map(|(_, names)| names.len()) {
            Some(3) => points
                .into_iter()
                .map(complete)
                .collect::<Option<_>>()
                .map(Points::Spatial),
            _ => points
                .into_iter()
                .map(complete)
                .collect::<Option<_>>()
                .map(Points::Planar),
        }
    }
}

/// The place in the job file of a curve-level error of the core crate.
fn curve_error_path(e: &t2spline::Error) -> String {
    use t2spline::Error as E;
    match *e {
        E::TooFewControlPoints { .. } => "points".to_owned(),
        E::WeightCount { .. } => "weights".to_owned(),
        E::Weight { index, .. } | E::WeightOutOfRange { index, .. } => element("weights", index),
        _ => knot_error_path(e, "knots").unwrap_or_default(),
    }
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
    /// The top-level `lower_height` as the numbers read it: `Err(())`
    /// where it was given and refused.
    height: Result<Option<f64>, ()>,
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
