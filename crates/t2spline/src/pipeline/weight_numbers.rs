//! Fuzzy weights (docs/method.md §16): each weight of a curve or surface a
//! normal type-2 fuzzy number whose every value is a valid weight.

use crate::error::Error;
use crate::fuzzy::{Layer, Nt2Number};
use crate::nurbs::curve::weight_problems;

/// The crisp values of `numbers`, the weights of `count` control points,
/// once every value of every number (the feet of the upper cut, the least
/// and the largest, included) is a valid weight.
///
/// # Errors
/// [`Error::WeightCount`] unless there are `count` numbers;
/// [`Error::Weight`] or [`Error::WeightOutOfRange`] for the first value that
/// is not a valid weight, the upper cut's left feet first: every other value
/// of a number lies between its upper feet.
fn check_weight_numbers(numbers: &[Nt2Number], count: usize) -> Result<Vec<f64>, Error> {
    for layer in [Layer::UpperLeft, Layer::UpperRight] {
        let values: Vec<f64> = numbers.iter().map(|w| w.layer(layer)).collect();
        if let Some(e) = weight_problems(&values, count).into_iter().next() {
            return Err(e);
        }
    }
    Ok(numbers.iter().map(Nt2Number::crisp).collect())
}

/// Whether every value of `number` is its crisp value: a crisp weight
/// written as a number.
fn is_crisp(number: &Nt2Number) -> bool {
    let c = number.crisp();
    Layer::ALL.iter().all(|&l| number.layer(l) == c)
}

/// The weights of `count` control points from `numbers`: their crisp values,
/// and the numbers themselves unless every one is crisp (then the weights
/// are crisp).
///
/// # Errors
/// As [`check_weight_numbers`].
pub(crate) fn weights_of(
    numbers: Vec<Nt2Number>,
    count: usize,
) -> Result<(Vec<f64>, Option<Vec<Nt2Number>>), Error> {
    let weights = check_weight_numbers(&numbers, count)?;
    let fuzzy = numbers.iter().any(|w| !is_crisp(w));
    Ok((weights, fuzzy.then_some(numbers)))
}

/// `Err(`[`Error::FuzzyWeights`]`)` naming `what` where there are fuzzy
/// weights: the guard of the operations that take crisp weights only.
pub(crate) fn crisp_only(numbers: Option<&[Nt2Number]>, what: &'static str) -> Result<(), Error> {
    match numbers {
        Some(_) => Err(Error::FuzzyWeights { what }),
        None => Ok(()),
    }
}
