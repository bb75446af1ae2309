//! Readings to the data of a fit by the options of `t2spline fuzzify`
//! (and `fit` of a readings file, and Python's `t2spline.fuzzify`): the
//! rule's tolerance and lower height, the curve's degree or order (default
//! [`DEFAULT_DEGREE`]), the alpha to carry, and enough stations for the
//! degree. Each front end spells the option an error names
//! ([`ReadingsOption`]: `--tolerance`, `tolerance=`).

use std::fmt;

use t2spline::fit::{FuzzifyRule, DEFAULT_LOWER_HEIGHT};
use t2spline::Alpha;

use super::curve::parse_readings;
use super::net::parse_net_readings;
use super::net::NetReadings;
use crate::error::Error;
use crate::fit_data::FitData;
use crate::limits::MAX_ORDER;

/// The degree of a fit when neither a degree nor an order is given.
pub const DEFAULT_DEGREE: usize = 3;

/// How readings become fuzzy data points, as given (each checked by
/// [`fuzzify_readings`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ReadingsOptions {
    /// The instrument's accuracy `T` (default 0).
    pub tolerance: Option<f64>,
    /// The lower membership function's height (default
    /// [`DEFAULT_LOWER_HEIGHT`]).
    pub lower_height: Option<f64>,
    /// The curve's degree (default [`DEFAULT_DEGREE`]).
    pub degree: Option<u64>,
    /// The curve's order; wins over `degree`.
    pub order: Option<u64>,
    /// For a net: the degree along v, the second of a pair `P,Q`
    /// (`degree` is then the degree along u); default: `degree`.
    pub degree_v: Option<u64>,
    /// For a net: the order along v, the second of a pair (`order` is then
    /// the order along u); default: `order`.
    pub order_v: Option<u64>,
    /// The level alpha to carry into the data (and so into the fitted job).
    pub alpha: Option<f64>,
}

/// An option of [`ReadingsOptions`], named by an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReadingsOption {
    /// [`ReadingsOptions::tolerance`].
    Tolerance,
    /// [`ReadingsOptions::lower_height`].
    LowerHeight,
    /// [`ReadingsOptions::degree`].
    Degree,
    /// [`ReadingsOptions::order`].
    Order,
    /// [`ReadingsOptions::alpha`].
    Alpha,
}

/// Why readings gave no data.
#[derive(Debug, thiserror::Error)]
pub enum ReadingsError {
    /// An option's value breaks its rule (or asks for more stations than the
    /// file has).
    #[error("{message}")]
    Option {
        /// Which option: each front end spells it its own way.
        option: ReadingsOption,
        /// The value and the rule it breaks.
        message: String,
    },
    /// The file's problems, each with its line and column.
    #[error(transparent)]
    File(#[from] Error),
}

impl fmt::Display for ReadingsOption {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ReadingsOption::Tolerance => "tolerance",
            ReadingsOption::LowerHeight => "lower_height",
            ReadingsOption::Degree => "degree",
            ReadingsOption::Order => "order",
            ReadingsOption::Alpha => "alpha",
        })
    }
}

fn refused(option: ReadingsOption, message: impl Into<String>) -> ReadingsError {
    ReadingsError::Option {
        option,
        message: message.into(),
    }
}

/// The validated data of a fit from the readings file `text` (named
/// `source` in messages) by `options`: the readings of a curve's stations
/// (header `station,x,y[,z]`) or of a net's (header `row,col,x,y,z`,
/// [`parse_net_readings`](super::net::parse_net_readings), then
/// [`fuzzify_net`]); median, quartiles, 10th–90th
/// percentiles and the extremes widened by the tolerance of each station
/// (the core's [`Readings::fuzzify`](t2spline::fit::Readings::fuzzify)),
/// with a description of how.
///
/// # Errors
/// [`ReadingsError::Option`] for an option out of its range or a degree
/// the stations cannot carry; [`ReadingsError::File`] for the file's
/// problems.
///
/// # Examples
/// ```
/// # use t2spline_io::{fuzzify_readings, ReadingsOptions};
/// let text = std::fs::read_to_string("../../examples/beach-readings.csv")?;
/// let options = ReadingsOptions { alpha: Some(0.5), ..ReadingsOptions::default() };
/// let data = fuzzify_readings(&text, "beach-readings.csv", &options)?;
/// assert_eq!((data.degree, data.alpha.map(|a| a.get())), (3, Some(0.5)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fuzzify_readings(
    text: &str,
    source: &str,
    options: &ReadingsOptions,
) -> Result<FitData, ReadingsError> {
    let rule = rule(options)?;
    if super::net::is_net(text) {
        let net = parse_net_readings(text, source)?;
        return fuzzify_net(&net, options);
    }
    if let Some((option, _)) = [
        (ReadingsOption::Degree, options.degree_v),
        (ReadingsOption::Order, options.order_v),
    ]
    .into_iter()
    .find(|(_, v)| v.is_some())
    {
        return Err(refused(
            option,
            format!("a pair P,Q is for a net (the header row,col,x,y,z, or a raster); the stations of a curve take one {option}"),
        ));
    }
    let (degree_key, option, degree) = degree(options)?;
    let alpha = alpha(options)?;
    let file = parse_readings(text, source)?;
    if file.stations.len() < degree + 1 {
        return Err(refused(
            option,
            format!(
                "{}: {} stations, but a curve of degree {degree} needs at least {}; give a lower degree",
                crate::printable(&file.source),
                file.stations.len(),
                degree + 1
            ),
        ));
    }
    let points = file
        .readings
        .fuzzify(&rule)
        .map_err(|e| file.fuzzify_error(&e))?;
    Ok(file.fit_data(points, &rule, degree_key, degree, alpha))
}

/// The validated data of a fit from the readings of a net's stations, by
/// `options`: per station and coordinate the rule of [`fuzzify_readings`]
/// (for the blocks of a raster, `x` and `y` are the block's centre, crisp,
/// and `z` is fuzzified), as rows of fuzzy data points (`points[i][j]`),
/// with the degrees `[p, q]` of `--degree P,Q` (one `P` for both; default
/// [`DEFAULT_DEGREE`] for both).
///
/// # Errors
/// [`ReadingsError::Option`] for an option out of its range or a degree
/// the rows or columns of the net cannot carry; [`ReadingsError::File`]
/// for a value the rule takes beyond the range of coordinates.
///
/// # Examples
/// ```
/// # use t2spline_io::{fuzzify_net, parse_net_readings, ReadingsOptions};
/// let mut text = String::from("row,col,x,y,z\n");
/// for (i, j, z) in [(0, 0, 1.0), (0, 1, 2.0), (1, 0, 3.0), (1, 1, 4.0)] {
///     text += &format!("{i},{j},{j},{i},{z}\n{i},{j},{j},{i},{}\n", z + 0.5);
/// }
/// let net = parse_net_readings(&text, "net.csv")?;
/// let options = ReadingsOptions { degree: Some(1), ..ReadingsOptions::default() };
/// let data = fuzzify_net(&net, &options)?;
/// assert_eq!((data.degree, data.degree_v), (1, Some(1)));
/// let json = t2spline_io::data_json(&data);
/// assert_eq!(json["degree"], serde_json::json!([1, 1]));
/// assert_eq!(json["points"][1][0]["z"]["crisp"], 3.25);
/// assert_eq!(json["points"][1][0]["x"]["upper"], serde_json::json!([0.0, 0.0]));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fuzzify_net(net: &NetReadings, options: &ReadingsOptions) -> Result<FitData, ReadingsError> {
    let rule = rule(options)?;
    let (degree_key, option, degrees) = net_degrees(options)?;
    let alpha = alpha(options)?;
    for ((p, n), (direction, lines)) in degrees
        .into_iter()
        .zip(net.shape)
        .zip([("u", "row(s)"), ("v", "station(s) per row")])
    {
        if n <= p {
            return Err(refused(
                option,
                format!(
                    "{}: a net of {} × {} stations has {n} {lines}, but degree {p} along {direction} needs at least {}; give a lower degree",
                    crate::printable(&net.source),
                    net.shape[0],
                    net.shape[1],
                    p + 1
                ),
            ));
        }
    }
    let points = net.fuzzify(&rule)?;
    Ok(net.fit_data(points, &rule, degree_key, degrees, alpha))
}

/// The rule from the options.
fn rule(options: &ReadingsOptions) -> Result<FuzzifyRule, ReadingsError> {
    FuzzifyRule::try_new(
        options.tolerance.unwrap_or(0.0),
        options.lower_height.unwrap_or(DEFAULT_LOWER_HEIGHT),
    )
    .map_err(|e| {
        let option = match e {
            t2spline::Error::OutOfRange {
                what: "tolerance", ..
            } => ReadingsOption::Tolerance,
            _ => ReadingsOption::LowerHeight,
        };
        refused(option, e.to_string())
    })
}

/// The alpha to carry, checked.
fn alpha(options: &ReadingsOptions) -> Result<Option<Alpha>, ReadingsError> {
    options
        .alpha
        .map(Alpha::try_new)
        .transpose()
        .map_err(|e| refused(ReadingsOption::Alpha, e.to_string()))
}

/// The degrees `[p, q]` of a net from the orders or the degrees (one for
/// both, or a pair; default [`DEFAULT_DEGREE`] for both), with the key the
/// data file will use and the option that gave them.
fn net_degrees(
    options: &ReadingsOptions,
) -> Result<(&'static str, ReadingsOption, [usize; 2]), ReadingsError> {
    let (key, option, p) = degree(options)?;
    let second = if options.order.is_some() {
        options.order_v.map(|k| k.checked_sub(1))
    } else {
        options.degree_v.map(Some)
    };
    let q = match second {
        None => p,
        Some(Some(q)) if q >= 1 && q < MAX_ORDER as u64 => q as usize,
        Some(_) => {
            return Err(refused(
                option,
                format!(
                    "a fit needs degree 1 to {} (order 2 to {MAX_ORDER}) in each direction",
                    MAX_ORDER - 1
                ),
            ))
        }
    };
    Ok((key, option, [p, q]))
}

/// The degree from the order or the degree (default [`DEFAULT_DEGREE`]),
/// with the key the data file will use and the option that gave it.
fn degree(
    options: &ReadingsOptions,
) -> Result<(&'static str, ReadingsOption, usize), ReadingsError> {
    let (key, option, degree) = match (options.degree, options.order) {
        (_, Some(k)) => ("order", ReadingsOption::Order, k.checked_sub(1)),
        (Some(p), None) => ("degree", ReadingsOption::Degree, Some(p)),
        (None, None) => return Ok(("degree", ReadingsOption::Degree, DEFAULT_DEGREE)),
    };
    match degree {
        Some(p) if p >= 1 && p < MAX_ORDER as u64 => Ok((key, option, p as usize)),
        _ => Err(refused(
            option,
            format!(
                "a fit needs degree 1 to {} (order 2 to {MAX_ORDER})",
                MAX_ORDER - 1
            ),
        )),
    }
}
