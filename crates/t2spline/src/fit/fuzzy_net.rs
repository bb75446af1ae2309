//! Fitting a net of fuzzy data points: one pair of parametrizations and of
//! knot vectors for all seven layers, the crisp layer by the surface fit, the
//! six others by [`FuzzyFitMode`] as for curves.

use crate::error::Error;
use crate::fit::curve::{check_finite, check_within_limit};
use crate::fit::fuzzy::{control_point, deviation, heights, violations};
use crate::fit::net::{NetDesign, SurfaceFitOptions};
use crate::fit::{Deviation, FuzzyFitMode, OrderViolation};
use crate::fuzzy::{Height, Layer, Layers, Nt2Point};
use crate::nurbs::KnotVector;
use crate::pipeline::FuzzySurface;
use crate::place::Direction;

/// The result of fitting a net of fuzzy data points
/// ([`fit_fuzzy_surface`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FuzzySurfaceFit {
    mode: FuzzyFitMode,
    params: [Vec<f64>; 2],
    knots: [KnotVector; 2],
    /// Each layer's control net, row by row (`[i·nv + j]`).
    control: Layers<Vec<[f64; 3]>>,
    columns: usize,
    heights: [Height; 3],
    mixed_heights: [bool; 3],
    deviations: Layers<Deviation>,
    spread_deviations: Layers<Deviation>,
    independent_violations: Vec<OrderViolation>,
    condition: f64,
}

/// Fits a fuzzy surface (weights 1) to a net of fuzzy data points
/// `net[k][l]` (`k` along u).
///
/// The parameters come from the crisp values (averaged over rows and
/// columns) and are shared by every layer, as are the knots. The crisp layer
/// is fitted as in [`fit_surface`](crate::fit::fit_surface). The six other
/// layers are fitted by `mode`:
///
/// - [`FuzzyFitMode::Valid`]: the spreads `crisp − layer` and
///   `layer − crisp` of each coordinate are fitted as nested non-negative
///   increments (lower, then primary, then upper, as for curves), each
///   increment by the tensor fit when that is non-negative everywhere, else
///   by non-negative least squares in each pass (columns, then rows), so
///   that the intermediate and the final control values are `≥ 0`: every
///   control point is a valid fuzzy number, in floating point too.
/// - [`FuzzyFitMode::Independent`]: each layer fitted on its own; exact
///   for every layer when interpolating, but the order of docs/method.md §1
///   may break ([`FuzzySurfaceFit::violations`]).
///
/// The lower height of each coordinate is the one its data share, or the
/// smallest if they differ.
///
/// # Errors
/// As [`fit_surface`](crate::fit::fit_surface); [`Error::FitBeyondLimit`]
/// names the first control value of any layer beyond
/// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
///
/// # Examples
/// ```
/// # use t2spline::{Layer, Nt2Number, Nt2Point};
/// # use t2spline::fit::{fit_fuzzy_surface, FuzzyFitMode, SurfaceFitOptions};
/// let crisp = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 0.5);
/// let z = |c: f64, s: f64| Nt2Number::try_new(c, [c - 3.0 * s, c + 2.0 * s], [c - 2.0 * s, c + s], [c - s, c + s], 0.5);
/// let net = (0..4)
///     .map(|i| (0..3)
///         .map(|j| Ok(Nt2Point::new([crisp(i as f64)?, crisp(j as f64)?, z((i * j) as f64, 0.1 + 0.05 * j as f64)?])))
///         .collect::<Result<Vec<_>, t2spline::Error>>())
///     .collect::<Result<Vec<_>, _>>()?;
/// let fit = fit_fuzzy_surface(&net, &SurfaceFitOptions::interpolation([2, 2])?, FuzzyFitMode::Valid)?;
/// assert!(fit.violations().is_empty());
/// assert!(fit.deviations()[Layer::Crisp].max < 1e-12);
/// let surface = fit.to_surface()?;
/// assert_eq!(surface.points().len(), 12);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn fit_fuzzy_surface(
    net: &[Vec<Nt2Point<3>>],
    options: &SurfaceFitOptions,
    mode: FuzzyFitMode,
) -> Result<FuzzySurfaceFit, Error> {
    let layer_data: Layers<Vec<Vec<[f64; 3]>>> = Layers::from_fn(|l| {
        net.iter()
            .map(|row| row.iter().map(|p| p.layer(l)).collect())
            .collect()
    });
    for row in &layer_data[Layer::Crisp] {
        check_finite(row)?;
    }
    let directions = options.parameters_and_knots(&layer_data[Layer::Crisp])?;
    let design = NetDesign::new(&directions)?;
    let crisp = design.fit(&layer_data[Layer::Crisp])?;
    let mut independent = Layers::from_fn(|_| Vec::new());
    for layer in Layer::ALL {
        independent[layer] = if layer == Layer::Crisp {
            crisp.clone()
        } else {
            design.fit(&layer_data[layer])?
        };
    }
    let flat = |net: &Layers<Vec<Vec<[f64; 3]>>>| -> Layers<Vec<[f64; 3]>> {
        Layers::from_fn(|l| net[l].concat())
    };
    let independent_violations = violations(&flat(&independent), 0);
    let control = match mode {
        FuzzyFitMode::Independent => independent,
        FuzzyFitMode::Valid => nested_spreads(&design, &layer_data, &crisp)?,
    };
    let crisp_first =
        std::iter::once(Layer::Crisp).chain(Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp));
    for layer in crisp_first {
        for row in &control[layer] {
            check_within_limit(row, Some(layer))?;
        }
    }
    let fitted = flat(&Layers::from_fn(|l| design.values(&control[l])));
    let data = flat(&layer_data);
    let deviations = Layers::from_fn(|l| deviation(&fitted[l], &data[l]));
    let spread = |v: &Layers<Vec<[f64; 3]>>, l: Layer| -> Vec<[f64; 3]> {
        v[l].iter()
            .zip(&v[Layer::Crisp])
            .map(|(a, c)| std::array::from_fn(|d| a[d] - c[d]))
            .collect()
    };
    let spread_deviations = Layers::from_fn(|l| deviation(&spread(&fitted, l), &spread(&data, l)));
    let (heights, mixed_heights) = heights(&net.concat());
    let [(pu, ku), (pv, kv)] = directions;
    Ok(FuzzySurfaceFit {
        mode,
        params: [pu, pv],
        knots: [ku, kv],
        columns: design.counts()[1],
        control: flat(&control),
        heights,
        mixed_heights,
        deviations,
        spread_deviations,
        independent_violations,
        condition: design.condition(),
    })
}

/// The control values of [`FuzzyFitMode::Valid`]: for each coordinate and
/// side, the spreads of lower, primary and upper fitted as non-negative
/// increments, each on what the ones inside it left.
fn nested_spreads(
    design: &NetDesign,
    data: &Layers<Vec<Vec<[f64; 3]>>>,
    crisp: &[Vec<[f64; 3]>],
) -> Result<Layers<Vec<Vec<[f64; 3]>>>, Error> {
    let mut control = Layers::from_fn(|_| crisp.to_vec());
    let sides = [
        (
            -1.0,
            [Layer::LowerLeft, Layer::PrimaryLeft, Layer::UpperLeft],
        ),
        (
            1.0,
            [Layer::LowerRight, Layer::PrimaryRight, Layer::UpperRight],
        ),
    ];
    let [nu, nv] = design.counts();
    for d in 0..3 {
        for (sign, layers) in sides {
            // Accumulated control spreads E and their values at the data.
            let mut spread = vec![vec![0.0; nv]; nu];
            let mut fitted: Vec<Vec<f64>> = data[Layer::Crisp]
                .iter()
                .map(|row| vec![0.0; row.len()])
                .collect();
            for layer in layers {
                let target: Vec<Vec<f64>> = data[layer]
                    .iter()
                    .zip(&data[Layer::Crisp])
                    .zip(&fitted)
                    .map(|((q, c), f)| {
                        q.iter()
                            .zip(c)
                            .zip(f)
                            .map(|((q, c), f)| sign * (q[d] - c[d]) - f)
                            .collect()
                    })
                    .collect();
                let increment = design.fit_nonnegative(&target)?;
                for (row, inc) in spread.iter_mut().zip(&increment) {
                    for (e, i) in row.iter_mut().zip(inc) {
                        // e ≥ 0 and i ≥ 0: the sum does not decrease.
                        *e += i;
                    }
                }
                for ((out, c), e) in control[layer].iter_mut().zip(crisp).zip(&spread) {
                    for ((p, c), e) in out.iter_mut().zip(c).zip(e) {
                        p[d] = if sign < 0.0 { c[d] - e } else { c[d] + e };
                    }
                }
                let wrapped: Vec<Vec<[f64; 1]>> = spread
                    .iter()
                    .map(|r| r.iter().map(|&e| [e]).collect())
                    .collect();
                fitted = design
                    .values(&wrapped)
                    .into_iter()
                    .map(|r| r.into_iter().map(|v| v[0]).collect())
                    .collect();
            }
        }
    }
    Ok(control)
}

impl FuzzySurfaceFit {
    /// How the layers were fitted.
    #[must_use]
    pub fn mode(&self) -> FuzzyFitMode {
        self.mode
    }

    /// The parameters `[ū, v̄]` of the net's rows and columns.
    #[must_use]
    pub fn params(&self) -> &[Vec<f64>; 2] {
        &self.params
    }

    /// The knot vector of `direction`, shared by every layer.
    #[must_use]
    pub fn knots(&self, direction: Direction) -> &KnotVector {
        &self.knots[direction.index()]
    }

    /// The number of control points in u and in v.
    #[must_use]
    pub fn counts(&self) -> [usize; 2] {
        [self.knots[0].count(), self.knots[1].count()]
    }

    /// The fitted control values of one layer, row by row (`[i·nv + j]`).
    #[must_use]
    pub fn layer_control_points(&self, layer: Layer) -> &[[f64; 3]] {
        &self.control[layer]
    }

    /// The larger of the two directions' estimated condition numbers.
    #[must_use]
    pub fn condition(&self) -> f64 {
        self.condition
    }

    /// The lower height given to each coordinate of the control points.
    #[must_use]
    pub fn heights(&self) -> [Height; 3] {
        self.heights
    }

    /// For each coordinate, whether the data mixed lower heights.
    #[must_use]
    pub fn mixed_heights(&self) -> [bool; 3] {
        self.mixed_heights
    }

    /// How far each layer surface is from that layer's data at the data
    /// parameters; [`Deviation::point`] counts the stations row by row
    /// (`k·columns + l`).
    #[must_use]
    pub fn deviations(&self) -> &Layers<Deviation> {
        &self.deviations
    }

    /// How far each fitted spread `layer − crisp` is from the data's.
    #[must_use]
    pub fn spread_deviations(&self) -> &Layers<Deviation> {
        &self.spread_deviations
    }

    /// Where this fit's control points break the order of docs/method.md §1
    /// ([`OrderViolation::control_point`] counts row by row); always empty for
    /// [`FuzzyFitMode::Valid`].
    #[must_use]
    pub fn violations(&self) -> Vec<OrderViolation> {
        violations(&self.control, 0)
    }

    /// Where fitting every layer on its own breaks the order, in both modes.
    #[must_use]
    pub fn independent_violations(&self) -> &[OrderViolation] {
        &self.independent_violations
    }

    /// The fitted fuzzy surface.
    ///
    /// # Errors
    /// [`Error::UnorderedFit`] if the control points break the order of
    /// docs/method.md §1 (possible only for [`FuzzyFitMode::Independent`]).
    pub fn to_surface(&self) -> Result<FuzzySurface<3>, Error> {
        let found = self.violations();
        if let Some(&first) = found.first() {
            return Err(Error::UnorderedFit {
                count: found.len(),
                first,
            });
        }
        let [nu, nv] = self.counts();
        let points = (0..nu)
            .map(|i| {
                (0..nv)
                    .map(|j| control_point(&self.control, i * self.columns + j, self.heights))
                    .collect::<Result<Vec<_>, Error>>()
            })
            .collect::<Result<Vec<_>, Error>>()?;
        FuzzySurface::try_new(
            [self.knots[0].degree(), self.knots[1].degree()],
            points,
            vec![vec![1.0; nv]; nu],
            [
                Some(self.knots[0].as_slice().to_vec()),
                Some(self.knots[1].as_slice().to_vec()),
            ],
        )
    }
}
