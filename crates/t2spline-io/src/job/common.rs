//! The top-level keys that job and data files read alike, curve or surface
//! (named in [`schema`](super::schema)): `description`, `order`/`degree`, `alpha`,
//! `lower_height`, `samples` and `type_reduction`; and the place of an error
//! about a knot vector; `units`, and whether a curve said to be closed
//! closes (read alike by the validator and the one-pass reading).

use serde_json::{Map, Value};
use t2spline::job::{check_samples, LengthUnit, Model};
use t2spline::{Alpha, Height, TypeReduction};

use super::place::element;
use super::walker::{kind, suggestion, written, Walker};
use crate::limits::check_order;
use crate::printable;

/// Whether a curve model closes ([`FuzzyCurve::closure_gap`]); a surface
/// is never asked.
pub(super) fn closure_gap(model: &Model) -> Result<(), t2spline::Error> {
    match model {
        Model::Planar(c) => c.closure_gap().map(drop),
        Model::Spatial(c) => c.closure_gap().map(drop),
        _ => Ok(()),
    }
}

/// The top-level keys that every job and data file reads alike, as parsed
/// (`None`: missing or invalid, and reported).
pub(super) struct Common {
    pub(super) description: Option<String>,
    pub(super) alpha: Option<Alpha>,
    /// The top-level lower height; `Err(())`: given but invalid (reported
    /// here once, not again for every number that inherits it).
    pub(super) height: Result<Option<f64>, ()>,
}

impl Walker {
    /// `units`, one of [`LengthUnit::names`]; `None` when missing or
    /// wrong (reported).
    pub(super) fn units(&mut self, o: &Map<String, Value>) -> Option<LengthUnit> {
        let v = o.get("units")?;
        let unit = v.as_str().and_then(LengthUnit::named);
        if unit.is_none() {
            self.report(
                "units",
                format!(
                    "expected one of {} (the unit of the coordinates, for CAD files), got {}",
                    LengthUnit::names(),
                    written(v)
                ),
            );
        }
        unit
    }

    /// The keys every file shares, in the order of the file format: unknown
    /// keys (against `known`), `description`, the model's order (read by
    /// `order`, as the kind of model needs), `alpha`, `lower_height`.
    pub(super) fn common<T>(
        &mut self,
        o: &Map<String, Value>,
        known: &[&'static str],
        order: impl FnOnce(&mut Self) -> T,
    ) -> (Common, T) {
        self.unknown_keys(o, "", known);
        let description = match o.get("description") {
            None => None,
            Some(Value::String(s)) => Some(s.clone()),
            Some(v) => {
                self.report("description", format!("expected a string, got {}", kind(v)));
                None
            }
        };
        let order = order(self);
        let alpha = o.get("alpha").and_then(|v| {
            let a = self.number(v, "alpha")?;
            Alpha::try_new(a).map_err(|e| self.located("alpha", e)).ok()
        });
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
        let common = Common {
            description,
            alpha,
            height,
        };
        (common, order)
    }

    /// A number of samples at `path`: a whole number from 2 to the limit
    /// (docs/jobs.md).
    pub(super) fn samples_in(&mut self, v: &Value, path: &str) -> Option<usize> {
        let n = self.whole(v, path)?;
        check_samples(n, &written(v))
            .map_err(|rule| self.report(path, rule))
            .ok()
    }

    /// `type_reduction`: one of the [`TypeReduction::name`]s (docs/method.md §9),
    /// the paper's when the key is missing. Curve and surface jobs alike.
    pub(super) fn type_reduction(&mut self, o: &Map<String, Value>) -> Option<TypeReduction> {
        let Some(v) = o.get("type_reduction") else {
            return Some(TypeReduction::Paper);
        };
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

    /// The key that gives the order, `order` or `degree`, and its value:
    /// exactly one of them must be given.
    pub(super) fn order_key<'v>(
        &mut self,
        o: &'v Map<String, Value>,
    ) -> Option<(&'static str, &'v Value)> {
        match (o.get("order"), o.get("degree")) {
            (Some(_), Some(_)) => {
                self.located(
                    "degree",
                    "order, degree: give exactly one of them (order = degree + 1)",
                );
                None
            }
            (None, None) => {
                self.report("order", "missing: give `order` (k) or `degree` (k - 1)");
                None
            }
            (Some(v), None) => Some(("order", v)),
            (None, Some(v)) => Some(("degree", v)),
        }
    }

    /// One order `v` at `path`, given as `key` (`order` or `degree`): a
    /// whole number, an order of at least 1, within
    /// [`MAX_ORDER`](crate::limits::MAX_ORDER). Returns the degree.
    pub(super) fn degree_of(&mut self, key: &str, path: &str, v: &Value) -> Option<usize> {
        let given = self.whole(v, path)?;
        if key == "order" && given == 0 {
            self.report(path, "order = 0: the order must be at least 1");
            return None;
        }
        let order = check_order(key, given, &written(v))
            .map_err(|rule| self.report(path, rule))
            .ok()?;
        Some(order - 1)
    }
}

/// The place of an error of the core crate about a knot vector, the array at
/// `knots` (`knots`, or `knots.v` of a surface); `None` for other errors.
pub(super) fn knot_error_path(e: &t2spline::Error, knots: &str) -> Option<String> {
    use t2spline::Error as E;
    match *e {
        E::KnotCount { .. } | E::EmptyDomain { .. } => Some(knots.to_owned()),
        E::KnotNotFinite { index, .. }
        | E::KnotOutOfRange { index, .. }
        | E::KnotDecreasing { index, .. }
        | E::KnotMultiplicity { first: index, .. } => Some(element(knots, index)),
        _ => None,
    }
}
