//! What to measure ([`MeasureOptions`] for curves, [`SurfaceMeasureOptions`]
//! for surfaces), checked once, when made: the fields are private, so an
//! options value that exists keeps every rule below, and no front end
//! repeats a range. A broken rule is [`Error::Setting`] naming the setting
//! ([`Setting::Levels`], [`Setting::At`], [`Setting::Order`],
//! [`Setting::Datum`]), which each front end spells its own way (`--levels`,
//! `levels=`).

use crate::error::{Error, Setting};
use crate::fuzzy::Alpha;
use crate::nurbs::MAX_DERIVATIVE_ORDER;

/// Levels at most in one measurement: each level costs a length and an
/// area bracket per function, about 0.14 s on a 20-point cubic (release, one
/// core), so 51 levels take seconds (docs/performance.md, docs/jobs.md).
pub const MAX_MEASURE_LEVELS: usize = 51;
/// Parameters at most in one measurement, counted once per level
/// (parameters × levels): each costs a curvature bracket per function, up
/// to about 2 ms where its search ends at its budget, so the limit takes
/// seconds.
pub const MAX_MEASURE_PARAMETERS: usize = 1_000;

/// Levels a measurement takes when neither the job nor the caller gives
/// any: 0, 0.1, …, 1.
pub const DEFAULT_MEASURE_LEVELS: usize = 11;

fn refuse(setting: Setting, message: String) -> Error {
    Error::Setting { setting, message }
}

/// `count` levels equally spaced from 0 to 1.
///
/// # Errors
/// [`Setting::Levels`] unless `2 ≤ count ≤` [`MAX_MEASURE_LEVELS`].
pub fn uniform_levels(count: usize) -> Result<Vec<Alpha>, Error> {
    if !(2..=MAX_MEASURE_LEVELS).contains(&count) {
        return Err(refuse(
            Setting::Levels,
            format!("{count} is outside 2 ..= {MAX_MEASURE_LEVELS}"),
        ));
    }
    (0..count)
        .map(|k| Alpha::try_new(k as f64 / (count - 1) as f64))
        .collect()
}

/// Levels given one by one: 1 to [`MAX_MEASURE_LEVELS`] of them.
fn check_levels(levels: &[Alpha]) -> Result<(), Error> {
    if levels.is_empty() || levels.len() > MAX_MEASURE_LEVELS {
        return Err(refuse(
            Setting::Levels,
            format!(
                "{} levels are outside 1 ..= {MAX_MEASURE_LEVELS}",
                levels.len()
            ),
        ));
    }
    Ok(())
}

/// What to measure on a curve.
#[derive(Clone, Debug, PartialEq)]
pub struct MeasureOptions {
    levels: Vec<Alpha>,
    at: Vec<f64>,
    order: usize,
    length: bool,
    area: bool,
    closed: Option<bool>,
}

impl MeasureOptions {
    /// The length and the area at each of `levels`, and the derivative of
    /// order `order`, the tangent angle and the curvature at each parameter
    /// of `at`; the curve closed as its crisp layer says
    /// ([`MeasureOptions::closed`] to say otherwise).
    ///
    /// # Errors
    /// [`Error::Setting`]: [`Setting::Levels`] for no levels or more than
    /// [`MAX_MEASURE_LEVELS`]; [`Setting::At`] for a parameter that is not
    /// finite or more than [`MAX_MEASURE_PARAMETERS`] parameters × levels;
    /// [`Setting::Order`] for an order outside `1 ..=`
    /// [`MAX_DERIVATIVE_ORDER`]. Parameters outside the curve's domain are
    /// found when it is measured ([`Error::MeasureAt`]).
    pub fn new(levels: Vec<Alpha>, at: Vec<f64>, order: usize) -> Result<Self, Error> {
        check_levels(&levels)?;
        if let Some((i, t)) = at.iter().enumerate().find(|(_, t)| !t.is_finite()) {
            return Err(refuse(
                Setting::At,
                format!("item {} ({t}) is not a finite number", i + 1),
            ));
        }
        let count = at.len() * levels.len();
        if count > MAX_MEASURE_PARAMETERS {
            return Err(refuse(
                Setting::At,
                format!("parameters × levels = {count} is outside [0, {MAX_MEASURE_PARAMETERS}]"),
            ));
        }
        if !(1..=MAX_DERIVATIVE_ORDER).contains(&order) {
            return Err(refuse(
                Setting::Order,
                format!("{order} is outside 1 ..= {MAX_DERIVATIVE_ORDER}"),
            ));
        }
        Ok(MeasureOptions {
            levels,
            at,
            order,
            length: true,
            area: true,
            closed: None,
        })
    }

    /// `count` levels from 0 to 1 ([`uniform_levels`]), no parameters, the
    /// first derivative, length and area.
    ///
    /// # Errors
    /// [`Setting::Levels`] unless `2 ≤ count ≤` [`MAX_MEASURE_LEVELS`].
    pub fn uniform(count: usize) -> Result<Self, Error> {
        MeasureOptions::new(uniform_levels(count)?, Vec::new(), 1)
    }

    /// The same, with the curve closed as `closed` says: `Some(true)` asks
    /// that it close ([`Error::NotClosed`] otherwise), `Some(false)`
    /// measures the area under it even if it closes, `None` closes a curve
    /// whose crisp layer closes
    /// ([`FuzzyCurve::closure`](crate::FuzzyCurve::closure)).
    #[must_use]
    pub fn closed(mut self, closed: Option<bool>) -> Self {
        self.closed = closed;
        self
    }

    /// The same, measuring the arc length and the area only where asked:
    /// with neither, only the quantities at the parameters.
    #[must_use]
    pub fn quantities(mut self, length: bool, area: bool) -> Self {
        self.length = length;
        self.area = area;
        self
    }

    /// The levels, as given.
    #[must_use]
    pub fn levels(&self) -> &[Alpha] {
        &self.levels
    }

    /// The parameters for derivatives, tangent and curvature.
    #[must_use]
    pub fn at(&self) -> &[f64] {
        &self.at
    }

    /// The order of the derivative at each parameter.
    #[must_use]
    pub fn order(&self) -> usize {
        self.order
    }

    /// Whether the arc length is measured.
    #[must_use]
    pub fn length(&self) -> bool {
        self.length
    }

    /// Whether the area is measured (plane curves).
    #[must_use]
    pub fn area(&self) -> bool {
        self.area
    }

    /// Whether the curve is closed ([`MeasureOptions::closed`]).
    #[must_use]
    pub fn closing(&self) -> Option<bool> {
        self.closed
    }
}

/// What to measure on a surface.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceMeasureOptions {
    levels: Vec<Alpha>,
    datum: f64,
    area: bool,
}

impl SurfaceMeasureOptions {
    /// The volumes and plan areas about the plane `z = datum` at each of
    /// `levels`, and the surface area ([`SurfaceMeasureOptions::area`] to
    /// leave it out).
    ///
    /// # Errors
    /// [`Error::Setting`]: [`Setting::Levels`] for no levels or more than
    /// [`MAX_MEASURE_LEVELS`]; [`Setting::Datum`] for a datum that is not
    /// finite.
    pub fn new(levels: Vec<Alpha>, datum: f64) -> Result<Self, Error> {
        check_levels(&levels)?;
        if !datum.is_finite() {
            return Err(refuse(
                Setting::Datum,
                format!("{datum} is not a finite number"),
            ));
        }
        Ok(SurfaceMeasureOptions {
            levels,
            datum,
            area: true,
        })
    }

    /// `count` levels from 0 to 1, datum 0, with the surface area.
    ///
    /// # Errors
    /// [`Setting::Levels`] unless `2 ≤ count ≤` [`MAX_MEASURE_LEVELS`].
    pub fn uniform(count: usize) -> Result<Self, Error> {
        SurfaceMeasureOptions::new(uniform_levels(count)?, 0.0)
    }

    /// The same, with the surface area measured or not (a convex
    /// minimisation and a vertex search per level and function; the
    /// volumes cost far less).
    #[must_use]
    pub fn with_area(mut self, area: bool) -> Self {
        self.area = area;
        self
    }

    /// The levels, as given.
    #[must_use]
    pub fn levels(&self) -> &[Alpha] {
        &self.levels
    }

    /// The height `z₀` of the plane the volumes are measured from.
    #[must_use]
    pub fn datum(&self) -> f64 {
        self.datum
    }

    /// Whether the surface area is measured.
    #[must_use]
    pub fn area(&self) -> bool {
        self.area
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setting(e: Error) -> (Setting, String) {
        match e {
            Error::Setting { setting, message } => (setting, message),
            other => panic!("not a setting's error: {other}"),
        }
    }

    #[test]
    fn each_rule_names_its_setting() {
        let one = vec![Alpha::ONE];
        let (s, m) = setting(MeasureOptions::uniform(52).unwrap_err());
        assert_eq!((s, m.as_str()), (Setting::Levels, "52 is outside 2 ..= 51"));
        let (s, m) = setting(MeasureOptions::new(Vec::new(), vec![], 1).unwrap_err());
        assert_eq!(
            (s, m.as_str()),
            (Setting::Levels, "0 levels are outside 1 ..= 51")
        );
        let (s, m) = setting(MeasureOptions::new(one.clone(), vec![0.5, f64::NAN], 1).unwrap_err());
        assert_eq!(
            (s, m.as_str()),
            (Setting::At, "item 2 (NaN) is not a finite number")
        );
        let (s, m) = setting(MeasureOptions::new(one.clone(), vec![0.5; 1001], 1).unwrap_err());
        assert_eq!(
            (s, m.as_str()),
            (
                Setting::At,
                "parameters × levels = 1001 is outside [0, 1000]"
            )
        );
        for order in [0, 65] {
            let (s, m) = setting(MeasureOptions::new(one.clone(), vec![], order).unwrap_err());
            assert_eq!(
                (s, m),
                (Setting::Order, format!("{order} is outside 1 ..= 64"))
            );
        }
        let (s, m) = setting(SurfaceMeasureOptions::new(one, f64::INFINITY).unwrap_err());
        assert_eq!(
            (s, m.as_str()),
            (Setting::Datum, "inf is not a finite number")
        );
    }

    #[test]
    fn the_limits_themselves_are_accepted() {
        let levels = uniform_levels(MAX_MEASURE_LEVELS).unwrap();
        assert_eq!(levels.len(), 51);
        assert_eq!(levels[25].get(), 0.5);
        let o = MeasureOptions::new(vec![Alpha::ONE], vec![0.0; 1000], 64).unwrap();
        assert_eq!((o.at().len(), o.order(), o.closing()), (1000, 64, None));
        let o = o.closed(Some(true)).quantities(false, true);
        assert_eq!(
            (o.closing(), o.length(), o.area()),
            (Some(true), false, true)
        );
    }
}
