//! The axis and the four quadrant sweeps of K. C. Hui and Y. H. Lai, "Generating subdivision
//! surfaces from profile curves", Computer-Aided Design 39 (2007), equations (1)–(4.3).
//!
//! At parameter `t` the four silhouettes give `c₁ = (x₁, z₁)`, `c₂ = (y₂, z₂)`,
//! `c₃ = (x₃, z₃)`, `c₄ = (y₄, z₄)`. The axis point is
//! `a = ((x₁ + x₃)/2, (y₂ + y₄)/2, (z₁ + z₂ + z₃ + z₄)/4)`, and with `q = 2θ/π` quadrant
//! `i` (`θ ∈ [(i−1)π/2, iπ/2)`) sweeps `cᵢ` into `cᵢ₊₁` about it:
//! - `x = ±(x₁ or x₃ − aₓ) cos θ + aₓ` (`x₁` in quadrants 1 and 4, `−(x₃ − aₓ)` in 2 and 3),
//! - `y = ±(y₂ or y₄ − a_y) sin θ + a_y` (`y₂` in quadrants 1 and 2, `−(y₄ − a_y)` in 3
//!   and 4),
//! - `z = zᵢ + (q − (i − 1)) (zᵢ₊₁ − zᵢ)` (heights blended linearly across the quadrant).

use crate::math;
use std::f64::consts::{FRAC_PI_2, PI};

use glam::{DVec2, DVec3};

/// The axis point `a(t)` (1.1)–(1.3) from the four curve points `(w, z)` at `t`.
pub fn axis(c: &[DVec2; 4]) -> DVec3 {
    DVec3::new(
        (c[0].x + c[2].x) / 2.0,
        (c[1].x + c[3].x) / 2.0,
        (c[0].y + c[1].y + c[2].y + c[3].y) / 4.0,
    )
}

/// The blended surface point `s(θ, t)` from the four curve points at `t`; `θ` in radians,
/// taken modulo 2π. Quadrant `i` (`θ ∈ [(i−1)π/2, iπ/2)`) sweeps `cᵢ` into `cᵢ₊₁`.
pub fn surface(theta: f64, c: &[DVec2; 4]) -> DVec3 {
    let a = axis(c);
    let theta = theta.rem_euclid(2.0 * PI);
    let (sin, cos) = math::sin_cos(theta);
    let q = theta / FRAC_PI_2;
    let (c1, c2, c3, c4) = (c[0], c[1], c[2], c[3]);
    if theta < FRAC_PI_2 {
        DVec3::new(
            (c1.x - a.x) * cos + a.x,
            (c2.x - a.y) * sin + a.y,
            c1.y + q * (c2.y - c1.y),
        )
    } else if theta < PI {
        DVec3::new(
            -(c3.x - a.x) * cos + a.x,
            (c2.x - a.y) * sin + a.y,
            c2.y + (q - 1.0) * (c3.y - c2.y),
        )
    } else if theta < 3.0 * FRAC_PI_2 {
        DVec3::new(
            -(c3.x - a.x) * cos + a.x,
            -(c4.x - a.y) * sin + a.y,
            c3.y + (q - 2.0) * (c4.y - c3.y),
        )
    } else {
        DVec3::new(
            (c1.x - a.x) * cos + a.x,
            -(c4.x - a.y) * sin + a.y,
            c4.y + (q - 3.0) * (c1.y - c4.y),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passes_through_the_silhouettes_and_reproduces_an_ellipse() {
        let (a, b, z) = (2.0, 1.0, 0.3);
        let c = [
            DVec2::new(a, z),
            DVec2::new(b, z),
            DVec2::new(-a, z),
            DVec2::new(-b, z),
        ];
        assert_eq!(surface(0.0, &c), DVec3::new(a, 0.0, z));
        assert!((surface(FRAC_PI_2, &c) - DVec3::new(0.0, b, z)).length() < 1e-15);
        assert!((surface(PI, &c) - DVec3::new(-a, 0.0, z)).length() < 1e-15);
        assert!((surface(3.0 * FRAC_PI_2, &c) - DVec3::new(0.0, -b, z)).length() < 1e-15);
        for k in 0..64 {
            let p = surface(k as f64 * 0.1, &c);
            assert!(((p.x / a).powi(2) + (p.y / b).powi(2) - 1.0).abs() < 1e-14);
            assert_eq!(p.z, z);
        }
        // Off-centre silhouettes and different heights: z blends linearly per quadrant.
        let c = [
            DVec2::new(3.0, 0.0),
            DVec2::new(2.0, 1.0),
            DVec2::new(1.0, 2.0),
            DVec2::new(0.0, 3.0),
        ];
        let p = surface(FRAC_PI_2 * 0.5, &c);
        assert!((p.z - 0.5).abs() < 1e-15);
        assert!((axis(&c) - DVec3::new(2.0, 1.0, 1.5)).length() < 1e-15);
        let p = surface(PI, &c);
        assert!((p - DVec3::new(1.0, 1.0, 2.0)).length() < 1e-15);
    }
}
