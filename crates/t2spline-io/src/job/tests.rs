//! The description of the format ([`schema`](super::schema)) against its
//! readers: every key it names is read by the validator, which reports a
//! value of a type no key takes at that key's place, and by the one-pass
//! reading, which refuses it (and leaves the message to the validator). A
//! key added to the description and not taught to the validator fails here.

use serde_json::{json, Value};

use super::parse::parse_walking;
use super::schema::{FUZZY_NUMBER_KEYS, KNOT_DIRECTIONS, POINT_KEYS, TOP_KEYS};
use super::valid;

fn example(name: &str) -> Value {
    let path = format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// A value no key of a job takes.
fn stray() -> Value {
    json!({"?": [[]]})
}

/// Whether the validator reports a problem whose place (the text before
/// the first `: `) names `place`, and the one-pass reading refuses the job.
fn reported_at(job: &Value, place: &str) -> Result<(), String> {
    let text = serde_json::to_string_pretty(job).unwrap();
    if valid::job(&text).is_some() {
        return Err(format!("the one-pass reading took {place}"));
    }
    let problems = parse_walking(&text).map(drop).unwrap_err();
    let placed = problems.iter().any(|p| {
        p.message
            .split(": ")
            .next()
            .is_some_and(|at| at.contains(place))
    });
    if placed {
        Ok(())
    } else {
        Err(format!("{place}: {problems:?}"))
    }
}

#[test]
fn every_top_level_key_of_the_description_is_read() {
    for key in TOP_KEYS {
        let mut job = example("paper-alg-1-1.json");
        job[key] = stray();
        reported_at(&job, key).unwrap();
    }
}

#[test]
fn every_key_of_a_point_and_of_a_fuzzy_number_is_read() {
    for axis in POINT_KEYS {
        let mut job = example("paper-alg-1-1.json");
        job["points"][0][axis] = stray();
        reported_at(&job, &format!("points[0].{axis}")).unwrap();
    }
    for key in FUZZY_NUMBER_KEYS {
        let mut job = example("paper-alg-1-1.json");
        job["points"][0]["x"][key] = stray();
        reported_at(&job, &format!("points[0].x.{key}")).unwrap();
    }
}

#[test]
fn every_direction_of_a_surface_s_knots_is_read() {
    for direction in KNOT_DIRECTIONS {
        let mut job = example("fuzzy-terrain.json");
        job["knots"] = Value::Object([(direction.to_owned(), stray())].into_iter().collect());
        reported_at(&job, &format!("knots.{direction}")).unwrap();
    }
}
