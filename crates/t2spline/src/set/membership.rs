//! The membership grade of a point in the fuzzy curve (docs/method.md §10):
//!
//! ```text
//! mu_m(p) = sup over t of  min( top(t), min over c of mu_{m,c,t}(p_c) )
//! ```
//! certified by a branch and bound over the knot spans on the Bernstein
//! forms of the cut ends (`set/certify.rs`).

use crate::error::Error;
use crate::pipeline::FuzzyCurve;
use crate::set::bernstein::bezier_matrix;
pub(crate) use crate::set::certify::sup_of;
use crate::set::certify::{Form, Work};
use crate::set::cut_lines::{slack, CutLines, MEMBERSHIPS};
use crate::set::grades::Grades;
use crate::set::weighted_grades::weighted_grades;
use crate::set::weighted_terms::Weighted;

/// The membership functions of a curve in Bézier form span by span, ready
/// to grade many points.
#[derive(Clone, Debug)]
pub(crate) struct Grader<const D: usize> {
    /// Per function (upper, primary, lower), per non-empty knot span.
    forms: [Vec<Form<D>>; 3],
    /// The slack of "on the set" ([`slack`]).
    slack: f64,
}

impl<const D: usize> Grader<D> {
    pub(crate) fn new(curve: &FuzzyCurve<D>) -> Self {
        let lines = MEMBERSHIPS.map(|m| CutLines::of(curve.points(), m));
        let (knots, weights) = (curve.knots(), curve.weights());
        let p = curve.degree();
        let mut forms: [Vec<Form<D>>; 3] = Default::default();
        for (span, _) in knots.spans() {
            let m = bezier_matrix(knots.as_slice(), p, span);
            let first = span - p;
            for (f, l) in forms.iter_mut().zip(&lines) {
                f.push(Form::new(
                    [&m, &[1.0]],
                    [p + 1, 1],
                    &weights[first..=span],
                    &l.ends[first..=span],
                    l.top_of(first, p + 1),
                ));
            }
        }
        Grader {
            forms,
            slack: slack(curve.points()),
        }
    }

    /// The grades of `p`.
    pub(crate) fn grades(&self, p: &[f64; D]) -> Grades {
        self.grades_with(p, &mut Work::default())
    }

    /// The grades of `p`, searched in the buffers `work`.
    pub(crate) fn grades_with(&self, p: &[f64; D], work: &mut Work) -> Grades {
        Grades::ordered(
            self.forms
                .each_ref()
                .map(|f| sup_of(f, p, self.slack, [0.0, 0.0, f64::INFINITY], work)),
        )
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// The membership grades of the point `p` in the fuzzy curve as a set
    /// (docs/method.md §10): for each membership function `m`, the largest
    /// level `alpha` at which some curve whose control points lie inside
    /// their `m`-cuts at `alpha` passes through `p`; 0 where none does.
    ///
    /// A point counts as in a box when it lies within the set view's slack
    /// of it ([`RELATIVE_SLACK`](crate::set::RELATIVE_SLACK) of the job's
    /// extent), so a point computed on the crisp curve grades 1.
    ///
    /// The sup over the domain is certified: a branch and bound over the
    /// knot spans bounds it from above by the Bernstein coefficients of the
    /// cut ends on each sub-interval and from below by the grades at the
    /// sub-intervals' ends, and the upper bound is returned once the two are
    /// within [`GRADE_TOLERANCE`](crate::set::GRADE_TOLERANCE): never below
    /// the true grade, at most that far above it. Numbers with their own
    /// heights are handled: the lower function's top on a span is the least
    /// height of the control points that count there. With fuzzy weights
    /// the weights are cut too, and the set at each parameter is decided
    /// exactly (docs/method.md §15–§16), with the same certificate.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] if a coordinate of `p` is NaN or infinite.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.25, c + 0.25], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(4.0)?, n(0.0)?])];
    /// let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// // On the crisp curve: 1, 1 and h.
    /// let on = line.membership(&[2.0, 0.0])?;
    /// assert_eq!((on.upper, on.primary, on.lower), (1.0, 1.0, 0.5));
    /// // Half-way to the upper cut's edge in y: the upper grade is 1/2.
    /// let off = line.membership(&[2.0, 0.5])?;
    /// assert!((off.upper - 0.5).abs() < 1e-9 && off.primary.abs() < 1e-9);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn membership(&self, p: &[f64; D]) -> Result<Grades, Error> {
        check_point(0, p)?;
        if let Some(weights) = self.weight_numbers() {
            return Ok(weighted_grades(&Weighted::new(self, weights), p));
        }
        Ok(Grader::new(self).grades(p))
    }

    /// The slack of "on the set" ([`RELATIVE_SLACK`](crate::set::RELATIVE_SLACK)
    /// of the job's extent): grades, regions and sections count a point
    /// within this distance of a box (in every coordinate) as in it.
    ///
    /// ```text
    /// slack = 1e-12 · max( largest side of the box of all upper cuts at level 0,
    ///                      largest magnitude of an upper foot / 16 )
    /// ```
    #[must_use]
    pub fn set_slack(&self) -> f64 {
        slack(self.points())
    }

    /// [`FuzzyCurve::membership`] of many points, sharing the preparation.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] naming the first point with a coordinate that
    /// is NaN or infinite.
    pub fn memberships(&self, points: &[[f64; D]]) -> Result<Vec<Grades>, Error> {
        for (i, p) in points.iter().enumerate() {
            check_point(i, p)?;
        }
        if let Some(weights) = self.weight_numbers() {
            let on = Weighted::new(self, weights);
            return Ok(points.iter().map(|p| weighted_grades(&on, p)).collect());
        }
        let grader = Grader::new(self);
        let mut work = Work::default();
        Ok(points
            .iter()
            .map(|p| grader.grades_with(p, &mut work))
            .collect())
    }
}

/// Refuses a query point with a coordinate that is not finite; `index` names
/// it in the message.
pub(crate) fn check_point<const D: usize>(index: usize, p: &[f64; D]) -> Result<(), Error> {
    for (axis, &value) in crate::Axis::of::<D>().into_iter().zip(p) {
        if !value.is_finite() {
            return Err(Error::QueryPoint { index, axis, value });
        }
    }
    Ok(())
}
