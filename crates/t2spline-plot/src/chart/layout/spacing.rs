//! The fixed distances of a page's layout, in pixels.

/// Outer margin of the page.
pub(super) const PAD: f64 = 10.0;
/// Length of a tick mark.
pub const TICK_LEN: f64 = 5.0;
/// Width reserved right of the panels for a colour bar and its labels.
pub(super) const COLORBAR_SPACE: f64 = 96.0;
/// Height of a line of notes.
pub const NOTE_ROW: f64 = 14.0;
