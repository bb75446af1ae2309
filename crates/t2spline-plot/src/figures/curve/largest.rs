//! The largest distance between the crisp and the defuzzified curve: its two
//! ends, computed by the library, and how a panel marks it (stage 4 and its
//! magnified panel; surfaces mark theirs the same way).

use t2spline::job::{Job, RunOutput};
use t2spline::Alpha;

use crate::chart::scene::{Mark, Panel, Priority, Xy};
use crate::data;
use crate::error::Error;
use crate::figures::style::{distance_marker, distance_stroke};

/// The two ends of the largest distance: the crisp and the defuzzified curve
/// at `max_at`, by the library.
pub(super) struct Ends {
    pub crisp: Vec<f64>,
    pub solution: Vec<f64>,
}

impl Ends {
    pub(super) fn of(job: &Job, r: &RunOutput) -> Result<Ends, Error> {
        let (c, d) = data::curves_at(
            &job.model,
            Alpha::try_new(r.alpha)?,
            r.type_reduction,
            &[data::curve_spline(r).max_at],
        )?;
        Ok(Ends {
            crisp: c.point(0).unwrap_or_default(),
            solution: d.point(0).unwrap_or_default(),
        })
    }

    pub(super) fn projected(&self, (i, j): (usize, usize)) -> [Xy; 2] {
        [
            [self.crisp[i], self.crisp[j]],
            [self.solution[i], self.solution[j]],
        ]
    }
}

/// The segment between the two ends of the largest distance, its end
/// markers, and (with `text`) its annotation, which is always placed.
pub fn largest_distance(p: &mut Panel, ends: [Xy; 2], text: Option<String>) {
    p.push(
        "distance",
        Mark::Segments {
            segments: vec![ends],
            stroke: distance_stroke(),
        },
    );
    p.push(
        "distance-ends",
        Mark::Markers {
            points: ends.to_vec(),
            marker: distance_marker(),
        },
    );
    let mid = [
        0.5 * (ends[0][0] + ends[1][0]),
        0.5 * (ends[0][1] + ends[1][1]),
    ];
    p.push(
        "distance-text",
        text.map_or(Mark::Empty, |text| Mark::Label {
            anchor: mid,
            text,
            priority: Priority::Always,
        }),
    );
}
