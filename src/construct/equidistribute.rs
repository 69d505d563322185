//! Ring spacing that follows the profile's curvature.
//!
//! Rings uniform in arc length under-resolve a profile whose curvature varies a lot: the rim
//! of an oblate ellipsoid (3, 2, 0.75) has a curvature radius of 0.19 against 12 at its poles,
//! and its error there dominates. The interpolation error of a curved stretch sampled at step
//! `h` grows with its curvature `κ`, so rings are placed to equidistribute the density
//! `ρ = 1 + (κ / κ̄)^p` per unit arc length, `κ̄` being the mean curvature of the stretch (its
//! turning over its length) and `p` [`CURVATURE_EXPONENT`]: a circle or a straight line keeps
//! uniform rings, a sharply turning part gets up to `(κ / κ̄)^p` times more. The density is
//! bounded below by 1, so the map stays a smooth reparameterization with positive slope.
//!
//! [`ring_parameters`] places the rings of a stretch between breakpoints this way, and
//! [`place_samples`] does it for every run of a curve's samples, both only mildly denser
//! towards smooth poles ([`pole_graded`]): the pole caps ([`crate::construct::pole_cap`])
//! replace several rings, so the mesh stays quasi-uniform there (rings graded to `O(h²)` next
//! to a pole made the interpolating fit fold; see the README, "Valid surfaces").

use crate::math;
use glam::DVec2;

use crate::curves::CurveSample;

/// Exponent `p` of the curvature ratio in the ring density. A curved stretch of step `h`
/// leaves an error of about `h⁴ κ³`, equal everywhere when `h ∝ κ^(-3/4)`. Measured on the
/// oblate (3, 2, 0.75) at 32 × 16: 2.0e-4 of its size, then 23× and 12× per doubling (with
/// `p = 0.5`, 512 probes: 5.9e-5, then only 5.4× and 28×).
pub const CURVATURE_EXPONENT: f64 = 0.75;

/// Probe intervals per ring interval on which the density is measured (at least
/// [`MIN_PROBES`] per stretch), so the piecewise linear map is smooth at the scale of the
/// rings. With 4 the ellipsoids' rates wandered (8× instead of 15× per doubling for
/// (1, 1, 5)); 8 probes per ring add about 3 ms to the bottle's 25 ms at 128 × 64 (each probe
/// is four height searches in the profile pipeline).
pub const PROBES_PER_RING: usize = 8;

/// Total turning (radians) up to which a stretch counts as straight and keeps uniform rings.
/// Rounding alone gives a straight stretch a turning of 1e-15 to 1e-12 that depends on where
/// it lies (a profile moved along the axis, or scaled); the density normalizes the turning
/// by itself, so that noise was weighted as real curvature and the same shape moved
/// elsewhere got other rings (1e-2 of its size apart). A floor under `κ̄` instead of this
/// cut still left (noise / floor)^p, 1e-6. A stretch turning less than 1e-6 radians in all is
/// straight for any model; one turning more is weighted as before.
pub const MIN_TURNING: f64 = 1e-6;

/// Fewest probe intervals of a stretch.
pub const MIN_PROBES: usize = 64;

/// Number of probe intervals for a stretch of `rings` ring intervals.
pub fn probe_count(rings: usize) -> usize {
    (PROBES_PER_RING * rings).max(MIN_PROBES)
}

/// A monotone map from a stretch's uniform fraction `u ∈ [0, 1]` to the fraction `σ` of its
/// curvature-weighted length, piecewise linear between probes.
#[derive(Debug, Clone)]
pub struct Equidistribution {
    /// Cumulative weighted length at each probe, normalized to end at 1.
    sigma: Vec<f64>,
}

impl Equidistribution {
    /// The map of a stretch traced by one or more curves, each sampled at the same `n + 1`
    /// fractions `u = m / n` (`curves[k][m]`, `n >= 1`); the curves' densities are added.
    pub fn new(curves: &[Vec<DVec2>]) -> Equidistribution {
        let n = curves.first().map_or(1, |c| c.len().max(2) - 1);
        let mut cost = vec![0.0; n];
        for p in curves {
            add_density(p, &mut cost);
        }
        let total: f64 = cost.iter().sum();
        let mut sigma = Vec::with_capacity(n + 1);
        sigma.push(0.0);
        let mut acc = 0.0;
        for (m, c) in cost.iter().enumerate() {
            // A degenerate stretch (all curves a single point) stays uniform.
            acc += if total > 0.0 {
                c / total
            } else {
                1.0 / n as f64
            };
            sigma.push(if m + 1 == n { 1.0 } else { acc });
        }
        Equidistribution { sigma }
    }

    /// The fraction `u` whose weighted fraction is `s ∈ [0, 1]`.
    pub fn inverse(&self, s: f64) -> f64 {
        let s = s.clamp(0.0, 1.0);
        let n = self.sigma.len() - 1;
        let m = (self.sigma.partition_point(|&v| v <= s).max(1) - 1).min(n - 1);
        let (a, b) = (self.sigma[m], self.sigma[m + 1]);
        let f = if b > a { (s - a) / (b - a) } else { 0.0 };
        (m as f64 + f) / n as f64
    }
}

/// Ring spacing at a smooth pole relative to the stretch's mean ([`pole_graded`]).
pub const POLE_SPACING: f64 = 0.5;

/// The position of the uniform fraction `u ∈ [0, 1]` of a stretch whose ends at `u = 0` and
/// `u = 1` are smooth poles where `poles` says so: a cubic with slope [`POLE_SPACING`] at a
/// pole and 1 at another end (`u` without poles), increasing. Mild on purpose: it halves the
/// rings' spacing near a pole, where the caps' valence-3 corners leave an `O(κh²)` error,
/// but keeps neighbouring rings within a factor 2 of each other (grading to zero slope put
/// the first ring `O(h²)` from the pole, and the fit folded in the tiny cap).
pub fn pole_graded(u: f64, poles: [bool; 2]) -> f64 {
    let c = POLE_SPACING - 1.0;
    match poles {
        [true, true] => u + c * u * (1.0 - u) * (1.0 - 2.0 * u),
        [true, false] => u + c * u * (1.0 - u) * (1.0 - u),
        [false, true] => u - c * u * u * (1.0 - u),
        [false, false] => u,
    }
}

/// Parameters of the `rings + 1` rings of a stretch `range` of a curve parameter (ends
/// included) between breakpoints: uniform in the curvature-weighted length of the curves
/// traced by `points`, mildly denser towards a smooth pole at the start when `poles[0]` and
/// at the end when `poles[1]` ([`pole_graded`]).
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
        .map(|i| a + (b - a) * eq.inverse(pole_graded(i as f64 / rings as f64, poles)))
        .collect()
}

/// Replace curve samples (uniform within each run between corner samples, first and last
/// sample included) by [`ring_parameters`] of each run of the curve `point(s)`, the first run
/// graded towards a smooth pole at the first sample when `poles[0]`, the last towards the
/// last sample when `poles[1]`.
pub fn place_samples(samples: &mut [CurveSample], poles: [bool; 2], point: impl Fn(f64) -> DVec2) {
    let n = samples.len();
    let breaks: Vec<usize> = (0..n)
        .filter(|&i| i == 0 || i + 1 == n || samples[i].corner)
        .collect();
    let runs = breaks.len().saturating_sub(1);
    for (r, w) in breaks.windows(2).enumerate() {
        let range = [samples[w[0]].s, samples[w[1]].s];
        let ends = [r == 0 && poles[0], r + 1 == runs && poles[1]];
        let s = ring_parameters(range, w[1] - w[0], ends, |s| [point(s)]);
        for (sample, &s) in samples[w[0] + 1..w[1]].iter_mut().zip(&s[1..]) {
            sample.s = s;
        }
    }
}

/// Add the weighted length `ds (1 + (κ / κ̄)^p)` of each probe interval of polyline `p`.
fn add_density(p: &[DVec2], cost: &mut [f64]) {
    let ds: Vec<f64> = p.windows(2).map(|w| (w[1] - w[0]).length()).collect();
    // Turning angle at each probe point, the ends taking their neighbour's.
    let n = p.len();
    let mut turn = vec![0.0; n];
    for m in 1..n - 1 {
        let (a, b) = (p[m] - p[m - 1], p[m + 1] - p[m]);
        if a.length() > 0.0 && b.length() > 0.0 {
            turn[m] = math::atan2(a.perp_dot(b), a.dot(b)).abs();
        }
    }
    if n > 2 {
        turn[0] = turn[1];
        turn[n - 1] = turn[n - 2];
    }
    // Each interval takes half of each end's turning.
    let tau: Vec<f64> = turn.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let length: f64 = ds.iter().sum();
    let turning: f64 = tau.iter().sum();
    for (m, c) in cost.iter_mut().enumerate() {
        *c += ds[m];
        if turning > MIN_TURNING && ds[m] > 0.0 {
            let ratio = tau[m] / ds[m] * length / turning;
            *c += ds[m] * math::powf(ratio, CURVATURE_EXPONENT);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PROBES: usize = 512;

    fn arc(r: f64, a0: f64, a1: f64) -> Vec<DVec2> {
        (0..=PROBES)
            .map(|m| {
                let a = a0 + (a1 - a0) * m as f64 / PROBES as f64;
                DVec2::new(r * math::cos(a), r * math::sin(a))
            })
            .collect()
    }

    #[test]
    fn circles_and_lines_stay_uniform() {
        let line: Vec<DVec2> = (0..=PROBES)
            .map(|m| DVec2::new(2.0, 3.0) * (m as f64 / PROBES as f64))
            .collect();
        for e in [
            Equidistribution::new(&[arc(2.0, -1.0, 1.0)]),
            Equidistribution::new(&[line]),
        ] {
            for q in 0..=10 {
                let s = q as f64 / 10.0;
                assert!((e.inverse(s) - s).abs() < 1e-9, "{s}: {}", e.inverse(s));
            }
        }
    }

    #[test]
    fn rings_gather_where_the_curve_turns() {
        // A quarter of a flat ellipse, from its tip (curvature 12, u = 0) to its flank.
        let p: Vec<DVec2> = (0..=PROBES)
            .map(|m| {
                let a = std::f64::consts::FRAC_PI_2 * m as f64 / PROBES as f64;
                DVec2::new(3.0 * math::cos(a), 0.5 * math::sin(a))
            })
            .collect();
        let arc_to = |u: f64| -> f64 {
            let k = (u * PROBES as f64).round() as usize;
            p[..=k].windows(2).map(|w| (w[1] - w[0]).length()).sum()
        };
        let length = arc_to(1.0);
        let e = Equidistribution::new(std::slice::from_ref(&p));
        assert_eq!(e.inverse(0.0), 0.0);
        assert_eq!(e.inverse(1.0), 1.0);
        assert!((0..100).all(|q| e.inverse((q + 1) as f64 / 100.0) > e.inverse(q as f64 / 100.0)));
        // The first tenth of the rings spans much less than a tenth of the arc, the last
        // tenth more.
        let first = arc_to(e.inverse(0.1)) / length;
        let last = 1.0 - arc_to(e.inverse(0.9)) / length;
        assert!(first < 0.05 && last > 0.1, "{first} {last}");
    }

    #[test]
    fn pole_grading_is_mild_and_monotone() {
        let d = 1e-7;
        for poles in [[true, true], [true, false], [false, true], [false, false]] {
            assert_eq!(pole_graded(0.0, poles), 0.0);
            assert!((pole_graded(1.0, poles) - 1.0).abs() < 1e-15);
            let slope = |u: f64| (pole_graded(u + d, poles) - pole_graded(u, poles)) / d;
            let expect = |pole: bool| if pole { POLE_SPACING } else { 1.0 };
            assert!((slope(0.0) - expect(poles[0])).abs() < 1e-6, "{poles:?}");
            assert!(
                (slope(1.0 - d) - expect(poles[1])).abs() < 1e-6,
                "{poles:?}"
            );
            // Neighbouring spacings stay within a factor 2 and positive.
            assert!((0..100).all(|i| {
                let s = slope(i as f64 / 100.0);
                (0.49..=1.5).contains(&s)
            }));
        }
    }

    #[test]
    fn samples_are_placed_per_run_between_corners() {
        let samples = |corner_at: usize| -> Vec<CurveSample> {
            (0..=8)
                .map(|i| CurveSample {
                    s: 2.0 * i as f64,
                    corner: i == corner_at,
                })
                .collect()
        };
        // A straight curve: the spacing stays uniform in each run.
        let line = |s: f64| DVec2::new(1.0, 2.0) * s;
        let mut s = samples(4);
        place_samples(&mut s, [false; 2], line);
        let got: Vec<f64> = s.iter().map(|c| c.s).collect();
        let expect: Vec<f64> = (0..=8).map(|i| 2.0 * i as f64).collect();
        assert!(got.iter().zip(&expect).all(|(a, b)| (a - b).abs() < 1e-12));
        // A quarter circle then a straight run, split at a corner: each run keeps its ends,
        // the circle stays uniform in angle (its density is constant).
        let bend = |s: f64| {
            if s <= 8.0 {
                let a = s / 8.0 * std::f64::consts::FRAC_PI_2;
                DVec2::new(math::cos(a), math::sin(a))
            } else {
                DVec2::new(-(s - 8.0), 1.0)
            }
        };
        let mut s = samples(4);
        s[2].s = 1.0;
        place_samples(&mut s, [false; 2], bend);
        assert_eq!((s[0].s, s[4].s, s[8].s), (0.0, 8.0, 16.0));
        assert!((s[2].s - 4.0).abs() < 1e-9, "{}", s[2].s);
        assert!((s[6].s - 12.0).abs() < 1e-9, "{}", s[6].s);
    }
}
