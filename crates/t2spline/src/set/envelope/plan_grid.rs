//! The regular grid over a plan extent whose cell centres an envelope bounds.

use crate::error::Error;

/// Values of an envelope at most (cells × levels × 6, at 8 bytes each
/// 800 MB): the 1 000 × 1 000 grid at 11 levels is 66 million.
pub const MAX_ENVELOPE_VALUES: usize = 100_000_000;

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
