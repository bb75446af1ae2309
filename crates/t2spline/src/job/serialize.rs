//! The result file's layout (docs/jobs.md; docs/method.md §8): how a [`RunOutput`] serializes.
//!
//! Most parts derive `Serialize`; what is written by hand here is what the
//! derive cannot say: the spline's keys at the top level, the samples under
//! `curves` or `surfaces`, and parameters as a number or a pair.

use serde::ser::{Serialize, SerializeStruct, Serializer};

use super::output::{Parameter, Parameters, RunOutput, Spline};

/// `{"u": …, "v": …}`.
struct Uv<'a, T>(&'a [T; 2]);

impl<T: Serialize> Serialize for Uv<'_, T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut o = s.serialize_struct("Uv", 2)?;
        o.serialize_field("u", &self.0[0])?;
        o.serialize_field("v", &self.0[1])?;
        o.end()
    }
}

impl Serialize for RunOutput {
    /// The keys in the order of the result file: `description` (if any),
    /// `dimension`, `order`, `degree`, `weights`, `knots`, `domain`,
    /// `type_reduction`, `alpha`, `alpha_used`, `regime` (`null` for a
    /// reduction other than the paper's), `note` (only for an alpha a few
    /// ulps above a lower height: the [`NearHeight`](super::NearHeight)'s
    /// text, naming the height), `control_points`, `weight_stages` (only
    /// with fuzzy weights), `curves` or `surfaces`, `error`. A
    /// surface's `order` and `degree` are pairs, its `weights` rows, its
    /// `knots` and `domain` objects with `u` and `v`.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut o = s.serialize_struct("RunOutput", 15)?;
        if let Some(d) = &self.description {
            o.serialize_field("description", d)?;
        }
        o.serialize_field("dimension", &self.dimension)?;
        let samples_key = match &self.spline {
            Spline::Curve {
                order,
                degree,
                weights,
                knots,
                domain,
            } => {
                o.serialize_field("order", order)?;
                o.serialize_field("degree", degree)?;
                o.serialize_field("weights", weights)?;
                o.serialize_field("knots", knots)?;
                o.serialize_field("domain", domain)?;
                "curves"
            }
            Spline::Surface {
                order,
                degree,
                weights,
                knots,
                domain,
            } => {
                o.serialize_field("order", order)?;
                o.serialize_field("degree", degree)?;
                o.serialize_field("weights", weights)?;
                o.serialize_field("knots", &Uv(knots))?;
                o.serialize_field("domain", &Uv(domain))?;
                "surfaces"
            }
        };
        o.serialize_field("type_reduction", &self.type_reduction)?;
        o.serialize_field("alpha", &self.alpha)?;
        o.serialize_field("alpha_used", &self.alpha_used)?;
        o.serialize_field("regime", &self.regime)?;
        if let Some(near) = &self.near_height {
            o.serialize_field("note", &near.to_string())?;
        }
        o.serialize_field("control_points", &self.control_points)?;
        if let Some(w) = &self.weight_stages {
            o.serialize_field("weight_stages", w)?;
        }
        o.serialize_field(samples_key, &self.samples)?;
        o.serialize_field("error", &self.error)?;
        o.end()
    }
}

impl Serialize for Parameters {
    /// A list `[t₀, …]`, or `{"u": [...], "v": [...]}`.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Parameters::Along(t) => t.serialize(s),
            Parameters::Grid { u, v } => {
                let mut o = s.serialize_struct("Parameters", 2)?;
                o.serialize_field("u", u)?;
                o.serialize_field("v", v)?;
                o.end()
            }
        }
    }
}

impl Serialize for Parameter {
    /// `t`, or the pair `[u, v]`.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Parameter::T(t) => t.serialize(s),
            Parameter::Uv(uv) => uv.serialize(s),
        }
    }
}
