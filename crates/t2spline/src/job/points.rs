//! Points of a run's output as structure of arrays, whatever their dimension.

use crate::sampling::{CurveSamples, SampleBuffer};
use crate::vector::euclidean_norm;

/// Points of one dimension stored as one vector per coordinate (structure of
/// arrays): `coord(0)[i]` is the x coordinate of the i-th point.
///
/// This is the form in which a run hands control points and samples to the
/// writers (JSON, CSV), the figures and the Python bindings: the sampling
/// engine produces it without copies, columnar formats write it as it is, and
/// a point at a time is one index per coordinate.
///
/// `T` is `f64`, or `Option<f64>` for the alpha-cut control points, whose lower
/// ends are absent above a number's lower height (docs/method.md §2).
///
/// # Examples
/// ```
/// # use t2spline::job::Points;
/// let p = Points::from_points(&[[0.0, 1.0], [2.0, 3.0]]);
/// assert_eq!((p.len(), p.dimension()), (2, 2));
/// assert_eq!(p.coord(1), &[1.0, 3.0]);
/// assert_eq!(p.point(1), Some(vec![2.0, 3.0]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Points<T = f64> {
    coords: Vec<Vec<T>>,
    /// `Some([rows, columns])` when the points form a grid (a surface's net
    /// or samples), stored row by row: point `(a, b)` is at `a·columns + b`.
    grid: Option<[usize; 2]>,
}

impl<T: Copy> Points<T> {
    /// Points from one vector per coordinate, all of one length (checked in
    /// debug builds: only the crate builds them).
    pub(crate) fn from_coords(coords: Vec<Vec<T>>) -> Self {
        debug_assert!(coords
            .iter()
            .all(|c| Some(c.len()) == coords.first().map(Vec::len)));
        Points { coords, grid: None }
    }

    /// The same points seen as a grid of `rows × columns`, stored row by row
    /// (only the crate builds grids, from samples of that shape).
    pub(crate) fn into_grid(self, [rows, columns]: [usize; 2]) -> Self {
        debug_assert_eq!(rows * columns, self.len());
        Points {
            grid: Some([rows, columns]),
            ..self
        }
    }

    /// Points from a list of fixed-size points.
    #[must_use]
    pub fn from_points<const D: usize>(points: &[[T; D]]) -> Self {
        Points {
            coords: (0..D)
                .map(|d| points.iter().filter_map(|p| p.get(d).copied()).collect())
                .collect(),
            grid: None,
        }
    }

    /// `Some([rows, columns])` when the points form a grid (the control net or
    /// the samples of a surface, point `(a, b)` at index `a·columns + b`),
    /// `None` for a list.
    #[must_use]
    pub fn grid(&self) -> Option<[usize; 2]> {
        self.grid
    }

    /// The number of points.
    #[must_use]
    pub fn len(&self) -> usize {
        self.coords.first().map_or(0, Vec::len)
    }

    /// Whether there are no points.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of coordinates of each point.
    #[must_use]
    pub fn dimension(&self) -> usize {
        self.coords.len()
    }

    /// The values of one coordinate (`0` is x); empty for an axis the points
    /// do not have.
    #[must_use]
    pub fn coord(&self, axis: usize) -> &[T] {
        self.coords.get(axis).map_or(&[], Vec::as_slice)
    }

    /// The values of one coordinate, to change in place; empty for an axis the
    /// points do not have.
    pub fn coord_mut(&mut self, axis: usize) -> &mut [T] {
        self.coords.get_mut(axis).map_or(&mut [], Vec::as_mut_slice)
    }

    /// The vectors of all coordinates.
    #[must_use]
    pub fn coords(&self) -> &[Vec<T>] {
        &self.coords
    }

    /// The i-th point, or `None` past the end.
    #[must_use]
    pub fn point(&self, i: usize) -> Option<Vec<T>> {
        self.coords.iter().map(|c| c.get(i).copied()).collect()
    }

    /// The points in order, each as a vector of coordinates.
    pub fn rows(&self) -> impl ExactSizeIterator<Item = Vec<T>> + '_ {
        // Every coordinate has `len()` values (the constructors' invariant).
        (0..self.len()).map(|i| {
            self.coords
                .iter()
                .filter_map(|c| c.get(i).copied())
                .collect()
        })
    }
}

impl<const D: usize> From<CurveSamples<D>> for Points {
    /// Takes the sampling engine's buffers, without copying those that are
    /// ordinary vectors (a run samples into such).
    fn from(samples: CurveSamples<D>) -> Self {
        Points::from_coords(
            samples
                .into_coords()
                .into_iter()
                .map(SampleBuffer::into_vec)
                .collect(),
        )
    }
}

impl<T> Points<T> {
    /// The index range of row `a` of a grid: point `(a, b)` is at index
    /// `start + b`; all points for a list.
    #[must_use]
    pub fn row_range(&self, a: usize) -> std::ops::Range<usize> {
        match self.grid {
            Some([_, columns]) => a * columns..(a + 1) * columns,
            None => 0..self.coords.first().map_or(0, Vec::len),
        }
    }
}

impl Points {
    /// The name under which [`Points`] serialize as a newtype struct (feature
    /// `serde`). JSON writers treat a newtype as its content, so result files
    /// are unchanged; a serializer that builds arrays (the Python bindings
    /// build numpy arrays) recognises point lists by this name.
    pub const SERDE_NAME: &'static str = "t2spline::Points";

    /// The Euclidean distance between point `i` of these points and point `i`
    /// of `other` (over the coordinates both have, at most three), scaled so
    /// that neither a distance near 1e-170 underflows nor one near 1e300
    /// overflows when squared ([`euclidean_norm`]): the `distance` column of
    /// the tables of a run, between the crisp and the defuzzified curve.
    /// `None` if `i` is past the end of either.
    #[must_use]
    pub fn distance_at(&self, other: &Points, i: usize) -> Option<f64> {
        let mut d = [0.0; 3];
        let mut dims = 0;
        for ((a, b), slot) in self.coords.iter().zip(&other.coords).zip(&mut d) {
            *slot = a.get(i)? - b.get(i)?;
            dims += 1;
        }
        Some(euclidean_norm(d.get(..dims)?))
    }
}

#[cfg(feature = "serde")]
impl<T: serde::Serialize + Copy> serde::Serialize for Points<T> {
    /// A list of points, each a list of coordinates (`[[x, y], …]`), or for a
    /// grid a list of rows of points (`[[[x, y, z], …], …]`), written straight
    /// from the columns, as the newtype struct [`Points::SERDE_NAME`].
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_newtype_struct(Points::SERDE_NAME, &Shaped(self))
    }
}

/// The points as nested lists: of points, or of rows of points.
#[cfg(feature = "serde")]
struct Shaped<'a, T>(&'a Points<T>);

#[cfg(feature = "serde")]
impl<T: serde::Serialize + Copy> serde::Serialize for Shaped<'_, T> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeSeq;
        /// One point: its coordinates.
        struct Point<'a, T>(&'a [Vec<T>], usize);
        impl<T: serde::Serialize> serde::Serialize for Point<'_, T> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut seq = s.serialize_seq(Some(self.0.len()))?;
                // Every coordinate has a value at every index of the points.
                for v in self.0.iter().filter_map(|c| c.get(self.1)) {
                    seq.serialize_element(v)?;
                }
                seq.end()
            }
        }
        /// The points of an index range.
        struct Run<'a, T>(&'a [Vec<T>], std::ops::Range<usize>);
        impl<T: serde::Serialize> serde::Serialize for Run<'_, T> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut seq = s.serialize_seq(Some(self.1.len()))?;
                for i in self.1.clone() {
                    seq.serialize_element(&Point(self.0, i))?;
                }
                seq.end()
            }
        }
        match self.0.grid {
            None => Run(&self.0.coords, self.0.row_range(0)).serialize(s),
            Some([rows, _]) => {
                let mut seq = s.serialize_seq(Some(rows))?;
                for a in 0..rows {
                    seq.serialize_element(&Run(&self.0.coords, self.0.row_range(a)))?;
                }
                seq.end()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_and_columns_agree() {
        let p = Points::from_points(&[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
        assert_eq!(p.dimension(), 3);
        assert_eq!(
            p.rows().collect::<Vec<_>>(),
            [vec![1.0, 2.0, 3.0], vec![4.0, 5.0, 6.0]]
        );
        assert_eq!(p.coord(2), &[3.0, 6.0]);
        assert!(p.coord(3).is_empty());
        assert_eq!(p.point(2), None);
    }

    #[test]
    fn a_grid_keeps_its_rows() {
        let p = Points::from_points(&[
            [1.0, 2.0],
            [3.0, 4.0],
            [5.0, 6.0],
            [7.0, 8.0],
            [9.0, 0.0],
            [1.0, 1.0],
        ])
        .into_grid([2, 3]);
        assert_eq!(p.grid(), Some([2, 3]));
        assert_eq!(p.row_range(1), 3..6);
        assert_eq!(p.point(4), Some(vec![9.0, 0.0]));
    }

    #[test]
    fn empty_points() {
        let p = Points::<f64>::from_points::<2>(&[]);
        assert!(p.is_empty());
        assert_eq!(p.rows().count(), 0);
    }
}
