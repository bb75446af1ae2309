//! Station sections of a plane curve: the fuzzy value of y at `x = x0`
//! (docs/method.md §10), every height some admissible curve takes there.

use crate::error::Error;
use crate::fuzzy::{Alpha, Membership};
use crate::pipeline::FuzzyCurve;
use crate::set::cut_lines::MEMBERSHIPS;
use crate::set::intervals::join;
use crate::set::sweep::{hull_of, PlaneBox, Sweep, TooManyBoxes};
use crate::set::weighted_section::weighted_section;
use crate::set::weighted_terms::Weighted;

/// The section of every membership function at one level: the intervals of
/// the station's value, in increasing order (several where the curve passes
/// the station more than once); `None` where the function has no cut at
/// this level, empty where the region does not reach the station.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SectionLevel {
    /// The level.
    pub alpha: f64,
    /// The upper function's intervals.
    pub upper: Option<Vec<[f64; 2]>>,
    /// The primary function's intervals.
    pub primary: Option<Vec<[f64; 2]>>,
    /// The lower function's intervals.
    pub lower: Option<Vec<[f64; 2]>>,
}

impl SectionLevel {
    /// The intervals of one function.
    #[must_use]
    pub fn get(&self, membership: Membership) -> Option<&[[f64; 2]]> {
        match membership {
            Membership::Upper => self.upper.as_deref(),
            Membership::Primary => self.primary.as_deref(),
            Membership::Lower => self.lower.as_deref(),
        }
    }
}

impl FuzzyCurve<2> {
    /// The section `{ y : (x0, y) in region }` of the region of `membership`
    /// at `alpha`, as intervals in increasing order; `None` if the function
    /// has no cut at `alpha` anywhere. Interval ends are within `tolerance`
    /// (`None`: the [default](FuzzyCurve::default_tolerance)): the region's
    /// sampled sweep (as for [`FuzzyCurve::region`], not grown) is cut by the
    /// line, and intervals closer than half the tolerance are joined. A line
    /// within the set view's slack of the region
    /// ([`RELATIVE_SLACK`](crate::set::RELATIVE_SLACK) of the job's extent)
    /// meets it, as [`FuzzyCurve::membership`] counts such points in. With
    /// fuzzy weights the section is the union over `t` of the exact
    /// sections of the sets at `t`, bounded piece by piece
    /// (docs/method.md §16): never narrower than the truth, each end
    /// within `tolerance` of a value some choice attains.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] if `x0` is not finite; [`Error::Tolerance`] as
    /// for [`FuzzyCurve::region`].
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Membership, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c, c], 1.0);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(4.0)?, n(2.0)?])];
    /// let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// // At x = 2 the boxes with t in [1/4, 3/4] count: y from 0.5 − 1 to 1.5 + 1.
    /// let s = line.section(2.0, Membership::Upper, Alpha::ZERO, Some(1e-6))?.unwrap();
    /// assert_eq!(s.len(), 1);
    /// assert!((s[0][0] + 0.5).abs() < 1e-6 && (s[0][1] - 2.5).abs() < 1e-6);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn section(
        &self,
        x0: f64,
        membership: Membership,
        alpha: Alpha,
        tolerance: Option<f64>,
    ) -> Result<Option<Vec<[f64; 2]>>, Error> {
        crate::set::membership::check_point(0, &[x0])?;
        let tolerance = self.checked_tolerance([0, 1], tolerance)?;
        if let Some(weights) = self.weight_numbers() {
            let on = Weighted::new(self, weights);
            return Ok(weighted_section(&on, x0, membership, alpha, tolerance));
        }
        let sweep = Sweep::of(self, membership, alpha.get(), [0, 1], 0.25 * tolerance).map_err(
            |TooManyBoxes| Error::Tolerance {
                value: tolerance,
                least: 2.0 * tolerance,
            },
        )?;
        if sweep.runs.is_empty() {
            return Ok(None);
        }
        let slack = crate::set::cut_lines::slack(self.points());
        let mut intervals = Vec::new();
        for run in &sweep.runs {
            if run.len() == 1 {
                intervals.extend(cut(&run[0], &run[0], x0, slack));
            }
            for w in run.windows(2) {
                intervals.extend(cut(&w[0], &w[1], x0, slack));
            }
        }
        Ok(Some(join(intervals, 0.5 * tolerance)))
    }

    /// The sections of all three functions at each level of `levels`.
    ///
    /// # Errors
    /// As [`FuzzyCurve::section`].
    pub fn sections(
        &self,
        x0: f64,
        levels: &[Alpha],
        tolerance: Option<f64>,
    ) -> Result<Vec<SectionLevel>, Error> {
        levels
            .iter()
            .map(|&alpha| {
                let [upper, primary, lower] =
                    MEMBERSHIPS.map(|m| self.section(x0, m, alpha, tolerance));
                Ok(SectionLevel {
                    alpha: alpha.get(),
                    upper: upper?,
                    primary: primary?,
                    lower: lower?,
                })
            })
            .collect()
    }
}

/// The interval where the line `x = x0` meets the convex hull of two boxes;
/// a line within `slack` of the hull (the set view's slack) meets it at its
/// nearest side, as [`FuzzyCurve::membership`] counts such a point in.
fn cut(b0: &PlaneBox, b1: &PlaneBox, x0: f64, slack: f64) -> Option<[f64; 2]> {
    let hull = hull_of(b0, b1, 0.0);
    let (least, most) = hull
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, m), v| {
            (l.min(v[0]), m.max(v[0]))
        });
    if !(least - slack <= x0 && x0 <= most + slack) {
        return None;
    }
    let x0 = x0.clamp(least, most);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let n = hull.len();
    for i in 0..n {
        let (a, b) = (hull[i], hull[(i + 1) % n]);
        let (xa, xb) = (a[0].min(b[0]), a[0].max(b[0]));
        if x0 < xa || x0 > xb {
            continue;
        }
        let ys: [f64; 2] = if xa == xb {
            [a[1], b[1]]
        } else {
            let y = a[1] + (x0 - a[0]) * (b[1] - a[1]) / (b[0] - a[0]);
            [y, y]
        };
        for y in ys {
            lo = lo.min(y);
            hi = hi.max(y);
        }
    }
    (lo <= hi).then_some([lo, hi])
}
