//! The top-level keys of a value's JSON object, each with its own JSON text,
//! taken from the value's `Serialize` (for a result: the result file's keys
//! in its order), leaving out some keys without ever serializing them (the
//! samples of a million parameters).

use serde::ser::{self, Impossible, Serialize, SerializeStruct, Serializer};
use serde_json::Error;

/// Every top-level key of `value` (a struct) but those in `skip`, in order,
/// each with its compact JSON text.
///
/// # Errors
/// If `value` does not serialize as a struct, or a kept value cannot be
/// written as JSON.
pub(crate) fn top_level_json<T: Serialize>(
    value: &T,
    skip: &[&str],
) -> Result<Vec<(String, String)>, Error> {
    let mut keys = Keys {
        skip,
        out: Vec::new(),
    };
    value.serialize(&mut keys)?;
    Ok(keys.out)
}

struct Keys<'s> {
    skip: &'s [&'s str],
    out: Vec<(String, String)>,
}

fn not_a_struct() -> Error {
    ser::Error::custom("the top level is not a struct")
}

/// Every kind of value but a struct is refused at the top level.
macro_rules! refuse {
    ($($name:ident($($t:ty),*)),* $(,)?) => {$(
        fn $name(self, $(_: $t),*) -> Result<(), Error> { Err(not_a_struct()) }
    )*};
}

impl Serializer for &mut Keys<'_> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Impossible<(), Error>;
    type SerializeTuple = Impossible<(), Error>;
    type SerializeTupleStruct = Impossible<(), Error>;
    type SerializeTupleVariant = Impossible<(), Error>;
    type SerializeMap = Impossible<(), Error>;
    type SerializeStruct = Self;
    type SerializeStructVariant = Impossible<(), Error>;

    refuse!(
        serialize_bool(bool),
        serialize_i8(i8),
        serialize_i16(i16),
        serialize_i32(i32),
        serialize_i64(i64),
        serialize_u8(u8),
        serialize_u16(u16),
        serialize_u32(u32),
        serialize_u64(u64),
        serialize_f32(f32),
        serialize_f64(f64),
        serialize_char(char),
        serialize_str(&str),
        serialize_bytes(&[u8]),
        serialize_none(),
        serialize_unit(),
        serialize_unit_struct(&'static str),
        serialize_unit_variant(&'static str, u32, &'static str),
    );

    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Result<(), Error> {
        value.serialize(self)
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Error> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<(), Error> {
        Err(not_a_struct())
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Error> {
        Err(not_a_struct())
    }
    fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Error> {
        Err(not_a_struct())
    }
    fn serialize_tuple_struct(
        self,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleStruct, Error> {
        Err(not_a_struct())
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleVariant, Error> {
        Err(not_a_struct())
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Error> {
        Err(not_a_struct())
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, Error> {
        Ok(self)
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStructVariant, Error> {
        Err(not_a_struct())
    }
}

impl SerializeStruct for &mut Keys<'_> {
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Error> {
        if !self.skip.contains(&key) {
            self.out
                .push((key.to_owned(), serde_json::to_string(value)?));
        }
        Ok(())
    }

    fn end(self) -> Result<(), Error> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Serialize)]
    struct Result {
        alpha: f64,
        curves: Vec<f64>,
        regime: &'static str,
    }

    #[test]
    fn kept_keys_in_order_skipped_ones_never_written() {
        let r = Result {
            alpha: 0.8,
            curves: vec![1.0; 3],
            regime: "alpha > h",
        };
        let keys = top_level_json(&r, &["curves"]).unwrap();
        assert_eq!(
            keys,
            [
                ("alpha".to_owned(), "0.8".to_owned()),
                ("regime".to_owned(), "\"alpha > h\"".to_owned())
            ]
        );
        assert!(top_level_json(&[1.0], &[]).is_err());
    }
}
