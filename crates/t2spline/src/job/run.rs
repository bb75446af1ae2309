//! Running a job: every stage of Algorithm 1.1 on the control points, every
//! curve sampled, the distance, and the derivatives when asked for.

use crate::error::{Error, Place};
use crate::fuzzy::{Alpha, Layer};
use crate::nurbs::NurbsCurve;
use crate::pipeline::{FuzzyCurve, Side};
use crate::sampling::{CurveSamples, Params};

use super::output::{ControlPoints, CrispDefuzzified, Curves, LeftRight, Regime, SixLayers};
use super::{Job, ModelVisitor, Points, RunOutput, Settings};

impl Job {
    /// Runs stages 1–4 at `settings.alpha` and samples every curve at
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
    ///
    /// # Examples
    /// ```
    /// # use t2spline::job::{Job, Model, Overrides};
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// // A crisp segment from (0, 0) to (3, 4): C' = (3, 4), C'' = 0, length 5.
    /// let n = |c: f64| Nt2Number::try_new(c, [c, c], [c, c], [c, c], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(3.0)?, n(4.0)?])];
    /// let job = Job::new(Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?));
    /// let s = job.settings(&Overrides { alpha: Some(0.5), samples: Some(2), derivatives: Some(2) })?;
    /// let out = job.run(&s)?;
    /// let d = out.curves.derivatives.as_ref().unwrap();
    /// assert_eq!(d.crisp[0].point(1), Some(vec![3.0, 4.0]));
    /// assert_eq!(d.crisp[1].point(1), Some(vec![0.0, 0.0]));
    /// assert!((out.curves.arc_length.unwrap().crisp - 5.0).abs() < 1e-14);
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
        let Settings {
            alpha,
            samples,
            derivatives,
        } = *self.0;
        let mut out = run_curve(curve, alpha, samples)?;
        if let Some(order) = derivatives {
            let (d, lengths) = derivative_curves(curve, alpha, &out.curves.params, order)?;
            out.curves.derivatives = Some(d);
            out.curves.arc_length = Some(lengths);
        }
        Ok(out)
    }
}

fn run_curve<const D: usize>(
    curve: &FuzzyCurve<D>,
    alpha: Alpha,
    samples: usize,
) -> Result<RunOutput, Error> {
    let solution = curve.solve(alpha);
    let params = curve.domain().uniform(samples);
    // Every curve of every stage from one power form of the rational basis.
    let sweep = curve.sample_sweep(Params::Uniform(samples), &[alpha])?;
    let mut layer_curves = sweep.layers.layers.map(Some);
    let level = match sweep.levels.into_iter().next() {
        Some(level) => level,
        // A sweep of one level gives one level; should it not, the stages
        // are sampled on their own.
        None => solution.sample_stages(Params::Uniform(samples))?,
    };
    let mut take =
        |l: Layer| Points::from(layer_curves[l].take().unwrap_or_else(CurveSamples::empty));
    let cut_points = solution.alpha_cut_points();
    let below = cut_points
        .iter()
        .flatten()
        .filter(|c| c.lower().is_some())
        .count();
    let regime = match below {
        0 => Regime::Above,
        n if n == cut_points.len() * D => Regime::AtOrBelow,
        _ => Regime::Mixed,
    };
    let mut cut_curves = level.alpha_cut;
    let [left, right] = level.type_reduced;
    let d = solution.distance();
    Ok(RunOutput {
        description: None,
        dimension: D,
        order: curve.order(),
        degree: curve.degree(),
        weights: curve.weights().to_vec(),
        knots: curve.knots().as_slice().to_vec(),
        domain: [curve.domain().start, curve.domain().end],
        alpha: alpha.get(),
        regime,
        control_points: ControlPoints {
            crisp: Points::from_points(
                &curve.points().iter().map(|p| p.crisp()).collect::<Vec<_>>(),
            ),
            layers: SixLayers::from_fn(|l| {
                Points::from_points(
                    &curve
                        .points()
                        .iter()
                        .map(|p| p.layer(l))
                        .collect::<Vec<_>>(),
                )
            }),
            alpha_cut: SixLayers::from_fn(|l| {
                Points::from_points(
                    &cut_points
                        .iter()
                        .map(|cuts| std::array::from_fn::<_, D, _>(|d| cuts[d].layer(l)))
                        .collect::<Vec<_>>(),
                )
            }),
            type_reduced_left: Points::from_points(&solution.type_reduced_side(Side::Left)),
            type_reduced_right: Points::from_points(&solution.type_reduced_side(Side::Right)),
            defuzzified: Points::from_points(solution.defuzzified_points()),
        },
        curves: Curves {
            crisp: take(Layer::Crisp),
            layers: SixLayers::from_fn(&mut take),
            defuzzified: level.defuzzified.into(),
            alpha_cut: SixLayers::from_fn(|l| cut_curves[l].take().map(Points::from)),
            type_reduced: LeftRight {
                left: left.into(),
                right: right.into(),
            },
            params,
            derivatives: None,
            arc_length: None,
        },
        error: d,
    })
}

/// The derivatives of orders `1 ..= order` of the crisp and the defuzzified
/// curve at `params`, and their arc lengths.
fn derivative_curves<const D: usize>(
    curve: &FuzzyCurve<D>,
    alpha: Alpha,
    params: &[f64],
    order: usize,
) -> Result<(CrispDefuzzified<Vec<Points>>, CrispDefuzzified<f64>), Error> {
    let crisp = curve.crisp_curve();
    let defuzzified = curve.solve(alpha).defuzzified_curve();
    let derivatives = |c: &NurbsCurve<D>, name: &'static str| -> Result<Vec<Points>, Error> {
        let mut columns = vec![vec![Vec::with_capacity(params.len()); D]; order];
        for (i, &t) in params.iter().enumerate() {
            let at = c.derivatives(t, order)?;
            for (k, column) in columns.iter_mut().enumerate() {
                for (axis, values) in column.iter_mut().enumerate() {
                    let value = at[k + 1][axis];
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
            defuzzified: derivatives(&defuzzified, "defuzzified")?,
        },
        CrispDefuzzified {
            crisp: finite_length(crisp.arc_length(), "curves.arc_length.crisp")?,
            defuzzified: finite_length(defuzzified.arc_length(), "curves.arc_length.defuzzified")?,
        },
    ))
}

/// An arc length, or an error if it is beyond the range of a float (a speed
/// of `coordinate / knot span` can be).
fn finite_length(length: f64, what: &'static str) -> Result<f64, Error> {
    if length.is_finite() {
        Ok(length)
    } else {
        Err(Error::NotFinite {
            place: Place::NONE,
            what,
            value: length,
        })
    }
}
