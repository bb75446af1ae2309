//! The words of the curve figures' titles and subtitles: point names, the
//! level α, the type reduction, the weights.

use t2spline::job::RunOutput;

use crate::chart::ticks::short;
use crate::figures::style::reduction_label;

/// `P₀`, `P₁₂`: a control point's name with a subscript index.
#[must_use]
pub fn point_name(i: usize) -> String {
    const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    let digits: String = i
        .to_string()
        .chars()
        .map(|c| c.to_digit(10).map_or(c, |d| SUB[d as usize]))
        .collect();
    format!("P{digits}")
}

/// "α = 0.8 > h = 0.6" and what it means, for subtitles of result `r`; for
/// a type reduction other than the paper's, that it does not use α (docs/method.md §9).
#[must_use]
pub fn alpha_phrase(r: &RunOutput, heights: &[f64]) -> String {
    let a = short(r.alpha, 4);
    let Some(regime) = r.regime.filter(|_| r.alpha_used) else {
        return format!(
            "{} does not use α: cut shown at α = {a}, the whole footprint",
            reduction_label(r.type_reduction)
        );
    };
    match heights {
        [h] if r.alpha <= *h => format!(
            "α = {a} ≤ h = {}: all three functions are cut",
            short(*h, 4)
        ),
        [h] => format!(
            "α = {a} > h = {}: the lower function has no cut",
            short(*h, 4)
        ),
        _ => format!(
            "α = {a}, heights h from {} to {} ({regime})",
            short(heights.first().copied().unwrap_or(1.0), 4),
            short(heights.last().copied().unwrap_or(1.0), 4),
        ),
    }
}

/// `α = 0.8` for a result of the paper's type reduction, else the
/// reduction's name.
#[must_use]
pub fn reduction_phrase(r: &RunOutput) -> String {
    if r.alpha_used {
        format!("α = {}", short(r.alpha, 4))
    } else {
        reduction_label(r.type_reduction).to_owned()
    }
}

/// The weights for a subtitle: all of them when few, else their range.
#[must_use]
pub fn weights_phrase(weights: &[f64]) -> String {
    let (lo, hi) = weights
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &w| {
            (a.min(w), b.max(w))
        });
    if lo == hi {
        format!("all weights {}", short(lo, 4))
    } else if weights.len() <= 8 {
        let list: Vec<String> = weights.iter().map(|w| short(*w, 4)).collect();
        format!("weights ({})", list.join(", "))
    } else {
        format!(
            "{} weights from {} to {}",
            weights.len(),
            short(lo, 4),
            short(hi, 4)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_names_use_subscripts() {
        assert_eq!(point_name(0), "P₀");
        assert_eq!(point_name(12), "P₁₂");
    }

    #[test]
    fn many_weights_are_summarised() {
        assert_eq!(
            weights_phrase(&[1.0, 1.0, 3.0, 1.0]),
            "weights (1, 1, 3, 1)"
        );
        assert_eq!(weights_phrase(&[1.0; 200]), "all weights 1");
        let w: Vec<f64> = (0..200).map(|i| 0.5 + f64::from(i) / 100.0).collect();
        assert_eq!(weights_phrase(&w), "200 weights from 0.5 to 2.49");
    }
}
