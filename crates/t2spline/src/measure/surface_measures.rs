//! The volumes, plan area and surface area of a fuzzy surface at many
//! levels, under the three membership functions (docs/method.md §14): what
//! `t2spline measure` writes for a surface job.
//!
//! With x and y crisp, the height above a plan point is `Σ Rₖ·zₖ` with
//! `Rₖ ≥ 0`, so every quantity that grows (or shrinks) with the height at
//! every plan point grows (or shrinks) with each `zₖ`: the volumes and the
//! plan area take their ends at the two extreme nets, every height at its
//! cut's left end or every one at its right end, the nets of the envelope.
//!
//! ```text
//! V_below ∈ [V_below(right net), V_below(left net)]
//! V_above ∈ [V_above(left net),  V_above(right net)]
//! A_below ∈ [A_below(right net), A_below(left net)]
//! ```
//! The surface area is convex in the heights (`surface_area.rs`). Against a
//! second surface, the cut and fill (`cut_fill.rs`, `overlap.rs`).

use crate::error::Error;
use crate::fuzzy::Membership;
use crate::measure::bracket::Bracket;
use crate::measure::cut_box::CutBox;
use crate::measure::cut_fill::{cut_fill, cut_fill_overlap, overlap, second_plan};
use crate::measure::extreme_nets::{each, finish, from_nets};
use crate::measure::measures::{Level, PerMembership};
use crate::measure::options::SurfaceMeasureOptions;
use crate::measure::plan::Plan;
use crate::measure::surface_area::{heights, surface_area_bracket, AreaRule};
use crate::measure::volume::{VolumeForm, Volumes, VOLUME_TOLERANCE};
use crate::pipeline::FuzzySurface;

/// Every quantity of docs/method.md §14 at many levels. A membership
/// function's lists hold only the levels where it has a cut.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SurfaceMeasures {
    /// The levels asked for.
    pub levels: Vec<f64>,
    /// The height of the plane the volumes are measured from.
    pub datum: f64,
    /// The relative tolerance the volumes and plan areas are integrated to;
    /// each level's `gap` is the error bound reached.
    pub tolerance: f64,
    /// The plan area of the surface (the same for every net), and its
    /// error bound.
    pub plan_area: [f64; 2],
    /// The volume between the plane and the surface where it lies below.
    pub volume_below: PerMembership<Vec<Level>>,
    /// The volume between the plane and the surface where it lies above.
    pub volume_above: PerMembership<Vec<Level>>,
    /// The plan area where the surface lies below the plane.
    pub plan_area_below: PerMembership<Vec<Level>>,
    /// The surface area.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub area: Option<PerMembership<Vec<Level>>>,
    /// Against a second surface ([`FuzzySurface::measure_against`]): the
    /// cut, the volume where this surface lies above the second,
    /// `∫∫ max(z₁ − z₂, 0) dx dy`.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub cut: Option<PerMembership<Vec<Level>>>,
    /// Against a second surface: the fill, the volume where this surface
    /// lies below the second, `∫∫ max(z₂ − z₁, 0) dx dy`.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub fill: Option<PerMembership<Vec<Level>>>,
}

/// The heights of the nets of every level and function.
type Boxes = PerMembership<Vec<(f64, CutBox)>>;

impl FuzzySurface<3> {
    /// The volumes between the surface and the plane `z = options.datum()`,
    /// the plan area below it and (with `options.area()`) the surface area,
    /// each an interval over the nets whose heights lie in their cuts, at
    /// each level and under each membership function (docs/method.md §14).
    ///
    /// # Errors
    /// [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md
    /// §16); [`Error::FuzzyPlan`] where x or y of a control point is fuzzy;
    /// [`Error::NotAGraph`] where the surface folds over its plan or has a
    /// vertical part.
    ///
    /// # Examples
    /// A square of side 2 at height 1 whose heights may move 0.5 either way:
    /// the volume above z = 0 lies in [4·0.5, 4·1.5] at level 0.
    /// ```
    /// # use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
    /// # use t2spline::measure::SurfaceMeasureOptions;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let z = Nt2Number::try_new(1.0, [0.5, 1.5], [0.75, 1.25], [1.0, 1.0], 1.0)?;
    /// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([c(x)?, c(y)?, z]));
    /// let net = vec![vec![p(0.0, 0.0)?, p(0.0, 2.0)?], vec![p(2.0, 0.0)?, p(2.0, 2.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let m = s.measure(&SurfaceMeasureOptions::uniform(3)?)?;
    /// let above = &m.volume_above.upper[0];
    /// assert!((above.min - 2.0).abs() < 1e-9 && (above.max - 6.0).abs() < 1e-9);
    /// assert_eq!(m.volume_below.upper[0].max, 0.0);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn measure(&self, options: &SurfaceMeasureOptions) -> Result<SurfaceMeasures, Error> {
        self.measure_with(None, options)
    }

    /// [`FuzzySurface::measure`], and the cut and fill between this surface
    /// and `other` (docs/method.md §14): the volumes where this one lies
    /// above and below `other`, each an interval over the nets of both
    /// surfaces whose heights lie in their cuts, exact where both have one
    /// plan map, else integrated over the overlap of the two plans to the
    /// stated tolerance (`gap` the error bound reached, `exact` false where
    /// it is missed),
    ///
    /// ```text
    /// cut  ∈ [cut(l₁, r₂),  cut(r₁, l₂)],   fill ∈ [fill(r₁, l₂), fill(l₁, r₂)]
    /// ```
    /// (`l`, `r`: every height at its cut's left or right end). A function
    /// without a cut at a level in either surface is left out there.
    ///
    /// # Errors
    /// As [`FuzzySurface::measure`], and [`Error::PlansDiffer`] where x or
    /// y of `other` is fuzzy or the two plans do not overlap;
    /// [`Error::NotAGraph`] where `other`'s plan map folds.
    ///
    /// # Examples
    /// Two planes over the square [0, 2]², `z₁ = x` and `z₂ = 1` crisp:
    /// the first lies 1/2 above the second on average over half the square.
    /// ```
    /// # use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
    /// # use t2spline::measure::SurfaceMeasureOptions;
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let p = |x: f64, y: f64, z: f64| Ok::<_, t2spline::Error>(Nt2Point::new([c(x)?, c(y)?, c(z)?]));
    /// let net = |z: [f64; 2]| Ok::<_, t2spline::Error>(vec![
    ///     vec![p(0.0, 0.0, z[0])?, p(0.0, 2.0, z[0])?],
    ///     vec![p(2.0, 0.0, z[1])?, p(2.0, 2.0, z[1])?],
    /// ]);
    /// let w = vec![vec![1.0; 2]; 2];
    /// let one = FuzzySurface::try_new([1, 1], net([0.0, 2.0])?, w.clone(), [None, None])?;
    /// let two = FuzzySurface::try_new([1, 1], net([1.0, 1.0])?, w, [None, None])?;
    /// let m = one.measure_against(&two, &SurfaceMeasureOptions::uniform(2)?)?;
    /// let (cut, fill) = (&m.cut.unwrap().upper[0], &m.fill.unwrap().upper[0]);
    /// assert!((cut.min - 1.0).abs() < 1e-9 && (cut.max - 1.0).abs() < 1e-9);
    /// assert!((fill.min - 1.0).abs() < 1e-9 && (fill.max - 1.0).abs() < 1e-9);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn measure_against(
        &self,
        other: &FuzzySurface<3>,
        options: &SurfaceMeasureOptions,
    ) -> Result<SurfaceMeasures, Error> {
        self.measure_with(Some(other), options)
    }

    fn measure_with(
        &self,
        other: Option<&FuzzySurface<3>>,
        options: &SurfaceMeasureOptions,
    ) -> Result<SurfaceMeasures, Error> {
        self.crisp_weights_for("a surface measure")?;
        if let Some(other) = other {
            other.crisp_weights_for("a surface measure")?;
        }
        let plan = Plan::of(self)?;
        plan.check_graph()?;
        let second = match other {
            Some(other) => Some((other, second_plan(&plan, other)?)),
            None => None,
        };
        let crisp: Vec<f64> = self
            .points()
            .iter()
            .map(|p| p.coords()[2].crisp())
            .collect();
        let area_rule = options.area().then(|| AreaRule::new(&plan, &crisp));
        let one = second
            .as_ref()
            .is_some_and(|(_, two)| two.is_some())
            .then(|| plan.clone());
        let form = VolumeForm::new(plan);
        let [cut, fill] = match (second, one) {
            (Some((other, Some(two))), Some(one)) => {
                let areas = [form.area[0], VolumeForm::new(two.clone()).area[0]];
                let (overlap, area) = overlap(&one, two, areas)?;
                cut_fill_overlap(&overlap, area, self, other, options.levels()).map(Some)
            }
            (Some((other, _)), _) => cut_fill(&form, self, other, options.levels()).map(Some),
            (None, _) => [None, None],
        };
        let boxes: Boxes = PerMembership::from_fn(|m| {
            options
                .levels()
                .iter()
                .filter_map(|&a| CutBox::of(self.points(), m, a).map(|b| (a.get(), b)))
                .collect()
        });
        let datum = options.datum();
        let plan_area = form.area[0];
        // Every extreme net of every level and function, evaluated on
        // rayon's pool (`each`): two per cut.
        let cuts: Vec<(Membership, f64, [Vec<f64>; 2])> =
            [Membership::Upper, Membership::Primary, Membership::Lower]
                .into_iter()
                .flat_map(|m| {
                    boxes
                        .get(m)
                        .iter()
                        .map(move |(a, cut)| (m, *a, heights(cut).0))
                })
                .collect();
        let all: Vec<&[f64]> = cuts
            .iter()
            .flat_map(|(_, _, [lo, hi])| [lo.as_slice(), hi.as_slice()])
            .collect();
        let volumes = each(&all, |z| form.eval(z, datum));
        let nets: PerMembership<Vec<(f64, [Volumes; 2], f64)>> = PerMembership::from_fn(|m| {
            cuts.iter()
                .zip(volumes.chunks_exact(2))
                .filter(|((n, _, _), _)| *n == m)
                .map(|((_, a, [lo, hi]), v)| {
                    let depth = lo
                        .iter()
                        .chain(hi)
                        .fold(0.0_f64, |d, z| d.max((z - datum).abs()));
                    (*a, [v[0], v[1]], plan_area * depth)
                })
                .collect()
        });
        let pick = |f: &dyn Fn(&[Volumes; 2], f64) -> Bracket| {
            finish(PerMembership::from_fn(|m| {
                nets.get(m)
                    .iter()
                    .map(|(a, v, scale)| (*a, Some(f(v, *scale))))
                    .collect()
            }))
        };
        let volume_below = pick(&|[l, r], scale| from_nets(r.below, l.below, scale));
        let volume_above = pick(&|[l, r], scale| from_nets(l.above, r.above, scale));
        let plan_area_below = pick(&|[l, r], _| from_nets(r.plan_below, l.plan_below, plan_area));
        let area = area_rule.map(|rule| {
            finish(PerMembership::from_fn(|m: Membership| {
                boxes
                    .get(m)
                    .iter()
                    .map(|(a, cut)| (*a, Some(surface_area_bracket(&rule, cut))))
                    .collect()
            }))
        });
        Ok(SurfaceMeasures {
            levels: options.levels().iter().map(|a| a.get()).collect(),
            datum,
            tolerance: VOLUME_TOLERANCE,
            plan_area: form.area,
            volume_below,
            volume_above,
            plan_area_below,
            area,
            cut,
            fill,
        })
    }
}
