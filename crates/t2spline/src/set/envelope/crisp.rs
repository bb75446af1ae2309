//! The exact envelope of a surface with crisp x and y: per plan point the
//! rational basis at its parameters, four sums per function, and per level
//! the two ends (module docs of `envelope`).
//!
//! For function `m` and the height's cut ends `leftᵢ(alpha) = Lᵢ + alpha·Gᵢ`
//! and `rightᵢ(alpha) = Rᵢ − alpha·G'ᵢ` (`cut_lines.rs`):
//!
//! ```text
//! least(alpha)    = Σ Rᵢ·Lᵢ + alpha·Σ Rᵢ·Gᵢ
//! greatest(alpha) = Σ Rᵢ·Rᵢ − alpha·Σ Rᵢ·G'ᵢ
//! ```
//! valid while `alpha` is at most the least top of the points acting there.

use super::bounds::{EnvelopeLevel, Gathered};
use super::plan_grid::PlanGrid;
use crate::fuzzy::Alpha;
use crate::nurbs::surface::TensorBasis;
use crate::nurbs::Direction;
use crate::pipeline::FuzzySurface;
use crate::set::cut_lines::{CutLines, MEMBERSHIPS};
use crate::set::envelope::plan_map::{Separable, Table};

/// Per function, the sums `[Σ R·L, Σ R·G, Σ R·R, Σ R·G']` at a point.
type Sums = [[f64; 4]; 3];

/// The heights' cut ends of every control point, all three functions.
struct HeightLines {
    /// `ends[i][k]`: point `i`, function `k`: `[L, G, R, G']`.
    ends: Vec<Sums>,
    /// `top[i][k]`: the top of point `i` under function `k`.
    top: Vec<[f64; 3]>,
    /// Per function, the largest top of a span rectangle: above it the
    /// function has no cut anywhere.
    present: [f64; 3],
}

impl HeightLines {
    fn of(s: &FuzzySurface<3>) -> Self {
        let lines = MEMBERSHIPS.map(|m| CutLines::of(s.points(), m));
        let n = s.points().len();
        let ends = (0..n)
            .map(|i| {
                [0, 1, 2].map(|k| {
                    let e = lines[k].ends[i][2];
                    [e.foot_left, e.slope_left, e.foot_right, e.slope_right]
                })
            })
            .collect();
        let top: Vec<[f64; 3]> = (0..n).map(|i| [0, 1, 2].map(|k| lines[k].top[i])).collect();
        let crisp = s.crisp_surface();
        let ([ku, kv], nv) = (crisp.order(), s.shape()[1]);
        let mut present = [f64::NEG_INFINITY; 3];
        for ([su, sv], _) in crisp.patches() {
            let mut least = [1.0_f64; 3];
            for i in su + 1 - ku..=su {
                for j in sv + 1 - kv..=sv {
                    for (l, t) in least.iter_mut().zip(top[i * nv + j]) {
                        *l = l.min(t);
                    }
                }
            }
            for (p, l) in present.iter_mut().zip(least) {
                *p = p.max(l);
            }
        }
        HeightLines { ends, top, present }
    }

    fn gathered(&self, n: usize, levels: &[Alpha]) -> Gathered {
        Gathered::new(n, levels, |k, alpha| alpha <= self.present[k])
    }
}

/// Adds `r·ends` into `sums` and lowers `top` to the point's.
#[inline]
fn add(sums: &mut Sums, top: &mut [f64; 3], r: f64, ends: &Sums, point_top: &[f64; 3]) {
    for ((s, e), (t, pt)) in sums.iter_mut().zip(ends).zip(top.iter_mut().zip(point_top)) {
        for (a, b) in s.iter_mut().zip(e) {
            *a += r * b;
        }
        *t = t.min(*pt);
    }
}

/// Records the ends at every level for point `cell`.
#[inline]
fn record(g: &mut Gathered, cell: usize, sums: &Sums, top: &[f64; 3]) {
    for (alpha, bounds) in &mut g.levels {
        let alpha = *alpha;
        for ((b, s), t) in bounds.iter_mut().zip(sums).zip(top) {
            let Some(b) = b else { continue };
            if alpha > *t {
                continue;
            }
            let (lo, hi) = (s[0] + alpha * s[1], s[2] - alpha * s[3]);
            let (l, h) = (&mut b.least[cell], &mut b.greatest[cell]);
            *l = l.min(lo);
            *h = h.max(hi);
        }
    }
}

/// The envelope at the cell centres of `grid`.
pub(crate) fn on_grid(
    s: &FuzzySurface<3>,
    grid: &PlanGrid,
    levels: &[Alpha],
) -> Vec<EnvelopeLevel> {
    on_axes(s, &grid.xs(), &grid.ys(), levels)
}

/// The envelope at the plan points `(xs[i], ys[j])`, row by row (`y`
/// outer), as [`on_grid`].
pub(crate) fn on_axes(
    s: &FuzzySurface<3>,
    xs: &[f64],
    ys: &[f64],
    levels: &[Alpha],
) -> Vec<EnvelopeLevel> {
    let crisp = s.crisp_surface();
    let Some(map) = Separable::of(&crisp) else {
        let points: Vec<[f64; 2]> = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| [x, y]))
            .collect();
        return at_points(s, &points, levels);
    };
    if !map.exact {
        return near_separable(s, &map, xs, ys, levels);
    }
    let lines = HeightLines::of(s);
    let nx = xs.len();
    let mut g = lines.gathered(nx * ys.len(), levels);
    // The direction of the grid's rows (y) and of its columns (x).
    let (row_axis, column_axis) = if map.x_along_u { (1, 0) } else { (0, 1) };
    let [nu, nv] = s.shape();
    let orders = [s.degree()[0] + 1, s.degree()[1] + 1];
    let columns: Vec<Option<(usize, Vec<f64>)>> = xs
        .iter()
        .map(|&x| {
            map.axes[column_axis].invert(x).map(|t| {
                let mut b = vec![0.0; orders[column_axis]];
                let first = map.axes[column_axis].basis(t, &mut b);
                (first, b)
            })
        })
        .collect();
    // Lines of the net along the row direction, contracted per grid row.
    let count = [nu, nv][column_axis];
    let mut contracted: Vec<(Sums, [f64; 3])> = vec![([[0.0; 4]; 3], [1.0; 3]); count];
    let mut rb = vec![0.0; orders[row_axis]];
    for (j, &y) in ys.iter().enumerate() {
        let Some(t) = map.axes[row_axis].invert(y) else {
            continue;
        };
        let first = map.axes[row_axis].basis(t, &mut rb);
        for (c, (sums, top)) in contracted.iter_mut().enumerate() {
            *sums = [[0.0; 4]; 3];
            *top = [1.0; 3];
            for (a, &r) in rb.iter().enumerate() {
                let k = if map.x_along_u {
                    c * nv + first + a
                } else {
                    (first + a) * nv + c
                };
                add(sums, top, r, &lines.ends[k], &lines.top[k]);
            }
        }
        for (i, column) in columns.iter().enumerate() {
            let Some((first, cb)) = column else { continue };
            let mut sums = [[0.0; 4]; 3];
            let mut top = [1.0; 3];
            for (r, (e, t)) in cb.iter().zip(&contracted[*first..]) {
                add(&mut sums, &mut top, *r, e, t);
            }
            record(&mut g, j * nx + i, &sums, &top);
        }
    }
    g.finish()
}

/// The envelope at any plan points, by the general inversion of the plan map.
pub(crate) fn at_points(
    s: &FuzzySurface<3>,
    points: &[[f64; 2]],
    levels: &[Alpha],
) -> Vec<EnvelopeLevel> {
    let crisp = s.crisp_surface();
    let lines = HeightLines::of(s);
    let mut g = lines.gathered(points.len(), levels);
    let table = Table::new(&crisp);
    let knots = [s.knots(Direction::U).clone(), s.knots(Direction::V).clone()];
    let nv = s.shape()[1];
    for (cell, &p) in points.iter().enumerate() {
        for [u, v] in table.preimages(p) {
            let basis = TensorBasis::new(&knots, s.weights(), u, v);
            let mut sums = [[0.0; 4]; 3];
            let mut top = [1.0; 3];
            basis.for_each(nv, |k, r| {
                add(&mut sums, &mut top, r, &lines.ends[k], &lines.top[k])
            });
            record(&mut g, cell, &sums, &top);
        }
    }
    g.finish()
}

/// The envelope on a grid of a net separable to within rounding: each
/// cell's parameters start from the separable map's inversion and are
/// polished by Newton's method on the true map (any cell where that fails is
/// solved as a plan point of any map).
fn near_separable(
    s: &FuzzySurface<3>,
    map: &Separable,
    xs: &[f64],
    ys: &[f64],
    levels: &[Alpha],
) -> Vec<EnvelopeLevel> {
    let crisp = s.crisp_surface();
    let lines = HeightLines::of(s);
    let nx = xs.len();
    let mut g = lines.gathered(nx * ys.len(), levels);
    let table = Table::new(&crisp);
    let knots = [s.knots(Direction::U).clone(), s.knots(Direction::V).clone()];
    let nv = s.shape()[1];
    let (row_axis, column_axis) = if map.x_along_u { (1, 0) } else { (0, 1) };
    let columns: Vec<Option<f64>> = xs
        .iter()
        .map(|&x| map.axes[column_axis].invert(x))
        .collect();
    for (j, &y) in ys.iter().enumerate() {
        let row = map.axes[row_axis].invert(y);
        for (i, (&x, column)) in xs.iter().zip(&columns).enumerate() {
            let start = row
                .zip(*column)
                .map(|(r, c)| if map.x_along_u { [c, r] } else { [r, c] });
            let found = match start.and_then(|uv| table.newton(uv, [x, y])) {
                Some(uv) => vec![uv],
                None => table.preimages([x, y]),
            };
            for [u, v] in found {
                let basis = TensorBasis::new(&knots, s.weights(), u, v);
                let mut sums = [[0.0; 4]; 3];
                let mut top = [1.0; 3];
                basis.for_each(nv, |k, r| {
                    add(&mut sums, &mut top, r, &lines.ends[k], &lines.top[k])
                });
                record(&mut g, j * nx + i, &sums, &top);
            }
        }
    }
    g.finish()
}
