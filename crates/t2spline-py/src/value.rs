//! Any serde value (a run's `RunOutput` above all) as a tree of Python-ready
//! values, in which every array of numbers is one `float64` block.
//!
//! The tree has exactly the structure that `serde_json` writes for the same
//! value — objects with their keys in order, `null` where JSON has `null` —
//! except that arrays of numbers become [`Value::Array`]s (numpy arrays in
//! Python):
//!
//! | serde | JSON | here |
//! |---|---|---|
//! | `Points` (newtype [`Points::SERDE_NAME`]) | `[[x, y], …]` | array `(n, d)`; an absent value (`None`) is NaN |
//! | sequence of floats (`Vec<f64>`, `[f64; 2]`) | `[a, b, …]` | array `(n,)` |
//! | sequence of arrays of one shape `s` | nested lists | array `(n, *s)` |
//! | any other sequence | list | [`Value::List`] |
//! | struct, map | object | [`Value::Dict`] |
//!
//! So whatever a run's output becomes (curves today, surfaces' grids of points
//! tomorrow), Python gets the JSON's structure with numpy arrays in it, and
//! nothing here names a field. Building the tree needs no Python, so it runs
//! with the GIL released; [`Value::into_py`] then only wraps the blocks.

use std::fmt;

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde::ser::{self, Serialize};
use t2spline::job::Points;

use crate::arrays::array;

/// A serde value ready to become a Python object.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Value {
    /// `None` (JSON `null`).
    Null,
    /// `bool`.
    Bool(bool),
    /// `int` from a signed integer.
    Int(i64),
    /// `int` from an unsigned integer.
    UInt(u64),
    /// `float`.
    Float(f64),
    /// `str`.
    Str(String),
    /// A numpy `float64` array of `shape`, values in C order.
    Array { shape: Vec<usize>, data: Vec<f64> },
    /// `list`.
    List(Vec<Value>),
    /// `dict`, keys in order.
    Dict(Vec<(String, Value)>),
}

impl Value {
    /// The Python object.
    pub(crate) fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
        Ok(match self {
            Value::Null => py.None().into_bound(py),
            Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
            Value::Int(i) => i.into_pyobject(py)?.into_any(),
            Value::UInt(u) => u.into_pyobject(py)?.into_any(),
            Value::Float(x) => x.into_pyobject(py)?.into_any(),
            Value::Str(s) => s.into_pyobject(py)?.into_any(),
            Value::Array { shape, data } => array(py, data, &shape)?,
            Value::List(items) => {
                let list = PyList::empty(py);
                for item in items {
                    list.append(item.into_py(py)?)?;
                }
                list.into_any()
            }
            Value::Dict(entries) => {
                let dict = PyDict::new(py);
                for (key, value) in entries {
                    dict.set_item(key, value.into_py(py)?)?;
                }
                dict.into_any()
            }
        })
    }
}

impl Value {
    /// The same tree with every empty one-dimensional array a `list`: for
    /// results whose sequences are lists of objects (the levels of a
    /// measure), where an empty one has no numbers to make an array of.
    pub(crate) fn empty_as_lists(self) -> Value {
        match self {
            Value::Array { shape, .. } if shape == [0] => Value::List(Vec::new()),
            Value::List(items) => {
                Value::List(items.into_iter().map(Value::empty_as_lists).collect())
            }
            Value::Dict(entries) => Value::Dict(
                entries
                    .into_iter()
                    .map(|(k, v)| (k, v.empty_as_lists()))
                    .collect(),
            ),
            other => other,
        }
    }
}

/// The tree of `value`.
///
/// # Errors
/// [`Unsupported`] for what JSON cannot hold either (bytes, maps with
/// non-string keys).
pub(crate) fn to_value<T: Serialize + ?Sized>(value: &T) -> Result<Value, Unsupported> {
    value.serialize(ValueSerializer)
}

/// A serde value with no JSON form.
#[derive(Debug)]
pub(crate) struct Unsupported(String);

impl fmt::Display for Unsupported {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Unsupported {}

impl ser::Error for Unsupported {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Unsupported(msg.to_string())
    }
}

fn unsupported<T>(what: &str) -> Result<T, Unsupported> {
    Err(Unsupported(format!("{what} has no form in a result")))
}

/// The items of a sequence, kept as one block of floats while they allow it.
#[derive(Debug)]
enum Items {
    /// Floats only (or nothing yet).
    Floats(Vec<f64>),
    /// `count` arrays, all of `shape`, one after the other.
    Arrays {
        shape: Vec<usize>,
        count: usize,
        data: Vec<f64>,
    },
    /// Anything else.
    Values(Vec<Value>),
}

impl Items {
    fn push(&mut self, item: Value) {
        match (&mut *self, item) {
            (Items::Floats(floats), Value::Float(x)) => floats.push(x),
            (Items::Floats(floats), Value::Array { shape, data }) if floats.is_empty() => {
                *self = Items::Arrays {
                    shape,
                    count: 1,
                    data,
                };
            }
            (Items::Arrays { shape, count, data }, Value::Array { shape: s, data: d })
                if *shape == s =>
            {
                *count += 1;
                data.extend_from_slice(&d);
            }
            (Items::Values(values), item) => values.push(item),
            (_, item) => {
                let mut values = std::mem::replace(self, Items::Values(Vec::new())).into_values();
                values.push(item);
                *self = Items::Values(values);
            }
        }
    }

    fn into_values(self) -> Vec<Value> {
        match self {
            Items::Floats(floats) => floats.into_iter().map(Value::Float).collect(),
            Items::Arrays { shape, count, data } => {
                let size = shape.iter().product::<usize>();
                (0..count)
                    .map(|k| Value::Array {
                        shape: shape.clone(),
                        data: data[k * size..(k + 1) * size].to_vec(),
                    })
                    .collect()
            }
            Items::Values(values) => values,
        }
    }

    fn finish(self) -> Value {
        match self {
            Items::Floats(data) => Value::Array {
                shape: vec![data.len()],
                data,
            },
            Items::Arrays {
                mut shape,
                count,
                data,
            } => {
                shape.insert(0, count);
                Value::Array { shape, data }
            }
            Items::Values(values) => Value::List(values),
        }
    }
}

/// Builds a [`Value`].
struct ValueSerializer;

/// A sequence being built; with `variant`, the content of an enum variant
/// (`{"variant": [...]}`, as serde_json writes it).
struct SeqBuilder {
    items: Items,
    variant: Option<&'static str>,
}

/// An object being built; `key` holds a map key until its value arrives.
struct MapBuilder {
    entries: Vec<(String, Value)>,
    key: Option<String>,
    variant: Option<&'static str>,
}

fn in_variant(variant: Option<&'static str>, value: Value) -> Value {
    match variant {
        Some(name) => Value::Dict(vec![(name.to_owned(), value)]),
        None => value,
    }
}

impl ser::Serializer for ValueSerializer {
    type Ok = Value;
    type Error = Unsupported;
    type SerializeSeq = SeqBuilder;
    type SerializeTuple = SeqBuilder;
    type SerializeTupleStruct = SeqBuilder;
    type SerializeTupleVariant = SeqBuilder;
    type SerializeMap = MapBuilder;
    type SerializeStruct = MapBuilder;
    type SerializeStructVariant = MapBuilder;

    fn serialize_bool(self, v: bool) -> Result<Value, Unsupported> {
        Ok(Value::Bool(v))
    }
    fn serialize_i8(self, v: i8) -> Result<Value, Unsupported> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_i16(self, v: i16) -> Result<Value, Unsupported> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_i32(self, v: i32) -> Result<Value, Unsupported> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_i64(self, v: i64) -> Result<Value, Unsupported> {
        Ok(Value::Int(v))
    }
    fn serialize_u8(self, v: u8) -> Result<Value, Unsupported> {
        Ok(Value::UInt(v.into()))
    }
    fn serialize_u16(self, v: u16) -> Result<Value, Unsupported> {
        Ok(Value::UInt(v.into()))
    }
    fn serialize_u32(self, v: u32) -> Result<Value, Unsupported> {
        Ok(Value::UInt(v.into()))
    }
    fn serialize_u64(self, v: u64) -> Result<Value, Unsupported> {
        Ok(Value::UInt(v))
    }
    fn serialize_f32(self, v: f32) -> Result<Value, Unsupported> {
        Ok(Value::Float(v.into()))
    }
    fn serialize_f64(self, v: f64) -> Result<Value, Unsupported> {
        Ok(Value::Float(v))
    }
    fn serialize_char(self, v: char) -> Result<Value, Unsupported> {
        Ok(Value::Str(v.to_string()))
    }
    fn serialize_str(self, v: &str) -> Result<Value, Unsupported> {
        Ok(Value::Str(v.to_owned()))
    }
    fn serialize_bytes(self, _: &[u8]) -> Result<Value, Unsupported> {
        unsupported("a byte string")
    }
    fn serialize_none(self) -> Result<Value, Unsupported> {
        Ok(Value::Null)
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<Value, Unsupported> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<Value, Unsupported> {
        Ok(Value::Null)
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<Value, Unsupported> {
        Ok(Value::Null)
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<Value, Unsupported> {
        Ok(Value::Str(variant.to_owned()))
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        name: &'static str,
        value: &T,
    ) -> Result<Value, Unsupported> {
        if name == Points::SERDE_NAME {
            value.serialize(PointsSerializer)
        } else {
            value.serialize(self)
        }
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<Value, Unsupported> {
        Ok(in_variant(Some(variant), value.serialize(self)?))
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<SeqBuilder, Unsupported> {
        Ok(SeqBuilder {
            items: Items::Floats(Vec::new()),
            variant: None,
        })
    }
    fn serialize_tuple(self, len: usize) -> Result<SeqBuilder, Unsupported> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_struct(
        self,
        _: &'static str,
        len: usize,
    ) -> Result<SeqBuilder, Unsupported> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<SeqBuilder, Unsupported> {
        Ok(SeqBuilder {
            items: Items::Floats(Vec::new()),
            variant: Some(variant),
        })
    }
    fn serialize_map(self, _: Option<usize>) -> Result<MapBuilder, Unsupported> {
        Ok(MapBuilder {
            entries: Vec::new(),
            key: None,
            variant: None,
        })
    }
    fn serialize_struct(self, _: &'static str, len: usize) -> Result<MapBuilder, Unsupported> {
        self.serialize_map(Some(len))
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<MapBuilder, Unsupported> {
        Ok(MapBuilder {
            entries: Vec::new(),
            key: None,
            variant: Some(variant),
        })
    }
}

impl SeqBuilder {
    fn push<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        self.items.push(value.serialize(ValueSerializer)?);
        Ok(())
    }

    fn finish(self) -> Value {
        in_variant(self.variant, self.items.finish())
    }
}

/// The serde traits of sequences, each pushing its elements into the builder.
macro_rules! seq_traits {
    ($($name:ident: $method:ident),*) => {
        $(
            impl ser::$name for SeqBuilder {
                type Ok = Value;
                type Error = Unsupported;
                fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
                    self.push(value)
                }
                fn end(self) -> Result<Value, Unsupported> {
                    Ok(self.finish())
                }
            }
        )*
    };
}

seq_traits!(
    SerializeSeq: serialize_element,
    SerializeTuple: serialize_element,
    SerializeTupleStruct: serialize_field,
    SerializeTupleVariant: serialize_field
);

impl MapBuilder {
    fn field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Unsupported> {
        self.entries
            .push((key.to_owned(), value.serialize(ValueSerializer)?));
        Ok(())
    }

    fn finish(self) -> Value {
        in_variant(self.variant, Value::Dict(self.entries))
    }
}

impl ser::SerializeMap for MapBuilder {
    type Ok = Value;
    type Error = Unsupported;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Unsupported> {
        match key.serialize(ValueSerializer)? {
            Value::Str(s) => {
                self.key = Some(s);
                Ok(())
            }
            _ => unsupported("a map key that is not a string"),
        }
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        let key = self
            .key
            .take()
            .ok_or_else(|| Unsupported("a map value without a key".to_owned()))?;
        self.entries.push((key, value.serialize(ValueSerializer)?));
        Ok(())
    }
    fn end(self) -> Result<Value, Unsupported> {
        Ok(self.finish())
    }
}

/// The serde traits of structs, each adding its fields to the object.
macro_rules! struct_traits {
    ($($name:ident),*) => {
        $(
            impl ser::$name for MapBuilder {
                type Ok = Value;
                type Error = Unsupported;
                fn serialize_field<T: Serialize + ?Sized>(
                    &mut self,
                    key: &'static str,
                    value: &T,
                ) -> Result<(), Unsupported> {
                    self.field(key, value)
                }
                fn end(self) -> Result<Value, Unsupported> {
                    Ok(self.finish())
                }
            }
        )*
    };
}

struct_traits!(SerializeStruct, SerializeStructVariant);

mod points;
use points::PointsSerializer;

#[cfg(test)]
mod tests;
