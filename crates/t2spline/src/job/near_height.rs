//! An alpha a few units in the last place above a number's lower height.
//!
//! The paper's reduction jumps at `alpha = h` (docs/method.md §3): at
//! `alpha <= h` the lower cut exists and the three left (right) ends are
//! averaged, above it only two. A level computed in floating point lands
//! next to a height unnoticed, `np.linspace(0, 1, 21)[12]` being
//! `0.6000000000000001`, one ulp above `h = 0.6`, and so on the other side
//! of the jump from the level meant. Such a run is valid; front ends say so.

use std::fmt;

use super::model::Model;
use crate::fuzzy::Alpha;

/// How many units in the last place above a lower height an alpha may lie
/// to be taken for that height computed in floating point.
pub const NEAR_HEIGHT_ULPS: u64 = 4;

/// An alpha just above a lower height `h` of the model's numbers:
/// `h < alpha <= h + NEAR_HEIGHT_ULPS` ulps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NearHeight {
    /// The level of the run.
    pub alpha: f64,
    /// The height it passes (the greatest such height).
    pub height: f64,
    /// How many representable numbers above `height` alpha lies.
    pub ulps: u64,
}

impl NearHeight {
    /// The height of `model`'s numbers that `alpha` lies just above, if any.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point};
    /// # use t2spline::job::{Model, NearHeight};
    /// # let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.2, c + 0.2], 0.6);
    /// # let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(1.0)?])];
    /// # let model = Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?);
    /// let sweep = 12.0 * (1.0 / 20.0); // 0.6000000000000001
    /// let near = NearHeight::of(&model, Alpha::try_new(sweep)?).unwrap();
    /// assert_eq!((near.height, near.ulps), (0.6, 1));
    /// assert_eq!(NearHeight::of(&model, Alpha::try_new(0.6)?), None);
    /// assert_eq!(NearHeight::of(&model, Alpha::try_new(0.61)?), None);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn of(model: &Model, alpha: Alpha) -> Option<NearHeight> {
        let a = alpha.get();
        model
            .numbers()
            .iter()
            .flatten()
            .map(|x| x.height().get())
            .filter(|&h| h < a && a.to_bits() - h.to_bits() <= NEAR_HEIGHT_ULPS)
            .reduce(f64::max)
            .map(|height| NearHeight {
                alpha: a,
                height,
                ulps: a.to_bits() - height.to_bits(),
            })
    }
}

impl fmt::Display for NearHeight {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let unit = if self.ulps == 1 { "ulp" } else { "ulps" };
        write!(
            f,
            "alpha {} lies {} {unit} above the lower height {h} of a number: the run takes alpha > h \
             there (no lower cut, two-term averages), on the other side of the jump from alpha = {h}",
            self.alpha,
            self.ulps,
            h = self.height
        )
    }
}

#[cfg(test)]
mod tests {
    use super::{NearHeight, NEAR_HEIGHT_ULPS};
    use crate::fuzzy::{Alpha, Nt2Number, Nt2Point};
    use crate::job::Model;
    use crate::pipeline::FuzzyCurve;

    /// A plane segment whose two points' numbers have heights `h0` and `h1`.
    fn model(h0: f64, h1: f64) -> Model {
        let n = |c: f64, h| {
            Nt2Number::try_new(
                c,
                [c - 1.0, c + 1.0],
                [c - 0.5, c + 0.5],
                [c - 0.2, c + 0.2],
                h,
            )
            .unwrap()
        };
        let points = vec![
            Nt2Point::new([n(0.0, h0), n(0.0, h0)]),
            Nt2Point::new([n(1.0, h1), n(1.0, h1)]),
        ];
        Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None).unwrap())
    }

    fn up(x: f64, k: u64) -> f64 {
        f64::from_bits(x.to_bits() + k)
    }

    #[test]
    fn only_an_alpha_a_few_ulps_above_a_height_is_near_it() {
        for h in [0.3, 0.5, 0.6, 0.75, 1e-9] {
            let m = model(h, 1.0);
            let at = |a: f64| NearHeight::of(&m, Alpha::try_new(a).unwrap());
            for k in 1..=NEAR_HEIGHT_ULPS {
                let near = at(up(h, k)).unwrap();
                assert_eq!((near.height, near.ulps, near.alpha), (h, k, up(h, k)));
            }
            assert_eq!(at(up(h, NEAR_HEIGHT_ULPS + 1)), None);
            assert_eq!(at(h), None);
            assert_eq!(at(f64::from_bits(h.to_bits() - 1)), None);
        }
        // Of two heights alpha passes, the nearer is named.
        let m = model(0.6, f64::from_bits(0.6f64.to_bits() + 2));
        let near = NearHeight::of(&m, Alpha::try_new(up(0.6, 3)).unwrap()).unwrap();
        assert_eq!(near.ulps, 1);
        assert_eq!(
            near.to_string(),
            format!("alpha {} lies 1 ulp above the lower height {} of a number: the run takes alpha > h there (no lower cut, two-term averages), on the other side of the jump from alpha = {}", up(0.6, 3), up(0.6, 2), up(0.6, 2))
        );
    }

    #[test]
    fn a_sweep_by_linspace_lands_next_to_the_height() {
        // numpy's linspace(0, 1, 21)[12]: 12 · (1/20).
        let a = 12.0 * (1.0 / 20.0);
        assert_eq!(a, 0.600_000_000_000_000_1);
        let near = NearHeight::of(&model(0.6, 0.6), Alpha::try_new(a).unwrap()).unwrap();
        assert!(near
            .to_string()
            .starts_with("alpha 0.6000000000000001 lies 1 ulp above the lower height 0.6"));
    }
}
