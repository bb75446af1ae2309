//! Job files (SPEC §8): reading, validating every rule at once, and writing back.

pub mod limits;
pub(crate) mod parse;
mod position;
mod read;

pub use limits::{
    check_samples, DEFAULT_SAMPLES, MAX_ARRAY, MAX_FILE_BYTES, MAX_KEYS, MAX_NESTING, MAX_ORDER,
    MAX_POINTS, MAX_PROBLEMS, MAX_SAMPLES, MAX_VALUES,
};
pub use position::{locate, LineColumn};
pub use read::{read_text, read_text_from};

use std::path::Path;

use serde_json::{json, Map, Value};
use t2spline::{Alpha, FuzzyCurve, Layer, Nt2Point};

use crate::Error;

/// A validated job: a fuzzy curve in 2-D or 3-D and how to run it (SPEC §8).
#[derive(Clone, Debug, PartialEq)]
pub struct Job {
    /// Free text carried along to the result.
    pub description: Option<String>,
    /// The level alpha; may be left to the command line.
    pub alpha: Option<Alpha>,
    /// Number of uniform parameters at which curves are sampled (2 … [`MAX_SAMPLES`]).
    pub samples: usize,
    /// The fuzzy curve.
    pub curve: JobCurve,
}

/// A fuzzy curve of either dimension.
#[derive(Clone, Debug, PartialEq)]
pub enum JobCurve {
    /// Points with coordinates `x`, `y`.
    Planar(FuzzyCurve<2>),
    /// Points with coordinates `x`, `y`, `z`.
    Spatial(FuzzyCurve<3>),
}

impl JobCurve {
    /// 2 or 3.
    #[must_use]
    pub fn dimension(&self) -> usize {
        match self {
            JobCurve::Planar(_) => 2,
            JobCurve::Spatial(_) => 3,
        }
    }
}

impl Job {
    /// Parses and validates a job from JSON text; `source` names the file in
    /// messages.
    ///
    /// # Errors
    /// [`Error::Invalid`] listing every problem found: JSON syntax, duplicate,
    /// unknown or missing keys, wrong types, the limits of [`limits`], and
    /// every rule of SPEC §1, §6 and §8. Each names its line and column (of the
    /// key or element concerned; for a missing key, of the object that lacks it)
    /// and its place (`points[2].y`, `weights[1]`, `knots`, ...).
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::Job;
    /// let e = Job::parse(r#"{"order": 2, "alhpa": 0.5, "points": []}"#, "job.json").unwrap_err();
    /// assert_eq!(e.lines(), [
    ///     "job.json:1:14: alhpa: unknown key (did you mean `alpha`?)",
    ///     "job.json:1:28: points: a curve of order 2 needs at least 2 control points, got 0",
    /// ]);
    /// ```
    pub fn parse(text: &str, source: &str) -> Result<Job, Error> {
        parse::parse(text).map_err(|problems| Error::Invalid {
            file: source.to_owned(),
            problems,
        })
    }

    /// Reads and validates a job file.
    ///
    /// # Errors
    /// The errors of [`read_text`] (a file that cannot be read, is too large or
    /// is not UTF-8) and of [`Job::parse`].
    pub fn read(path: &Path) -> Result<Job, Error> {
        let text = read_text(path)?;
        Job::parse(&text, &path.display().to_string())
    }

    /// The job as JSON in canonical form: explicit weights and knots, and every
    /// number with its own `lower_height`. Parsing it gives back an equal job.
    #[must_use]
    pub fn to_json(&self) -> Value {
        let mut out = Map::new();
        if let Some(d) = &self.description {
            out.insert("description".into(), json!(d));
        }
        let (degree, weights, knots, points) = match &self.curve {
            JobCurve::Planar(c) => curve_parts(c),
            JobCurve::Spatial(c) => curve_parts(c),
        };
        out.insert("degree".into(), json!(degree));
        out.insert("weights".into(), json!(weights));
        out.insert("knots".into(), json!(knots));
        if let Some(a) = self.alpha {
            out.insert("alpha".into(), json!(a.get()));
        }
        out.insert("samples".into(), json!(self.samples));
        out.insert("points".into(), Value::Array(points));
        Value::Object(out)
    }
}

fn curve_parts<const D: usize>(c: &FuzzyCurve<D>) -> (usize, Vec<f64>, Vec<f64>, Vec<Value>) {
    let points = c.points().iter().map(|p| point_json(p, None)).collect();
    (
        c.degree(),
        c.weights().to_vec(),
        c.knots().as_slice().to_vec(),
        points,
    )
}

/// A point as in a job file; a number's `lower_height` is left out when it
/// equals `top_height`, the job's top-level default.
pub(crate) fn point_json<const D: usize>(p: &Nt2Point<D>, top_height: Option<f64>) -> Value {
    let mut out = Map::new();
    for (axis, x) in t2spline::Axis::first::<D>().iter().zip(p.coords()) {
        let pair = |l: Layer, r: Layer| json!([x.layer(l), x.layer(r)]);
        let mut number = json!({
            "crisp": x.crisp(),
            "upper": pair(Layer::UpperLeft, Layer::UpperRight),
            "primary": pair(Layer::PrimaryLeft, Layer::PrimaryRight),
            "lower": pair(Layer::LowerLeft, Layer::LowerRight),
        });
        if top_height != Some(x.height().get()) {
            number["lower_height"] = json!(x.height().get());
        }
        out.insert(axis.name().into(), number);
    }
    Value::Object(out)
}
