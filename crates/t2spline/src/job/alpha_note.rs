//! What a front end says about the alpha of a run, in one place: an alpha
//! given to a type reduction that does not use it (docs/method.md §9), and
//! an alpha a few ulps above a lower height ([`NearHeight`], §3). Each front
//! end spells where the alpha came from (`--alpha 0.3`, `alpha=0.3`, `the
//! job's alpha 0.3`) and what it still does in its command; the words
//! around them are these.

use std::fmt;

use super::near_height::NearHeight;
use super::settings::Settings;
use crate::fuzzy::Alpha;
use crate::reduction::TypeReduction;

/// What an alpha that the type reduction does not use does in a run:
/// nothing (stage 2 is shown at level 0).
pub const ALPHA_IGNORED: &str = "is ignored (stage 2 is cut at alpha = 0, the whole footprint)";

/// That `reduction` does not use alpha: `type reduction centroid does not
/// use alpha`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnusedBy(pub TypeReduction);

impl fmt::Display for UnusedBy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "type reduction {} does not use alpha", self.0)
    }
}

/// A note on the alpha of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AlphaNote {
    /// The type reduction does not use the alpha given.
    Unused {
        /// The type reduction.
        reduction: TypeReduction,
        /// The alpha given.
        alpha: Alpha,
    },
    /// Alpha lies a few ulps above a lower height.
    NearHeight(NearHeight),
}

impl AlphaNote {
    /// The note as one sentence: `source` names where the alpha came from,
    /// as the front end spells it (`--alpha`, `alpha=`, `the job's alpha`),
    /// and `effect` says what it still does in the command (for a run,
    /// [`ALPHA_IGNORED`]).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::job::{AlphaNote, ALPHA_IGNORED};
    /// # use t2spline::{Alpha, TypeReduction};
    /// let note = AlphaNote::Unused { reduction: TypeReduction::Centroid, alpha: Alpha::try_new(0.3)? };
    /// assert_eq!(
    ///     note.sentence("--alpha ", ALPHA_IGNORED),
    ///     "type reduction centroid does not use alpha; --alpha 0.3 is ignored (stage 2 is cut at alpha = 0, the whole footprint)"
    /// );
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn sentence(&self, source: &str, effect: &str) -> String {
        match self {
            AlphaNote::Unused { reduction, alpha } => {
                format!("{}; {source}{} {effect}", UnusedBy(*reduction), alpha.get())
            }
            AlphaNote::NearHeight(near) => near.to_string(),
        }
    }
}

impl Settings {
    /// The notes on this run's alpha, in the order front ends say them:
    /// an alpha the type reduction does not use, then an alpha just above a
    /// lower height (the two never come together: only the paper's
    /// reduction uses alpha).
    #[must_use]
    pub fn alpha_notes(&self) -> Vec<AlphaNote> {
        let unused = self.unused_alpha().map(|alpha| AlphaNote::Unused {
            reduction: self.type_reduction(),
            alpha,
        });
        unused
            .into_iter()
            .chain(self.near_height().map(AlphaNote::NearHeight))
            .collect()
    }
}
