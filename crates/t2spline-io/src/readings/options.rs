//! Readings to the data of a fit by the options of `t2spline fuzzify`
//! (and `fit` of a readings file, and Python's `t2spline.fuzzify`): the
//! rule's tolerance and lower height, the curve's degree or order (default
//! [`DEFAULT_DEGREE`]), the alpha to carry, each checked when the
//! [`ReadingsOptions`] are made, and enough stations for the degree, checked
//! with the file. Each front end spells the option an error names
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

/// How readings become fuzzy data points: the rule's tolerance and lower
/// height, the degrees and the alpha to carry, every rule checked once, when
/// made ([`ReadingsOptions::new`]); the fields are private, so options that
/// exist keep the rules, and no front end repeats a range or a default. What
/// needs the file (enough stations for the degree, a pair of degrees only
/// for a net) is checked by [`fuzzify_readings`] and [`fuzzify_net`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReadingsOptions {
    rule: FuzzifyRule,
    degree_key: &'static str,
    degree_option: ReadingsOption,
    degree: usize,
    degree_v: Option<usize>,
    pair: Option<ReadingsOption>,
    alpha: Option<Alpha>,
}

impl ReadingsOptions {
    /// The options as given, each checked: the instrument's accuracy
    /// `tolerance` (default 0) and the lower membership function's
    /// `lower_height` (default [`DEFAULT_LOWER_HEIGHT`]) by
    /// [`FuzzifyRule::try_new`]; the curve's degree, `degree[0]`, or its
    /// order, `order[0]`, which wins (default [`DEFAULT_DEGREE`]), and for a
    /// net the second of a pair `P,Q`, `degree[1]` or `order[1]` (the degree
    /// along v; default: the one along u), each from 1 to `MAX_ORDER − 1`
    /// (an order from 2 to `MAX_ORDER`); the level `alpha` to carry into
    /// the data (and so into the fitted job).
    ///
    /// # Errors
    /// [`ReadingsError::Option`] naming the option whose value breaks its
    /// rule.
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::{ReadingsOption, ReadingsOptions};
    /// let o = ReadingsOptions::new(Some(0.02), None, [None; 2], [Some(3), Some(2)], Some(0.5))?;
    /// assert_eq!((o.degree(), o.degree_v(), o.tolerance(), o.lower_height()), (2, Some(1), 0.02, 0.5));
    /// let e = ReadingsOptions::new(None, None, [Some(0), None], [None; 2], None).unwrap_err();
    /// assert_eq!(e.to_string(), "a fit needs degree 1 to 31 (order 2 to 32)");
    /// # Ok::<(), t2spline_io::ReadingsError>(())
    /// ```
    pub fn new(
        tolerance: Option<f64>,
        lower_height: Option<f64>,
        degree: [Option<u64>; 2],
        order: [Option<u64>; 2],
        alpha: Option<f64>,
    ) -> Result<Self, ReadingsError> {
        let rule = rule(tolerance, lower_height)?;
        let (degree_key, degree_option, p) = self::degree(degree[0], order[0])?;
        let second = if order[0].is_some() {
            order[1].map(|k| k.checked_sub(1))
        } else {
            degree[1].map(Some)
        };
        let degree_v = match second {
            None => None,
            Some(Some(q)) if q >= 1 && q < MAX_ORDER as u64 => Some(q as usize),
            Some(_) => {
                return Err(refused(
                    degree_option,
                    format!(
                        "a fit needs degree 1 to {} (order 2 to {MAX_ORDER}) in each direction",
                        MAX_ORDER - 1
                    ),
                ))
            }
        };
        let pair = [
            (ReadingsOption::Degree, degree[1]),
            (ReadingsOption::Order, order[1]),
        ]
        .into_iter()
        .find_map(|(option, v)| v.map(|_| option));
        let alpha = alpha
            .map(Alpha::try_new)
            .transpose()
            .map_err(|e| refused(ReadingsOption::Alpha, e.to_string()))?;
        Ok(ReadingsOptions {
            rule,
            degree_key,
            degree_option,
            degree: p,
            degree_v,
            pair,
            alpha,
        })
    }

    /// The rule that turns readings into fuzzy numbers.
    #[must_use]
    pub fn rule(&self) -> FuzzifyRule {
        self.rule
    }

    /// The instrument's accuracy `T`.
    #[must_use]
    pub fn tolerance(&self) -> f64 {
        self.rule.tolerance()
    }

    /// The lower membership function's height.
    #[must_use]
    pub fn lower_height(&self) -> f64 {
        self.rule.lower_height().get()
    }

    /// The degree of a curve, or of a net along u.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The degree of a net along v, if a pair was given.
    #[must_use]
    pub fn degree_v(&self) -> Option<usize> {
        self.degree_v
    }

    /// The level alpha to carry into the data.
    #[must_use]
    pub fn alpha(&self) -> Option<Alpha> {
        self.alpha
    }
}

/// An option of [`ReadingsOptions`], named by an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReadingsOption {
    /// [`ReadingsOptions::tolerance`].
    Tolerance,
    /// [`ReadingsOptions::lower_height`].
    LowerHeight,
    /// [`ReadingsOptions::degree`], given as a degree.
    Degree,
    /// [`ReadingsOptions::degree`], given as an order.
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
/// [`ReadingsError::Option`] for a degree the stations cannot carry or a
/// pair of degrees for a curve (the options' ranges were checked when they
/// were made); [`ReadingsError::File`] for the file's problems.
///
/// # Examples
/// ```
/// # use t2spline_io::{fuzzify_readings, ReadingsOptions};
/// let text = std::fs::read_to_string("../../examples/beach-readings.csv")?;
/// let options = ReadingsOptions::new(None, None, [None; 2], [None; 2], Some(0.5))?;
/// let data = fuzzify_readings(&text, "beach-readings.csv", &options)?;
/// assert_eq!((data.degree, data.alpha.map(|a| a.get())), (3, Some(0.5)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fuzzify_readings(
    text: &str,
    source: &str,
    options: &ReadingsOptions,
) -> Result<FitData, ReadingsError> {
    if super::net::is_net(text) {
        let net = parse_net_readings(text, source)?;
        return fuzzify_net(&net, options);
    }
    if let Some(option) = options.pair {
        return Err(refused(
            option,
            format!("a pair P,Q is for a net (the header row,col,x,y,z, or a raster); the stations of a curve take one {option}"),
        ));
    }
    let (option, degree) = (options.degree_option, options.degree);
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
        .fuzzify(&options.rule)
        .map_err(|e| file.fuzzify_error(&e))?;
    Ok(file.fit_data(
        points,
        &options.rule,
        options.degree_key,
        degree,
        options.alpha,
    ))
}

/// The validated data of a fit from the readings of a net's stations, by
/// `options`: per station and coordinate the rule of [`fuzzify_readings`]
/// (for the blocks of a raster, `x` and `y` are the block's centre, crisp,
/// and `z` is fuzzified), as rows of fuzzy data points (`points[i][j]`),
/// with the degrees `[p, q]` of `--degree P,Q` (one `P` for both; default
/// [`DEFAULT_DEGREE`] for both).
///
/// # Errors
/// [`ReadingsError::Option`] for a degree the rows or columns of the net
/// cannot carry; [`ReadingsError::File`] for a value the rule takes beyond
/// the range of coordinates.
///
/// # Examples
/// ```
/// # use t2spline_io::{fuzzify_net, parse_net_readings, ReadingsOptions};
/// let mut text = String::from("row,col,x,y,z\n");
/// for (i, j, z) in [(0, 0, 1.0), (0, 1, 2.0), (1, 0, 3.0), (1, 1, 4.0)] {
///     text += &format!("{i},{j},{j},{i},{z}\n{i},{j},{j},{i},{}\n", z + 0.5);
/// }
/// let net = parse_net_readings(&text, "net.csv")?;
/// let options = ReadingsOptions::new(None, None, [Some(1), None], [None; 2], None)?;
/// let data = fuzzify_net(&net, &options)?;
/// assert_eq!((data.degree, data.degree_v), (1, Some(1)));
/// let json = t2spline_io::data_json(&data);
/// assert_eq!(json["degree"], serde_json::json!([1, 1]));
/// assert_eq!(json["points"][1][0]["z"]["crisp"], 3.25);
/// assert_eq!(json["points"][1][0]["x"]["upper"], serde_json::json!([0.0, 0.0]));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fuzzify_net(net: &NetReadings, options: &ReadingsOptions) -> Result<FitData, ReadingsError> {
    let option = options.degree_option;
    let degrees = [options.degree, options.degree_v.unwrap_or(options.degree)];
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
    let points = net.fuzzify(&options.rule)?;
    Ok(net.fit_data(
        points,
        &options.rule,
        options.degree_key,
        degrees,
        options.alpha,
    ))
}

/// The rule from the tolerance and the lower height (defaults 0 and
/// [`DEFAULT_LOWER_HEIGHT`]).
fn rule(tolerance: Option<f64>, lower_height: Option<f64>) -> Result<FuzzifyRule, ReadingsError> {
    FuzzifyRule::try_new(
        tolerance.unwrap_or(0.0),
        lower_height.unwrap_or(DEFAULT_LOWER_HEIGHT),
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

/// The degree from the order or the degree (default [`DEFAULT_DEGREE`]),
/// with the key the data file will use and the option that gave it.
fn degree(
    degree: Option<u64>,
    order: Option<u64>,
) -> Result<(&'static str, ReadingsOption, usize), ReadingsError> {
    let (key, option, degree) = match (degree, order) {
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
