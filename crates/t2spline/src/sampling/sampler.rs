//! The sampling engine: many curves with one knot vector and one set of weights,
//! evaluated together from one power form per span.

use super::buffer::{Fresh, SampleBuffer};
use super::params::Params;
use crate::error::{Error, Place};
use crate::nurbs::curve::check_weights;
use crate::nurbs::{Domain, KnotVector};
use crate::sampling::direct::Direct;
use crate::sampling::kernel;
use crate::sampling::power_form::{PowerBasis, Span};

/// A rule that keeps one sampled channel between two others, applied after
/// evaluation: `out[channel] = clamp(out[channel], out[at_least], out[at_most])`.
///
/// Use it only where the exact curves obey the order (for instance layer curves
/// whose control values are ordered, docs/method.md §6): then it only removes rounding,
/// and never moves a value further from the exact one than the rounding error
/// of its neighbour. Bounds are applied in the order given, so a bound may rely
/// on channels that earlier bounds have settled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bound {
    /// The channel to clamp.
    pub channel: usize,
    /// A channel it must not be below.
    pub at_least: Option<usize>,
    /// A channel it must not be above.
    pub at_most: Option<usize>,
}

/// Evaluates many rational B-spline curves that share one knot vector and one
/// set of weights — the seven layer curves of a fuzzy curve, the curves of every
/// stage at any number of alpha levels — at many parameters (docs/method.md §6–§7).
///
/// A *channel* is one coordinate of one curve: the values `vᵢ` it takes at the
/// control points. On construction every non-empty span is converted once to
/// power form in its local variable `s ∈ [−1, 1]` (see `power_form.rs`), for
/// the common denominator and for every channel's numerator:
///
/// ```text
/// W(s) = Σₖ dₖ sᵏ = Σⱼ wⱼ Nⱼ,ₚ(t),   Vᶜ(s) = Σₖ aᶜₖ sᵏ = Σⱼ wⱼ Nⱼ,ₚ(t) vᶜⱼ,   Cᶜ(t) = Vᶜ(s) / W(s)
/// ```
/// so a parameter costs one Horner evaluation and one division for the
/// denominator and one Horner evaluation and one multiplication per channel.
/// Sorted parameters are walked span by span, unsorted ones are found by binary
/// search; the value at an interior knot is taken from the right and the right
/// end of the domain uses the last non-empty span, as [`crate::NurbsCurve::eval`]
/// does. Output is one array per channel (structure of arrays). With the
/// `parallel` feature, large jobs are split into chunks over rayon's threads;
/// every value is computed by the same operations in either case, so the results
/// are bit for bit the same.
///
/// # Examples
/// ```
/// # use t2spline::{KnotVector, NurbsCurve};
/// # use t2spline::sampling::{Params, Sampler};
/// // Two channels (x and y) of the rational quarter circle.
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let knots = KnotVector::clamped_uniform(2, 3)?;
/// let sampler = Sampler::try_new(&knots, &[1.0, w, 1.0], &[[1.0, 1.0, 0.0], [0.0, 1.0, 1.0]])?;
/// let [x, y] = <[Vec<f64>; 2]>::try_from(sampler.sample(Params::Uniform(11))?).unwrap();
/// assert!(x.iter().zip(&y).all(|(x, y)| (x.hypot(*y) - 1.0).abs() < 1e-14));
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Sampler {
    domain: Domain,
    order: usize,
    spans: Vec<Span>,
    channels: usize,
    /// Per span: `channels + 1` rows of `order` power coefficients, row 0 the
    /// denominator.
    table: Vec<f64>,
    /// For spans evaluated directly ([`Span::direct`]); `None` if there are none.
    direct: Option<Direct>,
    bounds: Vec<Bound>,
}

/// Below this many channel values a job runs on the calling thread: splitting
/// costs more than it saves.
#[cfg(feature = "parallel")]
const PARALLEL_MIN_VALUES: usize = 1 << 16;

/// Smallest number of parameters per parallel task.
#[cfg(feature = "parallel")]
const MIN_CHUNK: usize = 4096;

impl Sampler {
    /// Prepares `channels` (each one value per control point) for sampling, with
    /// the curve's knots and weights.
    ///
    /// # Errors
    /// [`Error::WeightCount`] or [`Error::Weight`] for wrong weights;
    /// [`Error::Length`] if a channel does not have one value per control point;
    /// [`Error::NotFinite`] for a value that is NaN or infinite.
    pub fn try_new<C: AsRef<[f64]>>(
        knots: &KnotVector,
        weights: &[f64],
        channels: &[C],
    ) -> Result<Self, Error> {
        let n = knots.count();
        check_weights(weights, n)?;
        for channel in channels {
            let values = channel.as_ref();
            if values.len() != n {
                return Err(Error::Length {
                    what: "channel values (one per control point)",
                    expected: n,
                    found: values.len(),
                });
            }
            if let Some((i, &value)) = values.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(Error::NotFinite {
                    place: Place {
                        point: Some(i),
                        ..Place::NONE
                    },
                    what: "channel value",
                    value,
                });
            }
        }
        Ok(Self::new_unchecked(knots, weights, channels))
    }

    /// [`Sampler::try_new`] for inputs known to be valid.
    pub(crate) fn new_unchecked<C: AsRef<[f64]>>(
        knots: &KnotVector,
        weights: &[f64],
        channels: &[C],
    ) -> Self {
        let basis = PowerBasis::new(knots, weights);
        let order = basis.order();
        let rows = channels.len() + 1;
        let mut table = Vec::with_capacity(basis.spans().len() * rows * order);
        for (k, span) in basis.spans().iter().enumerate() {
            let c = basis.span_coefficients(k);
            // Row 0: the denominator Σⱼ wⱼNⱼ; then each channel's numerator.
            for power in 0..order {
                table.push((0..order).map(|j| c[j * order + power]).sum());
            }
            for channel in channels {
                let v = &channel.as_ref()[span.first..span.first + order];
                for power in 0..order {
                    table.push((0..order).map(|j| c[j * order + power] * v[j]).sum());
                }
            }
        }
        let direct = basis
            .spans()
            .iter()
            .any(|s| s.direct)
            .then(|| Direct::new(knots.as_slice(), knots.degree(), weights, channels));
        Sampler {
            domain: knots.domain(),
            order,
            spans: basis.spans().to_vec(),
            channels: channels.len(),
            table,
            direct,
            bounds: Vec::new(),
        }
    }

    /// [`Sampler::new_unchecked`] for sampling `count` parameters. With fewer
    /// parameters than knot spans the power form is not built: converting a
    /// span costs more than evaluating one parameter from the basis, and most
    /// spans would serve none (a job of 100 000 control points of order 32
    /// spent a third of its time there for 101 samples). Every span is then
    /// evaluated directly, as ill-conditioned spans always are.
    pub(crate) fn for_count_unchecked<C: AsRef<[f64]>>(
        knots: &KnotVector,
        weights: &[f64],
        channels: &[C],
        count: usize,
    ) -> Self {
        if count >= knots.spans().count() {
            return Self::new_unchecked(knots, weights, channels);
        }
        let p = knots.degree();
        let spans = knots
            .spans()
            .map(|(i, [start, end])| Span::direct(start, end, i - p))
            .collect();
        Sampler {
            domain: knots.domain(),
            order: p + 1,
            spans,
            channels: channels.len(),
            table: Vec::new(),
            direct: Some(Direct::new(knots.as_slice(), p, weights, channels)),
            bounds: Vec::new(),
        }
    }

    /// Adds order-keeping rules, applied in the given order after evaluation. A
    /// channel bounded by itself is left as it is.
    ///
    /// # Errors
    /// [`Error::Length`] if a bound names a channel that does not exist.
    pub fn with_bounds(mut self, bounds: &[Bound]) -> Result<Self, Error> {
        for b in bounds {
            let worst = [Some(b.channel), b.at_least, b.at_most]
                .into_iter()
                .flatten()
                .max()
                .unwrap_or(0);
            if worst >= self.channels {
                return Err(Error::Length {
                    what: "channels (a bound names a channel past the last)",
                    expected: self.channels,
                    found: worst + 1,
                });
            }
        }
        // A channel bounded by itself is left as it is: drop such halves.
        let own = |c: Option<usize>, channel: usize| c.filter(|&c| c != channel);
        self.bounds.extend(bounds.iter().map(|b| Bound {
            channel: b.channel,
            at_least: own(b.at_least, b.channel),
            at_most: own(b.at_most, b.channel),
        }));
        Ok(self)
    }

    /// The number of channels.
    #[must_use]
    pub fn channels(&self) -> usize {
        self.channels
    }

    /// The parameter domain.
    #[must_use]
    pub fn domain(&self) -> Domain {
        self.domain
    }

    /// Samples every channel at `params`; one vector per channel.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample<'a>(&self, params: impl Into<Params<'a>>) -> Result<Vec<Vec<f64>>, Error> {
        self.sample_reusing(params, &mut Vec::new())
    }

    /// Samples every channel at `params` into vectors taken from `buffers` (and
    /// new ones when it runs out), resized to `params.len()`: repeated sampling
    /// reuses memory the operating system has already handed over.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample_reusing<'a>(
        &self,
        params: impl Into<Params<'a>>,
        buffers: &mut Vec<Vec<f64>>,
    ) -> Result<Vec<Vec<f64>>, Error> {
        let mut own: Vec<SampleBuffer> = buffers.drain(..).map(SampleBuffer::from).collect();
        let out = self.sample_buffers(params, &mut own, Fresh::Vectors);
        buffers.extend(own.into_iter().map(SampleBuffer::into_vec));
        Ok(out?.into_iter().map(SampleBuffer::into_vec).collect())
    }

    /// Samples every channel at `params` into buffers taken from `buffers`
    /// (resized), and new ones from `fresh` when it runs out.
    pub(crate) fn sample_buffers<'a>(
        &self,
        params: impl Into<Params<'a>>,
        buffers: &mut Vec<SampleBuffer>,
        fresh: Fresh,
    ) -> Result<Vec<SampleBuffer>, Error> {
        let params = params.into();
        let sorted = params.check(self.domain)?;
        let n = params.len();
        let mut out = outputs(self.channels, n, buffers, fresh)?;
        let mut slices: Vec<&mut [f64]> = out.iter_mut().map(|b| &mut **b).collect();
        self.run(params, sorted, &mut slices);
        Ok(out)
    }

    /// Samples every channel at `params` into `out`, one slice per channel, each
    /// as long as `params`; reuses the caller's memory.
    ///
    /// # Errors
    /// [`Error::Length`] if `out` has the wrong number or length of slices;
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample_into<'a>(
        &self,
        params: impl Into<Params<'a>>,
        out: &mut [&mut [f64]],
    ) -> Result<(), Error> {
        let params = params.into();
        check_outputs(
            out,
            self.channels,
            params.len(),
            "output values (one per parameter)",
        )?;
        let sorted = params.check(self.domain)?;
        self.run(params, sorted, out);
        Ok(())
    }

    /// Runs a checked job, in parallel when it is large enough; `sorted` says
    /// that the parameters never decrease.
    fn run(&self, params: Params<'_>, sorted: bool, out: &mut [&mut [f64]]) {
        #[cfg(feature = "parallel")]
        {
            let threads = rayon::current_num_threads();
            if threads > 1 && params.len().saturating_mul(self.channels + 1) >= PARALLEL_MIN_VALUES
            {
                let chunk = params
                    .len()
                    .div_ceil(threads * 4)
                    .next_multiple_of(super::params::BLOCK)
                    .max(MIN_CHUNK);
                self.run_parallel(params, sorted, out, chunk);
                return;
            }
        }
        self.run_serial(params, sorted, 0, out);
    }

    /// Evaluates the parameters `first ..` (as many as each slice of `out` is
    /// long) on the calling thread.
    pub(crate) fn run_serial(
        &self,
        params: Params<'_>,
        sorted: bool,
        first: usize,
        out: &mut [&mut [f64]],
    ) {
        kernel::run(self, params, sorted, first, out);
    }

    /// Splits the job into chunks of `chunk` parameters and runs them on rayon's
    /// threads; each chunk is [`Sampler::run_serial`] on its part of every slice.
    #[cfg(feature = "parallel")]
    pub(crate) fn run_parallel(
        &self,
        params: Params<'_>,
        sorted: bool,
        out: &mut [&mut [f64]],
        chunk: usize,
    ) {
        use rayon::prelude::*;
        let tasks = params.len().div_ceil(chunk);
        let mut jobs: Vec<(usize, Vec<&mut [f64]>)> = (0..tasks)
            .map(|k| (k * chunk, Vec::with_capacity(out.len())))
            .collect();
        for slice in out.iter_mut() {
            for (job, piece) in jobs.iter_mut().zip(slice.chunks_mut(chunk)) {
                job.1.push(piece);
            }
        }
        jobs.into_par_iter()
            .for_each(|(first, mut pieces)| self.run_serial(params, sorted, first, &mut pieces));
    }

    pub(crate) fn order(&self) -> usize {
        self.order
    }

    pub(crate) fn spans(&self) -> &[Span] {
        &self.spans
    }

    pub(crate) fn bounds(&self) -> &[Bound] {
        &self.bounds
    }

    /// The table rows of one span: denominator, then one per channel.
    /// The data of the direct evaluation, if a span needs it.
    pub(crate) fn direct(&self) -> Option<&Direct> {
        self.direct.as_ref()
    }

    pub(crate) fn span_table(&self, span: usize) -> &[f64] {
        let size = (self.channels + 1) * self.order;
        &self.table[span * size..(span + 1) * size]
    }
}

/// `channels` output buffers of `n` values, taken from `buffers` (resized)
/// while it has them, else new from `fresh`. Nothing is written into a new
/// buffer: its pages are first touched by the threads that fill them.
///
/// # Errors
/// [`Error::Memory`] if `n` values are more than a vector can hold (memory
/// the system cannot give still ends the process, as any allocation does).
pub(crate) fn outputs(
    channels: usize,
    n: usize,
    buffers: &mut Vec<SampleBuffer>,
    fresh: Fresh,
) -> Result<Vec<SampleBuffer>, Error> {
    if n.checked_mul(size_of::<f64>())
        .is_none_or(|bytes| bytes > isize::MAX as usize)
    {
        return Err(Error::Memory { values: n });
    }
    Ok((0..channels)
        .map(|_| match buffers.pop() {
            Some(mut b) => {
                b.resize(n, fresh);
                b
            }
            // Untouched memory (a zeroed allocation, a new or cached
            // mapping): nothing is written before the engine writes.
            None => SampleBuffer::fresh(n, fresh),
        })
        .collect())
}

/// Checks caller-given outputs: one slice per channel, each of `n` values.
///
/// # Errors
/// [`Error::Length`] naming what is wrong (`values` says what the `n` values
/// are).
pub(crate) fn check_outputs(
    out: &[&mut [f64]],
    channels: usize,
    n: usize,
    values: &'static str,
) -> Result<(), Error> {
    if out.len() != channels {
        return Err(Error::Length {
            what: "output slices (one per channel)",
            expected: channels,
            found: out.len(),
        });
    }
    if let Some(o) = out.iter().find(|o| o.len() != n) {
        return Err(Error::Length {
            what: values,
            expected: n,
            found: o.len(),
        });
    }
    Ok(())
}
