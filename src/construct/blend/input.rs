//! [`BlendInput`]: N pipes meeting at a junction, the GBS order and the shape parameters,
//! with the checks that reject inputs the blend cannot join.

use glam::DVec3;
use serde::Deserialize;

use crate::error::{Error, Result};
use crate::gbs::GbsOptions;
use crate::math::cos;

/// One pipe: a cylinder that starts at the junction and runs away from it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pipe {
    /// Centre of the pipe's end at the junction.
    pub end: DVec3,
    /// Axis direction, away from the junction (need not be unit).
    pub axis: DVec3,
    /// Radius of the limit cylinder, > 0.
    pub radius: f64,
    /// Length of the pipe from its junction end, > 0.
    pub length: f64,
}

/// Input of the N-way blend. JSON: `{"pipes": [{"end": [x,y,z], "axis": [x,y,z],
/// "radius": r, "length": l}, ...], "columns": 4, "order": 4, "tension": null, "alpha": 0.5,
/// "k_alpha": 0.5, "gbs_level": 1}` (all keys but `pipes` optional, defaults as
/// [`BlendInput::new`]), plus the settings keys.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(from = "BlendJson")]
pub struct BlendInput {
    /// The pipes, 3 to 8, in any order (the blend sorts them round the junction).
    pub pipes: Vec<Pipe>,
    /// Control points round every pipe's cross-section, [`MIN_COLUMNS`]..=[`MAX_COLUMNS`].
    pub columns: usize,
    /// GBS order k, 3..=8.
    pub order: u32,
    /// Level-0 tension; `None` for the pipes' exact-circle tension cos(π/columns).
    pub tension: Option<f64>,
    /// Lift of the two centre points off the junction plane, in units of the mean control
    /// radius (≥ 0 domes the centre, 0 leaves it flat).
    pub alpha: f64,
    /// Push of the valley points towards the junction, along the pipes' end tangents.
    pub k_alpha: f64,
    /// Level of the GBS refinement whose vertices the Catmull–Clark result interpolates
    /// (1..=4).
    pub gbs_level: u32,
}

/// [`Pipe`] as JSON.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PipeJson {
    end: [f64; 3],
    axis: [f64; 3],
    radius: f64,
    length: f64,
}

/// [`BlendInput`] as JSON.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BlendJson {
    pipes: Vec<PipeJson>,
    columns: Option<usize>,
    order: Option<u32>,
    tension: Option<f64>,
    alpha: Option<f64>,
    k_alpha: Option<f64>,
    gbs_level: Option<u32>,
}

impl From<BlendJson> for BlendInput {
    fn from(j: BlendJson) -> BlendInput {
        let pipes = j
            .pipes
            .into_iter()
            .map(|p| Pipe {
                end: DVec3::from(p.end),
                axis: DVec3::from(p.axis),
                radius: p.radius,
                length: p.length,
            })
            .collect();
        let d = BlendInput::new(pipes);
        BlendInput {
            columns: j.columns.unwrap_or(d.columns),
            order: j.order.unwrap_or(d.order),
            tension: j.tension,
            alpha: j.alpha.unwrap_or(d.alpha),
            k_alpha: j.k_alpha.unwrap_or(d.k_alpha),
            gbs_level: j.gbs_level.unwrap_or(d.gbs_level),
            ..d
        }
    }
}

/// Fewest control points round a pipe.
pub const MIN_COLUMNS: usize = 3;
/// Most control points round a pipe.
pub const MAX_COLUMNS: usize = 16;

impl BlendInput {
    /// `pipes` with four columns, order 4, the exact-circle tension, α = 0.5, k_α = 0.5 and
    /// GBS level 1.
    pub fn new(pipes: Vec<Pipe>) -> BlendInput {
        BlendInput {
            pipes,
            columns: 4,
            order: 4,
            tension: None,
            alpha: 0.5,
            k_alpha: 0.5,
            gbs_level: 1,
        }
    }

    /// The GBS options: the order and the tension (cos(π/columns) unless given: the
    /// pipes' circles are exact).
    pub fn gbs_options(&self) -> GbsOptions {
        GbsOptions {
            order: self.order,
            tension: self
                .tension
                .unwrap_or_else(|| cos(std::f64::consts::PI / self.columns as f64)),
        }
    }

    /// Check the input. Errors ([`Error::InvalidArgument`]): fewer than 3 or more than 8
    /// pipes, columns outside 3..=16, a radius or length not positive and finite, a zero or
    /// non-finite axis or end,
    /// order or tension out of range, α or k_α not finite, two pipes parallel (same
    /// direction) or with the same end, a pipe pointing into the junction, and two pipes
    /// whose cylinders come closer than the sum of their radii (they would intersect before
    /// reaching the junction).
    pub fn validate(&self) -> Result<()> {
        let bad = |m: String| Err(Error::invalid_argument(m));
        let n = self.pipes.len();
        if !(3..=8).contains(&n) {
            return bad(format!("a blend joins 3 to 8 pipes, not {n}"));
        }
        if !(MIN_COLUMNS..=MAX_COLUMNS).contains(&self.columns) {
            return bad(format!(
                "columns {} is outside {MIN_COLUMNS}..={MAX_COLUMNS}",
                self.columns
            ));
        }
        self.gbs_options().validate()?;
        if !self.alpha.is_finite() || !self.k_alpha.is_finite() {
            return bad("alpha and k_alpha must be finite".into());
        }
        for (i, p) in self.pipes.iter().enumerate() {
            if !(p.radius.is_finite() && p.radius > 0.0) {
                return bad(format!("pipe {i}: radius {} must be positive", p.radius));
            }
            if !(p.length.is_finite() && p.length > 0.0) {
                return bad(format!("pipe {i}: length {} must be positive", p.length));
            }
            if !p.end.is_finite() || !p.axis.is_finite() || p.axis.length() < 1e-12 {
                return bad(format!(
                    "pipe {i}: end and axis must be finite, the axis non-zero"
                ));
            }
        }
        let centre = self.pipes.iter().map(|p| p.end).sum::<DVec3>() / n as f64;
        for (i, p) in self.pipes.iter().enumerate() {
            if (p.end - centre).dot(p.axis) <= 0.0 {
                return bad(format!(
                    "pipe {i} points into the junction, not away from it"
                ));
            }
        }
        for i in 0..n {
            for j in i + 1..n {
                let (a, b) = (&self.pipes[i], &self.pipes[j]);
                let (da, db) = (a.axis.normalize(), b.axis.normalize());
                if (a.end - b.end).length() < 1e-9 * (a.radius + b.radius) {
                    return bad(format!("pipes {i} and {j} are coincident (same end)"));
                }
                if da.dot(db) > 1.0 - 1e-9 {
                    return bad(format!("pipes {i} and {j} are parallel"));
                }
                let gap =
                    segment_distance(a.end, a.end + da * a.length, b.end, b.end + db * b.length);
                if gap < a.radius + b.radius {
                    return bad(format!(
                        "pipes {i} and {j} intersect before the junction: their axes come {gap:.6} apart, less than the radii's sum {:.6}",
                        a.radius + b.radius
                    ));
                }
            }
        }
        Ok(())
    }
}

/// Distance between segments `[p0, p1]` and `[q0, q1]` (clamped closest points).
fn segment_distance(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> f64 {
    let (d1, d2, r) = (p1 - p0, q1 - q0, p0 - q0);
    let (a, e, f) = (d1.dot(d1), d2.dot(d2), d2.dot(r));
    let (c, b) = (d1.dot(r), d1.dot(d2));
    let denom = a * e - b * b;
    let mut s = if denom > 1e-300 {
        ((b * f - c * e) / denom).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let mut t = (b * s + f) / e;
    if t < 0.0 {
        t = 0.0;
        s = (-c / a).clamp(0.0, 1.0);
    } else if t > 1.0 {
        t = 1.0;
        s = ((b - c) / a).clamp(0.0, 1.0);
    }
    ((p0 + d1 * s) - (q0 + d2 * t)).length()
}
