//! The one error type of the core crate.
//!
//! Every variant names the rule that was broken and, where it has one, the place
//! (point index and coordinate) where it was broken. Messages are lowercase, one
//! line, without a final period, so that callers can prefix a file name.

use std::fmt;

use crate::place::Axis;
pub use crate::place::Place;

/// A number in a message: as `Display` writes it (`0.5`, `2`, `-3.25`), but in
/// exponent form when that would take more than about 20 digits (`1e301`,
/// `2.5e-200`), so that an extreme value does not become a 300-digit line.
///
/// ```
/// # use t2spline::Num;
/// assert_eq!(Num(0.0).to_string(), "0");
/// assert_eq!(Num(-2.5).to_string(), "-2.5");
/// assert_eq!(Num(1e301).to_string(), "1e301");
/// assert_eq!(Num(-2.5e-200).to_string(), "-2.5e-200");
/// assert_eq!(Num(f64::NAN).to_string(), "NaN");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = self.0.abs();
        if a.is_finite() && a != 0.0 && !(1e-6..1e16).contains(&a) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

/// A positive number rounded up to two significant digits for a message
/// (`6.499999999999999e-7` is shown as `6.5e-7`, `6.41e-7` as `6.5e-7`).
struct RoundedUp(f64);

impl fmt::Display for RoundedUp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !(x.is_finite() && x > 0.0) {
            return write!(f, "{}", Num(x));
        }
        let mut exponent = x.log10().floor() as i32;
        // Two digits, up; a relative 1e-12 absorbs the rounding of `x` itself.
        let mut digits = (x / 10f64.powi(exponent - 1) * (1.0 - 1e-12)).ceil();
        if digits >= 100.0 {
            digits /= 10.0;
            exponent += 1;
        }
        let shown = digits / 10.0;
        if exponent == 0 {
            write!(f, "{shown:.1}")
        } else {
            write!(f, "{shown:.1}e{exponent}")
        }
    }
}

/// A setting of a run, to name it in messages: each front end spells it its
/// own way (`--samples` on the command line, `samples=` in Python).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Setting {
    /// The level alpha.
    Alpha,
    /// The number of samples.
    Samples,
    /// The highest derivative order.
    Derivatives,
    /// The parameters of a benchmark (`t2spline bench`).
    Points,
    /// The threads of a benchmark.
    Threads,
    /// The levels of a measurement.
    Levels,
    /// The parameters of a measurement.
    At,
    /// The order of a measurement's derivative.
    Order,
    /// The height of the plane a surface's volumes are measured from.
    Datum,
    /// The degree of a fit.
    Degree,
    /// The number of control points of a least-squares fit.
    ControlPoints,
}

impl Setting {
    /// The name in job files and in the Python API.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Setting::Alpha => "alpha",
            Setting::Samples => "samples",
            Setting::Derivatives => "derivatives",
            Setting::Points => "points",
            Setting::Threads => "threads",
            Setting::Levels => "levels",
            Setting::At => "at",
            Setting::Order => "order",
            Setting::Datum => "datum",
            Setting::Degree => "degree",
            Setting::ControlPoints => "control_points",
        }
    }
}

/// Everything that can be wrong with the input of the core crate.
///
/// The library never panics on user input; each validated constructor
/// (`try_new`) returns one of these instead.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A value that must be a finite number is NaN or infinite.
    ///
    /// ```
    /// # use t2spline::{Error, Nt2Number};
    /// let e = Nt2Number::try_new(f64::NAN, [0.0, 1.0], [0.0, 1.0], [0.0, 1.0], 0.5).unwrap_err();
    /// assert!(matches!(e, Error::NotFinite { what: "crisp", .. }));
    /// ```
    #[error("{place}{what} = {value} is not a finite number")]
    NotFinite {
        /// Where the value was found.
        place: Place,
        /// Which value (`"crisp"`, `"upper.left"`, `"weight"`, ...).
        what: &'static str,
        /// The offending value.
        value: f64,
    },

    /// The seven values of a fuzzy number are out of order (docs/method.md §1).
    ///
    /// ```
    /// # use t2spline::{Error, Nt2Number};
    /// let e = Nt2Number::try_new(1.0, [0.7, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6).unwrap_err();
    /// assert!(matches!(e, Error::Order { rule: "upper.left <= primary.left", .. }));
    /// assert_eq!(e.to_string(), "the order upper.left <= primary.left is broken: 0.7 > 0.6");
    /// ```
    #[error("{place}the order {rule} is broken: {} > {}", Num(*left), Num(*right))]
    Order {
        /// Where the number is.
        place: Place,
        /// The broken inequality, in the words of docs/method.md §1.
        rule: &'static str,
        /// The value on the left of the inequality.
        left: f64,
        /// The value on the right of the inequality.
        right: f64,
    },

    /// A scalar is outside the range it must lie in.
    ///
    /// ```
    /// # use t2spline::{Alpha, Error};
    /// let e = Alpha::try_new(1.5).unwrap_err();
    /// assert_eq!(e.to_string(), "alpha = 1.5 is outside [0, 1]");
    /// ```
    #[error("{place}{what} = {} is outside {range}", Num(*value))]
    OutOfRange {
        /// Where the value was found.
        place: Place,
        /// Which value (`"alpha"`, `"lower_height"`, ...).
        what: &'static str,
        /// The offending value.
        value: f64,
        /// The allowed range, as text (`"[0, 1]"`, `"(0, 1]"`).
        range: &'static str,
    },

    /// A curve of order `k` needs at least `k` control points (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let e = NurbsCurve::<2>::try_clamped(2, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 1.0]).unwrap_err();
    /// assert_eq!(e, Error::TooFewControlPoints { order: 3, count: 2 });
    /// ```
    #[error("a curve of order {order} needs at least {order} control points, got {count}")]
    TooFewControlPoints {
        /// The order `k = degree + 1`.
        order: usize,
        /// The number of control points given.
        count: usize,
    },

    /// A weight is finite and positive but outside
    /// [[`MIN_WEIGHT`](crate::MIN_WEIGHT), [`MAX_WEIGHT`](crate::MAX_WEIGHT)].
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let e = NurbsCurve::<2>::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 1e151]).unwrap_err();
    /// assert_eq!(e.to_string(), "weights[1] = 1e151 is outside [1e-150, 1e150]");
    /// ```
    #[error("weights[{index}] = {} is outside [1e-150, 1e150]", Num(*value))]
    WeightOutOfRange {
        /// Index of the weight (0-based).
        index: usize,
        /// The offending value.
        value: f64,
    },

    /// There must be one weight per control point.
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let e = NurbsCurve::<2>::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0]).unwrap_err();
    /// assert_eq!(e, Error::WeightCount { expected: 2, found: 1 });
    /// ```
    #[error("weights: expected {expected} (one per control point), got {found}")]
    WeightCount {
        /// Number of control points.
        expected: usize,
        /// Number of weights given.
        found: usize,
    },

    /// A weight is not a finite number greater than 0 (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let e = NurbsCurve::<2>::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 0.0]).unwrap_err();
    /// assert_eq!(e.to_string(), "weights[1] = 0 must be finite and greater than 0");
    /// ```
    #[error("weights[{index}] = {} must be finite and greater than 0", Num(*value))]
    Weight {
        /// Index of the weight (0-based).
        index: usize,
        /// The offending value.
        value: f64,
    },

    /// The knot vector must have `n + k` values (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector};
    /// let e = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0], 2, 3).unwrap_err();
    /// assert_eq!(e, Error::KnotCount { expected: 6, found: 4 });
    /// ```
    #[error("knots: expected {expected} values (control points + order), got {found}")]
    KnotCount {
        /// `n + k`.
        expected: usize,
        /// Number of knots given.
        found: usize,
    },

    /// A knot is not a finite number.
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector};
    /// let e = KnotVector::try_new(vec![0.0, 0.0, f64::INFINITY, 1.0], 1, 2).unwrap_err();
    /// assert!(matches!(e, Error::KnotNotFinite { index: 2, .. }));
    /// ```
    #[error("knots[{index}] = {value} is not a finite number")]
    KnotNotFinite {
        /// Index of the knot (0-based).
        index: usize,
        /// The offending value.
        value: f64,
    },

    /// A knot is finite but its magnitude is more than
    /// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector};
    /// let e = KnotVector::try_new(vec![-2e150, 0.0, 1.0, 1.0], 1, 2).unwrap_err();
    /// assert_eq!(e.to_string(), "knots[0] = -2e150 is outside [-1e150, 1e150]");
    /// ```
    #[error("knots[{index}] = {} is outside [-1e150, 1e150]", Num(*value))]
    KnotOutOfRange {
        /// Index of the knot (0-based).
        index: usize,
        /// The offending value.
        value: f64,
    },

    /// Knots must not decrease (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector};
    /// let e = KnotVector::try_new(vec![0.0, 0.0, 0.7, 0.5, 1.0, 1.0], 1, 4).unwrap_err();
    /// assert_eq!(e.to_string(), "knots[3] = 0.5 is less than knots[2] = 0.7: knots must not decrease");
    /// ```
    #[error("knots[{index}] = {} is less than knots[{}] = {}: knots must not decrease", Num(*value), index.saturating_sub(1), Num(*previous))]
    KnotDecreasing {
        /// Index of the knot that is smaller than its predecessor.
        index: usize,
        /// The predecessor's value.
        previous: f64,
        /// The knot's value.
        value: f64,
    },

    /// A knot repeats more than `k` times (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector};
    /// let e = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0], 1, 3).unwrap_err();
    /// assert_eq!(e.to_string(), "knots[0..3]: the value 0 repeats 3 times, more than the order 2");
    /// ```
    #[error("knots[{first}..{}]: the value {} repeats {multiplicity} times, more than the order {order}", first.saturating_add(*multiplicity), Num(*value))]
    KnotMultiplicity {
        /// Index of the first copy.
        first: usize,
        /// The repeated value.
        value: f64,
        /// How many times it repeats.
        multiplicity: usize,
        /// The order `k`.
        order: usize,
    },

    /// The parameter domain `[U[p], U[n]]` is empty (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector};
    /// let e = KnotVector::try_new(vec![0.0, 1.0, 1.0, 1.0, 2.0, 3.0], 2, 3).unwrap_err();
    /// assert!(matches!(e, Error::EmptyDomain { .. }));
    /// ```
    #[error("knots: the domain [knots[{degree}], knots[{count}]] = [{}, {}] is empty; it needs knots[{degree}] < knots[{count}]", Num(*start), Num(*end))]
    EmptyDomain {
        /// The degree `p`.
        degree: usize,
        /// The number of control points `n`.
        count: usize,
        /// `U[p]`.
        start: f64,
        /// `U[n]`.
        end: f64,
    },

    /// A parameter is NaN or outside the curve's domain.
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let c = NurbsCurve::<2>::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 1.0])?;
    /// assert!(matches!(c.eval(1.5), Err(Error::OutOfDomain { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("parameter t = {} is outside the domain [{}, {}]", Num(*t), Num(*start), Num(*end))]
    OutOfDomain {
        /// The parameter.
        t: f64,
        /// Start of the domain.
        start: f64,
        /// End of the domain.
        end: f64,
    },

    /// A knot cannot be inserted that many times: its multiplicity would pass
    /// the order `k` (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let c = NurbsCurve::<2>::try_clamped(2, vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], vec![1.0; 3])?;
    /// let e = c.insert_knot(0.5, 4).unwrap_err();
    /// assert_eq!(e.to_string(), "cannot insert knot 0.5 4 times: it has multiplicity 0 and may have at most the order 3");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("cannot insert knot {knot} {times} times: it has multiplicity {multiplicity} and may have at most the order {order}")]
    KnotInsertion {
        /// The knot value.
        knot: f64,
        /// How many insertions were asked for.
        times: usize,
        /// Its multiplicity before insertion.
        multiplicity: usize,
        /// The order `k`.
        order: usize,
    },

    /// A curve can only be split strictly inside its domain.
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let c = NurbsCurve::<2>::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 1.0])?;
    /// assert!(matches!(c.split_at(1.0), Err(Error::SplitOutside { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("cannot split at t = {t}: it must lie strictly inside the domain ({start}, {end})")]
    SplitOutside {
        /// The parameter.
        t: f64,
        /// Start of the domain.
        start: f64,
        /// End of the domain.
        end: f64,
    },

    /// An arc length outside `[0, total length]`, by more than the relative
    /// accuracy of lengths (`LENGTH_TOLERANCE`), has no parameter.
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let c = NurbsCurve::<2>::try_clamped(1, vec![[0.0, 0.0], [3.0, 4.0]], vec![1.0, 1.0])?;
    /// assert!(matches!(c.param_at_length(6.0), Err(Error::LengthOutside { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("arc length {length} is outside [0, {total}], the length of the curve")]
    LengthOutside {
        /// The length asked for.
        length: f64,
        /// The length of the whole curve.
        total: f64,
    },

    /// The curve has no direction here: every derivative up to the degree
    /// vanishes (the curve is constant around `t`), or the first derivative
    /// vanishes where a quantity needs it (curvature at a cusp).
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let c = NurbsCurve::<2>::try_clamped(1, vec![[1.0, 1.0], [1.0, 1.0]], vec![1.0, 1.0])?;
    /// assert!(matches!(c.tangent(0.5), Err(Error::Singular { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("the {what} at t = {t} is undefined: the curve has zero speed there")]
    Singular {
        /// `"tangent"` or `"curvature"`.
        what: &'static str,
        /// The parameter.
        t: f64,
    },

    /// An operation on a valid curve would give a curve outside the input
    /// ranges: degree elevation removes knots by dividing by knot differences,
    /// and knots very close together or weights many orders of magnitude apart
    /// amplify rounding past any meaningful value.
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector, NurbsCurve};
    /// // Interior knots 1e-311 apart (subnormal) and weights 1e150 apart.
    /// let u = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 1e-311, 2e-311, 1.0, 1.0, 1.0, 1.0], 3, 6)?;
    /// let c = NurbsCurve::try_new(
    ///     vec![[0.0, 1.0], [1.0, -1.0], [2.0, 1.0], [3.0, -1.0], [4.0, 1.0], [5.0, -1.0]],
    ///     vec![1.0, 1e-150, 1e-150, 1.0, 1e-150, 1.0], u)?;
    /// assert!(matches!(c.elevate_degree(1), Err(Error::IllConditioned { operation: "degree elevation", .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{operation}: the result would have {what} = {} outside {range}; the knots are too close together or the weights too far apart for it", Num(*value))]
    IllConditioned {
        /// `"degree elevation"`, `"splitting"`, ...
        operation: &'static str,
        /// `"a weight"` or `"a coordinate"`.
        what: &'static str,
        /// The value.
        value: f64,
        /// The range it should lie in.
        range: &'static str,
    },

    /// An operation that makes new fuzzy control points needs one lower height
    /// per coordinate: a combination of numbers with different heights has no
    /// height that keeps the alpha-cut curves unchanged (docs/method.md §6).
    ///
    /// ```
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64, h: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c, c], [c, c], h);
    /// let points = vec![
    ///     Nt2Point::new([n(0.0, 0.5)?, n(0.0, 0.5)?]),
    ///     Nt2Point::new([n(1.0, 0.7)?, n(1.0, 0.5)?]),
    /// ];
    /// let c = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let e = c.insert_knot(0.5, 1).unwrap_err();
    /// assert_eq!(e.to_string(), "points[1].x: lower_height 0.7 differs from 0.5 of points[0].x; this operation needs one lower height per coordinate");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{place}lower_height {height} differs from {expected} of points[0].{axis}; this operation needs one lower height per coordinate", axis = place.axis.map_or("?", |a| a.name()))]
    MixedHeights {
        /// The first number whose height differs from the first point's.
        place: Place,
        /// Its height.
        height: f64,
        /// The height of the same coordinate of the first point.
        expected: f64,
    },

    /// A curve of degree `p` through data needs at least `p + 1` data points.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::{fit_curve, FitOptions};
    /// let e = fit_curve(&[[0.0, 0.0], [1.0, 1.0]], &FitOptions::interpolation(2)?).unwrap_err();
    /// assert_eq!(e.to_string(), "points: a curve of degree 2 needs at least 3 data points, got 2");
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[error("points: a curve of degree {degree} needs at least {} data points, got {count}", degree.saturating_add(1))]
    TooFewDataPoints {
        /// The degree `p`.
        degree: usize,
        /// The number of data points given.
        count: usize,
    },

    /// A closed curve of degree `p` around a loop of data needs at least
    /// `p + 1` distinct data points; a last point repeating the first
    /// (`repeated`) is the first again and does not count.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::{fit_curve, FitOptions};
    /// let q = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.0]];
    /// let e = fit_curve(&q, &FitOptions::interpolation(3)?.closed()).unwrap_err();
    /// assert_eq!(e, Error::TooFewClosedDataPoints { degree: 3, count: 3, repeated: true });
    /// assert_eq!(e.to_string(), "points: a closed curve of degree 3 needs at least 4 distinct data points around its loop, got 3 (the last point repeats the first and counts once)");
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[error("points: a closed curve of degree {degree} needs at least {} distinct data points around its loop, got {count}{}", degree.saturating_add(1), if *repeated { " (the last point repeats the first and counts once)" } else { "" })]
    TooFewClosedDataPoints {
        /// The degree `p`.
        degree: usize,
        /// The number of distinct data points.
        count: usize,
        /// Whether the data's last point repeated the first.
        repeated: bool,
    },

    /// A net of data points (a surface) cannot be fitted closed: closed fits
    /// are for curves.
    ///
    /// ```
    /// # use t2spline::{Error, Nt2Number, Nt2Point};
    /// # use t2spline::fit::{FitOptions, FuzzyData, FuzzyFitMode};
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let net = (0..3)
    ///     .map(|i| (0..3).map(|j| Ok(Nt2Point::new([c(i as f64)?, c(j as f64)?, c(0.0)?]))).collect())
    ///     .collect::<Result<Vec<Vec<_>>, Error>>()?;
    /// let e = FuzzyData::Net(net).fit(&FitOptions::interpolation(2)?.closed(), FuzzyFitMode::Valid).unwrap_err();
    /// assert_eq!(e, Error::ClosedSurfaceFit);
    /// # Ok::<(), Error>(())
    /// ```
    #[error("closed: a net of data points is fitted by a surface, which cannot be closed; a closed fit is for the data points of a curve, taken as a loop")]
    ClosedSurfaceFit,

    /// A station of a readings file has fewer readings than percentiles need
    /// ([`MIN_READINGS`](crate::fit::MIN_READINGS)).
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::{fuzzify, FuzzifyRule};
    /// let stations = vec![vec![[0.0, 0.0], [1.0, 1.0]], vec![[2.0, 2.0]]];
    /// let e = fuzzify(&stations, &FuzzifyRule::try_new(0.0, 0.5)?).unwrap_err();
    /// assert_eq!(e, Error::TooFewReadings { station: Some(1), count: 1 });
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{}{count} reading(s); percentiles need at least 2", station.map_or(String::new(), |s| format!("station {s} (points[{s}]): ")))]
    TooFewReadings {
        /// The station (0-based, as the data point it becomes), if known.
        station: Option<usize>,
        /// The number of readings given.
        count: usize,
    },

    /// Fitting needs degree 1 or more: knots by averaging divide by the degree,
    /// and a piecewise-constant curve cannot pass through distinct points.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::averaging_knots;
    /// let e = averaging_knots(&[0.0, 1.0], 0).unwrap_err();
    /// assert_eq!(e, Error::ZeroDegreeFit);
    /// ```
    #[error("degree 0 cannot be fitted: a piecewise-constant curve does not pass through its data; give degree 1 or more")]
    ZeroDegreeFit,

    /// Least squares with `n` control points needs `p + 1 ≤ n ≤` the number of
    /// data points.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::{fit_curve, FitOptions};
    /// let q = [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]];
    /// let e = fit_curve(&q, &FitOptions::approximation(1, 5)?).unwrap_err();
    /// assert_eq!(e.to_string(), "control points: 5 is outside [2, 3] (degree + 1 to the number of data points)");
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[error("control points: {count} is outside [{min}, {max}] (degree + 1 to the number of data points)")]
    ControlPointCount {
        /// The number asked for.
        count: usize,
        /// `p + 1`.
        min: usize,
        /// The number of data points.
        max: usize,
    },

    /// Two consecutive data points coincide (or nearly so), so chord-length or
    /// centripetal parameters would give them one parameter.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::{fit_curve, FitOptions};
    /// let q = [[0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]];
    /// let e = fit_curve(&q, &FitOptions::interpolation(2)?).unwrap_err();
    /// assert_eq!(e, Error::CoincidentDataPoints { first: 1, second: 2 });
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[error("points[{first}] and points[{second}]: consecutive data points at the same crisp position get the same parameter; remove or merge the repeat, or use uniform parameters")]
    CoincidentDataPoints {
        /// Index of the first point.
        first: usize,
        /// Index of the second point.
        second: usize,
    },

    /// The fitting system is singular to working precision: the data do not
    /// determine a control point.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::{fit_curve, FitOptions};
    /// // points[1] and points[2] are 1e-15 apart: their parameters differ, but
    /// // the two equations agree to working precision.
    /// let q = [[0.0, 0.0], [1.0, 0.0], [1.0 + 1e-15, 0.0], [2.0, 1.0]];
    /// let e = fit_curve(&q, &FitOptions::interpolation(2)?).unwrap_err();
    /// assert_eq!(e, Error::SingularFit { column: 2 });
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[error("the fitting system is singular to working precision: control point {column} is not determined by the data (are data points repeated, or their parameters too close?)")]
    SingularFit {
        /// The first control point that is not determined.
        column: usize,
    },

    /// The fitting system is so ill-conditioned that the control points would
    /// keep fewer than four correct digits (condition number above 10¹²).
    /// Least squares with nearly as many control points as data points does
    /// this with the knots of The NURBS Book Eq. 9.69; fewer control points
    /// help.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::fit::{fit_curve, FitOptions};
    /// // 39 points spaced ever wider (chords grow by 10 % each), degree 5.
    /// let q: Vec<[f64; 2]> = (0..39).map(|k| [1.1f64.powi(k), 0.0]).collect();
    /// let e = fit_curve(&q, &FitOptions::approximation(5, 38)?).unwrap_err();
    /// assert!(matches!(e, Error::IllConditionedFit { .. }), "{e}");
    /// assert!(fit_curve(&q, &FitOptions::approximation(5, 20)?).is_ok());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[error("the fitting system is too ill-conditioned (condition number {condition:.1e}): the control points would keep fewer than four correct digits; use fewer control points, or check for nearly repeated data points")]
    IllConditionedFit {
        /// The estimated condition number.
        condition: f64,
    },

    /// Fitting each layer on its own gave control points that break the order
    /// of docs/method.md §1; the valid fit ([`FuzzyFitMode::Valid`](crate::fit::FuzzyFitMode::Valid)) avoids this.
    ///
    /// ```
    /// # use t2spline::{Error, Nt2Number, Nt2Point};
    /// # use t2spline::fit::{fit_fuzzy, FitOptions, FuzzyFitMode};
    /// // The upper spread is wide at the middle point only: the independent
    /// // quadratic interpolant of the upper.left layer dips below where the
    /// // primary.left layer's control point lies.
    /// let n = |c: f64, up: f64| Nt2Number::try_new(c, [c - up, c + 0.3], [c - 0.2, c + 0.2], [c - 0.1, c + 0.1], 1.0);
    /// let data = vec![
    ///     Nt2Point::new([n(0.0, 0.3)?, n(0.0, 0.3)?]),
    ///     Nt2Point::new([n(1.0, 0.2)?, n(1.0, 0.2)?]),
    ///     Nt2Point::new([n(2.0, 3.0)?, n(2.0, 0.2)?]),
    ///     Nt2Point::new([n(3.0, 0.2)?, n(3.0, 0.2)?]),
    ///     Nt2Point::new([n(4.0, 0.3)?, n(4.0, 0.3)?]),
    /// ];
    /// let fit = fit_fuzzy(&data, &FitOptions::interpolation(3)?, FuzzyFitMode::Independent)?;
    /// assert!(matches!(fit.to_curve(), Err(Error::UnorderedFit { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("fitting every layer on its own breaks the order of the seven values at {count} place(s); the first: {first}")]
    UnorderedFit {
        /// How many inequalities are broken.
        count: usize,
        /// The first of them.
        first: crate::place::OrderViolation,
    },

    /// A fitted control value lies beyond the limit of coordinates
    /// ([`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE)): the curve through the data
    /// swings that far beyond them (data near the limit, interpolated).
    ///
    /// ```
    /// # use t2spline::{Error, Layer, Nt2Number, Nt2Point};
    /// # use t2spline::fit::{fit_fuzzy, FitOptions, FuzzyFitMode};
    /// let n = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 1.0);
    /// let y = [0.0, 9e149, -9e149, 9e149, 0.0];
    /// let data: Vec<Nt2Point<2>> = y
    ///     .iter()
    ///     .enumerate()
    ///     .map(|(i, &y)| Ok(Nt2Point::new([n(i as f64)?, n(y)?])))
    ///     .collect::<Result<_, Error>>()?;
    /// let e = fit_fuzzy(&data, &FitOptions::interpolation(3)?, FuzzyFitMode::Valid).unwrap_err();
    /// assert!(matches!(e, Error::FitBeyondLimit { layer: Some(Layer::Crisp), .. }), "{e}");
    /// assert!(e.to_string().contains("is beyond the limit of coordinates, [-1e150, 1e150]"));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("control point {control_point}, {axis}{}: the fitted value {} is beyond the limit of coordinates, [-1e150, 1e150]; the curve through these data swings that far beyond them, so fewer control points (least squares) or data of smaller magnitude are needed", layer.map_or(String::new(), |l| format!(", layer {l}")), Num(*value))]
    FitBeyondLimit {
        /// Index of the control point (0-based).
        control_point: usize,
        /// The coordinate.
        axis: Axis,
        /// The layer of a fuzzy fit; `None` for a crisp curve.
        layer: Option<crate::place::Layer>,
        /// The fitted value.
        value: f64,
    },

    /// A list given to the sampling engine has the wrong length.
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector};
    /// # use t2spline::sampling::Sampler;
    /// let knots = KnotVector::clamped_uniform(1, 2)?;
    /// let e = Sampler::try_new(&knots, &[1.0, 1.0], &[vec![0.0, 1.0, 2.0]]).unwrap_err();
    /// assert!(matches!(e, Error::Length { expected: 2, found: 3, .. }));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{what}: expected {expected}, got {found}")]
    Length {
        /// What was counted.
        what: &'static str,
        /// The length needed.
        expected: usize,
        /// The length given.
        found: usize,
    },

    /// A run needs the level alpha, and neither the job nor the front end
    /// gave it.
    ///
    /// ```
    /// # use t2spline::job::{Job, Model, Overrides};
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// # let n = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 0.5);
    /// # let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(1.0)?])];
    /// let job = Job::new(Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?));
    /// let e = job.settings(&Overrides::default()).unwrap_err();
    /// assert_eq!(e, Error::MissingAlpha);
    /// # Ok::<(), Error>(())
    /// ```
    #[error("alpha: missing: give it in the job or as a setting of the run")]
    MissingAlpha,

    /// A setting of a run (alpha, samples, derivative order) breaks its rule;
    /// front ends name the setting their own way (`--samples`, `samples=`).
    ///
    /// ```
    /// # use t2spline::job::{Job, Model, Overrides, Setting};
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// # let n = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 0.5);
    /// # let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(1.0)?])];
    /// let job = Job::new(Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?));
    /// let e = job.settings(&Overrides { alpha: Some(0.5), samples: Some(vec![1]), ..Overrides::default() }).unwrap_err();
    /// assert!(matches!(e, Error::Setting { setting: Setting::Samples, .. }));
    /// assert_eq!(e.to_string(), "samples = 1: at least 2 are needed (both ends of the domain)");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{message}")]
    Setting {
        /// Which setting.
        setting: Setting,
        /// The value and the rule it breaks.
        message: String,
    },

    /// A derivative asked of a run is beyond the range of a float: a
    /// derivative grows like `(coordinate / knot span)^order`, so narrow knot
    /// spans or large coordinates can take it there.
    ///
    /// ```
    /// # use t2spline::job::{Job, Model, Overrides};
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 0.5);
    /// // A jump of 1e150 over a knot span of 1e-150: the first derivative is 1e300,
    /// // the second would be about 1e450.
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1e150)?, n(0.0)?]), Nt2Point::new([n(0.0)?, n(1.0)?])];
    /// let curve = FuzzyCurve::try_new(2, points, vec![1.0; 3], Some(vec![0.0, 0.0, 0.0, 1e-150, 1e-150, 1e-150]))?;
    /// let job = Job::new(Model::Planar(curve));
    /// let s = job.settings(&Overrides { alpha: Some(0.5), samples: Some(vec![2]), derivatives: Some(2), ..Overrides::default() })?;
    /// let e = job.run(&s).unwrap_err();
    /// assert!(matches!(e, Error::DerivativeOverflow { derivative: 2, .. }), "{e}");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("curves.derivatives.{curve}[{}][{sample}][{axis}] = {value} is beyond the range of a 64-bit float (about 1.8e308): the knot spans are too narrow or the coordinates too large for derivatives of order {derivative}", derivative.saturating_sub(1))]
    DerivativeOverflow {
        /// `"crisp"` or `"defuzzified"`.
        curve: &'static str,
        /// The order of the derivative (1 or more).
        derivative: usize,
        /// The index of the sample parameter.
        sample: usize,
        /// The coordinate (0 is x).
        axis: usize,
        /// The value computed.
        value: f64,
    },
    /// The arc length of a curve whose derivatives were asked of a run is
    /// beyond the range of a float (its speed, `coordinate / knot span`,
    /// can be).
    ///
    /// ```
    /// # use t2spline::Error;
    /// let e = Error::ArcLengthOverflow { curve: "crisp", value: f64::INFINITY };
    /// assert_eq!(e.to_string(), "curves.arc_length.crisp = inf is not a finite number");
    /// assert_eq!(e.setting(), Some(t2spline::job::Setting::Derivatives));
    /// ```
    #[error("curves.arc_length.{curve} = {value} is not a finite number")]
    ArcLengthOverflow {
        /// `"crisp"` or `"defuzzified"`.
        curve: &'static str,
        /// The value computed.
        value: f64,
    },
    /// A rule of one parameter direction of a surface is broken (docs/method.md §8):
    /// `inner` is the error the same rule gives for a curve, `direction` says
    /// whether it concerns `u` (rows of the net, `knots.u`) or `v` (columns,
    /// `knots.v`). The message names the place in the surface's terms.
    ///
    /// ```
    /// # use t2spline::{Direction, Error, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let e = NurbsSurface::try_clamped([1, 2], net, vec![vec![1.0; 2]; 2]).unwrap_err();
    /// assert!(matches!(&e, Error::InDirection { direction: Direction::V, .. }));
    /// assert_eq!(e.to_string(), "points: a surface of order 3 in v needs at least 3 control points along v, got 2");
    /// ```
    #[error("{}", in_direction(*direction, inner))]
    InDirection {
        /// The parameter direction.
        direction: crate::place::Direction,
        /// The rule broken, as for a curve in that direction.
        inner: Box<Error>,
    },

    /// The rows of a surface's net (of points or of weights) differ in length.
    ///
    /// ```
    /// # use t2spline::{Error, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0]]];
    /// let e = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0; 2]; 2]).unwrap_err();
    /// assert_eq!(e.to_string(), "points[1]: expected 2 entries (as points[0]), got 1");
    /// ```
    #[error("{what}[{row}]: expected {expected} entries (as {reference}), got {found}")]
    NetShape {
        /// `"points"` or `"weights"`.
        what: &'static str,
        /// The row (0-based, along u).
        row: usize,
        /// What it is measured against (`"points[0]"`, `"points"`).
        reference: &'static str,
        /// The length needed.
        expected: usize,
        /// The length given.
        found: usize,
    },

    /// A weight of a surface's net is not finite and positive, or outside
    /// [[`MIN_WEIGHT`](crate::MIN_WEIGHT), [`MAX_WEIGHT`](crate::MAX_WEIGHT)].
    ///
    /// ```
    /// # use t2spline::{Error, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let e = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0, 1.0], vec![1.0, -2.0]]).unwrap_err();
    /// assert_eq!(e.to_string(), "weights[1][1] = -2 must be finite and greater than 0");
    /// ```
    #[error("weights[{row}][{column}] = {} {rule}", Num(*value))]
    NetWeight {
        /// The row (0-based, along u).
        row: usize,
        /// The column (0-based, along v).
        column: usize,
        /// The offending value.
        value: f64,
        /// The rule broken, as text.
        rule: &'static str,
    },

    /// A surface has no normal here: its partial derivatives `S_u` and `S_v`
    /// are parallel or zero (at a pole, a cusp or a degenerate edge).
    ///
    /// ```
    /// # use t2spline::{Error, NurbsSurface};
    /// // A bilinear patch with one edge collapsed to a point: S_v = 0 along u = 0.
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 0.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0; 2]; 2])?;
    /// assert!(matches!(s.normal(0.0, 0.5), Err(Error::SingularNormal { .. })));
    /// assert!(s.normal(0.5, 0.5).is_ok());
    /// # Ok::<(), Error>(())
    /// ```
    #[error("the normal at (u, v) = ({}, {}) is undefined: the partial derivatives are parallel or zero there", Num(*u), Num(*v))]
    SingularNormal {
        /// The parameter u.
        u: f64,
        /// The parameter v.
        v: f64,
    },

    /// A quantity of one layer surface (or layer curve) of a fuzzy model is
    /// undefined: `inner` is the error of that layer's crisp computation,
    /// `layer` names the layer.
    ///
    /// ```
    /// # use t2spline::{Error, FuzzySurface, Layer, Nt2Number, Nt2Point};
    /// let exact = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 1.0);
    /// let p = |x: f64, y: f64| Ok::<_, Error>(Nt2Point::new([exact(x)?, exact(y)?, exact(0.0)?]));
    /// // P₀₁.y has the upper foot 0 on the left: in the upper_left layer the
    /// // edge u = 0 collapses to a point.
    /// let y = Nt2Number::try_new(1.0, [0.0, 2.0], [0.5, 1.5], [0.8, 1.2], 0.5)?;
    /// let p01 = Nt2Point::new([exact(0.0)?, y, exact(0.0)?]);
    /// let net = vec![vec![p(0.0, 0.0)?, p01], vec![p(1.0, 0.0)?, p(1.0, 1.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let e = s.curvatures(0.0, 0.5).unwrap_err();
    /// assert!(matches!(&e, Error::InLayer { layer: Layer::UpperLeft, inner } if matches!(**inner, Error::SingularNormal { .. })));
    /// assert!(e.to_string().starts_with("layer upper_left: the normal at (u, v) = (0, 0.5) is undefined"));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("layer {layer}: {inner}")]
    InLayer {
        /// The layer.
        layer: crate::place::Layer,
        /// The error of that layer.
        inner: Box<Error>,
    },

    /// A sample of a sampled interval type-2 set breaks a rule of
    /// [`SampledSet::try_new`](crate::reduction::discrete::SampledSet::try_new):
    /// finite values, `x` within [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE) and not
    /// decreasing, `0 ≤ lmf ≤ umf ≤ 1e150`; or a value given to
    /// [`weighted_average_range`](crate::interval_weights::weighted_average_range)
    /// is not finite (`what` = `"values"`).
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::reduction::discrete::SampledSet;
    /// let e = SampledSet::try_new(&[0.0, 1.0, 2.0], &[0.0, 0.7, 0.0], &[0.5, 0.5, 0.2]).unwrap_err();
    /// assert_eq!(e.to_string(), "lmf[1] = 0.7 is greater than the umf at that index; a sampled set needs 0 <= lmf <= umf");
    /// let e = SampledSet::try_new(&[0.0, 2.0, 1.0], &[0.0; 3], &[1.0; 3]).unwrap_err();
    /// assert!(matches!(e, Error::Sample { what: "x", index: 2, .. }));
    /// ```
    #[error("{what}[{index}] = {} {rule}", Num(*value))]
    Sample {
        /// `"x"`, `"lmf"` or `"umf"`.
        what: &'static str,
        /// Index of the sample (0-based).
        index: usize,
        /// The offending value.
        value: f64,
        /// The rule it breaks, as the end of the message.
        rule: &'static str,
    },

    /// No upper membership of a sampled set is greater than 0 (or there are no
    /// samples): the set has no centroid.
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::reduction::discrete::SampledSet;
    /// let e = SampledSet::try_new(&[0.0, 1.0], &[0.0, 0.0], &[0.0, 0.0]).unwrap_err();
    /// assert_eq!(e, Error::ZeroUpperMembership);
    /// ```
    #[error("umf: no sample is greater than 0, so the set has no centroid")]
    ZeroUpperMembership,

    /// A point has one, two or three coordinates; a type of another
    /// dimension `D` (e.g. `NurbsCurve::<4>`) is refused by its constructor.
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// let e = NurbsCurve::<4>::try_clamped(1, vec![[0.0; 4], [1.0; 4]], vec![1.0, 1.0]).unwrap_err();
    /// assert_eq!(e, Error::Dimension { dimension: 4 });
    /// assert_eq!(e.to_string(), "a point has 1, 2 or 3 coordinates, not 4");
    /// ```
    #[error("a point has 1, 2 or 3 coordinates, not {dimension}")]
    Dimension {
        /// The dimension asked for.
        dimension: usize,
    },

    /// More sample values were asked for than a vector can hold.
    ///
    /// ```
    /// # use t2spline::{Error, NurbsCurve};
    /// # use t2spline::sampling::Params;
    /// let c = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 1.0])?;
    /// let e = c.sample_soa(Params::Uniform(usize::MAX)).unwrap_err();
    /// assert_eq!(e, Error::Memory { values: usize::MAX });
    /// # Ok::<(), Error>(())
    /// ```
    #[error("cannot hold {values} sample values per curve in memory")]
    Memory {
        /// The values per curve asked for.
        values: usize,
    },

    /// A point whose membership is asked has a coordinate that is NaN or
    /// infinite.
    ///
    /// ```
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// # let n = |c: f64| Nt2Number::try_crisp(c);
    /// # let c = FuzzyCurve::try_new(1, vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(1.0)?])], vec![1.0, 1.0], None)?;
    /// let e = c.memberships(&[[0.0, 0.0], [1.0, f64::NAN]]).unwrap_err();
    /// assert_eq!(e.to_string(), "query point 1: y = NaN is not a finite number");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("query point {index}: {axis} = {value} is not a finite number")]
    QueryPoint {
        /// The point's index (0-based) in the list given.
        index: usize,
        /// The coordinate.
        axis: Axis,
        /// The value.
        value: f64,
    },

    /// The tolerance of a region's outline is not a positive finite number,
    /// or is finer than the outline can be computed (`least`: the size of
    /// the region's box times [`crate::set::LEAST_RELATIVE_TOLERANCE`], the
    /// resolution of the polygon union's integer grid with room for
    /// rounding). The message rounds `least` up to two significant digits,
    /// so that the number it shows is allowed.
    ///
    /// ```
    /// # use t2spline::{Alpha, Error, FuzzyCurve, Membership, Nt2Number, Nt2Point};
    /// # let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.25, c + 0.25], 0.5);
    /// # let c = FuzzyCurve::try_new(1, vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(4.0)?, n(3.0)?])], vec![1.0, 1.0], None)?;
    /// let e = c.region(Membership::Upper, Alpha::try_new(0.5)?, Some(0.0)).unwrap_err();
    /// assert!(matches!(e, Error::Tolerance { .. }));
    /// assert!(e.to_string().starts_with("tolerance = 0 must be a positive number of at least "));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("tolerance = {} must be a positive number of at least {}", Num(*value), RoundedUp(*least))]
    Tolerance {
        /// The tolerance given.
        value: f64,
        /// The finest tolerance allowed for this curve.
        least: f64,
    },
    /// The tolerance of a region's outline or a section is coarser than the
    /// box that holds every region of the curve (`most`: the largest side
    /// of the box of the upper cuts at level 0, or the largest coordinate's
    /// magnitude where that box is a point): an outline so coarse says
    /// nothing, and its area would overflow.
    ///
    /// ```
    /// # use t2spline::{Alpha, Error, FuzzyCurve, Membership, Nt2Number, Nt2Point};
    /// # let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.25, c + 0.25], 0.5);
    /// # let c = FuzzyCurve::try_new(1, vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(4.0)?, n(3.0)?])], vec![1.0, 1.0], None)?;
    /// let e = c.region(Membership::Upper, Alpha::try_new(0.5)?, Some(1e155)).unwrap_err();
    /// assert_eq!(e.to_string(), "tolerance = 1e155 must be at most 6 (the size of the box that holds every region)");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("tolerance = {} must be at most {} (the size of the box that holds every region)", Num(*value), Num(*most))]
    ToleranceTooCoarse {
        /// The tolerance given.
        value: f64,
        /// The coarsest tolerance allowed for this curve.
        most: f64,
    },

    /// A part of a region read back breaks a rule of regions
    /// ([`crate::set::Region::try_from_parts`]).
    #[error("polygon {polygon}, ring {ring} ({}): {rule}", if *ring == 0 { "the exterior" } else { "a hole" })]
    RegionPart {
        /// Which polygon, from 0.
        polygon: usize,
        /// Which ring of it: 0 the exterior, then the holes.
        ring: usize,
        /// The rule it breaks.
        rule: &'static str,
    },

    /// A range of a membership grid is empty (its end not above its start).
    #[error("the grid's {axis} range [{}, {}] is empty: its end must be above its start", Num(*lo), Num(*hi))]
    GridRange {
        /// The coordinate of the range.
        axis: Axis,
        /// The start given.
        lo: f64,
        /// The end given.
        hi: f64,
    },

    /// A membership grid asks for more cells than [`crate::set::MAX_GRID_CELLS`].
    #[error("a membership grid of {columns} x {rows} cells is more than the limit of {limit}")]
    GridTooLarge {
        /// Cells along x.
        columns: usize,
        /// Cells along y.
        rows: usize,
        /// The limit on their product.
        limit: usize,
    },

    /// An envelope asks for more than [`crate::set::MAX_ENVELOPE_VALUES`]
    /// values, or (x or y fuzzy) more than
    /// [`crate::set::MAX_FUZZY_ENVELOPE_CELLS`] cells × levels.
    ///
    /// ```
    /// # use t2spline::{Alpha, Error, FuzzySurface, Nt2Number, Nt2Point};
    /// # use t2spline::set::PlanGrid;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let p = |x: f64, y: f64| Ok::<_, Error>(Nt2Point::new([c(x)?, c(y)?, c(0.0)?]));
    /// let net = vec![vec![p(0.0, 0.0)?, p(0.0, 1.0)?], vec![p(1.0, 0.0)?, p(1.0, 1.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let grid = PlanGrid::try_new([0.0, 0.0, 1.0, 1.0], [10_000, 10_000])?;
    /// let e = s.envelope(&grid, &[Alpha::ZERO; 2]).unwrap_err();
    /// assert_eq!(e.to_string(), "an envelope of 10000 x 10000 cells at 2 level(s) is more than the limit of 100000000 values (cells x levels x 6)");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("an envelope of {columns} x {rows} cells at {levels} level(s) is more than the limit of {limit} {counted}")]
    EnvelopeTooLarge {
        /// Cells along x (points, for a list of plan points).
        columns: usize,
        /// Cells along y (1 for a list of plan points).
        rows: usize,
        /// The levels asked.
        levels: usize,
        /// The limit.
        limit: usize,
        /// What the limit counts.
        counted: &'static str,
    },

    /// An index given to an accessor is past the end of what it indexes.
    ///
    /// ```
    /// # use t2spline::{Error, KnotVector, NurbsSurface};
    /// let knots = KnotVector::clamped_uniform(1, 2)?;
    /// let net = vec![vec![[0.0; 3], [1.0; 3]], vec![[2.0; 3], [3.0; 3]]];
    /// let s = NurbsSurface::try_new(net, vec![vec![1.0; 2]; 2], [knots.clone(), knots])?;
    /// let e = s.control_point(0, 2).unwrap_err();
    /// assert_eq!(e.to_string(), "column 2 is out of bounds: there are 2");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{what} {index} is out of bounds: there are {count}")]
    Index {
        /// What the index counts (`"row"`, `"column"`, ...).
        what: &'static str,
        /// The index given (0-based).
        index: usize,
        /// How many there are.
        count: usize,
    },

    /// A parameter at which a quantity is measured (docs/method.md §11) is
    /// NaN or outside the curve's domain.
    ///
    /// ```
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// # use t2spline::measure::{uniform_levels, MeasureOptions};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c, c], [c, c], 1.0);
    /// let line = FuzzyCurve::try_new(1, vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(1.0)?])], vec![1.0, 1.0], None)?;
    /// let options = MeasureOptions::new(uniform_levels(2)?, vec![0.5, 1.5], 1)?;
    /// let e = line.measure(&options).unwrap_err();
    /// assert_eq!(e.to_string(), "at[1] = 1.5 is outside the domain [0, 1]");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("at[{index}] = {} is outside the domain [{}, {}]", Num(*t), Num(*start), Num(*end))]
    MeasureAt {
        /// The position of the parameter in the list (0-based).
        index: usize,
        /// The parameter.
        t: f64,
        /// Start of the domain.
        start: f64,
        /// End of the domain.
        end: f64,
    },

    /// Volumes and areas of a surface (docs/method.md §14) are measured over
    /// a crisp plan: this control point's x or y is fuzzy.
    ///
    /// ```
    /// # use t2spline::{Error, FuzzySurface, Nt2Number, Nt2Point};
    /// # use t2spline::measure::SurfaceMeasureOptions;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let fuzzy = Nt2Number::try_new(2.0, [1.5, 2.5], [2.0, 2.0], [2.0, 2.0], 1.0)?;
    /// let p = |x: Nt2Number, y: f64| Ok::<_, Error>(Nt2Point::new([x, c(y)?, c(0.0)?]));
    /// let net = vec![vec![p(c(0.0)?, 0.0)?, p(c(0.0)?, 2.0)?], vec![p(fuzzy, 0.0)?, p(c(2.0)?, 2.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let e = s.measure(&SurfaceMeasureOptions::uniform(2)?).unwrap_err();
    /// assert_eq!(e.to_string(), "points[1][0].x is fuzzy: volumes and areas are measured over a crisp plan (x and y crisp at every control point)");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("points[{row}][{column}].{axis} is fuzzy: volumes and areas are measured over a crisp plan (x and y crisp at every control point)")]
    FuzzyPlan {
        /// The row of the control point (along u, 0-based).
        row: usize,
        /// Its column (along v, 0-based).
        column: usize,
        /// The coordinate, x or y.
        axis: Axis,
    },

    /// Volumes and areas of a surface (docs/method.md §14) need the surface
    /// to be the graph of a height over its plan: the plan map folds (its
    /// Jacobian changes sign) or the surface is vertical near this place.
    ///
    /// ```
    /// # use t2spline::{Error, FuzzySurface, Nt2Number, Nt2Point};
    /// # use t2spline::measure::SurfaceMeasureOptions;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let p = |x: f64, y: f64| Ok::<_, Error>(Nt2Point::new([c(x)?, c(y)?, c(0.0)?]));
    /// // Along u, x runs 0 → 2 → 0: the plan folds back over itself.
    /// let net = vec![
    ///     vec![p(0.0, 0.0)?, p(0.0, 1.0)?],
    ///     vec![p(2.0, 0.0)?, p(2.0, 1.0)?],
    ///     vec![p(0.0, 0.0)?, p(0.0, 1.0)?],
    /// ];
    /// let s = FuzzySurface::try_new([2, 1], net, vec![vec![1.0; 2]; 3], [None, None])?;
    /// let e = s.measure(&SurfaceMeasureOptions::uniform(2)?).unwrap_err();
    /// assert!(e.to_string().starts_with("the surface is not the graph of a height over its plan at (u, v) = ("), "{e}");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("the surface is not the graph of a height over its plan at (u, v) = ({}, {}), (x, y) = ({}, {}): {rule}", Num(*u), Num(*v), Num(*x), Num(*y))]
    NotAGraph {
        /// The parameter along u.
        u: f64,
        /// The parameter along v.
        v: f64,
        /// The plan point's x.
        x: f64,
        /// The plan point's y.
        y: f64,
        /// What is wrong there.
        rule: &'static str,
    },

    /// The cut and fill between two surfaces (docs/method.md §14) need
    /// crisp x and y in both and plans that overlap (of positive area).
    /// `what` names the fuzzy coordinate of the second surface, or says
    /// that the plans do not overlap.
    ///
    /// ```
    /// # use t2spline::{Error, FuzzySurface, Nt2Number, Nt2Point};
    /// # use t2spline::measure::SurfaceMeasureOptions;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let p = |x: f64, y: f64| Ok::<_, Error>(Nt2Point::new([c(x)?, c(y)?, c(0.0)?]));
    /// let net = |w: f64| Ok::<_, Error>(vec![vec![p(0.0, 0.0)?, p(0.0, w)?], vec![p(2.0, 0.0)?, p(2.0, w)?]]);
    /// let a = FuzzySurface::try_new([1, 1], net(2.0)?, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let q = |x: f64, y: f64| Ok::<_, Error>(Nt2Point::new([c(x)?, c(y)?, c(0.0)?]));
    /// let far = vec![vec![q(5.0, 0.0)?, q(5.0, 2.0)?], vec![q(7.0, 0.0)?, q(7.0, 2.0)?]];
    /// let b = FuzzySurface::try_new([1, 1], far, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let e = a.measure_against(&b, &SurfaceMeasureOptions::uniform(2)?).unwrap_err();
    /// assert_eq!(e.to_string(), "the two surfaces' plans cannot be compared (the plans do not overlap): cut and fill need crisp x and y in both surfaces and plans that overlap");
    /// # Ok::<(), Error>(())
    /// ```
    #[error(
        "the two surfaces' plans cannot be compared ({what}): cut and fill need crisp x and y in both surfaces and plans that overlap"
    )]
    PlansDiffer {
        /// What differs: `degree in u`, `knots in v`, `net shape`,
        /// `weight of points[i][j]`, `x of points[i][j]`,
        /// `points[i][j].y is fuzzy`, ….
        what: String,
    },

    /// A curve said to be closed whose crisp layer does not end where it
    /// starts (docs/method.md §11).
    ///
    /// ```
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let p = |x: f64, y: f64| Ok::<_, Error>(Nt2Point::new([c(x)?, c(y)?]));
    /// let open = FuzzyCurve::try_new(1, vec![p(0.0, 0.0)?, p(1.0, 0.0)?, p(1.0, 1.0)?], vec![1.0; 3], None)?;
    /// assert_eq!(open.closure_gap().unwrap_err().to_string(),
    ///     "the curve does not close: it starts at (0, 0) and ends at (1, 1)");
    /// # Ok::<(), Error>(())
    /// ```
    #[error(
        "the curve does not close: it starts at ({}) and ends at ({})",
        Nums(start),
        Nums(end)
    )]
    NotClosed {
        /// The crisp curve at the start of its domain.
        start: Vec<f64>,
        /// The crisp curve at the end of its domain.
        end: Vec<f64>,
    },

    /// An operation that does not yet take fuzzy weights was asked of a
    /// model that has them (docs/method.md §16 lists what does).
    ///
    /// ```
    /// # use t2spline::{Error, FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.2, c + 0.2], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(3.0)?, n(4.0)?])];
    /// let c = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?
    ///     .with_weight_numbers(vec![
    ///         Nt2Number::try_new(1.0, [0.5, 1.5], [0.7, 1.3], [0.9, 1.1], 0.5)?,
    ///         Nt2Number::try_new(2.0, [1.0, 3.0], [1.5, 2.5], [1.8, 2.2], 0.5)?,
    ///     ])?;
    /// let e = c.insert_knot(0.5, 1).unwrap_err();
    /// assert_eq!(e.to_string(), "knot insertion is not available for a model with fuzzy weights");
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[error("{what} is not available for a model with fuzzy weights")]
    FuzzyWeights {
        /// The operation, as the start of the message.
        what: &'static str,
    },

    /// The cut `[left, right]` of an uncertain weight is not valid
    /// (docs/method.md §15): both ends finite, `0 < left ≤ right` (at least
    /// 0 for [`weighted_average_range`](crate::interval_weights::weighted_average_range)).
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::interval_weights::IntervalTerms;
    /// let e = IntervalTerms::try_new(&[1.0], &[[2.0, 1.0]], &[[[0.0, 1.0]]]).unwrap_err();
    /// assert_eq!(e.to_string(), "weights[0] = [2, 1] is out of order: its left end is above its right end");
    /// ```
    #[error("weights[{index}] = [{}, {}] {rule}", Num(*left), Num(*right))]
    WeightCut {
        /// Index of the weight (0-based).
        index: usize,
        /// The left end of its cut.
        left: f64,
        /// The right end of its cut.
        right: f64,
        /// The rule it breaks, as the end of the message.
        rule: &'static str,
    },

    /// A basis value given for the weighted average at one parameter is not
    /// a finite number at least 0, or every one is 0 (docs/method.md §15).
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::interval_weights::IntervalTerms;
    /// let e = IntervalTerms::try_new(&[-0.5], &[[1.0, 1.0]], &[[[0.0, 1.0]]]).unwrap_err();
    /// assert_eq!(e.to_string(), "basis[0] = -0.5 must be a finite number at least 0");
    /// ```
    #[error("basis[{index}] = {} {rule}", Num(*value))]
    Basis {
        /// Index of the basis value (0-based).
        index: usize,
        /// The offending value.
        value: f64,
        /// The rule it breaks, as the end of the message.
        rule: &'static str,
    },

    /// More terms at one parameter than the functions of uncertain weights
    /// take ([`MAX_TERMS`](crate::interval_weights::MAX_TERMS); docs/method.md §15).
    ///
    /// ```
    /// # use t2spline::Error;
    /// # use t2spline::interval_weights::IntervalCurve;
    /// let points = vec![[[0.0, 1.0]]; 200];
    /// let e = IntervalCurve::try_new(150, points, vec![[1.0, 2.0]; 200], None).unwrap_err();
    /// assert_eq!(e.to_string(), "151 terms at one parameter are more than the limit of 128: uncertain weights are taken on curves of degree below 128");
    /// ```
    #[error("{count} terms at one parameter are more than the limit of {limit}: uncertain weights are taken on curves of degree below {limit}")]
    TooManyTerms {
        /// The number of terms (basis values above 0, or the order).
        count: usize,
        /// The limit.
        limit: usize,
    },

    /// A section of a set needs two different coordinates of its points: the
    /// one fixed and the one whose range is asked for (docs/method.md §15).
    ///
    /// ```
    /// # use t2spline::{Axis, Error};
    /// # use t2spline::interval_weights::IntervalTerms;
    /// let terms = IntervalTerms::try_new(&[1.0], &[[1.0, 1.0]], &[[[0.0, 1.0], [0.0, 1.0]]])?;
    /// let e = terms.section(Axis::X, 0.5, Axis::X).unwrap_err();
    /// assert_eq!(e.to_string(), "a section fixes one coordinate and ranges over another; got x twice");
    /// let e = terms.section(Axis::X, 0.5, Axis::Z).unwrap_err();
    /// assert_eq!(e.to_string(), "a section of points with 2 coordinates cannot use z");
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{}", section_axes(*along, *of, *dimension))]
    SectionAxes {
        /// The coordinate fixed.
        along: Axis,
        /// The coordinate whose range is asked for.
        of: Axis,
        /// The number of coordinates of the points.
        dimension: usize,
    },
}

/// The message of [`Error::SectionAxes`].
fn section_axes(along: Axis, of: Axis, dimension: usize) -> String {
    if along == of {
        format!("a section fixes one coordinate and ranges over another; got {along} twice")
    } else {
        let bad = if along.index() >= dimension {
            along
        } else {
            of
        };
        format!("a section of points with {dimension} coordinates cannot use {bad}")
    }
}

/// Numbers shown as [`Num`]s separated by `, `.
struct Nums<'a>(&'a [f64]);

impl fmt::Display for Nums<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, x) in self.0.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            write!(f, "{}", Num(*x))?;
        }
        Ok(())
    }
}

/// The message of [`Error::InDirection`]: the curve rule in the surface's words.
fn in_direction(direction: crate::place::Direction, inner: &Error) -> String {
    let d = direction;
    match inner {
        Error::TooFewControlPoints { order, count } => format!(
            "points: a surface of order {order} in {d} needs at least {order} control points along {d}, got {count}"
        ),
        Error::KnotCount { expected, found } => {
            let lines = match d {
                crate::place::Direction::U => "rows",
                crate::place::Direction::V => "columns",
            };
            format!("knots.{d}: expected {expected} values ({lines} + order in {d}), got {found}")
        }
        // The curve's message with its knot vector named by direction:
        // `knots[3] = …` becomes `knots.v[3] = …`, the path in a job file.
        Error::KnotNotFinite { .. }
        | Error::KnotOutOfRange { .. }
        | Error::KnotDecreasing { .. }
        | Error::KnotMultiplicity { .. }
        | Error::EmptyDomain { .. } => inner.to_string().replace("knots", &format!("knots.{d}")),
        Error::OutOfDomain { t, start, end } => format!(
            "parameter {d} = {} is outside the domain [{}, {}]",
            Num(*t),
            Num(*start),
            Num(*end)
        ),
        Error::SplitOutside { t, start, end } => format!(
            "cannot split at {d} = {}: it must lie strictly inside the domain ({}, {})",
            Num(*t),
            Num(*start),
            Num(*end)
        ),
        other => format!("in {d}: {other}"),
    }
}

impl Error {
    /// The setting of a run whose value caused this error, if one did: the
    /// setting of an [`Error::Setting`], and [`Setting::Derivatives`] for a
    /// derivative or an arc length beyond the range of a float (the order
    /// asked for takes them there). Front ends name their own spelling of
    /// the setting (`--derivatives`, `derivatives=`) from it.
    ///
    /// ```
    /// # use t2spline::{job::Setting, Error};
    /// let e = Error::Setting { setting: Setting::Samples, message: "samples = 1: at least 2 are needed".into() };
    /// assert_eq!(e.setting(), Some(Setting::Samples));
    /// assert_eq!(Error::MissingAlpha.setting(), None);
    /// ```
    #[must_use]
    pub fn setting(&self) -> Option<Setting> {
        match self {
            Error::Setting { setting, .. } => Some(*setting),
            Error::DerivativeOverflow { .. } | Error::ArcLengthOverflow { .. } => {
                Some(Setting::Derivatives)
            }
            _ => None,
        }
    }

    /// `Ok(index)` if `index < count`, else [`Error::Index`] naming `what`.
    pub(crate) fn check_index(
        what: &'static str,
        index: usize,
        count: usize,
    ) -> Result<usize, Error> {
        if index < count {
            Ok(index)
        } else {
            Err(Error::Index { what, index, count })
        }
    }

    /// The same error as a rule of `direction` of a surface
    /// ([`Error::InDirection`]).
    pub(crate) fn in_direction(self, direction: crate::place::Direction) -> Self {
        Error::InDirection {
            direction,
            inner: Box::new(self),
        }
    }

    /// The same error, as the error of one layer of a fuzzy model.
    pub(crate) fn in_layer(self, layer: crate::place::Layer) -> Self {
        Error::InLayer {
            layer,
            inner: Box::new(self),
        }
    }

    /// Returns the same error, located at `place` if it carries a place.
    #[must_use]
    pub fn at(self, place: Place) -> Self {
        match self {
            Error::NotFinite { what, value, .. } => Error::NotFinite { place, what, value },
            Error::Order {
                rule, left, right, ..
            } => Error::Order {
                place,
                rule,
                left,
                right,
            },
            Error::OutOfRange {
                what, value, range, ..
            } => Error::OutOfRange {
                place,
                what,
                value,
                range,
            },
            other => other,
        }
    }
}

#[cfg(test)]
mod rounded_up {
    use super::RoundedUp;

    #[test]
    fn two_significant_digits_never_below_the_value() {
        for (x, shown) in [
            (6.499999999999999e-7, "6.5e-7"),
            (6.41e-7, "6.5e-7"),
            (6.5e-7, "6.5e-7"),
            (9.96e-3, "1.0e-2"),
            (1.0, "1.0"),
            (2.01, "2.1"),
            (123.0, "1.3e2"),
        ] {
            assert_eq!(RoundedUp(x).to_string(), shown, "{x}");
            assert!(shown.parse::<f64>().unwrap() >= x * (1.0 - 1e-12), "{x}");
        }
        assert_eq!(RoundedUp(0.0).to_string(), "0");
        assert_eq!(RoundedUp(f64::NAN).to_string(), "NaN");
    }
}
