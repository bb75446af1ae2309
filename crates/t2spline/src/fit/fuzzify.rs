//! Fuzzy numbers from repeated readings: the statistics that turn a station's
//! readings into one normal type-2 fuzzy number per coordinate.
//!
//! A surveyor who measures a station `n` times has `n` readings per
//! coordinate, which scatter around the true value. The rule maps order
//! statistics of the readings onto the three membership functions of docs/method.md §1:
//!
//! ```text
//! crisp   = median                      (P50)
//! lower   = [P25, P75]                  half of the readings: the core of belief
//! primary = [P10, P90]                  four readings in five: the type-1 triangle
//! upper   = [min − T, max + T]          every reading, widened by the instrument's accuracy T
//! lower_height = 0.5 (by default)
//! ```
//!
//! Why these: the footprint of uncertainty between the lower and the upper
//! membership function is the region where belief is uncertain. Its inner
//! edge, the lower membership function, should hold what almost nobody would
//! doubt: the middle half of the readings (the interquartile range, robust to
//! outliers), at a height of one half because half of the readings lie there.
//! Its outer edge, the upper membership function, should hold everything that
//! is possible: every reading, widened by the accuracy the instrument claims
//! (a reading can be off by `T` in either direction). The primary membership
//! function, the type-1 number one would use without type-2 modelling, covers
//! the usual 10–90 % range of the readings. The median is the crisp value:
//! the apex shared by all three triangles, robust to a stray reading, and
//! inside every interval by construction. Each percentile lies between its
//! neighbours, so the seven values are ordered as docs/method.md §1 requires.
//!
//! Percentiles are Hyndman and Fan's type 7 (linear interpolation between
//! order statistics; numpy's default `np.percentile(x, q)`), computed the way
//! numpy computes them, so that a spreadsheet or a numpy script gives the same
//! numbers to the last bit:
//!
//! ```text
//! x₍₀₎ ≤ … ≤ x₍ₙ₋₁₎ sorted,  h = (n − 1)·(q/100),  j = ⌊h⌋,  g = h − j
//! P_q = x₍ⱼ₎ + g·(x₍ⱼ₊₁₎ − x₍ⱼ₎)          if g < 0.5
//! P_q = x₍ⱼ₊₁₎ − (1 − g)·(x₍ⱼ₊₁₎ − x₍ⱼ₎)  if g ≥ 0.5
//! ```
//! (The two forms are numpy's `_lerp`: each is exact at its own end.)

use crate::error::{Error, Place};
use crate::fuzzy::{Axis, Height, Nt2Number, Nt2Point};
use crate::limits::MAX_MAGNITUDE;

use super::FuzzyData;

/// The smallest number of readings per station: two give every percentile.
pub const MIN_READINGS: usize = 2;

/// The lower height of fuzzified numbers unless a front end sets another:
/// the lower membership function holds half of the readings.
pub const DEFAULT_LOWER_HEIGHT: f64 = 0.5;

/// How readings become fuzzy numbers: the instrument's accuracy and the lower
/// height, checked once, when made ([`FuzzifyRule::try_new`]): the fields
/// are private.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FuzzifyRule {
    tolerance: f64,
    lower_height: Height,
}

impl FuzzifyRule {
    /// The rule with accuracy `tolerance` and lower height `lower_height`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if `tolerance` is negative, NaN or above
    /// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE), or `lower_height` is outside
    /// `(0, 1]`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::FuzzifyRule;
    /// assert!(FuzzifyRule::try_new(0.02, 0.5).is_ok());
    /// assert_eq!(
    ///     FuzzifyRule::try_new(-1.0, 0.5).unwrap_err().to_string(),
    ///     "tolerance = -1 is outside [0, 1e150]"
    /// );
    /// ```
    pub fn try_new(tolerance: f64, lower_height: f64) -> Result<Self, Error> {
        if !(0.0..=MAX_MAGNITUDE).contains(&tolerance) {
            return Err(Error::OutOfRange {
                place: Place::NONE,
                what: "tolerance",
                value: tolerance,
                range: "[0, 1e150]",
            });
        }
        let lower_height = Height::try_new(lower_height)?;
        Ok(FuzzifyRule {
            tolerance,
            lower_height,
        })
    }

    /// The accuracy `T ≥ 0` of the instrument: the upper membership
    /// function reaches `T` beyond the smallest and the largest reading.
    #[must_use]
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The height `h` of the lower membership function.
    #[must_use]
    pub fn lower_height(&self) -> Height {
        self.lower_height
    }
}

/// The `q`-th percentile (`q` in `[0, 100]`) of sorted values, Hyndman and
/// Fan's type 7, computed as numpy's `np.percentile(x, q)` (see the module
/// docs for the formula).
///
/// `None` if `sorted` is empty. A `q` outside `[0, 100]` is taken as the
/// nearer end, a NaN `q` gives NaN; values that are not sorted give a value
/// between two of them, but not a percentile.
///
/// # Examples
/// ```
/// # use t2spline::fit::percentile;
/// let x = [1.0, 2.0, 4.0, 8.0];
/// assert_eq!(percentile(&x, 50.0), Some(3.0));   // h = 1.5: halfway from 2 to 4
/// assert_eq!(percentile(&x, 25.0), Some(1.75));  // h = 0.75
/// assert_eq!(percentile(&x, 100.0), Some(8.0));
/// assert_eq!(percentile(&[], 50.0), None);
/// ```
#[must_use]
pub fn percentile(sorted: &[f64], q: f64) -> Option<f64> {
    let last = sorted.len().checked_sub(1)?;
    // As numpy: the fraction q/100 first, then the virtual index (a NaN or
    // negative `h` casts to 0, one past the end is clamped).
    let h = last as f64 * (q.clamp(0.0, 100.0) / 100.0);
    let j = (h.floor() as usize).min(last);
    let g = h - j as f64;
    let (a, b) = (*sorted.get(j)?, *sorted.get((j + 1).min(last))?);
    let d = b - a;
    Some(if g < 0.5 {
        a + d * g
    } else {
        b - d * (1.0 - g)
    })
}

/// One fuzzy number from the readings of one coordinate (sorted in place):
/// the rule of the module docs.
///
/// # Errors
/// [`Error::TooFewReadings`] for fewer than [`MIN_READINGS`] readings;
/// [`Error::NotFinite`] for a NaN or infinite reading; the errors of
/// [`Nt2Number::try_new`] when a value is beyond
/// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE) (also after widening by the
/// tolerance).
///
/// # Examples
/// ```
/// # use t2spline::fit::{fuzzify_number, FuzzifyRule};
/// // Ten readings 1, 2, …, 10 with an accuracy of 0.5.
/// let mut r: Vec<f64> = (1..=10).map(f64::from).collect();
/// let x = fuzzify_number(&mut r, &FuzzifyRule::try_new(0.5, 0.5)?)?;
/// assert_eq!(x.crisp(), 5.5);
/// assert_eq!((x.lower().left(), x.lower().right()), (3.25, 7.75));
/// assert_eq!((x.primary().left(), x.primary().right()), (1.9, 9.1));
/// assert_eq!((x.upper().left(), x.upper().right()), (0.5, 10.5));
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn fuzzify_number(readings: &mut [f64], rule: &FuzzifyRule) -> Result<Nt2Number, Error> {
    if readings.len() < MIN_READINGS {
        return Err(Error::TooFewReadings {
            station: None,
            count: readings.len(),
        });
    }
    if let Some(&value) = readings.iter().find(|x| !x.is_finite()) {
        return Err(Error::NotFinite {
            place: Place::NONE,
            what: "reading",
            value,
        });
    }
    readings.sort_by(f64::total_cmp);
    let (Some(&min), Some(&max)) = (readings.first(), readings.last()) else {
        return Err(Error::TooFewReadings {
            station: None,
            count: 0,
        });
    };
    // Not empty (just checked), so every percentile is `Some`.
    let mut q = [10.0, 25.0, 50.0, 75.0, 90.0].map(|q| percentile(readings, q).unwrap_or(min));
    // Exact percentiles are ordered; rounding of neighbouring interpolations
    // (two forms of the lerp) could in principle swap two by an ulp.
    let mut previous = f64::NEG_INFINITY;
    for x in &mut q {
        *x = x.max(previous);
        previous = *x;
    }
    let [p10, p25, p50, p75, p90] = q;
    Nt2Number::try_new(
        p50,
        [
            (min - rule.tolerance()).min(p10),
            (max + rule.tolerance()).max(p90),
        ],
        [p10.min(p25), p90.max(p75)],
        [p25, p75],
        rule.lower_height().get(),
    )
}

/// Fuzzy data points from repeated readings: one point per station, one
/// number per coordinate by [`fuzzify_number`].
///
/// # Errors
/// The errors of [`fuzzify_number`], located at the station
/// (`points[3].y: …`, [`Error::TooFewReadings`] names the station).
///
/// # Examples
/// ```
/// # use t2spline::fit::{fuzzify, FuzzifyRule};
/// let stations = vec![
///     vec![[0.0, 1.0], [0.2, 1.1], [0.1, 0.9]],
///     vec![[5.0, 2.0], [5.2, 2.4]],
/// ];
/// let points = fuzzify(&stations, &FuzzifyRule::try_new(0.0, 0.5)?)?;
/// assert_eq!(points[0].crisp(), [0.1, 1.0]);
/// assert_eq!(points[1].crisp(), [5.1, 2.2]);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn fuzzify<const D: usize>(
    stations: &[Vec<[f64; D]>],
    rule: &FuzzifyRule,
) -> Result<Vec<Nt2Point<D>>, Error> {
    let mut column = Vec::new();
    stations
        .iter()
        .enumerate()
        .map(|(station, readings)| {
            if readings.len() < MIN_READINGS {
                return Err(Error::TooFewReadings {
                    station: Some(station),
                    count: readings.len(),
                });
            }
            let mut numbers = Vec::with_capacity(D);
            for axis in Axis::first::<D>()? {
                column.clear();
                column.extend(readings.iter().map(|r| r[axis.index()]));
                numbers.push(
                    fuzzify_number(&mut column, rule)
                        .map_err(|e| e.at(Place::new(station, axis)))?,
                );
            }
            // `numbers` has one entry per axis, D in all: the error is never made.
            let coords: [Nt2Number; D] = numbers.try_into().map_err(|v: Vec<_>| Error::Length {
                what: "coordinates",
                expected: D,
                found: v.len(),
            })?;
            Ok(Nt2Point::new(coords))
        })
        .collect()
}

/// Readings of stations in the plane or in space, as a readings file gives
/// them: per station, its readings in file order.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Readings {
    /// Readings with coordinates `x`, `y`.
    Planar(Vec<Vec<[f64; 2]>>),
    /// Readings with coordinates `x`, `y`, `z`.
    Spatial(Vec<Vec<[f64; 3]>>),
}

impl Readings {
    /// The number of stations.
    #[must_use]
    pub fn stations(&self) -> usize {
        match self {
            Readings::Planar(s) => s.len(),
            Readings::Spatial(s) => s.len(),
        }
    }

    /// The number of readings of all stations.
    #[must_use]
    pub fn readings(&self) -> usize {
        match self {
            Readings::Planar(s) => s.iter().map(Vec::len).sum(),
            Readings::Spatial(s) => s.iter().map(Vec::len).sum(),
        }
    }

    /// The fuzzy data points of the stations ([`fuzzify`]).
    ///
    /// # Errors
    /// The errors of [`fuzzify`].
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::{FuzzifyRule, Readings};
    /// let r = Readings::Spatial(vec![vec![[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]; 3]);
    /// let data = r.fuzzify(&FuzzifyRule::try_new(0.0, 0.5)?)?;
    /// assert_eq!(data.len(), 3);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn fuzzify(&self, rule: &FuzzifyRule) -> Result<FuzzyData, Error> {
        Ok(match self {
            Readings::Planar(s) => FuzzyData::Planar(fuzzify(s, rule)?),
            Readings::Spatial(s) => FuzzyData::Spatial(fuzzify(s, rule)?),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// numpy 2.4.6, `np.percentile(x, [10, 25, 50, 75, 90])` for the values
    /// below (printed with `repr`), and the closed forms they equal.
    #[test]
    fn percentiles_equal_numpy_type_7() {
        // x = 1..=20: h = 19·q/100.
        let x: Vec<f64> = (1..=20).map(f64::from).collect();
        // h = 1.9 → 2 + 0.9 = 2.9; h = 4.75 → 5.75; 9.5 → 10.5; 14.25 → 15.25; 17.1 → 18.1.
        let numpy = [2.9000000000000004, 5.75, 10.5, 15.25, 18.1];
        for (q, expected) in [10.0, 25.0, 50.0, 75.0, 90.0].into_iter().zip(numpy) {
            assert_eq!(percentile(&x, q), Some(expected), "q = {q}");
        }
        // Two readings: P_q = a + (b − a)·q/100.
        assert_eq!(percentile(&[1.0, 3.0], 10.0), Some(1.2));
        assert_eq!(percentile(&[1.0, 3.0], 75.0), Some(2.5));
        assert_eq!(percentile(&[1.0, 3.0], 90.0), Some(2.8));
        // Odd count: the median is the middle value itself.
        assert_eq!(percentile(&[1.0, 5.0, 9.0], 50.0), Some(5.0));
        // Equal values: every percentile is that value.
        assert_eq!(percentile(&[4.0; 7], 10.0), Some(4.0));
    }

    #[test]
    fn percentile_ends_are_the_extremes() {
        let x = [-3.5, -1.0, 0.25, 7.0, 11.0];
        assert_eq!(percentile(&x, 0.0), Some(-3.5));
        assert_eq!(percentile(&x, 100.0), Some(11.0));
    }

    #[test]
    fn each_form_of_the_interpolation_is_exact_at_its_end() {
        // g < 0.5 uses a + d·g: exact at g = 0; g ≥ 0.5 uses b − d·(1 − g):
        // exact at g = 1. Values far apart in magnitude show the difference.
        let x = [0.1, 1e17];
        assert_eq!(percentile(&x, 0.0), Some(0.1));
        assert_eq!(percentile(&x, 100.0), Some(1e17));
    }

    #[test]
    fn readings_give_ordered_numbers_with_the_rule() {
        let mut r = vec![2.0, 1.0, 4.0, 3.0];
        let rule = FuzzifyRule::try_new(0.25, 0.6).unwrap();
        let x = fuzzify_number(&mut r, &rule).unwrap();
        // sorted 1 2 3 4, h = 3q/100: P10 = 1.3, P25 = 1.75, P50 = 2.5, P75 = 3.25, P90 = 3.7.
        assert_eq!(x.crisp(), 2.5);
        assert_eq!((x.lower().left(), x.lower().right()), (1.75, 3.25));
        assert_eq!((x.primary().left(), x.primary().right()), (1.3, 3.7));
        assert_eq!((x.upper().left(), x.upper().right()), (0.75, 4.25));
        assert_eq!(x.height().get(), 0.6);
    }

    #[test]
    fn bad_readings_name_their_station_and_coordinate() {
        let stations = vec![
            vec![[0.0, 1.0], [1.0, 2.0]],
            vec![[0.0, f64::NAN], [1.0, 2.0]],
        ];
        let e = fuzzify(&stations, &FuzzifyRule::try_new(0.0, 0.5).unwrap()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "points[1].y: reading = NaN is not a finite number"
        );
        let stations = vec![vec![[0.0, 1.0], [1.0, 2.0]], vec![[0.0, 1.0]]];
        let e = fuzzify(&stations, &FuzzifyRule::try_new(0.0, 0.5).unwrap()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "station 1 (points[1]): 1 reading(s); percentiles need at least 2"
        );
        let stations = vec![vec![[1e150, 0.0], [1e150, 1.0]]];
        let e = fuzzify(&stations, &FuzzifyRule::try_new(1e140, 0.5).unwrap()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "points[0].x: upper.right = 1.0000000000999999e150 is outside [-1e150, 1e150]"
        );
    }
}
