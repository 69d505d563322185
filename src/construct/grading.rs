//! Ring spacing graded towards smooth poles.
//!
//! A smooth pole is closed by a grid cap ([`crate::construct::pole_cap`]) filling the ring
//! next to the pole; the cap's four corners are valence-3 vertices. Around a valence-3 vertex
//! Catmull-Clark cannot follow a curved surface to second order (its subsubdominant
//! eigenvalue, 1/6, lies below the square of the subdominant one, λ² ≈ 0.168), so an
//! interpolating fit leaves a deviation of about `κ h²` there, `h` being the local mesh
//! size: with uniform rings the largest error of a sphere falls only ~3.9× per doubling of the
//! sample counts, against ~16× everywhere else.
//!
//! Grading makes that local size shrink faster than the global one: within a segment that
//! ends at a smooth pole, ring `i` of `c` sits at the fraction `g(i / c)` of the segment
//! (of its curvature-weighted length, [`crate::construct::equidistribute`]), where `g` has
//! zero slope at the pole. The first ring, and the cap inside it, then lie
//! `O(h²)` from the pole, the error next to the valence-3 vertices becomes `O(h⁴)` like the
//! rest, and the rings stay a smooth (polynomial) reparameterization of the surface, which
//! keeps the fourth-order error elsewhere. At the other end `g` has slope 1 (that end is a
//! crease ring or an open boundary, where uniform spacing continues) or 0 (another pole).

use glam::DVec2;

use crate::construct::equidistribute::{probe_count, Equidistribution};
use crate::curves::CurveSample;

/// The graded position of the uniform fraction `u ∈ [0, 1]` of a segment whose ends at
/// `u = 0` and `u = 1` are smooth poles where `poles` says so: `3u² − 2u³` between two
/// poles, `u²(2 − u)` from a pole at `u = 0` (mirrored for a pole at `u = 1`), `u` without.
pub fn graded(u: f64, poles: [bool; 2]) -> f64 {
    match poles {
        [true, true] => u * u * (3.0 - 2.0 * u),
        [true, false] => u * u * (2.0 - u),
        [false, true] => {
            let w = 1.0 - u;
            1.0 - w * w * (2.0 - w)
        }
        [false, false] => u,
    }
}

/// Parameters of the `rings + 1` rings of a stretch `range` of a curve parameter (ends
/// included) between breakpoints: uniform in the curvature-weighted length of the curves
/// traced by `points` ([`crate::construct::equidistribute`]), graded towards a smooth pole at
/// the start when `poles[0]` and at the end when `poles[1]`.
pub fn ring_parameters<const K: usize>(
    range: [f64; 2],
    rings: usize,
    poles: [bool; 2],
    points: impl Fn(f64) -> [DVec2; K],
) -> Vec<f64> {
    let [a, b] = range;
    let n = probe_count(rings);
    let probes: Vec<[DVec2; K]> = (0..=n)
        .map(|m| points(a + (b - a) * m as f64 / n as f64))
        .collect();
    let curves: Vec<Vec<DVec2>> = (0..K)
        .map(|k| probes.iter().map(|p| p[k]).collect())
        .collect();
    let eq = Equidistribution::new(&curves);
    (0..=rings)
        .map(|i| a + (b - a) * eq.inverse(graded(i as f64 / rings as f64, poles)))
        .collect()
}

/// Replace curve samples (uniform within each run between corner samples, first and last
/// sample included) by [`ring_parameters`] of each run of the curve `point(s)`, the first run
/// graded towards a smooth pole at the first sample when `poles[0]`, and the last run towards
/// the last sample when `poles[1]`.
pub fn grade_samples(samples: &mut [CurveSample], poles: [bool; 2], point: impl Fn(f64) -> DVec2) {
    let n = samples.len();
    let breaks: Vec<usize> = (0..n)
        .filter(|&i| i == 0 || i + 1 == n || samples[i].corner)
        .collect();
    let runs = breaks.len().saturating_sub(1);
    for (r, w) in breaks.windows(2).enumerate() {
        let ends = [r == 0 && poles[0], r + 1 == runs && poles[1]];
        let range = [samples[w[0]].s, samples[w[1]].s];
        let s = ring_parameters(range, w[1] - w[0], ends, |s| [point(s)]);
        for (sample, &s) in samples[w[0] + 1..w[1]].iter_mut().zip(&s[1..]) {
            sample.s = s;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grading_fixes_the_ends_and_flattens_at_poles() {
        let d = 1e-6;
        for poles in [[true, true], [true, false], [false, true], [false, false]] {
            assert_eq!(graded(0.0, poles), 0.0);
            assert_eq!(graded(1.0, poles), 1.0);
            // Increasing.
            assert!((0..100)
                .all(|i| graded((i + 1) as f64 / 100.0, poles) > graded(i as f64 / 100.0, poles)));
            // Slope 0 at a pole, 1 at a free end (one-sided differences).
            let slope0 = graded(d, poles) / d;
            let slope1 = (1.0 - graded(1.0 - d, poles)) / d;
            let expect = |pole: bool| if pole { 0.0 } else { 1.0 };
            assert!((slope0 - expect(poles[0])).abs() < 1e-5, "{poles:?}");
            assert!((slope1 - expect(poles[1])).abs() < 1e-5, "{poles:?}");
        }
    }

    #[test]
    fn samples_are_graded_only_in_runs_touching_a_pole() {
        let uniform = |corner_at: usize| -> Vec<CurveSample> {
            (0..=8)
                .map(|i| CurveSample {
                    s: 2.0 * i as f64,
                    corner: i == corner_at,
                })
                .collect()
        };
        // A straight curve: the curvature weighting leaves the spacing as it is.
        let line = |s: f64| DVec2::new(1.0, 2.0) * s;
        let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12);
        let mut s = uniform(4);
        grade_samples(&mut s, [true, false], line);
        let got: Vec<f64> = s.iter().map(|c| c.s).collect();
        let first: Vec<f64> = (0..=4)
            .map(|i| 8.0 * graded(i as f64 / 4.0, [true, false]))
            .collect();
        assert!(close(&got[..5], &first), "{got:?}");
        assert!(close(&got[4..], &[8.0, 10.0, 12.0, 14.0, 16.0]), "{got:?}");
        let mut s = uniform(99);
        grade_samples(&mut s, [true, true], line);
        assert!((s[4].s - 8.0).abs() < 1e-12);
        assert!((s[1].s - 16.0 * graded(0.125, [true, true])).abs() < 1e-12);
        // The first ring moves to a third of its uniform distance from the pole.
        assert!(s[1].s < 0.35 * 2.0);
    }
}
