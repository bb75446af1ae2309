//! The largest job t2spline accepts, and the rules that enforce it.
//!
//! Every limit is checked before the memory or time it guards is spent: a file
//! is measured before it is read, its arrays, objects and values are counted
//! before it is parsed into a tree, a count before anything of that size is
//! allocated. The limits are far above what the method needs (the paper's
//! example has 4 points of order 3) and low enough that the largest accepted
//! job runs in about a minute and 1.3 GB of memory; the README gives measured
//! figures.
//!
//! Surface jobs (docs/method.md §8) have the same limits, counted over the net and per
//! direction: at most [`MAX_POINTS`] control points in the whole net
//! (`nu·nv`, counted from the rows' lengths before any point is read), an
//! order of at most [`MAX_ORDER`] in each direction, and a grid of samples of
//! at most [`t2spline::job::MAX_SAMPLES`] points (`su·sv`,
//! [`t2spline::job::check_grid_samples`]). Rows and knot vectors are arrays,
//! bounded by [`MAX_ARRAY`] like every other. One more limit bounds the time
//! of a surface's run, [`MAX_SURFACE_WORK`]: the distance of docs/method.md §8 is
//! measured on every span rectangle of the net, at a cost that grows with the
//! number of basis terms `ku·kv`, so a net that [`MAX_POINTS`] allows would
//! run for hours.
//!
//! Numbers themselves are limited by the core crate: coordinates and knots to
//! `[-1e150, 1e150]` ([`t2spline::MAX_MAGNITUDE`]) and weights to
//! `[1e-150, 1e150]`, so that every result is a finite number; the number of
//! samples by [`t2spline::job::MAX_SAMPLES`].

// The input decides sizes and indices here: no indexing that can panic.
#![cfg_attr(not(test), deny(clippy::indexing_slicing))]

/// The largest job file, in bytes (64 MiB), also for standard input. A
/// 100 000-point 3-D job written one number per line is about 40 MB.
pub const MAX_FILE_BYTES: u64 = 64 << 20;

/// The largest number of control points: of a curve, or of a surface's net
/// in all (`nu·nv`).
pub const MAX_POINTS: usize = 100_000;

/// The largest order `k` (degree `k − 1`). Evaluating a curve costs about `k²`
/// operations per parameter, so a very high order makes every sample slow; it
/// is also far beyond what B-spline modelling uses (orders 2–6, rarely above 10).
pub const MAX_ORDER: usize = 32;

/// The most work a surface job may ask for: its span rectangles (at most
/// `(nu − ku + 1)(nv − kv + 1)`) times the basis terms `ku·kv` of each. The
/// distance between the crisp and the defuzzified surface (docs/method.md §8) scans
/// and refines every rectangle whose control points could hold the largest
/// distance; at worst (the same spreads everywhere) that is every one. The
/// limit is set so that the largest such jobs run in under a minute on a
/// loaded 2-core machine (figures in `docs/performance.md`): 316 × 316 control
/// points of orders 2 × 2 (99 225 rectangles), 203 × 203 of orders 4 × 4,
/// 56 × 56 of orders 32 × 32. The time per rectangle grows more slowly than
/// `ku·kv`, so the product is a bound that errs on the side of low orders.
/// Below [`MAX_POINTS`], this is the limit that large nets meet first.
pub const MAX_SURFACE_WORK: usize = 640_000;

/// How deeply arrays and objects may nest: `serde_json`'s own recursion limit
/// (it refuses the 128th level), which stops a hostile file before it can
/// exhaust the stack. A job needs 4.
pub const MAX_NESTING: usize = 127;

/// The longest array a job or data file can need: `knots` of a curve with
/// [`MAX_POINTS`] points of order [`MAX_ORDER`]. A longer array is refused
/// before the JSON tree is built: a 64 MiB file of `0,` would otherwise make
/// 33 million values and take about 3 GB.
pub const MAX_ARRAY: usize = MAX_POINTS + MAX_ORDER;

/// The most members an object may have: no object of a job or data file has
/// more than 9 keys; unknown keys are errors, but millions of them would only
/// cost time and memory.
pub const MAX_KEYS: usize = 64;

/// The most JSON values (numbers, strings, arrays, objects, …) a file may
/// hold. A 3-D job of [`MAX_POINTS`] points with a height in every number,
/// weights and knots has 3.9 million (37 per point); each value takes 30 to 80
/// bytes once parsed, so this bounds the memory of reading any file.
pub const MAX_VALUES: usize = 4_000_000;

/// The most problems an error lists; the rest are counted in one last line
/// ([`more_problems`]). A 64 MiB file of `0,` could otherwise make eight
/// million messages, and a screen holds about twenty.
pub const MAX_PROBLEMS: usize = 20;

/// The most problems a reader of readings collects before it stops reading
/// the file (it then counts no further): the memory of a file of nothing
/// but errors stays small.
pub const MAX_PROBLEMS_FOUND: usize = 1000;

/// The last line of a list of problems cut at [`MAX_PROBLEMS`]: `more` were
/// not listed; `stopped`: reading stopped there, so there may be more.
#[must_use]
pub fn more_problems(more: usize, stopped: bool) -> String {
    let at_least = if stopped { "at least " } else { "" };
    format!("… and {at_least}{more} more problems (only the first {MAX_PROBLEMS} are listed)")
}

/// Checks an order `k` against [`MAX_ORDER`]; `key` is `"order"` or `"degree"`,
/// `given` its value and `written` the value as the file wrote it.
pub(crate) fn check_order(key: &str, given: u64, written: &str) -> Result<usize, String> {
    let order = if key == "degree" {
        given.saturating_add(1)
    } else {
        given
    };
    if order > MAX_ORDER as u64 {
        let (limit, other) = if key == "degree" {
            (MAX_ORDER - 1, format!("order {MAX_ORDER}"))
        } else {
            (MAX_ORDER, format!("degree {}", MAX_ORDER - 1))
        };
        Err(format!(
            "{key} = {written} is more than the limit {limit} ({other})"
        ))
    } else {
        // At most MAX_ORDER, which is a usize.
        Ok(order as usize)
    }
}

/// Checks the number of control points of a surface's net, `nu·nv`, against
/// [`MAX_POINTS`].
pub(crate) fn check_net_size(count: usize) -> Result<(), String> {
    if count > MAX_POINTS {
        Err(format!(
            "a net of {count} control points is more than the limit {MAX_POINTS}"
        ))
    } else {
        Ok(())
    }
}

/// Checks a surface of `shape` control points and `orders` against
/// [`MAX_SURFACE_WORK`]; a direction with fewer points than its order is
/// another rule's (it has no rectangles).
pub(crate) fn check_surface_work(shape: [usize; 2], orders: [usize; 2]) -> Result<(), String> {
    let [nu, nv] = shape;
    let [ku, kv] = orders;
    let rectangles = (nu + 1).saturating_sub(ku) * (nv + 1).saturating_sub(kv);
    let work = rectangles.saturating_mul(ku.saturating_mul(kv));
    if work > MAX_SURFACE_WORK {
        Err(format!(
            "a surface of {nu} × {nv} control points and orders {ku} × {kv} has up to {rectangles} span rectangles of {} basis terms each, {work} in all, more than the limit {MAX_SURFACE_WORK}: the distance of the solution is measured on every rectangle; use fewer control points or lower orders",
            ku * kv
        ))
    } else {
        Ok(())
    }
}

/// The rule a file breaks when it is larger than [`MAX_FILE_BYTES`]; `size`
/// is its size when known (a regular file), `None` when it was noticed while
/// reading (a pipe, standard input).
pub(crate) fn file_too_large(size: Option<u64>) -> String {
    let limit = format!(
        "the limit of {} MiB ({MAX_FILE_BYTES} bytes)",
        MAX_FILE_BYTES >> 20
    );
    match size {
        Some(size) => format!("the file has {size} bytes, more than {limit}"),
        None => format!("the input is larger than {limit}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn order_and_degree_limits_name_both() {
        assert_eq!(check_order("order", 32, "32"), Ok(32));
        assert_eq!(check_order("degree", 31, "31"), Ok(32));
        assert_eq!(
            check_order("order", 33, "33"),
            Err("order = 33 is more than the limit 32 (degree 31)".to_owned())
        );
        assert_eq!(
            check_order("degree", u64::MAX, "1e30"),
            Err("degree = 1e30 is more than the limit 31 (order 32)".to_owned())
        );
    }

    #[test]
    fn surface_work_counts_rectangles_times_terms() {
        assert_eq!(check_surface_work([203, 203], [4, 4]), Ok(()));
        assert_eq!(check_surface_work([56, 56], [32, 32]), Ok(()));
        assert!(check_surface_work([57, 57], [32, 32]).is_err());
        assert_eq!(check_surface_work([1, 1], [1, 1]), Ok(()));
        // Fewer points than the order: no rectangles, another rule's.
        assert_eq!(check_surface_work([2, 100_000], [3, 32]), Ok(()));
        assert_eq!(
            check_surface_work([204, 204], [4, 4]),
            Err("a surface of 204 × 204 control points and orders 4 × 4 has up to 40401 span rectangles of 16 basis terms each, 646416 in all, more than the limit 640000: the distance of the solution is measured on every rectangle; use fewer control points or lower orders".to_owned())
        );
        assert!(check_surface_work([MAX_POINTS, 1], [1, 1]).is_ok());
        assert!(check_surface_work([640_001, 1], [1, 1]).is_err());
    }

    #[test]
    fn file_size_message() {
        assert_eq!(
            file_too_large(Some(100 << 20)),
            "the file has 104857600 bytes, more than the limit of 64 MiB (67108864 bytes)"
        );
        assert_eq!(
            file_too_large(None),
            "the input is larger than the limit of 64 MiB (67108864 bytes)"
        );
    }
}
