//! Running a job: every stage of Algorithm 1.1 on the control points, every
//! curve sampled, the distance, and the derivatives when asked for.

use crate::error::{Error, Setting};
use crate::fuzzy::{Alpha, Layer, Membership, Nt2Number, Nt2Point};
use crate::nurbs::{Direction, NurbsCurve};
use crate::pipeline::point_stages::PointStages;
use crate::pipeline::{FuzzyCurve, FuzzySurface, Side};
use crate::reduction::TypeReduction;
use crate::sampling::{CurveSamples, Params, SweepSamples};

use super::model::ModelVisitor;
use super::output::Envelope;
use super::output::RunOutput;
use super::output::{
    ControlPoints, CrispDefuzzified, Distance, LeftRight, Parameter, Parameters, Regime, Sampled,
    SixLayers, Spline, WeightStages,
};
use super::points::Points;
use super::settings::{Samples, Settings};
use super::Job;

impl Job {
    /// Runs stages 1–4 at `settings.alpha` with `settings.type_reduction`
    /// (the defuzzified curve and the distance are that reduction's) and
    /// samples every curve at
    /// `settings.samples` uniform parameters, all with the sampling engine
    /// ([`crate::sampling`]: one power form of the rational basis for every
    /// curve, multi-threaded for large jobs); with `settings.derivatives = K`
    /// also the derivatives of orders `1 ..= K` of the crisp and the
    /// defuzzified curve at those parameters (one-sided at knots as in
    /// [`NurbsCurve::derivatives`]) and their arc lengths.
    ///
    /// # Errors
    /// [`Error::DerivativeOverflow`] when a derivative is beyond the range of a
    /// float (a derivative grows like `(coordinate / knot span)^order`, so
    /// narrow spans or large coordinates can take it there); the other parts of
    /// a run are finite for every valid job (the core's input ranges).
    /// [`Error::ArcLengthOverflow`] likewise for an arc length. Settings made
    /// by [`Job::settings`] of another job, for another kind of model, are an
    /// [`Error::Setting`]; they are otherwise taken as they are, checked once.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::job::{Job, Model, Overrides};
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// // A crisp segment from (0, 0) to (3, 4): C' = (3, 4), C'' = 0, length 5.
    /// let n = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(3.0)?, n(4.0)?])];
    /// let job = Job::new(Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?));
    /// let s = job.settings(&Overrides { alpha: Some(0.5), samples: Some(vec![2]), derivatives: Some(2), ..Overrides::default() })?;
    /// let out = job.run(&s)?;
    /// let d = out.samples.derivatives.as_ref().unwrap();
    /// assert_eq!(d.crisp[0].point(1), Some(vec![3.0, 4.0]));
    /// assert_eq!(d.crisp[1].point(1), Some(vec![0.0, 0.0]));
    /// assert!((out.samples.arc_length.unwrap().crisp - 5.0).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn run(&self, settings: &Settings) -> Result<RunOutput, Error> {
        let mut out = self.model.visit(Run(settings))?;
        out.description.clone_from(&self.description);
        Ok(out)
    }
}

/// [`Job::run`] for one kind of model.
struct Run<'a>(&'a Settings);

impl ModelVisitor for Run<'_> {
    type Output = Result<RunOutput, Error>;

    fn curve<const D: usize>(self, curve: &FuzzyCurve<D>) -> Self::Output {
        let s = self.0;
        let (alpha, type_reduction, samples, derivatives) =
            (s.alpha(), s.type_reduction(), s.samples(), s.derivatives());
        let Samples::Along(samples) = samples else {
            return Err(wrong_samples("a grid of samples", "a curve"));
        };
        let solution = curve.solve_with(alpha, type_reduction);
        // Every curve of every stage from one power form of the rational basis.
        let sweep = solution.sample_with_layers(Params::Uniform(samples))?;
        let d = solution.distance();
        let mut out = RunOutput {
            description: None,
            dimension: D,
            spline: Spline::Curve {
                order: curve.order(),
                degree: curve.degree(),
                weights: curve.weights().to_vec(),
                knots: curve.knots().as_slice().to_vec(),
                domain: [curve.domain().start, curve.domain().end],
            },
            type_reduction,
            alpha: alpha.get(),
            alpha_used: type_reduction.uses_alpha(),
            regime: regime(solution.stages()),
            near_height: s.near_height(),
            control_points: control_points(curve.points(), solution.stages(), None),
            weight_stages: weight_stages(curve.weight_numbers(), solution.weight_stages()),
            samples: sampled(
                sweep,
                Parameters::Along(curve.domain().uniform(samples)?),
                None,
            )?,
            error: Distance {
                max: d.max,
                max_at: Parameter::T(d.max_at),
                rms: d.rms,
            },
        };
        if curve.weight_numbers().is_some() {
            let params = out.samples.params.along();
            out.samples.envelope = Some(envelope(curve, params, solution.alpha())?);
        }
        if let Some(order) = derivatives {
            let params = out.samples.params.along();
            let (d, lengths) =
                derivative_curves(curve, &solution.defuzzified_curve(), params, order)?;
            out.samples.derivatives = Some(d);
            out.samples.arc_length = Some(lengths);
        }
        Ok(out)
    }

    fn surface<const D: usize>(self, surface: &FuzzySurface<D>) -> Self::Output {
        let s = self.0;
        let (alpha, type_reduction, samples, derivatives) =
            (s.alpha(), s.type_reduction(), s.samples(), s.derivatives());
        let Samples::Grid([su, sv]) = samples else {
            return Err(wrong_samples("one number of samples", "a surface"));
        };
        if derivatives.is_some() {
            return Err(Error::Setting {
                setting: Setting::Derivatives,
                message: "derivatives are offered for curves; this job is a surface".into(),
            });
        }
        let solution = surface.solve_with(alpha, type_reduction);
        let grid = solution.sample_with_layers(Params::Uniform(su), Params::Uniform(sv))?;
        let d = solution.distance();
        let [du, dv] = Direction::BOTH.map(|dir| surface.domain(dir));
        let [nu, nv] = surface.shape();
        let [p, q] = surface.degree();
        Ok(RunOutput {
            description: None,
            dimension: D,
            spline: Spline::Surface {
                order: [p + 1, q + 1],
                degree: [p, q],
                weights: surface
                    .weights()
                    .chunks(nv.max(1))
                    .map(<[f64]>::to_vec)
                    .collect(),
                knots: Direction::BOTH.map(|dir| surface.knots(dir).as_slice().to_vec()),
                domain: [[du.start, du.end], [dv.start, dv.end]],
            },
            type_reduction,
            alpha: alpha.get(),
            alpha_used: type_reduction.uses_alpha(),
            regime: regime(solution.stages()),
            near_height: s.near_height(),
            control_points: control_points(surface.points(), solution.stages(), Some([nu, nv])),
            // Row by row in one list, as `Surface::weight_numbers` holds them.
            weight_stages: weight_stages(surface.weight_numbers(), solution.weight_stages()),
            samples: sampled(
                grid.into_samples(),
                Parameters::Grid {
                    u: du.uniform(su)?,
                    v: dv.uniform(sv)?,
                },
                Some([su, sv]),
            )?,
            error: Distance {
                max: d.max,
                max_at: Parameter::Uv(d.max_at),
                rms: d.rms,
            },
        })
    }
}

/// The error for settings made for another kind of model (a caller's slip:
/// [`Job::settings`] makes them to fit the job).
fn wrong_samples(given: &str, model: &str) -> Error {
    Error::Setting {
        setting: Setting::Samples,
        message: format!("{given} does not fit {model}"),
    }
}

/// Which rule of docs/method.md §3 reduced the numbers; `None` if the paper's
/// reduction did not.
fn regime<const D: usize>(stages: &PointStages<D>) -> Option<Regime> {
    if stages.type_reduction() != TypeReduction::Paper {
        return None;
    }
    let cut_points = stages.alpha_cut_points();
    let below = cut_points
        .iter()
        .flatten()
        .filter(|c| c.lower().is_some())
        .count();
    Some(match below {
        0 => Regime::Above,
        n if n == cut_points.len() * D => Regime::AtOrBelow,
        _ => Regime::Mixed,
    })
}

/// Points as a list, or as a grid of `grid`'s shape.
fn shaped<T: Copy>(points: Points<T>, grid: Option<[usize; 2]>) -> Points<T> {
    match grid {
        Some(shape) => points.into_grid(shape),
        None => points,
    }
}

/// The control points of every stage, as a list or (for a net) a grid.
fn control_points<const D: usize>(
    points: &[Nt2Point<D>],
    stages: &PointStages<D>,
    grid: Option<[usize; 2]>,
) -> ControlPoints {
    let of = |f: &dyn Fn(&Nt2Point<D>) -> [f64; D]| {
        shaped(
            Points::from_points(&points.iter().map(f).collect::<Vec<_>>()),
            grid,
        )
    };
    let cut_points = stages.alpha_cut_points();
    ControlPoints {
        crisp: of(&|p| p.crisp()),
        layers: SixLayers::from_fn(|l| of(&|p| p.layer(l))),
        alpha_cut: SixLayers::from_fn(|l| {
            let cut: Vec<[Option<f64>; D]> = cut_points
                .iter()
                .map(|cuts| std::array::from_fn(|d| cuts.get(d).and_then(|c| c.layer(l))))
                .collect();
            shaped(Points::from_points(&cut), grid)
        }),
        type_reduced_left: shaped(
            Points::from_points(&stages.type_reduced_side(Side::Left)),
            grid,
        ),
        type_reduced_right: shaped(
            Points::from_points(&stages.type_reduced_side(Side::Right)),
            grid,
        ),
        defuzzified: shaped(Points::from_points(stages.defuzzified_points()), grid),
    }
}

/// The weights of every stage where they are fuzzy.
fn weight_stages(
    numbers: Option<&[Nt2Number]>,
    stages: Option<&PointStages<1>>,
) -> Option<WeightStages> {
    let points: Vec<Nt2Point<1>> = numbers?.iter().map(|&w| Nt2Point::new([w])).collect();
    Some(WeightStages::of(&control_points(&points, stages?, None)))
}

/// The exact envelope of a curve at `params` at level `alpha`, per
/// membership function (docs/method.md §16).
fn envelope<const D: usize>(
    curve: &FuzzyCurve<D>,
    params: &[f64],
    alpha: Alpha,
) -> Result<Envelope, Error> {
    let of = |m: Membership| -> Result<Option<LeftRight<Points>>, Error> {
        let (mut left, mut right) = (
            Vec::with_capacity(params.len()),
            Vec::with_capacity(params.len()),
        );
        for &t in params {
            let Some(ranges) = curve.envelope_at(t, m, alpha)? else {
                return Ok(None);
            };
            left.push(ranges.map(|r| r.left()));
            right.push(ranges.map(|r| r.right()));
        }
        Ok(Some(LeftRight {
            left: Points::from_points(&left),
            right: Points::from_points(&right),
        }))
    };
    // Every number has upper and primary cuts at every level.
    let missing = || Error::Setting {
        setting: Setting::Alpha,
        message: format!(
            "alpha = {}: a number has no upper or primary cut",
            alpha.get()
        ),
    };
    Ok(Envelope {
        upper: of(Membership::Upper)?.ok_or_else(missing)?,
        primary: of(Membership::Primary)?.ok_or_else(missing)?,
        lower: of(Membership::Lower)?,
    })
}

/// The sampled stages of a sweep at one level, as lists or (for a surface) as
/// grids of `grid`'s shape.
fn sampled<const D: usize>(
    sweep: SweepSamples<D>,
    params: Parameters,
    grid: Option<[usize; 2]>,
) -> Result<Sampled, Error> {
    let points = |samples: CurveSamples<D>| shaped(Points::from(samples), grid);
    let mut layers = sweep.layers.layers.map(Some);
    let mut take = |l: Layer| points(layers[l].take().unwrap_or_else(CurveSamples::empty));
    // A sweep of one level gives one level.
    let level = sweep
        .levels
        .into_iter()
        .next()
        .ok_or_else(|| wrong_samples("a sweep without levels", "a run"))?;
    let mut cuts = level.alpha_cut;
    let [left, right] = level.type_reduced;
    Ok(Sampled {
        params,
        crisp: take(Layer::Crisp),
        layers: SixLayers::from_fn(&mut take),
        defuzzified: points(level.defuzzified),
        alpha_cut: SixLayers::from_fn(|l| cuts[l].take().map(points)),
        type_reduced: LeftRight {
            left: points(left),
            right: points(right),
        },
        derivatives: None,
        arc_length: None,
        envelope: None,
    })
}

/// The derivatives of orders `1 ..= order` of the crisp curve of `curve` and
/// of the `defuzzified` curve at `params`, and their arc lengths.
fn derivative_curves<const D: usize>(
    curve: &FuzzyCurve<D>,
    defuzzified: &NurbsCurve<D>,
    params: &[f64],
    order: usize,
) -> Result<(CrispDefuzzified<Vec<Points>>, CrispDefuzzified<f64>), Error> {
    let crisp = curve.crisp_curve();
    let derivatives = |c: &NurbsCurve<D>, name: &'static str| -> Result<Vec<Points>, Error> {
        let mut columns = vec![vec![Vec::with_capacity(params.len()); D]; order];
        for (i, &t) in params.iter().enumerate() {
            let at = c.derivatives(t, order)?;
            // `at` holds the point and its derivatives of orders 1 ..= order.
            for (k, (column, derivative)) in columns.iter_mut().zip(at.iter().skip(1)).enumerate() {
                for (axis, (values, &value)) in column.iter_mut().zip(derivative).enumerate() {
                    if !value.is_finite() {
                        return Err(Error::DerivativeOverflow {
                            curve: name,
                            derivative: k + 1,
                            sample: i,
                            axis,
                            value,
                        });
                    }
                    values.push(value);
                }
            }
        }
        Ok(columns.into_iter().map(Points::from_coords).collect())
    };
    Ok((
        CrispDefuzzified {
            crisp: derivatives(&crisp, "crisp")?,
            defuzzified: derivatives(defuzzified, "defuzzified")?,
        },
        CrispDefuzzified {
            crisp: finite_length(crisp.arc_length(), "crisp")?,
            defuzzified: finite_length(defuzzified.arc_length(), "defuzzified")?,
        },
    ))
}

/// An arc length, or an error if it is beyond the range of a float (a speed
/// of `coordinate / knot span` can be).
fn finite_length(length: f64, curve: &'static str) -> Result<f64, Error> {
    if length.is_finite() {
        Ok(length)
    } else {
        Err(Error::ArcLengthOverflow {
            curve,
            value: length,
        })
    }
}
