//! What a CAD file says about itself: name, description, time and unit.

use t2spline::job::LengthUnit;

use super::clock;
use crate::error::{Error, Problem};

/// What a CAD file says about itself, checked once, when made
/// ([`CadMeta::new`], [`CadMeta::now`]): the fields are private, so the
/// timestamp every writer copies into its header has its one form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CadMeta {
    name: String,
    description: Option<String>,
    timestamp: String,
    units: LengthUnit,
}

impl CadMeta {
    /// The header of a file named `name` of a job with `description`,
    /// written at `timestamp` (`YYYY-MM-DDThh:mm:ss`, UTC), its coordinates
    /// in `units`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the file `name` if `timestamp` is not of
    /// the form `YYYY-MM-DDThh:mm:ss` (ASCII digits, month 01–12, day
    /// 01–31, hour 00–23, minute and second 00–59).
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::CadMeta;
    /// let meta = CadMeta::new("a.step".into(), None, "2026-01-02T03:04:05", Default::default())?;
    /// assert_eq!(meta.timestamp(), "2026-01-02T03:04:05");
    /// assert!(CadMeta::new("a.step".into(), None, "2026-01-02 03:04'", Default::default()).is_err());
    /// # Ok::<(), t2spline_io::Error>(())
    /// ```
    pub fn new(
        name: String,
        description: Option<String>,
        timestamp: &str,
        units: LengthUnit,
    ) -> Result<CadMeta, Error> {
        if !is_timestamp(timestamp) {
            return Err(Error::Invalid {
                file: name,
                problems: vec![Problem::new(format!(
                    "timestamp `{}` is not of the form YYYY-MM-DDThh:mm:ss",
                    crate::printable(timestamp)
                ))],
            });
        }
        Ok(CadMeta {
            name,
            description,
            timestamp: timestamp.to_owned(),
            units,
        })
    }

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

    /// The file's name (STEP `FILE_NAME`, IGES global section).
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The job's description, if any.
    #[must_use]
    pub fn description(&self) -> Option<&str> {
        self.description.as_deref()
    }

    /// When the file was written, as `YYYY-MM-DDThh:mm:ss` (UTC).
    #[must_use]
    pub fn timestamp(&self) -> &str {
        &self.timestamp
    }

    /// The unit of the coordinates, which the file records (DXF
    /// `$INSUNITS`, the STEP context's length unit, the IGES unit flag, an
    /// OBJ comment); the numbers are written as they are.
    #[must_use]
    pub fn units(&self) -> LengthUnit {
        self.units
    }
}

/// Whether `text` is `YYYY-MM-DDThh:mm:ss` with each field in its range.
fn is_timestamp(text: &str) -> bool {
    let b = text.as_bytes();
    let shape = b.len() == 19
        && b.iter().enumerate().all(|(i, &c)| match i {
            4 | 7 => c == b'-',
            10 => c == b'T',
            13 | 16 => c == b':',
            _ => c.is_ascii_digit(),
        });
    if !shape {
        return false;
    }
    let field = |at: usize| u32::from(b[at] - b'0') * 10 + u32::from(b[at + 1] - b'0');
    (1..=12).contains(&field(5))
        && (1..=31).contains(&field(8))
        && field(11) <= 23
        && field(14) <= 59
        && field(17) <= 59
}

#[cfg(test)]
mod tests {
    use super::is_timestamp;

    #[test]
    fn a_timestamp_has_one_form_and_its_fields_their_ranges() {
        for good in [
            "1970-01-01T00:00:00",
            "2026-12-31T23:59:59",
            "9999-09-09T09:09:09",
        ] {
            assert!(is_timestamp(good), "{good}");
        }
        for bad in [
            "",
            "2026-01-02 03:04:05",
            "2026-01-02T03:04:05Z",
            "2026-13-02T03:04:05",
            "2026-00-02T03:04:05",
            "2026-01-32T03:04:05",
            "2026-01-02T24:04:05",
            "2026-01-02T03:60:05",
            "2026-01-02T03:04:60",
            "2026-01-0'T03:04:05",
            "２０26-01-02T03:04",
        ] {
            assert!(!is_timestamp(bad), "{bad}");
        }
    }
}
