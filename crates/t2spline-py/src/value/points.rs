//! `Points` straight into one block of floats: the points `[[x, y], …]` (or,
//! for a surface's grid, the rows of points `[[[x, y, z], …], …]`) that serde
//! hands over are written one after the other, so a million samples cost a
//! million point visits and no allocation per point. An absent value (`None`,
//! a lower alpha-cut above the number's height) becomes NaN. The block's
//! shape is the nesting's: `(n, d)` for a list of points, `(rows, columns, d)`
//! for a grid.

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

/// Serializes the content of a `Points` newtype: nested sequences whose
/// innermost elements are coordinates.
pub(super) struct PointsSerializer;

/// The block being filled: the coordinates in C order, and the length of
/// each level of nesting as far as it is known.
struct Block {
    data: Vec<f64>,
    shape: Vec<Option<usize>>,
    /// The depth at which coordinates sit, once one has been seen.
    leaf_depth: Option<usize>,
}

impl Block {
    /// Records that the sequence at `depth` had `count` elements.
    fn close(&mut self, depth: usize, count: usize) -> Result<(), Unsupported> {
        if self.shape.len() <= depth {
            self.shape.resize(depth + 1, None);
        }
        match self.shape[depth] {
            Some(known) if known != count => {
                unsupported("a point list whose rows or points differ in length")
            }
            _ => {
                self.shape[depth] = Some(count);
                Ok(())
            }
        }
    }

    /// Records a coordinate at `depth`.
    fn push(&mut self, depth: usize, v: f64) -> Result<(), Unsupported> {
        if *self.leaf_depth.get_or_insert(depth) != depth {
            return unsupported("a point list nested to different depths");
        }
        self.data.push(v);
        Ok(())
    }
}

/// The top-level sequence of a point list.
pub(super) struct PointsSeq {
    block: Block,
    count: usize,
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
            block: Block {
                // Points of up to three coordinates; the exact count follows.
                data: Vec::with_capacity(len.unwrap_or(0).saturating_mul(3)),
                shape: Vec::new(),
                leaf_depth: None,
            },
            count: 0,
        })
    }
}

impl ser::SerializeSeq for PointsSeq {
    type Ok = Value;
    type Error = Unsupported;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, row: &T) -> Result<(), Unsupported> {
        row.serialize(NestedSerializer {
            block: &mut self.block,
            depth: 1,
        })?;
        self.count += 1;
        Ok(())
    }
    fn end(mut self) -> Result<Value, Unsupported> {
        self.block.close(0, self.count)?;
        let Block {
            data,
            shape,
            leaf_depth,
        } = self.block;
        if leaf_depth == Some(1) {
            return unsupported("a point list whose points are numbers");
        }
        // An empty list is `(0, 0)`: a list of points of unknown dimension.
        let depth = leaf_depth.unwrap_or(2).max(2);
        let mut dims: Vec<usize> = shape.into_iter().map(|d| d.unwrap_or(0)).collect();
        dims.resize(depth, 0);
        Ok(Value::Array { shape: dims, data })
    }
}

/// Serializes an element at `depth` of a point list: a sequence (a row of
/// points, or a point) or a coordinate.
struct NestedSerializer<'a> {
    block: &'a mut Block,
    depth: usize,
}

/// A sequence being written at `depth`.
struct NestedSeq<'a> {
    block: &'a mut Block,
    depth: usize,
    count: usize,
}

impl<'a> ser::Serializer for NestedSerializer<'a> {
    type Ok = ();
    type Error = Unsupported;
    type SerializeSeq = NestedSeq<'a>;
    reject_compounds!();

    fn serialize_f64(self, v: f64) -> Result<(), Unsupported> {
        self.block.push(self.depth, v)
    }
    fn serialize_none(self) -> Result<(), Unsupported> {
        self.block.push(self.depth, f64::NAN)
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Unsupported> {
        value.serialize(self)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<NestedSeq<'a>, Unsupported> {
        if self.block.leaf_depth.is_some_and(|d| d <= self.depth) {
            return unsupported("a point list nested to different depths");
        }
        Ok(NestedSeq {
            block: self.block,
            depth: self.depth,
            count: 0,
        })
    }
}

impl ser::SerializeSeq for NestedSeq<'_> {
    type Ok = ();
    type Error = Unsupported;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        value.serialize(NestedSerializer {
            block: self.block,
            depth: self.depth + 1,
        })?;
        self.count += 1;
        Ok(())
    }
    fn end(self) -> Result<(), Unsupported> {
        self.block.close(self.depth, self.count)
    }
}
