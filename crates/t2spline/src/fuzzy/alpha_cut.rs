//! The alpha-cut of docs/method.md §2 (the paper's "fuzzification", Eqs. 4.1–4.2).

use super::alpha::Alpha;
use super::interval::Interval;
use super::layer::Layer;
use super::number::Nt2Number;

/// The alpha-cut of one [`Nt2Number`] (docs/method.md §2).
///
/// Upper and primary cuts always exist; the lower cut exists only for `α ≤ h`
/// (paper Eq. 4.1) and is absent above the lower height (Eq. 4.2, where the paper
/// writes 0 for the missing value).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AlphaCut {
    crisp: f64,
    upper: Interval,
    primary: Interval,
    lower: Option<Interval>,
}

/// `cut(e, s) = e + s·(crisp − e)` (docs/method.md §2), evaluated as `(1 − s)·e + s·crisp`
/// so that `s = 0` gives `e` and `s = 1` gives `crisp` exactly, and kept between
/// `e` and `crisp`, where the exact value lies, against rounding.
fn cut(e: f64, crisp: f64, s: f64) -> f64 {
    ((1.0 - s) * e + s * crisp).clamp(e.min(crisp), e.max(crisp))
}

impl AlphaCut {
    pub(crate) fn of(x: &Nt2Number, alpha: Alpha) -> Self {
        let (a, c, h) = (alpha.get(), x.crisp(), x.height().get());
        let upper =
            Interval::new_unchecked(cut(x.upper().left(), c, a), cut(x.upper().right(), c, a));
        let primary = Interval::new_unchecked(
            cut(x.primary().left(), c, a),
            cut(x.primary().right(), c, a),
        );
        // α ≤ h: the lower triangle of height h is cut at the fraction α/h of the
        // way to its apex (docs/method.md §2). Mathematically the lower ends stay inside
        // the primary cut (α/h ≥ α and lower ⊂ primary); `max`/`min` only guard
        // the last bit against rounding.
        let lower = (a <= h).then(|| {
            let s = a / h;
            Interval::new_unchecked(
                cut(x.lower().left(), c, s).max(primary.left()),
                cut(x.lower().right(), c, s).min(primary.right()),
            )
        });
        AlphaCut {
            crisp: c,
            upper,
            primary,
            lower,
        }
    }

    /// The crisp value, which every cut contains.
    #[must_use]
    pub fn crisp(&self) -> f64 {
        self.crisp
    }

    /// The cut of the upper membership function.
    #[must_use]
    pub fn upper(&self) -> Interval {
        self.upper
    }

    /// The cut of the primary membership function.
    #[must_use]
    pub fn primary(&self) -> Interval {
        self.primary
    }

    /// The cut of the lower membership function; `None` when `α > h`.
    #[must_use]
    pub fn lower(&self) -> Option<Interval> {
        self.lower
    }

    /// The cut value of one layer; `None` for the lower layers when `α > h`.
    #[must_use]
    pub fn layer(&self, layer: Layer) -> Option<f64> {
        match layer {
            Layer::UpperLeft => Some(self.upper.left()),
            Layer::PrimaryLeft => Some(self.primary.left()),
            Layer::LowerLeft => self.lower.map(|l| l.left()),
            Layer::Crisp => Some(self.crisp),
            Layer::LowerRight => self.lower.map(|l| l.right()),
            Layer::PrimaryRight => Some(self.primary.right()),
            Layer::UpperRight => Some(self.upper.right()),
        }
    }
}

impl Nt2Number {
    /// The alpha-cut at level `alpha` (docs/method.md §2, paper Eqs. 4.1–4.2).
    ///
    /// ```text
    /// cut(e, s) = e + s·(crisp − e)
    /// α ≤ h:  s = α on upper and primary ends, s = α/h on lower ends
    /// α > h:  s = α on upper and primary ends; the lower cut is absent
    /// ```
    /// At `α = h` the first rule applies and the lower cut is the single value
    /// `crisp`.
    #[must_use]
    pub fn alpha_cut(&self, alpha: Alpha) -> AlphaCut {
        AlphaCut::of(self, alpha)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x() -> Nt2Number {
        Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6).unwrap()
    }

    #[test]
    fn alpha_zero_is_the_number_itself() {
        let c = x().alpha_cut(Alpha::try_new(0.0).unwrap());
        assert_eq!(c.upper(), x().upper());
        assert_eq!(c.primary(), x().primary());
        assert_eq!(c.lower(), Some(x().lower()));
    }

    #[test]
    fn alpha_one_is_crisp() {
        let c = x().alpha_cut(Alpha::try_new(1.0).unwrap());
        for l in crate::fuzzy::Layer::ALL {
            assert!(
                matches!(c.layer(l), None | Some(1.0)),
                "{l}: {:?}",
                c.layer(l)
            );
        }
        assert_eq!(c.lower(), None);
    }

    #[test]
    fn lower_cut_at_alpha_equal_h_is_the_crisp_value() {
        let c = x().alpha_cut(Alpha::try_new(0.6).unwrap());
        assert_eq!(c.lower(), Some(Interval::new_unchecked(1.0, 1.0)));
    }

    #[test]
    fn lower_cut_uses_alpha_over_h() {
        // α = 0.3, h = 0.6: s = 0.5, lower.left' = 0.8 + 0.5·0.2 = 0.9.
        let c = x().alpha_cut(Alpha::try_new(0.3).unwrap());
        let l = c.lower().unwrap();
        assert!((l.left() - 0.9).abs() < 1e-15);
        assert!((l.right() - 1.15).abs() < 1e-15);
    }
}
