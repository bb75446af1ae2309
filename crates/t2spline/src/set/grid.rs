//! The membership map of a plane curve on a grid: the curve's footprint of
//! uncertainty as pictures (docs/method.md §10).
//!
//! Scanning the parameter for every cell would cost a search per cell. The
//! map is instead drawn box by box: the parameter of every piece is stepped so
//! that the box moves by at most half a cell per step, and each box raises the
//! cells it covers to its grade there,
//!
//! ```text
//! grade(x, y) = min( top, (x − A_x)/G_x, (B_x − x)/G'_x, (y − A_y)/G_y, (B_y − y)/G'_y )
//! ```
//! (the box at level alpha is `[A + alpha·G, B − alpha·G']` per coordinate), a
//! truncated pyramid over the box at level 0, computed per column and per row
//! and combined by `min`. A cell's value is then the grade of its centre to
//! within the change of the grade over half a cell.

use crate::error::Error;
use crate::pipeline::FuzzyCurve;
use crate::set::cut_lines::{CutLines, MEMBERSHIPS};
use crate::set::scan::{pieces, rational_basis};

/// Cells of a membership grid at most (4096 × 4096): three maps of eight-byte
/// values, 400 MB.
pub const MAX_GRID_CELLS: usize = 4096 * 4096;

/// The coarse steps per piece from which the step count is chosen.
const PROBE_STEPS: usize = 16;

/// The grades of the cell centres of a grid, row by row (`y` outer, `x`
/// inner): `upper[j * xs.len() + i]` is the upper grade of `(xs[i], ys[j])`.
#[derive(Clone, Debug, PartialEq)]
pub struct MembershipGrid {
    /// The cell centres along x, increasing.
    pub xs: Vec<f64>,
    /// The cell centres along y, increasing.
    pub ys: Vec<f64>,
    /// `mu_upper` per cell.
    pub upper: Vec<f64>,
    /// `mu_primary` per cell.
    pub primary: Vec<f64>,
    /// `mu_lower` per cell.
    pub lower: Vec<f64>,
}

impl FuzzyCurve<2> {
    /// The membership grades of the centres of a regular grid: `columns`
    /// cells across `[x0, x1]` and `rows` cells across `[y0, y1]`.
    ///
    /// # Errors
    /// [`Error::GridTooLarge`] past [`MAX_GRID_CELLS`] or with no cell;
    /// [`Error::QueryPoint`] if a bound is not finite; [`Error::GridRange`]
    /// if a range is empty.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.25, c + 0.25], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(4.0)?, n(0.0)?])];
    /// let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let g = line.membership_grid([-2.0, 6.0], [-2.0, 2.0], [80, 40])?;
    /// let at = |x: f64, y: f64| line.membership(&[x, y]).unwrap().upper;
    /// let (i, j) = (25, 24); // the centre (0.55, 0.5)
    /// assert!((g.upper[j * 80 + i] - at(g.xs[i], g.ys[j])).abs() < 0.01);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn membership_grid(
        &self,
        [x0, x1]: [f64; 2],
        [y0, y1]: [f64; 2],
        [columns, rows]: [usize; 2],
    ) -> Result<MembershipGrid, Error> {
        self.crisp_weights_for("a membership grid")?;
        let cells = columns.saturating_mul(rows);
        if cells == 0 || cells > MAX_GRID_CELLS {
            return Err(Error::GridTooLarge {
                columns,
                rows,
                limit: MAX_GRID_CELLS,
            });
        }
        for (index, p) in [[x0, y0], [x1, y1]].iter().enumerate() {
            crate::set::membership::check_point(index, p)?;
        }
        for (axis, [lo, hi]) in [(crate::Axis::X, [x0, x1]), (crate::Axis::Y, [y0, y1])] {
            if lo >= hi {
                return Err(Error::GridRange { axis, lo, hi });
            }
        }
        let (dx, dy) = ((x1 - x0) / columns as f64, (y1 - y0) / rows as f64);
        let xs: Vec<f64> = (0..columns).map(|i| x0 + (i as f64 + 0.5) * dx).collect();
        let ys: Vec<f64> = (0..rows).map(|j| y0 + (j as f64 + 0.5) * dy).collect();
        let [upper, primary, lower] = MEMBERSHIPS.map(|m| {
            let lines = CutLines::of(self.points(), m);
            let mut map = vec![0.0; cells];
            self.raster(&lines, &xs, &ys, [dx, dy], &mut map);
            map
        });
        // The grades' order holds exactly; the rasters meet the same boxes.
        let (mut upper, mut primary, mut lower) = (upper, primary, lower);
        for ((u, p), l) in upper.iter_mut().zip(&mut primary).zip(&mut lower) {
            *u = u.clamp(0.0, 1.0);
            *p = p.clamp(0.0, *u);
            *l = l.clamp(0.0, *p);
        }
        Ok(MembershipGrid {
            xs,
            ys,
            upper,
            primary,
            lower,
        })
    }

    /// Raises every cell of `map` to the grade of the boxes under `lines`.
    fn raster(&self, lines: &CutLines<2>, xs: &[f64], ys: &[f64], cell: [f64; 2], map: &mut [f64]) {
        let (knots, weights) = (self.knots(), self.weights());
        let p = self.degree();
        let mut basis = vec![0.0; p + 1];
        let mut gx: Vec<f64> = Vec::new();
        for piece in pieces(knots, weights) {
            let first = piece.first(p);
            let top = lines.top_of(first, p + 1);
            if top <= 0.0 {
                continue;
            }
            let mut sums = |t: f64| {
                rational_basis(knots, weights, piece.span, t, &mut basis);
                lines.sums(first, &basis)
            };
            // Steps: enough that no foot moves more than half a cell per step,
            // judged on a coarse probe.
            let probe: Vec<_> = piece.params(PROBE_STEPS).map(&mut sums).collect();
            let mut most = 0.0_f64;
            for w in probe.windows(2) {
                for c in 0..2 {
                    for e in [0, 2] {
                        most = most.max((w[1][c][e] - w[0][c][e]).abs() / cell[c]);
                    }
                }
            }
            let steps =
                ((PROBE_STEPS as f64 * most * 2.0).ceil() as usize).clamp(PROBE_STEPS, 1 << 22);
            for t in piece.params(steps) {
                let s = sums(t);
                let ([ax, gxl, bx, gxr], [ay, gyl, by, gyr]) = (s[0], s[1]);
                let (i0, i1) = (first_at_least(xs, ax), xs.partition_point(|&x| x <= bx));
                let (j0, j1) = (first_at_least(ys, ay), ys.partition_point(|&y| y <= by));
                if i0 >= i1 || j0 >= j1 {
                    continue;
                }
                gx.clear();
                gx.extend(
                    xs[i0..i1]
                        .iter()
                        .map(|&x| side(x - ax, gxl).min(side(bx - x, gxr)).min(top)),
                );
                for (j, &y) in ys.iter().enumerate().take(j1).skip(j0) {
                    let gy = side(y - ay, gyl).min(side(by - y, gyr));
                    let row = &mut map[j * xs.len() + i0..j * xs.len() + i1];
                    for (m, &g) in row.iter_mut().zip(&gx) {
                        let v = g.min(gy);
                        if v > *m {
                            *m = v;
                        }
                    }
                }
            }
        }
    }
}

/// The index of the first value `≥ v` in increasing `xs`.
fn first_at_least(xs: &[f64], v: f64) -> usize {
    xs.partition_point(|&x| x < v)
}

/// `room/slope` (the level up to which one side admits the value), `+∞` for
/// a crisp side.
fn side(room: f64, slope: f64) -> f64 {
    if slope > 0.0 {
        room / slope
    } else {
        f64::INFINITY
    }
}
