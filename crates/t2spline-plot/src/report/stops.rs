//! The alphas the report's slider stops at: a regular grid, every lower
//! height h and the starting alpha. The grid is as fine as the report's size
//! budget allows: every stop carries its figures' changing parts and its
//! downloads, so a job of hundreds of control points gets fewer stops.

use t2spline::job::Job;
use t2spline::Alpha;

/// Grid steps the slider may have, finest first: each divides 1.
pub const STEPS: [u32; 5] = [100, 50, 20, 10, 4];

/// The slider's stops.
#[derive(Clone, Debug, PartialEq)]
pub struct Stops {
    /// The alphas, ascending, without repeats.
    pub alphas: Vec<f64>,
    /// The index of the starting alpha.
    pub initial: usize,
    /// Grid intervals per unit of alpha (100: stops 0.01 apart).
    pub per_unit: u32,
}

impl Stops {
    /// Stops at `0, 1/per_unit, …, 1`, at every lower height of `job` and at
    /// `start`.
    ///
    /// # Examples
    /// ```
    /// let job = t2spline_io::read_job("../../examples/paper-alg-1-1.json".as_ref())?;
    /// let s = t2spline_plot::Stops::new(&job, t2spline::Alpha::try_new(0.8)?, 100);
    /// assert_eq!(s.alphas.len(), 101); // 0.6 and 0.8 are already on the grid
    /// assert_eq!((s.alphas[60], s.alphas[s.initial]), (0.6, 0.8));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn new(job: &Job, start: Alpha, per_unit: u32) -> Stops {
        // i / n is the correctly rounded double nearest to the decimal, which
        // is what `--alpha 0.37` parses to.
        let mut v: Vec<f64> = (0..=per_unit)
            .map(|i| f64::from(i) / f64::from(per_unit))
            .collect();
        v.extend(job.model.heights());
        v.push(start.get());
        v.sort_by(f64::total_cmp);
        v.dedup();
        let initial = v.iter().position(|&a| a == start.get()).unwrap_or(0);
        Stops {
            alphas: v,
            initial,
            per_unit,
        }
    }

    /// The grid's step as text ("0.01").
    #[must_use]
    pub fn step_text(&self) -> String {
        serde_json::Value::from(1.0 / f64::from(self.per_unit)).to_string()
    }

    /// A few stops whose figures stand for all of them when placing legends
    /// and labels: both ends, the start, every h and the stop after it.
    #[must_use]
    pub fn probes(&self, heights: &[f64]) -> Vec<usize> {
        let last = self.alphas.len() - 1;
        let mut p = vec![0, last, self.initial, last / 2];
        for h in heights {
            if let Some(k) = self.alphas.iter().position(|a| a == h) {
                p.push(k);
                p.push((k + 1).min(last));
            }
        }
        p.sort_unstable();
        p.dedup();
        p
    }
}

/// The finest grid of [`STEPS`] whose stops, at `per_stop` bytes each, fit
/// `budget` bytes; the coarsest if none does.
#[must_use]
pub fn finest_within(job: &Job, start: Alpha, per_stop: usize, budget: usize) -> Stops {
    let mut last = None;
    for n in STEPS {
        let s = Stops::new(job, start, n);
        if s.alphas.len().saturating_mul(per_stop) <= budget {
            return s;
        }
        last = Some(s);
    }
    last.unwrap_or_else(|| Stops::new(job, start, STEPS[STEPS.len() - 1]))
}
