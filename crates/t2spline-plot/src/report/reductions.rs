//! The report's type-reduction selector (docs/method.md §9): which frame shows each
//! reduction, the `<select>` element, and its entry in the data block.
//!
//! The paper's reduction has one frame per slider stop; each other
//! reduction, which does not use alpha, has one frame after them. The page's
//! script only switches to the frame the data block names.

use std::fmt::Write as _;

use serde_json::{json, Value};
use t2spline::job::RunOutput;
use t2spline::TypeReduction;

use crate::figures::reduction_label;

/// The frame that shows a reduction other than the paper's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct ReductionFrame {
    /// The reduction.
    pub method: TypeReduction,
    /// Its frame, after the paper's `stops` frames.
    pub frame: usize,
}

/// How many reductions have a frame of their own: all but the paper's.
pub(super) fn count() -> usize {
    TypeReduction::ALL
        .into_iter()
        .filter(|m| !m.uses_alpha())
        .count()
}

/// One frame for each reduction but the paper's, numbered after the paper's
/// `stops` frames.
pub(super) fn frames(stops: usize) -> Vec<ReductionFrame> {
    TypeReduction::ALL
        .into_iter()
        .filter(|m| !m.uses_alpha())
        .enumerate()
        .map(|(i, method)| ReductionFrame {
            method,
            frame: stops + i,
        })
        .collect()
}

/// The frame of `method`; `None` for the paper's, whose frame is the
/// slider's.
pub(super) fn initial_frame(frames: &[ReductionFrame], method: TypeReduction) -> Option<usize> {
    frames.iter().find(|f| f.method == method).map(|f| f.frame)
}

/// `[{"name": "paper", "frame": null}, {"name": "centroid", "frame": 102}, …]`
/// in the order of [`TypeReduction::ALL`].
pub(super) fn json(frames: &[ReductionFrame]) -> Value {
    TypeReduction::ALL
        .into_iter()
        .map(|m| json!({ "name": m.name(), "frame": initial_frame(frames, m) }))
        .collect()
}

/// The `<select>` of the reductions, `initial` selected; enabled by the
/// page's script once the data block is unpacked.
pub(super) fn selector(initial: TypeReduction) -> String {
    let mut s = String::from(
        "<label for=\"reduction\">type reduction</label>\n<select id=\"reduction\" disabled>\n",
    );
    for m in TypeReduction::ALL {
        let selected = if m == initial { " selected" } else { "" };
        let uses = if m.uses_alpha() { ", uses α" } else { "" };
        let _ = writeln!(
            s,
            "<option value=\"{}\"{selected}>{}{uses}</option>",
            m.name(),
            reduction_label(m)
        );
    }
    s.push_str("</select>\n");
    s
}

/// What the regime line says: the regime of the paper's reduction, or that
/// another reduction does not use alpha.
pub(super) fn regime_text(r: &RunOutput) -> String {
    match r.regime.filter(|_| r.alpha_used) {
        Some(regime) => regime.as_str().to_owned(),
        None => format!(
            "{} does not use α; stage 2 is cut at α = 0",
            reduction_label(r.type_reduction)
        ),
    }
}
