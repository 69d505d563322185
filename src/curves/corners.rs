//! Corner detection on a point list, and one-sided tangent estimates.
//!
//! Two detectors, because the two kinds of input mean different things by their points, and
//! one test would change the result of the other (the default sharp angle is 30° for both):
//! - [`detect_corners`] (the planar profile silhouettes, open): the points are *samples* of a
//!   smooth outline that may have kinks, their spacing means nothing. A point is a corner
//!   where the outline's tangents on its two sides disagree: the tangent on each side is
//!   estimated from the parabola (chord-length parameter) through the point and its two
//!   neighbours on that side, or from the chord when only one neighbour exists. For densely
//!   sampled smooth curves the two estimates agree to second order, while at a real kink they
//!   differ by the kink's angle, so a coarsely sampled circle has no corner.
//! - [`detect_chord_corners`] (the sweep's profiles and trajectories, in space, open or
//!   closed): the points are the *vertices* of a polygon the user drew (a square or hexagonal
//!   section, an L-shaped rail, often 3 to 8 points). A vertex is a corner where the polygon
//!   turns by more than the sharp angle, whatever its neighbours. The parabola test would
//!   round such polygons off: its parabolas through three vertices follow the circumscribed
//!   circle, so a regular hexagon's middle vertices turn by about 22° there instead of 60°
//!   (see the test `the_two_detectors_answer_different_questions`).

use crate::math;
use glam::{DVec2, DVec3};

/// Unit tangent leaving point `i` towards increasing index (`forward`) or arriving from
/// decreasing index (`!forward`), both oriented along increasing index.
pub fn one_sided_tangent(points: &[DVec2], i: usize, forward: bool) -> DVec2 {
    one_sided_tangent_within(points, i, forward, &[])
}

/// [`one_sided_tangent`] that does not look across the `corners` (point indices): when the
/// neighbour on that side is a corner, the chord to it is used.
pub fn one_sided_tangent_within(
    points: &[DVec2],
    i: usize,
    forward: bool,
    corners: &[usize],
) -> DVec2 {
    let n = points.len();
    let (a, b, c) = if forward {
        if i + 1 >= n {
            return one_sided_tangent_within(points, i, false, corners);
        }
        (
            i,
            i + 1,
            (i + 2 < n && !corners.contains(&(i + 1))).then_some(i + 2),
        )
    } else {
        if i == 0 {
            return one_sided_tangent_within(points, i, true, corners);
        }
        (
            i,
            i - 1,
            i.checked_sub(2).filter(|_| !corners.contains(&(i - 1))),
        )
    };
    let sign = if forward { 1.0 } else { -1.0 };
    let (p0, p1) = (points[a], points[b]);
    let h1 = (p1 - p0).length();
    let d = match c {
        None => (p1 - p0) / h1,
        Some(c) => {
            // Parabola through p0 (param 0), p1 (h1), p2 (h1 + h2); derivative at 0.
            let p2 = points[c];
            let h2 = (p2 - p1).length();
            let t2 = h1 + h2;
            (p1 - p0) * (t2 / (h1 * h2)) - (p2 - p0) * (h1 / (t2 * h2))
        }
    };
    (d * sign).normalize_or_zero()
}

/// Turning angle (radians, `0..=π`) at interior point `i`: the smallest angle between an
/// arriving and a leaving tangent estimate, each either the chord or the parabola on that
/// side. Taking the smallest keeps a point next to a corner (whose parabola spans the
/// corner) from looking like a corner itself.
pub fn turning_angle(points: &[DVec2], i: usize) -> f64 {
    let chord = |j: usize| (points[j + 1] - points[j]).normalize_or_zero();
    let arriving = [chord(i - 1), one_sided_tangent(points, i, false)];
    let leaving = [chord(i), one_sided_tangent(points, i, true)];
    arriving
        .iter()
        .flat_map(|a| {
            leaving
                .iter()
                .map(move |b| math::acos(a.dot(*b).clamp(-1.0, 1.0)))
        })
        .fold(f64::INFINITY, f64::min)
}

/// Interior points whose turning angle exceeds `sharp_angle` (radians), in increasing order.
pub fn detect_corners(points: &[DVec2], sharp_angle: f64) -> Vec<usize> {
    (1..points.len().saturating_sub(1))
        .filter(|&i| turning_angle(points, i) > sharp_angle)
        .collect()
}

/// Turning angle (radians, `0..=π`) at point `i` between the incoming and the outgoing chord.
pub fn chord_turning_angle(points: &[DVec3], closed: bool, i: usize) -> f64 {
    let n = points.len();
    if !closed && (i == 0 || i == n - 1) {
        return 0.0;
    }
    let a = (points[i] - points[(i + n - 1) % n]).normalize();
    let b = (points[(i + 1) % n] - points[i]).normalize();
    math::atan2(a.cross(b).length(), a.dot(b))
}

/// Points whose chord turning angle exceeds `sharp_angle` (radians): interior points of an
/// open curve, any point of a closed one.
pub fn detect_chord_corners(points: &[DVec3], closed: bool, sharp_angle: f64) -> Vec<usize> {
    (0..points.len())
        .filter(|&i| chord_turning_angle(points, closed, i) > sharp_angle)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_two_detectors_answer_different_questions() {
        // Seven vertices of a regular hexagon (60° turns), as an open polygon.
        let hexagon: Vec<DVec2> = (0..=6)
            .map(|k| {
                let a = std::f64::consts::PI * k as f64 / 3.0;
                DVec2::new(math::cos(a), math::sin(a))
            })
            .collect();
        let lifted: Vec<DVec3> = hexagon.iter().map(|p| p.extend(0.0)).collect();
        let sharp = 30f64.to_radians();
        // Drawn polygon: every interior vertex turns by 60°.
        assert_eq!(
            detect_chord_corners(&lifted, false, sharp),
            vec![1, 2, 3, 4, 5]
        );
        let chord = chord_turning_angle(&lifted, false, 3).to_degrees();
        assert!((chord - 60.0).abs() < 1e-9, "{chord}");
        // Samples of a smooth outline: the parabolas follow the circle, no kink in the
        // middle; next to the ends one side has a single neighbour, whose chord is the estimate.
        assert_eq!(detect_corners(&hexagon, sharp), vec![1, 5]);
        let smooth = turning_angle(&hexagon, 3).to_degrees();
        assert!((smooth - 21.79).abs() < 0.01, "{smooth}");
    }

    #[test]
    fn finds_the_kink_of_a_double_cone_and_none_on_a_circle() {
        let cone: Vec<DVec2> = (0..=8)
            .map(|i| {
                let z = i as f64 / 8.0 * 2.0 - 1.0;
                DVec2::new(1.0 - z.abs(), z)
            })
            .collect();
        assert_eq!(detect_corners(&cone, 30f64.to_radians()), vec![4]);
        let angle = turning_angle(&cone, 4).to_degrees();
        assert!((angle - 90.0).abs() < 1e-9, "{angle}");
        let circle: Vec<DVec2> = (0..=16)
            .map(|i| {
                let a = std::f64::consts::PI * (i as f64 / 16.0 - 0.5);
                DVec2::new(math::cos(a), math::sin(a))
            })
            .collect();
        assert!(detect_corners(&circle, 10f64.to_radians()).is_empty());
        // The parabola estimate of a circle's end tangent is close to vertical... here the
        // circle starts at the bottom pole, where the tangent is horizontal.
        let t = one_sided_tangent(&circle, 0, true);
        assert!(t.y.abs() < 0.01 && t.x > 0.99, "{t}");
    }
}
