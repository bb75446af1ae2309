//! `t2spline fuzzify READINGS [-o DATA.json] [--tolerance T]
//! [--lower-height H] [--degree P[,Q] | --order K[,KV]] [--alpha A]
//! [--block K [--origin X0,Y0 --spacing DX,DY]]`.

use std::path::{Path, PathBuf};

use anyhow::anyhow;
use t2spline_io::{
    data_json_text, fuzzify_net, fuzzify_readings, parse_ascii_grid, parse_data, parse_grid_csv,
    printable, read_npy, FitData, Raster, RasterGeometry, ReadingsError, ReadingsOption,
    ReadingsOptions,
};

use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::{FuzzifyArgs, ReadingsArgs};
use crate::output::{job_name, read_input, Outputs};

/// The options of the rule and the degrees, as the I/O crate takes them:
/// `--degree P,Q` (and `--order`) split into the degree along u and along v.
fn options(args: &ReadingsArgs, alpha: Option<f64>) -> anyhow::Result<ReadingsOptions> {
    let pair = |values: &Option<Vec<u64>>,
                option: &'static str|
     -> anyhow::Result<(Option<u64>, Option<u64>)> {
        match values.as_deref() {
            None => Ok((None, None)),
            Some([p]) => Ok((Some(*p), None)),
            Some([p, q]) => Ok((Some(*p), Some(*q))),
            Some(_) => Err(OptionError {
                option,
                message: "one value, or a pair P,Q for a net (along u, along v)".into(),
            }
            .into()),
        }
    };
    let (degree, degree_v) = pair(&args.degree, "--degree")?;
    let (order, order_v) = pair(&args.order, "--order")?;
    ReadingsOptions::new(
        args.tolerance,
        args.lower_height,
        [degree, degree_v],
        [order, order_v],
        alpha,
    )
    .map_err(spelled)
}

/// The error of the I/O crate with the option it names spelled as a flag.
fn spelled(e: ReadingsError) -> anyhow::Error {
    match e {
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
    }
}

/// Fuzzy data points from the readings file at `path` (whose text is
/// `text`), with the rule and the degree from the options, and the
/// `alpha` to carry; the validated data of a fit (the I/O crate's
/// [`fuzzify_readings`], errors naming the option).
pub(super) fn readings_data(
    path: &Path,
    text: &str,
    options: &ReadingsArgs,
    alpha: Option<f64>,
) -> anyhow::Result<FitData> {
    let options = self::options(options, alpha)?;
    fuzzify_readings(text, &job_name(path), &options).map_err(spelled)
}

/// The kinds of raster `--block` reads, by the file's extension.
enum RasterKind {
    Csv,
    Ascii,
    Npy,
}

/// The raster's kind, or `None` for readings of stations; `.asc` and
/// `.npy` need `--block`, `--origin` and `--spacing` belong to `.npy`.
fn raster_kind(args: &FuzzifyArgs) -> anyhow::Result<Option<RasterKind>> {
    let extension = args
        .readings
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let kind = match (extension.as_deref(), args.block) {
        (Some("asc"), _) => Some(RasterKind::Ascii),
        (Some("npy"), _) => Some(RasterKind::Npy),
        (_, Some(_)) => Some(RasterKind::Csv),
        (_, None) => None,
    };
    let option = |option: &'static str, message: String| -> anyhow::Error {
        OptionError { option, message }.into()
    };
    if kind.is_some() && args.block.is_none() {
        return Err(option(
            "--block",
            format!(
                "{}: a raster's cells are single readings; give --block K for the K × K cells that are the readings of one station",
                printable(&job_name(&args.readings))
            ),
        ));
    }
    if !matches!(kind, Some(RasterKind::Npy)) {
        for (name, given) in [("--origin", &args.origin), ("--spacing", &args.spacing)] {
            if given.is_some() {
                return Err(option(
                    name,
                    "only for a .npy raster; a CSV grid and an ESRI ASCII grid say where their cells are".into(),
                ));
            }
        }
    }
    if let Some(k) = args.block.filter(|&k| k < 2) {
        return Err(option(
            "--block",
            format!("{k}: a block of K × K cells needs K of at least 2, for at least 2 readings per station"),
        ));
    }
    Ok(kind)
}

/// The geometry of a `.npy` raster from `--origin` and `--spacing`.
fn geometry(args: &FuzzifyArgs) -> anyhow::Result<RasterGeometry> {
    let pair = |values: &Option<Vec<f64>>, option: &'static str, what: &str| match values.as_deref()
    {
        Some(&[a, b]) if a.is_finite() && b.is_finite() => Ok([a, b]),
        Some(_) => Err(anyhow::Error::from(OptionError {
            option,
            message: format!("two finite numbers {what}"),
        })),
        None => Err(OptionError {
            option,
            message: format!(
                "a .npy raster needs {option} {what}: the cells' places are not in the file"
            ),
        }
        .into()),
    };
    let origin = pair(
        &args.origin,
        "--origin",
        "X0,Y0 (the centre of the cell at row 0, column 0)",
    )?;
    let spacing = pair(
        &args.spacing,
        "--spacing",
        "DX,DY (the step per column and per row)",
    )?;
    if spacing.contains(&0.0) {
        return Err(OptionError {
            option: "--spacing",
            message: "the steps DX and DY must not be 0".into(),
        }
        .into());
    }
    Ok(RasterGeometry { origin, spacing })
}

/// The data of a fit from a raster: read, cut into blocks, fuzzified; a
/// note on standard error for rows and columns left out.
fn raster_data(args: &FuzzifyArgs, kind: &RasterKind) -> anyhow::Result<FitData> {
    let options = options(&args.rule, args.alpha)?;
    let block = args.block.unwrap_or(2);
    let name = job_name(&args.readings);
    let raster: Raster = match kind {
        RasterKind::Npy => read_npy(&args.readings, &geometry(args)?)?,
        RasterKind::Ascii => parse_ascii_grid(&read_input(&args.readings)?, &name)?,
        RasterKind::Csv => parse_grid_csv(&read_input(&args.readings)?, &name)?,
    };
    let (net, note) = raster.blocks(usize::try_from(block).unwrap_or(usize::MAX))?;
    let data = fuzzify_net(&net, &options).map_err(spelled)?;
    if let Some(note) = note {
        crate::output::note("fuzzify", note);
    }
    Ok(data)
}

pub fn fuzzify(args: FuzzifyArgs) -> anyhow::Result<()> {
    if let Some(output) = &args.output {
        Claims::new([args.readings.as_path()]).file("--output", output)?;
    }
    let data = match raster_kind(&args)? {
        Some(kind) => raster_data(&args, &kind)?,
        None => {
            let text = read_input(&args.readings)?;
            readings_data(&args.readings, &text, &args.rule, args.alpha)?
        }
    };
    let json = data_json_text(&data);
    let output: Option<PathBuf> = args.output;
    // The last guard: what is written must be a valid data file.
    let name = output.as_deref().map_or("<stdout>".to_owned(), job_name);
    parse_data(&json, &name)
        .map_err(|e| anyhow!("internal error: the data file does not validate:\n{e}"))?;
    let mut out = Outputs::default();
    out.to(output.as_deref(), json.into_bytes());
    out.commit()
}
