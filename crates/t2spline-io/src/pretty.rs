//! JSON text for people: indented like `serde_json`'s pretty printer, but with
//! every array of plain numbers (a point, a pair, a knot vector) on one line, so
//! that a result of a few hundred samples stays readable.

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
    let mut out = String::new();
    write_value(&mut out, value, 0);
    out.push('\n');
    out
}

fn is_scalar(v: &Value) -> bool {
    !matches!(v, Value::Array(_) | Value::Object(_))
}

fn indent(out: &mut String, depth: usize) {
    out.extend(std::iter::repeat_n("  ", depth));
}

fn write_value(out: &mut String, value: &Value, depth: usize) {
    match value {
        Value::Array(items) if items.is_empty() => out.push_str("[]"),
        Value::Array(items) if items.iter().all(is_scalar) => {
            out.push('[');
            for (i, item) in items.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                out.push_str(&item.to_string());
            }
            out.push(']');
        }
        Value::Array(items) => {
            out.push_str("[\n");
            for (i, item) in items.iter().enumerate() {
                indent(out, depth + 1);
                write_value(out, item, depth + 1);
                out.push_str(if i + 1 < items.len() { ",\n" } else { "\n" });
            }
            indent(out, depth);
            out.push(']');
        }
        Value::Object(map) if map.is_empty() => out.push_str("{}"),
        Value::Object(map) => {
            out.push_str("{\n");
            for (i, (key, item)) in map.iter().enumerate() {
                indent(out, depth + 1);
                out.push_str(&Value::String(key.clone()).to_string());
                out.push_str(": ");
                write_value(out, item, depth + 1);
                out.push_str(if i + 1 < map.len() { ",\n" } else { "\n" });
            }
            indent(out, depth);
            out.push('}');
        }
        scalar => out.push_str(&scalar.to_string()),
    }
}
