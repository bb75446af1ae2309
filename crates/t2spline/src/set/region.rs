//! The alpha-region of a 2-D fuzzy curve as polygons, and the projections of
//! a 3-D curve's region onto the coordinate planes (docs/method.md §10).

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::{FloatOverlay, OverlayOptions};

use crate::error::Error;
use crate::fuzzy::{Alpha, Membership};
use crate::pipeline::FuzzyCurve;
use crate::set::polygon::{Polygon, Region};
use crate::set::sweep::{hull_of, Sweep, TooManyBoxes};

/// The finest tolerance allowed, relative to the size of the region's box:
/// each polygon union rounds to an integer grid of about 2³⁰ steps per side,
/// and the outline goes through a dozen of them.
pub const LEAST_RELATIVE_TOLERANCE: f64 = 1e-7;
/// The default tolerance, relative to the diagonal of the crisp control
/// points' bounding box.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-6;

/// A coordinate plane: the two axes a region of a 3-D curve is projected on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Plane {
    /// x and y (a 2-D curve's own plane).
    Xy,
    /// x and z.
    Xz,
    /// y and z.
    Yz,
}

impl Plane {
    /// The three planes, in order.
    pub const ALL: [Plane; 3] = [Plane::Xy, Plane::Xz, Plane::Yz];

    /// The indices of the two coordinates.
    #[must_use]
    pub fn axes(self) -> [usize; 2] {
        match self {
            Plane::Xy => [0, 1],
            Plane::Xz => [0, 2],
            Plane::Yz => [1, 2],
        }
    }

    /// `"xy"`, `"xz"` or `"yz"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Plane::Xy => "xy",
            Plane::Xz => "xz",
            Plane::Yz => "yz",
        }
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// The default tolerance of region outlines: 1e-6 of the diagonal of the
    /// crisp control points' bounding box (of the upper feet' box if the
    /// crisp points coincide, 1e-6 if that too is a point).
    #[must_use]
    pub fn default_tolerance(&self) -> f64 {
        let diagonal = |pick: &dyn Fn(&crate::Nt2Number) -> [f64; 2]| {
            let mut lo = [f64::INFINITY; D];
            let mut hi = [f64::NEG_INFINITY; D];
            for p in self.points() {
                for (c, x) in p.coords().iter().enumerate() {
                    let [a, b] = pick(x);
                    lo[c] = lo[c].min(a);
                    hi[c] = hi[c].max(b);
                }
            }
            lo.iter()
                .zip(&hi)
                .map(|(l, h)| (h - l).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let crisp = diagonal(&|x| [x.crisp(), x.crisp()]);
        let feet = diagonal(&|x| [x.upper().left(), x.upper().right()]);
        let d = if crisp > 0.0 { crisp } else { feet };
        if d > 0.0 && d.is_finite() {
            DEFAULT_RELATIVE_TOLERANCE * d
        } else {
            DEFAULT_RELATIVE_TOLERANCE
        }
    }

    /// The largest level at which `membership` has a cut everywhere on some
    /// part of the curve: 1 for the upper and primary functions, the largest
    /// height among the knot spans' least heights for the lower.
    #[must_use]
    pub fn membership_top(&self, membership: Membership) -> f64 {
        let lines = crate::set::cut_lines::CutLines::of(self.points(), membership);
        let p = self.degree();
        self.knots()
            .spans()
            .map(|(span, _)| lines.top_of(span - p, p + 1))
            .fold(0.0_f64, f64::max)
    }

    /// The projection onto `plane` of the region of `membership` at `alpha`:
    /// the set of places some curve with control points inside their cuts
    /// passes through (docs/method.md §10), as polygons with holes. `None`
    /// when the function has no cut at `alpha` anywhere on the curve (the
    /// lower function above every height).
    ///
    /// The outline is within `tolerance` of the true region (`None`: the
    /// [default](FuzzyCurve::default_tolerance)): the region is the union of
    /// the curve's boxes, sampled in the parameter until the sweep between
    /// neighbours is their convex hull to a quarter of the tolerance; each
    /// hull is grown by a quarter of the tolerance, so the polygons hold
    /// the true region and lie within the tolerance of it; the union is
    /// `i_overlay`'s (an OGC-valid set of polygons). A region without area
    /// (crisp numbers, or the upper function at alpha 1) is a band of the
    /// tolerance's width around the curve.
    ///
    /// # Errors
    /// [`Error::Tolerance`] if `tolerance` is not finite, or below
    /// [`LEAST_RELATIVE_TOLERANCE`] of the region's size, or so fine that
    /// the curve needs more than four million boxes; [`Error::Index`]
    /// if `plane` names a coordinate the curve does not have.
    pub fn region_in(
        &self,
        plane: Plane,
        membership: Membership,
        alpha: Alpha,
        tolerance: Option<f64>,
    ) -> Result<Option<Region>, Error> {
        self.crisp_weights_for("a region")?;
        let axes = plane.axes();
        if axes[1] >= D {
            return Err(Error::Index {
                what: "coordinate",
                index: axes[1],
                count: D,
            });
        }
        let tolerance = self.checked_tolerance(axes, tolerance)?;
        let least = self.least_tolerance(axes);
        let quarter = 0.25 * tolerance;
        let sweep =
            Sweep::of(self, membership, alpha.get(), axes, quarter).map_err(|TooManyBoxes| {
                Error::Tolerance {
                    value: tolerance,
                    least: least.max(tolerance * 2.0),
                }
            })?;
        if sweep.runs.is_empty() {
            return Ok(None);
        }
        let mut shapes: Vec<Vec<[f64; 2]>> = Vec::new();
        for run in &sweep.runs {
            if run.len() == 1 {
                shapes.push(hull_of(&run[0], &run[0], quarter));
            }
            for w in run.windows(2) {
                shapes.push(hull_of(&w[0], &w[1], quarter));
            }
        }
        let chunks: Vec<&[Vec<[f64; 2]>]> = shapes.chunks(LEAF).collect();
        let leaves = each(&chunks, |hulls| {
            FloatOverlay::with_subj_custom(hulls, overlay_options(), Default::default())
                .overlay(OverlayRule::Subject, FillRule::NonZero)
        });
        let union = union_tree(leaves);
        let polygons = union.into_iter().filter_map(Polygon::from_rings).collect();
        Ok(Some(Region::new(polygons, tolerance)))
    }

    /// `tolerance`, or the default, checked for an outline in the plane of
    /// `axes`: positive, at least [`FuzzyCurve::least_tolerance`], and at
    /// most the box that holds every region (its largest side, or where
    /// that box is a point the largest coordinate's magnitude).
    pub(crate) fn checked_tolerance(
        &self,
        axes: [usize; 2],
        tolerance: Option<f64>,
    ) -> Result<f64, Error> {
        let tolerance = tolerance.unwrap_or_else(|| self.default_tolerance());
        let least = self.least_tolerance(axes);
        if !(tolerance.is_finite() && tolerance > 0.0 && tolerance >= least) {
            return Err(Error::Tolerance {
                value: tolerance,
                least,
            });
        }
        let extent = self.footprint_extent(axes);
        let most = if extent > 0.0 {
            extent
        } else {
            self.points()
                .iter()
                .flat_map(|p| axes.map(|c| p.coords()[c].crisp().abs()))
                .fold(f64::MIN_POSITIVE, f64::max)
        };
        if tolerance > most {
            return Err(Error::ToleranceTooCoarse {
                value: tolerance,
                most,
            });
        }
        Ok(tolerance)
    }

    /// The finest tolerance of an outline in the plane of `axes`:
    /// [`LEAST_RELATIVE_TOLERANCE`] of the largest side of the box of the
    /// upper cuts at level 0.
    pub(crate) fn least_tolerance(&self, axes: [usize; 2]) -> f64 {
        LEAST_RELATIVE_TOLERANCE * self.footprint_extent(axes)
    }

    /// The largest side of the box of the upper cuts at level 0 in the two
    /// coordinates `axes` (which holds every region).
    fn footprint_extent(&self, axes: [usize; 2]) -> f64 {
        axes.iter()
            .map(|&c| {
                let (lo, hi) =
                    self.points()
                        .iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                            let u = p.coords()[c].upper();
                            (lo.min(u.left()), hi.max(u.right()))
                        });
                hi - lo
            })
            .fold(0.0_f64, f64::max)
    }
}

/// Neighbouring hulls united in one pass before the pairwise unions.
const LEAF: usize = 16;

/// OGC-valid output (holes apart from their exterior, no self-touching rings).
pub(crate) fn overlay_options() -> OverlayOptions<f64> {
    OverlayOptions {
        ogc: true,
        ..OverlayOptions::default()
    }
}

/// Polygons as `i_overlay` gives them: shapes of rings, the first the exterior.
type Shapes = Vec<Vec<Vec<[f64; 2]>>>;

/// The union of `parts`, in the order given, by pairs: the hulls of
/// neighbouring boxes overlap almost entirely, so one union of all of them
/// would meet every edge with every other (quadratic in their number), while
/// the union of two neighbouring pieces meets only their outlines. The pairs
/// of one round are united on rayon's threads (feature `parallel`); the
/// pairs, and so the result, are the same on one thread.
fn union_tree(mut parts: Vec<Shapes>) -> Shapes {
    let options = overlay_options();
    while parts.len() > 1 {
        let odd = if parts.len() % 2 == 1 {
            parts.pop()
        } else {
            None
        };
        let pairs: Vec<&[Shapes]> = parts.chunks(2).collect();
        let mut next = each(&pairs, |pair| match pair {
            [a, b] => FloatOverlay::with_subj_and_clip_custom(a, b, options, Default::default())
                .overlay(OverlayRule::Union, FillRule::NonZero),
            _ => Shapes::new(),
        });
        next.extend(odd);
        parts = next;
    }
    parts.pop().unwrap_or_default()
}

/// `f` of every item, in order: on rayon's threads with the feature
/// `parallel`, else one after the other.
fn each<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync + Send) -> Vec<R> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        items.par_iter().map(f).collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        items.iter().map(f).collect()
    }
}

impl FuzzyCurve<2> {
    /// The region of `membership` at `alpha` of a plane curve; see
    /// [`FuzzyCurve::region_in`].
    ///
    /// # Errors
    /// As [`FuzzyCurve::region_in`].
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Membership, Nt2Number, Nt2Point};
    /// // A segment whose ends may move ±1 in x and y at level 0 (upper cut).
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c, c], 1.0);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(4.0)?, n(0.0)?])];
    /// let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let r = line.region(Membership::Upper, Alpha::ZERO, Some(1e-6))?.unwrap();
    /// // The boxes [t·4 − 1, t·4 + 1] × [−1, 1] sweep the rectangle [−1, 5] × [−1, 1].
    /// assert!((r.area() - 12.0).abs() < 1e-4);
    /// assert!(r.contains([4.9, 0.9]) && !r.contains([5.1, 0.0]));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn region(
        &self,
        membership: Membership,
        alpha: Alpha,
        tolerance: Option<f64>,
    ) -> Result<Option<Region>, Error> {
        self.region_in(Plane::Xy, membership, alpha, tolerance)
    }
}

impl FuzzyCurve<3> {
    /// The region's projections onto the planes xy, xz and yz; see
    /// [`FuzzyCurve::region_in`].
    ///
    /// # Errors
    /// As [`FuzzyCurve::region_in`].
    pub fn region_projections(
        &self,
        membership: Membership,
        alpha: Alpha,
        tolerance: Option<f64>,
    ) -> Result<[Option<Region>; 3], Error> {
        let [a, b, c] = Plane::ALL.map(|p| self.region_in(p, membership, alpha, tolerance));
        Ok([a?, b?, c?])
    }
}
