//! The numbers figures draw of the fuzzy curve as a set (docs/method.md
//! §10): alpha-regions per projection, membership maps and the section at a
//! station, each asked of the core's set view (`FuzzyCurve::region_in`,
//! `membership_grid`, `sections`, `memberships`). Plotting only draws them.

use t2spline::job::{Model, ModelVisitor};
use t2spline::set::{MembershipGrid, Plane, Region, SectionLevel};
use t2spline::{Alpha, FuzzyCurve, FuzzySurface, Membership};

use crate::error::Error;

/// The outline tolerance of regions in figures, relative to the diagonal of
/// the crisp control points' box (100 times the core's default): a page
/// draws that diagonal in about 700 pixels, so the outline is within a
/// tenth of a pixel, and the core samples far fewer boxes than at 1e-6.
pub const FIGURE_RELATIVE_TOLERANCE: f64 = 1e-4;

/// Cells along the longer side of a membership map: about two SVG units a
/// cell on a page, six pixels in a PNG.
pub const MAP_CELLS: usize = 240;

/// The regions figures shade at one level: per projection (in the order of
/// the figure's panels), the upper and the lower function's region, `None`
/// where the function has no cut at the level (the lower above its
/// heights).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Regions {
    /// The level.
    pub alpha: f64,
    /// The upper function's region per projection.
    pub upper: Vec<Option<Region>>,
    /// The lower function's region per projection.
    pub lower: Vec<Option<Region>>,
}

impl Regions {
    /// The region of `membership` (upper or lower) in projection `k`.
    #[must_use]
    pub fn get(&self, membership: Membership, k: usize) -> Option<&Region> {
        let list = match membership {
            Membership::Lower => &self.lower,
            _ => &self.upper,
        };
        list.get(k).and_then(Option::as_ref)
    }
}

/// The coordinate plane of a panel's axes `(i, j)`.
#[must_use]
pub fn plane_of((i, j): (usize, usize)) -> Plane {
    match (i, j) {
        (0, 2) => Plane::Xz,
        (1, 2) => Plane::Yz,
        _ => Plane::Xy,
    }
}

/// The figure tolerance of `curve`'s outlines.
fn tolerance<const D: usize>(curve: &FuzzyCurve<D>) -> f64 {
    curve.default_tolerance() / t2spline::set::DEFAULT_RELATIVE_TOLERANCE
        * FIGURE_RELATIVE_TOLERANCE
}

/// The upper and lower regions of a curve model at `alpha` in the planes of
/// `axes` (one per panel), at [`FIGURE_RELATIVE_TOLERANCE`]; empty lists for
/// a surface and for a curve with fuzzy weights.
///
/// # Errors
/// [`Error::Core`] if the core refuses the tolerance (never for a validated
/// job: it lies far above the least).
pub fn regions(model: &Model, alpha: Alpha, axes: &[(usize, usize)]) -> Result<Regions, Error> {
    struct Of<'a> {
        alpha: Alpha,
        axes: &'a [(usize, usize)],
    }
    impl ModelVisitor for Of<'_> {
        type Output = Result<Regions, Error>;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
            if c.weight_numbers().is_some() {
                // No regions with fuzzy weights yet (docs/method.md §16).
                return Ok(Regions {
                    alpha: self.alpha.get(),
                    ..Regions::default()
                });
            }
            let tol = tolerance(c);
            let of = |m: Membership| -> Result<Vec<Option<Region>>, Error> {
                self.axes
                    .iter()
                    .map(|&ij| Ok(c.region_in(plane_of(ij), m, self.alpha, Some(tol))?))
                    .collect()
            };
            Ok(Regions {
                alpha: self.alpha.get(),
                upper: of(Membership::Upper)?,
                lower: of(Membership::Lower)?,
            })
        }
        fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> Self::Output {
            Ok(Regions {
                alpha: self.alpha.get(),
                ..Regions::default()
            })
        }
    }
    model.visit(Of { alpha, axes })
}

/// The plane curve of a model, or [`Error::Planar`] for any other.
///
/// # Errors
/// [`Error::Planar`] for a space curve or a surface.
pub fn planar(model: &Model) -> Result<&FuzzyCurve<2>, Error> {
    match model {
        Model::Planar(c) => Ok(c),
        _ => Err(Error::Planar),
    }
}

/// The box of the upper region at level 0 (which holds every point of
/// non-zero grade), padded by 4 % of its larger side on every side; the box
/// of the control points' upper intervals if the region has no vertex (it
/// always has).
fn footprint_box(curve: &FuzzyCurve<2>) -> Result<[[f64; 2]; 2], Error> {
    let region = curve.region(Membership::Upper, Alpha::ZERO, Some(tolerance(curve)))?;
    let mut b = [[f64::INFINITY, f64::NEG_INFINITY]; 2];
    let add = |b: &mut [[f64; 2]; 2], p: [f64; 2]| {
        for c in 0..2 {
            b[c] = [b[c][0].min(p[c]), b[c][1].max(p[c])];
        }
    };
    for g in region.iter().flat_map(Region::polygons) {
        g.exterior.iter().for_each(|&p| add(&mut b, p));
    }
    if b[0][0] > b[0][1] || b[0][0].is_nan() {
        for p in curve.points() {
            let [x, y] = (*p.coords()).map(|n| n.upper());
            add(&mut b, [x.left(), y.left()]);
            add(&mut b, [x.right(), y.right()]);
        }
    }
    let pad = 0.04 * (b[0][1] - b[0][0]).max(b[1][1] - b[1][0]).max(1e-300);
    Ok(b.map(|[lo, hi]| [lo - pad, hi + pad]))
}

/// A membership map and the rectangle its cells tile.
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    /// The grades of the cell centres.
    pub grid: MembershipGrid,
    /// The range of x the columns tile.
    pub x: [f64; 2],
    /// The range of y the rows tile.
    pub y: [f64; 2],
}

impl Map {
    /// The width and height of one cell.
    #[must_use]
    pub fn cell(&self) -> [f64; 2] {
        [
            (self.x[1] - self.x[0]) / self.grid.xs.len().max(1) as f64,
            (self.y[1] - self.y[0]) / self.grid.ys.len().max(1) as f64,
        ]
    }
}

/// The membership maps of a plane curve on a grid over its footprint
/// ([`MAP_CELLS`] cells along the longer side, square cells), from the
/// core's `membership_grid`.
///
/// # Errors
/// As [`FuzzyCurve::membership_grid`] (never for a validated job).
pub fn membership_map(curve: &FuzzyCurve<2>) -> Result<Map, Error> {
    let [x, y] = footprint_box(curve)?;
    let (w, h) = (x[1] - x[0], y[1] - y[0]);
    let cell = w.max(h) / MAP_CELLS as f64;
    let count = |side: f64| ((side / cell).round() as usize).clamp(1, MAP_CELLS);
    let grid = curve.membership_grid(x, y, [count(w), count(h)])?;
    Ok(Map { grid, x, y })
}

/// The outlines of the regions of `membership` at `levels` (those where it
/// has a cut), as `(level, region)`.
///
/// # Errors
/// As [`regions`].
pub fn contours(
    curve: &FuzzyCurve<2>,
    membership: Membership,
    levels: &[f64],
) -> Result<Vec<(f64, Region)>, Error> {
    let tol = tolerance(curve);
    let mut out = Vec::new();
    for &a in levels {
        if let Some(r) = curve.region(membership, Alpha::try_new(a)?, Some(tol))? {
            out.push((a, r));
        }
    }
    Ok(out)
}

/// The section of a plane curve at `x0`: the intervals of every function at
/// each of `levels`, and the grades `(y, upper, primary, lower)` of the
/// points `(x0, y)` at `ys` (the membership functions of the fuzzy y).
///
/// # Errors
/// [`Error::Core`] if `x0` is not finite.
pub fn section(
    curve: &FuzzyCurve<2>,
    x0: f64,
    levels: &[Alpha],
    ys: &[f64],
) -> Result<(Vec<SectionLevel>, Vec<[f64; 4]>), Error> {
    let cuts = curve.sections(x0, levels, Some(tolerance(curve)))?;
    let points: Vec<[f64; 2]> = ys.iter().map(|&y| [x0, y]).collect();
    let grades = curve
        .memberships(&points)?
        .into_iter()
        .zip(ys)
        .map(|(g, &y)| [y, g.upper, g.primary, g.lower])
        .collect();
    Ok((cuts, grades))
}
