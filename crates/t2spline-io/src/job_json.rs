//! Jobs written back as job files (docs/jobs.md), and the models and points
//! of data files: the writing side of the job format, shared by the job
//! reader (which re-exports [`job_json`]), the data of fits and readings.

use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::{json, Map, Value};
use t2spline::job::{Job, Model, ModelVisitor, Samples};
use t2spline::{Axis, Direction, FuzzyCurve, FuzzySurface, Layer, Nt2Number, Nt2Point};

/// The job as JSON in canonical form: explicit weights, knots and type
/// reduction, and every number with its own `lower_height`. Parsing it gives
/// back an equal job.
///
/// # Examples
/// ```
/// # let text = std::fs::read_to_string("../../examples/paper-alg-1-1.json")?;
/// let job = t2spline_io::parse_job(&text, "paper-alg-1-1.json")?;
/// let json = t2spline_io::job_json(&job);
/// assert_eq!(json["knots"], serde_json::json!([0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]));
/// assert_eq!(t2spline_io::parse_job(&json.to_string(), "again")?, job);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn job_json(job: &Job) -> Value {
    let mut out = Map::new();
    if let Some(d) = &job.description {
        out.insert("description".into(), json!(d));
    }
    for (key, value) in model_json(&job.model, None) {
        if key == "points" {
            if let Some(a) = job.alpha {
                out.insert("alpha".into(), json!(a.get()));
            }
            out.insert("type_reduction".into(), json!(job.type_reduction.name()));
            let samples = match job.samples {
                Samples::Along(n) => json!(n),
                Samples::Grid(pair) => json!(pair),
            };
            out.insert("samples".into(), samples);
            if let Some(closed) = job.closed {
                out.insert("closed".into(), json!(closed));
            }
            if let Some(units) = job.units {
                out.insert("units".into(), json!(units.name()));
            }
        }
        out.insert(key, value);
    }
    Value::Object(out)
}

/// The model's keys of a job file, in the order of docs/jobs.md: `degree`,
/// `weights` (fuzzy numbers where they are fuzzy), `knots`, `points` (for a surface, docs/method.md §8: `degree` a pair,
/// `weights` and `points` rows of the net, `knots` an object with `u` and
/// `v`); a number's `lower_height` is left out when it equals `top_height`.
pub(crate) fn model_json(model: &Model, top_height: Option<f64>) -> Map<String, Value> {
    struct Keys(Option<f64>);
    impl ModelVisitor for Keys {
        type Output = Map<String, Value>;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Map<String, Value> {
            let mut out = Map::new();
            out.insert("degree".into(), json!(c.degree()));
            let weights = weights_json(c.weights(), c.weight_numbers(), self.0);
            out.insert("weights".into(), Value::Array(weights));
            out.insert("knots".into(), json!(c.knots().as_slice()));
            let points = c.points().iter().map(|p| point_json(p, self.0)).collect();
            out.insert("points".into(), Value::Array(points));
            out
        }
        fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Map<String, Value> {
            let [_, nv] = s.shape();
            let rows = |values: Vec<Value>| -> Value {
                Value::Array(
                    values
                        .chunks(nv.max(1))
                        .map(|r| Value::Array(r.to_vec()))
                        .collect(),
                )
            };
            let mut out = Map::new();
            out.insert("degree".into(), json!(s.degree()));
            let weights = weights_json(s.weights(), s.weight_numbers(), self.0);
            out.insert("weights".into(), rows(weights));
            out.insert(
                "knots".into(),
                json!({
                    "u": s.knots(Direction::U).as_slice(),
                    "v": s.knots(Direction::V).as_slice(),
                }),
            );
            let points = s.points().iter().map(|p| point_json(p, self.0)).collect();
            out.insert("points".into(), rows(points));
            out
        }
    }
    model.visit(Keys(top_height))
}

/// The weights as in a job file, one value per control point: numbers, or
/// the fuzzy weights as fuzzy numbers (a `lower_height` left out when it
/// equals `top_height`).
fn weights_json(
    crisp: &[f64],
    numbers: Option<&[Nt2Number]>,
    top_height: Option<f64>,
) -> Vec<Value> {
    match numbers {
        // Serializing keys and floats into a tree of values cannot fail.
        Some(numbers) => numbers
            .iter()
            .map(|w| {
                serde_json::to_value(NumberView {
                    number: w,
                    top_height,
                })
                .unwrap_or(Value::Null)
            })
            .collect(),
        None => crisp.iter().map(|w| json!(w)).collect(),
    }
}

/// A point as in a job file; a number's `lower_height` is left out when it
/// equals `top_height`, the job's top-level default.
pub(crate) fn point_json<const D: usize>(p: &Nt2Point<D>, top_height: Option<f64>) -> Value {
    // Serializing keys and floats into a tree of values cannot fail.
    serde_json::to_value(PointView {
        point: p,
        top_height,
    })
    .unwrap_or(Value::Null)
}

/// A point as in a job file, serialized straight from the point: the keys
/// of [`point_json`] in its order (`x`, `y`, `z`; in each number `crisp`,
/// `upper`, `primary`, `lower`, then `lower_height` where it differs from
/// `top_height`), without building a tree of values.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PointView<'a, const D: usize> {
    /// The point.
    pub point: &'a Nt2Point<D>,
    /// The file's top-level `lower_height`, if it has one.
    pub top_height: Option<f64>,
}

impl<const D: usize> Serialize for PointView<'_, D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(D))?;
        for (axis, x) in Axis::ALL.iter().zip(self.point.coords()) {
            map.serialize_entry(
                axis.name(),
                &NumberView {
                    number: x,
                    top_height: self.top_height,
                },
            )?;
        }
        map.end()
    }
}

/// One fuzzy number of a [`PointView`].
struct NumberView<'a> {
    number: &'a Nt2Number,
    top_height: Option<f64>,
}

impl Serialize for NumberView<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let x = self.number;
        let height = x.height().get();
        let own_height = self.top_height != Some(height);
        let mut map = serializer.serialize_map(Some(4 + usize::from(own_height)))?;
        map.serialize_entry("crisp", &x.crisp())?;
        let pair = |l: Layer, r: Layer| [x.layer(l), x.layer(r)];
        map.serialize_entry("upper", &pair(Layer::UpperLeft, Layer::UpperRight))?;
        map.serialize_entry("primary", &pair(Layer::PrimaryLeft, Layer::PrimaryRight))?;
        map.serialize_entry("lower", &pair(Layer::LowerLeft, Layer::LowerRight))?;
        if own_height {
            map.serialize_entry("lower_height", &height)?;
        }
        map.end()
    }
}
