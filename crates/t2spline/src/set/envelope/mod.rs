//! The envelope of a fuzzy surface over a plan grid (docs/method.md §12): at
//! each level and for each membership function, the least and the greatest
//! height the surface can take above each plan point.
//!
//! With crisp x and y (a terrain: stations at known places, uncertain
//! heights) every admissible net has the same plan map, and above a plan
//! point with parameters `(u, v)` the height is `Σ Rᵢⱼ(u, v)·zᵢⱼ` with
//! `Rᵢⱼ ≥ 0`: it is least with every `zᵢⱼ` at its cut's left end and greatest
//! with every one at its right end,
//!
//! ```text
//! least_m(alpha; x, y)    = Σ Rᵢⱼ(u, v)·left_m(zᵢⱼ, alpha)
//! greatest_m(alpha; x, y) = Σ Rᵢⱼ(u, v)·right_m(zᵢⱼ, alpha),   (x(u, v), y(u, v)) = (x, y)
//! ```
//! exactly (up to rounding): two crisp surfaces per level and function,
//! evaluated at parameters found once per plan point (`plan_map.rs`). The
//! ends are linear in alpha (`cut_lines.rs`), so each cell needs four sums
//! per function whatever the number of levels.
//!
//! Where x or y is fuzzy the height interval at `(x, y)` is the section of
//! the set ([`FuzzySurface::sections`]), hulled over its intervals, to that
//! method's tolerance (about 1e-9 of the region's height) and at its cost.
//!
//! A cell whose plan point no admissible surface reaches is NODATA (NaN); so
//! is a cell whose span rectangle has a control point without a lower cut at
//! the level. A function without a cut anywhere at a level (the lower one
//! above the heights `h`) is `None` at that level.

mod crisp;
mod fuzzy;
mod plan_map;

use crate::error::Error;
use crate::fuzzy::{Alpha, Membership};
use crate::pipeline::FuzzySurface;

/// Values of an envelope at most (cells × levels × 6, at 8 bytes each
/// 800 MB): the 1 000 × 1 000 grid at 11 levels is 66 million.
pub const MAX_ENVELOPE_VALUES: usize = 100_000_000;

/// Cells × levels at most where x or y of a control point is fuzzy, since
/// each cell is then a search of the set: about 40 ms per cell and level for
/// a 6 × 5 net (docs/performance.md), so the limit is some minutes.
pub const MAX_FUZZY_ENVELOPE_CELLS: usize = 10_000;

/// A regular grid over a plan extent: `nx × ny` cells over
/// `[x0, x1] × [y0, y1]`, whose centres are the plan points of an envelope.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanGrid {
    extent: [f64; 4],
    shape: [usize; 2],
}

impl PlanGrid {
    /// The grid of `shape = [nx, ny]` cells over `extent = [x0, y0, x1, y1]`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] with no cell along x or y;
    /// [`Error::EnvelopeTooLarge`] past [`MAX_ENVELOPE_VALUES`] cells;
    /// [`Error::QueryPoint`] if a bound is not finite; [`Error::GridRange`] if
    /// a range is empty.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::set::PlanGrid;
    /// let g = PlanGrid::try_new([0.0, 0.0, 4.0, 2.0], [4, 2])?;
    /// assert_eq!(g.xs(), vec![0.5, 1.5, 2.5, 3.5]);
    /// assert_eq!(g.ys(), vec![0.5, 1.5]);
    /// let e = PlanGrid::try_new([0.0, 0.0, 4.0, 2.0], [0, 2]).unwrap_err();
    /// assert_eq!(e.to_string(), "grid cells along x = 0 is outside 1, 2, …");
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(extent: [f64; 4], shape: [usize; 2]) -> Result<Self, Error> {
        let [x0, y0, x1, y1] = extent;
        let [columns, rows] = shape;
        for (what, n) in [
            ("grid cells along x", columns),
            ("grid cells along y", rows),
        ] {
            if n == 0 {
                return Err(Error::OutOfRange {
                    place: crate::place::Place::NONE,
                    what,
                    value: 0.0,
                    range: "1, 2, …",
                });
            }
        }
        if columns.saturating_mul(rows) > MAX_ENVELOPE_VALUES {
            return Err(Error::EnvelopeTooLarge {
                columns,
                rows,
                levels: 1,
                limit: MAX_ENVELOPE_VALUES,
                counted: "values (cells x levels x 6)",
            });
        }
        for (index, p) in [[x0, y0], [x1, y1]].iter().enumerate() {
            crate::set::membership::check_point(index, p)?;
        }
        for (axis, [lo, hi]) in [(crate::Axis::X, [x0, x1]), (crate::Axis::Y, [y0, y1])] {
            if lo >= hi || !(hi - lo).is_finite() {
                return Err(Error::GridRange { axis, lo, hi });
            }
        }
        Ok(PlanGrid { extent, shape })
    }

    /// `[x0, y0, x1, y1]`.
    #[must_use]
    pub fn extent(&self) -> [f64; 4] {
        self.extent
    }

    /// `[nx, ny]`: cells along x and along y.
    #[must_use]
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// The size of a cell, `[(x1 − x0)/nx, (y1 − y0)/ny]`.
    #[must_use]
    pub fn cell_size(&self) -> [f64; 2] {
        let [x0, y0, x1, y1] = self.extent;
        [
            (x1 - x0) / self.shape[0] as f64,
            (y1 - y0) / self.shape[1] as f64,
        ]
    }

    /// The cell centres along x, increasing: `x0 + (i + ½)·(x1 − x0)/nx`.
    #[must_use]
    pub fn xs(&self) -> Vec<f64> {
        let d = self.cell_size()[0];
        (0..self.shape[0])
            .map(|i| self.extent[0] + (i as f64 + 0.5) * d)
            .collect()
    }

    /// The cell centres along y, increasing.
    #[must_use]
    pub fn ys(&self) -> Vec<f64> {
        let d = self.cell_size()[1];
        (0..self.shape[1])
            .map(|j| self.extent[1] + (j as f64 + 0.5) * d)
            .collect()
    }
}

/// The least and the greatest height per plan point (NaN: NODATA).
#[derive(Clone, Debug, PartialEq)]
pub struct EnvelopeBounds {
    /// The least height.
    pub least: Vec<f64>,
    /// The greatest height.
    pub greatest: Vec<f64>,
}

/// The envelope of every membership function at one level; `None` where the
/// function has no cut at this level.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvelopeLevel {
    /// The level.
    pub alpha: f64,
    /// The upper function's bounds.
    pub upper: Option<EnvelopeBounds>,
    /// The primary function's bounds.
    pub primary: Option<EnvelopeBounds>,
    /// The lower function's bounds.
    pub lower: Option<EnvelopeBounds>,
}

impl EnvelopeLevel {
    /// The bounds of one function.
    #[must_use]
    pub fn get(&self, membership: Membership) -> Option<&EnvelopeBounds> {
        match membership {
            Membership::Upper => self.upper.as_ref(),
            Membership::Primary => self.primary.as_ref(),
            Membership::Lower => self.lower.as_ref(),
        }
    }
}

/// The envelope of a fuzzy surface on a [`PlanGrid`]: per level, bounds per
/// cell, row by row (`y` outer, increasing; `x` inner):
/// `least[j·nx + i]` belongs to `(xs[i], ys[j])`.
#[derive(Clone, Debug, PartialEq)]
pub struct Envelope {
    /// The grid.
    pub grid: PlanGrid,
    /// Per level, in the order asked.
    pub levels: Vec<EnvelopeLevel>,
    /// Whether x and y are crisp, so that the bounds are exact up to
    /// rounding; else they are sections of the set, to their tolerance.
    pub exact: bool,
}

impl FuzzySurface<3> {
    /// Whether x and y of every control point are crisp (all seven values
    /// equal), so that every admissible net has the same plan map.
    #[must_use]
    pub fn has_crisp_plan(&self) -> bool {
        self.points()
            .iter()
            .all(|p| p.coords()[..2].iter().all(|c| c.upper().width() == 0.0))
    }

    /// The plan extent `[x0, y0, x1, y1]`: with a crisp plan the box of the
    /// surface's x and y (tight, [`crate::NurbsSurface::bounding_box`]); else
    /// the box of the control points' upper cuts at level 0, which holds the
    /// set (convex hull property).
    #[must_use]
    pub fn plan_extent(&self) -> [f64; 4] {
        if self.has_crisp_plan() {
            let b = self.crisp_surface().bounding_box();
            return [b.min[0], b.min[1], b.max[0], b.max[1]];
        }
        let mut e = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in self.points() {
            let [x, y, _] = p.coords();
            e = [
                e[0].min(x.upper().left()),
                e[1].min(y.upper().left()),
                e[2].max(x.upper().right()),
                e[3].max(y.upper().right()),
            ];
        }
        e
    }

    /// The envelope on `grid` at `levels`: for each level and membership
    /// function, the least and the greatest height of the surfaces whose
    /// control points lie inside their cuts, above each cell centre (module
    /// [`crate::set`], docs/method.md §12). Exact up to rounding where x and
    /// y are crisp; else the hull of [`FuzzySurface::sections`] per cell.
    ///
    /// # Errors
    /// [`Error::EnvelopeTooLarge`] past [`MAX_ENVELOPE_VALUES`] values, or
    /// (x or y fuzzy) past [`MAX_FUZZY_ENVELOPE_CELLS`] cells × levels;
    /// checked before anything is computed.
    ///
    /// # Examples
    /// A plane `z = 0` over `[0, 2]²` whose heights are `±1` wide at level 0:
    /// ```
    /// # use t2spline::{Alpha, FuzzySurface, Nt2Number, Nt2Point};
    /// # use t2spline::set::PlanGrid;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let z = Nt2Number::try_new(0.0, [-1.0, 1.0], [-0.5, 0.5], [-0.25, 0.25], 0.5)?;
    /// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([c(x)?, c(y)?, z]));
    /// let net = vec![vec![p(0.0, 0.0)?, p(0.0, 2.0)?], vec![p(2.0, 0.0)?, p(2.0, 2.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let grid = PlanGrid::try_new(s.plan_extent(), [2, 2])?;
    /// let e = s.envelope(&grid, &[Alpha::ZERO, Alpha::try_new(1.0)?])?;
    /// let upper = e.levels[0].upper.as_ref().unwrap();
    /// assert_eq!((upper.least[3], upper.greatest[3]), (-1.0, 1.0));
    /// assert!(e.levels[1].lower.is_none()); // above the lower height 0.5
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn envelope(&self, grid: &PlanGrid, levels: &[Alpha]) -> Result<Envelope, Error> {
        let [nx, ny] = grid.shape();
        self.check_envelope_size([nx, ny], levels.len())?;
        let exact = self.has_crisp_plan();
        let levels = if exact {
            crisp::on_grid(self, grid, levels)
        } else {
            let (xs, ys) = (grid.xs(), grid.ys());
            let points: Vec<[f64; 2]> = ys
                .iter()
                .flat_map(|&y| xs.iter().map(move |&x| [x, y]))
                .collect();
            fuzzy::at_points(self, &points, levels)
        };
        Ok(Envelope {
            grid: grid.clone(),
            levels,
            exact,
        })
    }

    /// The envelope at any plan points (bounds indexed as `points`), as
    /// [`FuzzySurface::envelope`].
    ///
    /// # Errors
    /// [`Error::QueryPoint`] for a point that is not finite; the errors of
    /// [`FuzzySurface::envelope`].
    pub fn envelope_at(
        &self,
        points: &[[f64; 2]],
        levels: &[Alpha],
    ) -> Result<Vec<EnvelopeLevel>, Error> {
        self.check_envelope_size([points.len(), 1], levels.len())?;
        for (i, p) in points.iter().enumerate() {
            crate::set::membership::check_point(i, p)?;
        }
        Ok(if self.has_crisp_plan() {
            crisp::at_points(self, points, levels)
        } else {
            fuzzy::at_points(self, points, levels)
        })
    }

    /// The envelope at the plan points `(xs[i], ys[j])`, row by row (`y`
    /// outer, `x` inner), as [`FuzzySurface::envelope`] on a grid whose
    /// centres they are: the corners of the cells of a contour.
    pub(crate) fn envelope_on_axes(
        &self,
        xs: &[f64],
        ys: &[f64],
        levels: &[Alpha],
    ) -> Result<Vec<EnvelopeLevel>, Error> {
        self.check_envelope_size([xs.len(), ys.len()], levels.len())?;
        Ok(if self.has_crisp_plan() {
            crisp::on_axes(self, xs, ys, levels)
        } else {
            let points: Vec<[f64; 2]> = ys
                .iter()
                .flat_map(|&y| xs.iter().map(move |&x| [x, y]))
                .collect();
            fuzzy::at_points(self, &points, levels)
        })
    }

    /// The limits on an envelope's size, checked before it is computed.
    fn check_envelope_size(&self, [columns, rows]: [usize; 2], levels: usize) -> Result<(), Error> {
        let cells = columns.saturating_mul(rows);
        let values = cells.saturating_mul(levels).saturating_mul(6);
        let too_large = |limit: usize, counted: &'static str| Error::EnvelopeTooLarge {
            columns,
            rows,
            levels,
            limit,
            counted,
        };
        if values > MAX_ENVELOPE_VALUES {
            return Err(too_large(
                MAX_ENVELOPE_VALUES,
                "values (cells x levels x 6)",
            ));
        }
        if !self.has_crisp_plan() && cells.saturating_mul(levels) > MAX_FUZZY_ENVELOPE_CELLS {
            return Err(too_large(
                MAX_FUZZY_ENVELOPE_CELLS,
                "cells x levels for a surface whose x or y is fuzzy",
            ));
        }
        Ok(())
    }
}

/// Bounds being gathered: per level, per function (upper, primary, lower),
/// `None` where the function has no cut at that level.
pub(crate) struct Gathered {
    pub(crate) levels: Vec<(f64, [Option<EnvelopeBounds>; 3])>,
}

impl Gathered {
    /// Empty bounds (`+∞`, `−∞`) for `n` points, at each level where
    /// `present(alpha)` holds per function.
    pub(crate) fn new(n: usize, levels: &[Alpha], present: impl Fn(usize, f64) -> bool) -> Self {
        let levels = levels
            .iter()
            .map(|a| {
                let alpha = a.get();
                let bounds = [0, 1, 2].map(|k| {
                    present(k, alpha).then(|| EnvelopeBounds {
                        least: vec![f64::INFINITY; n],
                        greatest: vec![f64::NEG_INFINITY; n],
                    })
                });
                (alpha, bounds)
            })
            .collect();
        Gathered { levels }
    }

    /// The finished levels: points never reached NaN; ends that rounding
    /// crossed (at a function's top, where both are the same sum) put in
    /// order; and the order of the functions (upper ⊇ primary ⊇ lower) made
    /// exact where rounding of the separate sums could break it by an ulp.
    pub(crate) fn finish(self) -> Vec<EnvelopeLevel> {
        self.levels
            .into_iter()
            .map(|(alpha, bounds)| {
                let [mut upper, mut primary, mut lower] = bounds;
                for b in [&mut upper, &mut primary, &mut lower].into_iter().flatten() {
                    for (lo, hi) in b.least.iter_mut().zip(&mut b.greatest) {
                        if *lo == f64::INFINITY {
                            (*lo, *hi) = (f64::NAN, f64::NAN);
                        } else if *lo > *hi {
                            (*lo, *hi) = (*hi, *lo);
                        }
                    }
                }
                nest(upper.as_ref(), primary.as_mut());
                nest(primary.as_ref(), lower.as_mut());
                EnvelopeLevel {
                    alpha,
                    upper,
                    primary,
                    lower,
                }
            })
            .collect()
    }
}

/// Clamps `inner` into `outer` where both have data.
fn nest(outer: Option<&EnvelopeBounds>, inner: Option<&mut EnvelopeBounds>) {
    let (Some(o), Some(i)) = (outer, inner) else {
        return;
    };
    let pairs = o.least.iter().zip(&o.greatest);
    for ((lo, hi), (olo, ohi)) in i.least.iter_mut().zip(&mut i.greatest).zip(pairs) {
        if lo.is_nan() || olo.is_nan() {
            continue;
        }
        *lo = lo.max(*olo);
        *hi = hi.min(*ohi);
        if *lo > *hi {
            // Intervals that rounding moved apart by an ulp (at a top, where
            // both are one value): the point between, inside the outer.
            let m = (0.5 * (*lo + *hi)).max(*olo).min(*ohi);
            (*lo, *hi) = (m, m);
        }
    }
}
