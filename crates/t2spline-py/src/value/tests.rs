use serde_json::json;
use t2spline::job::{Overrides, Points};

use super::*;

/// The JSON that a tree stands for: arrays as nested lists, NaN as `null`.
fn json_of(value: &Value) -> serde_json::Value {
    fn nested(shape: &[usize], data: &[f64]) -> serde_json::Value {
        match shape {
            [] => serde_json::Number::from_f64(data[0]).map_or(serde_json::Value::Null, Into::into),
            [n, rest @ ..] => {
                let size = rest.iter().product::<usize>();
                (0..*n)
                    .map(|k| nested(rest, &data[k * size..(k + 1) * size]))
                    .collect()
            }
        }
    }
    match value {
        Value::Null => serde_json::Value::Null,
        Value::Bool(b) => json!(b),
        Value::Int(i) => json!(i),
        Value::UInt(u) => json!(u),
        Value::Float(x) => json!(x),
        Value::Str(s) => json!(s),
        Value::Array { shape, data } => {
            assert_eq!(shape.iter().product::<usize>(), data.len(), "{shape:?}");
            nested(shape, data)
        }
        Value::List(items) => items.iter().map(json_of).collect(),
        Value::Dict(entries) => entries
            .iter()
            .map(|(k, v)| (k.clone(), json_of(v)))
            .collect::<serde_json::Map<_, _>>()
            .into(),
    }
}

/// The array at `path` (keys separated by dots).
fn at<'a>(value: &'a Value, path: &str) -> &'a Value {
    path.split('.').fold(value, |v, key| match v {
        Value::Dict(entries) => &entries.iter().find(|(k, _)| k == key).expect(key).1,
        other => panic!("{key}: not in {other:?}"),
    })
}

fn shape(value: &Value) -> &[usize] {
    match value {
        Value::Array { shape, .. } => shape,
        other => panic!("not an array: {other:?}"),
    }
}

fn example_output(alpha: f64, derivatives: Option<i64>) -> t2spline::job::RunOutput {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/paper-alg-1-1.json"
    );
    let job = t2spline_io::read_job(std::path::Path::new(path)).unwrap();
    let overrides = Overrides {
        alpha: Some(alpha),
        samples: Some(vec![11]),
        derivatives,
        ..Overrides::default()
    };
    job.run(&job.settings(&overrides).unwrap()).unwrap()
}

#[test]
fn a_run_has_the_structure_of_its_json_with_arrays_of_numbers() {
    // 0.3 and 0.8 lie on both sides of the example's lower heights; with
    // derivatives the output has lists of point lists.
    for (alpha, derivatives) in [(0.3, None), (0.8, Some(2)), (1.0, None)] {
        let out = example_output(alpha, derivatives);
        let tree = to_value(&out).unwrap();
        assert_eq!(json_of(&tree), serde_json::to_value(&out).unwrap());
        assert_eq!(shape(at(&tree, "curves.crisp")), [11, 2]);
        assert_eq!(shape(at(&tree, "curves.params")), [11]);
        assert_eq!(shape(at(&tree, "domain")), [2]);
        assert_eq!(
            shape(at(&tree, "control_points.alpha_cut.upper_left")),
            [4, 2]
        );
        if derivatives.is_some() {
            // Two derivative orders, stacked.
            assert_eq!(shape(at(&tree, "curves.derivatives.crisp")), [2, 11, 2]);
            assert!(matches!(
                at(&tree, "curves.arc_length.crisp"),
                Value::Float(_)
            ));
        }
    }
}

#[test]
fn absent_values_are_nan_and_absent_curves_none() {
    let out = example_output(1.0, None);
    let tree = to_value(&out).unwrap();
    // At alpha = 1 > every lower height, no number has a lower cut.
    let Value::Array { data, .. } = at(&tree, "control_points.alpha_cut.lower_left") else {
        panic!("not an array")
    };
    assert!(data.iter().all(|v| v.is_nan()), "{data:?}");
    assert_eq!(at(&tree, "curves.alpha_cut.lower_left"), &Value::Null);
    assert!(matches!(at(&tree, "order"), Value::UInt(3)));
    assert!(matches!(at(&tree, "regime"), Value::Str(s) if s == "alpha > h"));
}

#[test]
fn sequences_stack_when_they_can_and_stay_lists_otherwise() {
    let points = Points::from_points(&[[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]);
    let tree = to_value(&vec![points.clone(), points.clone()]).unwrap();
    assert_eq!(shape(&tree), [2, 3, 2]);
    let ragged = to_value(&(vec![1.0, 2.0], vec![3.0])).unwrap();
    assert!(matches!(&ragged, Value::List(items) if items.len() == 2));
    assert_eq!(json_of(&ragged), json!([[1.0, 2.0], [3.0]]));
    // Arrays, then something else: the arrays come back one by one, empty
    // ones too.
    let empty = Vec::<f64>::new();
    let then_other = to_value(&(&empty, &empty, "x")).unwrap();
    assert_eq!(json_of(&then_other), json!([[], [], "x"]));
    let mixed = to_value(&(1.5, "a", 2u8)).unwrap();
    assert_eq!(json_of(&mixed), json!([1.5, "a", 2]));
    assert_eq!(shape(&to_value(&Vec::<f64>::new()).unwrap()), [0]);
    let with_gap = Points::from_points(&[[Some(1.0), None]]);
    let Value::Array { shape, data } = to_value(&with_gap).unwrap() else {
        panic!("not an array")
    };
    assert_eq!((shape.as_slice(), data[0]), ([1, 2].as_slice(), 1.0));
    assert!(data[1].is_nan());
}

#[test]
fn what_json_cannot_hold_is_an_error() {
    let mut map = std::collections::BTreeMap::new();
    map.insert(1, 2.0);
    assert!(to_value(&map).is_err());
    assert!(to_value(serde_bytes_like()).is_err());
}

/// A value that serializes as bytes.
fn serde_bytes_like() -> &'static impl Serialize {
    struct Bytes;
    impl Serialize for Bytes {
        fn serialize<S: ser::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            s.serialize_bytes(b"ab")
        }
    }
    &Bytes
}

#[test]
fn a_surface_run_gives_grids_of_points() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/fuzzy-terrain.json"
    );
    let job = t2spline_io::read_job(std::path::Path::new(path)).unwrap();
    let overrides = Overrides {
        samples: Some(vec![4, 3]),
        ..Overrides::default()
    };
    let out = job.run(&job.settings(&overrides).unwrap()).unwrap();
    let tree = to_value(&out).unwrap();
    assert_eq!(json_of(&tree), serde_json::to_value(&out).unwrap());
    assert_eq!(shape(at(&tree, "surfaces.crisp")), [4, 3, 3]);
    assert_eq!(shape(at(&tree, "surfaces.type_reduced.left")), [4, 3, 3]);
    assert_eq!(shape(at(&tree, "control_points.defuzzified")), [6, 5, 3]);
    assert_eq!(shape(at(&tree, "weights")), [6, 5]);
}
