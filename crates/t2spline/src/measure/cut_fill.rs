//! The cut and fill between two fuzzy surfaces of one crisp plan map
//! (docs/method.md §14): the volume where the first lies above the second
//! and the volume where it lies below, as intervals over the nets whose
//! heights lie in their cuts.
//!
//! With x and y crisp, the height of either surface above a plan point is
//! `Σ Rₖ·zₖ` with `Rₖ ≥ 0`, and
//!
//! ```text
//! cut  = ∫∫_P max(z₁ − z₂, 0) dx dy,   fill = ∫∫_P max(z₂ − z₁, 0) dx dy
//! ```
//! `max(·, 0)` does not decrease, so the cut does not decrease in any height
//! `z₁ₖ` of the first surface nor increase in any `z₂ₖ` of the second, and
//! the fill the other way; over the box of cut heights (a product of
//! intervals, each height free of the others) the ends are at its corners:
//!
//! ```text
//! cut  ∈ [cut(l₁, r₂),  cut(r₁, l₂)]
//! fill ∈ [fill(r₁, l₂), fill(l₁, r₂)]
//! ```
//! (`l`, `r`: every height at its cut's left or right end), attained, so
//! exact. With one plan map (the same degrees, knots, weights, x and y)
//! `z₁ − z₂ = Σ Rₖ·(z₁ₖ − z₂ₖ)` is the surface of the same plan with the
//! difference heights `dₖ = z₁ₖ − z₂ₖ`, and the cut and fill are its volumes
//! above and below the datum 0 (`volume.rs`): `cut(l₁, r₂) = V_above(l₁ − r₂)`,
//! `fill(l₁, r₂) = V_below(l₁ − r₂)`, and so on. Plans that differ are
//! refused ([`Error::PlansDiffer`]): the difference is then no surface of
//! one plan.
//!
//! Forming `dₖ` is one correctly rounded subtraction, off by at most
//! `ε/2·|dₖ|`, which moves a volume by at most that times the plan area:
//! `ε` times the plan area times the largest `|dₖ|` is added to each end's
//! error bound (nothing where the heights are equal).

use crate::error::Error;
use crate::fuzzy::Alpha;
use crate::measure::cut_box::CutBox;
use crate::measure::extreme_nets::{finish, from_nets};
use crate::measure::measures::{Level, PerMembership};
use crate::measure::plan::Plan;
use crate::measure::surface_area::heights;
use crate::measure::volume::{VolumeForm, Volumes};
use crate::pipeline::FuzzySurface;

/// Refuses a second surface whose plan map is not `plan`.
///
/// # Errors
/// [`Error::PlansDiffer`] naming the first difference (a fuzzy x or y of the
/// second surface among them).
pub(crate) fn same_plan(plan: &Plan, other: &FuzzySurface<3>) -> Result<(), Error> {
    let theirs = Plan::of(other).map_err(|e| match e {
        Error::FuzzyPlan { row, column, axis } => Error::PlansDiffer {
            what: format!("points[{row}][{column}].{axis} is fuzzy"),
        },
        other => other,
    })?;
    match plan.difference(&theirs) {
        None => Ok(()),
        Some(what) => Err(Error::PlansDiffer { what }),
    }
}

/// The two difference nets of one level and function.
struct Corners {
    alpha: f64,
    /// The volumes of `l₁ − r₂` and `r₁ − l₂`.
    volumes: [Volumes; 2],
    /// The plan area times the largest `|dₖ|`.
    scale: f64,
}

/// Which volume of the two difference nets is least and which largest.
type Ends = fn(&[Volumes; 2]) -> ([f64; 2], [f64; 2]);

/// The cut and fill of `first` over `second` (of the plan of `form`, checked
/// by [`same_plan`]) at each level, per membership function; a function
/// without a cut at a level in either surface is left out there.
pub(crate) fn cut_fill(
    form: &VolumeForm,
    first: &FuzzySurface<3>,
    second: &FuzzySurface<3>,
    levels: &[Alpha],
) -> [PerMembership<Vec<Level>>; 2] {
    let plan_area = form.area[0];
    let corners: PerMembership<Vec<Corners>> = PerMembership::from_fn(|m| {
        levels
            .iter()
            .filter_map(|&a| {
                let one = CutBox::of(first.points(), m, a)?;
                let two = CutBox::of(second.points(), m, a)?;
                let ([l1, r1], _) = heights(&one);
                let ([l2, r2], _) = heights(&two);
                let least: Vec<f64> = l1.iter().zip(&r2).map(|(a, b)| a - b).collect();
                let largest: Vec<f64> = r1.iter().zip(&l2).map(|(a, b)| a - b).collect();
                let depth = least
                    .iter()
                    .chain(&largest)
                    .fold(0.0_f64, |d, z| d.max(z.abs()));
                Some(Corners {
                    alpha: a.get(),
                    volumes: [form.eval(&least, 0.0), form.eval(&largest, 0.0)],
                    scale: plan_area * depth,
                })
            })
            .collect()
    });
    let pick = |ends: Ends| {
        finish(PerMembership::from_fn(|m| {
            corners
                .get(m)
                .iter()
                .map(|c| {
                    let (least, largest) = ends(&c.volumes);
                    // The rounding of the differences (module docs).
                    let widen = |x: [f64; 2]| [x[0], x[1] + c.scale * f64::EPSILON];
                    let bracket = from_nets(widen(least), widen(largest), c.scale);
                    (c.alpha, Some(bracket))
                })
                .collect()
        }))
    };
    let cut = pick(|[l, r]| (l.above, r.above));
    let fill = pick(|[l, r]| (r.below, l.below));
    [cut, fill]
}
