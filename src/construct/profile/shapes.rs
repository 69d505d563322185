//! Silhouettes of analytic shapes, for tests, benchmarks and demonstrations.

use super::input::ProfileInput;
use crate::math;

/// Silhouettes of the ellipsoid x²/a² + y²/b² + z²/c² = 1 centred at the origin, `m + 1`
/// points per curve (uniform in the polar angle), other settings at their defaults.
pub fn ellipsoid(a: f64, b: f64, c: f64, m: usize) -> ProfileInput {
    let curve = |r: f64| -> Vec<[f64; 2]> {
        (0..=m)
            .map(|i| {
                let phi = std::f64::consts::PI * i as f64 / m as f64;
                [r * math::sin(phi), -c * math::cos(phi)]
            })
            .collect()
    };
    ProfileInput::new(curve(a), curve(b))
}

/// Silhouettes of the double cone of radius `r` and half-height `h` (tips at z = ±h), `m`
/// intervals per half.
pub fn double_cone(r: f64, h: f64, m: usize) -> ProfileInput {
    let c: Vec<[f64; 2]> = (0..=2 * m)
        .map(|i| {
            let z = h * (i as f64 / m as f64 - 1.0);
            [r * (1.0 - z.abs() / h), z]
        })
        .collect();
    ProfileInput::new(c.clone(), c)
}
