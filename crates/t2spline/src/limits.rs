//! The range of numbers the core accepts, chosen so that every result is a
//! finite `f64`.
//!
//! `f64` reaches about 1.8e308. The stages add up to three values (type
//! reduction, defuzzification), subtract two (the distance between the crisp
//! and the defuzzified curve, knot differences) and sum up to `p + 1` weighted
//! basis terms; the curve operations (knot insertion, degree elevation,
//! splitting, derivatives) work on homogeneous coordinates `(w·x, w·y, w)`.
//! With every coordinate and knot in `[-1e150, 1e150]` and every weight in
//! `[1e-150, 1e150]`, a homogeneous coordinate lies within `1e300` and none of
//! these sums or products can overflow; the sum of weighted basis terms cannot
//! underflow to 0. Squares of distances are formed only after scaling, so
//! coordinates as small as the smallest subnormal number are fine too.
//!
//! A number outside these ranges is refused with an error naming it, never
//! clamped. There is no lower bound on coordinates: evaluation and the four
//! stages keep their relative accuracy down to the smallest subnormal number,
//! while the operations on homogeneous coordinates keep an absolute accuracy
//! of about `1e-308 / (smallest weight)` for coordinates below `1e-150`.

/// The largest magnitude of a coordinate or a knot: `1e150`.
///
/// # Examples
/// ```
/// # use t2spline::{Error, Nt2Number, MAX_MAGNITUDE};
/// assert!(Nt2Number::try_crisp(MAX_MAGNITUDE).is_ok());
/// let e = Nt2Number::try_crisp(-1e151).unwrap_err();
/// assert!(matches!(e, Error::OutOfRange { what: "upper.left", .. }));
/// ```
pub const MAX_MAGNITUDE: f64 = 1e150;

/// The smallest weight: `1e-150`.
pub const MIN_WEIGHT: f64 = 1e-150;

/// The largest weight: `1e150`.
pub const MAX_WEIGHT: f64 = 1e150;

/// `MAX_MAGNITUDE` as an interval, for messages.
pub(crate) const MAGNITUDE_RANGE: &str = "[-1e150, 1e150]";

/// Whether a finite value is within [`MAX_MAGNITUDE`].
pub(crate) fn within_magnitude(x: f64) -> bool {
    x.abs() <= MAX_MAGNITUDE
}
