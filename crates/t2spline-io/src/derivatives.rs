//! `t2spline run --derivatives K`: derivatives of the crisp and the defuzzified
//! curve at the sample parameters, and their arc lengths.

use serde::{Deserialize, Serialize};
use t2spline::{Alpha, FuzzyCurve, NurbsCurve};

use crate::job::{Job, JobCurve, MAX_SAMPLES};
use crate::result::{Point, RunResult};

/// The highest derivative order `--derivatives` accepts. Above it the numbers
/// of a rational curve grow like `K!` and say little; the bound also keeps a
/// result's size in proportion.
pub const MAX_DERIVATIVE_ORDER: i64 = 16;

/// One value for the crisp and one for the defuzzified curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CrispDefuzzified<T> {
    /// For the crisp curve (through the crisp control points).
    pub crisp: T,
    /// For the defuzzified curve (the crisp type-2 solution, stage 4).
    pub defuzzified: T,
}

/// `curves.derivatives.*`: for each order `1 … K`, the derivative vectors at
/// `curves.params` (`[order − 1][sample]` is a point).
pub type DerivativeCurves = CrispDefuzzified<Vec<Vec<Point>>>;

/// Checks a derivative order `K` for a run with `samples` samples: at least 1,
/// at most [`MAX_DERIVATIVE_ORDER`], and `K·samples` derivative vectors per
/// curve at most [`MAX_SAMPLES`] (the same bound as for the samples).
///
/// # Errors
/// The rule that `k` breaks, as text.
///
/// # Examples
/// ```
/// # use t2spline_io::derivatives::check_derivative_order;
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
    if k > MAX_DERIVATIVE_ORDER {
        return Err(format!(
            "{k} is more than the highest order offered, {MAX_DERIVATIVE_ORDER}"
        ));
    }
    let vectors = k.saturating_mul(i64::try_from(samples).unwrap_or(i64::MAX));
    if vectors > MAX_SAMPLES as i64 {
        return Err(format!(
            "{k} orders at {samples} samples make {vectors} derivative vectors per curve, more than the limit {MAX_SAMPLES}; lower --derivatives or --samples"
        ));
    }
    Ok(k as usize)
}

impl RunResult {
    /// Adds `curves.derivatives` (orders `1 … order` at `curves.params`) and
    /// `curves.arc_length` for the crisp and the defuzzified curve of `job` at
    /// this result's alpha.
    ///
    /// Derivatives are one-sided at knots as in
    /// [`NurbsCurve::derivatives`]: from the right, and from the left at the end
    /// of the domain. Arc lengths are accurate to 10⁻¹⁰ relative.
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::{Job, RunResult};
    /// let job = Job::parse(r#"{"order": 2, "alpha": 0.5, "lower_height": 0.5, "samples": 2, "points": [
    ///   {"x": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}, "y": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}},
    ///   {"x": {"crisp": 3, "upper": [3, 3], "primary": [3, 3], "lower": [3, 3]}, "y": {"crisp": 4, "upper": [4, 4], "primary": [4, 4], "lower": [4, 4]}}]}"#, "job.json")?;
    /// let mut r = RunResult::compute(&job, job.alpha.unwrap(), 2);
    /// r.add_derivatives(&job, 2);
    /// let d = r.curves.derivatives.as_ref().unwrap();
    /// assert_eq!(d.crisp[0], vec![vec![3.0, 4.0], vec![3.0, 4.0]]); // C' at t = 0 and 1
    /// assert_eq!(d.crisp[1], vec![vec![0.0, 0.0], vec![0.0, 0.0]]); // C''
    /// assert!((r.curves.arc_length.as_ref().unwrap().crisp - 5.0).abs() < 1e-14);
    /// # Ok::<(), t2spline_io::Error>(())
    /// ```
    pub fn add_derivatives(&mut self, job: &Job, order: usize) {
        let alpha = Alpha::try_new(self.alpha).expect("a result's alpha is valid");
        let (derivatives, lengths) = match &job.curve {
            JobCurve::Planar(c) => compute(c, alpha, &self.curves.params, order),
            JobCurve::Spatial(c) => compute(c, alpha, &self.curves.params, order),
        };
        self.curves.derivatives = Some(derivatives);
        self.curves.arc_length = Some(lengths);
    }
}

fn compute<const D: usize>(
    curve: &FuzzyCurve<D>,
    alpha: Alpha,
    params: &[f64],
    order: usize,
) -> (DerivativeCurves, CrispDefuzzified<f64>) {
    let crisp = curve.crisp_curve();
    let defuzzified = curve.solve(alpha).defuzzified_curve();
    let derivatives = |c: &NurbsCurve<D>| -> Vec<Vec<Point>> {
        let at: Vec<Vec<[f64; D]>> = params
            .iter()
            .map(|&t| {
                c.derivatives(t, order)
                    .expect("sample parameters lie in the domain")
            })
            .collect();
        (1..=order)
            .map(|k| at.iter().map(|d| d[k].to_vec()).collect())
            .collect()
    };
    (
        CrispDefuzzified {
            crisp: derivatives(&crisp),
            defuzzified: derivatives(&defuzzified),
        },
        CrispDefuzzified {
            crisp: crisp.arc_length(),
            defuzzified: defuzzified.arc_length(),
        },
    )
}
