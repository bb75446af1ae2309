//! The two directions of a surface fit: the options of each, the parameters
//! of a net of data points averaged over its rows and columns (The NURBS
//! Book §9.2.5, Algorithm A9.3), and the tensor-product fit as curve fits in
//! one direction, then the other (Algorithms A9.4 and A9.7).

use crate::error::{Error, Setting};
use crate::fit::design::Design;
use crate::fit::knots::{approximation_knots, averaging_knots, check_counts};
use crate::fit::Parametrization;
use crate::nurbs::surface::net_shape;
use crate::nurbs::KnotVector;
use crate::place::Direction;

/// What to fit to a net of data points `Q[k][l]` (`k` along u, `l` along v):
/// the degree in each direction, how the rows and columns get their
/// parameters, and whether the surface interpolates the net or approximates
/// it with fewer control points; checked once, when made
/// ([`SurfaceFitOptions::new`]): the fields are private. What needs the net
/// (enough rows and columns for the degrees and the control points) is
/// checked by the fit.
///
/// # Examples
/// ```
/// # use t2spline::fit::{Parametrization, SurfaceFitOptions};
/// let o = SurfaceFitOptions::interpolation([3, 2])?;
/// assert_eq!((o.degree(), o.control_points(), o.parametrization()), ([3, 2], None, Parametrization::ChordLength));
/// assert_eq!(SurfaceFitOptions::approximation([3, 3], [8, 6])?.control_points(), Some([8, 6]));
/// assert!(SurfaceFitOptions::approximation([3, 3], [8, 3]).is_err()); // fewer than q + 1 along v
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SurfaceFitOptions {
    degree: [usize; 2],
    parametrization: Parametrization,
    control_points: Option<[usize; 2]>,
}

impl SurfaceFitOptions {
    /// A fit of degrees `degree = [p, q]` in u and in v, chord-length
    /// parameters: with `control_points` `None`, interpolation, one control
    /// point per data point (A9.4); with `Some([n, m])`, least squares with
    /// `n × m` control points, the boundary curves' end points interpolated
    /// (A9.7), each count at most the data along its direction (checked by
    /// the fit).
    ///
    /// # Errors
    /// [`Error::Setting`]: [`Setting::Degree`] for degree 0 in a direction;
    /// [`Setting::ControlPoints`] for fewer control points in a direction
    /// than its degree + 1.
    pub fn new(degree: [usize; 2], control_points: Option<[usize; 2]>) -> Result<Self, Error> {
        for (d, direction) in ["u", "v"].into_iter().enumerate() {
            if degree[d] == 0 {
                return Err(Error::Setting {
                    setting: Setting::Degree,
                    message: format!("0 along {direction} is outside 1 ..: a piecewise-constant surface does not pass through its data"),
                });
            }
            if let Some(n) = control_points.map(|c| c[d]).filter(|&n| n <= degree[d]) {
                return Err(Error::Setting {
                    setting: Setting::ControlPoints,
                    message: format!(
                        "{n} along {direction} is fewer than degree + 1 (the degree is {})",
                        degree[d]
                    ),
                });
            }
        }
        Ok(SurfaceFitOptions {
            degree,
            parametrization: Parametrization::ChordLength,
            control_points,
        })
    }

    /// Interpolation of degrees `degree` ([`SurfaceFitOptions::new`] with no
    /// counts).
    ///
    /// # Errors
    /// As [`SurfaceFitOptions::new`].
    pub fn interpolation(degree: [usize; 2]) -> Result<Self, Error> {
        SurfaceFitOptions::new(degree, None)
    }

    /// Least squares of degrees `degree` with `control_points` control
    /// points in u and in v ([`SurfaceFitOptions::new`]).
    ///
    /// # Errors
    /// As [`SurfaceFitOptions::new`].
    pub fn approximation(degree: [usize; 2], control_points: [usize; 2]) -> Result<Self, Error> {
        SurfaceFitOptions::new(degree, Some(control_points))
    }

    /// The same options with another parametrization.
    #[must_use]
    pub fn with_parametrization(self, parametrization: Parametrization) -> Self {
        SurfaceFitOptions {
            parametrization,
            ..self
        }
    }

    /// The degrees `[p, q] ≥ 1` in u and in v.
    #[must_use]
    pub fn degree(&self) -> [usize; 2] {
        self.degree
    }

    /// How the rows and columns of the net get their parameters; the
    /// parameters of a direction are the average over the lines of the net
    /// in that direction (A9.3).
    #[must_use]
    pub fn parametrization(&self) -> Parametrization {
        self.parametrization
    }

    /// `None`: interpolate (A9.4). `Some([n, m])`: least squares with
    /// `n × m` control points (A9.7).
    #[must_use]
    pub fn control_points(&self) -> Option<[usize; 2]> {
        self.control_points
    }

    /// The parameters of the net's rows (`u`) and columns (`v`) and the knot
    /// vectors of the fit in each direction: averaging knots (Eq. 9.8) for
    /// interpolation, Eqs. 9.68–9.69 for fewer control points than data.
    ///
    /// # Errors
    /// As [`fit_surface`](crate::fit::fit_surface).
    pub fn parameters_and_knots(
        &self,
        net: &[Vec<[f64; 3]>],
    ) -> Result<[(Vec<f64>, KnotVector); 2], Error> {
        let shape = net_shape(net, "points")?;
        let direction = |direction: Direction| {
            let d = direction.index();
            let in_direction = |e: Error| e.in_direction(direction);
            check_counts(shape[d], self.degree[d]).map_err(in_direction)?;
            let params = net_parameters(net, shape, direction, self.parametrization)?;
            let knots = match self.control_points {
                Some(count) if count[d] != shape[d] => {
                    approximation_knots(&params, self.degree[d], count[d])
                }
                _ => averaging_knots(&params, self.degree[d]),
            }
            .map_err(in_direction)?;
            Ok((params, knots))
        };
        Ok([direction(Direction::U)?, direction(Direction::V)?])
    }
}

/// The parameters of the lines of `net` in `direction`, averaged (A9.3):
///
/// ```text
/// ū_k = (1/L) Σ_l ū_k^l,   ū^l the parameters of the column l (Eqs. 9.3–9.6)
/// ```
/// over the `L` lines of non-zero length (a line whose points all coincide,
/// as at a pole, says nothing of the spacing and is left out).
///
/// # Errors
/// [`Error::InDirection`] wrapping [`Error::CoincidentDataPoints`] when two
/// neighbouring rows (columns) get the same averaged parameter, or every
/// line has length 0; [`Error::NotFinite`] if a line's length overflows.
fn net_parameters(
    net: &[Vec<[f64; 3]>],
    [rows, columns]: [usize; 2],
    direction: Direction,
    method: Parametrization,
) -> Result<Vec<f64>, Error> {
    let (count, lines) = match direction {
        Direction::U => (rows, columns),
        Direction::V => (columns, rows),
    };
    let at = |line: usize, k: usize| match direction {
        Direction::U => net[k][line],
        Direction::V => net[line][k],
    };
    let m = count - 1;
    if method == Parametrization::Uniform {
        return Ok((0..=m).map(|k| k as f64 / m as f64).collect());
    }
    let mut sum = vec![0.0; count];
    let mut used = 0usize;
    let mut line_params = vec![0.0; count];
    for line in 0..lines {
        let mut total = 0.0;
        for (k, partial) in line_params.iter_mut().enumerate() {
            if k > 0 {
                let chord = distance(&at(line, k - 1), &at(line, k));
                total += match method {
                    Parametrization::Centripetal => chord.sqrt(),
                    _ => chord,
                };
            }
            *partial = total;
        }
        if !total.is_finite() {
            return Err(Error::NotFinite {
                place: crate::Place::NONE,
                what: "total chord length",
                value: total,
            });
        }
        if total > 0.0 {
            used += 1;
            for (s, p) in sum.iter_mut().zip(&line_params) {
                *s += p / total;
            }
        }
    }
    let coincident = |first: usize| {
        Error::CoincidentDataPoints {
            first,
            second: first + 1,
        }
        .in_direction(direction)
    };
    if used == 0 {
        return Err(coincident(0));
    }
    let mut params: Vec<f64> = sum.into_iter().map(|s| s / used as f64).collect();
    // Exactly 0 and 1 at the ends, as the clamped knots need.
    params[0] = 0.0;
    params[m] = 1.0;
    match params.windows(2).position(|w| w[0] >= w[1]) {
        Some(k) => Err(coincident(k)),
        None => Ok(params),
    }
}

/// Euclidean distance, without overflow for large coordinates.
fn distance(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| x - y)
        .fold(0.0, |acc: f64, d| acc.hypot(d))
}

/// The tensor-product fit of a net: a curve fit along u of every column of
/// data, then along v of every row of the intermediate control points (The
/// NURBS Book A9.4 for interpolation, A9.7 for least squares). Both fits are
/// linear maps acting on different indices, so the order of the two passes
/// does not change the result, and the surface's values at the data
/// parameters are `N_u · P · N_vᵀ`.
#[derive(Clone, Debug)]
pub(crate) struct NetDesign {
    u: Design,
    v: Design,
}

impl NetDesign {
    /// The designs of the two directions.
    ///
    /// # Errors
    /// The errors of [`Design::new`], in their direction.
    pub(crate) fn new(directions: &[(Vec<f64>, KnotVector); 2]) -> Result<Self, Error> {
        let [(pu, ku), (pv, kv)] = directions;
        Ok(NetDesign {
            u: Design::new(pu, ku).map_err(|e| e.in_direction(Direction::U))?,
            v: Design::new(pv, kv).map_err(|e| e.in_direction(Direction::V))?,
        })
    }

    /// The larger of the two directions' condition numbers (the condition
    /// number of the tensor system is their product; each pass solves one
    /// direction's system).
    pub(crate) fn condition(&self) -> f64 {
        self.u.condition().max(self.v.condition())
    }

    /// The control points in u and in v.
    pub(crate) fn counts(&self) -> [usize; 2] {
        [self.u.count(), self.v.count()]
    }

    /// Control values fitting `q[k][l]`, by `fit` along u of every column,
    /// then along v of every intermediate row.
    fn passes<T: Copy>(
        &self,
        q: &[Vec<T>],
        fit: impl Fn(&Design, &[T]) -> Result<Vec<T>, Error>,
    ) -> Result<Vec<Vec<T>>, Error> {
        let columns = q.first().map_or(0, Vec::len);
        let mut middle: Vec<Vec<T>> = Vec::with_capacity(columns);
        for l in 0..columns {
            let column: Vec<T> = q.iter().map(|row| row[l]).collect();
            middle.push(fit(&self.u, &column).map_err(|e| e.in_direction(Direction::U))?);
        }
        // `middle[l][i]`: column l's control values; the rows of the
        // intermediate net are `middle[·][i]`.
        (0..self.u.count())
            .map(|i| {
                let row: Vec<T> = middle.iter().map(|c| c[i]).collect();
                fit(&self.v, &row).map_err(|e| e.in_direction(Direction::V))
            })
            .collect()
    }

    /// Control values fitting `q` (exact interpolation with one control
    /// point per data point).
    ///
    /// # Errors
    /// [`Error::SingularFit`] in the direction whose data do not determine
    /// the control values.
    pub(crate) fn fit<const R: usize>(
        &self,
        q: &[Vec<[f64; R]>],
    ) -> Result<Vec<Vec<[f64; R]>>, Error> {
        self.passes(q, |design, line| design.fit(line))
    }

    /// Non-negative control values approximating `q`: each pass a
    /// non-negative least-squares curve fit ([`Design::fit_nonnegative`]),
    /// so the intermediate values and the result are `≥ 0`, and so are the
    /// surface's values (the basis is non-negative). Returns the plain fit
    /// when that is already non-negative everywhere.
    ///
    /// # Errors
    /// As [`NetDesign::fit`].
    pub(crate) fn fit_nonnegative(&self, q: &[Vec<f64>]) -> Result<Vec<Vec<f64>>, Error> {
        let wrapped: Vec<Vec<[f64; 1]>> =
            q.iter().map(|r| r.iter().map(|&x| [x]).collect()).collect();
        let plain = self.fit(&wrapped)?;
        if plain.iter().flatten().all(|v| v[0] >= 0.0) {
            return Ok(plain
                .into_iter()
                .map(|r| r.into_iter().map(|v| v[0]).collect())
                .collect());
        }
        self.passes(q, |design, line| design.fit_nonnegative(line))
    }

    /// The surface's values `Σᵢⱼ Nᵢ(ū_k) Nⱼ(v̄_l) Pᵢⱼ` at every data parameter
    /// pair.
    pub(crate) fn values<const R: usize>(&self, control: &[Vec<[f64; R]>]) -> Vec<Vec<[f64; R]>> {
        let nv = control.first().map_or(0, Vec::len);
        // Along u first: for each control column j, its curve at every ū_k.
        let along_u: Vec<Vec<[f64; R]>> = (0..nv)
            .map(|j| {
                let column: Vec<[f64; R]> = control.iter().map(|row| row[j]).collect();
                self.u.values(&column)
            })
            .collect();
        let stations_u = along_u.first().map_or(0, Vec::len);
        (0..stations_u)
            .map(|k| {
                let row: Vec<[f64; R]> = along_u.iter().map(|c| c[k]).collect();
                self.v.values(&row)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(rows: usize, columns: usize, f: impl Fn(f64, f64) -> f64) -> Vec<Vec<[f64; 3]>> {
        (0..rows)
            .map(|i| {
                (0..columns)
                    .map(|j| {
                        let (x, y) = (
                            i as f64 / (rows - 1) as f64,
                            (j as f64 / (columns - 1) as f64).powi(2),
                        );
                        [x, y, f(x, y)]
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn averaged_parameters_of_a_flat_grid_are_its_spacing() {
        let net = grid(4, 5, |_, _| 0.0);
        let [(u, _), (v, _)] = SurfaceFitOptions::interpolation([2, 2])
            .unwrap()
            .parameters_and_knots(&net)
            .unwrap();
        for (k, uk) in u.iter().enumerate() {
            assert!((uk - k as f64 / 3.0).abs() < 1e-15, "{u:?}");
        }
        // The columns are at y = (l/4)²: chord lengths proportional to it.
        for (l, vl) in v.iter().enumerate() {
            assert!((vl - (l as f64 / 4.0).powi(2)).abs() < 1e-15, "{v:?}");
        }
    }

    #[test]
    fn a_line_of_length_zero_is_left_out_of_the_average() {
        // Column 0 collapses to a point (a pole): the parameters along u come
        // from the other columns alone.
        let mut net = grid(4, 3, |x, _| x);
        for row in &mut net {
            row[0] = [0.0, 0.0, 0.0];
        }
        let u = net_parameters(&net, [4, 3], Direction::U, Parametrization::ChordLength).unwrap();
        for (k, uk) in u.iter().enumerate() {
            assert!((uk - k as f64 / 3.0).abs() < 1e-15, "{u:?}");
        }
    }

    #[test]
    fn coincident_rows_are_named_with_their_direction() {
        let mut net = grid(4, 3, |_, _| 0.0);
        net[2] = net[1].clone();
        let e =
            net_parameters(&net, [4, 3], Direction::U, Parametrization::ChordLength).unwrap_err();
        assert_eq!(
            e,
            Error::CoincidentDataPoints {
                first: 1,
                second: 2
            }
            .in_direction(Direction::U)
        );
    }
}
