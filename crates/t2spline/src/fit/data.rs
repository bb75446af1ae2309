//! Fitting fuzzy data points of either dimension, or a net of them, into a job's model, with a
//! summary of what the fit found that needs no dimension.

use crate::error::Error;
use crate::fuzzy::{Axis, Height, Layers, Nt2Point};
use crate::job::Model;
use crate::pipeline::FuzzyCurve;

use super::{
    fit_fuzzy, fit_fuzzy_surface, Deviation, FitOptions, FuzzyFit, FuzzyFitMode, FuzzySurfaceFit,
    OrderViolation, SurfaceFitOptions,
};

/// Fuzzy data points in the plane or in space, as a data file gives them.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum FuzzyData {
    /// Points with coordinates `x`, `y`.
    Planar(Vec<Nt2Point<2>>),
    /// Points with coordinates `x`, `y`, `z`.
    Spatial(Vec<Nt2Point<3>>),
    /// A net of points with coordinates `x`, `y`, `z`: rows along u, each
    /// row along v (`points[i][j]`, as a surface job's control points), all
    /// rows of one length.
    Net(Vec<Vec<Nt2Point<3>>>),
}

/// What a fit found, for a report: the same for every dimension.
#[derive(Clone, Debug, PartialEq)]
pub struct FitSummary {
    /// Number of data points.
    pub data_points: usize,
    /// Number of control points of the curve.
    pub control_points: usize,
    /// How the layers were fitted.
    pub mode: FuzzyFitMode,
    /// The estimated condition number of the fitting system.
    pub condition: f64,
    /// For each layer, the largest distance between its curve and its data at
    /// the data parameters.
    pub deviations: Layers<Deviation>,
    /// For each layer, the largest distance between its fitted spread
    /// `layer − crisp` and the data's, at the data parameters.
    pub spread_deviations: Layers<Deviation>,
    /// Where fitting each layer on its own breaks the order of docs/method.md §1.
    pub independent_violations: Vec<OrderViolation>,
    /// For a net (a surface): the stations and the control points in u and
    /// in v. Data points, control points and deviations then count row by
    /// row.
    pub net: Option<NetCounts>,
    /// Coordinates whose data mix lower heights, with the (smallest) height
    /// given to the control points.
    pub mixed_heights: Vec<(Axis, Height)>,
    /// For a closed curve: its loop. `control_points` then counts the
    /// distinct control points (the curve repeats the first `p` at its end).
    pub closed: Option<LoopCounts>,
}

/// The loop of a closed fit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LoopCounts {
    /// The distinct data points around the loop.
    pub data: usize,
    /// Whether the data's last point repeated the first and was taken as it.
    pub repeated_last: bool,
    /// The control points the curve repeats at its end: its degree `p`.
    pub wrap: usize,
}

/// The shape of a fitted net: stations and control points in u and in v.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NetCounts {
    /// Rows and columns of the data net.
    pub data: [usize; 2],
    /// Control points in u and in v.
    pub control: [usize; 2],
}

/// The outcome of fitting fuzzy data: the summary, and the fitted fuzzy curve
/// or the places where its control points are not valid fuzzy numbers (only
/// with [`FuzzyFitMode::Independent`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FitOutcome {
    /// What the fit found.
    pub summary: FitSummary,
    /// The fitted fuzzy curve, or every broken inequality of docs/method.md §1.
    pub model: Result<Model, Vec<OrderViolation>>,
}

impl FuzzyData {
    /// The number of data points (of a net: all of its points, rows × columns).
    #[must_use]
    pub fn len(&self) -> usize {
        match self {
            FuzzyData::Planar(p) => p.len(),
            FuzzyData::Spatial(p) => p.len(),
            FuzzyData::Net(rows) => rows.iter().map(Vec::len).sum(),
        }
    }

    /// The number of distinct data points of a curve taken as a loop: all
    /// of them, or all but the last when its crisp values repeat the first's
    /// ([`FitOptions::closed`]); of a net, all of its points.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::FuzzyData;
    /// # use t2spline::{Nt2Number, Nt2Point};
    /// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([Nt2Number::try_crisp(x)?, Nt2Number::try_crisp(y)?]));
    /// let square = vec![p(0.0, 0.0)?, p(1.0, 0.0)?, p(1.0, 1.0)?, p(0.0, 1.0)?];
    /// assert_eq!(FuzzyData::Planar(square.clone()).loop_len(), 4);
    /// let again = square.into_iter().chain([p(0.0, 0.0)?]).collect();
    /// assert_eq!(FuzzyData::Planar(again).loop_len(), 4);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn loop_len(&self) -> usize {
        fn crisp<const D: usize>(p: &[Nt2Point<D>]) -> usize {
            let q: Vec<[f64; D]> = p.iter().map(Nt2Point::crisp).collect();
            super::curve::loop_length(&q)
        }
        match self {
            FuzzyData::Planar(p) => crisp(p),
            FuzzyData::Spatial(p) => crisp(p),
            FuzzyData::Net(_) => self.len(),
        }
    }

    /// Whether there are no data points.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Fits a fuzzy curve to the data ([`fit_fuzzy`]).
    ///
    /// # Errors
    /// The errors of [`fit_fuzzy`]: too few points, coincident neighbours,
    /// a singular or ill-conditioned system, a control value beyond the
    /// limit of coordinates ([`Error::FitBeyondLimit`]), and so on.
    /// [`Error::Length`] for a net ([`FuzzyData::Net`]): a net is fitted by
    /// the surface fit, not as a curve.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::{FitOptions, FuzzyData, FuzzyFitMode};
    /// # use t2spline::{Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.2, c + 0.2], 0.5);
    /// let data = FuzzyData::Planar(vec![
    ///     Nt2Point::new([n(0.0)?, n(0.0)?]),
    ///     Nt2Point::new([n(1.0)?, n(2.0)?]),
    ///     Nt2Point::new([n(2.0)?, n(1.0)?]),
    /// ]);
    /// let outcome = data.fit(&FitOptions::interpolation(2)?, FuzzyFitMode::Valid)?;
    /// assert_eq!(outcome.summary.control_points, 3);
    /// assert_eq!(outcome.model.expect("valid by construction").control_point_count(), 3);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    ///
    /// A net is fitted with these options in both directions; [`FuzzyData::fit_net`]
    /// takes the degrees and control points of each.
    pub fn fit(&self, options: &FitOptions, mode: FuzzyFitMode) -> Result<FitOutcome, Error> {
        match self {
            FuzzyData::Planar(p) => outcome(p.len(), &fit_fuzzy(p, options, mode)?, Model::Planar),
            FuzzyData::Spatial(p) => {
                outcome(p.len(), &fit_fuzzy(p, options, mode)?, Model::Spatial)
            }
            FuzzyData::Net(_) if options.is_closed() => Err(Error::ClosedSurfaceFit),
            FuzzyData::Net(_) => self.fit_net(
                &SurfaceFitOptions::new(
                    [options.degree(); 2],
                    options.control_points().map(|n| [n; 2]),
                )?
                .with_parametrization(options.parametrization()),
                mode,
            ),
        }
    }

    /// Fits a fuzzy surface to a net ([`fit_fuzzy_surface`]), or a fuzzy
    /// curve to points with the options of u.
    ///
    /// # Errors
    /// The errors of [`fit_fuzzy_surface`] (or [`fit_fuzzy`]).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::{FuzzyData, FuzzyFitMode, SurfaceFitOptions};
    /// # use t2spline::{Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.2, c + 0.2], 0.5);
    /// let net = (0..3)
    ///     .map(|i| (0..4).map(|j| Ok(Nt2Point::new([n(i as f64)?, n(j as f64)?, n(0.0)?]))).collect())
    ///     .collect::<Result<Vec<Vec<_>>, t2spline::Error>>()?;
    /// let outcome = FuzzyData::Net(net).fit_net(&SurfaceFitOptions::interpolation([2, 3])?, FuzzyFitMode::Valid)?;
    /// assert_eq!(outcome.summary.net.map(|n| n.control), Some([3, 4]));
    /// assert_eq!(outcome.model.expect("valid by construction").control_point_count(), 12);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn fit_net(
        &self,
        options: &SurfaceFitOptions,
        mode: FuzzyFitMode,
    ) -> Result<FitOutcome, Error> {
        let curve = FitOptions::new(
            options.degree()[0],
            options.control_points().map(|[n, _]| n),
        )?
        .with_parametrization(options.parametrization());
        match self {
            FuzzyData::Planar(_) | FuzzyData::Spatial(_) => self.fit(&curve, mode),
            FuzzyData::Net(rows) => net_outcome(rows, &fit_fuzzy_surface(rows, options, mode)?),
        }
    }
}

/// The coordinates whose data mix lower heights, with the height given.
fn mixed<const D: usize>(mixed: [bool; D], heights: [Height; D]) -> Vec<(Axis, Height)> {
    Axis::of::<D>()
        .into_iter()
        .zip(mixed.into_iter().zip(heights))
        .filter(|(_, (mixed, _))| *mixed)
        .map(|(axis, (_, h))| (axis, h))
        .collect()
}

fn outcome<const D: usize>(
    data_points: usize,
    fit: &FuzzyFit<D>,
    model: impl FnOnce(FuzzyCurve<D>) -> Model,
) -> Result<FitOutcome, Error> {
    let mixed_heights = mixed(fit.mixed_heights(), fit.heights());
    let model = match fit.to_curve() {
        Ok(curve) => Ok(model(curve)),
        Err(Error::UnorderedFit { .. }) => Err(fit.violations()),
        // Any other reason is named as it is, never as broken orders.
        Err(e) => return Err(e),
    };
    Ok(FitOutcome {
        summary: FitSummary {
            data_points,
            control_points: fit.distinct_control_points(),
            mode: fit.mode(),
            condition: fit.condition(),
            deviations: *fit.deviations(),
            spread_deviations: *fit.spread_deviations(),
            independent_violations: fit.independent_violations().to_vec(),
            mixed_heights,
            net: None,
            closed: fit.is_closed().then(|| LoopCounts {
                data: fit.params().len(),
                repeated_last: fit.repeated_last(),
                wrap: fit.knots().count() - fit.distinct_control_points(),
            }),
        },
        model,
    })
}

fn net_outcome(rows: &[Vec<Nt2Point<3>>], fit: &FuzzySurfaceFit) -> Result<FitOutcome, Error> {
    let mixed_heights = mixed(fit.mixed_heights(), fit.heights());
    let model = match fit.to_surface() {
        Ok(surface) => Ok(Model::Surface(surface)),
        Err(Error::UnorderedFit { .. }) => Err(fit.violations()),
        Err(e) => return Err(e),
    };
    let control = fit.counts();
    Ok(FitOutcome {
        summary: FitSummary {
            data_points: rows.iter().map(Vec::len).sum(),
            control_points: control[0] * control[1],
            mode: fit.mode(),
            condition: fit.condition(),
            deviations: *fit.deviations(),
            spread_deviations: *fit.spread_deviations(),
            independent_violations: fit.independent_violations().to_vec(),
            mixed_heights,
            closed: None,
            net: Some(NetCounts {
                data: [rows.len(), rows.first().map_or(0, Vec::len)],
                control,
            }),
        },
        model,
    })
}
