//! `Points` straight into one block of floats: the rows `[[x, y], …]` that
//! serde hands over are written one after the other, so a million samples
//! cost a million row visits and no allocation per row. An absent value
//! (`None`, a lower alpha-cut above the number's height) becomes NaN.

use serde::ser::{self, Impossible, Serialize};

use super::{unsupported, Unsupported, Value};

/// Rejects the serde methods of scalar kinds that a point list never holds.
macro_rules! reject_scalars {
    ($($name:ident: $arg:ty),* $(,)?) => {
        $(
            fn $name(self, _: $arg) -> Result<Self::Ok, Unsupported> {
                unsupported(concat!("in a point list, a value of ", stringify!($arg)))
            }
        )*
    };
}

/// Rejects the serde methods of compound kinds other than sequences.
macro_rules! reject_compounds {
    () => {
        type SerializeTuple = Impossible<Self::Ok, Unsupported>;
        type SerializeTupleStruct = Impossible<Self::Ok, Unsupported>;
        type SerializeTupleVariant = Impossible<Self::Ok, Unsupported>;
        type SerializeMap = Impossible<Self::Ok, Unsupported>;
        type SerializeStruct = Impossible<Self::Ok, Unsupported>;
        type SerializeStructVariant = Impossible<Self::Ok, Unsupported>;

        reject_scalars!(
            serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
            serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
            serialize_u64: u64, serialize_f32: f32, serialize_char: char,
            serialize_str: &str, serialize_bytes: &[u8], serialize_unit_struct: &'static str,
        );
        fn serialize_unit(self) -> Result<Self::Ok, Unsupported> {
            unsupported("in a point list, a unit")
        }
        fn serialize_unit_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
        ) -> Result<Self::Ok, Unsupported> {
            unsupported("in a point list, an enum variant")
        }
        fn serialize_newtype_struct<T: Serialize + ?Sized>(
            self,
            _: &'static str,
            value: &T,
        ) -> Result<Self::Ok, Unsupported> {
            value.serialize(self)
        }
        fn serialize_newtype_variant<T: Serialize + ?Sized>(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: &T,
        ) -> Result<Self::Ok, Unsupported> {
            unsupported("in a point list, an enum variant")
        }
        fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Unsupported> {
            unsupported("in a point list, a tuple")
        }
        fn serialize_tuple_struct(
            self,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleStruct, Unsupported> {
            unsupported("in a point list, a tuple")
        }
        fn serialize_tuple_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleVariant, Unsupported> {
            unsupported("in a point list, an enum variant")
        }
        fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Unsupported> {
            unsupported("in a point list, a map")
        }
        fn serialize_struct(
            self,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeStruct, Unsupported> {
            unsupported("in a point list, a struct")
        }
        fn serialize_struct_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeStructVariant, Unsupported> {
            unsupported("in a point list, an enum variant")
        }
    };
}

/// Serializes the content of a `Points` newtype: a sequence of rows.
pub(super) struct PointsSerializer;

/// The rows so far: their values one after the other, and their width.
pub(super) struct PointsSeq {
    data: Vec<f64>,
    rows: usize,
    width: Option<usize>,
}

impl ser::Serializer for PointsSerializer {
    type Ok = Value;
    type Error = Unsupported;
    type SerializeSeq = PointsSeq;
    reject_compounds!();
    reject_scalars!(serialize_f64: f64);

    fn serialize_none(self) -> Result<Value, Unsupported> {
        unsupported("an absent point list")
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<Value, Unsupported> {
        value.serialize(self)
    }
    fn serialize_seq(self, len: Option<usize>) -> Result<PointsSeq, Unsupported> {
        Ok(PointsSeq {
            // Points of up to three coordinates; the exact count follows.
            data: Vec::with_capacity(len.unwrap_or(0).saturating_mul(3)),
            rows: 0,
            width: None,
        })
    }
}

impl ser::SerializeSeq for PointsSeq {
    type Ok = Value;
    type Error = Unsupported;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, row: &T) -> Result<(), Unsupported> {
        let width = row.serialize(RowSerializer {
            data: &mut self.data,
        })?;
        if *self.width.get_or_insert(width) != width {
            return unsupported("a point list whose points differ in dimension");
        }
        self.rows += 1;
        Ok(())
    }
    fn end(self) -> Result<Value, Unsupported> {
        Ok(Value::Array {
            shape: vec![self.rows, self.width.unwrap_or(0)],
            data: self.data,
        })
    }
}

/// Serializes one point (a sequence of coordinates) into the block; gives
/// the number of coordinates.
struct RowSerializer<'a> {
    data: &'a mut Vec<f64>,
}

/// A point being written.
struct RowSeq<'a> {
    data: &'a mut Vec<f64>,
    count: usize,
}

impl<'a> ser::Serializer for RowSerializer<'a> {
    type Ok = usize;
    type Error = Unsupported;
    type SerializeSeq = RowSeq<'a>;
    reject_compounds!();
    reject_scalars!(serialize_f64: f64);

    fn serialize_none(self) -> Result<usize, Unsupported> {
        unsupported("an absent point")
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<usize, Unsupported> {
        value.serialize(self)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<RowSeq<'a>, Unsupported> {
        Ok(RowSeq {
            data: self.data,
            count: 0,
        })
    }
}

impl ser::SerializeSeq for RowSeq<'_> {
    type Ok = usize;
    type Error = Unsupported;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        value.serialize(CellSerializer { data: self.data })?;
        self.count += 1;
        Ok(())
    }
    fn end(self) -> Result<usize, Unsupported> {
        Ok(self.count)
    }
}

/// Serializes one coordinate: a float, or NaN for an absent value.
struct CellSerializer<'a> {
    data: &'a mut Vec<f64>,
}

impl ser::Serializer for CellSerializer<'_> {
    type Ok = ();
    type Error = Unsupported;
    type SerializeSeq = Impossible<(), Unsupported>;
    reject_compounds!();

    fn serialize_f64(self, v: f64) -> Result<(), Unsupported> {
        self.data.push(v);
        Ok(())
    }
    fn serialize_none(self) -> Result<(), Unsupported> {
        self.data.push(f64::NAN);
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Unsupported> {
        value.serialize(self)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Unsupported> {
        unsupported("a coordinate that is a list")
    }
}
