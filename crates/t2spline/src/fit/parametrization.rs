//! Parameters of the data points (The NURBS Book §9.2.1, Eqs. 9.3–9.6).

use std::fmt;
use std::str::FromStr;

use crate::error::Error;

/// How data points are assigned parameters `ū₀ = 0 < … < ū_m = 1`.
///
/// ```text
/// uniform:      ūₖ = k/m                                            (Eq. 9.3)
/// chord length: ūₖ = ūₖ₋₁ + |Qₖ − Qₖ₋₁| / d,   d = Σ |Qₖ − Qₖ₋₁|     (Eqs. 9.4–9.5)
/// centripetal:  ūₖ = ūₖ₋₁ + |Qₖ − Qₖ₋₁|^½ / d, d = Σ |Qₖ − Qₖ₋₁|^½   (Eq. 9.6)
/// ```
/// Chord length is the usual choice; centripetal (Lee, 1989) behaves better at
/// sharp turns; uniform ignores the geometry and can produce loops when the
/// spacing of the data is uneven.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Parametrization {
    /// Parameters proportional to the distance along the data polygon.
    #[default]
    ChordLength,
    /// Parameters proportional to the square root of the distances.
    Centripetal,
    /// Equally spaced parameters.
    Uniform,
}

impl Parametrization {
    /// All three, in the order of the documentation.
    pub const ALL: [Parametrization; 3] = [
        Parametrization::ChordLength,
        Parametrization::Centripetal,
        Parametrization::Uniform,
    ];

    /// The name used on the command line: `chord`, `centripetal`, `uniform`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Parametrization::ChordLength => "chord",
            Parametrization::Centripetal => "centripetal",
            Parametrization::Uniform => "uniform",
        }
    }

    /// The parameters `ū₀ … ū_m` of `points` (at least two); the first is
    /// exactly 0, the last exactly 1, and they do not decrease.
    ///
    /// # Errors
    /// For chord length and centripetal: [`Error::CoincidentDataPoints`] if two
    /// consecutive points are equal, or so close that their parameters round to
    /// the same value (no curve passes through two points at one parameter);
    /// [`Error::NotFinite`] if a distance overflows. [`Error::TooFewDataPoints`]
    /// for fewer than two points.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::Parametrization;
    /// let q = [[0.0, 0.0], [3.0, 4.0], [3.0, 5.0]]; // chords 5 and 1
    /// assert_eq!(Parametrization::ChordLength.parameters(&q)?, vec![0.0, 5.0 / 6.0, 1.0]);
    /// let c = Parametrization::Centripetal.parameters(&q)?;
    /// assert!((c[1] - 5f64.sqrt() / (5f64.sqrt() + 1.0)).abs() < 1e-15);
    /// assert_eq!(Parametrization::Uniform.parameters(&q)?, vec![0.0, 0.5, 1.0]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn parameters<const D: usize>(self, points: &[[f64; D]]) -> Result<Vec<f64>, Error> {
        let m = points.len().saturating_sub(1);
        if m == 0 {
            return Err(Error::TooFewDataPoints {
                degree: 1,
                count: points.len(),
            });
        }
        if self == Parametrization::Uniform {
            return Ok((0..=m).map(|k| k as f64 / m as f64).collect());
        }
        self.chord_parameters(points, (0..m).map(|k| (k, k + 1)))
    }

    /// The normalised partial sums `ūₖ = sₖ/d` of the chords (or their
    /// square roots, centripetal) between the points of each pair of
    /// `pairs`, taken in order: `ū₀ = 0`, then one parameter a pair, the
    /// last `d/d = 1` exactly. A chord too short to move the rounded sum
    /// gives equal parameters, which no interpolant can honour either.
    ///
    /// # Errors
    /// [`Error::CoincidentDataPoints`] naming the pair whose chord is 0 or
    /// too short; [`Error::NotFinite`] if the sum overflows.
    fn chord_parameters<const D: usize>(
        self,
        points: &[[f64; D]],
        pairs: impl Iterator<Item = (usize, usize)> + Clone,
    ) -> Result<Vec<f64>, Error> {
        let coincident =
            |(first, second): (usize, usize)| Error::CoincidentDataPoints { first, second };
        let mut cumulative = vec![0.0];
        let mut total = 0.0;
        for (a, b) in pairs.clone() {
            let chord = distance(&points[a], &points[b]);
            if chord == 0.0 {
                return Err(coincident((a, b)));
            }
            total += match self {
                Parametrization::Centripetal => chord.sqrt(),
                _ => chord,
            };
            cumulative.push(total);
        }
        if !total.is_finite() {
            return Err(Error::NotFinite {
                place: crate::Place::NONE,
                what: "total chord length",
                value: total,
            });
        }
        let u: Vec<f64> = cumulative.into_iter().map(|s| s / total).collect();
        match u.windows(2).position(|w| w[0] >= w[1]) {
            Some(k) => Err(pairs.clone().nth(k).map_or(
                Error::CoincidentDataPoints {
                    first: k,
                    second: k + 1,
                },
                coincident,
            )),
            None => Ok(u),
        }
    }
}

impl Parametrization {
    /// The parameters `ū₀ … ū_{N−1}` of `points` taken as a loop (at least
    /// two, the last not repeating the first): the closing chord from
    /// `Q_{N−1}` back to `Q₀` counts, so the loop's parameter runs once
    /// around `[0, 1)` and `ū_N = 1` is `Q₀` again.
    ///
    /// ```text
    /// uniform:      ūₖ = k/N
    /// chord length: ūₖ = sₖ/d,  sₖ = Σ_{i<k} |Q_{i+1} − Qᵢ|,  d = s_{N−1} + |Q₀ − Q_{N−1}|
    /// centripetal:  the same with the square roots of the chords
    /// ```
    /// (The NURBS Book Eqs. 9.3–9.6 around the closed polygon; FITPACK's
    /// `percur` and scipy's `splprep(per=1)` take the same chord-length
    /// parameters of a loop whose last point repeats the first.)
    ///
    /// # Errors
    /// As [`Parametrization::parameters`]; the closing pair is named
    /// `points[N−1]` and `points[0]`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::fit::Parametrization;
    /// // A 3-4-5 triangle: chords 3, 4 and the closing 5.
    /// let q = [[0.0, 0.0], [3.0, 0.0], [3.0, 4.0]];
    /// assert_eq!(Parametrization::ChordLength.loop_parameters(&q)?, vec![0.0, 0.25, 7.0 / 12.0]);
    /// assert_eq!(Parametrization::Uniform.loop_parameters(&q)?, vec![0.0, 1.0 / 3.0, 2.0 / 3.0]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn loop_parameters<const D: usize>(self, points: &[[f64; D]]) -> Result<Vec<f64>, Error> {
        let n = points.len();
        if n < 2 {
            return Err(Error::TooFewDataPoints {
                degree: 1,
                count: n,
            });
        }
        if self == Parametrization::Uniform {
            return Ok((0..n).map(|k| k as f64 / n as f64).collect());
        }
        // ū_N = d/d = 1 closes the loop; it is not returned.
        let mut u = self.chord_parameters(points, (0..n).map(|k| (k, (k + 1) % n)))?;
        u.truncate(n);
        Ok(u)
    }
}

impl fmt::Display for Parametrization {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Parametrization {
    type Err = String;

    /// Accepts the [`Parametrization::name`]s and `chord-length`.
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "chord" | "chord-length" => Ok(Parametrization::ChordLength),
            "centripetal" => Ok(Parametrization::Centripetal),
            "uniform" => Ok(Parametrization::Uniform),
            _ => Err(format!(
                "unknown parametrization `{s}` (known: chord, centripetal, uniform)"
            )),
        }
    }
}

/// Euclidean distance, without overflow for large coordinates.
fn distance<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| x - y)
        .fold(0.0, |acc: f64, d| acc.hypot(d))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_start_at_zero_end_at_one_and_increase() {
        let q = [
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 2.0],
            [1.0, 2.0, 2.5],
            [9.0, 2.0, 2.5],
        ];
        for method in Parametrization::ALL {
            let u = method.parameters(&q).unwrap();
            assert_eq!((u[0], u[3]), (0.0, 1.0), "{method}");
            assert!(u.windows(2).all(|w| w[0] < w[1]), "{method}: {u:?}");
        }
        // Chords 3, 0.5, 8.
        let u = Parametrization::ChordLength.parameters(&q).unwrap();
        assert_eq!(u, vec![0.0, 3.0 / 11.5, 3.5 / 11.5, 1.0]);
    }

    #[test]
    fn coincident_neighbours_are_named() {
        let q = [[0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]];
        assert_eq!(
            Parametrization::ChordLength.parameters(&q),
            Err(Error::CoincidentDataPoints {
                first: 1,
                second: 2
            })
        );
        assert!(Parametrization::Centripetal.parameters(&q).is_err());
        // Uniform parameters do not look at the geometry.
        assert!(Parametrization::Uniform.parameters(&q).is_ok());
    }

    #[test]
    fn loop_parameters_count_the_closing_chord() {
        // A unit square: four equal chords, the closing one included.
        let q = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        for method in Parametrization::ALL {
            assert_eq!(
                method.loop_parameters(&q).unwrap(),
                vec![0.0, 0.25, 0.5, 0.75],
                "{method}"
            );
        }
        // The closing pair is named when it coincides.
        let q = [[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]];
        assert_eq!(
            Parametrization::ChordLength.loop_parameters(&q),
            Err(Error::CoincidentDataPoints {
                first: 2,
                second: 0
            })
        );
    }

    #[test]
    fn names_round_trip() {
        for method in Parametrization::ALL {
            assert_eq!(method.name().parse(), Ok(method));
        }
        assert_eq!("chord-length".parse(), Ok(Parametrization::ChordLength));
        assert!("chordal".parse::<Parametrization>().is_err());
    }
}
