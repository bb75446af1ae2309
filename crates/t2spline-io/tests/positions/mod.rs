//! Where tests expect a problem to be reported, found in the text itself
//! (independently of the reader's own scan): shared by `limits.rs` and
//! `surface_job.rs`.

/// `line:column` (from 1, columns in characters) of the `nth` occurrence of
/// `needle` in `text`: where the tests expect a problem to be reported.
pub fn at(text: &str, needle: &str, nth: usize) -> String {
    let (i, _) = text
        .match_indices(needle)
        .nth(nth)
        .unwrap_or_else(|| panic!("{needle:?} #{nth} is not in the text"));
    let before = &text[..i];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
    format!("{line}:{column}")
}
