//! Data files for `t2spline fit`: fuzzy data points in, a job file out.
//!
//! A data file has the keys of a job file (docs/jobs.md) except `weights` and
//! `knots`, which the fit computes (`type_reduction` among them, carried to
//! the job); its `points` are fuzzy *data* points. It
//! is read as a job is ([`parse_data`](crate::parse_data)): in one typed
//! pass when it has no problem, else by the job validator, so its messages
//! are the same (`points[2].y: the order … is broken`). The fit
//! itself is the core crate's ([`FuzzyData::fit`]); this module writes its
//! model back as a job file that carries the data file's settings.

use serde_json::{json, Map, Value};
use t2spline::fit::{FuzzyData, OrderViolation};
use t2spline::job::Model;
use t2spline::{Alpha, TypeReduction};

use crate::error::{Error, Problem};
use crate::job_json::model_json;

/// A validated data file.
#[derive(Clone, Debug, PartialEq)]
pub struct FitData {
    /// The file name used in messages.
    pub source: String,
    /// Carried to the job.
    pub description: Option<String>,
    /// `"order"` or `"degree"`: the key the file used, used again in the job.
    pub degree_key: &'static str,
    /// The degree of the curve to fit (at least 1); for the data of a net,
    /// the degree along u.
    pub degree: usize,
    /// The degree along v for the data of a net; `degree` is then the degree
    /// along u. `None` for curves.
    pub degree_v: Option<usize>,
    /// Carried to the job.
    pub alpha: Option<Alpha>,
    /// `type_reduction`, if the file gives one; carried to the job.
    pub type_reduction: Option<TypeReduction>,
    /// The top-level `lower_height`, if the file gives one; carried to the job.
    pub lower_height: Option<f64>,
    /// `samples`, if the file gives it; carried to the job.
    pub samples: Option<usize>,
    /// The data points (at least `degree + 1`; of a net, at least
    /// `degree + 1` rows of at least `degree_v + 1` points).
    pub points: FuzzyData,
}

impl FitData {
    /// Number of data points.
    #[must_use]
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether there are no data points (never, for a validated file).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The job file of a fitted model, keys in the order of docs/jobs.md: the
    /// file's `description`, its `order` or `degree` key, the weights and
    /// knots of the fit, the file's `alpha`, `type_reduction`, `lower_height`
    /// and `samples`,
    /// `"closed": true` for a closed fit (`closed`), and the control points
    /// (a number's `lower_height` only where it differs from the top-level
    /// one). It parses back with [`parse_job`](crate::parse_job).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::{FitOptions, FuzzyFitMode};
    /// let data = t2spline_io::parse_data(r#"{"degree": 1, "lower_height": 0.5, "points": [
    ///   {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]},
    ///    "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
    ///   {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
    ///    "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5]}}
    /// ]}"#, "data.json")?;
    /// let outcome = data.points.fit(&FitOptions::interpolation(data.degree)?, FuzzyFitMode::Valid)?;
    /// let job = data.job_json(&outcome.model.expect("a valid fit"), false);
    /// assert_eq!(job["knots"], serde_json::json!([0.0, 0.0, 1.0, 1.0]));
    /// assert!(t2spline_io::parse_job(&job.to_string(), "job.json").is_ok());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn job_json(&self, model: &Model, closed: bool) -> Value {
        let mut out = Map::new();
        if let Some(d) = &self.description {
            out.insert("description".into(), json!(d));
        }
        for (key, value) in model_json(model, self.lower_height) {
            match key.as_str() {
                "degree" => {
                    // One degree for a curve, a pair `[p, q]` for a surface.
                    let shift = u64::from(self.degree_key == "order");
                    let written = match &value {
                        Value::Array(pair) => json!(pair
                            .iter()
                            .map(|d| d.as_u64().unwrap_or_default() + shift)
                            .collect::<Vec<_>>()),
                        _ => json!(value.as_u64().unwrap_or_default() + shift),
                    };
                    out.insert(self.degree_key.into(), written);
                }
                "points" => {
                    if let Some(a) = self.alpha {
                        out.insert("alpha".into(), json!(a.get()));
                    }
                    if let Some(t) = self.type_reduction {
                        out.insert("type_reduction".into(), json!(t.name()));
                    }
                    if let Some(h) = self.lower_height {
                        out.insert("lower_height".into(), json!(h));
                    }
                    if let Some(n) = self.samples {
                        out.insert("samples".into(), json!(n));
                    }
                    if closed {
                        out.insert("closed".into(), json!(true));
                    }
                    out.insert(key, value);
                }
                _ => {
                    out.insert(key, value);
                }
            }
        }
        Value::Object(out)
    }

    /// An error naming this file, for what the fit of its data refused
    /// (coincident neighbours, too few points for the control points asked
    /// for, a singular or ill-conditioned system).
    #[must_use]
    pub fn fit_error(&self, e: &t2spline::Error) -> Error {
        Error::Invalid {
            file: self.source.clone(),
            problems: vec![Problem::new(e.to_string())],
        }
    }

    /// The error for a fit whose control points break the order of docs/method.md §1:
    /// one line per broken inequality (at most
    /// [`MAX_PROBLEMS`](crate::limits::MAX_PROBLEMS), then a count of the rest),
    /// then `advice`, each naming this file.
    #[must_use]
    pub fn order_error(&self, violations: &[OrderViolation], advice: &str) -> Error {
        let limit = crate::limits::MAX_PROBLEMS;
        let mut problems = vec![Problem::new(format!(
            "fitting every layer on its own breaks the order of the seven values at {} place(s) of the control points:",
            violations.len()
        ))];
        problems.extend(
            violations
                .iter()
                .take(limit)
                .map(|v| Problem::new(v.to_string())),
        );
        if violations.len() > limit {
            problems.push(Problem::new(format!(
                "… and {} more place(s)",
                violations.len() - limit
            )));
        }
        problems.push(Problem::new(advice));
        Error::Invalid {
            file: self.source.clone(),
            problems,
        }
    }
}
