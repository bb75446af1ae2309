//! `t2spline contour JOB.json --z Z0 [--alpha A | --levels N] [--grid NX,NY]
//! [--extent X0,Y0,X1,Y1] [-o OUT.geojson]`: the plan points where a fuzzy
//! surface can cross the height Z0, per level and membership function, as
//! GeoJSON polygons, beside the crisp surface's contour (docs/method.md §13).

use std::path::Path;

use t2spline::Error;
use t2spline_io::set::write_contour_geojson;

use super::envelope::{invalid, parse_extent, parse_grid, plan_grid};
use super::levels::{Levels, MAX_LEVELS};
use super::model_kind::ModelKind;
use crate::clash::Claims;
use crate::cli::ContourArgs;
use crate::output::{is_stdio, read_job, Outputs};

/// The checked options.
struct Plan {
    z: f64,
    levels: Levels,
    shape: Option<[usize; 2]>,
    extent: Option<[f64; 4]>,
}

pub fn contour(args: &ContourArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        Claims::new([args.job.as_path()]).file("--output", out)?;
    }
    let plan = plan(args)?;
    let job = read_job(&args.job)?;
    let Some(surface) = ModelKind::of(&job.model)?.surface() else {
        return Err(crate::output::unsuited(
            &args.job,
            "contours are traced on surfaces (a net of control points); this job is a curve: ask `t2spline region` or `t2spline section`",
        ));
    };
    if !surface.has_crisp_plan() {
        return Err(crate::output::unsuited(
            &args.job,
            "the contour needs crisp x and y at every control point (a terrain: stations at known places); this surface's plan is fuzzy: ask `t2spline envelope` for its heights",
        ));
    }
    let levels = plan.levels.resolve(&job)?;
    let extent = plan.extent.unwrap_or_else(|| surface.plan_extent());
    let shape = plan.shape.unwrap_or_else(|| surface.contour_shape(extent));
    let grid = plan_grid(extent, shape, plan.extent.is_some())?;
    let contour = surface
        .contour(&grid, plan.z, &levels)
        .map_err(|e| match e {
            Error::EnvelopeTooLarge { .. } => invalid("--grid", &e.to_string()),
            other => other.into(),
        })?;
    let mut bytes = Vec::new();
    write_contour_geojson(&mut bytes, &contour)?;
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

/// Every option checked and named, before the job is read.
fn plan(args: &ContourArgs) -> anyhow::Result<Plan> {
    if !args.z.is_finite() {
        return Err(invalid(
            "--z",
            &format!("{} is not a finite number", args.z),
        ));
    }
    let levels = Levels::from_arg(&args.levels, None, MAX_LEVELS)?;
    let shape = args.grid.as_deref().map(parse_grid).transpose()?;
    let extent = args.extent.as_deref().map(parse_extent).transpose()?;
    check_output(args.output.as_deref())?;
    Ok(Plan {
        z: args.z,
        levels,
        shape,
        extent,
    })
}

/// The output is GeoJSON: a name ending in `.geojson` or `.json`.
fn check_output(output: Option<&Path>) -> anyhow::Result<()> {
    let Some(path) = output.filter(|p| !is_stdio(p)) else {
        return Ok(());
    };
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("geojson" | "json") => Ok(()),
        _ => Err(invalid(
            "--output",
            &format!(
                "`{}` does not end in .geojson or .json: the contour is written as GeoJSON",
                crate::output::shown(path)
            ),
        )),
    }
}
