//! A job file read straight into plain values by serde visitors, refusing
//! at the first thing a valid job does not hold: an unknown or repeated
//! key, a value of another type, a number where a whole number belongs
//! (`3.0` included), an empty list, a mix of points and rows.
//!
//! Nothing here names a place or explains a rule: a refusal only sends the
//! text to the validator ([`parse`](super::super::parse)), which does. What
//! is read is what the validator would read: numbers come from the same
//! `serde_json` parser (an integer `n` becomes `n as f64`, as
//! `Value::as_f64` gives it) and keys are compared decoded, escapes
//! included.

use std::fmt;

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use t2spline::TypeReduction;

/// The keys of a job's top level, in the order of [`RawJob`]'s fields.
const TOP: [&str; 10] = [
    "description",
    "order",
    "degree",
    "weights",
    "knots",
    "alpha",
    "type_reduction",
    "lower_height",
    "samples",
    "points",
];
const POINT: [&str; 3] = ["x", "y", "z"];
const NUMBER: [&str; 5] = ["crisp", "upper", "primary", "lower", "lower_height"];
const DIRECTIONS: [&str; 2] = ["u", "v"];

/// The top level of a job as given: each key `None` when missing.
#[derive(Default)]
pub(super) struct RawJob {
    pub description: Option<String>,
    pub order: Option<Whole>,
    pub degree: Option<Whole>,
    pub weights: Option<Weights>,
    pub knots: Option<Knots>,
    pub alpha: Option<f64>,
    pub type_reduction: Option<TypeReduction>,
    pub lower_height: Option<f64>,
    pub samples: Option<Whole>,
    pub points: Option<Points>,
}

/// A whole number, or a pair of them (`order`, `degree`, `samples`).
pub(super) enum Whole {
    One(u64),
    Pair([u64; 2]),
}

/// `weights`: a curve's list, or a surface's rows.
pub(super) enum Weights {
    List(Vec<f64>),
    Rows(Vec<Vec<f64>>),
}

/// `knots`: a curve's list, or a surface's `u` and `v`.
pub(super) enum Knots {
    List(Vec<f64>),
    Directions([Option<Vec<f64>>; 2]),
}

/// A fuzzy number's values as given (SPEC §1), its own height if any.
#[derive(Clone, Copy)]
pub(super) struct RawNumber {
    pub crisp: f64,
    pub upper: [f64; 2],
    pub primary: [f64; 2],
    pub lower: [f64; 2],
    pub height: Option<f64>,
}

/// `points`: the numbers of every point, point after point, each point's
/// coordinates in the order x, y, z.
pub(super) struct Points {
    /// The numbers, `dimension` per point.
    pub numbers: Vec<RawNumber>,
    /// Coordinates per point: 2 or 3 for a curve, 3 for a surface.
    pub dimension: usize,
    /// `None`: a curve's list of points; `Some([nu, nv])`: a surface's net,
    /// `nu` rows of `nv` points.
    pub net: Option<[usize; 2]>,
}

/// Refuses: the validator will say why.
fn refuse<E: de::Error>() -> E {
    E::custom("not a plainly valid job")
}

/// The next key of `map` among `names`, as its index; refuses an unknown
/// key and one already in `seen` (a bit per name).
fn next_key<'de, A: MapAccess<'de>>(
    map: &mut A,
    names: &'static [&'static str],
    seen: &mut u32,
) -> Result<Option<usize>, A::Error> {
    let Some(i) = map.next_key_seed(Key(names))? else {
        return Ok(None);
    };
    let bit = 1 << i;
    if *seen & bit != 0 {
        return Err(refuse());
    }
    *seen |= bit;
    Ok(Some(i))
}

/// A key among the names, as its index.
struct Key(&'static [&'static str]);

impl<'de> DeserializeSeed<'de> for Key {
    type Value = usize;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        d.deserialize_identifier(self)
    }
}

impl Visitor<'_> for Key {
    type Value = usize;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a known key")
    }
    fn visit_str<E: de::Error>(self, s: &str) -> Result<usize, E> {
        self.0.iter().position(|k| *k == s).ok_or_else(refuse)
    }
}

impl<'de> de::Deserialize<'de> for RawJob {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_map(JobVisitor)
    }
}

struct JobVisitor;

impl<'de> Visitor<'de> for JobVisitor {
    type Value = RawJob;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a job")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<RawJob, A::Error> {
        let mut job = RawJob::default();
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, &TOP, &mut seen)? {
            match i {
                0 => job.description = Some(map.next_value()?),
                1 => job.order = Some(map.next_value_seed(WholeSeed)?),
                2 => job.degree = Some(map.next_value_seed(WholeSeed)?),
                3 => job.weights = Some(map.next_value_seed(WeightsSeed)?),
                4 => job.knots = Some(map.next_value_seed(KnotsSeed)?),
                5 => job.alpha = Some(map.next_value()?),
                6 => job.type_reduction = Some(map.next_value_seed(TypeReductionSeed)?),
                7 => job.lower_height = Some(map.next_value()?),
                8 => job.samples = Some(map.next_value_seed(WholeSeed)?),
                _ => job.points = Some(map.next_value_seed(PointsSeed)?),
            }
        }
        Ok(job)
    }
}

/// A [`Whole`].
struct WholeSeed;

impl<'de> DeserializeSeed<'de> for WholeSeed {
    type Value = Whole;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Whole, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for WholeSeed {
    type Value = Whole;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a whole number or a pair of them")
    }
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Whole, E> {
        Ok(Whole::One(n))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Whole, A::Error> {
        let u = seq.next_element()?.ok_or_else(refuse)?;
        let v = seq.next_element()?.ok_or_else(refuse)?;
        Ok(Whole::Pair([u, v]))
    }
}

/// A [`TypeReduction`] by its name.
struct TypeReductionSeed;

impl<'de> DeserializeSeed<'de> for TypeReductionSeed {
    type Value = TypeReduction;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<TypeReduction, D::Error> {
        d.deserialize_str(self)
    }
}

impl Visitor<'_> for TypeReductionSeed {
    type Value = TypeReduction;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a type reduction")
    }
    fn visit_str<E: de::Error>(self, s: &str) -> Result<TypeReduction, E> {
        s.parse().map_err(|_| refuse())
    }
}

/// [`Weights`]: the first entry tells a list from rows.
struct WeightsSeed;

impl<'de> DeserializeSeed<'de> for WeightsSeed {
    type Value = Weights;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Weights, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for WeightsSeed {
    type Value = Weights;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("weights")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Weights, A::Error> {
        match seq.next_element_seed(NumberOrList)?.ok_or_else(refuse)? {
            Ok(first) => {
                let mut list = vec![first];
                while let Some(w) = seq.next_element()? {
                    list.push(w);
                }
                Ok(Weights::List(list))
            }
            Err(first) => {
                let mut rows = vec![first];
                while let Some(row) = seq.next_element()? {
                    rows.push(row);
                }
                Ok(Weights::Rows(rows))
            }
        }
    }
}

/// A number, or a list of numbers.
struct NumberOrList;

impl<'de> DeserializeSeed<'de> for NumberOrList {
    type Value = Result<f64, Vec<f64>>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for NumberOrList {
    type Value = Result<f64, Vec<f64>>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a number or a list of numbers")
    }
    // As `serde_json::Value::as_f64` converts them.
    #[allow(clippy::cast_precision_loss)]
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Self::Value, E> {
        Ok(Ok(n as f64))
    }
    #[allow(clippy::cast_precision_loss)]
    fn visit_i64<E: de::Error>(self, n: i64) -> Result<Self::Value, E> {
        Ok(Ok(n as f64))
    }
    fn visit_f64<E: de::Error>(self, x: f64) -> Result<Self::Value, E> {
        Ok(Ok(x))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut list = Vec::new();
        while let Some(x) = seq.next_element()? {
            list.push(x);
        }
        Ok(Err(list))
    }
}

/// [`Knots`]: a list, or an object of directions.
struct KnotsSeed;

impl<'de> DeserializeSeed<'de> for KnotsSeed {
    type Value = Knots;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Knots, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for KnotsSeed {
    type Value = Knots;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("knots")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Knots, A::Error> {
        NumberOrList.visit_seq(seq)?.err().map(Knots::List).ok_or_else(refuse)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Knots, A::Error> {
        let mut values = [None, None];
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, &DIRECTIONS, &mut seen)? {
            let slot = values.get_mut(i).ok_or_else(refuse)?;
            *slot = Some(map.next_value()?);
        }
        Ok(Knots::Directions(values))
    }
}

/// [`Points`]: the first entry tells a list of points from rows of a net.
struct PointsSeed;

impl<'de> DeserializeSeed<'de> for PointsSeed {
    type Value = Points;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Points, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for PointsSeed {
    type Value = Points;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("points")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Points, A::Error> {
        let mut points = Points {
            numbers: Vec::new(),
            dimension: 0,
            net: None,
        };
        seq.next_element_seed(Entry(&mut points))?
            .ok_or_else(refuse)?;
        while seq.next_element_seed(Entry(&mut points))?.is_some() {}
        Ok(points)
    }
}

/// One entry of `points`: a point of a curve or a row of a net, as the
/// first entry was.
struct Entry<'p>(&'p mut Points);

impl<'de> DeserializeSeed<'de> for Entry<'_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Entry<'_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a point or a row of points")
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<(), A::Error> {
        let p = self.0;
        if p.net.is_some() {
            return Err(refuse());
        }
        let [x, y, z] = PointVisitor.visit_map(map)?;
        let (Some(x), Some(y)) = (x, y) else {
            return Err(refuse());
        };
        let dimension = 2 + usize::from(z.is_some());
        if p.dimension == 0 {
            p.dimension = dimension;
        } else if p.dimension != dimension {
            return Err(refuse());
        }
        p.numbers.extend([x, y]);
        p.numbers.extend(z);
        Ok(())
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let p = self.0;
        if p.dimension == 0 {
            p.dimension = 3;
            p.net = Some([0, 0]);
        }
        let Some([rows, columns]) = p.net.as_mut() else {
            return Err(refuse());
        };
        let mut length = 0;
        while let Some([x, y, z]) = seq.next_element_seed(PointVisitor)? {
            let (Some(x), Some(y), Some(z)) = (x, y, z) else {
                return Err(refuse());
            };
            p.numbers.extend([x, y, z]);
            length += 1;
        }
        if length == 0 || (*rows > 0 && length != *columns) {
            return Err(refuse());
        }
        *rows += 1;
        *columns = length;
        Ok(())
    }
}

/// A point: its numbers by axis, `None` for an axis it lacks.
struct PointVisitor;

impl<'de> DeserializeSeed<'de> for PointVisitor {
    type Value = [Option<RawNumber>; 3];
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for PointVisitor {
    type Value = [Option<RawNumber>; 3];
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a point")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let mut axes = [None; 3];
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, &POINT, &mut seen)? {
            let slot = axes.get_mut(i).ok_or_else(refuse)?;
            *slot = Some(map.next_value_seed(NumberVisitor)?);
        }
        Ok(axes)
    }
}

/// A fuzzy number: `crisp`, `upper`, `primary` and `lower` all given.
struct NumberVisitor;

impl<'de> DeserializeSeed<'de> for NumberVisitor {
    type Value = RawNumber;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<RawNumber, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for NumberVisitor {
    type Value = RawNumber;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a fuzzy number")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<RawNumber, A::Error> {
        let mut n = RawNumber {
            crisp: 0.0,
            upper: [0.0; 2],
            primary: [0.0; 2],
            lower: [0.0; 2],
            height: None,
        };
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, &NUMBER, &mut seen)? {
            match i {
                0 => n.crisp = map.next_value()?,
                1 => n.upper = map.next_value()?,
                2 => n.primary = map.next_value()?,
                3 => n.lower = map.next_value()?,
                _ => n.height = Some(map.next_value()?),
            }
        }
        // The first four are required.
        if seen & 0b1111 != 0b1111 {
            return Err(refuse());
        }
        Ok(n)
    }
}
