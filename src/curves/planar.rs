//! A planar curve through points: an open [`SpaceCurve`] in the plane `z = 0`, read and
//! written with 2-D points.

use glam::{DVec2, DVec3};

use super::curve::{EndCondition, Interpolation, SpaceCurve};
use crate::error::Result;

/// A planar curve through points, parameterized by summed chord length.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarCurve {
    points: Vec<DVec2>,
    curve: SpaceCurve,
}

impl PlanarCurve {
    /// Build the curve through `points`.
    ///
    /// `breaks` lists interior point indices where the curve is only C⁰ (corners); between
    /// breaks each run is a C² cubic spline with natural ends, except that `ends` may
    /// prescribe the tangent (`z = 0`) at the curve's first and last point. Polylines ignore
    /// `breaks` and `ends`.
    ///
    /// Errors ([`crate::error::Error::InvalidArgument`]): those of [`SpaceCurve::new`] for an
    /// open curve (fewer than 2 points, a non-finite coordinate, two consecutive points that
    /// coincide, a break index that is not interior).
    pub fn new(
        points: &[DVec2],
        interpolation: Interpolation,
        breaks: &[usize],
        ends: [EndCondition; 2],
    ) -> Result<PlanarCurve> {
        let lifted: Vec<DVec3> = points.iter().map(|p| p.extend(0.0)).collect();
        let curve = SpaceCurve::with_ends("", &lifted, false, interpolation, breaks, ends)?;
        Ok(PlanarCurve {
            points: points.to_vec(),
            curve,
        })
    }

    /// The points the curve passes through.
    pub fn points(&self) -> &[DVec2] {
        &self.points
    }

    /// Parameter of each point (summed chord length; the first is 0).
    pub fn knots(&self) -> &[f64] {
        self.curve.knots()
    }

    /// Parameter of the last point: the total chord length.
    pub fn length(&self) -> f64 {
        self.curve.length()
    }

    /// Point at parameter `s` (clamped to `[0, length]`).
    pub fn eval(&self, s: f64) -> DVec2 {
        self.curve.eval(s, false).position.truncate()
    }

    /// First derivative with respect to the parameter at `s` (clamped); at a knot, the
    /// derivative of the span that starts there.
    pub fn derivative(&self, s: f64) -> DVec2 {
        self.curve.eval(s, false).d1.truncate()
    }

    /// Derivatives at the two ends of span `i` (`[start, end]`).
    pub fn span_tangents(&self, i: usize) -> [DVec2; 2] {
        self.curve.span_tangents(i).map(DVec3::truncate)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;
    use crate::math;

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
            .map(|i| DVec2::new(math::sin(i as f64 * 0.5) + i as f64, (i * i) as f64 * 0.1))
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
            [EndCondition::Tangent(t.extend(0.0)), EndCondition::Natural],
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
