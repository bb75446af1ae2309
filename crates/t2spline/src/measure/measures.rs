//! Every quantity of docs/method.md §11 at many levels, under the three
//! membership functions: what `t2spline measure` writes.

use crate::error::Error;
use crate::fuzzy::{Alpha, Membership};
use crate::measure::area::{area_bracket, AreaForm, AreaKind, Closing};
use crate::measure::bracket::Bracket;
use crate::measure::coefficients;
use crate::measure::curvature::curvature_bracket;
use crate::measure::cut_box::CutBox;
use crate::measure::derivative::{angle_range, derivative_box};
use crate::measure::length::length_bracket;
use crate::measure::options::MeasureOptions;
use crate::measure::rule::{rules, Rules};
use crate::nurbs::curve::rational_basis_span;
use crate::nurbs::derivatives::check_order;
use crate::pipeline::FuzzyCurve;

/// One value per membership function.
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PerMembership<T> {
    /// Under the upper membership function.
    pub upper: T,
    /// Under the primary membership function.
    pub primary: T,
    /// Under the lower membership function.
    pub lower: T,
}

impl<T> PerMembership<T> {
    /// The value of one function.
    #[must_use]
    pub fn get(&self, membership: Membership) -> &T {
        match membership {
            Membership::Upper => &self.upper,
            Membership::Primary => &self.primary,
            Membership::Lower => &self.lower,
        }
    }

    pub(crate) fn from_fn(mut f: impl FnMut(Membership) -> T) -> Self {
        PerMembership {
            upper: f(Membership::Upper),
            primary: f(Membership::Primary),
            lower: f(Membership::Lower),
        }
    }
}

/// A quantity's [`Bracket`] at one level.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Level {
    /// The level.
    pub alpha: f64,
    /// A lower bound of the least value.
    pub min: f64,
    /// An upper bound of the largest value.
    pub max: f64,
    /// Whether both ends are exact to rounding or the stated tolerance.
    pub exact: bool,
    /// How far either end may lie outside the values attained.
    pub gap: f64,
}

impl Level {
    pub(crate) fn of(alpha: f64, b: Bracket) -> Self {
        Level {
            alpha,
            min: b.min,
            max: b.max,
            exact: b.exact,
            gap: b.gap,
        }
    }

    /// The bracket.
    #[must_use]
    pub fn bracket(&self) -> Bracket {
        Bracket {
            min: self.min,
            max: self.max,
            exact: self.exact,
            gap: self.gap,
        }
    }
}

/// A quantity at a parameter that some admissible curve may not have (the
/// tangent and the curvature where the derivative box holds the origin).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PartialLevel {
    /// The level.
    pub alpha: f64,
    /// `false` where some admissible curve stands still at the parameter;
    /// `min` and `max` are then `None`.
    pub defined: bool,
    /// A lower bound of the least value.
    pub min: Option<f64>,
    /// An upper bound of the largest value.
    pub max: Option<f64>,
    /// Whether both ends are exact to rounding or the stated tolerance.
    pub exact: bool,
    /// How far either end may lie outside the values attained.
    pub gap: f64,
}

impl PartialLevel {
    fn of(alpha: f64, b: Option<Bracket>) -> Self {
        PartialLevel {
            alpha,
            defined: b.is_some(),
            min: b.map(|b| b.min),
            max: b.map(|b| b.max),
            exact: b.is_none_or(|b| b.exact),
            gap: b.map_or(0.0, |b| b.gap),
        }
    }
}

/// A derivative's exact range at one level, per coordinate.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DerivativeLevel {
    /// The level.
    pub alpha: f64,
    /// The least value of each coordinate.
    pub min: Vec<f64>,
    /// The largest value of each coordinate.
    pub max: Vec<f64>,
}

/// The area of a plane curve at every level.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AreaMeasure {
    /// Under an open curve or enclosed by a closed one.
    pub kind: AreaKind,
    /// Why an enclosed area is closed by a chord ([`Closure::note`](crate::measure::Closure::note)).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub note: Option<String>,
    /// Under the upper membership function.
    pub upper: Vec<Level>,
    /// Under the primary membership function.
    pub primary: Vec<Level>,
    /// Under the lower membership function.
    pub lower: Vec<Level>,
}

/// The quantities at one parameter.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AtMeasure {
    /// The parameter.
    pub t: f64,
    /// The order of `derivative`.
    pub order: usize,
    /// The derivative of that order, per coordinate.
    pub derivative: PerMembership<Vec<DerivativeLevel>>,
    /// The angle of the first derivative (plane curves), radians.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub tangent_angle: Option<PerMembership<Vec<PartialLevel>>>,
    /// The curvature.
    pub curvature: PerMembership<Vec<PartialLevel>>,
}

/// Every quantity of a fuzzy curve at many levels (docs/method.md §11).
/// A membership function's lists hold only the levels where it has a cut
/// (the lower function up to the least height of its numbers).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Measures {
    /// The levels asked for.
    pub levels: Vec<f64>,
    /// The arc length.
    pub length: PerMembership<Vec<Level>>,
    /// The area (plane curves).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub area: Option<AreaMeasure>,
    /// The quantities at each parameter asked for.
    pub at: Vec<AtMeasure>,
}

/// The closing of a plane curve's enclosed area, or `None` for the area
/// under it: `closed` as a job gives it (`Some(true)`: it must close), or
/// `None` to close a curve whose crisp layer closes (docs/method.md §11).
///
/// # Errors
/// [`Error::NotClosed`] when `closed` is `Some(true)` and the curve does not
/// close.
pub(crate) fn closing<const D: usize>(
    curve: &FuzzyCurve<D>,
    closed: Option<bool>,
) -> Result<Option<Closing>, Error> {
    let closure = match closed {
        Some(false) => return Ok(None),
        Some(true) => curve.closure_gap()?,
        None => match curve.closure() {
            Some(c) => c,
            None => return Ok(None),
        },
    };
    let [a, b] = [curve.domain().start, curve.domain().end];
    Ok(Some(Closing {
        start: rational_basis_span(curve.knots(), curve.weights(), a),
        end: rational_basis_span(curve.knots(), curve.weights(), b),
        merged: if closure.merged { closure.wrap } else { 0 },
        note: closure.note(),
    }))
}

/// The rules and the area form of a curve, shared by every level.
pub(crate) struct Prepared {
    pub(crate) rules: Rules,
    pub(crate) area: Option<AreaForm>,
    /// What to say with an enclosed area ([`Closure::note`](crate::measure::Closure::note)).
    pub(crate) note: Option<String>,
}

impl Prepared {
    /// The rules, and the area form when `area` asks for it (plane curves),
    /// closed as [`closing`] says and oriented so that the crisp curve's
    /// enclosed area is positive.
    ///
    /// # Errors
    /// As [`closing`].
    pub(crate) fn of<const D: usize>(
        curve: &FuzzyCurve<D>,
        area: bool,
        closed: Option<bool>,
    ) -> Result<Self, Error> {
        let crisp: Vec<f64> = curve.points().iter().flat_map(|p| p.crisp()).collect();
        let rules = rules(curve.knots(), curve.weights(), &crisp, D);
        let (mut form, mut note) = (None, None);
        if area && D == 2 {
            let closing = closing(curve, closed)?;
            note = closing.as_ref().and_then(|c| c.note.clone());
            let f = AreaForm::new(&rules, curve.points().len(), closing.as_ref());
            form = Some(f.positive_for(&crisp));
        }
        Ok(Prepared {
            rules,
            area: form,
            note,
        })
    }

    /// The rules alone (no area).
    pub(crate) fn rules_of<const D: usize>(curve: &FuzzyCurve<D>) -> Rules {
        let crisp: Vec<f64> = curve.points().iter().flat_map(|p| p.crisp()).collect();
        rules(curve.knots(), curve.weights(), &crisp, D)
    }
}

/// Bounds of both ends: `least = [bound, attained]`, `largest = [attained,
/// bound]`.
#[derive(Clone, Copy, Debug)]
struct Ends {
    least: [f64; 2],
    largest: [f64; 2],
    exact: bool,
}

impl Ends {
    fn of(b: Bracket) -> Self {
        // A bracket keeps one gap; each end gets it.
        Ends {
            least: [b.min, b.min + b.gap],
            largest: [b.max - b.gap, b.max],
            exact: b.exact,
        }
    }

    fn bracket(self) -> Bracket {
        Bracket::from_ends(self.least, self.largest, self.exact)
    }
}

/// Tightens brackets by nesting, which the true intervals obey: a value
/// attained in an inner box is attained in the outer one, and the bounds of
/// an outer box hold for the inner one. Within one function a lower level's
/// box contains a higher level's, whatever the order the levels were asked
/// in; at one level `lists[f − 1]`'s box contains `lists[f]`'s (upper ⊇
/// primary ⊇ lower), and the levels of `lists[f]` are a subset of those of
/// `lists[f − 1]` in the same order (a function has a cut wherever one
/// inside it has).
fn nest(lists: &mut [&mut Vec<(f64, Option<Ends>)>]) {
    for list in lists.iter_mut() {
        // Increasing alpha: each level's box contains the next one's.
        let mut order: Vec<usize> = (0..list.len()).collect();
        order.sort_by(|&i, &j| list[i].0.total_cmp(&list[j].0));
        for pair in order.windows(2) {
            if let (Some(a), Some(b)) = (list[pair[0]].1, list[pair[1]].1) {
                list[pair[1]].1 = Some(tighten_inner(a, b));
            }
        }
        for pair in order.windows(2).rev() {
            if let (Some(a), Some(b)) = (list[pair[0]].1, list[pair[1]].1) {
                list[pair[0]].1 = Some(widen_outer(a, b));
            }
        }
    }
    for f in 1..lists.len() {
        let (outer, inner) = lists.split_at_mut(f);
        let (outer, inner) = (&mut *outer[f - 1], &mut *inner[0]);
        let mut o = 0;
        for i in inner.iter_mut() {
            // The same level in the outer list, found in order.
            while outer.get(o).is_some_and(|out| out.0 != i.0) {
                o += 1;
            }
            let Some(out) = outer.get_mut(o) else { break };
            if let (Some(a), Some(b)) = (out.1, i.1) {
                i.1 = Some(tighten_inner(a, b));
                out.1 = Some(widen_outer(a, b));
            }
            o += 1;
        }
    }
}

/// The ends of a quantity over an inner box, tightened by those over a box
/// that contains it: its least value is no less than the outer's least, its
/// largest no more than the outer's largest.
fn tighten_inner(outer: Ends, inner: Ends) -> Ends {
    Ends {
        least: [inner.least[0].max(outer.least[0]), inner.least[1]],
        largest: [inner.largest[0], inner.largest[1].min(outer.largest[1])],
        exact: inner.exact,
    }
}

/// The ends over an outer box, widened by those over a box inside it: what
/// the inner box attains, the outer attains too.
fn widen_outer(outer: Ends, inner: Ends) -> Ends {
    Ends {
        least: [outer.least[0], outer.least[1].min(inner.least[1])],
        largest: [outer.largest[0].max(inner.largest[0]), outer.largest[1]],
        exact: outer.exact,
    }
}

/// The nested brackets of a quantity `f(box)` at every level and function.
/// The levels are independent: with the feature `parallel` they run on
/// rayon's pool (each bracket is computed by the same operations either
/// way).
fn leveled(
    boxes: &PerMembership<Vec<(f64, CutBox)>>,
    f: impl Fn(&CutBox) -> Option<Bracket> + Sync,
) -> PerMembership<Vec<(f64, Option<Bracket>)>> {
    let one = |(alpha, cut): &(f64, CutBox)| (*alpha, f(cut));
    nested(PerMembership::from_fn(|m| {
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            boxes.get(m).par_iter().map(one).collect()
        }
        #[cfg(not(feature = "parallel"))]
        {
            boxes.get(m).iter().map(one).collect()
        }
    }))
}

/// Brackets at every level and function tightened by nesting ([`nest`]).
pub(crate) fn nested(
    brackets: PerMembership<Vec<(f64, Option<Bracket>)>>,
) -> PerMembership<Vec<(f64, Option<Bracket>)>> {
    let mut all: PerMembership<Vec<(f64, Option<Ends>)>> = PerMembership::from_fn(|m| {
        brackets
            .get(m)
            .iter()
            .map(|(a, b)| (*a, b.map(Ends::of)))
            .collect()
    });
    {
        let PerMembership {
            upper,
            primary,
            lower,
        } = &mut all;
        nest(&mut [upper, primary, lower]);
    }
    PerMembership::from_fn(|m| {
        all.get(m)
            .iter()
            .map(|(a, e)| (*a, e.map(Ends::bracket)))
            .collect()
    })
}

impl<const D: usize> FuzzyCurve<D> {
    /// The arc length of the crisp curve through the control points `x`
    /// (flattened, `D` per point) by adaptive quadrature.
    fn adaptive_length(&self, x: &[f64]) -> f64 {
        let points = x
            .chunks_exact(D)
            .map(|c| std::array::from_fn(|k| c[k]))
            .collect();
        self.with_control_points(points).arc_length()
    }

    /// The boxes of cut control points at each level, per function (only
    /// the levels where the function has a cut).
    fn cut_boxes(&self, levels: &[Alpha]) -> PerMembership<Vec<(f64, CutBox)>> {
        PerMembership::from_fn(|m| {
            levels
                .iter()
                .filter_map(|&a| CutBox::of(self.points(), m, a).map(|b| (a.get(), b)))
                .collect()
        })
    }

    /// Every quantity of docs/method.md §11: the arc length (and a plane
    /// curve's area) at each level, the derivative of order `options.order()`,
    /// the tangent angle (plane curves) and the curvature at each parameter
    /// of `options.at()`; each an interval over the box of cut control points
    /// under each membership function.
    ///
    /// # Errors
    /// [`Error::MeasureAt`] for a parameter outside the domain (the
    /// options checked their other rules when made).
    ///
    /// # Examples
    /// A straight segment from 0 to 4 whose end points may each move 1 along
    /// it: lengths from 2 to 6.
    /// ```
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// # use t2spline::measure::MeasureOptions;
    /// let n = |c: f64, s: f64| Nt2Number::try_new(c, [c - s, c + s], [c, c], [c, c], 1.0);
    /// let points = vec![Nt2Point::new([n(0.0, 1.0)?, n(0.0, 0.0)?]), Nt2Point::new([n(4.0, 1.0)?, n(0.0, 0.0)?])];
    /// let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let m = line.measure(&MeasureOptions::uniform(3)?)?;
    /// let upper = &m.length.upper[0];
    /// assert!((upper.min - 2.0).abs() < 1e-9 && (upper.max - 6.0).abs() < 1e-9);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn measure(&self, options: &MeasureOptions) -> Result<Measures, Error> {
        self.check_measure(options)?;
        self.crisp_weights_for("measure")?;
        let prepared = Prepared::of(self, options.area(), options.closing())?;
        let boxes = self.cut_boxes(options.levels());
        let finish = |l: PerMembership<Vec<(f64, Option<Bracket>)>>| {
            PerMembership::from_fn(|m| {
                l.get(m)
                    .iter()
                    .filter_map(|(a, b)| b.map(|b| Level::of(*a, b)))
                    .collect::<Vec<_>>()
            })
        };
        let length = if options.length() {
            finish(leveled(&boxes, |cut| {
                Some(length_bracket(&prepared.rules, cut, &|x| {
                    self.adaptive_length(x)
                }))
            }))
        } else {
            PerMembership::default()
        };
        let area = prepared.area.as_ref().map(|form| {
            let l = finish(leveled(&boxes, |cut| Some(area_bracket(form, cut))));
            AreaMeasure {
                kind: form.kind,
                note: prepared.note.clone(),
                upper: l.upper,
                primary: l.primary,
                lower: l.lower,
            }
        });
        let at = options
            .at()
            .iter()
            .map(|&t| self.measure_at(t, options.order(), &boxes))
            .collect();
        Ok(Measures {
            levels: options.levels().iter().map(|a| a.get()).collect(),
            length,
            area,
            at,
        })
    }

    /// The parameters inside the domain (the options checked the rest).
    fn check_measure(&self, options: &MeasureOptions) -> Result<(), Error> {
        let domain = self.domain();
        for (index, &t) in options.at().iter().enumerate() {
            if !domain.contains(t) {
                return Err(Error::MeasureAt {
                    index,
                    t,
                    start: domain.start,
                    end: domain.end,
                });
            }
        }
        Ok(())
    }

    fn measure_at(
        &self,
        t: f64,
        order: usize,
        boxes: &PerMembership<Vec<(f64, CutBox)>>,
    ) -> AtMeasure {
        let top = order.max(2);
        let (first, r) = coefficients::at(self.knots(), self.weights(), t, top);
        let derivative = PerMembership::from_fn(|m| {
            boxes
                .get(m)
                .iter()
                .map(|(alpha, cut)| {
                    let b = derivative_box(cut, first, &r[order]);
                    DerivativeLevel {
                        alpha: *alpha,
                        min: b.iter().map(|x| x[0]).collect(),
                        max: b.iter().map(|x| x[1]).collect(),
                    }
                })
                .collect()
        });
        let partial = |l: PerMembership<Vec<(f64, Option<Bracket>)>>| {
            PerMembership::from_fn(|m| {
                l.get(m)
                    .iter()
                    .map(|(a, b)| PartialLevel::of(*a, *b))
                    .collect::<Vec<_>>()
            })
        };
        let tangent_angle = (D == 2).then(|| {
            partial(PerMembership::from_fn(|m| {
                boxes
                    .get(m)
                    .iter()
                    .map(|(a, cut)| (*a, angle_range(&derivative_box(cut, first, &r[1]))))
                    .collect()
            }))
        });
        let curvature = partial(leveled(boxes, |cut| {
            curvature_bracket(cut, first, &r[1], &r[2])
        }));
        AtMeasure {
            t,
            order,
            derivative,
            tangent_angle,
            curvature,
        }
    }

    /// The arc length's bracket over the box of cut control points under
    /// `membership` at `alpha`; `None` where the function has no cut there,
    /// and with fuzzy weights (not bounded yet: docs/method.md §16).
    #[must_use]
    pub fn length_bracket(&self, membership: Membership, alpha: Alpha) -> Option<Bracket> {
        if self.weight_numbers().is_some() {
            return None;
        }
        let cut = CutBox::of(self.points(), membership, alpha)?;
        Some(length_bracket(&Prepared::rules_of(self), &cut, &|x| {
            self.adaptive_length(x)
        }))
    }

    /// The exact range of the derivative of order `order` at `t`, per
    /// coordinate (`[min, max]`), over the box under `membership` at
    /// `alpha`; `None` where the function has no cut there.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is outside the domain;
    /// [`Error::OutOfRange`] if `order` is above 64.
    pub fn derivative_bracket(
        &self,
        t: f64,
        order: usize,
        membership: Membership,
        alpha: Alpha,
    ) -> Result<Option<[[f64; 2]; D]>, Error> {
        self.crisp_weights_for("a derivative bracket")?;
        self.domain().check(t)?;
        check_order(order)?;
        let Some(cut) = CutBox::of(self.points(), membership, alpha) else {
            return Ok(None);
        };
        let (first, r) = coefficients::at(self.knots(), self.weights(), t, order);
        let b = derivative_box(&cut, first, &r[order]);
        Ok(Some(std::array::from_fn(|c| b[c])))
    }

    /// The curvature's certified bracket at `t` over the box under
    /// `membership` at `alpha`; `None` where the function has no cut there or
    /// where some admissible curve stands still at `t` (no curvature).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is outside the domain.
    pub fn curvature_bracket(
        &self,
        t: f64,
        membership: Membership,
        alpha: Alpha,
    ) -> Result<Option<Bracket>, Error> {
        self.crisp_weights_for("a curvature bracket")?;
        self.domain().check(t)?;
        let Some(cut) = CutBox::of(self.points(), membership, alpha) else {
            return Ok(None);
        };
        let (first, r) = coefficients::at(self.knots(), self.weights(), t, 2);
        Ok(curvature_bracket(&cut, first, &r[1], &r[2]))
    }
}

impl FuzzyCurve<2> {
    /// The area's bracket (under the curve, or enclosed where the curve
    /// closes: [`FuzzyCurve::closure`]) over the box under `membership` at
    /// `alpha`; `None` where the function has no cut.
    #[must_use]
    pub fn area_bracket(&self, membership: Membership, alpha: Alpha) -> Option<Bracket> {
        if self.weight_numbers().is_some() {
            return None;
        }
        let cut = CutBox::of(self.points(), membership, alpha)?;
        // Closed as the geometry says: no closure is asked, none refused.
        let prepared = Prepared::of(self, true, None).ok()?;
        prepared.area.as_ref().map(|form| area_bracket(form, &cut))
    }

    /// Which area [`FuzzyCurve::area_bracket`] measures.
    #[must_use]
    pub fn area_kind(&self) -> AreaKind {
        if self.closure().is_some() {
            AreaKind::Enclosed
        } else {
            AreaKind::Under
        }
    }

    /// The exact interval of the tangent's angle (radians) at `t`; `None`
    /// where the function has no cut, `Some(None)` where the derivative box
    /// holds the origin (some admissible curve stands still: no direction).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is outside the domain.
    pub fn tangent_angle_bracket(
        &self,
        t: f64,
        membership: Membership,
        alpha: Alpha,
    ) -> Result<Option<Option<Bracket>>, Error> {
        self.crisp_weights_for("a tangent-angle bracket")?;
        Ok(self
            .derivative_bracket(t, 1, membership, alpha)?
            .map(|b| angle_range(&b)))
    }
}
