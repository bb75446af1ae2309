//! `t2spline measure JOB.json [--levels N] [--at T1,T2,…] [--order K]
//! [-o OUT.json]`: arc length, area, derivative, tangent angle and
//! curvature of a fuzzy curve as intervals at each level (docs/method.md
//! §11).

use t2spline::job::Model;
use t2spline::measure::{MeasureOptions, Measures, MAX_MEASURE_LEVELS, MAX_MEASURE_PARAMETERS};
use t2spline::{Error, FuzzyCurve};

use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::MeasureArgs;
use crate::output::{read_job, Outputs};

pub fn measure(args: &MeasureArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        Claims::new([args.job.as_path()]).file("--output", out)?;
    }
    let mut options = options(args)?;
    let job = read_job(&args.job)?;
    let measures = match &job.model {
        Model::Planar(c) => run(c, &mut options)?,
        Model::Spatial(c) => {
            options.area = false;
            run(c, &mut options)?
        }
        _ => return Err(invalid(
            "JOB",
            "measures are taken of curves; this job is a surface (surfaces are not measured yet)",
        )),
    };
    t2spline_io::check_finite(&measures)?;
    let mut bytes = Vec::new();
    t2spline_io::write_json_pretty(&mut bytes, &measures)?;
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

/// The measurement, with a parameter outside the domain named as `--at`.
fn run<const D: usize>(
    curve: &FuzzyCurve<D>,
    options: &mut MeasureOptions,
) -> anyhow::Result<Measures> {
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

/// The options from the flags, each checked and named.
fn options(args: &MeasureArgs) -> anyhow::Result<MeasureOptions> {
    let levels = usize::try_from(args.levels).unwrap_or(usize::MAX);
    if !(2..=MAX_MEASURE_LEVELS).contains(&levels) {
        return Err(invalid(
            "--levels",
            &format!("{} is outside 2 ..= {MAX_MEASURE_LEVELS}", args.levels),
        ));
    }
    let mut options = MeasureOptions::uniform(levels)?;
    if !(1..=64).contains(&args.order) {
        return Err(invalid(
            "--order",
            &format!("{} is outside 1 ..= 64", args.order),
        ));
    }
    options.order = args.order as usize;
    if let Some(text) = &args.at {
        options.at = parse_at(text)?;
    }
    Ok(options)
}

/// `T1,T2,…` as finite numbers, each error naming the item.
fn parse_at(text: &str) -> anyhow::Result<Vec<f64>> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() > MAX_MEASURE_PARAMETERS {
        return Err(invalid(
            "--at",
            &format!(
                "{} parameters are more than the limit of {MAX_MEASURE_PARAMETERS}",
                parts.len()
            ),
        ));
    }
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
