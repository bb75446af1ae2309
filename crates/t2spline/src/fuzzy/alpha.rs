//! The membership level α at which a fuzzy number is cut (docs/method.md §2).

use crate::error::{Error, Place};

/// A membership level in `[0, 1]`; [`Alpha::try_new`] is the only way in.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Alpha(f64);

impl Alpha {
    /// The level 0: the cut keeps every number whole (its whole footprint).
    pub const ZERO: Alpha = Alpha(0.0);
    /// The level 1: the cut of a normal number's upper membership function
    /// is its crisp value.
    pub const ONE: Alpha = Alpha(1.0);

    /// Validates a level.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if `value` is NaN or not in `[0, 1]`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Alpha;
    /// assert_eq!(Alpha::try_new(0.8)?.get(), 0.8);
    /// assert!(Alpha::try_new(f64::NAN).is_err());
    /// // −0 is the level 0, written as 0.
    /// assert!(Alpha::try_new(-0.0)?.get().is_sign_positive());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(value: f64) -> Result<Self, Error> {
        if (0.0..=1.0).contains(&value) {
            // `+ 0.0` turns −0 into +0 and leaves every other value.
            Ok(Alpha(value + 0.0))
        } else {
            Err(Error::OutOfRange {
                place: Place::NONE,
                what: "alpha",
                value,
                range: "[0, 1]",
            })
        }
    }

    /// The value.
    #[must_use]
    pub fn get(self) -> f64 {
        self.0
    }
}
