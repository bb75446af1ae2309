//! Stages 2–4 of Algorithm 1.1 (docs/method.md §7): alpha-cut, type reduction and
//! defuzzification of the control points, and the curves through them.

use crate::fuzzy::Layer;
use crate::nurbs::NurbsCurve;
use crate::pipeline::point_stages::Side;
use crate::pipeline::stages::Stages;
use crate::pipeline::{Distance, FuzzyCurve};

/// The four stages of Algorithm 1.1 at one level alpha (docs/method.md §7):
///
/// 1. **NT2FRBsC** — the fuzzy curve ([`Solution::fuzzy_curve`], paper Fig. 5.1);
/// 2. **α-NT2FRBsC** — alpha-cut control points and their curves (Fig. 5.2);
/// 3. **TR-α-NT2FRBsC** — type-reduced control points `(left, crisp, right)` and
///    the left and right curves (Fig. 5.3);
/// 4. **D-TR-α-NT2FRBsC** — defuzzified control points and the crisp solution
///    curve, compared with the crisp curve (Fig. 5.4).
///
/// Stages 3–4 reduce each number by the solution's
/// [`TypeReduction`](crate::TypeReduction) (docs/method.md
/// §9; [`FuzzyCurve::solve`] takes the paper's, [`FuzzyCurve::solve_with`]
/// any): with the paper's, stage 3 is the triangle `(left, crisp, right)`;
/// with the others, `[left, right]` is a centroid interval, which need not
/// contain `crisp`.
///
/// Every stage works on the control points, as Algorithm 1.1 does; the curves
/// are rational B-splines through the results with the original weights and
/// knots. With one lower height per coordinate this equals cutting, reducing and
/// defuzzifying the curve itself; with mixed heights it does not (docs/method.md §6).
///
/// # Examples
/// ```
/// # use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point};
/// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.2, c + 0.2], 0.5);
/// let points = (0..4).map(|i| Ok(Nt2Point::new([n(i as f64)?, n((i * i) as f64)?])))
///     .collect::<Result<Vec<_>, t2spline::Error>>()?;
/// let s = FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 3.0, 1.0], None)?.solve(Alpha::try_new(0.8)?);
/// // Symmetric spreads: the defuzzified curve is the crisp curve.
/// assert!(s.distance().max < 1e-12);
/// # Ok::<(), t2spline::Error>(())
/// ```
/// The accessors of every stage are those of [`Stages`], written once for
/// curves and surfaces; this type adds the names of the curves.
pub type Solution<const D: usize> = Stages<FuzzyCurve<D>, D>;

impl<const D: usize> Solution<D> {
    /// Stage 1: the fuzzy curve.
    #[must_use]
    pub fn fuzzy_curve(&self) -> &FuzzyCurve<D> {
        self.fuzzy()
    }

    /// Stage 2: the curve through one alpha-cut layer, when that layer exists
    /// for every control point.
    #[must_use]
    pub fn alpha_cut_curve(&self, layer: Layer) -> Option<NurbsCurve<D>> {
        self.alpha_cut(layer)
    }

    /// Stage 3: the curve through the left or right type-reduced control points.
    #[must_use]
    pub fn type_reduced_curve(&self, side: Side) -> NurbsCurve<D> {
        self.type_reduced(side)
    }

    /// Stage 4: the crisp type-2 solution curve through the defuzzified points.
    #[must_use]
    pub fn defuzzified_curve(&self) -> NurbsCurve<D> {
        self.defuzzified()
    }

    /// The crisp curve through the crisp control points.
    #[must_use]
    pub fn crisp_curve(&self) -> NurbsCurve<D> {
        self.crisp()
    }

    /// The distance between the crisp and the defuzzified curve at equal `t`
    /// over the whole domain (docs/method.md §7); see [`Distance`].
    #[must_use]
    pub fn distance(&self) -> Distance {
        if self.fuzzy_curve().weight_numbers().is_some() {
            // The two curves have weights of their own (docs/method.md §16).
            return Distance::between(&self.defuzzified_curve(), &self.crisp_curve());
        }
        Distance::of_curve(&self.offsets())
    }
}
