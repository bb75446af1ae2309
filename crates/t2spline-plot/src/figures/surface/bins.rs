//! The discrete colour scale of the maps over `(u, v)`, and its colour bar.

use crate::chart::paint::{viridis, Color};
use crate::chart::scene::ColorBar;

/// A discrete colour scale from 0 to `max` in [`Bins::COUNT`] steps of
/// viridis; the colour of a value is that of the nearest step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bins {
    /// The largest value.
    pub max: f64,
}

impl Bins {
    /// Steps above zero.
    pub const COUNT: usize = 8;

    /// The scale of `values` (from 0 to their largest).
    #[must_use]
    pub fn of(values: &[f64]) -> Bins {
        Bins {
            max: values
                .iter()
                .copied()
                .filter(|v| v.is_finite())
                .fold(0.0, f64::max),
        }
    }

    fn step(&self, v: f64) -> usize {
        if self.max > 0.0 && v.is_finite() {
            ((v / self.max * Self::COUNT as f64).round().max(0.0) as usize).min(Self::COUNT)
        } else {
            0
        }
    }

    /// The colour of value `v`.
    #[must_use]
    pub fn colour(&self, v: f64) -> Color {
        viridis(self.step(v) as f64 / Self::COUNT as f64)
    }

    /// The colour bar, labelled `label`, with `marks`.
    #[must_use]
    pub fn colorbar(&self, label: &str, marks: Vec<(f64, String)>) -> ColorBar {
        let stops = if self.max > 0.0 {
            (0..=Self::COUNT)
                .map(|k| {
                    let s = k as f64 / Self::COUNT as f64;
                    (s * self.max, viridis(s))
                })
                .collect()
        } else {
            vec![(0.0, viridis(0.0))]
        };
        ColorBar {
            label: label.to_owned(),
            stops,
            marks,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bins_round_to_the_nearest_step() {
        let b = Bins { max: 8.0 };
        assert_eq!(b.colour(0.4), viridis(0.0));
        assert_eq!(b.colour(0.6), viridis(0.125));
        assert_eq!(b.colour(8.0), viridis(1.0));
        assert_eq!(b.colorbar("d", vec![]).stops.len(), 9);
        assert_eq!(Bins::of(&[0.0, 0.0]).colorbar("d", vec![]).stops.len(), 1);
    }
}
