//! A planar curve through points: C² cubic spline pieces with chord-length parameter, C⁰ at
//! break points (corners); or the polyline through the points.
//!
//! The parameter of point `i` is the summed chord length from point 0 (`knots()[i]`). Every
//! span is a cubic Hermite segment in that parameter, so evaluation is uniform for splines
//! and polylines.

use glam::DVec2;

use crate::error::{Error, Result};

/// How the points are joined (JSON: `"spline"`, `"polyline"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Interpolation {
    /// C² cubic spline with chord-length parameter, broken (C⁰) at corners. The default.
    #[default]
    Spline,
    /// Straight segments: the points taken literally.
    Polyline,
}

/// End condition of a spline run at the curve's first or last point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum EndCondition {
    /// Zero second derivative (natural spline).
    #[default]
    Natural,
    /// Prescribed first derivative with respect to the chord-length parameter.
    Tangent(DVec2),
}

/// A planar curve through points, parameterized by summed chord length.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarCurve {
    points: Vec<DVec2>,
    knots: Vec<f64>,
    /// Derivative at the start and at the end of each span (two per span).
    tangents: Vec<[DVec2; 2]>,
}

impl PlanarCurve {
    /// Build the curve through `points`.
    ///
    /// `breaks` lists interior point indices where the curve is only C⁰ (corners); between
    /// breaks each run is a C² cubic spline with natural ends, except that `ends` may
    /// prescribe the tangent at the curve's first and last point. Polylines ignore `breaks`
    /// and `ends`.
    ///
    /// Errors ([`Error::InvalidArgument`]): fewer than 2 points, a non-finite coordinate,
    /// two consecutive points that coincide, a break index that is not interior.
    pub fn new(
        points: &[DVec2],
        interpolation: Interpolation,
        breaks: &[usize],
        ends: [EndCondition; 2],
    ) -> Result<PlanarCurve> {
        let n = points.len();
        if n < 2 {
            return Err(Error::invalid_argument(format!(
                "a curve needs at least 2 points, got {n}"
            )));
        }
        if let Some((i, p)) = points.iter().enumerate().find(|(_, p)| !p.is_finite()) {
            return Err(Error::invalid_argument(format!(
                "point {i} ({}, {}) is not finite",
                p.x, p.y
            )));
        }
        let mut knots = Vec::with_capacity(n);
        knots.push(0.0);
        for i in 1..n {
            let h = (points[i] - points[i - 1]).length();
            if h <= 1e-12 * (1.0 + points[i].abs().max_element()) {
                return Err(Error::invalid_argument(format!(
                    "points {} and {i} coincide ({}, {})",
                    i - 1,
                    points[i].x,
                    points[i].y
                )));
            }
            knots.push(knots[i - 1] + h);
        }
        if let Some(&b) = breaks.iter().find(|&&b| b == 0 || b >= n - 1) {
            return Err(Error::invalid_argument(format!(
                "break point {b} is not an interior point (0 < index < {})",
                n - 1
            )));
        }
        let tangents = match interpolation {
            Interpolation::Polyline => (0..n - 1)
                .map(|i| {
                    let d = (points[i + 1] - points[i]) / (knots[i + 1] - knots[i]);
                    [d, d]
                })
                .collect(),
            Interpolation::Spline => spline_tangents(points, &knots, breaks, ends),
        };
        Ok(PlanarCurve {
            points: points.to_vec(),
            knots,
            tangents,
        })
    }

    /// The points the curve passes through.
    pub fn points(&self) -> &[DVec2] {
        &self.points
    }

    /// Parameter of each point (summed chord length; the first is 0).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// Parameter of the last point: the total chord length.
    pub fn length(&self) -> f64 {
        self.knots[self.knots.len() - 1]
    }

    /// The Hermite data of the span containing `s` (clamped to the curve): end points, end
    /// derivatives, span length and the local parameter `u ∈ [0, 1]`.
    fn local(&self, s: f64) -> ([DVec2; 2], [DVec2; 2], f64, f64) {
        let last = self.knots.len() - 2;
        let i = match self.knots.partition_point(|&k| k <= s) {
            0 => 0,
            i => (i - 1).min(last),
        };
        let (a, b) = (self.knots[i], self.knots[i + 1]);
        let h = b - a;
        let u = ((s - a) / h).clamp(0.0, 1.0);
        ([self.points[i], self.points[i + 1]], self.tangents[i], h, u)
    }

    /// Point at parameter `s` (clamped to `[0, length]`).
    pub fn eval(&self, s: f64) -> DVec2 {
        let ([p0, p1], [d0, d1], h, u) = self.local(s);
        let u2 = u * u;
        let u3 = u2 * u;
        p0 * (2.0 * u3 - 3.0 * u2 + 1.0)
            + d0 * (h * (u3 - 2.0 * u2 + u))
            + p1 * (-2.0 * u3 + 3.0 * u2)
            + d1 * (h * (u3 - u2))
    }

    /// First derivative with respect to the parameter at `s` (clamped); at a knot, the
    /// derivative of the span that starts there.
    pub fn derivative(&self, s: f64) -> DVec2 {
        let ([p0, p1], [d0, d1], h, u) = self.local(s);
        let u2 = u * u;
        (p0 - p1) * ((6.0 * u2 - 6.0 * u) / h)
            + d0 * (3.0 * u2 - 4.0 * u + 1.0)
            + d1 * (3.0 * u2 - 2.0 * u)
    }

    /// Derivatives at the two ends of span `i` (`[start, end]`).
    pub fn span_tangents(&self, i: usize) -> [DVec2; 2] {
        self.tangents[i]
    }
}

/// Derivatives of C² cubic spline runs between breaks (tridiagonal solve per run).
fn spline_tangents(
    points: &[DVec2],
    knots: &[f64],
    breaks: &[usize],
    ends: [EndCondition; 2],
) -> Vec<[DVec2; 2]> {
    let n = points.len();
    let mut cuts: Vec<usize> = breaks.to_vec();
    cuts.push(0);
    cuts.push(n - 1);
    cuts.sort_unstable();
    cuts.dedup();
    let mut tangents = vec![[DVec2::ZERO; 2]; n - 1];
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let start = if a == 0 {
            ends[0]
        } else {
            EndCondition::Natural
        };
        let end = if b == n - 1 {
            ends[1]
        } else {
            EndCondition::Natural
        };
        let m = run_derivatives(&points[a..=b], &knots[a..=b], start, end);
        for i in a..b {
            tangents[i] = [m[i - a], m[i + 1 - a]];
        }
    }
    tangents
}

/// First derivatives at the knots of one C² cubic spline run (Thomas algorithm).
fn run_derivatives(p: &[DVec2], k: &[f64], start: EndCondition, end: EndCondition) -> Vec<DVec2> {
    let n = p.len();
    let h: Vec<f64> = k.windows(2).map(|w| w[1] - w[0]).collect();
    let delta: Vec<DVec2> = (0..n - 1).map(|i| (p[i + 1] - p[i]) / h[i]).collect();
    // Rows: sub[i] m[i-1] + diag[i] m[i] + sup[i] m[i+1] = rhs[i].
    let mut sub = vec![0.0; n];
    let mut diag = vec![0.0; n];
    let mut sup = vec![0.0; n];
    let mut rhs = vec![DVec2::ZERO; n];
    match start {
        EndCondition::Natural => {
            diag[0] = 2.0;
            sup[0] = 1.0;
            rhs[0] = delta[0] * 3.0;
        }
        EndCondition::Tangent(t) => {
            diag[0] = 1.0;
            rhs[0] = t;
        }
    }
    for i in 1..n - 1 {
        sub[i] = h[i];
        diag[i] = 2.0 * (h[i - 1] + h[i]);
        sup[i] = h[i - 1];
        rhs[i] = (delta[i - 1] * h[i] + delta[i] * h[i - 1]) * 3.0;
    }
    match end {
        EndCondition::Natural => {
            sub[n - 1] = 1.0;
            diag[n - 1] = 2.0;
            rhs[n - 1] = delta[n - 2] * 3.0;
        }
        EndCondition::Tangent(t) => {
            diag[n - 1] = 1.0;
            rhs[n - 1] = t;
        }
    }
    for i in 1..n {
        let w = sub[i] / diag[i - 1];
        diag[i] -= w * sup[i - 1];
        rhs[i] = rhs[i] - rhs[i - 1] * w;
    }
    let mut m = vec![DVec2::ZERO; n];
    m[n - 1] = rhs[n - 1] / diag[n - 1];
    for i in (0..n - 1).rev() {
        m[i] = (rhs[i] - m[i + 1] * sup[i]) / diag[i];
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spline_reproduces_a_cubic_with_its_end_tangents() {
        // x = s, y = s³ on a chord-length parameter is not a cubic in s, so use a straight
        // line with uneven points: any spline through collinear points is that line.
        let pts = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 2.0),
            DVec2::new(1.5, 3.0),
            DVec2::new(4.0, 8.0),
        ];
        let c = PlanarCurve::new(&pts, Interpolation::Spline, &[], Default::default()).unwrap();
        for k in 0..=20 {
            let s = c.length() * k as f64 / 20.0;
            let p = c.eval(s);
            assert!((p.y - 2.0 * p.x).abs() < 1e-12, "{p}");
            assert!((p.length() - s).abs() < 1e-12);
        }
    }

    #[test]
    fn spline_interpolates_and_is_c2_inside_runs_and_c0_at_breaks() {
        let pts: Vec<DVec2> = (0..7)
            .map(|i| DVec2::new((i as f64 * 0.5).sin() + i as f64, (i * i) as f64 * 0.1))
            .collect();
        let c = PlanarCurve::new(&pts, Interpolation::Spline, &[3], Default::default()).unwrap();
        for (i, p) in pts.iter().enumerate() {
            assert!((c.eval(c.knots()[i]) - *p).length() < 1e-14);
        }
        // C¹ at knot 2 (inside the first run), not at the break 3.
        let [_, d_left] = c.span_tangents(1);
        let [d_right, _] = c.span_tangents(2);
        assert_eq!(d_left, d_right);
        let [_, d_left] = c.span_tangents(2);
        let [d_right, _] = c.span_tangents(3);
        assert!((d_left - d_right).length() > 1e-3);
        // Natural end: second derivative zero at the first point (finite difference).
        let e = 1e-5;
        let second = (c.derivative(e) - c.derivative(0.0)) / e;
        assert!(second.length() < 1e-4, "{second}");
    }

    #[test]
    fn clamped_end_takes_the_given_tangent_and_polyline_is_literal() {
        let pts = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(2.0, 3.0),
        ];
        let t = DVec2::new(1.0, 0.0);
        let c = PlanarCurve::new(
            &pts,
            Interpolation::Spline,
            &[],
            [EndCondition::Tangent(t), EndCondition::Natural],
        )
        .unwrap();
        assert!((c.derivative(0.0) - t).length() < 1e-14);
        let l = PlanarCurve::new(&pts, Interpolation::Polyline, &[], Default::default()).unwrap();
        let mid = l.eval(l.knots()[1] * 0.5);
        assert!((mid - DVec2::new(0.5, 0.5)).length() < 1e-14);
    }

    #[test]
    fn rejects_bad_points() {
        let one = [DVec2::ZERO];
        assert!(PlanarCurve::new(&one, Interpolation::Spline, &[], Default::default()).is_err());
        let nan = [DVec2::ZERO, DVec2::new(f64::NAN, 1.0)];
        assert!(PlanarCurve::new(&nan, Interpolation::Spline, &[], Default::default()).is_err());
        let dup = [DVec2::ZERO, DVec2::ZERO, DVec2::ONE];
        let e = PlanarCurve::new(&dup, Interpolation::Spline, &[], Default::default());
        assert!(matches!(e, Err(Error::InvalidArgument(m)) if m.contains("coincide")));
        let pts = [DVec2::ZERO, DVec2::ONE];
        assert!(PlanarCurve::new(&pts, Interpolation::Spline, &[1], Default::default()).is_err());
    }
}
