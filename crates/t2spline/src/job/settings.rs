//! How a job runs: the level alpha, the type reduction, the number of samples
//! and the derivative order, from the job and from what a front end overrides, every value checked.

use crate::error::{Error, Setting};
use crate::fuzzy::Alpha;
use crate::reduction::TypeReduction;

use super::near_height::NearHeight;
use super::Job;

/// The number of samples when a job gives none (docs/jobs.md).
pub const DEFAULT_SAMPLES: usize = 101;

/// The largest number of samples a run may ask for. A result holds up to 16
/// curves × 3 coordinates per sample, so at this limit it has 48 million
/// numbers: about 1 GB of JSON.
pub const MAX_SAMPLES: usize = 1_000_000;

/// The highest derivative order a run computes. Above it the numbers of a
/// rational curve grow like `K!` and say little; the bound also keeps a
/// result's size in proportion.
pub const MAX_DERIVATIVE_ORDER: usize = 16;

/// The number of surface samples per direction when a surface job gives none
/// (docs/method.md §8: a grid of 21 × 21).
pub const DEFAULT_SURFACE_SAMPLES: usize = 21;

/// How many uniform parameters a run samples: along a curve, or a grid
/// `u_a × v_b` over a surface's domain (docs/jobs.md; docs/method.md §8).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Samples {
    /// `n` parameters along a curve.
    Along(usize),
    /// `[su, sv]` parameters in u and in v.
    Grid([usize; 2]),
}

impl Samples {
    /// The number of sampled points: `n`, or `su · sv`.
    #[must_use]
    pub fn count(self) -> usize {
        match self {
            Samples::Along(n) => n,
            Samples::Grid([u, v]) => u * v,
        }
    }

    /// The counts as [`Overrides::samples`] takes them: `[n]`, or `[su, sv]`.
    #[must_use]
    pub fn counts(self) -> Vec<u64> {
        match self {
            Samples::Along(n) => vec![n as u64],
            Samples::Grid([u, v]) => vec![u as u64, v as u64],
        }
    }
}

impl std::fmt::Display for Samples {
    /// `101`, or `41 × 21` for a grid.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Samples::Along(n) => write!(f, "{n}"),
            Samples::Grid([u, v]) => write!(f, "{u} × {v}"),
        }
    }
}

/// What a front end may set in place of the job's own values; `None` keeps the
/// job's. Values are taken as given (a negative derivative order, a sample
/// count beyond the machine's) and checked by [`Job::settings`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overrides {
    /// The level alpha.
    pub alpha: Option<f64>,
    /// The type reduction of stages 3–4 (docs/method.md §9).
    pub type_reduction: Option<TypeReduction>,
    /// The number of uniform parameters: one count, or for a surface one
    /// count for both directions or two (`[su, sv]`).
    pub samples: Option<Vec<u64>>,
    /// The highest derivative order to compute (none without it; curves only).
    pub derivatives: Option<i64>,
}

/// How a job runs, every value checked: made only by [`Job::settings`],
/// read through its accessors, and never checked again ([`Job::run`] takes
/// it as it is).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    alpha: Alpha,
    type_reduction: TypeReduction,
    unused_alpha: Option<Alpha>,
    samples: Samples,
    derivatives: Option<usize>,
    near_height: Option<NearHeight>,
}

impl Settings {
    /// The level alpha of the cut (stage 2), and with the paper's type
    /// reduction of stages 3–4 too; [`Alpha::ZERO`] (the whole footprint,
    /// which they read) with a reduction that does not use alpha.
    #[must_use]
    pub fn alpha(&self) -> Alpha {
        self.alpha
    }

    /// The type reduction of stages 3–4 (docs/method.md §3, §9).
    #[must_use]
    pub fn type_reduction(&self) -> TypeReduction {
        self.type_reduction
    }

    /// An alpha that the job or the front end gave but the type reduction
    /// does not use; front ends say so rather than ignore it silently.
    #[must_use]
    pub fn unused_alpha(&self) -> Option<Alpha> {
        self.unused_alpha
    }

    /// The level the paper's reduction would use: [`Settings::alpha`], or
    /// the alpha set aside by a reduction that does not use it.
    #[must_use]
    pub fn paper_alpha(&self) -> Alpha {
        self.unused_alpha.unwrap_or(self.alpha)
    }

    /// Uniform parameters at which every curve or surface is sampled (at
    /// least 2 in each direction, at most [`MAX_SAMPLES`] points).
    #[must_use]
    pub fn samples(&self) -> Samples {
        self.samples
    }

    /// With `Some(K)`, the derivatives of orders `1 ..= K` of the crisp and the
    /// defuzzified curve and their arc lengths.
    #[must_use]
    pub fn derivatives(&self) -> Option<usize> {
        self.derivatives
    }

    /// With the paper's reduction, a lower height that alpha lies a few
    /// ulps above ([`NearHeight`]); front ends say so, as a sweep of levels
    /// computed in floating point lands there unnoticed.
    #[must_use]
    pub fn near_height(&self) -> Option<NearHeight> {
        self.near_height
    }
}

impl Job {
    /// The settings of a run of this job: each override if given, else the
    /// job's value.
    ///
    /// Alpha is the paper's parameter (docs/method.md §2–§3): the other type reductions
    /// read the whole number (docs/method.md §9). With one of them alpha may be left
    /// out, stage 2 is shown at [`Alpha::ZERO`] (the whole footprint), and
    /// an alpha given anyway is checked and returned as
    /// [`Settings::unused_alpha`].
    ///
    /// # Errors
    /// [`Error::MissingAlpha`] when neither gives alpha and the type
    /// reduction is the paper's; [`Error::Setting`]
    /// naming the setting whose value breaks its rule: alpha outside [0, 1],
    /// samples outside `2 ..= MAX_SAMPLES` (for a surface: two counts of at
    /// least 2 whose product is at most `MAX_SAMPLES`; for a curve: one
    /// count), a derivative order outside `1 ..= MAX_DERIVATIVE_ORDER` or with
    /// more than [`MAX_SAMPLES`] derivative vectors per curve, or asked of a
    /// surface.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::job::{Overrides, Samples, Setting};
    /// # use t2spline::Error;
    /// # use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point, TypeReduction};
    /// # use t2spline::job::{Job, Model};
    /// # let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.2, c + 0.2], 0.5);
    /// # let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(1.0)?])];
    /// # let curve = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let job = Job { alpha: Some(Alpha::try_new(0.8)?), ..Job::new(Model::Planar(curve)) };
    /// let s = job.settings(&Overrides { samples: Some(vec![5]), ..Overrides::default() })?;
    /// assert_eq!((s.alpha().get(), s.samples(), s.derivatives()), (0.8, Samples::Along(5), None));
    /// let e = job.settings(&Overrides { alpha: Some(1.5), ..Overrides::default() }).unwrap_err();
    /// assert!(matches!(e, Error::Setting { setting: Setting::Alpha, .. }));
    /// assert_eq!(e.to_string(), "alpha = 1.5 is outside [0, 1]");
    /// // The centroid does not use alpha: stage 2 at 0, the job's 0.8 set aside.
    /// let centroid = Overrides { type_reduction: Some(TypeReduction::Centroid), ..Overrides::default() };
    /// let s = job.settings(&centroid)?;
    /// assert_eq!((s.alpha(), s.unused_alpha()), (Alpha::ZERO, Some(Alpha::try_new(0.8)?)));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn settings(&self, overrides: &Overrides) -> Result<Settings, Error> {
        let setting = |setting| move |message| Error::Setting { setting, message };
        let given = match overrides.alpha {
            Some(a) => Some(Alpha::try_new(a).map_err(|e| Error::Setting {
                setting: Setting::Alpha,
                message: e.to_string(),
            })?),
            None => self.alpha,
        };
        let type_reduction = overrides.type_reduction.unwrap_or(self.type_reduction);
        let (alpha, unused_alpha) = if type_reduction.uses_alpha() {
            (given.ok_or(Error::MissingAlpha)?, None)
        } else {
            (Alpha::ZERO, given)
        };
        let surface = self.model.is_surface();
        let samples = match &overrides.samples {
            Some(counts) => samples_of(counts, surface),
            None => match self.samples {
                Samples::Along(n) => samples_of(&[n as u64], false),
                Samples::Grid([u, v]) => samples_of(&[u as u64, v as u64], true),
            },
        }
        .map_err(setting(Setting::Samples))?;
        let derivatives = match (overrides.derivatives, samples) {
            (None, _) => None,
            (Some(k), Samples::Along(n)) => {
                Some(check_derivative_order(k, n).map_err(setting(Setting::Derivatives))?)
            }
            (Some(_), Samples::Grid(_)) => {
                return Err(Error::Setting {
                    setting: Setting::Derivatives,
                    message: "derivatives are offered for curves; this job is a surface".into(),
                })
            }
        };
        let near_height = if type_reduction.uses_alpha() {
            NearHeight::of(&self.model, alpha)
        } else {
            None
        };
        Ok(Settings {
            alpha,
            type_reduction,
            unused_alpha,
            samples,
            derivatives,
            near_height,
        })
    }
}

/// The samples of `counts` as given: one count for a curve; one (both
/// directions) or two counts for a surface, whose product is at most
/// [`MAX_SAMPLES`].
fn samples_of(counts: &[u64], surface: bool) -> Result<Samples, String> {
    match (counts, surface) {
        (&[n], false) => Ok(Samples::Along(check_samples(n, &n.to_string())?)),
        (&[n], true) => samples_of(&[n, n], true),
        (&[u, v], true) => {
            let [u, v] = [u, v].map(|n| check_samples(n, &n.to_string()));
            let grid = [u?, v?];
            check_grid_samples(grid)?;
            Ok(Samples::Grid(grid))
        }
        (_, false) => Err(format!(
            "a curve is sampled at one number of parameters, got {} numbers",
            counts.len()
        )),
        (_, true) => Err(format!(
            "a surface is sampled at one number of parameters for both directions, or two (u, v), got {} numbers",
            counts.len()
        )),
    }
}

/// Checks a number of samples against docs/jobs.md (at least 2) and
/// [`MAX_SAMPLES`]; `written` is the value as its source wrote it (`1e300`,
/// not the `u64` it saturates to).
///
/// # Errors
/// The rule that `n` breaks, as text.
///
/// # Examples
/// ```
/// # use t2spline::job::check_samples;
/// assert_eq!(check_samples(101, "101"), Ok(101));
/// assert_eq!(
///     check_samples(1, "1"),
///     Err("samples = 1: at least 2 are needed (both ends of the domain)".to_owned())
/// );
/// assert!(check_samples(u64::MAX, "1e30").is_err());
/// ```
pub fn check_samples(n: u64, written: &str) -> Result<usize, String> {
    if n < 2 {
        Err(format!(
            "samples = {written}: at least 2 are needed (both ends of the domain)"
        ))
    } else if n > MAX_SAMPLES as u64 {
        Err(format!(
            "samples = {written} is more than the limit {MAX_SAMPLES}"
        ))
    } else {
        usize::try_from(n).map_err(|_| format!("samples = {written} does not fit this machine"))
    }
}

/// Checks the size of a grid of samples `[su, sv]` (docs/method.md §8), each already
/// checked by [`check_samples`]: at most [`MAX_SAMPLES`] grid points.
///
/// # Errors
/// The rule that the grid breaks, as text.
///
/// # Examples
/// ```
/// # use t2spline::job::check_grid_samples;
/// assert_eq!(check_grid_samples([1000, 1000]), Ok(()));
/// assert_eq!(
///     check_grid_samples([2000, 501]),
///     Err("samples = 2000 × 501 = 1002000 grid points is more than the limit 1000000".to_owned())
/// );
/// ```
pub fn check_grid_samples([u, v]: [usize; 2]) -> Result<(), String> {
    let points = u.saturating_mul(v);
    if points > MAX_SAMPLES {
        return Err(format!(
            "samples = {u} × {v} = {points} grid points is more than the limit {MAX_SAMPLES}"
        ));
    }
    Ok(())
}

/// Checks a derivative order `K` for a run with `samples` samples: at least 1,
/// at most [`MAX_DERIVATIVE_ORDER`], and `K·samples` derivative vectors per
/// curve at most [`MAX_SAMPLES`] (the bound of the samples themselves).
///
/// # Errors
/// The rule that `k` breaks, as text.
///
/// # Examples
/// ```
/// # use t2spline::job::check_derivative_order;
/// assert_eq!(check_derivative_order(2, 101), Ok(2));
/// assert!(check_derivative_order(0, 101).is_err());
/// assert!(check_derivative_order(-1, 101).is_err());
/// assert!(check_derivative_order(17, 101).is_err());
/// assert!(check_derivative_order(2, 1_000_000).is_err());
/// ```
pub fn check_derivative_order(k: i64, samples: usize) -> Result<usize, String> {
    if k < 1 {
        return Err(format!(
            "{k}: the highest derivative order must be at least 1"
        ));
    }
    if k > MAX_DERIVATIVE_ORDER as i64 {
        return Err(format!(
            "{k} is more than the highest order offered, {MAX_DERIVATIVE_ORDER}"
        ));
    }
    let vectors = k.saturating_mul(i64::try_from(samples).unwrap_or(i64::MAX));
    if vectors > MAX_SAMPLES as i64 {
        return Err(format!(
            "{k} orders at {samples} samples make {vectors} derivative vectors per curve, more than the limit {MAX_SAMPLES}; lower the derivative order or the number of samples"
        ));
    }
    // 1 ..= MAX_DERIVATIVE_ORDER fits a usize.
    Ok(k as usize)
}
