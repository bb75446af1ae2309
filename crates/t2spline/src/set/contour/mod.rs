//! The fuzzy contour of a fuzzy surface (docs/method.md §13): at a level and
//! for each membership function, the plan points where some admissible
//! surface (every height anywhere in its cut) crosses the height `z0`.
//!
//! Above a plan point the admissible heights fill the envelope's interval
//! `[least, greatest]` (§12; every height between is taken, the heights
//! being a connected set and the surface continuous in them), so the band is
//!
//! ```text
//! band_m(alpha; z0) = { (x, y) : least_m(alpha; x, y) ≤ z0 ≤ greatest_m(alpha; x, y) }
//! ```
//!
//! **On a grid, grown.** The envelope is taken at the corners of the cells
//! of a [`PlanGrid`]; a cell belongs to the band when the interval of the
//! envelope over the cell contains `z0`, and the band is the union of those
//! cells, traced as polygons with holes (`cells.rs`). The interval over a
//! cell is the hull of its corners' values widened by a bound of how far a
//! smooth function can pass beyond its corners inside the cell: bilinear
//! interpolation is off by at most `(hx²·|f_xx| + hy²·|f_yy|)/8`, and the
//! second differences of the corner values nearby give `hx²·f_xx` and
//! `hy²·f_yy`; the widening is twice that estimate, taken over the cell's
//! corners and their neighbours. A continuous `least ≤ greatest` reaches
//! `z0` inside a cell exactly when its least value there is at most `z0` and
//! its greatest at least `z0`, so a cell is kept when
//!
//! ```text
//! min corners(least) − slack_least ≤ z0 ≤ max corners(greatest) + slack_greatest
//! ```
//! The polygons hold every crossing while the envelope's curvature changes
//! by less than a factor two between neighbouring cells (a grid of several
//! cells per knot span), and every point of them lies within one cell
//! diagonal of a cell whose corners' interval, widened, contains `z0`: the
//! tolerance reported is the cell diagonal in the plan and, in height, the
//! most by which a kept cell's corners missed `z0` (where the widening alone
//! kept it; a surface that comes that close to `z0` without reaching it
//! may add such cells).
//!
//! The widening differs between functions and levels, so the kept cells are
//! then nested as the true bands are: a cell of the lower band is one of
//! the primary and the upper band, and a cell of a band at one level is one
//! of the same function's band at every lower level.
//!
//! The crisp surface's contour at `z0` is traced by marching squares on the
//! same corners with linear interpolation on the cells' edges (`lines.rs`).

mod cells;
mod lines;

use crate::error::Error;
use crate::fuzzy::{Alpha, Membership};
use crate::nurbs::Direction;
use crate::pipeline::FuzzySurface;
use crate::place::Place;
use crate::set::cut_lines::MEMBERSHIPS;
use crate::set::envelope::PlanGrid;
use crate::set::polygon::Region;

/// Cells per knot span of the default contour grid.
pub const CONTOUR_CELLS_PER_SPAN: usize = 8;

/// Cells along an axis of the default contour grid at most (and at least
/// [`MIN_CONTOUR_CELLS`]).
pub const MAX_CONTOUR_CELLS: usize = 1024;

/// Cells along an axis of the default contour grid at least.
pub const MIN_CONTOUR_CELLS: usize = 16;

/// The bands of every membership function at one level; `None` where the
/// function has no cut at this level. A band the surface never reaches is a
/// region without polygons.
#[derive(Clone, Debug, PartialEq)]
pub struct ContourLevel {
    /// The level.
    pub alpha: f64,
    /// The upper function's band.
    pub upper: Option<Region>,
    /// The primary function's band.
    pub primary: Option<Region>,
    /// The lower function's band.
    pub lower: Option<Region>,
}

impl ContourLevel {
    /// The band of one function.
    #[must_use]
    pub fn get(&self, membership: Membership) -> Option<&Region> {
        match membership {
            Membership::Upper => self.upper.as_ref(),
            Membership::Primary => self.primary.as_ref(),
            Membership::Lower => self.lower.as_ref(),
        }
    }
}

/// The fuzzy contour of a surface at height `z`: the band per level and
/// function, and the crisp surface's contour.
#[derive(Clone, Debug, PartialEq)]
pub struct Contour {
    /// The grid whose cell corners carry the envelope.
    pub grid: PlanGrid,
    /// The height.
    pub z: f64,
    /// Per level, in the order asked.
    pub levels: Vec<ContourLevel>,
    /// The crisp surface's contour at `z`: polylines, closed ones with their
    /// first vertex repeated at the end.
    pub crisp: Vec<Vec<[f64; 2]>>,
    /// The bands' tolerance in the plan: the diagonal of a cell.
    pub tolerance: f64,
    /// The bands' tolerance in height: the most by which the envelope's
    /// interval at a kept cell's corners misses `z` (0 where every kept
    /// cell's corners reach `z`). Every kept cell holds a point where the
    /// envelope comes within this of `z`, if the widening is not larger
    /// than the error it bounds.
    pub height_tolerance: f64,
}

impl FuzzySurface<3> {
    /// The default contour grid's shape over `extent = [x0, y0, x1, y1]`:
    /// square cells of the plan length of the shortest knot span over
    /// [`CONTOUR_CELLS_PER_SPAN`], `nx` and `ny` each within
    /// [`MIN_CONTOUR_CELLS`] ..= [`MAX_CONTOUR_CELLS`]. A span's plan length
    /// is the longest of the plan distances between its ends along the
    /// lines of the other direction at its start, middle and end.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([c(x)?, c(y)?, c(0.0)?]));
    /// let net = vec![vec![p(0.0, 0.0)?, p(0.0, 1.0)?], vec![p(8.0, 0.0)?, p(8.0, 1.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// // The shortest span is 1 long: cells of 1/8, 64 along x, 8 (so 16) along y.
    /// assert_eq!(s.contour_shape([0.0, 0.0, 8.0, 1.0]), [64, 16]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn contour_shape(&self, extent: [f64; 4]) -> [usize; 2] {
        let crisp = self.crisp_surface();
        let mut shortest = f64::INFINITY;
        for (d, other) in [(Direction::U, Direction::V), (Direction::V, Direction::U)] {
            let across = self.domain(other);
            for (_, [a, b]) in self.knots(d).spans() {
                let mut longest = 0.0_f64;
                for s in [0.0, 0.5, 1.0] {
                    let t = across.lerp(s);
                    let (p, q) = match d {
                        Direction::U => (crisp.eval(a, t), crisp.eval(b, t)),
                        Direction::V => (crisp.eval(t, a), crisp.eval(t, b)),
                    };
                    if let (Ok(p), Ok(q)) = (p, q) {
                        longest = longest.max((q[0] - p[0]).hypot(q[1] - p[1]));
                    }
                }
                if longest > 0.0 {
                    shortest = shortest.min(longest);
                }
            }
        }
        let cell = shortest / CONTOUR_CELLS_PER_SPAN as f64;
        let cells = |length: f64| {
            let n = (length / cell).ceil();
            if n.is_finite() && n >= 0.0 {
                (n.min(MAX_CONTOUR_CELLS as f64) as usize)
                    .clamp(MIN_CONTOUR_CELLS, MAX_CONTOUR_CELLS)
            } else {
                MAX_CONTOUR_CELLS
            }
        };
        [cells(extent[2] - extent[0]), cells(extent[3] - extent[1])]
    }

    /// The fuzzy contour at height `z` on `grid` at `levels`: per level and
    /// membership function, the plan points where a surface whose control
    /// points lie inside their cuts can cross `z`, as the union of the
    /// grid's cells whose envelope interval contains `z` (grown as the
    /// module [`crate::set`] and docs/method.md §13 say), and the crisp
    /// surface's contour at `z`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if `z` is not finite; the errors of
    /// [`FuzzySurface::envelope`] for a grid of one more corner each way; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    ///
    /// # Examples
    /// A plane rising along x from 0 to 2, its heights `±0.5` wide at level
    /// 0: the band of `z = 1` at level 0 runs from `x = 0.5` to `1.5`.
    /// ```
    /// # use t2spline::{Alpha, FuzzySurface, Membership, Nt2Number, Nt2Point};
    /// # use t2spline::set::PlanGrid;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let z = |z: f64| Nt2Number::try_new(z, [z - 0.5, z + 0.5], [z - 0.25, z + 0.25], [z, z], 1.0);
    /// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([c(x)?, c(y)?, z(x)?]));
    /// let net = vec![vec![p(0.0, 0.0)?, p(0.0, 1.0)?], vec![p(2.0, 0.0)?, p(2.0, 1.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let grid = PlanGrid::try_new([0.0, 0.0, 2.0, 1.0], [40, 20])?;
    /// let contour = s.contour(&grid, 1.0, &[Alpha::ZERO])?;
    /// let band = contour.levels[0].get(Membership::Upper).unwrap();
    /// assert!(band.contains([0.6, 0.5]) && band.contains([1.4, 0.5]));
    /// assert!(!band.contains([0.3, 0.5]) && !band.contains([1.7, 0.5]));
    /// assert_eq!(contour.crisp.len(), 1); // the line x = 1
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn contour(&self, grid: &PlanGrid, z: f64, levels: &[Alpha]) -> Result<Contour, Error> {
        self.crisp_weights_for("a contour")?;
        if !z.is_finite() {
            return Err(Error::NotFinite {
                place: Place::NONE,
                what: "contour height",
                value: z,
            });
        }
        let [nx, ny] = grid.shape();
        let [x0, y0, x1, y1] = grid.extent();
        let xs = corners(x0, x1, nx);
        let ys = corners(y0, y1, ny);
        // One more level, 1, whose upper cut is the crisp height.
        let mut asked = levels.to_vec();
        asked.push(Alpha::try_new(1.0)?);
        let mut envelope = self.envelope_on_axes(&xs, &ys, &asked)?;
        let top = envelope.pop();
        let crisp = top
            .as_ref()
            .and_then(|t| t.upper.as_ref())
            .map(|b| lines::contour_lines(&b.least, &xs, &ys, z))
            .unwrap_or_default();
        let [dx, dy] = grid.cell_size();
        let tolerance = dx.hypot(dy);
        let mut height_tolerance = 0.0_f64;
        let mut keeps: Vec<[Option<Vec<bool>>; 3]> = envelope
            .iter()
            .map(|level| {
                MEMBERSHIPS.map(|m| {
                    level.get(m).map(|b| {
                        let (keep, widened) = cells::band_cells(&b.least, &b.greatest, [nx, ny], z);
                        height_tolerance = height_tolerance.max(widened);
                        keep
                    })
                })
            })
            .collect();
        cells::nest(
            &mut keeps,
            &envelope.iter().map(|l| l.alpha).collect::<Vec<_>>(),
        );
        let levels = envelope
            .iter()
            .zip(keeps)
            .map(|(level, keep)| {
                let [upper, primary, lower] =
                    keep.map(|k| k.map(|k| Region::new(cells::trace(&k, &xs, &ys), tolerance)));
                ContourLevel {
                    alpha: level.alpha,
                    upper,
                    primary,
                    lower,
                }
            })
            .collect();
        Ok(Contour {
            grid: grid.clone(),
            z,
            levels,
            crisp,
            tolerance,
            height_tolerance,
        })
    }
}

/// The `n + 1` corners `lo + k·(hi − lo)/n`, the first and the last moved
/// inwards by [`RIM`] of a cell: the plan extent of a surface is its bounding
/// box, which rounding may put an ulp outside the plan map's range, where
/// the envelope is NODATA and a whole row of cells would lose its corners.
fn corners(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let inset = RIM * (hi - lo) / n as f64;
    (0..=n)
        .map(|k| {
            if k == 0 {
                lo + inset
            } else if k == n {
                hi - inset
            } else {
                lo + (hi - lo) * (k as f64 / n as f64)
            }
        })
        .collect()
}

/// How far the outer corners of a contour grid lie inside its extent, in
/// cells.
const RIM: f64 = 1e-9;
