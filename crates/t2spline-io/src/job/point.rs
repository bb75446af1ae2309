//! A control point as read: an object with a fuzzy number per coordinate,
//! each number checked by the core's rules (docs/method.md §1) and placed in the file;
//! shared by the points of a curve and the net of a surface.

use serde_json::Value;
use t2spline::{Axis, Nt2Number, Nt2Point, Place};

use super::place::{child, element};
use super::schema::{FUZZY_NUMBER_EXPECTED, FUZZY_NUMBER_KEYS, POINT_KEYS};
use super::walker::{kind, Walker};

/// The fuzzy numbers of one point, per axis, once parsed.
pub(super) type RawPoint = Vec<(Axis, Option<Nt2Number>)>;

impl Walker {
    /// One control point at `key` (`points[2]`, or `points[2][1]` in the net
    /// of a surface): an object with a fuzzy number per coordinate, each
    /// placed by `place` in the core's messages. `coordinates` judges which
    /// coordinates the point has (and reports at `key`); the numbers are
    /// checked even in a point it refuses, so that one run reports all their
    /// problems too. `None`: not an object, or refused.
    pub(super) fn point(
        &mut self,
        item: &Value,
        key: &str,
        place: impl Fn(Axis) -> Place,
        height: Result<Option<f64>, ()>,
        coordinates: impl FnOnce(&mut Self, &[&'static str]) -> bool,
    ) -> Option<RawPoint> {
        let o = self.object(item, key, "a point")?;
        self.unknown_keys(o, key, &POINT_KEYS);
        let axes: Vec<Axis> = [Axis::X, Axis::Y, Axis::Z]
            .into_iter()
            .filter(|a| o.contains_key(a.name()))
            .collect();
        let names: Vec<&'static str> = axes.iter().map(|a| a.name()).collect();
        let usable = coordinates(self, &names);
        let point: RawPoint = axes
            .into_iter()
            .map(|axis| {
                let number = self.number_of(&o[axis.name()], key, place(axis), height);
                (axis, number)
            })
            .collect();
        usable.then_some(point)
    }

    /// One fuzzy number: coordinate `place.axis` of the point at `point`.
    fn number_of(
        &mut self,
        v: &Value,
        point: &str,
        place: Place,
        height: Result<Option<f64>, ()>,
    ) -> Option<Nt2Number> {
        let key = child(point, place.axis.map_or("?", Axis::name));
        self.number_at(v, &key, place, height)
    }

    /// One fuzzy number at `key` (a coordinate, or a fuzzy weight
    /// `weights[2]`): a bare number (crisp) or an object with `crisp`,
    /// `upper`, `primary`, `lower` and perhaps its own `lower_height`,
    /// checked by the core's rules (docs/method.md §1); the core's errors
    /// carry `place`.
    pub(super) fn number_at(
        &mut self,
        v: &Value,
        key: &str,
        place: Place,
        height: Result<Option<f64>, ()>,
    ) -> Option<Nt2Number> {
        let key = key.to_owned();
        // A bare number is a crisp number: the job's height, else 1.
        if let Some(x) = v.as_f64() {
            let h = height.ok().flatten().unwrap_or(1.0);
            // Its seven values are one: its problems are the crisp value's.
            let problems = Nt2Number::problems(x, [x; 2], [x; 2], [x; 2], h);
            for e in problems.into_iter().filter(|e| {
                matches!(e, t2spline::Error::NotFinite { what, .. }
                    | t2spline::Error::OutOfRange { what, .. } if *what == "crisp")
            }) {
                self.number_problem(&key, &key, place, e);
            }
            return Nt2Number::try_new(x, [x; 2], [x; 2], [x; 2], h).ok();
        }
        if !v.is_object() {
            self.report(
                &key,
                format!("expected {FUZZY_NUMBER_EXPECTED}, got {}", kind(v)),
            );
            return None;
        }
        let o = self.object(v, &key, "a fuzzy number")?;
        self.unknown_keys(o, &key, &FUZZY_NUMBER_KEYS);
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
            self.number_problem(&path, &key, place, e);
        }
        if stand_in {
            return None;
        }
        Nt2Number::try_new(crisp, upper, primary, lower, h).ok()
    }
}

impl Walker {
    /// A problem `e` of the number at `key`, placed at `path`: the core's
    /// error names a coordinate's place itself (`points[1].y: …`); a number
    /// with no such place (a fuzzy weight) is named by its key.
    fn number_problem(&mut self, path: &str, key: &str, place: Place, e: t2spline::Error) {
        if place == Place::NONE {
            self.located(path, format!("{key}: {e}"));
        } else {
            self.located(path, e.at(place));
        }
    }
}

/// The path of one of the values of the number at `number`, by its name in docs/method.md §1
/// (`upper.left` → `upper[0]`, `lower_height` → `lower_height`).
fn value_path(number: &str, what: &str) -> String {
    match what.split_once('.') {
        Some((pair, side)) => element(&child(number, pair), usize::from(side == "right")),
        None => child(number, what),
    }
}

/// The point of `D` dimensions whose numbers were all read, if the point has
/// exactly `D`.
pub(super) fn complete<const D: usize>(p: RawPoint) -> Option<Nt2Point<D>> {
    let numbers: Vec<Nt2Number> = p.into_iter().map(|(_, x)| x).collect::<Option<_>>()?;
    numbers.try_into().ok().map(Nt2Point::new)
}
