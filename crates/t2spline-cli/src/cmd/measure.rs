//! `t2spline measure JOB.json [--alpha A | --levels N] [--at T1,T2,…]
//! [--order K] [--datum Z0] [--no-area] [--against JOB2] [-o OUT.json]`:
//! arc length, area, derivative, tangent angle and curvature of a fuzzy
//! curve (docs/method.md §11), or the volumes above and below the plane
//! `z = Z0`, the plan area below it and the surface area of a fuzzy surface
//! of crisp plan (§14), and with `--against` the cut and fill between it
//! and a second surface of the same plan map, as intervals at each level.

use t2spline::measure::{
    MeasureOptions, Measures, SurfaceMeasureOptions, DEFAULT_MEASURE_LEVELS, MAX_MEASURE_LEVELS,
};
use t2spline::{Alpha, Error, FuzzyCurve, FuzzySurface};

use super::levels::Levels;
use super::model_kind::ModelKind;
use super::prepare::{about_option, OptionError};
use crate::clash::Claims;
use crate::cli::MeasureArgs;
use crate::output::{is_stdio, read_job, shown, Outputs};

pub fn measure(args: &MeasureArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        let inputs = std::iter::once(args.job.as_path()).chain(args.against.as_deref());
        Claims::new(inputs).file("--output", out)?;
    }
    if let Some(against) = &args.against {
        if is_stdio(against) && is_stdio(&args.job) {
            return Err(invalid(
                "--against",
                "standard input is read once, and the job reads it already",
            ));
        }
    }
    let (levels, at) = options(args)?;
    let job = read_job(&args.job)?;
    let levels = levels.resolve(&job)?;
    let curve = |area: bool| {
        MeasureOptions::new(levels.clone(), at.clone(), order(args))
            .map(|o| o.closed(job.closed).quantities(true, area))
            .map_err(about_option)
    };
    let mut bytes = Vec::new();
    match ModelKind::of(&job.model)? {
        ModelKind::PlaneCurve(c) => write(&mut bytes, &run(c, &curve(true)?, args)?)?,
        ModelKind::SpaceCurve(c) => write(&mut bytes, &run(c, &curve(false)?, args)?)?,
        ModelKind::Surface(s) => {
            if args.at.is_some() {
                return Err(invalid(
                    "--at",
                    "parameters are measured on curves; this job is a surface",
                ));
            }
            let surface = SurfaceMeasureOptions::new(levels, args.datum.unwrap_or(0.0))
                .map_err(about_option)?
                .with_area(!args.no_area);
            let against = match &args.against {
                Some(path) => Some((path, surface_job(path)?)),
                None => None,
            };
            let measured = match &against {
                Some((_, other)) => s.measure_against(other, &surface),
                None => s.measure(&surface),
            };
            let measures = measured.map_err(|e| match e {
                Error::PlansDiffer { what } => {
                    let path = against.as_ref().map_or(args.job.as_path(), |a| a.0);
                    anyhow::anyhow!(
                        "--against {}: its plan cannot be compared with {}'s ({what}); cut and fill need crisp x and y in both surfaces and plans that overlap",
                        shown(path),
                        shown(&args.job)
                    )
                }
                other => other.into(),
            })?;
            t2spline_io::check_finite(&measures)?;
            t2spline_io::write_json_pretty(&mut bytes, &measures)?;
        }
    }
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

/// The surface of the job `--against` names; a job of another kind is
/// refused, naming the file.
fn surface_job(path: &std::path::Path) -> anyhow::Result<FuzzySurface<3>> {
    let job = read_job(path)?;
    let surface = ModelKind::of(&job.model).ok().and_then(ModelKind::surface);
    surface.cloned().ok_or_else(|| {
        anyhow::anyhow!(
            "--against {}: not a surface job; cut and fill are measured between two surfaces",
            shown(path)
        )
    })
}

fn write(bytes: &mut Vec<u8>, measures: &Measures) -> anyhow::Result<()> {
    t2spline_io::check_finite(measures)?;
    t2spline_io::write_json_pretty(bytes, measures)?;
    Ok(())
}

/// The measurement, with a parameter outside the domain named as `--at`.
fn run<const D: usize>(
    curve: &FuzzyCurve<D>,
    options: &MeasureOptions,
    args: &MeasureArgs,
) -> anyhow::Result<Measures> {
    if args.datum.is_some() || args.no_area || args.against.is_some() {
        let flag = if args.datum.is_some() {
            "--datum"
        } else if args.no_area {
            "--no-area"
        } else {
            "--against"
        };
        return Err(invalid(
            flag,
            "this applies to surfaces; this job is a curve",
        ));
    }
    curve.measure(options).map_err(|e| match e {
        Error::MeasureAt { .. } => invalid("--at", &e.to_string()),
        other => other.into(),
    })
}

fn invalid(option: &'static str, message: &str) -> anyhow::Error {
    OptionError {
        option,
        message: message.to_owned(),
    }
    .into()
}

/// The levels and parameters from the flags, each checked and named before
/// the job is read (the levels resolved once it is): the parameters and the
/// order by the core's rules of [`MeasureOptions`] at one level, and again
/// at the levels of the job.
fn options(args: &MeasureArgs) -> anyhow::Result<(Levels, Vec<f64>)> {
    let count = |n: usize| u64::try_from(n).unwrap_or(u64::MAX);
    let levels = Levels::from_arg(
        &args.levels,
        Some(count(DEFAULT_MEASURE_LEVELS)),
        count(MAX_MEASURE_LEVELS),
    )?;
    let at = match &args.at {
        Some(text) => parse_at(text)?,
        None => Vec::new(),
    };
    MeasureOptions::new(vec![Alpha::ONE], at.clone(), order(args)).map_err(about_option)?;
    Ok((levels, at))
}

/// `--order` (a count the core checks; one beyond `usize` is beyond its
/// limit too).
fn order(args: &MeasureArgs) -> usize {
    usize::try_from(args.order).unwrap_or(usize::MAX)
}

/// `T1,T2,…` as finite numbers, each error naming the item.
fn parse_at(text: &str) -> anyhow::Result<Vec<f64>> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    parts
        .iter()
        .enumerate()
        .map(|(i, p)| match p.parse::<f64>() {
            Ok(t) if t.is_finite() => Ok(t),
            _ => Err(invalid(
                "--at",
                &format!(
                    "item {} `{}` is not a finite number",
                    i + 1,
                    t2spline_io::printable(p)
                ),
            )),
        })
        .collect()
}
