//! The numbers the `measures` figure draws: the fuzzy arc length and the
//! fuzzy area of a curve (docs/method.md §11), asked of the core's
//! [`FuzzyCurve::measure`]. At level α the interval `[min, max]` of a
//! quantity under a membership function is its α-cut, so the ends over the
//! levels trace the quantity's membership function. Plotting only draws them.

use t2spline::job::{Model, ModelVisitor};
use t2spline::measure::{AreaKind, Level, MeasureOptions, Measures, PerMembership};
use t2spline::{Alpha, FuzzyCurve, FuzzySurface};

use crate::error::Error;

/// Uniform levels the figure traces each membership function at (the
/// heights h are added, so that the lower function is drawn up to its top).
pub const MEASURE_FIGURE_LEVELS: usize = 21;

/// One fuzzy quantity of a curve: its cuts under each membership function
/// and the crisp curve's value.
#[derive(Clone, Debug, PartialEq)]
pub struct FuzzyQuantity {
    /// The cuts per function, by increasing level (the lower function's only
    /// up to its height).
    pub levels: PerMembership<Vec<Level>>,
    /// The value of the crisp curve (through the crisp control points).
    pub crisp: f64,
}

/// The fuzzy length and, for a plane curve, the fuzzy area of a curve model.
#[derive(Clone, Debug, PartialEq)]
pub struct FuzzyMeasures {
    /// The arc length.
    pub length: FuzzyQuantity,
    /// The area (plane curves) and which area it is.
    pub area: Option<(AreaKind, FuzzyQuantity)>,
}

/// The levels of the figure: [`MEASURE_FIGURE_LEVELS`] from 0 to 1 and the
/// heights `heights`, increasing, without repeats.
fn figure_levels(heights: &[f64]) -> Result<Vec<Alpha>, Error> {
    let n = MEASURE_FIGURE_LEVELS - 1;
    let mut a: Vec<f64> = (0..=n).map(|k| k as f64 / n as f64).collect();
    a.extend(heights.iter().copied().filter(|h| (0.0..=1.0).contains(h)));
    a.sort_by(f64::total_cmp);
    a.dedup();
    Ok(a.into_iter()
        .map(Alpha::try_new)
        .collect::<Result<_, _>>()?)
}

/// The fuzzy length and area of a curve model at the figure's levels, the
/// curve closed as the job's `closed` says ([`MeasureOptions::closed`]).
///
/// # Errors
/// [`Error::Surface`] for a surface; [`Error::Core`] if the core refuses
/// the levels (never for a validated job).
pub fn fuzzy_measures(model: &Model, closed: Option<bool>) -> Result<FuzzyMeasures, Error> {
    struct Of(Vec<Alpha>, Option<bool>);
    impl ModelVisitor for Of {
        type Output = Result<FuzzyMeasures, Error>;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
            let options = MeasureOptions::new(self.0, Vec::new(), 1)?
                .closed(self.1)
                .quantities(true, D == 2);
            Ok(quantities(c, c.measure(&options)?))
        }
        fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> Self::Output {
            Err(Error::Surface)
        }
    }
    model.visit(Of(figure_levels(&model.heights())?, closed))
}

/// The fuzzy length and, for a plane curve whose measures hold level 1, the
/// fuzzy area of `measures` taken of `c` (the area's crisp value is its
/// bracket at level 1).
#[must_use]
pub fn quantities<const D: usize>(c: &FuzzyCurve<D>, m: Measures) -> FuzzyMeasures {
    let length = FuzzyQuantity {
        levels: m.length,
        crisp: c.crisp_curve().arc_length(),
    };
    let area = match m.area {
        Some(a) => crisp_value(&a.upper).map(|crisp| {
            (
                a.kind,
                FuzzyQuantity {
                    levels: PerMembership {
                        upper: a.upper,
                        primary: a.primary,
                        lower: a.lower,
                    },
                    crisp,
                },
            )
        }),
        None => None,
    };
    FuzzyMeasures { length, area }
}

/// The crisp curve's value of a quantity: the upper function's cut at
/// level 1 is the box of the crisp control points (a point), so its
/// bracket there is the value.
fn crisp_value(upper: &[Level]) -> Option<f64> {
    upper
        .iter()
        .find(|l| l.alpha == 1.0)
        .map(|l| 0.5 * (l.min + l.max))
}
