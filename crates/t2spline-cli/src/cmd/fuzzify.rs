//! `t2spline fuzzify READINGS.csv [-o DATA.json] [--tolerance T]
//! [--lower-height H] [--degree P | --order K] [--alpha A]`.

use std::path::{Path, PathBuf};

use anyhow::anyhow;
use t2spline::fit::{FuzzifyRule, DEFAULT_LOWER_HEIGHT};
use t2spline::Alpha;
use t2spline_io::job::MAX_ORDER;
use t2spline_io::{data_json, parse_data, parse_readings, to_json_pretty, FitData};

use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::{FuzzifyArgs, ReadingsArgs};
use crate::output::{job_name, read_input, Outputs};

/// The degree of a fit when neither `--degree` nor `--order` is given.
const DEFAULT_DEGREE: usize = 3;

/// Fuzzy data points from the readings file at `path` (whose text is
/// `text`), with the rule and the curve's degree from the options, and the
/// `alpha` to carry; the validated data of a fit.
pub(super) fn readings_data(
    path: &Path,
    text: &str,
    options: &ReadingsArgs,
    alpha: Option<f64>,
) -> anyhow::Result<FitData> {
    let rule = FuzzifyRule::try_new(
        options.tolerance.unwrap_or(0.0),
        options.lower_height.unwrap_or(DEFAULT_LOWER_HEIGHT),
    )
    .map_err(|e| OptionError {
        option: match e {
            t2spline::Error::OutOfRange {
                what: "tolerance", ..
            } => "--tolerance",
            _ => "--lower-height",
        },
        message: e.to_string(),
    })?;
    let (degree_key, degree) = degree(options)?;
    let alpha = alpha
        .map(Alpha::try_new)
        .transpose()
        .map_err(|e| OptionError {
            option: "--alpha",
            message: e.to_string(),
        })?;
    let file = parse_readings(text, &job_name(path))?;
    if file.stations.len() < degree + 1 {
        return Err(OptionError {
            option: if degree_key == "order" { "--order" } else { "--degree" },
            message: format!(
                "{}: {} stations, but a curve of degree {degree} needs at least {}; give a lower degree",
                t2spline_io::printable(&file.source),
                file.stations.len(),
                degree + 1
            ),
        }
        .into());
    }
    let points = file
        .readings
        .fuzzify(&rule)
        .map_err(|e| file.fuzzify_error(&e))?;
    Ok(file.fit_data(points, &rule, degree_key, degree, alpha))
}

/// The degree from `--degree` or `--order` (default [`DEFAULT_DEGREE`]), with
/// the key the data file will use.
fn degree(options: &ReadingsArgs) -> anyhow::Result<(&'static str, usize)> {
    let (key, option, degree) = match (options.degree, options.order) {
        (_, Some(k)) => ("order", "--order", k.checked_sub(1)),
        (Some(p), None) => ("degree", "--degree", Some(p)),
        (None, None) => return Ok(("degree", DEFAULT_DEGREE)),
    };
    match degree {
        Some(p) if p >= 1 && p < MAX_ORDER as u64 => Ok((key, p as usize)),
        _ => Err(OptionError {
            option,
            message: format!(
                "a fit needs degree 1 to {} (order 2 to {MAX_ORDER})",
                MAX_ORDER - 1
            ),
        }
        .into()),
    }
}

pub fn fuzzify(args: FuzzifyArgs) -> anyhow::Result<()> {
    if let Some(output) = &args.output {
        Claims::new([args.readings.as_path()]).file("--output", output)?;
    }
    let text = read_input(&args.readings)?;
    let data = readings_data(&args.readings, &text, &args.rule, args.alpha)?;
    let json = to_json_pretty(&data_json(&data));
    let output: Option<PathBuf> = args.output;
    // The last guard: what is written must be a valid data file.
    let name = output.as_deref().map_or("<stdout>".to_owned(), job_name);
    parse_data(&json, &name)
        .map_err(|e| anyhow!("internal error: the data file does not validate:\n{e}"))?;
    let mut out = Outputs::default();
    out.to(output.as_deref(), json.into_bytes());
    out.commit()
}
