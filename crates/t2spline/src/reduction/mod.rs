//! Type reductions of one number: the paper's (docs/method.md §3–§4) and the type-2
//! literature's (docs/method.md §9), all exact; and the literature's discrete
//! algorithms for sets given by samples ([`discrete`]).
//!
//! | reduction | reads the number as | left, right | defuzzified | source |
//! |---|---|---|---|---|
//! | [`TypeReduction::Paper`] | three triangles cut at alpha | docs/method.md §3 | docs/method.md §4 | the paper, Defs. 4.3–4.4 |
//! | [`TypeReduction::Centroid`] | interval type-2 set (LMF..UMF) | `c_l`, `c_r` ([`Nt2Number::centroid`]) | `(c_l + c_r)/2` | Karnik and Mendel 2001 |
//! | [`TypeReduction::NieTan`] | interval type-2 set | the value | centroid of `(LMF + UMF)/2` ([`Nt2Number::nie_tan`]) | Nie and Tan 2008 |
//! | [`TypeReduction::AlphaPlanes`] | general type-2 set, triangular secondary membership | `c_l(0)`, `c_r(0)` | `∫ z·(c_l + c_r) dz` ([`Nt2Number::alpha_planes`]) | Liu 2008; Mendel, Liu and Zhai 2009 |
//!
//! Only the paper's reduction uses alpha. None of the others is centred on
//! `crisp`: for a number with unequal sides, `crisp` may lie outside
//! `[left, right]`, which is why their result is a [`Reduced`] and not a
//! [`Tfn`](crate::Tfn).
//!
//! # How the reductions enter a run
//!
//! A run reduces every coordinate of every control point with
//! [`Nt2Number::reduce`] (`pipeline/point_stages.rs`), so its stage-3 and
//! stage-4 control points are the numbers' reductions bit for bit, whatever the
//! reduction (tested on curves and surfaces). For the paper's reduction this
//! computes the cut a second time per number: a few flops, not worth a second
//! code path.
//!
//! Alpha belongs to the paper's reduction. With any other, a run cuts stage 2
//! at alpha = 0, the whole footprint that these reductions read; alpha may be
//! missing from the job, the result says `"alpha_used": false` and
//! `"regime": null`, and an alpha given anyway comes back as
//! `Settings::unused_alpha` for each front end to note (a command's note,
//! Python's `UserWarning`). Showing stage 2 at the given alpha would show a cut
//! that stages 3–4 do not read; refusing the alpha would refuse the shipped
//! example and most jobs written for the paper; ignoring it silently would not
//! tell a user comparing reductions that alpha no longer acts. Every result
//! names its reduction (`type_reduction`, `alpha_used`), the paper's too, so
//! that a reader of a file or of a Parquet table's metadata need not know the
//! default to tell runs apart.
//!
//! # Exact, not sampled
//!
//! A number's footprint is piecewise linear with breakpoints at its seven
//! values, so the Karnik–Mendel function
//! `F(c) = ∫_{x<c} (x − c)·UMF + ∫_{x>c} (x − c)·LMF` is a cubic on each piece
//! (`F'' = LMF − UMF`). `F` at the seven breakpoints (sums of trapezoid areas
//! and moments) picks the piece, and Newton's method inside a bisection
//! bracket solves its cubic to about one ulp in some six steps
//! (`footprint.rs` holds this machinery, in local coordinates). Karnik–Mendel on a fine
//! sampling, which type-2 libraries do, errs as `1/N²` and took 15 µs at
//! N = 1000 against 0.34 µs here; Cardano's formula on the piece is exact in
//! principle but cancels badly when the cubic is nearly linear, the common case
//! of a thin footprint. The discrete algorithms stay for sets a user brings
//! ([`discrete`]).
//!
//! [`Tfn`](crate::Tfn) keeps `left ≤ crisp ≤ right`, which the centroid of an
//! asymmetric number breaks; [`Reduced`] keeps `left ≤ defuzzified ≤ right`,
//! which all four reductions satisfy, and replaced `Tfn` as stage 3's type.

mod alpha_planes;
mod centroid;
pub mod discrete;
mod footprint;
mod nie_tan;
mod paper;

use std::fmt;
use std::str::FromStr;

pub use alpha_planes::{AlphaPlanes, ALPHA_PLANES_TOLERANCE};

use crate::fuzzy::{Alpha, Nt2Number};

/// Which type reduction turns a number into a type-1 result (docs/method.md §3, §9).
///
/// Its [`name`](TypeReduction::name) is the job file's `"type_reduction"`
/// value; [`FromStr`] reads it back.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum TypeReduction {
    /// The paper's reduction of the alpha-cut (docs/method.md §3–§4); the default.
    #[default]
    Paper,
    /// The interval type-2 centroid `[c_l, c_r]` (Karnik and Mendel 2001).
    Centroid,
    /// The centroid of `(LMF + UMF)/2` (Nie and Tan 2008).
    NieTan,
    /// The general type-2 reduction by alpha-planes (Liu 2008; Mendel, Liu
    /// and Zhai 2009).
    AlphaPlanes,
}

impl TypeReduction {
    /// Every reduction, in the order of docs/method.md §9.
    pub const ALL: [TypeReduction; 4] = [
        TypeReduction::Paper,
        TypeReduction::Centroid,
        TypeReduction::NieTan,
        TypeReduction::AlphaPlanes,
    ];

    /// The name in job files: `paper`, `centroid`, `nie-tan`, `alpha-planes`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            TypeReduction::Paper => "paper",
            TypeReduction::Centroid => "centroid",
            TypeReduction::NieTan => "nie-tan",
            TypeReduction::AlphaPlanes => "alpha-planes",
        }
    }

    /// Whether the reduction depends on alpha (only the paper's does).
    #[must_use]
    pub fn uses_alpha(self) -> bool {
        self == TypeReduction::Paper
    }
}

impl fmt::Display for TypeReduction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for TypeReduction {
    /// The [`TypeReduction::name`], as in job files.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl FromStr for TypeReduction {
    type Err = String;

    /// Accepts the [`TypeReduction::name`]s.
    ///
    /// ```
    /// # use t2spline::TypeReduction;
    /// assert_eq!("nie-tan".parse(), Ok(TypeReduction::NieTan));
    /// assert!("nietan".parse::<TypeReduction>().unwrap_err().contains("alpha-planes"));
    /// ```
    fn from_str(s: &str) -> Result<Self, String> {
        TypeReduction::ALL
            .into_iter()
            .find(|r| r.name() == s)
            .ok_or_else(|| {
                format!(
                    "unknown type reduction `{s}` (known: paper, centroid, nie-tan, alpha-planes)"
                )
            })
    }
}

/// One number reduced to a type-1 result by a [`TypeReduction`]:
/// `left ≤ defuzzified ≤ right`.
///
/// | reduction | left, right | defuzzified |
/// |---|---|---|
/// | `Paper` | the type-reduced triangle's feet (docs/method.md §3) | its centroid (docs/method.md §4) |
/// | `Centroid` | `c_l`, `c_r` | `(c_l + c_r)/2` |
/// | `NieTan` | the value | the value |
/// | `AlphaPlanes` | `c_l(0)`, `c_r(0)` (the widest plane) | the alpha-plane value |
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Reduced {
    left: f64,
    right: f64,
    defuzzified: f64,
}

impl Reduced {
    fn new(left: f64, right: f64, defuzzified: f64) -> Self {
        debug_assert!(
            left <= defuzzified && defuzzified <= right,
            "reduced ({left}, {defuzzified}, {right})"
        );
        Reduced {
            left,
            right,
            defuzzified,
        }
    }

    /// The left end.
    #[must_use]
    pub fn left(&self) -> f64 {
        self.left
    }

    /// The right end.
    #[must_use]
    pub fn right(&self) -> f64 {
        self.right
    }

    /// The defuzzified value.
    #[must_use]
    pub fn defuzzified(&self) -> f64 {
        self.defuzzified
    }
}

impl Nt2Number {
    /// Reduces the number by `method` (docs/method.md §3–§4 and §9); `alpha` is used by
    /// [`TypeReduction::Paper`] only, exactly as
    /// `self.alpha_cut(alpha).type_reduce()` and its `defuzzify()`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, Nt2Number, TypeReduction};
    /// let x = Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?;
    /// let alpha = Alpha::try_new(0.8)?;
    /// let paper = x.reduce(TypeReduction::Paper, alpha);
    /// assert!((paper.defuzzified() - 3.05 / 3.0).abs() < 1e-15);
    /// let centroid = x.reduce(TypeReduction::Centroid, alpha);
    /// assert_eq!(centroid.left(), x.centroid().left());
    /// let nie_tan = x.reduce(TypeReduction::NieTan, alpha);
    /// assert_eq!((nie_tan.left(), nie_tan.right()), (x.nie_tan(), x.nie_tan()));
    /// // The right side is longer: every reduction moves right of crisp = 1.
    /// for method in TypeReduction::ALL {
    ///     assert!(x.reduce(method, alpha).defuzzified() > 1.0, "{method}");
    /// }
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn reduce(&self, method: TypeReduction, alpha: Alpha) -> Reduced {
        match method {
            TypeReduction::Paper => {
                let t = self.alpha_cut(alpha).type_reduce();
                Reduced::new(t.left(), t.right(), t.defuzzify())
            }
            TypeReduction::Centroid => {
                let c = self.centroid();
                let mid = (c.left() + (c.right() - c.left()) / 2.0).clamp(c.left(), c.right());
                Reduced::new(c.left(), c.right(), mid)
            }
            TypeReduction::NieTan => {
                let v = self.nie_tan();
                Reduced::new(v, v, v)
            }
            TypeReduction::AlphaPlanes => {
                let a = self.alpha_planes();
                let w = a.widest();
                Reduced::new(w.left(), w.right(), a.defuzzified())
            }
        }
    }
}
