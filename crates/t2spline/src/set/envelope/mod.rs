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

mod bounds;
mod crisp;
mod fuzzy;
mod plan_grid;
mod plan_map;

pub use bounds::{EnvelopeBounds, EnvelopeLevel};
pub use plan_grid::{PlanGrid, MAX_ENVELOPE_VALUES};

use crate::error::Error;
use crate::fuzzy::Alpha;
use crate::pipeline::FuzzySurface;

/// Cells × levels at most where x or y of a control point is fuzzy, since
/// each cell is then a search of the set: about 40 ms per cell and level for
/// a 6 × 5 net (docs/performance.md), so the limit is some minutes.
pub const MAX_FUZZY_ENVELOPE_CELLS: usize = 10_000;

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
    /// checked before anything is computed; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
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
        self.crisp_weights_for("an envelope")?;
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
