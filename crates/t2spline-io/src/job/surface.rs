//! The rules of surface jobs (docs/method.md §8): a job whose `points` are rows of a
//! net.
//!
//! The walkers of keys, numbers, points, weights and knots are the curves'
//! own ([`common`](super::common), [`point`](super::point),
//! [`walker`](super::walker)); what is new here is the shape of a surface job
//! and the rules that tie its parts to the net:
//!
//! | key | curve | surface |
//! |---|---|---|
//! | `order` / `degree` | a number | a pair `[u, v]` |
//! | `points` | a list of points (x, y and optionally z) | rows of points along u, each row along v, all of one length; x, y and z |
//! | `weights` | a list, one per point | rows, the shape of `points` (either may hold fuzzy numbers) |
//! | `knots` | an array of `n + k` numbers | an object with `u` (`nu + ku` numbers) and/or `v` (`nv + kv`) |
//! | `samples` | a number (default 101) | a pair `[su, sv]`, or one number for both (default `[21, 21]`) |

use serde_json::{Map, Value};
use t2spline::fit::FuzzyData;
use t2spline::job::{check_grid_samples, Job, Model, Samples, DEFAULT_SURFACE_SAMPLES};
use t2spline::nurbs::net_weight_problems;
use t2spline::{
    Direction, Error as CoreError, FuzzySurface, KnotVector, Nt2Number, Nt2Point, Place,
};

use super::common::knot_error_path;
use super::place::{child, element};
use super::point::complete;
use super::schema::{KNOT_DIRECTIONS, TOP_KEYS};
use super::walker::{kind, written, Walker};
use crate::fit_data::FitData;
use crate::limits::{check_net_size, check_surface_work};

/// Whether the job object `o` is a surface job: more entries of `points` are
/// arrays (rows of a net) than objects (points of a curve); with as many of
/// each (no entries at all, say), when `order` or `degree` is a pair. A
/// curve job with one stray array keeps its curve messages, and a surface
/// job with one stray point its surface messages.
pub(super) fn is_surface(o: &Map<String, Value>) -> bool {
    let items = o
        .get("points")
        .and_then(Value::as_array)
        .map_or(&[][..], Vec::as_slice);
    let rows = items.iter().filter(|v| v.is_array()).count();
    let points = items.iter().filter(|v| v.is_object()).count();
    rows > points
        || (rows == points
            && ["order", "degree"]
                .iter()
                .any(|k| o.get(*k).is_some_and(Value::is_array)))
}

/// The net of control points as read.
struct Net {
    /// `[nu, nv]` when every row is an array of the same length, whether or
    /// not its points are valid (the rules of each direction need it).
    shape: Option<[usize; 2]>,
    /// The points, row by row, when every one is valid.
    points: Option<Vec<Vec<Nt2Point<3>>>>,
}

/// One row of a surface's `weights` as read.
enum WeightRow {
    /// Numbers: crisp weights.
    Crisp(Vec<f64>),
    /// Some entry a fuzzy number (a bare number among them a crisp one).
    Fuzzy(Vec<Nt2Number>),
}

/// A surface's `weights` once read: the crisp weights (with fuzzy ones,
/// their crisp values), and the fuzzy numbers row by row where some row has
/// one (docs/method.md §16).
struct NetWeights {
    crisp: Vec<Vec<f64>>,
    numbers: Option<Vec<Nt2Number>>,
}

impl NetWeights {
    /// The weights of `rows`; the numbers of every row, a crisp row's
    /// values as crisp numbers of lower height `height` (as a bare number
    /// among fuzzy ones is read), where some row is fuzzy.
    fn of(rows: Vec<WeightRow>, height: f64) -> Self {
        let crisp = rows
            .iter()
            .map(|r| match r {
                WeightRow::Crisp(w) => w.clone(),
                WeightRow::Fuzzy(w) => w.iter().map(Nt2Number::crisp).collect(),
            })
            .collect();
        let fuzzy = rows.iter().any(|r| matches!(r, WeightRow::Fuzzy(_)));
        let numbers = fuzzy.then(|| {
            rows.into_iter()
                .flat_map(|r| match r {
                    WeightRow::Crisp(w) => w
                        .into_iter()
                        .filter_map(|x| Nt2Number::try_new(x, [x; 2], [x; 2], [x; 2], height).ok())
                        .collect(),
                    WeightRow::Fuzzy(w) => w,
                })
                .collect()
        });
        NetWeights { crisp, numbers }
    }
}

/// The knot values of a surface as given, `[u, v]` (`None`: the default).
type KnotValues = [Option<Vec<f64>>; 2];

impl Walker {
    /// A surface job (docs/method.md §8): every problem of every key, then the rules
    /// that tie the net, weights and knots together in each direction.
    pub(super) fn surface_job(&mut self, o: &Map<String, Value>) -> Option<Job> {
        if o.contains_key("closed") {
            self.report(
                "closed",
                "a surface job has no `closed`: it is for curves (docs/method.md §11)",
            );
        }
        let (common, degree) = self.common(o, TOP_KEYS, |w| w.degrees(o));
        let samples = self.grid_samples(o.get("samples"));
        let type_reduction = self.type_reduction(o);
        let units = self.units(o);
        let net = match o.get("points") {
            None => {
                self.report("points", "missing: a job needs its fuzzy control points");
                None
            }
            Some(v) => self.net(v, common.height),
        };
        let shape = net.as_ref().and_then(|n| n.shape);
        let weights = match o.get("weights") {
            // The shape is within the limit of the net's size.
            None => shape.map(|[nu, nv]| NetWeights {
                crisp: vec![vec![1.0; nv]; nu],
                numbers: None,
            }),
            Some(v) => {
                self.net_weights(v, o.get("points").and_then(Value::as_array), common.height)
            }
        };
        let knots = match o.get("knots") {
            None => Some([None, None]),
            Some(v) => self.knot_vectors(v),
        };
        if let (Some(degree), Some(shape)) = (degree, shape) {
            self.direction_rules(degree, shape, knots.as_ref());
            // At most MAX_ORDER, so no overflow.
            if let Err(rule) = check_surface_work(shape, degree.map(|p| p + 1)) {
                self.report("points", rule);
            }
        }
        // A key that failed to parse is None here and has been reported.
        if !self.problems.is_empty() {
            return None;
        }
        let (degree, points, samples, weights, knots, type_reduction) = (
            degree?,
            net?.points?,
            samples?,
            weights?,
            knots?,
            type_reduction?,
        );
        let made = FuzzySurface::try_new(degree, points, weights.crisp, knots);
        let made = match weights.numbers {
            Some(numbers) => made.and_then(|s| s.with_weight_numbers(numbers)),
            None => made,
        };
        match made {
            Ok(surface) => Some(Job {
                description: common.description,
                alpha: common.alpha,
                type_reduction,
                samples: Samples::Grid(samples),
                closed: None,
                units,
                model: Model::Surface(surface),
            }),
            Err(e) => {
                // Every rule FuzzySurface checks was checked above; keep the
                // message should the two ever disagree.
                self.located(&surface_error_path(&e), e);
                None
            }
        }
    }

    /// A data file of a net (`points` as rows of fuzzy data points along u,
    /// each row along v): the keys of a data file (`known`), `order` or
    /// `degree` a pair `[u, v]`, `samples` one number, and at least
    /// `p + 1` rows of at least `q + 1` points. `weights` and `knots` have
    /// been refused by the caller.
    pub(super) fn data_net(
        &mut self,
        o: &Map<String, Value>,
        known: &[&'static str],
    ) -> Option<FitData> {
        let (common, degree) = self.common(o, known, |w| w.degrees(o));
        let samples = match o.get("samples") {
            None => Some(None),
            Some(v) if v.is_array() => {
                self.report(
                    "samples",
                    "a data file of a net takes one number of samples, for both directions of the fitted surface",
                );
                None
            }
            Some(v) => self.samples_in(v, "samples").map(Some),
        };
        let type_reduction = if o.contains_key("type_reduction") {
            self.type_reduction(o).map(Some)
        } else {
            Some(None)
        };
        let net = match o.get("points") {
            None => {
                self.report("points", "missing: a data file needs its fuzzy data points");
                None
            }
            Some(v) => self.net(v, common.height),
        };
        let shape = net.as_ref().and_then(|n| n.shape);
        let key = if o.contains_key("degree") {
            "degree"
        } else {
            "order"
        };
        if let Some(degree) = degree {
            for (i, p) in degree.into_iter().enumerate() {
                if p == 0 {
                    self.report(&element(key, i), t2spline::Error::ZeroDegreeFit);
                }
            }
            if let (Some(shape), true) = (shape, degree.iter().all(|&p| p > 0)) {
                for ((direction, p), n) in Direction::BOTH.into_iter().zip(degree).zip(shape) {
                    let lines = match direction {
                        Direction::U => "row(s)",
                        Direction::V => "point(s) per row",
                    };
                    if n <= p {
                        self.report(
                            "points",
                            format!(
                                "{n} {lines}, but a net of degree {p} along {direction} needs at least {}",
                                p.saturating_add(1)
                            ),
                        );
                    }
                }
            }
        }
        if !self.problems.is_empty() {
            return None;
        }
        let [p, q] = degree?;
        Some(FitData {
            // Set by the caller, which knows the file's name.
            source: String::new(),
            description: common.description,
            degree_key: key,
            degree: p,
            degree_v: Some(q),
            alpha: common.alpha,
            type_reduction: type_reduction?,
            lower_height: common.height.ok().flatten(),
            samples: samples?,
            points: FuzzyData::Net(net?.points?),
        })
    }

    /// The degrees `[p, q]`, from `order` or `degree`: a pair.
    fn degrees(&mut self, o: &Map<String, Value>) -> Option<[usize; 2]> {
        let (key, v) = self.order_key(o)?;
        match v.as_array().map(Vec::as_slice) {
            Some([u, v]) => {
                let u = self.degree_of(key, &element(key, 0), u);
                let v = self.degree_of(key, &element(key, 1), v);
                Some([u?, v?])
            }
            Some(items) => {
                self.report(
                    key,
                    format!(
                        "expected a pair [u, v], one {key} per direction, got an array of {} values",
                        items.len()
                    ),
                );
                None
            }
            None => {
                let got = if v.is_number() {
                    written(v)
                } else {
                    kind(v).to_owned()
                };
                self.report(
                    key,
                    format!(
                        "a surface (points given as rows of a net) has one {key} per direction: give a pair [u, v], got {got}"
                    ),
                );
                None
            }
        }
    }

    /// The grid of samples `[su, sv]`: a pair, or one number for both
    /// directions; at most [`MAX_SAMPLES`](t2spline::job::MAX_SAMPLES) grid
    /// points.
    fn grid_samples(&mut self, v: Option<&Value>) -> Option<[usize; 2]> {
        let Some(v) = v else {
            return Some([DEFAULT_SURFACE_SAMPLES; 2]);
        };
        let grid = match v.as_array().map(Vec::as_slice) {
            Some([su, sv]) => {
                let su = self.samples_in(su, &element("samples", 0));
                let sv = self.samples_in(sv, &element("samples", 1));
                [su?, sv?]
            }
            Some(items) => {
                self.report(
                    "samples",
                    format!(
                        "expected a pair [u, v] of numbers of samples, or one number for both directions, got an array of {} values",
                        items.len()
                    ),
                );
                return None;
            }
            None => [self.samples_in(v, "samples")?; 2],
        };
        check_grid_samples(grid)
            .map_err(|rule| self.report("samples", rule))
            .ok()?;
        Some(grid)
    }

    /// The net `points[i][j]`: rows of 3-D points, all of one length, at most
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS) in all (counted before any
    /// point is read).
    fn net(&mut self, v: &Value, height: Result<Option<f64>, ()>) -> Option<Net> {
        let Some(rows) = v.as_array() else {
            self.report(
                "points",
                format!(
                    "expected rows of points (an array of arrays), got {}",
                    kind(v)
                ),
            );
            return None;
        };
        let total: usize = rows.iter().filter_map(Value::as_array).map(Vec::len).sum();
        if let Err(rule) = check_net_size(total) {
            self.report("points", rule);
            return None;
        }
        let columns = rows.first().and_then(Value::as_array).map(Vec::len);
        let mut regular = true;
        let mut parsed: Vec<Option<Vec<Nt2Point<3>>>> = Vec::with_capacity(rows.len());
        for (i, row) in rows.iter().enumerate() {
            let key = element("points", i);
            let Some(items) = row.as_array() else {
                self.report(
                    &key,
                    format!("expected a row of points (an array), got {}", kind(row)),
                );
                regular = false;
                parsed.push(None);
                continue;
            };
            if let Some(c) = columns.filter(|&c| c != items.len()) {
                self.report(
                    &key,
                    format!(
                        "{}, row 0 has {c}: every row of the net needs as many points",
                        count(items.len(), "column")
                    ),
                );
                regular = false;
            }
            let points: Vec<Option<Nt2Point<3>>> = items
                .iter()
                .enumerate()
                .map(|(j, item)| {
                    let key = element(&key, j);
                    let spatial = |w: &mut Self, names: &[&'static str]| {
                        let spatial = names == ["x", "y", "z"];
                        if !spatial {
                            w.report(
                                &key,
                                format!(
                                    "has coordinates [{}]; the points of a surface need x, y and z",
                                    names.join(", ")
                                ),
                            );
                        }
                        spatial
                    };
                    self.point(item, &key, |a| Place::in_net(i, j, a), height, spatial)
                        .and_then(complete)
                })
                .collect();
            parsed.push(points.into_iter().collect());
        }
        Some(Net {
            shape: regular.then(|| [rows.len(), columns.unwrap_or(0)]),
            points: parsed.into_iter().collect(),
        })
    }

    /// `weights`: rows of numbers of the shape of `points` (the rows as
    /// given, when an array), each finite and within the core's range; an
    /// entry may be a fuzzy number as a curve's weight may
    /// (docs/method.md §16, [`Walker::curve_weights`]), its place
    /// `weights[i][j]`, each foot of its upper cut checked as a weight.
    fn net_weights(
        &mut self,
        v: &Value,
        points: Option<&Vec<Value>>,
        height: Result<Option<f64>, ()>,
    ) -> Option<NetWeights> {
        let rule = "rows of numbers, the shape of points";
        let Some(rows) = v.as_array() else {
            self.report("weights", format!("expected {rule}, got {}", kind(v)));
            return None;
        };
        if !rows.is_empty() && !rows.iter().any(Value::is_array) {
            self.report(
                "weights",
                format!("expected {rule}, got a list of numbers (the weights of a curve)"),
            );
            return None;
        }
        if let Some(nu) = points.map(Vec::len).filter(|&nu| nu != rows.len()) {
            self.report(
                "weights",
                format!("{}, points has {nu}", count(rows.len(), "row")),
            );
        }
        let mut out: Vec<Option<WeightRow>> = Vec::with_capacity(rows.len());
        for (i, row) in rows.iter().enumerate() {
            let key = element("weights", i);
            let length = row.as_array().map(Vec::len);
            let columns = points.and_then(|p| p.get(i)?.as_array().map(Vec::len));
            if let (Some(length), Some(nv)) = (length, columns) {
                if length != nv {
                    self.report(
                        &key,
                        format!("{}, points[{i}] has {nv}", count(length, "column")),
                    );
                }
            }
            let fuzzy = row.as_array().filter(|r| r.iter().any(Value::is_object));
            if let Some(items) = fuzzy {
                // Every value of a fuzzy weight lies between the feet of its
                // upper cut, the crisp value too: checking the feet checks all.
                let numbers: Vec<Option<Nt2Number>> = items
                    .iter()
                    .enumerate()
                    .map(|(j, item)| {
                        let at = element(&key, j);
                        let number = self.number_at(item, &at, Place::NONE, height)?;
                        self.weight_feet(&at, &number).then_some(number)
                    })
                    .collect();
                out.push(
                    numbers
                        .into_iter()
                        .collect::<Option<_>>()
                        .map(WeightRow::Fuzzy),
                );
                continue;
            }
            let values = self.numbers(row, &key);
            for e in values.iter().flat_map(|w| net_weight_problems(i, w)) {
                self.located(&surface_error_path(&e), e);
            }
            out.push(values.map(WeightRow::Crisp));
        }
        let rows: Vec<WeightRow> = out.into_iter().collect::<Option<_>>()?;
        Some(NetWeights::of(rows, height.ok().flatten().unwrap_or(1.0)))
    }

    /// `knots`: an object with the knot values of `u` and/or `v`.
    fn knot_vectors(&mut self, v: &Value) -> Option<KnotValues> {
        let Some(o) = v.as_object() else {
            self.report(
                "knots",
                format!(
                    "a surface has a knot vector per direction: expected an object with `u` and/or `v`, got {}",
                    kind(v)
                ),
            );
            return None;
        };
        self.unknown_keys(o, "knots", &KNOT_DIRECTIONS);
        let mut valid = true;
        let values = KNOT_DIRECTIONS.map(|d| {
            let values = o.get(d).map(|v| self.numbers(v, &child("knots", d)));
            valid &= !matches!(values, Some(None));
            values.flatten()
        });
        valid.then_some(values)
    }

    /// The rules of each direction (docs/method.md §6 as per §8): at least `k` control
    /// points along it, and its knot vector's rules when given.
    fn direction_rules(
        &mut self,
        degree: [usize; 2],
        shape: [usize; 2],
        knots: Option<&KnotValues>,
    ) {
        for ((direction, p), n) in Direction::BOTH.into_iter().zip(degree).zip(shape) {
            // A degree of usize::MAX saturates to an order no net reaches.
            let order = p.saturating_add(1);
            let problems = match knots.and_then(|k| k.get(direction.index())?.as_deref()) {
                Some(values) => KnotVector::problems(values, p, n),
                None if n < order => vec![CoreError::TooFewControlPoints { order, count: n }],
                None => Vec::new(),
            };
            for inner in problems {
                let e = CoreError::InDirection {
                    direction,
                    inner: Box::new(inner),
                };
                self.located(&surface_error_path(&e), e);
            }
        }
    }
}

/// `n` things, singular or plural: `1 column`, `3 rows`.
fn count(n: usize, thing: &str) -> String {
    if n == 1 {
        format!("1 {thing}")
    } else {
        format!("{n} {thing}s")
    }
}

/// The place in the job file of an error of the core crate about a surface.
fn surface_error_path(e: &CoreError) -> String {
    match e {
        CoreError::InDirection { direction, inner } => match **inner {
            CoreError::TooFewControlPoints { .. } => "points".to_owned(),
            ref inner => {
                knot_error_path(inner, &child("knots", &direction.to_string())).unwrap_or_default()
            }
        },
        CoreError::NetShape { what, row, .. } => element(what, *row),
        CoreError::NetWeight { row, column, .. } => element(&element("weights", *row), *column),
        _ => String::new(),
    }
}
