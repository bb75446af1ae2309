//! Fuzzified readings as a data file for `fit`.

use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::Value;
use t2spline::fit::{FuzzifyRule, FuzzyData};
use t2spline::{Alpha, Nt2Point, Num};

use super::curve::ReadingsFile;
use crate::error::{Error, Problem};
use crate::fit_data::FitData;
use crate::job_json::PointView;

impl ReadingsFile {
    /// The data of a fit from the fuzzy data points `points` that the core
    /// made of these readings with `rule`: a description of where they came
    /// from and how, the top-level `lower_height` of the rule, and the curve's
    /// `degree` (or `order`, by `degree_key`) and `alpha` to carry.
    #[must_use]
    pub fn fit_data(
        &self,
        points: FuzzyData,
        rule: &FuzzifyRule,
        degree_key: &'static str,
        degree: usize,
        alpha: Option<Alpha>,
    ) -> FitData {
        let description = format!(
            "Fuzzified by t2spline from {}: {} stations, {} readings. Per coordinate: crisp = median, lower = [25th, 75th percentile] (lower_height {}), primary = [10th, 90th percentile], upper = [min - T, max + T] with T = {} (percentiles by linear interpolation, type 7).",
            self.source,
            self.stations.len(),
            self.readings.readings(),
            Num(rule.lower_height().get()),
            // `-0` is 0 (adding 0 turns -0 into +0).
            Num(rule.tolerance() + 0.0),
        );
        FitData {
            source: self.source.clone(),
            description: Some(description),
            degree_key,
            degree,
            degree_v: None,
            alpha,
            type_reduction: None,
            lower_height: Some(rule.lower_height().get()),
            samples: None,
            points,
        }
    }

    /// A core error about fuzzifying station `i` (`points[i].x: …`), placed
    /// at the station's first row.
    #[must_use]
    pub fn fuzzify_error(&self, e: &t2spline::Error) -> Error {
        let station = match e {
            t2spline::Error::NotFinite { place, .. }
            | t2spline::Error::Order { place, .. }
            | t2spline::Error::OutOfRange { place, .. } => place.point,
            t2spline::Error::TooFewReadings { station, .. } => *station,
            _ => None,
        };
        let line_column = station
            .and_then(|s| self.first_lines.get(s))
            .map(|&line| (line, 1));
        let name = station.and_then(|s| self.stations.get(s));
        let message = match name {
            Some(name) => format!("station `{}`: {e}", super::fields::shorten(name)),
            None => e.to_string(),
        };
        Error::Invalid {
            file: self.source.clone(),
            problems: vec![Problem {
                line_column,
                message,
            }],
        }
    }
}

/// The data file of `data`, keys in the order of a job file: `description`,
/// `order` or `degree` (a pair `[u, v]` for a net), `alpha`, `lower_height`,
/// `samples`, `points` (rows of points for a net; a number's `lower_height`
/// only where it differs from the top-level one). It
/// parses back with [`parse_data`](crate::parse_data).
///
/// # Examples
/// ```
/// # use t2spline::fit::FuzzifyRule;
/// let file = t2spline_io::parse_readings("station,x,y\nA,0,0\nA,1,1\nB,2,0\nB,3,1\n", "r.csv")?;
/// let rule = FuzzifyRule::try_new(0.0, 0.5)?;
/// let data = file.fit_data(file.readings.fuzzify(&rule)?, &rule, "degree", 1, None);
/// let json = t2spline_io::data_json(&data);
/// assert_eq!(json["points"][1]["x"]["crisp"], 2.5);
/// let back = t2spline_io::parse_data(&json.to_string(), "data.json")?;
/// assert_eq!(back.points, data.points);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn data_json(data: &FitData) -> Value {
    // Serializing keys, numbers and strings into a tree of values cannot fail.
    serde_json::to_value(DataFileView(data)).unwrap_or(Value::Null)
}

/// The text of the data file of `data`: [`data_json`] in the layout of
/// [`to_json_pretty`](crate::to_json_pretty), byte for byte, written
/// straight from the points without the tree of values (a raster's data file
/// holds millions of numbers).
///
/// # Examples
/// ```
/// # use t2spline::fit::FuzzifyRule;
/// let file = t2spline_io::parse_readings("station,x,y\nA,0,0\nA,1,1\nB,2,0\nB,3,1\n", "r.csv")?;
/// let rule = FuzzifyRule::try_new(0.0, 0.5)?;
/// let data = file.fit_data(file.readings.fuzzify(&rule)?, &rule, "degree", 1, None);
/// assert_eq!(t2spline_io::data_json_text(&data), t2spline_io::to_json_pretty(&t2spline_io::data_json(&data)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn data_json_text(data: &FitData) -> String {
    let mut out = Vec::new();
    // Writing to memory cannot fail, nor can serializing keys and numbers;
    // serde_json writes UTF-8.
    if crate::pretty::write_json_pretty(&mut out, &DataFileView(data)).is_err() {
        return crate::pretty::to_json_pretty(&data_json(data));
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// A data file serialized from its parts: the keys of [`data_json`], in its
/// order.
struct DataFileView<'a>(&'a FitData);

impl Serialize for DataFileView<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let data = self.0;
        let mut map = serializer.serialize_map(None)?;
        if let Some(d) = &data.description {
            map.serialize_entry("description", d)?;
        }
        let shift = usize::from(data.degree_key == "order");
        match data.degree_v {
            Some(q) => map.serialize_entry(data.degree_key, &[data.degree + shift, q + shift])?,
            None => map.serialize_entry(data.degree_key, &(data.degree + shift))?,
        }
        if let Some(a) = data.alpha {
            map.serialize_entry("alpha", &a.get())?;
        }
        if let Some(h) = data.lower_height {
            map.serialize_entry("lower_height", &h)?;
        }
        if let Some(n) = data.samples {
            map.serialize_entry("samples", &n)?;
        }
        let top_height = data.lower_height;
        match &data.points {
            FuzzyData::Planar(p) => {
                let v: Vec<PointView<'_, 2>> = p
                    .iter()
                    .map(|point| PointView { point, top_height })
                    .collect();
                map.serialize_entry("points", &v)?;
            }
            FuzzyData::Spatial(p) => map.serialize_entry("points", &views(p, top_height))?,
            FuzzyData::Net(rows) => {
                let v: Vec<Vec<PointView<'_, 3>>> =
                    rows.iter().map(|r| views(r, top_height)).collect();
                map.serialize_entry("points", &v)?;
            }
            // A kind of data this version does not know: no points, which
            // the data file's validator then refuses.
            _ => map.serialize_entry("points", &[0u8; 0])?,
        }
        map.end()
    }
}

/// The views of `points` for serializing.
fn views(points: &[Nt2Point<3>], top_height: Option<f64>) -> Vec<PointView<'_, 3>> {
    points
        .iter()
        .map(|point| PointView { point, top_height })
        .collect()
}
