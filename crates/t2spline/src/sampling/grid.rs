//! The grid engine: many surfaces that share one net of weights and two knot
//! vectors, evaluated together on a grid of parameters `u_a × v_b`.
//!
//! The tensor product is contracted one direction at a time: per grid row the
//! isoparametric curve in homogeneous form, per grid column the basis in v, per
//! point two dot products of length `q + 1`. Unlike the curve engine it needs
//! no power form: the basis values of a column are computed once and reused by
//! every row, so a point costs the multiply-adds of Horner's rule, and every
//! coefficient `NᵢwᵢⱼMⱼ` is non-negative, which keeps the layers' order bit for
//! bit with no clamp and no conditioning limit (no fallback path). The
//! rational-basis form (coefficients `MⱼWⱼ/W` per point) was tried first: the
//! same accuracy and order, but `q + 1` more products and a scratch array per
//! point.

use super::buffer::{Fresh, SampleBuffer};
use super::params::Params;
use super::params::BLOCK;
use crate::error::{Error, Place};
use crate::nurbs::basis::basis_functions;
use crate::nurbs::surface::net_weights_flat;
use crate::nurbs::{Direction, KnotVector};
use crate::sampling::sampler::{check_outputs, outputs};

/// Evaluates many rational B-spline surfaces that share knots `[U, V]` and a
/// net of weights — the seven layer surfaces of a fuzzy surface, the surfaces
/// of every stage at any number of alpha levels — on a grid `u_a × v_b`
/// (docs/method.md §8). A *channel* is one coordinate of one surface: its values `xᵢⱼ`
/// at the control points, row by row.
///
/// The tensor product is contracted one direction at a time, in homogeneous
/// form (The NURBS Book Eq. 4.15):
///
/// ```text
/// per u_a (once per grid row):    Wⱼ = Σᵢ Nᵢ(u_a) wᵢⱼ,   Hᶜⱼ = Σᵢ Nᵢ(u_a) wᵢⱼ xᶜᵢⱼ
/// per v_b (once per grid column): Mⱼ(v_b)
/// per (a, b):                     Sᶜ(u_a, v_b) = Σⱼ Mⱼ(v_b) Hᶜⱼ · 1/Σⱼ Mⱼ(v_b) Wⱼ
/// ```
/// The first line is the isoparametric curve at `u_a` (homogeneous control
/// points `(Hⱼ, Wⱼ)`), the last evaluates it at `v_b`. The basis in u is
/// computed once per grid row and the basis in v once per grid column, for all
/// channels; a grid point costs `q + 1` multiply-adds and one division for the
/// denominator, then `q + 1` multiply-adds and one product per channel. Every
/// coefficient `Nᵢ wᵢⱼ Mⱼ` is non-negative and shared by all channels, so
/// channels whose control values are ordered give ordered values, exactly (no
/// clamping is needed), and no sum cancels beyond what the control values do:
/// the relative accuracy of [`NurbsSurface::eval`](crate::NurbsSurface::eval)
/// whatever the weights (tested with weights from 1e-12 to 1e12). As for the
/// operations on homogeneous coordinates (see `limits.rs`), a coordinate below
/// 1e-150 multiplied by a weight below 1 keeps an absolute accuracy of about
/// `1e-308 / weight` rather than its relative one. Spans follow `eval`: from
/// the right at an interior knot, the last non-empty span at the end of a
/// domain.
///
/// Output is one vector per channel of `su·sv` values, `[a·sv + b]` for
/// `(u_a, v_b)` (structure of arrays). With the `parallel` feature, large jobs
/// are split by grid rows over rayon's threads; every value is computed by the
/// same operations in any split, so the results are bit for bit the same.
///
/// # Examples
/// ```
/// # use t2spline::KnotVector;
/// # use t2spline::sampling::{GridSampler, Params};
/// // The bilinear patch (u, v, u·v) as three channels on a 2 × 2 net.
/// let k = KnotVector::clamped_uniform(1, 2)?;
/// let x = [0.0, 0.0, 1.0, 1.0];
/// let y = [0.0, 1.0, 0.0, 1.0];
/// let z = [0.0, 0.0, 0.0, 1.0];
/// let g = GridSampler::try_new(&[k.clone(), k], &[1.0; 4], &[x, y, z])?;
/// let out = g.sample(Params::Uniform(3), Params::Uniform(5))?;
/// assert_eq!(out[2][1 * 5 + 2], 0.25); // z at (u, v) = (0.5, 0.5)
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct GridSampler {
    knots: [KnotVector; 2],
    weights: Vec<f64>,
    /// `values[c]`: channel `c`'s value at every control point, row by row.
    values: Vec<Vec<f64>>,
}

/// Below this many channel values a job runs on the calling thread.
#[cfg(feature = "parallel")]
const PARALLEL_MIN_VALUES: usize = 1 << 16;

/// The basis in v at every grid column: its span's first control point and
/// the `q + 1` values, stored `[j·sv + b]` so that a run of columns reads
/// each `Mⱼ` contiguously.
struct Columns {
    first: Vec<usize>,
    basis: Vec<f64>,
}

impl GridSampler {
    /// Prepares `channels` (each one value per control point, row by row) for
    /// sampling with the knots `[U, V]` and the `nu·nv` weights (row by row).
    ///
    /// # Errors
    /// [`Error::Length`] if the weights or a channel do not have one value per
    /// control point; [`Error::NetWeight`] for a bad weight;
    /// [`Error::NotFinite`] for a channel value that is NaN or infinite.
    pub fn try_new<C: AsRef<[f64]>>(
        knots: &[KnotVector; 2],
        weights: &[f64],
        channels: &[C],
    ) -> Result<Self, Error> {
        let shape = knots.each_ref().map(KnotVector::count);
        let n = shape[0] * shape[1];
        net_weights_flat(weights, shape)?;
        for channel in channels {
            let values = channel.as_ref();
            if values.len() != n {
                return Err(Error::Length {
                    what: "channel values (one per control point)",
                    expected: n,
                    found: values.len(),
                });
            }
            if let Some((k, &value)) = values.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(Error::NotFinite {
                    place: Place {
                        point: Some(k / shape[1]),
                        column: Some(k % shape[1]),
                        axis: None,
                    },
                    what: "channel value",
                    value,
                });
            }
        }
        Ok(Self::new_unchecked(knots, weights, channels))
    }

    /// [`GridSampler::try_new`] for inputs known to be valid.
    pub(crate) fn new_unchecked<C: AsRef<[f64]>>(
        knots: &[KnotVector; 2],
        weights: &[f64],
        channels: &[C],
    ) -> Self {
        GridSampler {
            knots: knots.clone(),
            weights: weights.to_vec(),
            values: channels.iter().map(|c| c.as_ref().to_vec()).collect(),
        }
    }

    /// The number of channels.
    #[must_use]
    pub fn channels(&self) -> usize {
        self.values.len()
    }

    /// Samples every channel on the grid `u × v`; one vector of
    /// `u.len()·v.len()` values per channel, `[a·sv + b]` at `(u_a, v_b)`.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] for the first
    /// parameter outside its domain.
    pub fn sample<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
    ) -> Result<Vec<Vec<f64>>, Error> {
        self.sample_reusing(u, v, &mut Vec::new())
    }

    /// [`GridSampler::sample`] into vectors taken from `buffers` (and new ones
    /// when it runs out): repeated sampling reuses memory.
    ///
    /// # Errors
    /// As [`GridSampler::sample`].
    pub fn sample_reusing<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        buffers: &mut Vec<Vec<f64>>,
    ) -> Result<Vec<Vec<f64>>, Error> {
        let mut own: Vec<SampleBuffer> = buffers.drain(..).map(SampleBuffer::from).collect();
        let out = self.sample_buffers(u, v, &mut own, Fresh::Vectors);
        buffers.extend(own.into_iter().map(SampleBuffer::into_vec));
        Ok(out?.into_iter().map(SampleBuffer::into_vec).collect())
    }

    /// [`GridSampler::sample`] into buffers taken from `buffers` (resized),
    /// and new ones from `fresh` when it runs out.
    pub(crate) fn sample_buffers<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        buffers: &mut Vec<SampleBuffer>,
        fresh: Fresh,
    ) -> Result<Vec<SampleBuffer>, Error> {
        let (u, v) = (u.into(), v.into());
        self.check(u, v)?;
        let n = u
            .len()
            .checked_mul(v.len())
            .ok_or(Error::Memory { values: usize::MAX })?;
        let mut out = outputs(self.channels(), n, buffers, fresh)?;
        let mut slices: Vec<&mut [f64]> = out.iter_mut().map(|b| &mut **b).collect();
        self.run(u, v, &mut slices)?;
        Ok(out)
    }

    /// Samples every channel on the grid `u × v` into `out`, one slice of
    /// `u.len()·v.len()` values per channel.
    ///
    /// # Errors
    /// [`Error::Length`] if `out` has the wrong number or length of slices;
    /// as [`GridSampler::sample`] otherwise.
    pub fn sample_into<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        out: &mut [&mut [f64]],
    ) -> Result<(), Error> {
        let (u, v) = (u.into(), v.into());
        let n = u.len() * v.len();
        check_outputs(
            out,
            self.channels(),
            n,
            "output values (one per grid point)",
        )?;
        self.check(u, v)?;
        self.run(u, v, out)
    }

    fn check(&self, u: Params<'_>, v: Params<'_>) -> Result<(), Error> {
        for (direction, params) in Direction::BOTH.into_iter().zip([u, v]) {
            params
                .check(self.knots[direction.index()].domain())
                .map_err(|e| e.in_direction(direction))?;
        }
        Ok(())
    }

    /// The basis in v at every grid column.
    fn columns(&self, v: &[f64]) -> Columns {
        let k = &self.knots[1];
        let q = k.degree();
        let sv = v.len();
        let mut first = Vec::with_capacity(sv);
        let mut basis = vec![0.0; (q + 1) * sv];
        let mut m = vec![0.0; q + 1];
        for (b, &t) in v.iter().enumerate() {
            let span = k.find_span(t);
            basis_functions(k.as_slice(), q, span, t, &mut m);
            first.push(span - q);
            for (j, x) in m.iter().enumerate() {
                basis[j * sv + b] = *x;
            }
        }
        Columns { first, basis }
    }

    /// Runs a checked job, in parallel by grid rows when it is large enough.
    fn run(&self, u: Params<'_>, v: Params<'_>, out: &mut [&mut [f64]]) -> Result<(), Error> {
        let u = u.to_vec(self.knots[0].domain())?;
        let v = v.to_vec(self.knots[1].domain())?;
        if u.is_empty() || v.is_empty() {
            return Ok(());
        }
        let columns = self.columns(&v);
        #[cfg(feature = "parallel")]
        {
            let threads = rayon::current_num_threads();
            if threads > 1 && u.len() * v.len() * (self.channels() + 1) >= PARALLEL_MIN_VALUES {
                use rayon::prelude::*;
                let rows = u.len().div_ceil(threads * 4).max(1);
                let tasks = u.len().div_ceil(rows);
                let mut jobs: Vec<(usize, Vec<&mut [f64]>)> = (0..tasks)
                    .map(|k| (k * rows, Vec::with_capacity(out.len())))
                    .collect();
                for slice in out.iter_mut() {
                    for (job, piece) in jobs.iter_mut().zip(slice.chunks_mut(rows * v.len())) {
                        job.1.push(piece);
                    }
                }
                jobs.into_par_iter().for_each(|(first, mut pieces)| {
                    let last = (first + rows).min(u.len());
                    self.rows(&u[first..last], &columns, v.len(), &mut pieces);
                });
                return Ok(());
            }
        }
        self.rows(&u, &columns, v.len(), out);
        Ok(())
    }

    /// Evaluates the grid rows at `u` (each of `sv` columns) into `out`.
    fn rows(&self, u: &[f64], columns: &Columns, sv: usize, out: &mut [&mut [f64]]) {
        let (ku, kv) = (&self.knots[0], &self.knots[1]);
        let (p, q) = (ku.degree(), kv.degree());
        let nv = kv.count();
        let mut n = vec![0.0; p + 1];
        let mut w = vec![0.0; nv];
        let mut h = vec![0.0; self.channels() * nv];
        let mut inverse = vec![0.0; BLOCK];
        for (a, &t) in u.iter().enumerate() {
            // The isoparametric curve at u_a in homogeneous form: weights Wⱼ
            // and Hᶜⱼ = Σᵢ Nᵢ wᵢⱼ xᶜᵢⱼ.
            let span = ku.find_span(t);
            basis_functions(ku.as_slice(), p, span, t, &mut n);
            let first = span - p;
            w.fill(0.0);
            h.fill(0.0);
            for (i, ni) in n.iter().enumerate() {
                let row = (first + i) * nv;
                for (j, wj) in w.iter_mut().enumerate() {
                    let c = ni * self.weights[row + j];
                    *wj += c;
                    for (hc, values) in h.chunks_exact_mut(nv).zip(&self.values) {
                        hc[j] += c * values[row + j];
                    }
                }
            }
            // Runs of columns in one span of v, at most a block long.
            let mut b = 0;
            while b < sv {
                let f = columns.first[b];
                let end = (b + BLOCK).min(sv);
                let len = columns.first[b..end]
                    .iter()
                    .take_while(|&&g| g == f)
                    .count();
                let basis: Vec<&[f64]> = (0..=q)
                    .map(|j| &columns.basis[j * sv + b..][..len])
                    .collect();
                let inverse = &mut inverse[..len];
                combine(&basis, &w[f..f + q + 1], inverse);
                for r in inverse.iter_mut() {
                    // Σⱼ Mⱼ Wⱼ > 0: as for evaluation, some Mⱼ ≥ 1/(q + 1) and
                    // every Wⱼ is at least the least weight.
                    *r = 1.0 / *r;
                }
                let at = a * sv + b;
                for (hc, o) in h.chunks_exact(nv).zip(out.iter_mut()) {
                    let o = &mut o[at..at + len];
                    combine(&basis, &hc[f..f + q + 1], o);
                    for (o, r) in o.iter_mut().zip(inverse.iter()) {
                        *o *= r;
                    }
                }
                b += len;
            }
        }
    }
}

/// `o[k] = Σⱼ basis[j][k]·x[j]` for every `k`, with the number of terms fixed
/// at compile time for orders 1–8 (so that the loop over `k` vectorises) and
/// the same operations in the same order otherwise.
fn combine(basis: &[&[f64]], x: &[f64], o: &mut [f64]) {
    match basis.len() {
        1 => combine_fixed::<1>(basis, x, o),
        2 => combine_fixed::<2>(basis, x, o),
        3 => combine_fixed::<3>(basis, x, o),
        4 => combine_fixed::<4>(basis, x, o),
        5 => combine_fixed::<5>(basis, x, o),
        6 => combine_fixed::<6>(basis, x, o),
        7 => combine_fixed::<7>(basis, x, o),
        8 => combine_fixed::<8>(basis, x, o),
        _ => {
            for (k, o) in o.iter_mut().enumerate() {
                *o = basis
                    .iter()
                    .zip(x)
                    .fold(0.0, |acc, (m, xj)| acc + m[k] * xj);
            }
        }
    }
}

#[inline(always)]
fn combine_fixed<const K: usize>(basis: &[&[f64]], x: &[f64], o: &mut [f64]) {
    let x: [f64; K] = std::array::from_fn(|j| x[j]);
    let rows: [&[f64]; K] = std::array::from_fn(|j| &basis[j][..o.len()]);
    for (k, o) in o.iter_mut().enumerate() {
        let mut acc = 0.0;
        for j in 0..K {
            acc += rows[j][k] * x[j];
        }
        *o = acc;
    }
}
