//! `t2spline fuzzify READINGS.csv [-o DATA.json] [--tolerance T]
//! [--lower-height H] [--degree P | --order K] [--alpha A]`.

use std::path::{Path, PathBuf};

use anyhow::anyhow;
use t2spline_io::{
    data_json, fuzzify_readings, parse_data, to_json_pretty, FitData, ReadingsError,
    ReadingsOption, ReadingsOptions,
};

use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::{FuzzifyArgs, ReadingsArgs};
use crate::output::{job_name, read_input, Outputs};

/// Fuzzy data points from the readings file at `path` (whose text is
/// `text`), with the rule and the curve's degree from the options, and the
/// `alpha` to carry; the validated data of a fit (the I/O crate's
/// [`fuzzify_readings`], errors naming the option).
pub(super) fn readings_data(
    path: &Path,
    text: &str,
    options: &ReadingsArgs,
    alpha: Option<f64>,
) -> anyhow::Result<FitData> {
    let options = ReadingsOptions {
        tolerance: options.tolerance,
        lower_height: options.lower_height,
        degree: options.degree,
        order: options.order,
        alpha,
    };
    fuzzify_readings(text, &job_name(path), &options).map_err(|e| match e {
        ReadingsError::File(e) => e.into(),
        ReadingsError::Option { option, message } => OptionError {
            option: match option {
                ReadingsOption::Tolerance => "--tolerance",
                ReadingsOption::LowerHeight => "--lower-height",
                ReadingsOption::Degree => "--degree",
                ReadingsOption::Order => "--order",
                ReadingsOption::Alpha => "--alpha",
            },
            message,
        }
        .into(),
    })
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
