//! The swept profile: a planar curve in the frame's (normal, binormal) plane, optionally
//! morphing into a second profile with the same point count.

use glam::{DVec2, DVec3};

use crate::curves::corners::detect_chord_corners;
use crate::curves::{Interpolation, SpaceCurve};
use crate::error::{Error, Result};

/// A validated profile (and its optional end profile).
#[derive(Debug, Clone, PartialEq)]
pub struct SweptProfile {
    start: SpaceCurve,
    end: Option<SpaceCurve>,
}

/// The profile sampled once: the sample points of the start and end profiles.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileSamples {
    /// Sample points of the start profile, `(a, b)`.
    pub start: Vec<DVec2>,
    /// Sample points of the end profile at the same places (a copy of `start` without one).
    pub end: Vec<DVec2>,
    /// Indices of the samples that are profile corners.
    pub corners: Vec<usize>,
    /// Whether the profile is closed.
    pub closed: bool,
    /// Whether a closed profile runs clockwise in the (a, b) plane.
    pub clockwise: bool,
}

impl ProfileSamples {
    /// The profile at `fraction` (`0..=1`) of the way from start to end, scaled by `scale`.
    pub fn at(&self, fraction: f64, scale: f64) -> impl Iterator<Item = DVec2> + '_ {
        self.start
            .iter()
            .zip(&self.end)
            .map(move |(a, b)| scale * a.lerp(*b, fraction))
    }
}

fn lift(points: &[[f64; 2]]) -> Vec<DVec3> {
    points.iter().map(|p| DVec3::new(p[0], p[1], 0.0)).collect()
}

impl SweptProfile {
    /// Validate the profile points (and `end`, which must have as many points) and build
    /// the curves. A point turning by more than `sharp_angle` (radians) in either profile, or
    /// listed in `forced`, is a corner of both, so that the crease runs the whole length of the
    /// sweep.
    ///
    /// Errors ([`Error::InvalidArgument`]): those of [`SpaceCurve::new`], a different point
    /// count for `end`, a profile whose polygon crosses itself.
    pub fn new(
        points: &[[f64; 2]],
        end: Option<&[[f64; 2]]>,
        closed: bool,
        interpolation: Interpolation,
        sharp_angle: f64,
        forced: &[usize],
    ) -> Result<SweptProfile> {
        let start = lift(points);
        // Validate before looking at angles and crossings.
        SpaceCurve::new("profile", &start, closed, Interpolation::Polyline, &[])?;
        check_no_crossing("profile", points, closed)?;
        let mut corners = detect_chord_corners(&start, closed, sharp_angle);
        corners.extend_from_slice(forced);
        let end = match end {
            None => None,
            Some(e) => {
                if e.len() != points.len() {
                    return Err(Error::invalid_argument(format!(
                        "profile_end has {} points; it must have as many as profile ({})",
                        e.len(),
                        points.len()
                    )));
                }
                let e3 = lift(e);
                SpaceCurve::new("profile_end", &e3, closed, Interpolation::Polyline, &[])?;
                check_no_crossing("profile_end", e, closed)?;
                corners.extend(detect_chord_corners(&e3, closed, sharp_angle));
                Some(e3)
            }
        };
        let start = SpaceCurve::new("profile", &start, closed, interpolation, &corners)?;
        let end = match end {
            Some(e) => Some(SpaceCurve::new(
                "profile_end",
                &e,
                closed,
                interpolation,
                start.corners(),
            )?),
            None => None,
        };
        Ok(SweptProfile { start, end })
    }

    /// The start profile's curve.
    pub fn curve(&self) -> &SpaceCurve {
        &self.start
    }

    /// Sample with `segments` intervals (see [`SpaceCurve::sample_parameters`]); the end
    /// profile is sampled at the same span and local fraction.
    pub fn sample(&self, segments: usize) -> Result<ProfileSamples> {
        let params = self.start.sample_parameters("profile", segments)?;
        let start: Vec<DVec2> = params
            .iter()
            .map(|c| self.start.eval(c.s, false).position.truncate())
            .collect();
        let end = match &self.end {
            None => start.clone(),
            Some(e) => params
                .iter()
                .map(|c| {
                    let (i, u) = self.start.span_of(c.s);
                    e.eval_in_span(i, u).truncate()
                })
                .collect(),
        };
        let corners = (0..params.len()).filter(|&i| params[i].corner).collect();
        let closed = self.start.is_closed();
        let area: f64 = (0..start.len())
            .map(|i| start[i].perp_dot(start[(i + 1) % start.len()]))
            .sum();
        Ok(ProfileSamples {
            start,
            end,
            corners,
            closed,
            clockwise: closed && area < 0.0,
        })
    }
}

/// Error if two non-adjacent segments of the input polygon intersect (or touch).
pub(crate) fn check_no_crossing(what: &str, points: &[[f64; 2]], closed: bool) -> Result<()> {
    let p: Vec<DVec2> = points.iter().map(|&q| DVec2::from(q)).collect();
    let n = p.len();
    let segs = if closed { n } else { n - 1 };
    for i in 0..segs {
        for j in i + 2..segs {
            if closed && i == 0 && j == n - 1 {
                continue; // adjacent through the closing point
            }
            if segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]) {
                return Err(Error::invalid_argument(format!(
                    "{what} crosses itself: segment {i}-{} meets segment {j}-{}",
                    (i + 1) % n,
                    (j + 1) % n
                )));
            }
        }
    }
    Ok(())
}

/// Whether closed segments `ab` and `cd` share a point.
fn segments_meet(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let orient = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let on = |p: DVec2, q: DVec2, r: DVec2| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    (d1 == 0.0 && on(c, d, a))
        || (d2 == 0.0 && on(c, d, b))
        || (d3 == 0.0 && on(a, b, c))
        || (d4 == 0.0 && on(a, b, d))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: [[f64; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];

    #[test]
    fn square_profile_samples_have_four_corners_and_orientation() {
        let p = SweptProfile::new(&SQUARE, None, true, Interpolation::Spline, 0.5, &[]).unwrap();
        let s = p.sample(8).unwrap();
        assert_eq!(s.corners, vec![0, 2, 4, 6]);
        assert!(!s.clockwise);
        assert_eq!(s.start[1], DVec2::new(0.0, -1.0));
        let rev: Vec<[f64; 2]> = SQUARE.iter().rev().copied().collect();
        let s = SweptProfile::new(&rev, None, true, Interpolation::Spline, 0.5, &[])
            .unwrap()
            .sample(8)
            .unwrap();
        assert!(s.clockwise);
    }

    #[test]
    fn morph_and_scale_interpolate_between_profiles() {
        let big: Vec<[f64; 2]> = SQUARE.iter().map(|p| [3.0 * p[0], 2.0 * p[1]]).collect();
        let p =
            SweptProfile::new(&SQUARE, Some(&big), true, Interpolation::Spline, 0.5, &[]).unwrap();
        let s = p.sample(8).unwrap();
        assert_eq!(s.end[1], DVec2::new(0.0, -2.0));
        assert_eq!(s.end[2], DVec2::new(3.0, -2.0));
        let half: Vec<DVec2> = s.at(0.5, 2.0).collect();
        assert_eq!(half[2], DVec2::new(4.0, -3.0));
        let e = SweptProfile::new(
            &SQUARE,
            Some(&big[..3]),
            true,
            Interpolation::Spline,
            0.5,
            &[],
        )
        .unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("as many")));
    }

    #[test]
    fn crossing_profiles_are_refused() {
        let bow = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        let e = SweptProfile::new(&bow, None, true, Interpolation::Spline, 0.5, &[]).unwrap_err();
        assert!(
            matches!(e, Error::InvalidArgument(m) if m.contains("crosses itself: segment 0-1 meets segment 2-3"))
        );
        // A closed triangle does not cross itself (its closing segment is adjacent to both).
        assert!(SweptProfile::new(
            &[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0]],
            None,
            true,
            Interpolation::Spline,
            0.5,
            &[]
        )
        .is_ok());
        let touch = [[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [1.0, 0.0], [1.0, -1.0]];
        assert!(SweptProfile::new(&touch, None, false, Interpolation::Spline, 0.5, &[]).is_err());
    }
}
