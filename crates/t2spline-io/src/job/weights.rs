//! A curve's `weights` as read: a list of numbers (crisp weights), or a list
//! in which some entries are fuzzy numbers in the form of a coordinate
//! (docs/method.md §16). A bare number among fuzzy ones is a crisp weight.

use serde_json::Value;
use t2spline::{Layer, Nt2Number, Num, Place, MAX_WEIGHT, MIN_WEIGHT};

use super::place::{child, element};
use super::walker::Walker;

/// The weights of a curve, once read.
pub(super) enum CurveWeights {
    /// Crisp weights.
    Crisp(Vec<f64>),
    /// Fuzzy weights, one number per entry.
    Fuzzy(Vec<Nt2Number>),
}

impl CurveWeights {
    /// The crisp weights, or the crisp values of the fuzzy ones: what the
    /// rules tying weights to points and knots check.
    pub(super) fn crisp(&self) -> Vec<f64> {
        match self {
            CurveWeights::Crisp(w) => w.clone(),
            CurveWeights::Fuzzy(w) => w.iter().map(Nt2Number::crisp).collect(),
        }
    }
}

impl Walker {
    /// `weights` of a curve: an array of numbers, or of numbers and fuzzy
    /// numbers (each with the job's `lower_height` unless it gives its
    /// own, as a coordinate's number does). Every value of a fuzzy weight
    /// must be a weight: the feet of its upper cut, which bound the rest,
    /// are checked here, with their place; the crisp values are checked
    /// with the curve's other rules.
    pub(super) fn curve_weights(
        &mut self,
        v: &Value,
        height: Result<Option<f64>, ()>,
    ) -> Option<CurveWeights> {
        let fuzzy = v
            .as_array()
            .is_some_and(|items| items.iter().any(Value::is_object));
        if !fuzzy {
            return self.numbers(v, "weights").map(CurveWeights::Crisp);
        }
        let items = v.as_array()?;
        let numbers: Vec<Option<Nt2Number>> = items
            .iter()
            .enumerate()
            .map(|(i, item)| {
                let key = element("weights", i);
                let number = self.number_at(item, &key, Place::NONE, height)?;
                self.weight_feet(&key, &number).then_some(number)
            })
            .collect();
        numbers
            .into_iter()
            .collect::<Option<_>>()
            .map(CurveWeights::Fuzzy)
    }

    /// Whether the feet of the upper cut of the fuzzy weight at `key` are
    /// valid weights (finite, within [`MIN_WEIGHT`], [`MAX_WEIGHT`]);
    /// reports each that is not.
    pub(super) fn weight_feet(&mut self, key: &str, w: &Nt2Number) -> bool {
        let mut fine = true;
        for (side, layer) in [(0, Layer::UpperLeft), (1, Layer::UpperRight)] {
            let value = w.layer(layer);
            let problem = if !(value.is_finite() && value > 0.0) {
                "must be finite and greater than 0"
            } else if !(MIN_WEIGHT..=MAX_WEIGHT).contains(&value) {
                "is outside [1e-150, 1e150]"
            } else {
                continue;
            };
            fine = false;
            self.report(
                &element(&child(key, "upper"), side),
                format!(
                    "{} {problem}: every value of a fuzzy weight is a weight",
                    Num(value)
                ),
            );
        }
        fine
    }
}
