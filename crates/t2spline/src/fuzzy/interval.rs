//! A closed interval of finite numbers: the feet of a fuzzy number's triangles and of their cuts.

use crate::error::{Error, Place};

/// A closed interval `[left, right]` of finite numbers with `left ≤ right`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Interval {
    left: f64,
    right: f64,
}

impl Interval {
    /// Makes `[left, right]`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if an end is NaN or infinite; [`Error::Order`] if
    /// `left > right`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Interval;
    /// assert_eq!(Interval::try_new(1.0, 2.0)?.width(), 1.0);
    /// assert!(Interval::try_new(2.0, 1.0).is_err());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(left: f64, right: f64) -> Result<Self, Error> {
        for (what, value) in [("left", left), ("right", right)] {
            if !value.is_finite() {
                return Err(Error::NotFinite {
                    place: Place::NONE,
                    what,
                    value,
                });
            }
        }
        if left > right {
            return Err(Error::Order {
                place: Place::NONE,
                rule: "left <= right",
                left,
                right,
            });
        }
        Ok(Interval { left, right })
    }

    pub(crate) fn new_unchecked(left: f64, right: f64) -> Self {
        debug_assert!(left <= right, "interval [{left}, {right}]");
        Interval { left, right }
    }

    /// The left end.
    #[must_use]
    pub fn left(&self) -> f64 {
        self.left
    }

    /// The right end.
    #[must_use]
    pub fn right(&self) -> f64 {
        self.right
    }

    /// `right − left`.
    #[must_use]
    pub fn width(&self) -> f64 {
        self.right - self.left
    }

    /// Whether `other` lies inside `self` (ends included).
    #[must_use]
    pub fn contains(&self, other: &Interval) -> bool {
        self.left <= other.left && other.right <= self.right
    }
}
