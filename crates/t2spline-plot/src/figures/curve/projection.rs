//! The pairs of coordinates a curve figure draws, one panel each, and points
//! projected to them.

use t2spline::job::Points;

use crate::chart::scene::{Panel, Xy};
use crate::figures::aspect::Aspect;

const AXIS_NAMES: [&str; 3] = ["x", "y", "z"];

/// A pair of coordinates drawn in one panel: `(x, y)` in 2-D, each of the
/// three pairs in 3-D.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Projection {
    /// The coordinates on the horizontal and the vertical axis.
    pub axes: (usize, usize),
    /// Whether the panel says which projection it shows (3-D).
    titled: bool,
}

impl Projection {
    /// The projection to `axes`, titled or not.
    #[must_use]
    pub fn new(axes: (usize, usize), titled: bool) -> Projection {
        Projection { axes, titled }
    }

    /// "x–z".
    #[must_use]
    pub fn name(&self) -> String {
        format!("{}–{}", AXIS_NAMES[self.axes.0], AXIS_NAMES[self.axes.1])
    }

    /// An empty panel for this projection.
    #[must_use]
    pub fn panel(&self, aspect: Aspect) -> Panel {
        let (i, j) = self.axes;
        let mut p = match aspect {
            Aspect::Equal => Panel::curves(AXIS_NAMES[i], AXIS_NAMES[j]),
            Aspect::Auto => Panel::graph(AXIS_NAMES[i], AXIS_NAMES[j]),
        };
        if self.titled {
            p.title = Some(format!("{} projection", self.name()));
        }
        p
    }
}

/// The projections drawn for points of `dimension` coordinates.
#[must_use]
pub fn projections(dimension: usize) -> Vec<Projection> {
    if dimension >= 3 {
        [(0, 1), (0, 2), (1, 2)]
            .into_iter()
            .map(|ij| Projection::new(ij, true))
            .collect()
    } else {
        vec![Projection::new((0, 1), false)]
    }
}

/// Points projected to the coordinates `(i, j)`.
#[must_use]
pub fn project(points: &Points, (i, j): (usize, usize)) -> Vec<Xy> {
    points
        .coord(i)
        .iter()
        .zip(points.coord(j))
        .map(|(&x, &y)| [x, y])
        .collect()
}

/// The area between two curves: one forwards, the other backwards (the
/// type-reduced curves' band; not a region of the curve).
#[must_use]
pub fn band(a: &Points, b: &Points, ij: (usize, usize)) -> Vec<Xy> {
    let mut poly = project(a, ij);
    poly.extend(project(b, ij).into_iter().rev());
    poly
}
