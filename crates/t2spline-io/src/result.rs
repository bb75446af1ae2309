//! The result of a run (SPEC §8): control points and sampled curves of every
//! stage, and the distance between the crisp and the defuzzified curve.

use serde::{Deserialize, Serialize};
use t2spline::sampling::{CurveSamples, Params};
use t2spline::{Alpha, FuzzyCurve, Layer, Side, Solution};

use crate::derivatives::{CrispDefuzzified, DerivativeCurves};
use crate::job::{Job, JobCurve};

/// A point as a list of coordinates.
pub type Point = Vec<f64>;

/// Everything a run computes, as written to the result file.
///
/// The keys SPEC §8 requires are `alpha`, `control_points.{crisp,
/// type_reduced_left, type_reduced_right, defuzzified}`, `curves.{params, crisp,
/// defuzzified}`, `curves.layers.*` and `error.{max, rms}`; the others add the
/// curve's definition and the curves of stages 2 and 3.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunResult {
    /// The job's description, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// 2 or 3.
    pub dimension: usize,
    /// The order `k`.
    pub order: usize,
    /// The degree `p = k − 1`.
    pub degree: usize,
    /// The weights.
    pub weights: Vec<f64>,
    /// The knot vector actually used (the default made explicit).
    pub knots: Vec<f64>,
    /// The parameter domain `[U[p], U[n]]`.
    pub domain: [f64; 2],
    /// The level alpha.
    pub alpha: f64,
    /// Which type-reduction rule applied (SPEC §3): `"alpha <= h"` (three-term
    /// averages) for every number, `"alpha > h"` (two-term) for every number, or
    /// `"mixed"` when the numbers' heights put them on both sides.
    pub regime: String,
    /// Control points of every stage.
    pub control_points: ControlPoints,
    /// Curves sampled at `curves.params`.
    pub curves: Curves,
    /// Distance between the crisp and the defuzzified curve.
    pub error: Distance,
}

/// The control points of every stage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ControlPoints {
    /// The crisp control points.
    pub crisp: Vec<Point>,
    /// Stage 1: the six non-crisp values of every point.
    pub layers: SixLayers<Vec<Point>>,
    /// Stage 2: the alpha-cut ends of every point; a lower end is `null` where
    /// the level is above that number's lower height.
    pub alpha_cut: SixLayers<Vec<Vec<Option<f64>>>>,
    /// Stage 3: left type-reduced control points.
    pub type_reduced_left: Vec<Point>,
    /// Stage 3: right type-reduced control points.
    pub type_reduced_right: Vec<Point>,
    /// Stage 4: defuzzified control points.
    pub defuzzified: Vec<Point>,
}

/// The sampled curves.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Curves {
    /// The parameters `tᵢ = a + (b − a)·i/(samples − 1)`.
    pub params: Vec<f64>,
    /// The crisp curve.
    pub crisp: Vec<Point>,
    /// The crisp type-2 solution (stage 4).
    pub defuzzified: Vec<Point>,
    /// Stage 1: the six non-crisp layer curves, before the cut.
    pub layers: SixLayers<Vec<Point>>,
    /// Stage 2: the alpha-cut layer curves; a lower layer is `null` unless every
    /// number has a lower cut at this level.
    pub alpha_cut: SixLayers<Option<Vec<Point>>>,
    /// Stage 3: the type-reduced left and right curves.
    pub type_reduced: LeftRight<Vec<Point>>,
    /// With `--derivatives K`: for each order `1 … K`, the derivative vectors
    /// of the crisp and the defuzzified curve at `params`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub derivatives: Option<DerivativeCurves>,
    /// With `--derivatives K`: the arc lengths of the crisp and the
    /// defuzzified curve.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub arc_length: Option<CrispDefuzzified<f64>>,
}

/// One value per non-crisp layer, with the layer names of SPEC §8.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[allow(missing_docs)]
pub struct SixLayers<T> {
    pub upper_left: T,
    pub primary_left: T,
    pub lower_left: T,
    pub lower_right: T,
    pub primary_right: T,
    pub upper_right: T,
}

impl<T> SixLayers<T> {
    fn from_fn(mut f: impl FnMut(Layer) -> T) -> Self {
        SixLayers {
            upper_left: f(Layer::UpperLeft),
            primary_left: f(Layer::PrimaryLeft),
            lower_left: f(Layer::LowerLeft),
            lower_right: f(Layer::LowerRight),
            primary_right: f(Layer::PrimaryRight),
            upper_right: f(Layer::UpperRight),
        }
    }

    /// The value of a non-crisp layer; `None` for [`Layer::Crisp`].
    #[must_use]
    pub fn get(&self, layer: Layer) -> Option<&T> {
        match layer {
            Layer::UpperLeft => Some(&self.upper_left),
            Layer::PrimaryLeft => Some(&self.primary_left),
            Layer::LowerLeft => Some(&self.lower_left),
            Layer::Crisp => None,
            Layer::LowerRight => Some(&self.lower_right),
            Layer::PrimaryRight => Some(&self.primary_right),
            Layer::UpperRight => Some(&self.upper_right),
        }
    }
}

/// A left and a right value.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[allow(missing_docs)]
pub struct LeftRight<T> {
    pub left: T,
    pub right: T,
}

/// The distance between the crisp and the defuzzified curve over the whole
/// domain; see [`t2spline::Distance`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Distance {
    /// The largest distance at equal `t`.
    pub max: f64,
    /// A parameter where it is reached.
    pub max_at: f64,
    /// The root mean square distance.
    pub rms: f64,
}

impl RunResult {
    /// Runs stages 1–4 of the job's curve at `alpha` and samples every curve at
    /// `samples` uniform parameters, all with the sampling engine
    /// ([`t2spline::sampling`]: one power form of the rational basis for every
    /// curve, multi-threaded for large jobs).
    #[must_use]
    pub fn compute(job: &Job, alpha: Alpha, samples: usize) -> RunResult {
        let mut r = match &job.curve {
            JobCurve::Planar(c) => compute(c, alpha, samples),
            JobCurve::Spatial(c) => compute(c, alpha, samples),
        };
        r.description.clone_from(&job.description);
        r
    }
}

fn to_vecs<const D: usize>(points: &[[f64; D]]) -> Vec<Point> {
    points.iter().map(|p| p.to_vec()).collect()
}

/// A sampled curve as a list of points.
fn sampled<const D: usize>(curve: &CurveSamples<D>) -> Vec<Point> {
    curve.points().map(|p| p.to_vec()).collect()
}

fn compute<const D: usize>(curve: &FuzzyCurve<D>, alpha: Alpha, samples: usize) -> RunResult {
    let solution: Solution<D> = curve.solve(alpha);
    let params = curve.domain().uniform(samples);
    // Every curve of every stage from one power form of the rational basis.
    let (layers, levels) = curve
        .sample_sweep(Params::Uniform(samples), &[alpha])
        .expect("uniform parameters lie in the domain")
        .into_parts();
    let level = &levels[0];
    let layer_samples = |layer: Layer| sampled(&layers[layer]);
    let cut_points = solution.alpha_cut_points();
    let d = solution.distance();
    let regime = {
        let below = cut_points
            .iter()
            .flatten()
            .filter(|c| c.lower().is_some())
            .count();
        match below {
            0 => "alpha > h",
            n if n == cut_points.len() * D => "alpha <= h",
            _ => "mixed",
        }
    };
    RunResult {
        description: None,
        dimension: D,
        order: curve.order(),
        degree: curve.degree(),
        weights: curve.weights().to_vec(),
        knots: curve.knots().as_slice().to_vec(),
        domain: [curve.domain().start, curve.domain().end],
        alpha: alpha.get(),
        regime: regime.to_owned(),
        control_points: ControlPoints {
            crisp: curve.points().iter().map(|p| p.crisp().to_vec()).collect(),
            layers: SixLayers::from_fn(|l| {
                curve.points().iter().map(|p| p.layer(l).to_vec()).collect()
            }),
            alpha_cut: SixLayers::from_fn(|l| {
                cut_points
                    .iter()
                    .map(|cuts| cuts.iter().map(|c| c.layer(l)).collect())
                    .collect()
            }),
            type_reduced_left: to_vecs(&solution.type_reduced_side(Side::Left)),
            type_reduced_right: to_vecs(&solution.type_reduced_side(Side::Right)),
            defuzzified: to_vecs(solution.defuzzified_points()),
        },
        curves: Curves {
            crisp: layer_samples(Layer::Crisp),
            defuzzified: sampled(level.defuzzified()),
            layers: SixLayers::from_fn(layer_samples),
            alpha_cut: SixLayers::from_fn(|l| level.alpha_cut(l).map(sampled)),
            type_reduced: LeftRight {
                left: sampled(level.type_reduced(Side::Left)),
                right: sampled(level.type_reduced(Side::Right)),
            },
            params,
            derivatives: None,
            arc_length: None,
        },
        error: Distance {
            max: d.max,
            max_at: d.max_at,
            rms: d.rms,
        },
    }
}
