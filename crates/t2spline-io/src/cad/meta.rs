//! What a CAD file says about itself: name, description, time and unit.

use t2spline::job::LengthUnit;

use super::clock;

/// What a CAD file says about itself.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CadMeta {
    /// The file's name (STEP `FILE_NAME`, IGES global section).
    pub name: String,
    /// The job's description, if any.
    pub description: Option<String>,
    /// When the file was written, as `YYYY-MM-DDThh:mm:ss` (UTC).
    pub timestamp: String,
    /// The unit of the coordinates, which the file records (DXF
    /// `$INSUNITS`, the STEP context's length unit, the IGES unit flag, an
    /// OBJ comment); the numbers are written as they are.
    pub units: LengthUnit,
}

impl CadMeta {
    /// The header of a file named `name` written now (or at
    /// `SOURCE_DATE_EPOCH`, seconds since 1970, when set) of a job with
    /// `description`, its coordinates in `units`.
    #[must_use]
    pub fn now(name: String, description: Option<String>, units: LengthUnit) -> CadMeta {
        CadMeta {
            name,
            description,
            timestamp: clock::timestamp(),
            units,
        }
    }
}
