//! The trajectory of a sweep: a validated 3-D curve, its samples and their frames.
//!
//! Frames are computed on a finer sampling than the surface's ([`FRAME_SUBSTEPS`] steps per
//! surface interval) so that the rotation-minimizing frame's O(h⁴) error stays far below
//! the fit tolerance, and then read off at the surface samples.

use glam::DVec3;

use super::frames::{compute_frames, Frame, FrameKind, FramePoint};
use crate::curves::corners::detect_chord_corners;
use crate::curves::{CurveSample, Interpolation, SpaceCurve};
use crate::error::{Error, Result};

/// Frame steps per surface sample interval.
pub const FRAME_SUBSTEPS: usize = 8;

/// A validated trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    curve: SpaceCurve,
}

/// A surface sample of the trajectory: its frame and where it lies along the trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrajectorySample {
    /// Frame at the sample.
    pub frame: Frame,
    /// Fraction of the trajectory's (chord-length) parameter, `0..=1`.
    pub fraction: f64,
    /// Whether the sample is a trajectory corner (a crease ring goes across it).
    pub corner: bool,
    /// Curvature vector `κ·N` of the trajectory (leaving the sample at a corner).
    pub curvature: DVec3,
}

impl Trajectory {
    /// Validate the points and build the curve through them; points turning by more than
    /// `sharp_angle` (radians) and the indices in `corners` are corners.
    ///
    /// Errors ([`Error::InvalidArgument`]): fewer than 2 points (3 when closed), a non-finite
    /// coordinate, coincident consecutive points, a corner where the trajectory turns back on
    /// itself (the section there is undefined), a corner index out of range.
    pub fn new(
        points: &[DVec3],
        closed: bool,
        interpolation: Interpolation,
        sharp_angle: f64,
        corners: &[usize],
    ) -> Result<Trajectory> {
        if points.len() >= 2 {
            // Validate before detecting corners, which needs distinct finite points.
            SpaceCurve::new("trajectory", points, closed, Interpolation::Polyline, &[])?;
        }
        let mut all = detect_chord_corners(points, closed, sharp_angle);
        all.extend_from_slice(corners);
        let curve = SpaceCurve::new("trajectory", points, closed, interpolation, &all)?;
        for &c in curve.corners() {
            let s = curve.knots()[c];
            let (a, b) = (curve.eval(s, true).d1, curve.eval(s, false).d1);
            if a.normalize().dot(b.normalize()) < -1.0 + 1e-9 {
                return Err(Error::invalid_argument(format!(
                    "trajectory: it turns back on itself at point {c}, where no section plane exists"
                )));
            }
        }
        Ok(Trajectory { curve })
    }

    /// The curve through the trajectory points.
    pub fn curve(&self) -> &SpaceCurve {
        &self.curve
    }

    /// `segments` sample intervals (see [`SpaceCurve::sample_parameters`]) with their frames.
    pub fn samples(&self, segments: usize, kind: FrameKind) -> Result<Vec<TrajectorySample>> {
        let coarse = self.curve.sample_parameters("trajectory", segments)?;
        let closed = self.curve.is_closed();
        let len = self.curve.length();
        // Substeps between consecutive coarse samples (the closing interval too when closed).
        let mut fine: Vec<CurveSample> = Vec::with_capacity(coarse.len() * FRAME_SUBSTEPS);
        for (i, c) in coarse.iter().enumerate() {
            fine.push(*c);
            let next = match coarse.get(i + 1) {
                Some(n) => n.s,
                None if closed => len,
                None => break,
            };
            for k in 1..FRAME_SUBSTEPS {
                let s = c.s + (next - c.s) * k as f64 / FRAME_SUBSTEPS as f64;
                fine.push(CurveSample { s, corner: false });
            }
        }
        let points: Vec<FramePoint> = fine.iter().map(|c| self.frame_point(c)).collect();
        let curvature = |i: usize| points[i * FRAME_SUBSTEPS].curvature;
        let frames = compute_frames(&points, closed, kind)?;
        Ok(coarse
            .iter()
            .enumerate()
            .map(|(i, c)| TrajectorySample {
                frame: frames[i * FRAME_SUBSTEPS],
                fraction: c.s / len,
                corner: c.corner,
                curvature: curvature(i),
            })
            .collect())
    }

    fn frame_point(&self, c: &CurveSample) -> FramePoint {
        let right = self.curve.eval(c.s, false);
        let speed = right.d1.length();
        let tangent = right.d1 / speed;
        let curvature = (right.d2 - right.d2.dot(tangent) * tangent) / (speed * speed);
        if c.corner {
            let left = self.curve.eval(c.s, true);
            FramePoint {
                position: right.position,
                tangent: left.d1.normalize(),
                curvature,
                tangent_out: Some(tangent),
            }
        } else {
            FramePoint::smooth(right.position, tangent, curvature)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math;
    use std::f64::consts::TAU;

    fn sharp() -> f64 {
        30f64.to_radians()
    }

    #[test]
    fn helix_samples_carry_frames_with_exact_spacing_and_fractions() {
        let pts: Vec<DVec3> = (0..=40)
            .map(|i| {
                let t = TAU * i as f64 / 20.0;
                DVec3::new(math::cos(t), math::sin(t), 0.1 * t)
            })
            .collect();
        let tr = Trajectory::new(&pts, false, Interpolation::Spline, sharp(), &[]).unwrap();
        let s = tr.samples(16, FrameKind::RotationMinimizing).unwrap();
        assert_eq!(s.len(), 17);
        assert_eq!(s[0].fraction, 0.0);
        assert_eq!(s[16].fraction, 1.0);
        assert!((s[8].fraction - 0.5).abs() < 1e-15);
        assert!(s.iter().all(|x| !x.corner));
        for x in &s {
            assert!(x.frame.normal.dot(x.frame.tangent).abs() < 1e-12);
            // Near the helix: |(x, y)| ≈ 1 (natural ends are the least accurate part).
            assert!((x.frame.origin.truncate().length() - 1.0).abs() < 5e-4);
        }
    }

    #[test]
    fn l_shaped_trajectory_has_one_corner_sample_with_a_miter() {
        let pts = [
            DVec3::ZERO,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 2.0, 0.0),
        ];
        let tr = Trajectory::new(&pts, false, Interpolation::Spline, sharp(), &[]).unwrap();
        assert_eq!(tr.curve().corners(), &[1]);
        let s = tr.samples(8, FrameKind::RotationMinimizing).unwrap();
        let corners: Vec<usize> = (0..s.len()).filter(|&i| s[i].corner).collect();
        assert_eq!(corners, vec![4]);
        let f = s[4].frame;
        assert_eq!(f.origin, DVec3::new(2.0, 0.0, 0.0));
        let m = f.miter.unwrap();
        assert!((m - DVec3::new(1.0, 1.0, 0.0).normalize()).length() < 1e-12);
    }

    #[test]
    fn bad_trajectories_are_refused_with_specific_messages() {
        let msg = |pts: &[DVec3], closed| match Trajectory::new(
            pts,
            closed,
            Interpolation::Spline,
            sharp(),
            &[],
        ) {
            Err(Error::InvalidArgument(m)) => m,
            other => panic!("expected an error, got {other:?}"),
        };
        assert!(msg(&[DVec3::ZERO], false).contains("at least 2 points"));
        assert!(msg(&[DVec3::ZERO, DVec3::X], true).contains("at least 3 points"));
        assert!(msg(&[DVec3::ZERO, DVec3::ZERO], false).contains("coincide"));
        assert!(msg(&[DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0)], false).contains("not finite"));
        assert!(msg(&[DVec3::ZERO, DVec3::X, DVec3::ZERO], false).contains("turns back"));
        assert!(msg(&[DVec3::ZERO, DVec3::X * 2.0, DVec3::X], false).contains("turns back"));
        let line = [DVec3::ZERO, DVec3::X, DVec3::X * 2.0];
        let tr = Trajectory::new(&line, false, Interpolation::Spline, sharp(), &[]).unwrap();
        let e = tr.samples(4, FrameKind::Frenet).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("undefined everywhere")));
        assert!(tr.samples(4, FrameKind::RotationMinimizing).is_ok());
    }
}
