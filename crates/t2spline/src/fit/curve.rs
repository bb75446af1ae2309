//! Fitting a crisp B-spline curve to data points: global interpolation (The
//! NURBS Book §9.2.1, Algorithm A9.1) and least squares with the end points
//! interpolated (§9.4.1).

use crate::error::{Error, Setting};
use crate::fit::knots::{
    approximation_knots, averaging_knots, check_counts, check_loop_counts, periodic_knots,
};
use crate::fit::system::System;
use crate::fit::Parametrization;
use crate::nurbs::{KnotVector, NurbsCurve};

/// What to fit: the degree, how the data get their parameters, and whether
/// the curve interpolates the data or approximates them with fewer control
/// points; checked once, when made ([`FitOptions::new`]): the fields are
/// private, so options that exist keep the rules that need no data. What
/// needs the data (enough data points for the degree and the control
/// points) is checked by the fit.
///
/// # Examples
/// ```
/// # use t2spline::fit::{FitOptions, Parametrization};
/// let o = FitOptions::interpolation(3)?.with_parametrization(Parametrization::Centripetal);
/// assert_eq!((o.degree(), o.control_points()), (3, None));
/// assert_eq!(FitOptions::approximation(2, 7)?.control_points(), Some(7));
/// assert!(FitOptions::approximation(2, 2).is_err()); // fewer than degree + 1
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FitOptions {
    degree: usize,
    parametrization: Parametrization,
    control_points: Option<usize>,
    closed: bool,
}

impl FitOptions {
    /// A fit of degree `degree`, chord-length parameters, open: with
    /// `control_points` `None`, interpolation, one control point per data
    /// point (§9.2.1); with `Some(n)`, least squares with `n` control points
    /// (§9.4.1), at most the number of data points (checked by the fit).
    ///
    /// # Errors
    /// [`Error::Setting`]: [`Setting::Degree`] for degree 0 (a
    /// piecewise-constant curve does not pass through its data);
    /// [`Setting::ControlPoints`] for fewer than `degree + 1` control points.
    pub fn new(degree: usize, control_points: Option<usize>) -> Result<Self, Error> {
        if degree == 0 {
            return Err(Error::Setting {
                setting: Setting::Degree,
                message:
                    "0 is outside 1 ..: a piecewise-constant curve does not pass through its data"
                        .into(),
            });
        }
        if let Some(n) = control_points.filter(|&n| n <= degree) {
            return Err(Error::Setting {
                setting: Setting::ControlPoints,
                message: format!("{n} is fewer than degree + 1 (the degree is {degree})"),
            });
        }
        Ok(FitOptions {
            degree,
            parametrization: Parametrization::ChordLength,
            control_points,
            closed: false,
        })
    }

    /// Interpolation of degree `degree` ([`FitOptions::new`] with no count).
    ///
    /// # Errors
    /// As [`FitOptions::new`].
    pub fn interpolation(degree: usize) -> Result<Self, Error> {
        FitOptions::new(degree, None)
    }

    /// Least squares of degree `degree` with `control_points` control points
    /// ([`FitOptions::new`]).
    ///
    /// # Errors
    /// As [`FitOptions::new`].
    pub fn approximation(degree: usize, control_points: usize) -> Result<Self, Error> {
        FitOptions::new(degree, Some(control_points))
    }

    /// The same options with another parametrization.
    #[must_use]
    pub fn with_parametrization(self, parametrization: Parametrization) -> Self {
        FitOptions {
            parametrization,
            ..self
        }
    }

    /// The degree `p ≥ 1` of the curve.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// How the data points get their parameters.
    #[must_use]
    pub fn parametrization(&self) -> Parametrization {
        self.parametrization
    }

    /// `None`: interpolate, one control point per data point (§9.2.1).
    /// `Some(n)`: least squares with `n ≥ p + 1` control points, at most the
    /// number of data points, the end points interpolated (§9.4.1). For a
    /// closed fit, `n` distinct control points, at most the number of
    /// distinct data points, and no end points.
    #[must_use]
    pub fn control_points(&self) -> Option<usize> {
        self.control_points
    }

    /// Whether the data are a loop and the curve closed
    /// ([`FitOptions::closed`]).
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The same options for a closed curve through a loop of data points:
    /// periodic knots ([`periodic_knots`](crate::fit::periodic_knots)) on
    /// the loop parameters ([`Parametrization::loop_parameters`]), the last
    /// `p` control points repeating the first `p`, so that the curve is
    /// `C^{p−1}` where it closes. A last data point whose crisp values equal
    /// the first's (within [`CLOSURE_TOLERANCE`](crate::measure::CLOSURE_TOLERANCE)
    /// of the data's size) is the first point again, not another.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::{fit_curve, FitOptions};
    /// // Eight points of the unit circle: a closed cubic through them.
    /// let q: Vec<[f64; 2]> = (0..8)
    ///     .map(|k| { let a = f64::from(k) * std::f64::consts::FRAC_PI_4; [a.cos(), a.sin()] })
    ///     .collect();
    /// let fit = fit_curve(&q, &FitOptions::interpolation(3)?.closed())?;
    /// assert_eq!(fit.curve.control_points().len(), 8 + 3); // the first 3 repeated
    /// let (a, b) = (fit.curve.eval(0.0)?, fit.curve.eval(1.0)?);
    /// assert!((a[0] - b[0]).abs() < 1e-14 && (a[1] - b[1]).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn closed(self) -> Self {
        FitOptions {
            closed: true,
            ..self
        }
    }

    /// The parameters of `points` and the knot vector of the fit: averaging
    /// (Eq. 9.8) for interpolation, Eqs. 9.68–9.69 for least squares with
    /// fewer control points than data points. Least squares with as many
    /// control points as data points is interpolation, and gets its knots.
    ///
    /// # Errors
    /// As [`fit_curve`].
    pub fn parameters_and_knots<const D: usize>(
        &self,
        points: &[[f64; D]],
    ) -> Result<(Vec<f64>, KnotVector), Error> {
        if self.closed {
            return self.loop_parameters_and_knots(points);
        }
        check_counts(points.len(), self.degree)?;
        let params = self.parametrization.parameters(points)?;
        let knots = match self.control_points {
            // As many control points as data points: the least-squares
            // minimum is 0, the interpolant. Eq. 9.69 would place the knots
            // so that the system is nearly singular (condition numbers of
            // 10¹⁵ and more were seen on random data), Eq. 9.8 does not.
            Some(count) if count != points.len() => {
                approximation_knots(&params, self.degree, count)?
            }
            _ => averaging_knots(&params, self.degree)?,
        };
        Ok((params, knots))
    }

    /// [`FitOptions::parameters_and_knots`] of a closed fit: the loop
    /// parameters of the distinct points (one fewer than `points` when the
    /// last repeats the first) and the periodic knots.
    fn loop_parameters_and_knots<const D: usize>(
        &self,
        points: &[[f64; D]],
    ) -> Result<(Vec<f64>, KnotVector), Error> {
        let distinct = loop_length(points);
        check_loop_counts(distinct, self.degree, distinct < points.len())?;
        let params = self.parametrization.loop_parameters(&points[..distinct])?;
        let count = self.control_points.unwrap_or(distinct);
        let knots = periodic_knots(&params, self.degree, count)?;
        Ok((params, knots))
    }
}

/// The number of distinct points of a loop: all of them, or all but the
/// last when its crisp values are the first's within
/// [`CLOSURE_TOLERANCE`](crate::measure::CLOSURE_TOLERANCE) of the points'
/// largest extent along a coordinate (the rule by which a curve closes,
/// docs/method.md §11).
pub(crate) fn loop_length<const D: usize>(points: &[[f64; D]]) -> usize {
    let n = points.len();
    if n < 2 {
        return n;
    }
    let size = crate::measure::extent(points);
    let apart = points[0]
        .iter()
        .zip(&points[n - 1])
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    if apart <= crate::measure::CLOSURE_TOLERANCE * size {
        n - 1
    } else {
        n
    }
}

/// A fitted crisp curve and the parameters its data got.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveFit<const D: usize> {
    /// The curve: weights 1, clamped knots on `[0, 1]`.
    pub curve: NurbsCurve<D>,
    /// The parameter `ūₖ` of each data point.
    pub params: Vec<f64>,
    /// The estimated condition number of the system that was solved: the
    /// control points may be wrong in their last log₁₀(condition) digits.
    pub condition: f64,
}

/// Fits a B-spline curve (all weights 1) to `points`.
///
/// ```text
/// interpolation:  C(ūₖ) = Qₖ for k = 0 … m,  n + 1 = m + 1 control points   (A9.1)
/// least squares:  C(ū₀) = Q₀, C(ū_m) = Q_m,  min Σ_{k=1}^{m−1} |Qₖ − C(ūₖ)|²   (§9.4.1)
/// ```
/// Parameters from [`Parametrization`], knots by averaging (Eq. 9.8) or by
/// Eqs. 9.68–9.69 ([`FitOptions::parameters_and_knots`]). The linear systems
/// are banded and solved by Givens QR (see ARCHITECTURE.md), which needs
/// neither pivoting nor the normal equations; their condition number is
/// estimated and returned.
///
/// # Errors
/// [`Error::TooFewDataPoints`] for fewer than `p + 1`
/// points; [`Error::ControlPointCount`] for more control points than data points; [`Error::CoincidentDataPoints`] for
/// equal neighbours under chord-length or centripetal parameters;
/// [`Error::NotFinite`] for a non-finite coordinate; [`Error::SingularFit`] if
/// the system is singular to working precision; [`Error::IllConditionedFit`]
/// if its condition number exceeds 10¹²; [`Error::FitBeyondLimit`] if a
/// control point lies beyond [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
///
/// # Examples
/// Points on the parabola `y = x²` sampled at its own chord-length parameters
/// are reproduced by a quadratic interpolant wherever it is evaluated:
/// ```
/// # use t2spline::fit::{fit_curve, FitOptions};
/// let q: Vec<[f64; 2]> = (0..6).map(|i| { let x = i as f64 / 5.0; [x, x * x] }).collect();
/// let fit = fit_curve(&q, &FitOptions::interpolation(2)?)?;
/// for (t, qk) in fit.params.iter().zip(&q) {
///     let c = fit.curve.eval(*t)?;
///     assert!((c[0] - qk[0]).abs() < 1e-14 && (c[1] - qk[1]).abs() < 1e-14);
/// }
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn fit_curve<const D: usize>(
    points: &[[f64; D]],
    options: &FitOptions,
) -> Result<CurveFit<D>, Error> {
    check_finite(points)?;
    let (params, knots) = options.parameters_and_knots(points)?;
    let design = System::new(&params, &knots, options.is_closed())?;
    let control = design.fit(&points[..params.len()])?;
    check_within_limit(&control, None)?;
    let weights = vec![1.0; knots.count()];
    let curve = NurbsCurve::try_new(control, weights, knots)?;
    Ok(CurveFit {
        curve,
        params,
        condition: design.condition(),
    })
}

/// [`Error::FitBeyondLimit`] at the first fitted control value (of `layer`)
/// beyond [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE), or that is not finite.
pub(crate) fn check_within_limit<const D: usize>(
    control: &[[f64; D]],
    layer: Option<crate::Layer>,
) -> Result<(), Error> {
    let axes = crate::Axis::first::<D>()?;
    for (i, p) in control.iter().enumerate() {
        for (&axis, &value) in axes.iter().zip(p) {
            if !crate::limits::within_magnitude(value) {
                return Err(Error::FitBeyondLimit {
                    control_point: i,
                    axis,
                    layer,
                    value,
                });
            }
        }
    }
    Ok(())
}

/// [`Error::NotFinite`] at the first non-finite coordinate.
pub(crate) fn check_finite<const D: usize>(points: &[[f64; D]]) -> Result<(), Error> {
    let axes = crate::Axis::first::<D>()?;
    for (i, p) in points.iter().enumerate() {
        for (&axis, &value) in axes.iter().zip(p) {
            if !value.is_finite() {
                return Err(Error::NotFinite {
                    place: crate::Place::new(i, axis),
                    what: "coordinate",
                    value,
                });
            }
        }
    }
    Ok(())
}
