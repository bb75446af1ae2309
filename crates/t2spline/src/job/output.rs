//! What a run computes (docs/method.md §7–§8), in the shape of the result file.
//!
//! The field names and their order are those of the result file's keys (the
//! I/O crate writes these types with serde, feature `serde`); docs/jobs.md requires
//! `alpha`, `control_points.{crisp, type_reduced_left, type_reduced_right,
//! defuzzified}`, `curves.{params, crisp, defuzzified}`, `curves.layers.*` and
//! `error.{max, rms}`; the others add the curve's definition and the curves
//! of stages 2 and 3.

use std::fmt;

use crate::fuzzy::Layer;
use crate::reduction::TypeReduction;

use super::near_height::NearHeight;
use super::points::Points;

/// Everything a run computes: the stages' control points, every curve (or
/// surface) sampled at uniform parameters, and the distance between the crisp
/// and the defuzzified one.
///
/// Curves and surfaces share every stage's containers ([`Points`], lists for
/// a curve, grids for a surface); they differ in the spline's definition
/// ([`Spline`]), the parameters ([`Parameters`]) and where the distance is
/// largest ([`Parameter`]). The result file names the samples `curves` or
/// `surfaces` accordingly (docs/jobs.md; docs/method.md §8).
#[derive(Clone, Debug, PartialEq)]
pub struct RunOutput {
    /// The job's description, if any.
    pub description: Option<String>,
    /// 2 or 3.
    pub dimension: usize,
    /// Orders, degrees, weights, knots and domain of the spline.
    pub spline: Spline,
    /// The type reduction of stages 3–4 (docs/method.md §9).
    pub type_reduction: TypeReduction,
    /// The level alpha of the cut (stage 2); 0 (the whole footprint) when
    /// the type reduction does not use alpha.
    pub alpha: f64,
    /// Whether stages 3–4 depend on alpha (only the paper's type reduction
    /// uses it).
    pub alpha_used: bool,
    /// Which rule of docs/method.md §3 reduced the numbers; `None` for a type
    /// reduction other than the paper's.
    pub regime: Option<Regime>,
    /// With the paper's reduction, a lower height that alpha lies a few ulps
    /// above ([`NearHeight`]: the other side of the jump at `alpha = h`); the
    /// result file says so in a `note`.
    pub near_height: Option<NearHeight>,
    /// Control points of every stage.
    pub control_points: ControlPoints,
    /// The weights of every stage where they are fuzzy (docs/method.md
    /// §16); `None` with crisp weights.
    pub weight_stages: Option<WeightStages>,
    /// Curves or surfaces sampled at `samples.params`.
    pub samples: Sampled,
    /// Distance between the crisp and the defuzzified curve or surface.
    pub error: Distance,
}

/// The definition of the spline that a run sampled (docs/method.md §6, §8).
#[derive(Clone, Debug, PartialEq)]
pub enum Spline {
    /// A curve.
    Curve {
        /// The order `k`.
        order: usize,
        /// The degree `p = k − 1`.
        degree: usize,
        /// The weights.
        weights: Vec<f64>,
        /// The knot vector actually used (the default made explicit).
        knots: Vec<f64>,
        /// The parameter domain `[U[p], U[n]]`.
        domain: [f64; 2],
    },
    /// A surface.
    Surface {
        /// The orders `[ku, kv]`.
        order: [usize; 2],
        /// The degrees `[p, q]`.
        degree: [usize; 2],
        /// The weights, `[row][column]`.
        weights: Vec<Vec<f64>>,
        /// The knot vectors `U` and `V` actually used.
        knots: [Vec<f64>; 2],
        /// The domain `[U[p], U[nu]] × [V[q], V[nv]]`.
        domain: [[f64; 2]; 2],
    },
}

impl Spline {
    /// The weights, a surface's row by row.
    #[must_use]
    pub fn weights(&self) -> Vec<f64> {
        match self {
            Spline::Curve { weights, .. } => weights.clone(),
            Spline::Surface { weights, .. } => weights.concat(),
        }
    }

    /// The order (of a curve), or the orders in u and v (of a surface).
    #[must_use]
    pub fn orders(&self) -> Vec<usize> {
        match self {
            Spline::Curve { order, .. } => vec![*order],
            Spline::Surface { order, .. } => order.to_vec(),
        }
    }
}

/// The sample parameters: uniform `t` along a curve, or the uniform `u` and
/// `v` of a surface's grid.
#[derive(Clone, Debug, PartialEq)]
pub enum Parameters {
    /// `tᵢ = a + (b − a)·i/(samples − 1)`.
    Along(Vec<f64>),
    /// `u_a` and `v_b`, each uniform as along a curve.
    Grid {
        /// The parameters along u.
        u: Vec<f64>,
        /// The parameters along v.
        v: Vec<f64>,
    },
}

impl Parameters {
    /// The parameters along a curve; empty for a grid.
    #[must_use]
    pub fn along(&self) -> &[f64] {
        match self {
            Parameters::Along(t) => t,
            Parameters::Grid { .. } => &[],
        }
    }

    /// The number of sampled points (`su · sv` for a grid).
    #[must_use]
    pub fn count(&self) -> usize {
        match self {
            Parameters::Along(t) => t.len(),
            Parameters::Grid { u, v } => u.len() * v.len(),
        }
    }
}

/// A point of the parameter domain: `t`, or `(u, v)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Parameter {
    /// A curve's parameter.
    T(f64),
    /// A surface's parameters.
    Uv([f64; 2]),
}

impl Parameter {
    /// The curve parameter; `None` for a surface's.
    #[must_use]
    pub fn t(self) -> Option<f64> {
        match self {
            Parameter::T(t) => Some(t),
            Parameter::Uv(_) => None,
        }
    }
}

/// The distance between the crisp and the defuzzified curve or surface over
/// the whole domain ([`crate::Distance`], [`crate::SurfaceDistance`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Distance {
    /// The largest distance at equal parameters.
    pub max: f64,
    /// A parameter where it is reached.
    pub max_at: Parameter,
    /// The root mean square distance over the domain.
    pub rms: f64,
}

/// Which rule of docs/method.md §3 reduced the numbers at the run's alpha (the paper's
/// type reduction).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Regime {
    /// `alpha <= h` for every number: three-term averages.
    AtOrBelow,
    /// `alpha > h` for every number: two-term averages (no lower cut).
    Above,
    /// The numbers' heights put them on both sides.
    Mixed,
}

impl Regime {
    /// The text in result files: `"alpha <= h"`, `"alpha > h"` or `"mixed"`.
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Regime::AtOrBelow => "alpha <= h",
            Regime::Above => "alpha > h",
            Regime::Mixed => "mixed",
        }
    }
}

impl fmt::Display for Regime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for Regime {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// The control points of every stage.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ControlPoints {
    /// The crisp control points.
    pub crisp: Points,
    /// Stage 1: the six non-crisp values of every point.
    pub layers: SixLayers<Points>,
    /// Stage 2: the alpha-cut ends of every point; a lower end is absent where
    /// the level is above that number's lower height.
    pub alpha_cut: SixLayers<Points<Option<f64>>>,
    /// Stage 3: left type-reduced control points.
    pub type_reduced_left: Points,
    /// Stage 3: right type-reduced control points.
    pub type_reduced_right: Points,
    /// Stage 4: defuzzified control points.
    pub defuzzified: Points,
}

/// The weights of every stage of a curve or surface with fuzzy weights
/// (docs/method.md §16), one value per control point (a surface's net row
/// by row, in one list), each stage's curve or surface taking its stage's
/// weights.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct WeightStages {
    /// The crisp values.
    pub crisp: Vec<f64>,
    /// Stage 1: the six non-crisp values of every weight.
    pub layers: SixLayers<Vec<f64>>,
    /// Stage 2: the alpha-cut ends of every weight; a lower end is absent
    /// where the level is above that weight's lower height.
    pub alpha_cut: SixLayers<Vec<Option<f64>>>,
    /// Stage 3: the left type-reduced weights.
    pub type_reduced_left: Vec<f64>,
    /// Stage 3: the right type-reduced weights.
    pub type_reduced_right: Vec<f64>,
    /// Stage 4: the defuzzified weights.
    pub defuzzified: Vec<f64>,
}

impl WeightStages {
    /// The weights of every stage from the same stages of the control
    /// points of one coordinate.
    pub(crate) fn of(stages: &ControlPoints) -> Self {
        fn flat<T: Copy>(p: &Points<T>) -> Vec<T> {
            p.coord(0).to_vec()
        }
        WeightStages {
            crisp: flat(&stages.crisp),
            layers: SixLayers::from_fn(|l| stages.layers.get(l).map(flat).unwrap_or_default()),
            alpha_cut: SixLayers::from_fn(|l| {
                stages.alpha_cut.get(l).map(flat).unwrap_or_default()
            }),
            type_reduced_left: flat(&stages.type_reduced_left),
            type_reduced_right: flat(&stages.type_reduced_right),
            defuzzified: flat(&stages.defuzzified),
        }
    }
}

/// The sampled curves or surfaces (lists or grids of points).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Sampled {
    /// The parameters.
    pub params: Parameters,
    /// The crisp curve.
    pub crisp: Points,
    /// The crisp type-2 solution (stage 4).
    pub defuzzified: Points,
    /// Stage 1: the six non-crisp layer curves, before the cut.
    pub layers: SixLayers<Points>,
    /// Stage 2: the alpha-cut layer curves; a lower layer is absent unless
    /// every number has a lower cut at this level.
    pub alpha_cut: SixLayers<Option<Points>>,
    /// Stage 3: the type-reduced left and right curves.
    pub type_reduced: LeftRight<Points>,
    /// With a derivative order `K`: for each order `1 ..= K`, the derivative
    /// vectors of the crisp and the defuzzified curve at `params`.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub derivatives: Option<CrispDefuzzified<Vec<Points>>>,
    /// With a derivative order: the arc lengths of the crisp and the
    /// defuzzified curve.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub arc_length: Option<CrispDefuzzified<f64>>,
    /// With fuzzy weights (curves): the exact envelope of the curve at each
    /// parameter at the run's alpha (docs/method.md §16), where the stage
    /// curves, each with one choice of weights, do not bound it.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub envelope: Option<Envelope>,
}

impl Sampled {
    /// The sampled curve of one stage-1 layer (the crisp curve for
    /// [`Layer::Crisp`]).
    #[must_use]
    pub fn layer(&self, layer: Layer) -> &Points {
        self.layers.get(layer).unwrap_or(&self.crisp)
    }
}

/// One value per non-crisp layer, with the layer names of docs/jobs.md.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
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
    /// The six values from a function of the layer.
    pub fn from_fn(mut f: impl FnMut(Layer) -> T) -> Self {
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
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[allow(missing_docs)]
pub struct LeftRight<T> {
    pub left: T,
    pub right: T,
}

/// The envelope of a curve with fuzzy weights at every sample parameter,
/// per membership function: the least (`left`) and the largest (`right`)
/// value of each coordinate over every choice of points and weights inside
/// their cuts at the run's alpha (docs/method.md §16), exact at the
/// Karnik–Mendel switch points. The lower function's is absent where alpha
/// lies above a lower height.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Envelope {
    /// Under the upper membership functions.
    pub upper: LeftRight<Points>,
    /// Under the primary membership functions.
    pub primary: LeftRight<Points>,
    /// Under the lower membership functions, where every number has a cut.
    pub lower: Option<LeftRight<Points>>,
}

/// One value for the crisp and one for the defuzzified curve.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CrispDefuzzified<T> {
    /// For the crisp curve (through the crisp control points).
    pub crisp: T,
    /// For the defuzzified curve (the crisp type-2 solution, stage 4).
    pub defuzzified: T,
}
