//! What a job and a data file give alike: the order (or degree), alpha and
//! the lower height, and the numbers of samples, each rule checked.

use t2spline::job::check_samples;
use t2spline::{Alpha, Height};

use super::raw::{RawJob, Whole};
use crate::limits::check_order;

/// What a job and a data file give alike, each rule checked: the key that
/// gives the order (`order` or `degree`, exactly one of them) and its value,
/// `alpha`, and the top-level `lower_height`.
pub(super) struct Header {
    pub(super) key: &'static str,
    pub(super) order: Whole,
    pub(super) alpha: Option<Alpha>,
    pub(super) height: Option<f64>,
}

/// The [`Header`] of `raw`, if its rules hold.
pub(super) fn header(raw: &RawJob) -> Option<Header> {
    let (key, order) = match (raw.order, raw.degree) {
        (Some(order), None) => ("order", order),
        (None, Some(degree)) => ("degree", degree),
        _ => return None,
    };
    let alpha = raw.alpha.map(Alpha::try_new).transpose().ok()?;
    let height = match raw.lower_height {
        Some(h) => Some(Height::try_new(h).ok()?.get()),
        None => None,
    };
    Some(Header {
        key,
        order,
        alpha,
        height,
    })
}

/// The degree of an order given as `key` (`order` or `degree`): an order of
/// at least 1, within [`MAX_ORDER`](crate::limits::MAX_ORDER).
pub(super) fn degree_of(key: &str, given: u64) -> Option<usize> {
    if key == "order" && given == 0 {
        return None;
    }
    // The text is for the message, which a refusal leaves to the validator.
    Some(check_order(key, given, "").ok()? - 1)
}

/// A number of samples within the limits of
/// [`check_samples`](t2spline::job::check_samples).
pub(super) fn sample_count(n: u64) -> Option<usize> {
    // The text is for the message, which a refusal leaves to the validator.
    check_samples(n, "").ok()
}
