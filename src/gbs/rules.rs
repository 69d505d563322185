//! Pure generalized B-spline (GBS) rules: the tension update, the curve refinement of order
//! k with tension v, and the surface masks (edge, vertex, face-corner, averaging) that
//! generalize it to quad meshes of arbitrary topology. No topology here.
//!
//! One step of order k with tension v has the mask
//! `a(z) = (1+z)^{k−2} (1 + 2vz + z²) / (2^{k−2} (1+v))`: only one factor depends on v.
//! The curve is exact on span{1, t, …, t^{k−3}, cos ωt, sin ωt} with v₀ = cos(ωΔ/2) for
//! level-0 knot spacing Δ (cosh for imaginary ω, 1 for polynomials), and the tension of the
//! next level is `√((1+v)/2)` (Warren & Weimer 2002, p. 115, stored one level later).

use glam::DVec3;

use crate::math::{acos, cos, sin};

/// Smallest order accepted.
pub const MIN_ORDER: u32 = 3;
/// Largest order accepted.
pub const MAX_ORDER: u32 = 8;

/// The tension of the next level: `v_{l+1} = √((1 + v_l)/2)` (half-angle formula of cos and
/// cosh).
pub fn next_tension(v: f64) -> f64 {
    ((1.0 + v) / 2.0).sqrt()
}

/// The tension of level `level` from the level-0 tension `v0`.
pub fn tension_at(v0: f64, level: u32) -> f64 {
    (0..level).fold(v0, |v, _| next_tension(v))
}

/// One refinement of a closed polygon of order `k` with tension `v`, written as
/// Lane–Riesenfeld: duplicate every point, average neighbours `k − 1` times, the last two
/// averages followed by the tension correction `q = 2r/(1+v) − (1−v)/(1+v)·p` (`p` the point
/// the two averages centre on). At `v = 1` the correction is `q = 1·r − 0·p`, so the result
/// is Lane–Riesenfeld's bit for bit. Output point `j` is the average of duplicated points
/// `j ..= j + k − 1` (cyclically), the same alignment as plain Lane–Riesenfeld.
pub fn refine_closed_curve(points: &[DVec3], k: u32, v: f64) -> Vec<DVec3> {
    let n = points.len() * 2;
    let mut q: Vec<DVec3> = points.iter().flat_map(|&p| [p, p]).collect();
    for _ in 0..k - 3 {
        q = (0..n).map(|j| (q[j] + q[(j + 1) % n]) / 2.0).collect();
    }
    let once: Vec<DVec3> = (0..n).map(|j| (q[j] + q[(j + 1) % n]) / 2.0).collect();
    let (w, c) = tension_correction(v);
    (0..n)
        .map(|j| (once[j] + once[(j + 1) % n]) / 2.0 * w - q[(j + 1) % n] * c)
        .collect()
}

/// One refinement of an open polygon: the closed rule where the whole support lies inside
/// the polygon (no points are invented beyond the ends), and for even `k` the end points
/// kept (the boundary curve of a surface ends at a corner that does not move). An open
/// polygon of `m` points gives `2m − k + 1` inner points, plus the two ends for even `k`.
pub fn refine_open_curve(points: &[DVec3], k: u32, v: f64) -> Vec<DVec3> {
    let n = points.len() * 2;
    let mut q: Vec<DVec3> = points.iter().flat_map(|&p| [p, p]).collect();
    for _ in 0..k - 3 {
        q = (0..q.len() - 1).map(|j| (q[j] + q[j + 1]) / 2.0).collect();
    }
    let once: Vec<DVec3> = (0..q.len() - 1).map(|j| (q[j] + q[j + 1]) / 2.0).collect();
    let (w, c) = tension_correction(v);
    let inner = (0..once.len() - 1).map(|j| (once[j] + once[j + 1]) / 2.0 * w - q[j + 1] * c);
    debug_assert_eq!(once.len() - 1, n - k as usize + 1);
    if k % 2 == 0 {
        let (first, last) = (points[0], points[points.len() - 1]);
        std::iter::once(first)
            .chain(inner)
            .chain(std::iter::once(last))
            .collect()
    } else {
        inner.collect()
    }
}

/// `(2/(1+v), (1−v)/(1+v))`: the tension step `(p₋ + 2v·p + p₊)/(2(1+v))` as
/// `w·(p₋ + 2p + p₊)/4 − c·p`.
fn tension_correction(v: f64) -> (f64, f64) {
    (2.0 / (1.0 + v), (1.0 - v) / (1.0 + v))
}

/// The even-order tension step on a curve or crease vertex: `(m₋ + 2v·p + m₊)/(2(1+v))`,
/// `m₋`, `m₊` the midpoints of its two curve edges.
pub fn curve_vertex(p: DVec3, m_prev: DVec3, m_next: DVec3, v: f64) -> DVec3 {
    (m_prev + m_next + p * (2.0 * v)) / (2.0 * (1.0 + v))
}

/// The even-order tension step on a smooth edge point: `(2v·M + F₁ + F₂)/(2(1+v))`, `M` the
/// edge midpoint, `F₁`, `F₂` the centroids of its two faces. At `v = 1` Catmull–Clark's
/// edge rule.
pub fn smooth_edge(mid: DVec3, f1: DVec3, f2: DVec3, v: f64) -> DVec3 {
    (mid * (2.0 * v) + f1 + f2) / (2.0 * (1.0 + v))
}

/// Coefficients `(α, β, γ)` of the even-order smooth vertex rule
/// `V' = αV + β·avg M_j + γ·avg F_j` for a vertex of valence `n`: `β = 8v/(n(1+v)²)`,
/// `γ = 4/(n(1+v)²)`, `α = 1 − β − γ` (the design note's rule (A)). At `n = 4` it is the
/// tensor product of the curve rule (`α = v²/(1+v)²`); at `v = 1` Catmull–Clark's
/// `(n−3)/n, 2/n, 1/n`.
pub fn vertex_weights(n: usize, v: f64) -> (f64, f64, f64) {
    let d = n as f64 * (1.0 + v) * (1.0 + v);
    let (beta, gamma) = (8.0 * v / d, 4.0 / d);
    (1.0 - beta - gamma, beta, gamma)
}

/// The odd-order corner point of a face corner: `(v²V + v(M₋ + M₊) + F)/(1+v)²`, `V` the
/// corner, `M₋`, `M₊` the midpoints of the face's two edges at it, `F` the face centroid (the
/// tensor product of the curve's `((1+2v)p_i + p_{i+1})/(2(1+v))` on quads; Doo–Sabin
/// topology).
pub fn face_corner(p: DVec3, m_prev: DVec3, m_next: DVec3, centroid: DVec3, v: f64) -> DVec3 {
    (p * (v * v) + (m_prev + m_next) * v + centroid) / ((1.0 + v) * (1.0 + v))
}

/// The centroid of `points`.
pub fn centroid(points: impl ExactSizeIterator<Item = DVec3>) -> DVec3 {
    let n = points.len() as f64;
    points.sum::<DVec3>() / n
}

/// The order-4 curve limit stencil at a level of tension `v`: the limit of point `p` with
/// neighbours `p₋`, `p₊` is `(p₋ + w·p + p₊)/(w + 2)`, `w = 2(s − cos θ)/(1 − s)`,
/// `s = sin θ/θ`, `θ = 2 arccos v` (θ imaginary for `v > 1`: sinh, cosh; `w = 4` at `v = 1`,
/// the cubic B-spline's 1/6, 2/3, 1/6).
pub fn order4_limit_weight(v: f64) -> f64 {
    // x = θ² (negative for the hyperbolic case).
    let x = if v <= 1.0 {
        (2.0 * acos(v)).powi(2)
    } else {
        -(2.0 * v.acosh()).powi(2)
    };
    if x.abs() > 4.0 {
        let (s, c) = if x > 0.0 {
            let th = x.sqrt();
            (sin(th) / th, cos(th))
        } else {
            let th = (-x).sqrt();
            (th.sinh() / th, th.cosh())
        };
        return 2.0 * (s - c) / (1.0 - s);
    }
    // Near θ = 0 both s − cos θ and 1 − s cancel: sum their series divided by x,
    // Σ (−x)^{m−1} [1/(2m)! − 1/(2m+1)!] and Σ (−x)^{m−1}/(2m+1)!.
    let (mut a, mut b, mut power, mut fact) = (0.0, 0.0, 1.0, 1.0);
    for m in 1..=20 {
        let even = fact * (2 * m) as f64; // (2m)! from (2m − 1)!
        let odd = even * (2 * m + 1) as f64; // (2m+1)!
        a += power * (1.0 / even - 1.0 / odd);
        b += power / odd;
        power *= -x;
        fact = odd;
    }
    2.0 * a / b
}

/// The limit radius of a closed regular polygon of control radius 1 and angular spacing `θ`
/// at order `k` with the matching tension cos(θ/2):
/// `λ_k(θ) = (sin θ/θ)·(2 sin(θ/2)/θ)^{k−4}` (so a circle of radius r needs control radius
/// r/λ).
pub fn circle_factor(k: u32, theta: f64) -> f64 {
    (sin(theta) / theta) * (2.0 * sin(theta / 2.0) / theta).powi(k as i32 - 4)
}
