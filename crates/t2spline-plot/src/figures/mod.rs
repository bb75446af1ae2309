//! The figures of the method: one builder per figure, each reading a
//! [`RunOutput`] (and, for the fuzzy number, the library's number) and
//! returning a [`crate::scene::Figure`] in data coordinates.
//!
//! | file stem | shows | paper |
//! |---|---|---|
//! | `number` | membership functions of one number, its cut and type reduction | Figs. 3.1, 4.1–4.4 |
//! | `stage1-fuzzy` | fuzzy control points and the seven layer curves | Fig. 5.1 |
//! | `stage2-alpha-cut` | alpha-cut control points and curves | Fig. 5.2 |
//! | `stage3-type-reduced` | type-reduced control points and curves, with weights | Fig. 5.3 |
//! | `stage4-defuzzified` | crisp and defuzzified curves, maximum distance | Fig. 5.4 |
//! | `alpha-sweep` | defuzzified curves for alpha = 0, 0.1, …, 1 (the paper's reduction) | — |
//! | `reductions` | the solution curve of every type reduction and its distance to the crisp curve | SPEC §10 |

mod number;
mod number_reductions;
mod reductions;
mod stages;
pub mod style;
mod sweep;

use t2spline::job::Points;
use t2spline::job::{Job, RunOutput};
use t2spline::{Alpha, Axis};

pub use number::number_figure;
pub use reductions::{reduction_label, reductions_figure};
pub use stages::{stage1_figure, stage2_figure, stage3_figure, stage4_figure};
pub use sweep::sweep_figure;

use crate::scene::{Panel, Xy};
use crate::ticks::short;
use crate::{data, Error};

/// The file stems of all figures, in the order [`all_figures`] returns them.
pub const FIGURE_NAMES: [&str; 7] = [
    "number",
    "stage1-fuzzy",
    "stage2-alpha-cut",
    "stage3-type-reduced",
    "stage4-defuzzified",
    "alpha-sweep",
    "reductions",
];

/// Which number the `number` figure shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NumberChoice {
    /// Control point index, from 0.
    pub point: usize,
    /// Coordinate.
    pub axis: Axis,
}

impl Default for NumberChoice {
    fn default() -> Self {
        NumberChoice {
            point: 0,
            axis: Axis::X,
        }
    }
}

/// Every figure of the job at `alpha`, in the order of [`FIGURE_NAMES`].
/// Stages 2–4 follow the job's type reduction, as `t2spline run` does (a
/// reduction other than the paper's cuts stage 2 at 0); `alpha` is the
/// paper's level in the `number`, `alpha-sweep` and `reductions` figures.
///
/// # Errors
/// [`Error::NoSuchPoint`] or [`Error::NoSuchAxis`] if `choice` names a
/// point or coordinate the job lacks.
pub fn all_figures(
    job: &Job,
    alpha: Alpha,
    choice: NumberChoice,
) -> Result<Vec<crate::scene::Figure>, Error> {
    let number = number_figure(job, alpha, choice)?;
    let result = data::compute(job, alpha)?;
    Ok(vec![
        number,
        stage1_figure(&result),
        stage2_figure(&result, &job.model.heights()),
        stage3_figure(&result, &job.model.heights()),
        stage4_figure(job, &result, true)?,
        sweep_figure(job)?,
        reductions_figure(job, alpha)?,
    ])
}

/// The coordinate pairs drawn: `(x, y)` in 2-D, three projections in 3-D.
#[must_use]
pub fn projections(dimension: usize) -> Vec<(usize, usize)> {
    if dimension >= 3 {
        vec![(0, 1), (0, 2), (1, 2)]
    } else {
        vec![(0, 1)]
    }
}

/// An empty curve panel per projection, titled in 3-D.
fn curve_panels(dimension: usize) -> Vec<(Panel, (usize, usize))> {
    const NAMES: [&str; 3] = ["x", "y", "z"];
    projections(dimension)
        .into_iter()
        .map(|(i, j)| {
            let mut p = Panel::curves(NAMES[i], NAMES[j]);
            if dimension >= 3 {
                p.title = Some(format!("{}–{} projection", NAMES[i], NAMES[j]));
            }
            (p, (i, j))
        })
        .collect()
}

/// Points projected to the coordinates `(i, j)`.
fn project(points: &Points, (i, j): (usize, usize)) -> Vec<Xy> {
    points
        .coord(i)
        .iter()
        .zip(points.coord(j))
        .map(|(&x, &y)| [x, y])
        .collect()
}

/// The region between two curves: one forwards, the other backwards.
fn band(a: &Points, b: &Points, ij: (usize, usize)) -> Vec<Xy> {
    let mut poly = project(a, ij);
    poly.extend(project(b, ij).into_iter().rev());
    poly
}

/// `P₀`, `P₁₂`: a control point's name with a subscript index.
fn point_name(i: usize) -> String {
    const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    let digits: String = i
        .to_string()
        .chars()
        .map(|c| c.to_digit(10).map_or(c, |d| SUB[d as usize]))
        .collect();
    format!("P{digits}")
}

/// "α = 0.8 > h = 0.6" and what it means, for subtitles; for a type
/// reduction other than the paper's, that it does not use α.
fn alpha_phrase(result: &RunOutput, heights: &[f64]) -> String {
    let a = short(result.alpha, 4);
    let Some(regime) = result.regime.filter(|_| result.alpha_used) else {
        return format!(
            "{} does not use α: cut shown at α = {a}, the whole footprint",
            reduction_label(result.type_reduction)
        );
    };
    match heights {
        [h] if result.alpha <= *h => format!(
            "α = {a} ≤ h = {}: all three functions are cut",
            short(*h, 4)
        ),
        [h] => format!(
            "α = {a} > h = {}: the lower function has no cut",
            short(*h, 4)
        ),
        _ => format!(
            "α = {a}, heights h from {} to {} ({})",
            short(heights.first().copied().unwrap_or(1.0), 4),
            short(heights.last().copied().unwrap_or(1.0), 4),
            regime
        ),
    }
}

/// `α = 0.8` for the paper's reduction, else the reduction's name.
fn reduction_phrase(result: &RunOutput) -> String {
    if result.alpha_used {
        format!("α = {}", short(result.alpha, 4))
    } else {
        reduction_label(result.type_reduction).to_owned()
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
}
