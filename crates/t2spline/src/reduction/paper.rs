//! The paper's type reduction and defuzzification of an alpha-cut
//! (docs/method.md §3–§4, Defs. 4.3–4.4): each side of the cut becomes the
//! mean of its ends, then the triangle `(left, crisp, right)` its centroid.
//! The other reductions of one number are beside it in this module tree.

use crate::fuzzy::{Alpha, AlphaCut, Nt2Point, Tfn};

impl AlphaCut {
    /// Type reduction by the paper's "centroid min" rule (docs/method.md §3, Def. 4.3).
    ///
    /// ```text
    /// α ≤ h:  left = (upper.left' + primary.left' + lower.left') / 3
    ///         right = (lower.right' + primary.right' + upper.right') / 3
    /// α > h:  left = (upper.left' + primary.left') / 2
    ///         right = (primary.right' + upper.right') / 2
    /// ```
    /// The average changes from three terms to two at `α = h`, so the result
    /// jumps there: that is the paper's method.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, Nt2Number};
    /// let x = Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?;
    /// let t = x.alpha_cut(Alpha::try_new(0.8)?).type_reduce();
    /// assert!((t.left() - 0.9).abs() < 1e-15 && (t.right() - 1.15).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn type_reduce(&self) -> Tfn {
        let c = self.crisp();
        let (left, right) = match self.lower() {
            Some(l) => (
                (self.upper().left() + self.primary().left() + l.left()) / 3.0,
                (l.right() + self.primary().right() + self.upper().right()) / 3.0,
            ),
            None => (
                (self.upper().left() + self.primary().left()) / 2.0,
                (self.primary().right() + self.upper().right()) / 2.0,
            ),
        };
        // A mean of values in [upper.left', crisp] lies there too; the clamp
        // only removes rounding.
        Tfn::new_unchecked(
            left.clamp(self.upper().left(), c),
            c,
            right.clamp(c, self.upper().right()),
        )
    }
}

impl<const D: usize> Nt2Point<D> {
    /// Alpha-cut then type reduction of every coordinate (docs/method.md §2–§3).
    #[must_use]
    pub fn type_reduce(&self, alpha: Alpha) -> [Tfn; D] {
        self.alpha_cut(alpha).map(|c| c.type_reduce())
    }

    /// Alpha-cut, type reduction and defuzzification of every coordinate
    /// (docs/method.md §2–§4): the paper's crisp type-2 solution point.
    #[must_use]
    pub fn defuzzify(&self, alpha: Alpha) -> [f64; D] {
        self.type_reduce(alpha).map(|t| t.defuzzify())
    }
}
