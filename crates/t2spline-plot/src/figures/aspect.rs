//! How the axes of curve panels (and the 3-D box of surfaces) are scaled.

/// How the axes of curve panels are scaled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Aspect {
    /// One data unit has the same length on both axes: shapes are true.
    #[default]
    Equal,
    /// Each axis fitted to its data: for elongated data (a profile 86 m long
    /// and 6 m high), whose spreads equal aspect shows as nothing.
    Auto,
}
