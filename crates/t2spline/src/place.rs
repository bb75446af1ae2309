//! The names of places in a model that errors and messages carry: a
//! coordinate ([`Axis`]), one of the seven values ([`Layer`]), a direction of
//! a surface ([`Direction`]), a point's [`Place`] in a list or a net, and a
//! broken order of fitted values ([`OrderViolation`]). A leaf of the crate,
//! below the error type, so that the error type names them without importing
//! the modules that compute with them.

use std::fmt;

/// A coordinate axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Axis {
    /// The first coordinate.
    X,
    /// The second coordinate.
    Y,
    /// The third coordinate.
    Z,
}

impl Axis {
    /// The axes in order.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// The first `D` axes, for a `D` a constructor has checked
    /// ([`Axis::first`]); past the third every index names `z`, which no
    /// checked value reaches.
    pub(crate) fn of<const D: usize>() -> [Axis; D] {
        std::array::from_fn(|i| Axis::from_index(i).unwrap_or(Axis::Z))
    }

    /// The axis with this index (`0 → x`), if any.
    #[must_use]
    pub fn from_index(i: usize) -> Option<Axis> {
        Axis::ALL.get(i).copied()
    }

    /// Index of the coordinate (`x → 0`).
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The key used in job files: `"x"`, `"y"` or `"z"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
            Axis::Z => "z",
        }
    }
}

impl fmt::Display for Axis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One of the seven values of a normal type-2 fuzzy number, in docs/method.md §1 order.
///
/// A fuzzy curve has one *layer curve* per variant: the rational B-spline through
/// that value of every control point.
///
/// ```text
/// UpperLeft ≤ PrimaryLeft ≤ LowerLeft ≤ Crisp ≤ LowerRight ≤ PrimaryRight ≤ UpperRight
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Layer {
    /// Left foot of the upper membership function (paper: left-left).
    UpperLeft,
    /// Left foot of the primary membership function (paper: left).
    PrimaryLeft,
    /// Left foot of the lower membership function (paper: right-left).
    LowerLeft,
    /// The apex shared by all three triangles (paper: P).
    Crisp,
    /// Right foot of the lower membership function (paper: left-right).
    LowerRight,
    /// Right foot of the primary membership function (paper: right).
    PrimaryRight,
    /// Right foot of the upper membership function (paper: right-right).
    UpperRight,
}

impl Layer {
    /// All seven layers in docs/method.md §1 order.
    pub const ALL: [Layer; 7] = [
        Layer::UpperLeft,
        Layer::PrimaryLeft,
        Layer::LowerLeft,
        Layer::Crisp,
        Layer::LowerRight,
        Layer::PrimaryRight,
        Layer::UpperRight,
    ];

    /// Position in [`Layer::ALL`].
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The snake-case name used in job and result files (`"upper_left"`, ...).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Layer::UpperLeft => "upper_left",
            Layer::PrimaryLeft => "primary_left",
            Layer::LowerLeft => "lower_left",
            Layer::Crisp => "crisp",
            Layer::LowerRight => "lower_right",
            Layer::PrimaryRight => "primary_right",
            Layer::UpperRight => "upper_right",
        }
    }

    /// Whether this is an end of the lower membership function, which has no
    /// alpha-cut above its height (docs/method.md §2).
    #[must_use]
    pub fn is_lower(self) -> bool {
        matches!(self, Layer::LowerLeft | Layer::LowerRight)
    }
}

impl fmt::Display for Layer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A parameter direction of a surface: `U` runs along the rows of the net
/// (index `i`), `V` along the columns (index `j`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub enum Direction {
    /// The first parameter `u` (rows `i` of the net, knots `U`, degree `p`).
    U,
    /// The second parameter `v` (columns `j` of the net, knots `V`, degree `q`).
    V,
}

impl Direction {
    /// Both directions, `U` first.
    pub const BOTH: [Direction; 2] = [Direction::U, Direction::V];

    /// `0` for `U`, `1` for `V`: the index into `[u, v]` pairs.
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The other direction.
    #[must_use]
    pub fn other(self) -> Direction {
        match self {
            Direction::U => Direction::V,
            Direction::V => Direction::U,
        }
    }
}

impl fmt::Display for Direction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Direction::U => "u",
            Direction::V => "v",
        })
    }
}

/// A fitted control point whose seven values break the order of docs/method.md §1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrderViolation {
    /// Index of the control point (0-based).
    pub control_point: usize,
    /// The coordinate.
    pub axis: Axis,
    /// The broken inequality, in the words of docs/method.md §1 (`"primary.left <= lower.left"`).
    pub rule: &'static str,
    /// The value on the left of the inequality.
    pub left: f64,
    /// The value on the right.
    pub right: f64,
}

impl fmt::Display for OrderViolation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "control point {}, {}: the order {} is broken: {} > {}",
            self.control_point, self.axis, self.rule, self.left, self.right
        )
    }
}

/// Where in a list (or a net) of fuzzy points a fault was found.
///
/// Displayed as a JSON-like path with a trailing `": "`, e.g. `points[2].y: `
/// for a curve, `points[2][1].y: ` for the net of a surface (row `2` along u,
/// column `1` along v), or as nothing at all when the place is unknown.
/// Indices are 0-based, as in the `points` array of a job file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Place {
    /// Index of the point (0-based), if known; in a net, the row.
    pub point: Option<usize>,
    /// In a net of a surface, the column within the row.
    pub column: Option<usize>,
    /// Coordinate within the point, if known.
    pub axis: Option<Axis>,
}

impl Place {
    /// No place known.
    pub const NONE: Place = Place {
        point: None,
        column: None,
        axis: None,
    };

    /// The place `points[point].axis`.
    #[must_use]
    pub fn new(point: usize, axis: Axis) -> Self {
        Place {
            point: Some(point),
            column: None,
            axis: Some(axis),
        }
    }

    /// The place `points[row][column].axis` in the net of a surface.
    ///
    /// ```
    /// # use t2spline::{Axis, Place};
    /// assert_eq!(Place::in_net(2, 1, Axis::Y).to_string(), "points[2][1].y: ");
    /// ```
    #[must_use]
    pub fn in_net(row: usize, column: usize, axis: Axis) -> Self {
        Place {
            point: Some(row),
            column: Some(column),
            axis: Some(axis),
        }
    }
}

impl fmt::Display for Place {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(i) = self.point {
            write!(f, "points[{i}]")?;
            if let Some(j) = self.column {
                write!(f, "[{j}]")?;
            }
            return match self.axis {
                Some(a) => write!(f, ".{a}: "),
                None => write!(f, ": "),
            };
        }
        match self.axis {
            Some(a) => write!(f, "{a}: "),
            None => Ok(()),
        }
    }
}
