//! Curves through points, 3-D, open or closed: C² cubic splines (chord-length parameter)
//! broken at corners, or polylines.
//!
//! The parameter of point `i` is the summed chord length from point 0 (`knots()[i]`). Every
//! span is a cubic Hermite segment in that parameter, so evaluation is uniform for splines
//! and polylines. Between corners an open curve is a C² spline run with natural ends (or a
//! prescribed end tangent, see [`EndCondition`]); a closed curve without corners is a
//! *periodic* spline (cyclic tridiagonal system); a closed curve with corners is a chain of
//! runs from corner to corner. Planar curves use `z = 0` (see [`super::PlanarCurve`]).

use glam::DVec3;

use super::corners::chord_turning_angle;
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

/// End condition of a spline run at an open curve's first or last point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum EndCondition {
    /// Zero second derivative (natural spline).
    #[default]
    Natural,
    /// Prescribed first derivative with respect to the chord-length parameter.
    Tangent(DVec3),
}

/// `what: message`, or the bare message when the caller names nothing.
fn named(what: &str, message: String) -> Error {
    if what.is_empty() {
        Error::invalid_argument(message)
    } else {
        Error::invalid_argument(format!("{what}: {message}"))
    }
}

/// A curve through points, parameterized by summed chord length.
#[derive(Debug, Clone, PartialEq)]
pub struct SpaceCurve {
    points: Vec<DVec3>,
    closed: bool,
    /// Parameter of each point, plus the total length at the end for a closed curve.
    knots: Vec<f64>,
    /// First derivative at the start and at the end of each span.
    tangents: Vec<[DVec3; 2]>,
    /// Point indices where the curve is C⁰ only, increasing.
    corners: Vec<usize>,
}

/// Position and first two derivatives (with respect to the parameter) at a point of a curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePoint {
    /// The point.
    pub position: DVec3,
    /// First derivative.
    pub d1: DVec3,
    /// Second derivative.
    pub d2: DVec3,
}

/// Most points a curve may have (every construction's profile, trajectory and silhouettes):
/// far more than any sampling uses ([`crate::construct::settings::MAX_SAMPLES`] intervals).
pub const MAX_CURVE_POINTS: usize = 1 << 20;

impl SpaceCurve {
    /// Build the curve through `points` (a closed curve joins the last point to the first,
    /// which is not repeated).
    ///
    /// `corners` lists point indices where the curve is only C⁰; for an open curve they must be
    /// interior. Errors: [`Error::LimitExceeded`] above [`MAX_CURVE_POINTS`] points;
    /// [`Error::InvalidArgument`]: fewer than 2 points (3 when closed), a
    /// non-finite coordinate, consecutive points that coincide (the last and the first too
    /// when closed), a corner index out of range. `what` names the curve in messages.
    pub fn new(
        what: &str,
        points: &[DVec3],
        closed: bool,
        interpolation: Interpolation,
        corners: &[usize],
    ) -> Result<SpaceCurve> {
        Self::with_ends(
            what,
            points,
            closed,
            interpolation,
            corners,
            Default::default(),
        )
    }

    /// [`SpaceCurve::new`] with the end conditions of an open spline at its first and last
    /// point (ignored by closed curves and polylines).
    pub fn with_ends(
        what: &str,
        points: &[DVec3],
        closed: bool,
        interpolation: Interpolation,
        corners: &[usize],
        ends: [EndCondition; 2],
    ) -> Result<SpaceCurve> {
        let n = points.len();
        let need = if closed { 3 } else { 2 };
        if n > MAX_CURVE_POINTS {
            return Err(Error::LimitExceeded(format!(
                "{what}: {n} points, above the limit of {MAX_CURVE_POINTS}"
            )));
        }
        if n < need {
            return Err(named(
                what,
                format!(
                    "a{} curve needs at least {need} points, got {n}",
                    if closed { " closed" } else { "n open" }
                ),
            ));
        }
        if let Some((i, p)) = points.iter().enumerate().find(|(_, p)| !p.is_finite()) {
            return Err(named(
                what,
                format!("point {i} ({}, {}, {}) is not finite", p.x, p.y, p.z),
            ));
        }
        let scale = points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
        let spans = if closed { n } else { n - 1 };
        let mut knots = Vec::with_capacity(spans + 1);
        knots.push(0.0);
        for i in 0..spans {
            let j = (i + 1) % n;
            let h = points[i].distance(points[j]);
            if h <= 1e-12 * (1.0 + scale) {
                return Err(named(
                    what,
                    format!(
                        "points {i} and {j} coincide ({}, {}, {})",
                        points[j].x, points[j].y, points[j].z
                    ),
                ));
            }
            knots.push(knots[i] + h);
        }
        let mut corners = corners.to_vec();
        corners.sort_unstable();
        corners.dedup();
        if let Some(&c) = corners
            .iter()
            .find(|&&c| c >= n || (!closed && (c == 0 || c == n - 1)))
        {
            return Err(named(
                what,
                format!(
                    "corner {c} is not {} point index (0 ≤ index < {n})",
                    if closed { "a" } else { "an interior" }
                ),
            ));
        }
        if interpolation == Interpolation::Polyline {
            // Every point where the direction changes is a corner.
            corners = (0..n)
                .filter(|&i| {
                    (closed || (i > 0 && i < n - 1))
                        && chord_turning_angle(points, closed, i) > 1e-12
                })
                .collect();
        }
        let tangents = match interpolation {
            Interpolation::Polyline => (0..spans)
                .map(|i| {
                    let d = (points[(i + 1) % n] - points[i]) / (knots[i + 1] - knots[i]);
                    [d, d]
                })
                .collect(),
            Interpolation::Spline => spline_tangents(points, &knots, closed, &corners, ends),
        };
        Ok(SpaceCurve {
            points: points.to_vec(),
            closed,
            knots,
            tangents,
            corners,
        })
    }

    /// The points the curve passes through.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// Whether the last point joins the first.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// Parameter of each point (the first is 0), then the total length when closed.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// Total parameter length (summed chord length).
    pub fn length(&self) -> f64 {
        self.knots[self.knots.len() - 1]
    }

    /// Point indices where the curve is only C⁰, increasing.
    pub fn corners(&self) -> &[usize] {
        &self.corners
    }

    /// Derivatives at the two ends of span `i` (`[start, end]`).
    pub fn span_tangents(&self, i: usize) -> [DVec3; 2] {
        self.tangents[i]
    }

    fn span(&self, s: f64) -> usize {
        let last = self.knots.len() - 2;
        match self.knots.partition_point(|&k| k <= s) {
            0 => 0,
            i => (i - 1).min(last),
        }
    }

    /// Position and derivatives at parameter `s` (clamped to `[0, length]`). At a knot, the
    /// span that starts there; `left = true` takes the span that ends there instead (the
    /// incoming side of a corner).
    pub fn eval(&self, s: f64, left: bool) -> CurvePoint {
        let s = s.clamp(0.0, self.length());
        let mut i = self.span(s);
        if left && i > 0 && s <= self.knots[i] {
            i -= 1;
        }
        let (a, b) = (self.knots[i], self.knots[i + 1]);
        let h = b - a;
        let u = ((s - a) / h).clamp(0.0, 1.0);
        let [m0, m1] = self.tangents[i];
        let (p0, p1) = (self.points[i], self.points[(i + 1) % self.points.len()]);
        let (u2, u3) = (u * u, u * u * u);
        let position = p0 * (2.0 * u3 - 3.0 * u2 + 1.0)
            + m0 * (h * (u3 - 2.0 * u2 + u))
            + p1 * (-2.0 * u3 + 3.0 * u2)
            + m1 * (h * (u3 - u2));
        let d1 = (p0 - p1) * ((6.0 * u2 - 6.0 * u) / h)
            + m0 * (3.0 * u2 - 4.0 * u + 1.0)
            + m1 * (3.0 * u2 - 2.0 * u);
        let d2 = (p0 - p1) * ((12.0 * u - 6.0) / (h * h))
            + m0 * ((6.0 * u - 4.0) / h)
            + m1 * ((6.0 * u - 2.0) / h);
        CurvePoint { position, d1, d2 }
    }
}

/// A sample of a curve chosen by [`SpaceCurve::sample_parameters`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveSample {
    /// Curve parameter.
    pub s: f64,
    /// Whether the sample sits on a corner point.
    pub corner: bool,
}

impl SpaceCurve {
    /// `segments` sample intervals along the curve: `segments + 1` samples from start to end
    /// for an open curve, `segments` samples starting at point 0 for a closed one. Every
    /// corner is a sample; the pieces between corners (and the ends) get a share of the
    /// intervals proportional to their length, at least one each, spaced uniformly in the
    /// parameter inside a piece.
    ///
    /// Errors ([`Error::InvalidArgument`]): fewer intervals than pieces between corners.
    pub fn sample_parameters(&self, what: &str, segments: usize) -> Result<Vec<CurveSample>> {
        let mut out = self.sample_range(what, 0.0, self.length(), segments)?;
        if self.closed {
            out.pop();
            out[0].corner = self.corners.first() == Some(&0);
        }
        Ok(out)
    }

    /// `segments + 1` samples from parameter `s0` to `s1` (the rules of
    /// [`SpaceCurve::sample_parameters`] inside the range); the end samples are marked as
    /// corners when they sit on one.
    pub fn sample_range(
        &self,
        what: &str,
        s0: f64,
        s1: f64,
        segments: usize,
    ) -> Result<Vec<CurveSample>> {
        let corner_knots: Vec<f64> = self.corners.iter().map(|&c| self.knots[c]).collect();
        let is_corner = |s: f64| corner_knots.contains(&s);
        let mut fixed: Vec<f64> = vec![s0];
        fixed.extend(corner_knots.iter().filter(|&&k| k > s0 && k < s1));
        fixed.push(s1);
        let pieces = fixed.len() - 1;
        if segments < pieces {
            return Err(Error::invalid_argument(format!(
                "{what}: {segments} sample intervals cannot reach the {} corners; give at least {pieces}",
                pieces - 1
            )));
        }
        let len = s1 - s0;
        let ideal: Vec<f64> = fixed
            .windows(2)
            .map(|w| segments as f64 * (w[1] - w[0]) / len)
            .collect();
        let mut count: Vec<usize> = ideal.iter().map(|&x| (x.floor() as usize).max(1)).collect();
        let density = |k: usize, count: &[usize]| ideal[k] / count[k] as f64;
        // Adjust to the exact total: add where intervals are longest, remove where shortest.
        while count.iter().sum::<usize>() < segments {
            let k = (0..pieces)
                .max_by(|&a, &b| density(a, &count).total_cmp(&density(b, &count)))
                .unwrap_or(0);
            count[k] += 1;
        }
        while count.iter().sum::<usize>() > segments {
            let k = (0..pieces)
                .filter(|&k| count[k] > 1)
                .min_by(|&a, &b| density(a, &count).total_cmp(&density(b, &count)))
                .unwrap_or(0);
            count[k] -= 1;
        }
        let mut out = Vec::with_capacity(segments + 1);
        for (k, w) in fixed.windows(2).enumerate() {
            for j in 0..count[k] {
                let s = w[0] + (w[1] - w[0]) * j as f64 / count[k] as f64;
                out.push(CurveSample {
                    s,
                    corner: j == 0 && is_corner(s),
                });
            }
        }
        out.push(CurveSample {
            s: s1,
            corner: is_corner(s1),
        });
        Ok(out)
    }
}

impl SpaceCurve {
    /// The span containing parameter `s` (the one that starts there at a knot; the last
    /// at the end) and the local fraction `0..=1` in it.
    pub fn span_of(&self, s: f64) -> (usize, f64) {
        let i = self.span(s);
        let (a, b) = (self.knots[i], self.knots[i + 1]);
        (i, ((s - a) / (b - a)).clamp(0.0, 1.0))
    }

    /// The point at local fraction `u` of span `i`: the same place relative to the input
    /// points on two curves with the same point count (used to morph profiles).
    pub fn eval_in_span(&self, i: usize, u: f64) -> DVec3 {
        let (a, b) = (self.knots[i], self.knots[i + 1]);
        let s = a + u * (b - a);
        self.eval(s, u >= 1.0).position
    }
}

/// Derivatives at both ends of every span.
fn spline_tangents(
    points: &[DVec3],
    knots: &[f64],
    closed: bool,
    corners: &[usize],
    ends: [EndCondition; 2],
) -> Vec<[DVec3; 2]> {
    let n = points.len();
    let spans = knots.len() - 1;
    let mut tangents = vec![[DVec3::ZERO; 2]; spans];
    // Each run is a list of consecutive point indices (wrapping when closed).
    let runs: Vec<Vec<usize>> = if closed && corners.is_empty() {
        let m = periodic_derivatives(points, knots);
        for i in 0..spans {
            tangents[i] = [m[i], m[(i + 1) % n]];
        }
        return tangents;
    } else if closed {
        let k = corners.len();
        (0..k)
            .map(|c| {
                let (a, b) = (corners[c], corners[(c + 1) % k]);
                let len = if b > a { b - a } else { b + n - a };
                (0..=len).map(|j| (a + j) % n).collect()
            })
            .collect()
    } else {
        let mut cuts = corners.to_vec();
        cuts.insert(0, 0);
        cuts.push(n - 1);
        cuts.windows(2).map(|w| (w[0]..=w[1]).collect()).collect()
    };
    for run in runs {
        let pts: Vec<DVec3> = run.iter().map(|&i| points[i]).collect();
        let h: Vec<f64> = run
            .windows(2)
            .map(|w| knots[w[0] + 1] - knots[w[0]])
            .collect();
        // Only an open curve's own first and last points take the prescribed ends.
        let start = if !closed && run[0] == 0 {
            ends[0]
        } else {
            EndCondition::Natural
        };
        let end = if !closed && run[run.len() - 1] == n - 1 {
            ends[1]
        } else {
            EndCondition::Natural
        };
        let m = run_derivatives(&pts, &h, [start, end]);
        for (j, w) in run.windows(2).enumerate() {
            tangents[w[0]] = [m[j], m[j + 1]];
        }
    }
    tangents
}

/// Right-hand side and coefficients of the C² condition at a knot between spans of lengths
/// `h0` (before) and `h1` (after): `h1 m₋ + 2(h0+h1) m + h0 m₊ = 3(δ0 h1 + δ1 h0)`.
fn c2_row(p_prev: DVec3, p: DVec3, p_next: DVec3, h0: f64, h1: f64) -> ([f64; 3], DVec3) {
    let (d0, d1) = ((p - p_prev) / h0, (p_next - p) / h1);
    ([h1, 2.0 * (h0 + h1), h0], (d0 * h1 + d1 * h0) * 3.0)
}

/// First derivatives at the points of a C² spline run with span lengths `h` and the given
/// end conditions.
fn run_derivatives(p: &[DVec3], h: &[f64], ends: [EndCondition; 2]) -> Vec<DVec3> {
    let n = p.len();
    let mut rows = Vec::with_capacity(n);
    rows.push(match ends[0] {
        EndCondition::Natural => ([0.0, 2.0, 1.0], (p[1] - p[0]) / h[0] * 3.0),
        EndCondition::Tangent(t) => ([0.0, 1.0, 0.0], t),
    });
    for i in 1..n - 1 {
        rows.push(c2_row(p[i - 1], p[i], p[i + 1], h[i - 1], h[i]));
    }
    rows.push(match ends[1] {
        EndCondition::Natural => ([1.0, 2.0, 0.0], (p[n - 1] - p[n - 2]) / h[n - 2] * 3.0),
        EndCondition::Tangent(t) => ([0.0, 1.0, 0.0], t),
    });
    solve_tridiagonal(&rows)
}

/// First derivatives at the points of a periodic C² spline.
fn periodic_derivatives(p: &[DVec3], knots: &[f64]) -> Vec<DVec3> {
    let n = p.len();
    let h = |i: usize| knots[i + 1] - knots[i];
    let rows: Vec<([f64; 3], DVec3)> = (0..n)
        .map(|i| {
            c2_row(
                p[(i + n - 1) % n],
                p[i],
                p[(i + 1) % n],
                h((i + n - 1) % n),
                h(i),
            )
        })
        .collect();
    // Sherman–Morrison: the corner coefficients row 0 → m[n-1] (beta) and row n-1 → m[0]
    // (alpha) are moved into a rank-one correction of a plain tridiagonal system.
    let beta = rows[0].0[0];
    let alpha = rows[n - 1].0[2];
    let gamma = -rows[0].0[1];
    let mut plain = rows.clone();
    plain[0].0[0] = 0.0;
    plain[n - 1].0[2] = 0.0;
    plain[0].0[1] -= gamma;
    plain[n - 1].0[1] -= alpha * beta / gamma;
    let x = solve_tridiagonal(&plain);
    let mut u_rows = plain.clone();
    for (i, r) in u_rows.iter_mut().enumerate() {
        r.1 = DVec3::ZERO;
        if i == 0 {
            r.1 = DVec3::splat(gamma);
        }
        if i == n - 1 {
            r.1 = DVec3::splat(alpha);
        }
    }
    let z = solve_tridiagonal(&u_rows);
    let (z0, zn) = (z[0].x, z[n - 1].x);
    let fact = (x[0] + x[n - 1] * (beta / gamma)) / (1.0 + z0 + beta * zn / gamma);
    x.iter().zip(&z).map(|(&xi, zi)| xi - fact * zi.x).collect()
}

/// Thomas algorithm on rows `([sub, diag, sup], rhs)`; the system is diagonally dominant.
fn solve_tridiagonal(rows: &[([f64; 3], DVec3)]) -> Vec<DVec3> {
    let n = rows.len();
    let mut diag: Vec<f64> = rows.iter().map(|r| r.0[1]).collect();
    let mut rhs: Vec<DVec3> = rows.iter().map(|r| r.1).collect();
    for i in 1..n {
        let w = rows[i].0[0] / diag[i - 1];
        diag[i] -= w * rows[i - 1].0[2];
        rhs[i] = rhs[i] - rhs[i - 1] * w;
    }
    let mut m = vec![DVec3::ZERO; n];
    m[n - 1] = rhs[n - 1] / diag[n - 1];
    for i in (0..n - 1).rev() {
        m[i] = (rhs[i] - m[i + 1] * rows[i].0[2]) / diag[i];
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curves::corners::detect_chord_corners;
    use crate::math;
    use std::f64::consts::TAU;

    fn circle(n: usize, r: f64) -> Vec<DVec3> {
        (0..n)
            .map(|i| {
                let t = TAU * i as f64 / n as f64;
                DVec3::new(r * math::cos(t), r * math::sin(t), 0.0)
            })
            .collect()
    }

    #[test]
    fn periodic_spline_is_c2_at_every_point_and_near_a_circle() {
        let pts = circle(12, 2.0);
        let c = SpaceCurve::new("t", &pts, true, Interpolation::Spline, &[]).unwrap();
        assert!(c.corners().is_empty());
        for (i, k) in c.knots()[..12].iter().enumerate() {
            let (l, r) = (c.eval(*k, true), c.eval(*k, false));
            assert!((l.position - pts[i]).length() < 1e-14);
            assert!((r.position - pts[i]).length() < 1e-14);
            assert!((l.d1 - r.d1).length() < 1e-12);
            assert!((l.d2 - r.d2).length() < 1e-11, "{i}: {} {}", l.d2, r.d2);
        }
        // The closing point joins the first smoothly.
        let end = c.eval(c.length(), true);
        let start = c.eval(0.0, false);
        assert!((end.position - start.position).length() < 1e-14);
        assert!((end.d1 - start.d1).length() < 1e-12);
        // Fourth-order convergence to the circle.
        let dev = |n: usize| {
            let c =
                SpaceCurve::new("t", &circle(n, 2.0), true, Interpolation::Spline, &[]).unwrap();
            (0..400)
                .map(|k| {
                    (c.eval(c.length() * k as f64 / 400.0, false)
                        .position
                        .length()
                        - 2.0)
                        .abs()
                })
                .fold(0.0, f64::max)
        };
        let (e1, e2) = (dev(12), dev(24));
        assert!(e1 < 5e-4 && e1 / e2 > 14.0, "{e1} {e2}");
    }

    #[test]
    fn corners_break_the_spline_and_polyline_is_literal() {
        let sq = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ];
        let corners = detect_chord_corners(&sq, true, 30f64.to_radians());
        assert_eq!(corners, vec![0, 1, 2, 3]);
        let c = SpaceCurve::new("sq", &sq, true, Interpolation::Spline, &corners).unwrap();
        // Runs of one span with natural ends are straight lines.
        let mid = c.eval(2.5, false).position;
        assert!((mid - DVec3::new(0.5, 1.0, 0.0)).length() < 1e-14);
        let p = SpaceCurve::new("sq", &sq, true, Interpolation::Polyline, &[]).unwrap();
        assert_eq!(p.corners(), &[0, 1, 2, 3]);
        assert!((p.eval(3.25, false).position - DVec3::new(0.0, 0.75, 0.0)).length() < 1e-14);
        // The incoming and outgoing derivative differ at a corner.
        assert!((c.eval(1.0, true).d1 - DVec3::X).length() < 1e-14);
        assert!((c.eval(1.0, false).d1 - DVec3::Y).length() < 1e-14);
    }

    #[test]
    fn open_spline_through_collinear_points_is_the_line() {
        let pts = [
            DVec3::ZERO,
            DVec3::new(1.0, 2.0, 2.0),
            DVec3::new(1.5, 3.0, 3.0),
            DVec3::new(4.0, 8.0, 8.0),
        ];
        let c = SpaceCurve::new("l", &pts, false, Interpolation::Spline, &[]).unwrap();
        for k in 0..=20 {
            let s = c.length() * k as f64 / 20.0;
            let p = c.eval(s, false);
            assert!((p.position.length() - s).abs() < 1e-12);
            assert!(p.d2.length() < 1e-12);
        }
    }

    #[test]
    fn samples_hit_every_corner_and_share_the_rest_by_length() {
        // Open L: 3 long then 1 short, corner at point 1.
        let pts = [
            DVec3::ZERO,
            DVec3::new(3.0, 0.0, 0.0),
            DVec3::new(3.0, 1.0, 0.0),
        ];
        let c = SpaceCurve::new("l", &pts, false, Interpolation::Polyline, &[]).unwrap();
        let s = c.sample_parameters("l", 8).unwrap();
        let params: Vec<f64> = s.iter().map(|x| x.s).collect();
        assert_eq!(params, vec![0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]);
        let corners: Vec<bool> = s.iter().map(|x| x.corner).collect();
        assert_eq!(
            corners,
            vec![false, false, false, false, false, false, true, false, false]
        );
        assert!(c.sample_parameters("l", 1).is_err());
        // Closed square, corners everywhere: 3 intervals per side at 12.
        let sq = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let c = SpaceCurve::new("sq", &sq, true, Interpolation::Polyline, &[]).unwrap();
        let s = c.sample_parameters("sq", 12).unwrap();
        assert_eq!(s.len(), 12);
        assert_eq!(s.iter().filter(|x| x.corner).count(), 4);
        assert!(s[0].corner && s[3].corner && s[6].corner && s[9].corner);
        assert!((s[4].s - (1.0 + 1.0 / 3.0)).abs() < 1e-15);
        let e = c.sample_parameters("profile", 3).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("at least 4")));
    }

    #[test]
    fn rejects_bad_points() {
        let one = [DVec3::ZERO];
        let e = SpaceCurve::new("trajectory", &one, false, Interpolation::Spline, &[]).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("at least 2")));
        let two = [DVec3::ZERO, DVec3::ONE];
        assert!(SpaceCurve::new("t", &two, true, Interpolation::Spline, &[]).is_err());
        let nan = [DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0)];
        assert!(SpaceCurve::new("t", &nan, false, Interpolation::Spline, &[]).is_err());
        let dup = [DVec3::ZERO, DVec3::X, DVec3::X];
        let e = SpaceCurve::new("t", &dup, false, Interpolation::Spline, &[]).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("points 1 and 2 coincide")));
        let wrap = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ZERO];
        let e = SpaceCurve::new("t", &wrap, true, Interpolation::Spline, &[]).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("points 3 and 0 coincide")));
        let pts = [DVec3::ZERO, DVec3::X, DVec3::Y];
        assert!(SpaceCurve::new("t", &pts, false, Interpolation::Spline, &[0]).is_err());
        assert!(SpaceCurve::new("t", &pts, true, Interpolation::Spline, &[0]).is_ok());
    }
}
