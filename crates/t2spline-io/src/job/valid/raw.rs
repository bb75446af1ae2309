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
//!
//! The reading is the first to see the text, before the limits of
//! [`limits`](super::super::limits) are counted, so it keeps them itself, as
//! it goes ([`Count`]): it holds no more than the validator's tree could.

use std::cell::Cell;
use std::fmt;
use std::marker::PhantomData;

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use t2spline::TypeReduction;

use super::super::schema::{
    FUZZY_NUMBER_KEYS, FUZZY_NUMBER_REQUIRED, KNOT_DIRECTIONS, POINT_KEYS, TOP_KEYS,
};
use crate::limits::{MAX_ARRAY, MAX_KEYS, MAX_VALUES};

// No object of a job comes near the limit of keys; arrays and values are
// counted.
const _: () = assert!(TOP_KEYS.len() <= MAX_KEYS);

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
    pub closed: Option<bool>,
    pub units: Option<String>,
    pub points: Option<Points>,
    /// The JSON values of the file, counted as
    /// [`oversized`](super::super::position::oversized) counts them.
    pub values: usize,
}

/// A whole number, or a pair of them (`order`, `degree`, `samples`).
#[derive(Clone, Copy)]
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

/// A fuzzy number's values as given (docs/method.md §1), its own height if any.
#[derive(Clone, Copy)]
pub(super) struct RawNumber {
    pub crisp: f64,
    pub upper: [f64; 2],
    pub primary: [f64; 2],
    pub lower: [f64; 2],
    pub height: Option<f64>,
    /// Given as a bare number: a crisp number, whose height is the job's
    /// `lower_height` when given, else 1.
    pub bare: bool,
}

impl RawNumber {
    /// The crisp number `x`, given as a bare number.
    fn bare(x: f64) -> Self {
        RawNumber {
            crisp: x,
            upper: [x; 2],
            primary: [x; 2],
            lower: [x; 2],
            height: None,
            bare: true,
        }
    }
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

/// The job in `text`, or `None` at the first thing a valid job does not
/// hold.
pub(super) fn read(text: &str) -> Option<RawJob> {
    let count = Count(Cell::new(1));
    let mut de = serde_json::Deserializer::from_str(text);
    let mut job = JobVisitor(&count).deserialize(&mut de).ok()?;
    de.end().ok()?;
    job.values = count.0.get();
    Some(job)
}

/// The JSON values read so far, counted as
/// [`oversized`](super::super::position::oversized) counts them in valid
/// JSON (the root, then one per container and one per separator), within
/// [`MAX_VALUES`], and no array longer than [`MAX_ARRAY`].
struct Count(Cell<usize>);

impl Count {
    /// Counts `n` more values.
    fn add<E: de::Error>(&self, n: usize) -> Result<(), E> {
        let values = self.0.get() + n;
        self.0.set(values);
        if values > MAX_VALUES {
            return Err(refuse());
        }
        Ok(())
    }

    /// Counts an array or object about to be read.
    fn container<E: de::Error>(&self) -> Result<(), E> {
        self.add(1)
    }

    /// Counts entry `i` (from 0) of an array or object: the separator
    /// before it.
    fn entry<E: de::Error>(&self, i: usize) -> Result<(), E> {
        if i >= MAX_ARRAY {
            return Err(refuse());
        }
        self.add(usize::from(i > 0))
    }

    /// Counts a pair: an array and its separator.
    fn pair<E: de::Error>(&self) -> Result<(), E> {
        self.add(2)
    }
}

/// Refuses: the validator will say why.
fn refuse<E: de::Error>() -> E {
    E::custom("not a plainly valid job")
}

/// The next key of `map` among `names`, as its index, counted; refuses an
/// unknown key and one already in `seen` (a bit per name).
fn next_key<'de, A: MapAccess<'de>>(
    map: &mut A,
    names: &'static [&'static str],
    seen: &mut u32,
    count: &Count,
) -> Result<Option<usize>, A::Error> {
    let Some(i) = map.next_key_seed(Key(names))? else {
        return Ok(None);
    };
    let bit = 1 << i;
    if *seen & bit != 0 {
        return Err(refuse());
    }
    count.entry(seen.count_ones() as usize)?;
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

/// The top level: an object of known keys.
struct JobVisitor<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for JobVisitor<'_> {
    type Value = RawJob;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<RawJob, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for JobVisitor<'_> {
    type Value = RawJob;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a job")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<RawJob, A::Error> {
        let count = self.0;
        count.container()?;
        let mut job = RawJob::default();
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, TOP_KEYS, &mut seen, count)? {
            // Once per key of the file: matched by name, not by place in
            // the list.
            match TOP_KEYS.get(i).copied().unwrap_or_default() {
                "description" => job.description = Some(map.next_value()?),
                "order" => job.order = Some(map.next_value_seed(WholeSeed(count))?),
                "degree" => job.degree = Some(map.next_value_seed(WholeSeed(count))?),
                "weights" => job.weights = Some(map.next_value_seed(WeightsSeed(count))?),
                "knots" => job.knots = Some(map.next_value_seed(KnotsSeed(count))?),
                "alpha" => job.alpha = Some(map.next_value()?),
                "type_reduction" => {
                    job.type_reduction = Some(map.next_value_seed(TypeReductionSeed)?);
                }
                "lower_height" => job.lower_height = Some(map.next_value()?),
                "samples" => job.samples = Some(map.next_value_seed(WholeSeed(count))?),
                "closed" => job.closed = Some(map.next_value()?),
                "units" => job.units = Some(map.next_value()?),
                "points" => job.points = Some(map.next_value_seed(PointsSeed(count))?),
                _ => return Err(refuse()),
            }
        }
        Ok(job)
    }
}

/// A [`Whole`].
struct WholeSeed<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for WholeSeed<'_> {
    type Value = Whole;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Whole, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for WholeSeed<'_> {
    type Value = Whole;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a whole number or a pair of them")
    }
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Whole, E> {
        Ok(Whole::One(n))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Whole, A::Error> {
        // A third entry is refused by `serde_json` once this returns.
        self.0.pair()?;
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
struct WeightsSeed<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for WeightsSeed<'_> {
    type Value = Weights;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Weights, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for WeightsSeed<'_> {
    type Value = Weights;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("weights")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Weights, A::Error> {
        let count = self.0;
        count.container()?;
        count.entry(0)?;
        match seq.next_element_seed(NumberOrList(count))? {
            None => Err(refuse()),
            Some(Ok(first)) => {
                let mut list = vec![first];
                while let Some(w) = next_counted(&mut seq, list.len(), count, PhantomData)? {
                    list.push(w);
                }
                Ok(Weights::List(list))
            }
            Some(Err(first)) => {
                let mut rows = vec![first];
                while let Some(row) = next_counted(&mut seq, rows.len(), count, Numbers(count))? {
                    rows.push(row);
                }
                Ok(Weights::Rows(rows))
            }
        }
    }
}

/// Entry `i` of `seq`, read by `seed` and counted.
fn next_counted<'de, A: SeqAccess<'de>, S: DeserializeSeed<'de>>(
    seq: &mut A,
    i: usize,
    count: &Count,
    seed: S,
) -> Result<Option<S::Value>, A::Error> {
    let next = seq.next_element_seed(seed)?;
    if next.is_some() {
        count.entry(i)?;
    }
    Ok(next)
}

/// A number, or a list of numbers.
struct NumberOrList<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for NumberOrList<'_> {
    type Value = Result<f64, Vec<f64>>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for NumberOrList<'_> {
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
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
        Numbers(self.0).visit_seq(seq).map(Err)
    }
}

/// A list of numbers.
struct Numbers<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for Numbers<'_> {
    type Value = Vec<f64>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Vec<f64>, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for Numbers<'_> {
    type Value = Vec<f64>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a list of numbers")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<f64>, A::Error> {
        self.0.container()?;
        let mut list = Vec::new();
        while let Some(x) = next_counted(&mut seq, list.len(), self.0, PhantomData)? {
            list.push(x);
        }
        Ok(list)
    }
}

/// [`Knots`]: a list, or an object of directions.
struct KnotsSeed<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for KnotsSeed<'_> {
    type Value = Knots;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Knots, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for KnotsSeed<'_> {
    type Value = Knots;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("knots")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Knots, A::Error> {
        Numbers(self.0).visit_seq(seq).map(Knots::List)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Knots, A::Error> {
        self.0.container()?;
        let mut values = [None, None];
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, &KNOT_DIRECTIONS, &mut seen, self.0)? {
            let slot = values.get_mut(i).ok_or_else(refuse)?;
            *slot = Some(map.next_value_seed(Numbers(self.0))?);
        }
        Ok(Knots::Directions(values))
    }
}

/// [`Points`]: the first entry tells a list of points from rows of a net.
struct PointsSeed<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for PointsSeed<'_> {
    type Value = Points;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Points, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for PointsSeed<'_> {
    type Value = Points;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("points")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Points, A::Error> {
        let count = self.0;
        count.container()?;
        let mut points = Points {
            numbers: Vec::new(),
            dimension: 0,
            net: None,
        };
        let mut i = 0;
        while seq.next_element_seed(Entry(&mut points, count))?.is_some() {
            count.entry(i)?;
            i += 1;
        }
        if i == 0 {
            return Err(refuse());
        }
        Ok(points)
    }
}

/// One entry of `points`: a point of a curve or a row of a net, as the
/// first entry was.
struct Entry<'p, 'c>(&'p mut Points, &'c Count);

impl<'de> DeserializeSeed<'de> for Entry<'_, '_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Entry<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a point or a row of points")
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<(), A::Error> {
        let Entry(p, count) = self;
        if p.net.is_some() {
            return Err(refuse());
        }
        let [x, y, z] = PointVisitor(count).visit_map(map)?;
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
        let Entry(p, count) = self;
        count.container()?;
        if p.dimension == 0 {
            p.dimension = 3;
            p.net = Some([0, 0]);
        }
        let Some([rows, columns]) = p.net.as_mut() else {
            return Err(refuse());
        };
        let mut length = 0;
        while let Some([x, y, z]) = next_counted(&mut seq, length, count, PointVisitor(count))? {
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
struct PointVisitor<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for PointVisitor<'_> {
    type Value = [Option<RawNumber>; 3];
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for PointVisitor<'_> {
    type Value = [Option<RawNumber>; 3];
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a point")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        self.0.container()?;
        let mut axes = [None; 3];
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, &POINT_KEYS, &mut seen, self.0)? {
            let slot = axes.get_mut(i).ok_or_else(refuse)?;
            *slot = Some(map.next_value_seed(NumberVisitor(self.0))?);
        }
        Ok(axes)
    }
}

/// A fuzzy number: `crisp`, `upper`, `primary` and `lower` all given, or a
/// bare number (a crisp number).
struct NumberVisitor<'c>(&'c Count);

impl<'de> DeserializeSeed<'de> for NumberVisitor<'_> {
    type Value = RawNumber;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<RawNumber, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for NumberVisitor<'_> {
    type Value = RawNumber;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a fuzzy number")
    }
    // As `Value::as_f64` reads them, so as the validator does.
    #[allow(clippy::cast_precision_loss)]
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<RawNumber, E> {
        Ok(RawNumber::bare(n as f64))
    }
    #[allow(clippy::cast_precision_loss)]
    fn visit_i64<E: de::Error>(self, n: i64) -> Result<RawNumber, E> {
        Ok(RawNumber::bare(n as f64))
    }
    fn visit_f64<E: de::Error>(self, x: f64) -> Result<RawNumber, E> {
        Ok(RawNumber::bare(x))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<RawNumber, A::Error> {
        let count = self.0;
        count.container()?;
        let mut n = RawNumber {
            crisp: 0.0,
            upper: [0.0; 2],
            primary: [0.0; 2],
            lower: [0.0; 2],
            height: None,
            bare: false,
        };
        let mut seen = 0;
        while let Some(i) = next_key(&mut map, &FUZZY_NUMBER_KEYS, &mut seen, count)? {
            // `[f64; 2]` refuses other lengths (`serde_json` a third entry).
            // Matched by name, not by place in the list.
            match FUZZY_NUMBER_KEYS.get(i).copied().unwrap_or_default() {
                "crisp" => n.crisp = map.next_value()?,
                "upper" => n.upper = count.pair().and_then(|()| map.next_value())?,
                "primary" => n.primary = count.pair().and_then(|()| map.next_value())?,
                "lower" => n.lower = count.pair().and_then(|()| map.next_value())?,
                "lower_height" => n.height = Some(map.next_value()?),
                _ => return Err(refuse()),
            }
        }
        // The required ones, the first of the keys.
        let required = (1 << FUZZY_NUMBER_REQUIRED) - 1;
        if seen & required != required {
            return Err(refuse());
        }
        Ok(n)
    }
}
