//! The inner loops of [`Sampler`]: blocks of parameters, runs of parameters in
//! one span, and Horner's rule for a fixed order so that the compiler unrolls it
//! and vectorises across parameters.
//!
//! Orders 1–8 are compiled as separate loops, so that Horner's rule is unrolled
//! and vectorised across parameters; higher orders take a generic loop with the
//! same operations. Blocks of 512 parameters keep the parameters, their local
//! variables and the reciprocal denominators in the first-level cache. Sorted
//! parameters (always so for the uniform grid, checked once for given ones)
//! are walked span to span, the end of each run found by binary search within
//! the block; otherwise runs are scanned eight parameters at a time and each
//! new span found by binary search. There is no `unsafe` and no
//! target-specific code: the portable x86-64 baseline.

use super::params::{Params, BLOCK};
use super::sampler::Sampler;
use crate::sampling::power_form::Span;

/// Evaluates the parameters `first ..` of `params` (as many as each slice of
/// `out` is long) into `out`, one slice per channel; `sorted` says that the
/// parameters never decrease.
pub(crate) fn run(
    sampler: &Sampler,
    params: Params<'_>,
    sorted: bool,
    first: usize,
    out: &mut [&mut [f64]],
) {
    let Some(len) = out.first().map(|o| o.len()) else {
        return; // No channels: nothing to compute.
    };
    let domain = sampler.domain();
    let spans = sampler.spans();
    let mut t = [0.0; BLOCK];
    let mut s = [0.0; BLOCK];
    let mut r = [0.0; BLOCK];
    let mut span = 0;
    let mut done = 0;
    while done < len {
        let n = BLOCK.min(len - done);
        params.fill(domain, first + done, &mut t[..n]);
        let mut i = 0;
        while i < n {
            span = locate(spans, span, t[i]);
            let j = if sorted {
                sorted_run_end(spans, span, &t[..n], i + 1)
            } else {
                run_end(spans, span, &t[..n], i + 1)
            };
            evaluate(
                sampler,
                span,
                &t[i..j],
                &mut s[..j - i],
                &mut r[..j - i],
                out,
                done + i,
            );
            i = j;
        }
        apply_bounds(sampler, out, done..done + n);
        done += n;
    }
}

/// Whether `t` (in the domain) belongs to span `k`: `[start, end)`, or
/// `[start, end]` for the last span.
#[inline]
fn contains(spans: &[Span], k: usize, t: f64) -> bool {
    let sp = &spans[k];
    sp.start <= t && (t < sp.end || k + 1 == spans.len())
}

/// The first index `j ≥ from` of `t` whose parameter is not in span `k` (or
/// `t.len()`). Tests eight parameters at a time without branching, so that a
/// long sorted run costs a few vector comparisons per eight parameters.
#[inline]
fn run_end(spans: &[Span], k: usize, t: &[f64], from: usize) -> usize {
    let sp = &spans[k];
    // The last span is closed on the right; every parameter is in the domain.
    let end = if k + 1 == spans.len() {
        f64::INFINITY
    } else {
        sp.end
    };
    let mut j = from;
    while j + 8 <= t.len() {
        let all = t[j..j + 8]
            .iter()
            .fold(true, |all, &x| all & (sp.start <= x) & (x < end));
        if !all {
            break;
        }
        j += 8;
    }
    j + t[j..]
        .iter()
        .take_while(|&&x| sp.start <= x && x < end)
        .count()
}

/// [`run_end`] for parameters that never decrease (and `t[from − 1]` in span
/// `k`): a binary search for the first one past the span's end.
#[inline]
fn sorted_run_end(spans: &[Span], k: usize, t: &[f64], from: usize) -> usize {
    if k + 1 == spans.len() {
        return t.len(); // The last span takes the rest of the domain.
    }
    let end = spans[k].end;
    from + t[from..].partition_point(|&x| x < end)
}

/// The span of `t` (in the domain): the hint or its successor when parameters
/// are sorted, otherwise by binary search (the span to the right of an interior
/// knot, the last span at the right end).
#[inline]
fn locate(spans: &[Span], hint: usize, t: f64) -> usize {
    if contains(spans, hint, t) {
        hint
    } else if hint + 1 < spans.len() && contains(spans, hint + 1, t) {
        hint + 1
    } else {
        spans
            .partition_point(|sp| sp.start <= t)
            .saturating_sub(1)
            .min(spans.len() - 1)
    }
}

/// Evaluates the parameters `t`, all in span `span`, into `out[..][at ..]`;
/// `s` and `r` are scratch of `t.len()`. An ill-conditioned span is evaluated
/// from the basis instead (`direct.rs`).
#[inline]
fn evaluate(
    sampler: &Sampler,
    span: usize,
    t: &[f64],
    s: &mut [f64],
    r: &mut [f64],
    out: &mut [&mut [f64]],
    at: usize,
) {
    let sp = sampler.spans()[span];
    if let (true, Some(direct)) = (sp.direct, sampler.direct()) {
        direct.evaluate(&sp, t, out, at);
        return;
    }
    let table = sampler.span_table(span);
    match sampler.order() {
        1 => evaluate_order::<1>(&sp, table, t, s, r, out, at),
        2 => evaluate_order::<2>(&sp, table, t, s, r, out, at),
        3 => evaluate_order::<3>(&sp, table, t, s, r, out, at),
        4 => evaluate_order::<4>(&sp, table, t, s, r, out, at),
        5 => evaluate_order::<5>(&sp, table, t, s, r, out, at),
        6 => evaluate_order::<6>(&sp, table, t, s, r, out, at),
        7 => evaluate_order::<7>(&sp, table, t, s, r, out, at),
        8 => evaluate_order::<8>(&sp, table, t, s, r, out, at),
        order => evaluate_any(order, &sp, table, t, s, r, out, at),
    }
}

/// `Σₖ c[k]·sᵏ` by Horner's rule, `K` coefficients.
#[inline(always)]
fn horner<const K: usize>(c: &[f64; K], s: f64) -> f64 {
    let mut acc = c[K - 1];
    for k in (0..K - 1).rev() {
        acc = acc * s + c[k];
    }
    acc
}

/// Horner's rule for any number of coefficients, with the same operations in
/// the same order as [`horner`].
#[inline]
fn horner_any(c: &[f64], s: f64) -> f64 {
    let (last, rest) = c.split_last().unwrap_or((&0.0, &[]));
    rest.iter().rev().fold(*last, |acc, &ck| acc * s + ck)
}

/// [`evaluate_with`] for `K` coefficients held in registers.
#[inline(always)]
fn evaluate_order<const K: usize>(
    sp: &Span,
    table: &[f64],
    t: &[f64],
    s: &mut [f64],
    r: &mut [f64],
    out: &mut [&mut [f64]],
    at: usize,
) {
    let load = |row: &[f64]| -> [f64; K] { std::array::from_fn(|k| row[k]) };
    evaluate_with(K, load, horner::<K>, sp, table, t, s, r, out, at);
}

/// [`evaluate_with`] for any number of coefficients.
#[allow(clippy::too_many_arguments)]
fn evaluate_any(
    order: usize,
    sp: &Span,
    table: &[f64],
    t: &[f64],
    s: &mut [f64],
    r: &mut [f64],
    out: &mut [&mut [f64]],
    at: usize,
) {
    let load = |row: &[f64]| row.to_vec();
    let horner = |c: &Vec<f64>, x: f64| horner_any(c, x);
    evaluate_with(order, load, horner, sp, table, t, s, r, out, at);
}

/// Evaluates the parameters `t` of one span: the local variable `s` and the
/// reciprocal denominator `r` first, then every channel as `V(s)·r` into
/// `out[channel][at ..]`. `load` turns a row of `order` coefficients into the
/// form `horner` evaluates.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn evaluate_with<C>(
    order: usize,
    load: impl Fn(&[f64]) -> C,
    horner: impl Fn(&C, f64) -> f64,
    sp: &Span,
    table: &[f64],
    t: &[f64],
    s: &mut [f64],
    r: &mut [f64],
    out: &mut [&mut [f64]],
    at: usize,
) {
    let denominator = load(&table[..order]);
    for ((s, r), &t) in s.iter_mut().zip(r.iter_mut()).zip(t) {
        let x = sp.local(t);
        *s = x;
        // W > 0: the basis is non-negative, sums to 1, and the weights are > 0.
        *r = 1.0 / horner(&denominator, x);
    }
    for (row, o) in table[order..].chunks_exact(order).zip(out.iter_mut()) {
        let c = load(row);
        let o = &mut o[at..at + t.len()];
        for ((o, &x), &r) in o.iter_mut().zip(s.iter()).zip(r.iter()) {
            *o = horner(&c, x) * r;
        }
    }
}

/// Applies the sampler's bounds to `range` of every channel.
fn apply_bounds(sampler: &Sampler, out: &mut [&mut [f64]], range: std::ops::Range<usize>) {
    for b in sampler.bounds() {
        if let Some(lo) = b.at_least {
            let (o, l) = pair(out, b.channel, lo);
            // `if` rather than `f64::max`: no NaN here, and this form compiles
            // to packed max instructions.
            for (o, &l) in o[range.clone()].iter_mut().zip(&l[range.clone()]) {
                *o = if *o < l { l } else { *o };
            }
        }
        if let Some(hi) = b.at_most {
            let (o, h) = pair(out, b.channel, hi);
            for (o, &h) in o[range.clone()].iter_mut().zip(&h[range.clone()]) {
                *o = if *o > h { h } else { *o };
            }
        }
    }
}

/// Channel `write` mutably and channel `read` (another one) shared.
fn pair<'a>(out: &'a mut [&mut [f64]], write: usize, read: usize) -> (&'a mut [f64], &'a [f64]) {
    if read < write {
        let (head, tail) = out.split_at_mut(write);
        (&mut *tail[0], &*head[read])
    } else {
        let (head, tail) = out.split_at_mut(read);
        (&mut *head[write], &*tail[0])
    }
}
