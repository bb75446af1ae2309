//! The unit of length of a job's coordinates (docs/jobs.md, the key
//! `units`): a label that files which record one (CAD) carry. Nothing is
//! scaled: the numbers stay the job's.

/// A unit of length.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum LengthUnit {
    /// Millimetres (`mm`), the default of CAD files.
    #[default]
    Millimetre,
    /// Centimetres (`cm`).
    Centimetre,
    /// Metres (`m`).
    Metre,
    /// Inches (`in`), 25.4 mm.
    Inch,
    /// Feet (`ft`), 304.8 mm.
    Foot,
}

impl LengthUnit {
    /// Every unit, in the order of docs/jobs.md.
    pub const ALL: [LengthUnit; 5] = [
        LengthUnit::Millimetre,
        LengthUnit::Centimetre,
        LengthUnit::Metre,
        LengthUnit::Inch,
        LengthUnit::Foot,
    ];

    /// The name in a job and on the command line: `mm`, `cm`, `m`, `in`,
    /// `ft`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LengthUnit::Millimetre => "mm",
            LengthUnit::Centimetre => "cm",
            LengthUnit::Metre => "m",
            LengthUnit::Inch => "in",
            LengthUnit::Foot => "ft",
        }
    }

    /// The unit named `name` (as [`LengthUnit::name`] writes it).
    ///
    /// ```
    /// # use t2spline::job::LengthUnit;
    /// assert_eq!(LengthUnit::named("ft"), Some(LengthUnit::Foot));
    /// assert_eq!(LengthUnit::named("feet"), None);
    /// ```
    #[must_use]
    pub fn named(name: &str) -> Option<LengthUnit> {
        LengthUnit::ALL.into_iter().find(|u| u.name() == name)
    }

    /// The unit's length in millimetres.
    #[must_use]
    pub fn millimetres(self) -> f64 {
        match self {
            LengthUnit::Millimetre => 1.0,
            LengthUnit::Centimetre => 10.0,
            LengthUnit::Metre => 1000.0,
            LengthUnit::Inch => 25.4,
            LengthUnit::Foot => 304.8,
        }
    }

    /// The names of every unit, for messages: `mm, cm, m, in, ft`.
    #[must_use]
    pub fn names() -> String {
        LengthUnit::ALL.map(LengthUnit::name).join(", ")
    }
}
