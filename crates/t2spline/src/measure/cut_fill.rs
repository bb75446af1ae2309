//! The cut and fill between two fuzzy surfaces of crisp plan
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
//! integrated over their overlap (`overlap.rs`): the difference is then no
//! surface of one plan.
//!
//! Forming `dₖ` is one correctly rounded subtraction, off by at most
//! `ε/2·|dₖ|`, which moves a volume by at most that times the plan area:
//! `ε` times the plan area times the largest `|dₖ|` is added to each end's
//! error bound (nothing where the heights are equal).

use crate::error::Error;
use crate::fuzzy::{Alpha, Membership};
use crate::measure::cut_box::CutBox;
use crate::measure::extreme_nets::{each, finish, from_nets};
use crate::measure::measures::{Level, PerMembership};
use crate::measure::overlap::Overlap;
use crate::measure::plan::Plan;
use crate::measure::surface_area::heights;
use crate::measure::volume::{VolumeForm, Volumes};
use crate::pipeline::FuzzySurface;

/// The second surface's plan where it is not `plan` (`None` where both
/// surfaces have one plan map: the exact path).
///
/// # Errors
/// [`Error::PlansDiffer`] where x or y of the second surface is fuzzy;
/// [`Error::NotAGraph`] where its plan map folds.
pub(crate) fn second_plan(plan: &Plan, other: &FuzzySurface<3>) -> Result<Option<Plan>, Error> {
    let theirs = Plan::of(other).map_err(|e| match e {
        Error::FuzzyPlan { row, column, axis } => Error::PlansDiffer {
            what: format!("points[{row}][{column}].{axis} of the second surface is fuzzy"),
        },
        other => other,
    })?;
    match plan.difference(&theirs) {
        None => Ok(None),
        Some(_) => {
            theirs.check_graph()?;
            Ok(Some(theirs))
        }
    }
}

/// The overlap of the two plans, refused where it is empty.
///
/// # Errors
/// [`Error::PlansDiffer`] where the plans do not overlap (their common
/// part has no area, to `10⁻¹²` of the smaller plan's).
pub(crate) fn overlap(one: &Plan, two: Plan, areas: [f64; 2]) -> Result<(Overlap, f64), Error> {
    let overlap = Overlap::new(one.clone(), two);
    let ([area], _) = overlap.area();
    if area.is_nan() || area <= 1e-12 * areas[0].min(areas[1]) {
        return Err(Error::PlansDiffer {
            what: "the plans do not overlap".to_string(),
        });
    }
    Ok((overlap, area))
}

/// Per level and function: the function, the level, the corner pairs of
/// nets `[(l₁, r₂), (r₁, l₂)]` and the scale of the tolerance.
type Pairs = (Membership, f64, [[Vec<f64>; 2]; 2], f64);

/// The cut and fill of `first` over `second` over the overlap of their
/// plans (`overlap.rs`), at each level, per membership function: the same
/// corners as [`cut_fill`], each integrated to `10⁻⁹` of the overlap's area
/// times the greatest `|z₁ − z₂|`, exact where its error estimate is
/// within that.
pub(crate) fn cut_fill_overlap(
    overlap: &Overlap,
    area: f64,
    first: &FuzzySurface<3>,
    second: &FuzzySurface<3>,
    levels: &[Alpha],
) -> [PerMembership<Vec<Level>>; 2] {
    // Per level and function: the corners (l₁, r₂) and (r₁, l₂).
    let mut corners: Vec<Pairs> = Vec::new();
    for m in [Membership::Upper, Membership::Primary, Membership::Lower] {
        for &a in levels {
            let (Some(one), Some(two)) = (
                CutBox::of(first.points(), m, a),
                CutBox::of(second.points(), m, a),
            ) else {
                continue;
            };
            let ([l1, r1], _) = heights(&one);
            let ([l2, r2], _) = heights(&two);
            let range = |z: &[f64]| {
                z.iter().fold([f64::INFINITY, f64::NEG_INFINITY], |r, &x| {
                    [r[0].min(x), r[1].max(x)]
                })
            };
            let [one_lo, one_hi] = range(&l1.iter().chain(&r1).copied().collect::<Vec<_>>());
            let [two_lo, two_hi] = range(&l2.iter().chain(&r2).copied().collect::<Vec<_>>());
            let depth = (one_hi - two_lo).abs().max((two_hi - one_lo).abs());
            corners.push((m, a.get(), [[l1, r2], [r1, l2]], area * depth));
        }
    }
    let jobs: Vec<[&[f64]; 2]> = corners
        .iter()
        .flat_map(|(_, _, [least, largest], _)| {
            [
                [least[0].as_slice(), least[1].as_slice()],
                [largest[0].as_slice(), largest[1].as_slice()],
            ]
        })
        .collect();
    let measured = each(&jobs, |[z1, z2]| overlap.cut_fill(z1, z2));
    let pick = |k: usize, flip: bool| {
        finish(PerMembership::from_fn(|m| {
            corners
                .iter()
                .zip(measured.chunks_exact(2))
                .filter(|(c, _)| c.0 == m)
                .map(|(c, v)| {
                    let at = |i: usize| [v[i].0[k], v[i].1[k]];
                    let (least, largest) = if flip { (at(1), at(0)) } else { (at(0), at(1)) };
                    (c.1, Some(from_nets(least, largest, c.3)))
                })
                .collect()
        }))
    };
    // The cut is least at (l₁, r₂), the fill at (r₁, l₂).
    [pick(0, false), pick(1, true)]
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
