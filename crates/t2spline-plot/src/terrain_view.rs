//! The numbers the terrain figures draw of a surface job (docs/method.md
//! §12–§14), asked of the core as `t2spline envelope`, `contour` and
//! `measure` ask: the envelope's width over the plan
//! ([`FuzzySurface::envelope`]), the fuzzy contour at the datum `z = 0`
//! ([`FuzzySurface::contour`]) with the crisp surface's contour lines, and
//! the volumes, plan area below and surface area as fuzzy numbers
//! ([`FuzzySurface::measure`]). Plotting only draws them.
//!
//! A surface has terrain figures when it is a terrain as the core's
//! measures understand one: x and y crisp at every control point and the
//! surface the graph of a height over its plan ([`terrain`]); others (a
//! cylinder) get a reason instead, never an error.

use t2spline::job::Model;
use t2spline::measure::{Level, PerMembership, SurfaceMeasureOptions};
use t2spline::set::{Contour, PlanGrid};
use t2spline::{Alpha, FuzzySurface, Membership};

use crate::error::Error;

/// Cells along the longer side of the plan of the `envelope-width` map:
/// about three SVG units a cell on a page.
pub const WIDTH_MAP_CELLS: usize = 200;

/// Cells along the longer side of the width map in the report, which
/// stores the map at every slider stop.
pub const REPORT_WIDTH_MAP_CELLS: usize = 60;

/// Cells along the longer side of the grid of the band in the report (the
/// `shoreline` figure of `t2spline plot` uses the grid of `t2spline
/// contour`, [`FuzzySurface::contour_shape`]).
pub const REPORT_CONTOUR_CELLS: usize = 96;

/// Cells along the longer side of the grid the crisp surface's contour
/// lines are traced on (the contour map under the band).
pub const CONTOUR_MAP_CELLS: usize = 120;

/// Uniform levels the volumes and the plan area below are traced at (0,
/// 0.1, …, 1; the heights h are added): each level costs two volume
/// integrations per function, about 0.6 s for all of them on a 30 × 30 net.
pub const TERRAIN_MEASURE_LEVELS: usize = 11;

/// The levels the surface area is traced at (the heights h are added): a
/// convex minimisation and a vertex search per level and function, about
/// 0.3 s a level on the 6 × 5 terrain example, so three levels and every h.
pub const SURFACE_AREA_LEVELS: [f64; 3] = [0.0, 0.5, 1.0];

/// The most control points of a surface whose surface area is drawn:
/// beyond, a level takes seconds (8 s on the 16 × 20 Salish Sea net), and
/// `t2spline measure` gives it.
pub const SURFACE_AREA_MAX_POINTS: usize = 64;

/// The height of the datum the volumes, plan area below and the shoreline
/// are measured from.
pub const DATUM: f64 = 0.0;

/// Whether a model has terrain figures.
#[derive(Debug)]
pub enum Terrain<'a> {
    /// A terrain: crisp x and y, the graph of a height.
    Yes(&'a FuzzySurface<3>),
    /// Not a terrain; the core's reason.
    No(String),
}

/// Whether `model` is a terrain: the core's surface measures accept it (x
/// and y crisp, the graph of a height), asked at level 1 only, without the
/// surface area (one volume integration of the crisp surface). A surface
/// with fuzzy weights is none yet (docs/method.md §16).
///
/// # Errors
/// [`Error::Surface`]'s counterpart for a curve: a curve is not a terrain
/// and gets [`Terrain::No`]; [`Error::Core`] for any other refusal (never
/// for a validated job).
pub fn terrain(model: &Model) -> Result<Terrain<'_>, Error> {
    let Model::Surface(s) = model else {
        return Ok(Terrain::No(
            "a curve job has no plan to draw over".to_owned(),
        ));
    };
    if s.weight_numbers().is_some() {
        return Ok(Terrain::No(
            "the envelope, contour and measures of a surface with fuzzy weights are not available yet (docs/method.md §16)"
                .to_owned(),
        ));
    }
    let options = SurfaceMeasureOptions::new(vec![Alpha::ONE], DATUM)?.with_area(false);
    match s.measure(&options) {
        Ok(_) => Ok(Terrain::Yes(s)),
        Err(e @ (t2spline::Error::FuzzyPlan { .. } | t2spline::Error::NotAGraph { .. })) => {
            Ok(Terrain::No(e.to_string()))
        }
        Err(e) => Err(e.into()),
    }
}

/// The grid of `most` cells along the longer side of `extent`, square
/// cells as near as whole numbers allow (at least one cell each way).
///
/// # Errors
/// [`Error::Core`] if the extent is not a rectangle (never for a terrain:
/// its plan map is one to one).
pub fn plan_grid(extent: [f64; 4], most: usize) -> Result<PlanGrid, Error> {
    let [x0, y0, x1, y1] = extent;
    let (w, h) = (x1 - x0, y1 - y0);
    let long = w.max(h);
    let cells = |side: f64| {
        let n = (side / long * most as f64).round();
        if n.is_finite() {
            (n as usize).clamp(1, most)
        } else {
            1
        }
    };
    Ok(PlanGrid::try_new(extent, [cells(w), cells(h)])?)
}

/// The width of the envelope, greatest minus least height, per cell of a
/// grid, per membership function at one level.
#[derive(Clone, Debug, PartialEq)]
pub struct WidthMap {
    /// The grid (cells row by row, y outer).
    pub grid: PlanGrid,
    /// The level.
    pub alpha: f64,
    /// Per function (upper, primary, lower) its widths (NaN: NODATA);
    /// `None` where the function has no cut at the level.
    pub widths: [Option<Vec<f64>>; 3],
}

impl WidthMap {
    /// The largest width of any function (the upper's, which holds the
    /// others); 0 without data.
    #[must_use]
    pub fn max(&self) -> f64 {
        self.widths
            .iter()
            .flatten()
            .flatten()
            .copied()
            .filter(|w| w.is_finite())
            .fold(0.0, f64::max)
    }
}

/// The width maps of terrain `s` at `alphas` on a grid of `most` cells
/// along the longer side of its plan extent: one envelope for all levels
/// (its ends are linear in alpha, so the levels cost little more than one).
///
/// # Errors
/// [`Error::Core`] if the core refuses the grid (never below its limit of
/// values).
pub fn width_maps(
    s: &FuzzySurface<3>,
    alphas: &[Alpha],
    most: usize,
) -> Result<Vec<WidthMap>, Error> {
    let grid = plan_grid(s.plan_extent(), most)?;
    let envelope = s.envelope(&grid, alphas)?;
    Ok(envelope
        .levels
        .into_iter()
        .map(|level| WidthMap {
            grid: grid.clone(),
            alpha: level.alpha,
            widths: [Membership::Upper, Membership::Primary, Membership::Lower].map(|m| {
                level.get(m).map(|b| {
                    b.greatest
                        .iter()
                        .zip(&b.least)
                        .map(|(hi, lo)| hi - lo)
                        .collect()
                })
            }),
        })
        .collect())
}

/// The fuzzy contour of terrain `s` at the datum at `alphas`: on the grid of
/// `t2spline contour` ([`FuzzySurface::contour_shape`]), or with `most`
/// cells along the longer side.
///
/// # Errors
/// As [`FuzzySurface::contour`] (never for a terrain on these grids).
pub fn datum_contour(
    s: &FuzzySurface<3>,
    alphas: &[Alpha],
    most: Option<usize>,
) -> Result<Contour, Error> {
    let extent = s.plan_extent();
    let grid = match most {
        None => PlanGrid::try_new(extent, s.contour_shape(extent))?,
        Some(most) => plan_grid(extent, most)?,
    };
    Ok(s.contour(&grid, DATUM, alphas)?)
}

/// One height of a contour map and its polylines.
pub type ContourLevel = (f64, Vec<Vec<[f64; 2]>>);

/// The crisp surface's contour lines at each height of `heights` (the
/// contour map), traced by the core on a grid of [`CONTOUR_MAP_CELLS`]
/// along the longer side: per height, polylines.
///
/// # Errors
/// As [`datum_contour`].
pub fn contour_map(s: &FuzzySurface<3>, heights: &[f64]) -> Result<Vec<ContourLevel>, Error> {
    let grid = plan_grid(s.plan_extent(), CONTOUR_MAP_CELLS)?;
    use rayon::prelude::*;
    heights
        .par_iter()
        .map(|&z| Ok((z, s.contour(&grid, z, &[])?.crisp)))
        .collect()
}

/// The least and the greatest height of the crisp surface (its bounding
/// box in z).
#[must_use]
pub fn height_range(s: &FuzzySurface<3>) -> [f64; 2] {
    let b = s.crisp_surface().bounding_box();
    [b.min[2], b.max[2]]
}

/// One fuzzy quantity of a terrain: its cuts under each membership
/// function, by increasing level, and the crisp surface's value.
#[derive(Clone, Debug, PartialEq)]
pub struct TerrainQuantity {
    /// What it is ("volume below z = 0").
    pub name: &'static str,
    /// The cuts per function.
    pub levels: PerMembership<Vec<Level>>,
    /// The crisp surface's value: the upper function's cut at level 1.
    pub crisp: f64,
}

/// The terrain's fuzzy measures: volume below and above the datum, plan
/// area below it, and (nets of at most [`SURFACE_AREA_MAX_POINTS`] points)
/// the surface area.
#[derive(Clone, Debug, PartialEq)]
pub struct TerrainMeasures {
    /// Volume below, volume above, plan area below, then surface area.
    pub quantities: Vec<TerrainQuantity>,
    /// The plan area of the surface.
    pub plan_area: f64,
    /// The levels the volumes and plan area are traced at.
    pub levels: usize,
    /// The levels the surface area is traced at; `None` where it is left
    /// out (the net has more than [`SURFACE_AREA_MAX_POINTS`] points).
    pub area_levels: Option<usize>,
}

/// `uniform` plus `extra` (each in [0, 1]), increasing, without repeats.
fn levels_with(uniform: impl Iterator<Item = f64>, extra: &[f64]) -> Result<Vec<Alpha>, Error> {
    let mut a: Vec<f64> = uniform.collect();
    a.extend(extra.iter().copied().filter(|h| (0.0..=1.0).contains(h)));
    a.sort_by(f64::total_cmp);
    a.dedup();
    Ok(a.into_iter()
        .map(Alpha::try_new)
        .collect::<Result<_, _>>()?)
}

/// The crisp value of a quantity: its bracket at level 1 under the upper
/// function (the crisp net); NaN if absent.
fn crisp_value(upper: &[Level]) -> f64 {
    upper
        .iter()
        .find(|l| l.alpha == 1.0)
        .map_or(f64::NAN, |l| 0.5 * (l.min + l.max))
}

/// The fuzzy measures of terrain `s` (lower heights `heights`) about the
/// datum: volumes and plan area below at [`TERRAIN_MEASURE_LEVELS`] levels
/// and every h, the surface area at [`SURFACE_AREA_LEVELS`] and every h
/// (nets of at most [`SURFACE_AREA_MAX_POINTS`] points), both asked at once.
///
/// # Errors
/// [`Error::Core`] if the core refuses (never for a terrain).
pub fn terrain_measures(s: &FuzzySurface<3>, heights: &[f64]) -> Result<TerrainMeasures, Error> {
    let n = TERRAIN_MEASURE_LEVELS - 1;
    let levels = levels_with((0..=n).map(|k| k as f64 / n as f64), heights)?;
    let with_area = s.points().len() <= SURFACE_AREA_MAX_POINTS;
    let area_levels = levels_with(SURFACE_AREA_LEVELS.into_iter(), heights)?;
    let (volumes, area) = rayon::join(
        || s.measure(&SurfaceMeasureOptions::new(levels.clone(), DATUM)?.with_area(false)),
        || {
            with_area
                .then(|| s.measure(&SurfaceMeasureOptions::new(area_levels.clone(), DATUM)?))
                .transpose()
        },
    );
    let (m, area) = (volumes?, area?);
    let quantity = |name, levels: PerMembership<Vec<Level>>| TerrainQuantity {
        name,
        crisp: crisp_value(&levels.upper),
        levels,
    };
    let mut quantities = vec![
        quantity("volume below z = 0", m.volume_below),
        quantity("volume above z = 0", m.volume_above),
        quantity("plan area below z = 0", m.plan_area_below),
    ];
    if let Some(a) = area.and_then(|a| a.area) {
        quantities.push(quantity("surface area", a));
    }
    Ok(TerrainMeasures {
        quantities,
        plan_area: m.plan_area[0],
        levels: levels.len(),
        area_levels: with_area.then_some(area_levels.len()),
    })
}
