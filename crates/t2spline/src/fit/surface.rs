//! Fitting a crisp B-spline surface to a net of data points: global
//! interpolation (The NURBS Book §9.2.5, Algorithm A9.4) and least squares
//! with the boundary curves' end points interpolated (§9.4.3, Algorithm A9.7).

use crate::error::Error;
use crate::fit::curve::check_finite;
use crate::fit::net::{NetDesign, SurfaceFitOptions};
use crate::nurbs::NurbsSurface;

/// A fitted crisp surface and the parameters its data got.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFit {
    /// The surface: weights 1, clamped knots on `[0, 1]²`.
    pub surface: NurbsSurface<3>,
    /// The parameters `[ū, v̄]` of the net's rows and columns.
    pub params: [Vec<f64>; 2],
    /// The larger of the two directions' estimated condition numbers.
    pub condition: f64,
}

/// Fits a B-spline surface (all weights 1) to the net `net[k][l]` (`k` along
/// u, `l` along v, every row as long).
///
/// ```text
/// interpolation:  S(ū_k, v̄_l) = Q_kl for every k, l                          (A9.4)
/// least squares:  per column, then per row of the intermediate points, the
///                 curve fit of §9.4.1 (end points interpolated)               (A9.7)
/// ```
/// The parameters are averaged over the lines of the net (A9.3, see
/// [`SurfaceFitOptions`]); each pass is the curve fit of
/// [`fit_curve`](crate::fit::fit_curve) with its banded Givens QR. Geomdl's
/// `approximate_surface` implements the same algorithm.
///
/// # Errors
/// As [`fit_curve`](crate::fit::fit_curve) in each direction, wrapped in
/// [`Error::InDirection`] (too few rows or columns for the degree, a control
/// point count outside its range, rows or columns at the same parameter);
/// [`Error::NetShape`] for rows of unequal length; [`Error::NotFinite`] for
/// a coordinate that is not finite; [`Error::FitBeyondLimit`] if a control
/// point lies beyond [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
///
/// # Examples
/// A bilinear patch sampled on a grid is reproduced by a quadratic
/// interpolant:
/// ```
/// # use t2spline::fit::{fit_surface, SurfaceFitOptions};
/// let net: Vec<Vec<[f64; 3]>> = (0..4)
///     .map(|i| (0..5).map(|j| { let (x, y) = (i as f64, j as f64); [x, y, 0.5 * x * y] }).collect())
///     .collect();
/// let fit = fit_surface(&net, &SurfaceFitOptions::interpolation([2, 2])?)?;
/// let [u, v] = &fit.params;
/// let p = fit.surface.eval(u[2], v[3])?;
/// assert!((p[0] - 2.0).abs() < 1e-12 && (p[1] - 3.0).abs() < 1e-12 && (p[2] - 3.0).abs() < 1e-12);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn fit_surface(
    net: &[Vec<[f64; 3]>],
    options: &SurfaceFitOptions,
) -> Result<SurfaceFit, Error> {
    for row in net {
        check_finite(row)?;
    }
    let directions = options.parameters_and_knots(net)?;
    let design = NetDesign::new(&directions)?;
    let control = design.fit(net)?;
    for row in &control {
        crate::fit::curve::check_within_limit(row, None)?;
    }
    let [nu, nv] = design.counts();
    let [(pu, ku), (pv, kv)] = directions;
    let surface = NurbsSurface::try_new(control, vec![vec![1.0; nv]; nu], [ku, kv])?;
    Ok(SurfaceFit {
        surface,
        params: [pu, pv],
        condition: design.condition(),
    })
}
