//! Data files for `t2spline fit`: fuzzy data points in, a job file out.
//!
//! A data file has the keys of a job file (SPEC §8) except `weights` and
//! `knots`, which the fit computes; its `points` are fuzzy *data* points. It
//! goes through the job validator, so its messages are the same
//! (`points[2].y: the order … is broken`).

use std::path::Path;

use serde_json::{json, Map, Value};
use t2spline::fit::{fit_fuzzy, Deviation, FitOptions, FuzzyFit, FuzzyFitMode, OrderViolation};
use t2spline::{Alpha, Axis, FuzzyCurve, Height, Layers, Nt2Point};

use crate::job::parse::parse_data;
use crate::job::point_json;
use crate::{Error, Problem};

/// The fuzzy data points of either dimension.
#[derive(Clone, Debug, PartialEq)]
pub enum DataPoints {
    /// Points with coordinates `x`, `y`.
    Planar(Vec<Nt2Point<2>>),
    /// Points with coordinates `x`, `y`, `z`.
    Spatial(Vec<Nt2Point<3>>),
}

/// A validated data file.
#[derive(Clone, Debug, PartialEq)]
pub struct FitData {
    /// The file name used in messages.
    pub source: String,
    /// Carried to the job.
    pub description: Option<String>,
    /// `"order"` or `"degree"`: the key the file used, used again in the job.
    pub degree_key: &'static str,
    /// The degree of the curve to fit (at least 1).
    pub degree: usize,
    /// Carried to the job.
    pub alpha: Option<Alpha>,
    /// The top-level `lower_height`, if the file gives one; carried to the job.
    pub lower_height: Option<f64>,
    /// `samples`, if the file gives it; carried to the job.
    pub samples: Option<usize>,
    /// The data points (at least `degree + 1`).
    pub points: DataPoints,
}

/// What a fit found, for the report: dimension-free.
#[derive(Clone, Debug, PartialEq)]
pub struct FitSummary {
    /// Number of data points.
    pub data_points: usize,
    /// Number of control points of the curve.
    pub control_points: usize,
    /// How the layers were fitted.
    pub mode: FuzzyFitMode,
    /// The estimated condition number of the fitting system.
    pub condition: f64,
    /// For each layer, the largest distance between its curve and its data at
    /// the data parameters.
    pub deviations: Layers<Deviation>,
    /// For each layer, the largest distance between its fitted spread
    /// `layer − crisp` and the data's, at the data parameters.
    pub spread_deviations: Layers<Deviation>,
    /// Where fitting each layer on its own breaks the order of SPEC §1.
    pub independent_violations: Vec<OrderViolation>,
    /// Coordinates whose data mix lower heights, with the (smallest) height
    /// given to the control points.
    pub mixed_heights: Vec<(Axis, Height)>,
}

/// The outcome of fitting a data file.
#[derive(Clone, Debug, PartialEq)]
pub struct FitOutcome {
    /// What the fit found.
    pub summary: FitSummary,
    /// The job file as JSON, or the places where the control points are not
    /// valid fuzzy numbers (only with [`FuzzyFitMode::Independent`]).
    pub job: Result<Value, Vec<OrderViolation>>,
}

impl FitData {
    /// Parses and validates a data file; `source` names it in messages.
    ///
    /// # Errors
    /// [`Error::Invalid`] listing every problem: those of [`Job::parse`](crate::Job::parse)
    /// (without the rules for weights and knots, which a data file must not
    /// give), fewer than `degree + 1` points, degree 0.
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::FitData;
    /// let e = FitData::parse(r#"{"degree": 2, "knots": [0, 1], "points": []}"#, "data.json").unwrap_err();
    /// assert_eq!(e.lines(), [
    ///     "data.json:1:15: knots: not allowed in a data file: the fit makes the weights (all 1) and the knots",
    ///     "data.json:1:32: points: a curve of degree 2 needs at least 3 data points, got 0",
    /// ]);
    /// ```
    pub fn parse(text: &str, source: &str) -> Result<FitData, Error> {
        let mut data = parse_data(text).map_err(|problems| Error::Invalid {
            file: source.to_owned(),
            problems,
        })?;
        source.clone_into(&mut data.source);
        Ok(data)
    }

    /// Reads and validates a data file.
    ///
    /// # Errors
    /// The errors of [`read_text`](crate::job::read_text) (a file that cannot
    /// be read, is too large or is not UTF-8) and of [`FitData::parse`].
    pub fn read(path: &Path) -> Result<FitData, Error> {
        let text = crate::job::read_text(path)?;
        FitData::parse(&text, &path.display().to_string())
    }

    /// Number of data points.
    #[must_use]
    pub fn len(&self) -> usize {
        match &self.points {
            DataPoints::Planar(p) => p.len(),
            DataPoints::Spatial(p) => p.len(),
        }
    }

    /// Whether there are no data points (never, for a validated file).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Fits a fuzzy curve of the file's degree to the data
    /// ([`t2spline::fit::fit_fuzzy`]) and writes it as a job file: weights 1,
    /// explicit knots, the file's `description`, `alpha`, `lower_height` and
    /// `samples` carried over. The job parses back with
    /// [`Job::parse`](crate::Job::parse).
    ///
    /// `options.degree` is replaced by the file's degree.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming this file for what the fit refuses:
    /// coincident neighbours, too few points for the control points asked
    /// for, a singular or ill-conditioned system.
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::{FitData, Job};
    /// # use t2spline::fit::{FitOptions, FuzzyFitMode};
    /// let data = FitData::parse(r#"{"degree": 1, "lower_height": 0.5, "points": [
    ///   {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]},
    ///    "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
    ///   {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
    ///    "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5]}}
    /// ]}"#, "data.json")?;
    /// let outcome = data.fit(&FitOptions::interpolation(1), FuzzyFitMode::Valid)?;
    /// let job = outcome.job.expect("a valid fit");
    /// assert_eq!(job["knots"], serde_json::json!([0.0, 0.0, 1.0, 1.0]));
    /// assert!(Job::parse(&job.to_string(), "job.json").is_ok());
    /// # Ok::<(), t2spline_io::Error>(())
    /// ```
    pub fn fit(&self, options: &FitOptions, mode: FuzzyFitMode) -> Result<FitOutcome, Error> {
        let options = FitOptions {
            degree: self.degree,
            ..*options
        };
        let invalid = |e: t2spline::Error| Error::Invalid {
            file: self.source.clone(),
            problems: vec![Problem::new(e.to_string())],
        };
        match &self.points {
            DataPoints::Planar(p) => {
                let fit = fit_fuzzy(p, &options, mode).map_err(invalid)?;
                Ok(self.outcome(p.len(), &fit))
            }
            DataPoints::Spatial(p) => {
                let fit = fit_fuzzy(p, &options, mode).map_err(invalid)?;
                Ok(self.outcome(p.len(), &fit))
            }
        }
    }

    /// The error for a fit whose control points break the order of SPEC §1:
    /// one line per broken inequality, then `advice`, each naming this file.
    #[must_use]
    pub fn order_error(&self, violations: &[OrderViolation], advice: &str) -> Error {
        let mut problems = vec![Problem::new(format!(
            "fitting every layer on its own breaks the order of SPEC §1 at {} place(s) of the control points:",
            violations.len()
        ))];
        problems.extend(violations.iter().map(|v| Problem::new(v.to_string())));
        problems.push(Problem::new(advice));
        Error::Invalid {
            file: self.source.clone(),
            problems,
        }
    }

    fn outcome<const D: usize>(&self, data_points: usize, fit: &FuzzyFit<D>) -> FitOutcome {
        let mixed_heights = Axis::first::<D>()
            .into_iter()
            .zip(fit.mixed_heights().into_iter().zip(fit.heights()))
            .filter(|(_, (mixed, _))| *mixed)
            .map(|(axis, (_, h))| (axis, h))
            .collect();
        let summary = FitSummary {
            data_points,
            control_points: fit.knots().count(),
            mode: fit.mode(),
            condition: fit.condition(),
            deviations: *fit.deviations(),
            spread_deviations: *fit.spread_deviations(),
            independent_violations: fit.independent_violations().to_vec(),
            mixed_heights,
        };
        let job = match fit.to_curve() {
            Ok(curve) => Ok(self.job_json(&curve)),
            Err(_) => Err(fit.violations()),
        };
        FitOutcome { summary, job }
    }

    /// The job file of a fitted curve, keys in the order of SPEC §8.
    fn job_json<const D: usize>(&self, curve: &FuzzyCurve<D>) -> Value {
        let mut out = Map::new();
        if let Some(d) = &self.description {
            out.insert("description".into(), json!(d));
        }
        let degree = curve.degree();
        let value = if self.degree_key == "order" {
            degree + 1
        } else {
            degree
        };
        out.insert(self.degree_key.into(), json!(value));
        out.insert("weights".into(), json!(curve.weights()));
        out.insert("knots".into(), json!(curve.knots().as_slice()));
        if let Some(a) = self.alpha {
            out.insert("alpha".into(), json!(a.get()));
        }
        if let Some(h) = self.lower_height {
            out.insert("lower_height".into(), json!(h));
        }
        if let Some(n) = self.samples {
            out.insert("samples".into(), json!(n));
        }
        let points = curve
            .points()
            .iter()
            .map(|p| point_json(p, self.lower_height))
            .collect();
        out.insert("points".into(), Value::Array(points));
        Value::Object(out)
    }
}
