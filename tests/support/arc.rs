//! Sampled circular arcs for tests: `mod arc;` via `#[path = "support/arc.rs"]`.
// Reference geometry for tolerance checks: the platform's libm is fine here.
#![allow(clippy::disallowed_methods)]

/// `n + 1` points of the circle of radius `r` about the origin, from angle `from` to `to`.
pub fn arc(n: usize, r: f64, from: f64, to: f64) -> Vec<[f64; 2]> {
    (0..=n)
        .map(|i| {
            let t = from + (to - from) * i as f64 / n as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// A revolution profile of the unit sphere: `n + 1` points of the half circle from the south
/// pole to the north pole, its two ends exactly on the axis.
pub fn semicircle(n: usize) -> Vec<[f64; 2]> {
    let half = std::f64::consts::FRAC_PI_2;
    let mut points = arc(n, 1.0, -half, half);
    points[0][0] = 0.0;
    points[n][0] = 0.0;
    points
}
