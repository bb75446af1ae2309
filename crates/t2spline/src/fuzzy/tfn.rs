//! The type-1 triangular fuzzy number that type reduction yields (docs/method.md §3–§4).

/// A type-1 triangular fuzzy number `(left, crisp, right)`, `left ≤ crisp ≤ right`:
/// the result of type reduction (docs/method.md §3, paper Def. 4.3).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Tfn {
    left: f64,
    crisp: f64,
    right: f64,
}

impl Tfn {
    pub(crate) fn new_unchecked(left: f64, crisp: f64, right: f64) -> Self {
        debug_assert!(
            left <= crisp && crisp <= right,
            "tfn ({left}, {crisp}, {right})"
        );
        Tfn { left, crisp, right }
    }

    /// The left foot.
    #[must_use]
    pub fn left(&self) -> f64 {
        self.left
    }

    /// The apex.
    #[must_use]
    pub fn crisp(&self) -> f64 {
        self.crisp
    }

    /// The right foot.
    #[must_use]
    pub fn right(&self) -> f64 {
        self.right
    }

    /// Defuzzification by the centroid of the triangle (docs/method.md §4, paper Def. 4.4).
    ///
    /// ```text
    /// defuzzified = (left + crisp + right) / 3
    /// ```
    /// Symmetric spreads (`crisp − left = right − crisp`) give back `crisp`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, Nt2Number};
    /// let x = Nt2Number::try_new(2.0, [1.0, 3.0], [1.5, 2.5], [1.8, 2.2], 0.5)?;
    /// assert_eq!(x.alpha_cut(Alpha::try_new(0.2)?).type_reduce().defuzzify(), 2.0);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn defuzzify(&self) -> f64 {
        ((self.left + self.crisp + self.right) / 3.0).clamp(self.left, self.right)
    }
}
