//! The one way every front end prepares and runs a job: its text read by the
//! job file's rules, the settings of the run made from the job and the front
//! end's overrides (checked once, by the core's [`Job::settings`]), the run,
//! and the last guard before anything is written (every number finite).
//!
//! ```text
//! text ─► parse_job ─► Job ─► Job::settings(Overrides) ─► Prepared ─► Job::run ─► check_finite ─► RunOutput
//! ```
//!
//! Errors keep their kind: the job file's problems (with line and column, a
//! missing alpha placed at the job's top-level object), a setting whose value
//! breaks its rule as a typed [`Setting`] for each front end to spell
//! (`--samples`, `samples=`), and what only a bug can cause.

use t2spline::job::{Job, LengthUnit, Overrides, RunOutput, Setting, Settings};
use t2spline::{Alpha, TypeReduction};

use crate::cad::{render_cad, CadFormat, CadMeta};
use crate::error::{Error, Problem};
use crate::finite::check_finite;
use crate::job::locate;
use crate::job::parse_job;

/// What a run does when neither the job nor the front end gives alpha and
/// the type reduction needs it.
#[derive(Clone, Copy, Debug)]
pub enum MissingAlpha<'a> {
    /// Refuse, with `advice` saying how to give it (`"give it in the job
    /// file or with --alpha"`), placed at the job's top-level object.
    Refuse {
        /// How this front end's user gives alpha.
        advice: &'a str,
    },
    /// Take this level (a report's slider start).
    Default(Alpha),
}

/// Why a job could not be prepared or run.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The job's text breaks a rule of job files (a missing alpha among
    /// them), or a run's result holds a number that is not finite.
    #[error(transparent)]
    File(#[from] Error),
    /// A setting's value (given by the front end or the job) breaks its
    /// rule, or takes a run beyond the range of a float (`Setting::Derivatives`).
    #[error("{message}")]
    Setting {
        /// Which setting: each front end spells it its own way.
        setting: Setting,
        /// The value and the rule it breaks.
        message: String,
    },
    /// Any other error of the core: a bug for a job read by the rules.
    #[error(transparent)]
    Core(t2spline::Error),
}

impl From<t2spline::Error> for RunError {
    fn from(e: t2spline::Error) -> Self {
        match e.setting() {
            Some(setting) => RunError::Setting {
                setting,
                message: e.to_string(),
            },
            None => RunError::Core(e),
        }
    }
}

/// A job read and the settings of its run made: what every front end runs,
/// draws or exports.
#[derive(Clone, Debug)]
pub struct Prepared {
    job: Job,
    settings: Settings,
}

impl Prepared {
    /// Reads the job of `text` (named `source` in messages) and makes the
    /// settings of its run from `overrides`; the job's type reduction is the
    /// one the settings chose, so [`Prepared::job`] is the job as it runs.
    ///
    /// # Errors
    /// [`RunError::File`] for a text that breaks a rule of job files, and for
    /// a missing alpha under [`MissingAlpha::Refuse`]; [`RunError::Setting`]
    /// for an override (or the job's own value) that breaks its rule.
    ///
    /// # Examples
    /// ```
    /// use t2spline::job::{Overrides, Setting};
    /// use t2spline_io::{MissingAlpha, Prepared, RunError};
    /// let text = r#"{"order": 2, "lower_height": 0.5, "points": [
    ///   {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]},
    ///    "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
    ///   {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
    ///    "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5]}}]}"#;
    /// let refuse = MissingAlpha::Refuse { advice: "give it in the job file or with --alpha" };
    /// // No alpha anywhere: the problem placed at the job's object.
    /// let e = Prepared::from_text(text, "job.json", &Overrides::default(), refuse).unwrap_err();
    /// assert_eq!(e.to_string(), "job.json:1:1: alpha: missing: give it in the job file or with --alpha");
    /// // A setting out of its range: typed, for the front end to name.
    /// let wide = Overrides { alpha: Some(0.5), samples: Some(vec![1]), ..Overrides::default() };
    /// let e = Prepared::from_text(text, "job.json", &wide, refuse).unwrap_err();
    /// assert!(matches!(e, RunError::Setting { setting: Setting::Samples, .. }));
    /// // And a run, checked finite.
    /// let given = Overrides { alpha: Some(0.5), samples: Some(vec![3]), ..Overrides::default() };
    /// let result = Prepared::from_text(text, "job.json", &given, refuse)?.run()?;
    /// assert_eq!(result.samples.params.along(), &[0.0, 0.5, 1.0]);
    /// # Ok::<(), RunError>(())
    /// ```
    pub fn from_text(
        text: &str,
        source: &str,
        overrides: &Overrides,
        missing_alpha: MissingAlpha<'_>,
    ) -> Result<Prepared, RunError> {
        let job = parse_job(text, source)?;
        Prepared::new(job, text, source, overrides, missing_alpha)
    }

    /// [`Prepared::from_text`] for a job already read from `text`.
    ///
    /// # Errors
    /// As [`Prepared::from_text`], less the rules of job files.
    pub fn new(
        job: Job,
        text: &str,
        source: &str,
        overrides: &Overrides,
        missing_alpha: MissingAlpha<'_>,
    ) -> Result<Prepared, RunError> {
        let method = overrides.type_reduction.unwrap_or(job.type_reduction);
        let mut overrides = overrides.clone();
        let advice = match missing_alpha {
            MissingAlpha::Refuse { advice } => advice,
            MissingAlpha::Default(a) => {
                if method.uses_alpha() && overrides.alpha.is_none() && job.alpha.is_none() {
                    overrides.alpha = Some(a.get());
                }
                ""
            }
        };
        let settings = job.settings(&overrides).map_err(|e| match e {
            t2spline::Error::MissingAlpha => RunError::File(Error::Invalid {
                file: source.to_owned(),
                problems: vec![Problem {
                    line_column: Some(locate(text, "alpha")),
                    message: format!("alpha: missing: {advice}"),
                }],
            }),
            other => other.into(),
        })?;
        let job = Job {
            type_reduction: settings.type_reduction(),
            ..job
        };
        Ok(Prepared { job, settings })
    }

    /// The job, with the type reduction of its run.
    #[must_use]
    pub fn job(&self) -> &Job {
        &self.job
    }

    /// The settings of its run.
    #[must_use]
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The type reduction of the run.
    #[must_use]
    pub fn type_reduction(&self) -> TypeReduction {
        self.settings.type_reduction()
    }

    /// Runs the job ([`Job::run`]) and checks that every number of the
    /// result is finite: `serde_json` would write NaN as `null`, so nothing
    /// is written otherwise.
    ///
    /// # Errors
    /// [`RunError::Setting`] naming [`Setting::Derivatives`] for a
    /// derivative or arc length beyond the range of a float;
    /// [`RunError::File`] with [`Error::NotFinite`] for any other number
    /// that is not finite (a bug).
    pub fn run(&self) -> Result<RunOutput, RunError> {
        let result = self.job.run(&self.settings)?;
        check_finite(&result)?;
        Ok(result)
    }

    /// The job's exact curves (or surfaces) as the text of a CAD file in
    /// `format` ([`render_cad`]: the crisp and defuzzified ones and the six
    /// layers, clamped first where the format needs it), the file named
    /// `name` in its header, written now ([`CadMeta::now`]), its
    /// coordinates in `units` (else the job's `units`, else millimetres);
    /// `source` names the job in messages.
    ///
    /// # Errors
    /// [`RunError::File`] for what the format cannot hold (degree 0; a
    /// surface in DXF); the core's errors of [`Job::geometry`].
    pub fn cad(
        &self,
        format: CadFormat,
        name: String,
        source: &str,
        units: Option<LengthUnit>,
    ) -> Result<String, RunError> {
        let geometry = self.job.geometry(&self.settings)?;
        let geometry = if format.clamps() {
            geometry.clamped()
        } else {
            geometry
        };
        let units = units.or(self.job.units).unwrap_or_default();
        let meta = CadMeta::now(name, self.job.description.clone(), units);
        Ok(render_cad(format, &geometry, &meta, source)?)
    }
}
