//! Fitting fuzzy data points of either dimension into a job's model, with a
//! summary of what the fit found that needs no dimension.

use crate::error::Error;
use crate::fuzzy::{Axis, Height, Layers, Nt2Point};
use crate::job::Model;
use crate::pipeline::FuzzyCurve;

use super::{fit_fuzzy, Deviation, FitOptions, FuzzyFit, FuzzyFitMode, OrderViolation};

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
    /// Coordinates whose data mix lower heights, with the (smallest) height
    /// given to the control points.
    pub mixed_heights: Vec<(Axis, Height)>,
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
    /// let outcome = data.fit(&FitOptions::interpolation(2), FuzzyFitMode::Valid)?;
    /// assert_eq!(outcome.summary.control_points, 3);
    /// assert_eq!(outcome.model.expect("valid by construction").control_point_count(), 3);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn fit(&self, options: &FitOptions, mode: FuzzyFitMode) -> Result<FitOutcome, Error> {
        match self {
            FuzzyData::Planar(p) => outcome(p.len(), &fit_fuzzy(p, options, mode)?, Model::Planar),
            FuzzyData::Spatial(p) => {
                outcome(p.len(), &fit_fuzzy(p, options, mode)?, Model::Spatial)
            }
            FuzzyData::Net(rows) => Err(Error::Length {
                what: "rows of data points (a net is fitted by the surface fit, not as a curve)",
                expected: 1,
                found: rows.len(),
            }),
        }
    }
}

fn outcome<const D: usize>(
    data_points: usize,
    fit: &FuzzyFit<D>,
    model: impl FnOnce(FuzzyCurve<D>) -> Model,
) -> Result<FitOutcome, Error> {
    let mixed_heights = Axis::of::<D>()
        .into_iter()
        .zip(fit.mixed_heights().into_iter().zip(fit.heights()))
        .filter(|(_, (mixed, _))| *mixed)
        .map(|(axis, (_, h))| (axis, h))
        .collect();
    let model = match fit.to_curve() {
        Ok(curve) => Ok(model(curve)),
        Err(Error::UnorderedFit { .. }) => Err(fit.violations()),
        // Any other reason is named as it is, never as broken orders.
        Err(e) => return Err(e),
    };
    Ok(FitOutcome {
        summary: FitSummary {
            data_points,
            control_points: fit.knots().count(),
            mode: fit.mode(),
            condition: fit.condition(),
            deviations: *fit.deviations(),
            spread_deviations: *fit.spread_deviations(),
            independent_violations: fit.independent_violations().to_vec(),
            mixed_heights,
        },
        model,
    })
}
