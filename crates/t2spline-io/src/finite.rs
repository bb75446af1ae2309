//! The last check before writing: every number of an output is finite.
//!
//! `serde_json` writes NaN and infinity as `null`, and CSV writes them as `NaN`
//! and `inf`, so a non-finite number would pass silently into a file. The core
//! crate's input ranges make that impossible for valid jobs; this check makes
//! sure of it for any serializable output (present fields and fields added
//! later alike) by walking the value with a serde serializer that records only
//! its first non-finite number and the path to it.

use std::fmt;

use serde::ser::{self, Impossible, Serialize};

use crate::error::Error;

/// `Ok` if every `f32`/`f64` in `value` is finite.
///
/// # Errors
/// [`Error::NotFinite`] naming the first non-finite number by its path, e.g.
/// `curves.defuzzified[7][1]`.
///
/// # Examples
/// ```
/// # use t2spline_io::check_finite;
/// #[derive(serde::Serialize)]
/// struct Out { points: Vec<[f64; 2]>, label: Option<String> }
/// assert!(check_finite(&Out { points: vec![[1.0, 2.0]], label: None }).is_ok());
/// let e = check_finite(&Out { points: vec![[1.0, 2.0], [f64::NAN, 0.0]], label: None }).unwrap_err();
/// assert!(e.to_string().starts_with("internal error: points[1][0] = NaN is not a finite number"), "{e}");
/// ```
pub fn check_finite<T: Serialize + ?Sized>(value: &T) -> Result<(), Error> {
    let mut checker = Checker::default();
    match value.serialize(&mut checker) {
        Ok(()) => Ok(()),
        Err(Found::NotFinite(value)) => Err(Error::NotFinite {
            key: checker.path(),
            value,
        }),
        // A Serialize impl that fails on its own (none of ours does).
        Err(Found::Custom(message)) => Err(Error::NotFinite {
            key: format!("{} ({message})", checker.path()),
            value: f64::NAN,
        }),
    }
}

/// One step of a path.
enum Step {
    Key(&'static str),
    Index(usize),
}

#[derive(Default)]
struct Checker {
    path: Vec<Step>,
}

impl Checker {
    fn path(&self) -> String {
        let mut out = String::new();
        for step in &self.path {
            match step {
                Step::Key(k) if out.is_empty() => out.push_str(k),
                Step::Key(k) => {
                    out.push('.');
                    out.push_str(k);
                }
                Step::Index(i) => out.push_str(&format!("[{i}]")),
            }
        }
        out
    }

    /// Serializes one field under `key`.
    fn field<T: Serialize + ?Sized>(&mut self, key: &'static str, value: &T) -> Result<(), Found> {
        self.path.push(Step::Key(key));
        value.serialize(&mut *self)?;
        self.path.pop();
        Ok(())
    }
}

/// Why the walk stopped.
#[derive(Debug)]
enum Found {
    NotFinite(f64),
    Custom(String),
}

impl fmt::Display for Found {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Found::NotFinite(x) => write!(f, "{x} is not finite"),
            Found::Custom(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Found {}

impl ser::Error for Found {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Found::Custom(msg.to_string())
    }
}

/// A sequence, map or struct being walked: the path depth it started at and
/// the index of its next element.
struct Seq<'a> {
    checker: &'a mut Checker,
    depth: usize,
    next: usize,
}

impl Seq<'_> {
    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        self.checker.path.truncate(self.depth);
        self.checker.path.push(Step::Index(self.next));
        self.next += 1;
        value.serialize(&mut *self.checker)
    }

    fn end(self) -> Result<(), Found> {
        self.checker.path.truncate(self.depth);
        Ok(())
    }
}

macro_rules! ignore {
    ($($name:ident($t:ty)),* $(,)?) => {$(
        fn $name(self, _: $t) -> Result<(), Found> { Ok(()) }
    )*};
}

impl<'a> ser::Serializer for &'a mut Checker {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Seq<'a>;
    type SerializeTuple = Seq<'a>;
    type SerializeTupleStruct = Seq<'a>;
    type SerializeTupleVariant = Seq<'a>;
    type SerializeMap = Seq<'a>;
    type SerializeStruct = Seq<'a>;
    type SerializeStructVariant = Impossible<(), Found>;

    ignore!(
        serialize_bool(bool),
        serialize_i8(i8),
        serialize_i16(i16),
        serialize_i32(i32),
        serialize_i64(i64),
        serialize_u8(u8),
        serialize_u16(u16),
        serialize_u32(u32),
        serialize_u64(u64),
        serialize_char(char),
        serialize_str(&str),
        serialize_bytes(&[u8]),
        serialize_unit_struct(&'static str),
    );

    fn serialize_f32(self, v: f32) -> Result<(), Found> {
        self.serialize_f64(f64::from(v))
    }

    fn serialize_f64(self, v: f64) -> Result<(), Found> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(Found::NotFinite(v))
        }
    }

    fn serialize_none(self) -> Result<(), Found> {
        Ok(())
    }

    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Found> {
        value.serialize(self)
    }

    fn serialize_unit(self) -> Result<(), Found> {
        Ok(())
    }

    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Found> {
        Ok(())
    }

    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        value.serialize(self)
    }

    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        self.field(variant, value)
    }

    fn serialize_seq(self, _: Option<usize>) -> Result<Seq<'a>, Found> {
        let depth = self.path.len();
        Ok(Seq {
            checker: self,
            depth,
            next: 0,
        })
    }

    fn serialize_tuple(self, len: usize) -> Result<Seq<'a>, Found> {
        self.serialize_seq(Some(len))
    }

    fn serialize_tuple_struct(self, _: &'static str, len: usize) -> Result<Seq<'a>, Found> {
        self.serialize_seq(Some(len))
    }

    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        len: usize,
    ) -> Result<Seq<'a>, Found> {
        self.serialize_seq(Some(len))
    }

    fn serialize_map(self, len: Option<usize>) -> Result<Seq<'a>, Found> {
        self.serialize_seq(len)
    }

    fn serialize_struct(self, _: &'static str, len: usize) -> Result<Seq<'a>, Found> {
        self.serialize_seq(Some(len))
    }

    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Impossible<(), Found>, Found> {
        Err(Found::Custom("struct variants are not checked".into()))
    }
}

/// The sequence-like traits: each element is checked at the next index.
macro_rules! sequence {
    ($($trait:ident::$method:ident),*) => {$(
        impl ser::$trait for Seq<'_> {
            type Ok = ();
            type Error = Found;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
                self.element(value)
            }
            fn end(self) -> Result<(), Found> {
                Seq::end(self)
            }
        }
    )*};
}

sequence!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

impl ser::SerializeMap for Seq<'_> {
    type Ok = ();
    type Error = Found;
    // Map keys are not numbers in our outputs; values are checked by position.
    fn serialize_key<T: Serialize + ?Sized>(&mut self, _: &T) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        self.element(value)
    }
    fn end(self) -> Result<(), Found> {
        Seq::end(self)
    }
}

impl ser::SerializeStruct for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        self.checker.field(key, value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[derive(serde::Serialize)]
    struct Inner {
        a: Vec<Option<f64>>,
        b: (f32, f64),
    }

    #[derive(serde::Serialize)]
    struct Outer {
        name: String,
        inner: Vec<Inner>,
        map: BTreeMap<String, f64>,
    }

    fn outer(x: f64, y: f32, z: f64) -> Outer {
        Outer {
            name: "n".into(),
            inner: vec![
                Inner {
                    a: vec![Some(1.0), None],
                    b: (1.0, 2.0),
                },
                Inner {
                    a: vec![None, Some(x)],
                    b: (y, 2.0),
                },
            ],
            map: BTreeMap::from([("k".to_owned(), 1.0), ("l".to_owned(), z)]),
        }
    }

    #[test]
    fn names_the_first_non_finite_number() {
        assert!(check_finite(&outer(1.0, 1.0, 1.0)).is_ok());
        let key = |o: &Outer| match check_finite(o) {
            Err(Error::NotFinite { key, .. }) => key,
            other => panic!("{other:?}"),
        };
        assert_eq!(key(&outer(f64::NAN, 1.0, 1.0)), "inner[1].a[1]");
        assert_eq!(key(&outer(1.0, f32::INFINITY, 1.0)), "inner[1].b[0]");
        assert_eq!(key(&outer(1.0, 1.0, f64::NEG_INFINITY)), "map[1]");
    }
}
