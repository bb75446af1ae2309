//! Fitting fuzzy data points: one parametrization and one knot vector for all
//! seven layers, and two ways to fit the layers.

use std::fmt;
use std::str::FromStr;

use crate::error::Error;
use crate::fit::curve::{check_finite, check_within_limit};
use crate::fit::system::System;
use crate::fit::FitOptions;
use crate::fuzzy::{Axis, Height, Layer, Layers, Nt2Number, Nt2Point, RULES};
use crate::nurbs::KnotVector;
use crate::pipeline::FuzzyCurve;
pub use crate::place::OrderViolation;

/// How the six non-crisp layers are fitted once the crisp one is.
///
/// Both share the parameters (computed from the crisp values) and the knots, so
/// the result is one fuzzy curve. The crisp layer is fitted the same way in
/// both.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FuzzyFitMode {
    /// Valid by construction: the spreads `crisp − layer` (left) and
    /// `layer − crisp` (right) are fitted as non-negative quantities, nested
    /// from the inside out:
    ///
    /// ```text
    /// s_L(ūₖ) = |Q_L,ₖ − Q_crisp,ₖ|   for L = lower, primary, upper (each side)
    /// E_lower   = argmin_{e ≥ 0} ‖N·e − s_lower‖
    /// E_primary = E_lower   + argmin_{e ≥ 0} ‖N·e − (s_primary − N·E_lower)‖
    /// E_upper   = E_primary + argmin_{e ≥ 0} ‖N·e − (s_upper − N·E_primary)‖
    /// P_L = P_crisp ∓ E_L
    /// ```
    /// (non-negative least squares, Lawson–Hanson; ends fixed to the end
    /// data). Every increment is `≥ 0`, so the seven control values keep the
    /// order of docs/method.md §1 exactly, in floating point too. When fitting each layer
    /// on its own would already give ordered control points, the unconstrained
    /// solution is feasible and this mode returns it: the two modes agree.
    #[default]
    Valid,
    /// Each layer fitted on its own, like the crisp one. Exact for every layer
    /// when interpolating, but the control points may break the order of docs/method.md
    /// §1 and then do not form a fuzzy curve ([`FuzzyFit::violations`]).
    Independent,
}

impl FuzzyFitMode {
    /// The name used on the command line: `valid`, `independent`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            FuzzyFitMode::Valid => "valid",
            FuzzyFitMode::Independent => "independent",
        }
    }
}

impl fmt::Display for FuzzyFitMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for FuzzyFitMode {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "valid" => Ok(FuzzyFitMode::Valid),
            "independent" => Ok(FuzzyFitMode::Independent),
            _ => Err(format!(
                "unknown fuzzy fit `{s}` (known: valid, independent)"
            )),
        }
    }
}

/// The largest distance between one layer curve and the data of that layer,
/// at the data parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Deviation {
    /// `maxₖ,d |C_L(ūₖ)_d − Q_L,ₖ,d|`.
    pub max: f64,
    /// The data point where it is reached.
    pub point: usize,
    /// The coordinate where it is reached.
    pub axis: Axis,
}

/// The result of fitting fuzzy data points ([`fit_fuzzy`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FuzzyFit<const D: usize> {
    mode: FuzzyFitMode,
    params: Vec<f64>,
    knots: KnotVector,
    control: Layers<Vec<[f64; D]>>,
    heights: [Height; D],
    mixed_heights: [bool; D],
    deviations: Layers<Deviation>,
    spread_deviations: Layers<Deviation>,
    independent_violations: Vec<OrderViolation>,
    condition: f64,
    /// How many of the last control points repeat the first: `p` for a
    /// closed fit, 0 for an open one.
    wrap: usize,
    /// Whether the data's last point repeated the first (closed fits only).
    repeated_last: bool,
}

/// Fits a fuzzy curve (weights 1) to fuzzy data points.
///
/// The parameters come from the crisp values and are shared by every layer,
/// as are the knots ([`FitOptions::parameters_and_knots`]). The crisp layer is
/// fitted as in [`fit_curve`](crate::fit::fit_curve): it passes through the
/// crisp data when interpolating. The six other layers are fitted by `mode`.
/// The lower height of each coordinate is the one its data share, or the
/// smallest of them if they differ ([`FuzzyFit::mixed_heights`]): the widest
/// footprint of uncertainty among the data.
///
/// # Errors
/// As [`fit_curve`](crate::fit::fit_curve); [`Error::FitBeyondLimit`] names
/// the first control value of any layer beyond
/// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
///
/// # Examples
/// ```
/// # use t2spline::{Layer, Nt2Number, Nt2Point};
/// # use t2spline::fit::{fit_fuzzy, FitOptions, FuzzyFitMode};
/// let n = |c: f64, s: f64| Nt2Number::try_new(c, [c - 3.0 * s, c + 3.0 * s], [c - 2.0 * s, c + 2.0 * s], [c - s, c + s], 0.5);
/// let data = vec![
///     Nt2Point::new([n(0.0, 0.1)?, n(0.0, 0.1)?]),
///     Nt2Point::new([n(1.0, 0.3)?, n(2.0, 0.1)?]),
///     Nt2Point::new([n(2.0, 0.1)?, n(1.0, 0.2)?]),
///     Nt2Point::new([n(3.0, 0.1)?, n(3.0, 0.1)?]),
/// ];
/// let fit = fit_fuzzy(&data, &FitOptions::interpolation(2)?, FuzzyFitMode::Valid)?;
/// assert!(fit.violations().is_empty());
/// assert!(fit.deviations()[Layer::Crisp].max < 1e-14);
/// let curve = fit.to_curve()?; // a valid fuzzy curve, always, in this mode
/// assert_eq!(curve.points().len(), 4);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn fit_fuzzy<const D: usize>(
    data: &[Nt2Point<D>],
    options: &FitOptions,
    mode: FuzzyFitMode,
) -> Result<FuzzyFit<D>, Error> {
    let mut layer_data = Layers::from_fn(|l| data.iter().map(|p| p.layer(l)).collect::<Vec<_>>());
    check_finite(&layer_data[Layer::Crisp])?;
    let (params, knots) = options.parameters_and_knots(&layer_data[Layer::Crisp])?;
    // A closed fit takes a last point repeating the first as the first:
    // the loop has one data point fewer than the file.
    let repeated_last = params.len() < data.len();
    for layer in Layer::ALL {
        layer_data[layer].truncate(params.len());
    }
    let design = System::new(&params, &knots, options.is_closed())?;
    let crisp = design.fit(&layer_data[Layer::Crisp])?;
    let mut independent = Layers::from_fn(|_| Vec::new());
    for layer in Layer::ALL {
        independent[layer] = if layer == Layer::Crisp {
            crisp.clone()
        } else {
            design.fit(&layer_data[layer])?
        };
    }
    let wrap = if options.is_closed() {
        knots.degree()
    } else {
        0
    };
    let independent_violations = violations(&independent, wrap);
    let control = match mode {
        FuzzyFitMode::Independent => independent,
        FuzzyFitMode::Valid => nested_spreads(&design, &layer_data, crisp)?,
    };
    // The crisp layer first: the curve itself, the likeliest to swing out.
    let crisp_first =
        std::iter::once(Layer::Crisp).chain(Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp));
    for layer in crisp_first {
        check_within_limit(&control[layer], Some(layer))?;
    }
    let fitted = Layers::from_fn(|l| design.values(&control[l]));
    let deviations = Layers::from_fn(|l| deviation(&fitted[l], &layer_data[l]));
    // Spreads `layer − crisp`, fitted and in the data.
    let spread = |v: &Layers<Vec<[f64; D]>>, l: Layer| -> Vec<[f64; D]> {
        v[l].iter()
            .zip(&v[Layer::Crisp])
            .map(|(a, c)| std::array::from_fn(|d| a[d] - c[d]))
            .collect()
    };
    let spread_deviations =
        Layers::from_fn(|l| deviation(&spread(&fitted, l), &spread(&layer_data, l)));
    let (heights, mixed_heights) = heights(data);
    Ok(FuzzyFit {
        mode,
        params,
        knots,
        control,
        heights,
        mixed_heights,
        deviations,
        spread_deviations,
        independent_violations,
        condition: design.condition(),
        wrap,
        repeated_last,
    })
}

/// The control values of [`FuzzyFitMode::Valid`].
fn nested_spreads<const D: usize>(
    design: &System,
    data: &Layers<Vec<[f64; D]>>,
    crisp: Vec<[f64; D]>,
) -> Result<Layers<Vec<[f64; D]>>, Error> {
    let n = crisp.len();
    let mut control = Layers::from_fn(|_| crisp.clone());
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
    for d in 0..D {
        for (sign, layers) in sides {
            // Accumulated control spreads E and their curve values N·E.
            let mut spread = vec![0.0; n];
            let mut fitted = vec![0.0; data[Layer::Crisp].len()];
            for layer in layers {
                let target: Vec<f64> = data[layer]
                    .iter()
                    .zip(&data[Layer::Crisp])
                    .zip(&fitted)
                    .map(|((q, c), f)| sign * (q[d] - c[d]) - f)
                    .collect();
                let increment = design.fit_nonnegative(&target)?;
                for (e, inc) in spread.iter_mut().zip(&increment) {
                    // e ≥ 0 and inc ≥ 0: the sum does not decrease.
                    *e += inc;
                }
                for ((p, c), e) in control[layer].iter_mut().zip(&crisp).zip(&spread) {
                    p[d] = if sign < 0.0 { c[d] - e } else { c[d] + e };
                }
                fitted = design
                    .values(&spread.iter().map(|&e| [e]).collect::<Vec<_>>())
                    .into_iter()
                    .map(|v| v[0])
                    .collect();
            }
        }
    }
    Ok(control)
}

/// Every place where the seven control values break the order of docs/method.md §1;
/// the last `wrap` control points, which repeat the first, are not counted
/// again.
pub(crate) fn violations<const D: usize>(
    control: &Layers<Vec<[f64; D]>>,
    wrap: usize,
) -> Vec<OrderViolation> {
    let mut out = Vec::new();
    for i in 0..control[Layer::Crisp].len().saturating_sub(wrap) {
        for axis in Axis::of::<D>() {
            let v = Layer::ALL.map(|l| control[l][i][axis.index()]);
            for (r, rule) in RULES.iter().enumerate() {
                if v[r] > v[r + 1] {
                    out.push(OrderViolation {
                        control_point: i,
                        axis,
                        rule,
                        left: v[r],
                        right: v[r + 1],
                    });
                }
            }
        }
    }
    out
}

/// The largest coordinate difference between fitted values and data.
pub(crate) fn deviation<const D: usize>(fitted: &[[f64; D]], data: &[[f64; D]]) -> Deviation {
    let mut out = Deviation {
        max: 0.0,
        point: 0,
        axis: Axis::X,
    };
    for (k, (f, q)) in fitted.iter().zip(data).enumerate() {
        for axis in Axis::of::<D>() {
            let e = (f[axis.index()] - q[axis.index()]).abs();
            if e > out.max {
                out = Deviation {
                    max: e,
                    point: k,
                    axis,
                };
            }
        }
    }
    out
}

/// The height of each coordinate: the common one, or the smallest if mixed.
pub(crate) fn heights<const D: usize>(data: &[Nt2Point<D>]) -> ([Height; D], [bool; D]) {
    let first = data[0].coords().map(|x| x.height());
    let mut lowest = first;
    let mut mixed = [false; D];
    for p in data {
        for (d, x) in p.coords().iter().enumerate() {
            let h = x.height();
            mixed[d] |= h != first[d];
            if h < lowest[d] {
                lowest[d] = h;
            }
        }
    }
    (lowest, mixed)
}

impl<const D: usize> FuzzyFit<D> {
    /// How the layers were fitted.
    #[must_use]
    pub fn mode(&self) -> FuzzyFitMode {
        self.mode
    }

    /// The parameter `ūₖ` of each data point (from the crisp values).
    #[must_use]
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// The knot vector shared by every layer.
    #[must_use]
    pub fn knots(&self) -> &KnotVector {
        &self.knots
    }

    /// The fitted control values of one layer.
    #[must_use]
    pub fn layer_control_points(&self, layer: Layer) -> &[[f64; D]] {
        &self.control[layer]
    }

    /// The estimated condition number of the fitting system (shared by every
    /// layer; the systems of the valid fit's non-negative least squares use a
    /// subset of its columns and are no worse).
    #[must_use]
    pub fn condition(&self) -> f64 {
        self.condition
    }

    /// The lower height given to each coordinate of the control points.
    #[must_use]
    pub fn heights(&self) -> [Height; D] {
        self.heights
    }

    /// For each coordinate, whether the data mixed lower heights (the smallest
    /// was used).
    #[must_use]
    pub fn mixed_heights(&self) -> [bool; D] {
        self.mixed_heights
    }

    /// How far each layer curve is from that layer's data, at the data
    /// parameters. With interpolation the crisp deviation is rounding only;
    /// with least squares it is the approximation error. A non-crisp layer of
    /// the valid fit deviates by its crisp deviation plus the error of its
    /// spread.
    #[must_use]
    pub fn deviations(&self) -> &Layers<Deviation> {
        &self.deviations
    }

    /// How far each fitted spread `layer − crisp` is from the data's spread,
    /// at the data parameters: the deviation of the layer without that of the
    /// crisp layer (which least squares adds). Zero for the crisp layer.
    #[must_use]
    pub fn spread_deviations(&self) -> &Layers<Deviation> {
        &self.spread_deviations
    }

    /// The largest deviation of the six non-crisp layers, and its layer.
    #[must_use]
    pub fn max_spread_deviation(&self) -> (Layer, Deviation) {
        self.deviations
            .iter()
            .filter(|(l, _)| *l != Layer::Crisp)
            .map(|(l, d)| (l, *d))
            .fold(
                (Layer::UpperLeft, self.deviations[Layer::UpperLeft]),
                |a, b| {
                    if b.1.max > a.1.max {
                        b
                    } else {
                        a
                    }
                },
            )
    }

    /// Where this fit's control points break the order of docs/method.md §1; always
    /// empty for [`FuzzyFitMode::Valid`].
    #[must_use]
    pub fn violations(&self) -> Vec<OrderViolation> {
        violations(&self.control, self.wrap)
    }

    /// Whether the curve is closed: periodic knots, its last `p` control
    /// points repeating its first `p` ([`FitOptions::closed`]).
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.wrap > 0
    }

    /// The number of distinct control points: all of them for an open
    /// curve, all but the last `p` (which repeat the first) for a closed one.
    #[must_use]
    pub fn distinct_control_points(&self) -> usize {
        self.knots.count() - self.wrap
    }

    /// For a closed fit, whether the data's last point repeated the first
    /// (its crisp values within [`CLOSURE_TOLERANCE`](crate::measure::CLOSURE_TOLERANCE)
    /// of the data's size) and was taken as the same point.
    #[must_use]
    pub fn repeated_last(&self) -> bool {
        self.repeated_last
    }

    /// Where fitting every layer on its own breaks the order of docs/method.md §1 for
    /// these data: computed in both modes, so that a valid fit can say whether
    /// it had to differ from the independent one.
    #[must_use]
    pub fn independent_violations(&self) -> &[OrderViolation] {
        &self.independent_violations
    }

    /// The fitted fuzzy curve.
    ///
    /// # Errors
    /// [`Error::UnorderedFit`] if the control points break the order of docs/method.md
    /// §1 (possible only for [`FuzzyFitMode::Independent`]).
    pub fn to_curve(&self) -> Result<FuzzyCurve<D>, Error> {
        let found = self.violations();
        if let Some(&first) = found.first() {
            return Err(Error::UnorderedFit {
                count: found.len(),
                first,
            });
        }
        let n = self.control[Layer::Crisp].len();
        let points = (0..n)
            .map(|i| control_point(&self.control, i, self.heights))
            .collect::<Result<Vec<_>, Error>>()?;
        FuzzyCurve::try_new(
            self.knots.degree(),
            points,
            vec![1.0; n],
            Some(self.knots.as_slice().to_vec()),
        )
    }
}

/// The fuzzy control point `i` of fitted control values, its coordinates'
/// seven values from the seven layers, with the lower heights `heights`.
///
/// # Errors
/// [`Error::Order`] (and the other errors of [`Nt2Number::try_new`]) where
/// the values break the order of docs/method.md §1.
pub(crate) fn control_point<const D: usize>(
    control: &Layers<Vec<[f64; D]>>,
    i: usize,
    heights: [Height; D],
) -> Result<Nt2Point<D>, Error> {
    let coords: Result<Vec<Nt2Number>, Error> = (0..D)
        .map(|d| {
            let v = |l: Layer| control[l][i][d];
            Nt2Number::try_new(
                v(Layer::Crisp),
                [v(Layer::UpperLeft), v(Layer::UpperRight)],
                [v(Layer::PrimaryLeft), v(Layer::PrimaryRight)],
                [v(Layer::LowerLeft), v(Layer::LowerRight)],
                heights[d].get(),
            )
        })
        .collect();
    // One number per coordinate, D in all: the error is never made.
    let coords: [Nt2Number; D] = coords?.try_into().map_err(|v: Vec<_>| Error::Length {
        what: "coordinates",
        expected: D,
        found: v.len(),
    })?;
    Ok(Nt2Point::new(coords))
}
