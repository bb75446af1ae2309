//! Unions of intervals on a line: the sections of docs/method.md §10 and
//! §16 are joined here.

/// The union of `intervals`, joining those less than `gap` apart.
pub(crate) fn join(mut intervals: Vec<[f64; 2]>, gap: f64) -> Vec<[f64; 2]> {
    intervals.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let mut out: Vec<[f64; 2]> = Vec::new();
    for iv in intervals {
        match out.last_mut() {
            Some(last) if iv[0] <= last[1] + gap => last[1] = last[1].max(iv[1]),
            _ => out.push(iv),
        }
    }
    out
}
