//! Reading the arguments that define curves and surfaces: the degree (from
//! `degree`, `order` or the knots, per direction for a surface), counts,
//! names (layers, sides, directions), and fuzzy control or data points given
//! as arrays (`crisp` of shape net + `(d,)`, `upper`/`primary`/`lower` of
//! shape net + `(d, 2)`, a lower height per number or broadcast).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use t2spline::{Axis, Direction, KnotVector, Layer, Nt2Number, Nt2Point, Place, Side};
use t2spline_io::job::MAX_ORDER;

use crate::arrays::{floats, shape_text, Floats};
use crate::dim::{ByDim, PointList};
use crate::keyword;
pub(crate) use crate::keyword::{count, PerDirection};
use crate::net::shape;

/// How the arguments that give a degree are named in messages: `degree`,
/// `order`, `knots` for a curve; for the v direction of a surface
/// `degree[1]` (or `degree` when one value serves both), `order[1]`,
/// `knots_v`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DegreeNames<'a> {
    pub(crate) degree: &'a str,
    pub(crate) order: &'a str,
    pub(crate) knots: &'a str,
}

impl DegreeNames<'static> {
    /// The names of a curve's arguments.
    pub(crate) const CURVE: Self = DegreeNames {
        degree: "degree",
        order: "order",
        knots: "knots",
    };
}

/// The degree `p` from exactly one of `degree` and `order` (`p = k − 1`), or
/// when neither is given from the number of knots (`p = len(knots) − n − 1`).
/// The order is limited as in job files ([`MAX_ORDER`]).
///
/// # Errors
/// `ValueError` naming the keyword: both given, neither (and no knots), or
/// a value outside its range.
pub(crate) fn degree(
    degree: Option<i64>,
    order: Option<i64>,
    knots: Option<usize>,
    control_points: usize,
) -> PyResult<usize> {
    named_degree(degree, order, knots, control_points, DegreeNames::CURVE)
}

/// [`degree`] with the arguments called `names`.
///
/// # Errors
/// As [`degree`].
pub(crate) fn named_degree(
    degree: Option<i64>,
    order: Option<i64>,
    knots: Option<usize>,
    control_points: usize,
    names: DegreeNames<'_>,
) -> PyResult<usize> {
    let max = MAX_ORDER as i64;
    let DegreeNames {
        degree: dn,
        order: on,
        knots: kn,
    } = names;
    match (degree, order) {
        (Some(_), Some(_)) => Err(PyValueError::new_err(format!(
            "{dn}, {on}: give one of them, not both (degree = order - 1)"
        ))),
        (Some(p), None) if !(0..max).contains(&p) => Err(PyValueError::new_err(format!(
            "{dn}: {p} is outside [0, {}]",
            max - 1
        ))),
        (None, Some(k)) if !(1..=max).contains(&k) => Err(PyValueError::new_err(format!(
            "{on}: {k} is outside [1, {max}]"
        ))),
        // Both are within [0, MAX_ORDER] now.
        (Some(p), None) => Ok(p as usize),
        (None, Some(k)) => Ok(k as usize - 1),
        (None, None) => match knots {
            Some(m) if m > control_points && m - control_points <= MAX_ORDER => {
                Ok(m - control_points - 1)
            }
            Some(m) => Err(PyValueError::new_err(format!(
                "{dn}: not given, and {m} {kn} for {control_points} control points give no degree in [0, {}] (knots = control points + degree + 1)",
                max - 1
            ))),
            None => Err(PyValueError::new_err(format!(
                "{dn}: missing: give degree or order (or {kn})"
            ))),
        },
    }
}

/// The degrees `[p, q]` of a surface, each direction as [`degree`] reads a
/// curve's: from `degree` or `order` (one value for both directions, or one
/// per direction), else from the number of knots in that direction.
///
/// # Errors
/// As [`degree`], naming the direction (`degree[1]`, `knots_v`).
pub(crate) fn surface_degrees(
    degree: Option<PerDirection>,
    order: Option<PerDirection>,
    knots: [Option<usize>; 2],
    net: [usize; 2],
) -> PyResult<[usize; 2]> {
    let name = |given: Option<PerDirection>, base: &'static str, k: usize| match given {
        Some(PerDirection::One(_)) => base.to_owned(),
        _ => format!("{base}[{k}]"),
    };
    let mut out = [0; 2];
    for (k, direction) in Direction::BOTH.into_iter().enumerate() {
        let (dn, on) = (name(degree, "degree", k), name(order, "order", k));
        let kn = format!("knots_{direction}");
        out[k] = named_degree(
            degree.map(|d| d.pair()[k]),
            order.map(|o| o.pair()[k]),
            knots[k],
            net[k],
            DegreeNames {
                degree: &dn,
                order: &on,
                knots: &kn,
            },
        )?;
    }
    Ok(out)
}

/// The knot vector of one direction of a surface: `values` checked for
/// `count` lines of the net and degree `degree`, or the clamped uniform
/// default; errors name the direction as the core's surface constructors
/// do (`knots.v[3] = …`, `points: a surface of order 3 in v needs …`).
///
/// # Errors
/// [`t2spline::Error::InDirection`] wrapping the rule broken.
pub(crate) fn knot_vector(
    direction: Direction,
    values: Option<Vec<f64>>,
    degree: usize,
    count: usize,
) -> Result<KnotVector, t2spline::Error> {
    match values {
        Some(values) => KnotVector::try_new(values, degree, count),
        None => KnotVector::clamped_uniform(degree, count),
    }
    .map_err(|e| t2spline::Error::InDirection {
        direction,
        inner: Box::new(e),
    })
}

/// The weights of a net of shape `net` (`weights=`, shape `(nu, nv)`), row
/// by row; all 1 when not given. The core checks their values.
///
/// # Errors
/// The errors of reading an array; `ValueError` for another shape.
pub(crate) fn net_weights(arg: Option<&Bound<'_, PyAny>>, net: [usize; 2]) -> PyResult<Vec<f64>> {
    match arg.filter(|a| !a.is_none()) {
        None => Ok(vec![1.0; net[0] * net[1]]),
        Some(a) => {
            let w = floats(a, "weights")?;
            w.expect_shape("weights", &net, ": one per control point of the net")?;
            Ok(w.data)
        }
    }
}

/// A direction from its name (`"u"`, `"v"`).
///
/// # Errors
/// `TypeError` for anything but a `str`, `ValueError` for another name,
/// naming the argument.
pub(crate) fn direction(arg: &Bound<'_, PyAny>) -> PyResult<Direction> {
    let name = keyword::text(arg, "direction")?;
    Direction::BOTH
        .into_iter()
        .find(|d| d.to_string() == name)
        .ok_or_else(|| {
            PyValueError::new_err(format!("direction: expected 'u' or 'v', got {name:?}"))
        })
}

/// A layer from its name (`"upper_left"`, …, `"crisp"`, …, `"upper_right"`).
///
/// # Errors
/// `TypeError` for anything but a `str`, `ValueError` for another name,
/// naming the argument `arg` (and the names offered).
pub(crate) fn layer(value: &Bound<'_, PyAny>, arg: &str) -> PyResult<Layer> {
    let name = keyword::text(value, arg)?;
    Layer::ALL
        .into_iter()
        .find(|l| l.name() == name)
        .ok_or_else(|| {
            let names: Vec<&str> = Layer::ALL.iter().map(|l| l.name()).collect();
            PyValueError::new_err(format!(
                "{arg}: expected one of {}, got {name:?}",
                names.join(", ")
            ))
        })
}

/// A side of a type-reduced number from its name (`"left"`, `"right"`).
///
/// # Errors
/// `TypeError` for anything but a `str`, `ValueError` for another name,
/// naming the argument.
pub(crate) fn side(arg: &Bound<'_, PyAny>) -> PyResult<Side> {
    match keyword::text(arg, "side")?.as_str() {
        "left" => Ok(Side::Left),
        "right" => Ok(Side::Right),
        other => Err(PyValueError::new_err(format!(
            "side: expected 'left' or 'right', got {other:?}"
        ))),
    }
}

/// Fuzzy points given as arrays, their shapes checked against each other:
/// the `n` points of a curve or the `nu × nv` net of a surface.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct FuzzyArrays {
    /// The shape of the net: `[n]` or `[nu, nv]`.
    pub(crate) net: Vec<usize>,
    /// Number of points.
    pub(crate) n: usize,
    /// Coordinates per point: 2 or 3.
    pub(crate) d: usize,
    crisp: Floats,
    upper: Floats,
    primary: Floats,
    lower: Floats,
    /// The lower height of every number, net + `(d,)` in C order.
    heights: Vec<f64>,
}

impl FuzzyArrays {
    /// Reads `crisp` (net + `(d,)`), `upper`, `primary`, `lower` (net +
    /// `(d, 2)`, `[left, right]` last; each `[c, c]` when not given, as a
    /// crisp number's) and `lower_height` (anything that broadcasts to net +
    /// `(d,)`; 1 when not given); the net has `rank` dimensions (1 for a
    /// curve, 2 for a surface).
    ///
    /// # Errors
    /// `TypeError` / `ValueError` naming the argument and the shape expected.
    pub(crate) fn read(
        crisp: &Bound<'_, PyAny>,
        [upper, primary, lower, lower_height]: [Option<&Bound<'_, PyAny>>; 4],
        rank: usize,
    ) -> PyResult<Self> {
        let crisp = floats(crisp, "crisp")?;
        let (net, d) = crisp.net_shape("crisp", rank)?;
        // Feet not given: those of crisp numbers, `[c, c]`.
        let feet = |arg: Option<&Bound<'_, PyAny>>, name| -> PyResult<Floats> {
            let Some(arg) = arg else {
                return Ok(Floats {
                    shape: shape(&net, &[d, 2]),
                    data: crisp.data.iter().flat_map(|&c| [c, c]).collect(),
                });
            };
            let f = floats(arg, name)?;
            f.expect_shape(
                name,
                &shape(&net, &[d, 2]),
                ": [left, right] per coordinate of crisp",
            )?;
            Ok(f)
        };
        let (upper, primary, lower) = (
            feet(upper, "upper")?,
            feet(primary, "primary")?,
            feet(lower, "lower")?,
        );
        let h = match lower_height {
            Some(h) => floats(h, "lower_height")?,
            None => Floats {
                shape: Vec::new(),
                data: vec![1.0],
            },
        };
        let heights = h.broadcast_to(&crisp.shape).ok_or_else(|| {
            PyValueError::new_err(format!(
                "lower_height: expected a number or an array that broadcasts to shape {}: one per coordinate of crisp, got {}",
                shape_text(&crisp.shape),
                shape_text(&h.shape)
            ))
        })?;
        Ok(FuzzyArrays {
            n: net.iter().product(),
            net,
            d,
            crisp,
            upper,
            primary,
            lower,
            heights,
        })
    }

    /// The points in their dimension, in net order (row by row), every
    /// number checked (docs/method.md §1).
    ///
    /// # Errors
    /// The first broken rule, naming its place (`points[2].y: the order …`,
    /// `points[2][1].y: …` in a net).
    pub(crate) fn points(&self) -> Result<ByDim<PointList>, t2spline::Error> {
        Ok(match self.d {
            2 => ByDim::Planar(self.points_of()?),
            _ => ByDim::Spatial(self.points_of()?),
        })
    }

    /// The place of coordinate `axis` of the `i`-th point.
    fn place(&self, i: usize, axis: Axis) -> Place {
        match self.net[..] {
            [_, nv] => Place::in_net(i / nv, i % nv, axis),
            _ => Place::new(i, axis),
        }
    }

    fn points_of<const D: usize>(&self) -> Result<Vec<Nt2Point<D>>, t2spline::Error> {
        debug_assert_eq!(D, self.d);
        let feet = |f: &Floats, k: usize| [f.data[2 * k], f.data[2 * k + 1]];
        (0..self.n)
            .map(|i| {
                let mut coords = Vec::with_capacity(D);
                for (d, axis) in Axis::ALL.into_iter().take(D).enumerate() {
                    let k = i * D + d;
                    let number = Nt2Number::try_new(
                        self.crisp.data[k],
                        feet(&self.upper, k),
                        feet(&self.primary, k),
                        feet(&self.lower, k),
                        self.heights[k],
                    )
                    .map_err(|e| e.at(self.place(i, axis)))?;
                    coords.push(number);
                }
                // One number was pushed per coordinate, D of them: the error
                // is never made.
                let coords: [Nt2Number; D] =
                    coords
                        .try_into()
                        .map_err(|v: Vec<_>| t2spline::Error::Length {
                            what: "coordinates",
                            expected: D,
                            found: v.len(),
                        })?;
                Ok(Nt2Point::new(coords))
            })
            .collect()
    }
}

/// A list in net order cut into the rows of a net of shape `[nu, nv]`
/// (`rows[i][j]`, as the core's surface constructors take them).
pub(crate) fn rows<T>(list: Vec<T>, [nu, nv]: [usize; 2]) -> Vec<Vec<T>> {
    let mut items = list.into_iter();
    (0..nu).map(|_| items.by_ref().take(nv).collect()).collect()
}
