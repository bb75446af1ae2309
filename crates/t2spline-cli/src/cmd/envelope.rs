//! `t2spline envelope JOB.json --grid NX,NY [--levels N | --alpha A]
//! [--extent X0,Y0,X1,Y1] [--crs EPSG:CODE] [-o OUT]`: the least and
//! greatest height of a fuzzy surface above every cell of a plan grid
//! (docs/method.md §12), as a CSV or Parquet table or a GeoTIFF.

use std::path::Path;

use t2spline::set::{PlanGrid, MAX_ENVELOPE_VALUES};
use t2spline::{Alpha, Error};
use t2spline_io::set::{write_envelope_csv, write_envelope_geotiff, write_envelope_parquet, Crs};

use super::levels::{uniform, MAX_LEVELS};
use super::model_kind::ModelKind;
use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::EnvelopeArgs;
use crate::output::{is_stdio, read_job, Outputs};

/// What the output is, from its name.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Format {
    Csv,
    Parquet,
    GeoTiff,
}

/// The checked options.
struct Plan {
    shape: [usize; 2],
    levels: Vec<Alpha>,
    extent: Option<[f64; 4]>,
    crs: Option<Crs>,
    format: Format,
}

pub fn envelope(args: &EnvelopeArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        Claims::new([args.job.as_path()]).file("--output", out)?;
    }
    let plan = plan(args)?;
    let job = read_job(&args.job)?;
    let Some(surface) = ModelKind::of(&job.model)?.surface() else {
        return Err(crate::output::unsuited(
            &args.job,
            "envelopes are taken of surfaces (a net of control points); this job is a curve: ask `t2spline section` or `t2spline region`",
        ));
    };
    let extent = plan.extent.unwrap_or_else(|| surface.plan_extent());
    let grid = plan_grid(extent, plan.shape, plan.extent.is_some())?;
    let envelope = surface.envelope(&grid, &plan.levels).map_err(|e| match e {
        Error::EnvelopeTooLarge { .. } => invalid("--grid", &e.to_string()),
        other => other.into(),
    })?;
    let mut bytes = Vec::new();
    match plan.format {
        Format::Csv => write_envelope_csv(&mut bytes, &envelope)?,
        Format::Parquet => write_envelope_parquet(&mut bytes, &envelope)?,
        Format::GeoTiff => write_envelope_geotiff(&mut bytes, &envelope, plan.crs)?,
    }
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

pub(super) fn invalid(option: &'static str, message: &str) -> anyhow::Error {
    OptionError {
        option,
        message: message.to_owned(),
    }
    .into()
}

/// The grid of `shape` cells over `extent`, its errors named by the option
/// that set them: the extent is `--extent` when `given`, else the job's.
pub(super) fn plan_grid(
    extent: [f64; 4],
    shape: [usize; 2],
    given: bool,
) -> anyhow::Result<PlanGrid> {
    PlanGrid::try_new(extent, shape).map_err(|e| match e {
        Error::GridRange { .. } if !given => invalid(
            "JOB",
            &format!("the surface's plan extent is not a rectangle ({e}); give one with --extent X0,Y0,X1,Y1"),
        ),
        Error::GridRange { .. } | Error::QueryPoint { .. } => invalid("--extent", &e.to_string()),
        other => invalid("--grid", &other.to_string()),
    })
}

/// Every option checked and named, before the job is read.
fn plan(args: &EnvelopeArgs) -> anyhow::Result<Plan> {
    let shape = parse_grid(&args.grid)?;
    let levels =
        match (args.levels, args.alpha) {
            (_, Some(a)) => vec![Alpha::try_new(a)
                .map_err(|_| invalid("--alpha", &format!("{a} is outside [0, 1]")))?],
            (None, None) => uniform(11),
            (Some(n), None) if (2..=MAX_LEVELS).contains(&n) => uniform(n),
            (Some(n), None) => {
                return Err(invalid(
                    "--levels",
                    &format!("{n} is outside 2 ..= {MAX_LEVELS}"),
                ))
            }
        };
    let values = shape[0]
        .saturating_mul(shape[1])
        .saturating_mul(levels.len())
        .saturating_mul(6);
    if values > MAX_ENVELOPE_VALUES {
        return Err(invalid(
            "--grid",
            &format!(
                "{} x {} cells at {} level(s) are {values} values (cells x levels x 6), more than the limit of {MAX_ENVELOPE_VALUES}",
                shape[0],
                shape[1],
                levels.len()
            ),
        ));
    }
    let extent = args.extent.as_deref().map(parse_extent).transpose()?;
    let format = format(args.output.as_deref())?;
    let crs = args
        .crs
        .as_deref()
        .map(|text| Crs::parse(text).map_err(|m| invalid("--crs", &m)))
        .transpose()?;
    if crs.is_some() && format != Format::GeoTiff {
        return Err(invalid(
            "--crs",
            "is recorded in a GeoTIFF only: give -o OUT.tif, or leave --crs out",
        ));
    }
    Ok(Plan {
        shape,
        levels,
        extent,
        crs,
        format,
    })
}

/// The format from the output's name: standard output is CSV.
fn format(output: Option<&Path>) -> anyhow::Result<Format> {
    let Some(path) = output.filter(|p| !is_stdio(p)) else {
        return Ok(Format::Csv);
    };
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("csv") => Ok(Format::Csv),
        Some("parquet") => Ok(Format::Parquet),
        Some("tif" | "tiff") => Ok(Format::GeoTiff),
        _ => Err(invalid(
            "--output",
            &format!(
                "`{}` does not end in .tif, .tiff, .csv or .parquet, which say what to write",
                crate::output::shown(path)
            ),
        )),
    }
}

/// `NX,NY` as two positive whole numbers.
pub(super) fn parse_grid(text: &str) -> anyhow::Result<[usize; 2]> {
    let parts: Vec<Option<usize>> = text
        .split(',')
        .map(|p| p.trim().parse::<usize>().ok().filter(|&n| n > 0))
        .collect();
    match parts.as_slice() {
        &[Some(nx), Some(ny)] => Ok([nx, ny]),
        _ => Err(invalid(
            "--grid",
            &format!(
                "`{}` is not two positive whole numbers NX,NY",
                t2spline_io::printable(text)
            ),
        )),
    }
}

/// `X0,Y0,X1,Y1` as four finite numbers with `X0 < X1` and `Y0 < Y1`.
pub(super) fn parse_extent(text: &str) -> anyhow::Result<[f64; 4]> {
    let numbers: Vec<Option<f64>> = text
        .split(',')
        .map(|p| p.trim().parse::<f64>().ok().filter(|x| x.is_finite()))
        .collect();
    let &[Some(x0), Some(y0), Some(x1), Some(y1)] = numbers.as_slice() else {
        return Err(invalid(
            "--extent",
            &format!(
                "`{}` is not four finite numbers X0,Y0,X1,Y1",
                t2spline_io::printable(text)
            ),
        ));
    };
    for (name, lo, hi) in [("X", x0, x1), ("Y", y0, y1)] {
        if lo >= hi {
            return Err(invalid(
                "--extent",
                &format!("{name}0 = {lo} is not less than {name}1 = {hi}"),
            ));
        }
    }
    Ok([x0, y0, x1, y1])
}
