//! The attraction blend of Qin & Wright, eqs. (5)–(8).
//!
//! For a point `(u, v)` of the unit square, the lines `U = u` and `V = v` are intersected
//! with every curve's pre-image: the line `U = u` meets the bottom and top sides at `(u, 0)`
//! and `(u, 1)`, the line `V = v` the left and right sides at `(0, v)` and `(1, v)` (so with
//! no interior curve this is eq. (8)), and both meet every interior pre-image polyline
//! wherever it crosses them ([`super::preimage::crossings`]). Each intersection `j` is a 3-D
//! curve point `V_j` at the parametric distance `d_j` from `(u, v)` along its line
//! (`|v − v_j|` on the `U = u` line, `|u − u_j|` on the `V = v` line). The surface point is
//! eq. (6), `S = Σ_j R_j V_j` with `R_j = (1/d_j)^τ / W` (eq. (7)) and `W = Σ_j (1/d_j)^τ`
//! (eq. (5)). The ratios are computed as `(d_min/d_j)^τ / Σ_k (d_min/d_k)^τ` (the same
//! numbers; this form does not overflow as `d_min → 0`). Where some `d_j = 0` the point lies
//! on those curves' pre-images and the limit of eq. (6) is their curve point: the surface is
//! exactly the curve there (the average of the curve points at `d = 0` where several meet,
//! such as an open corner, whose two curve ends differ).

use glam::{DVec2, DVec3};

use super::preimage::{crossings, Boundary, Interior};
use crate::math;

/// The curves' pre-images and the softness exponent τ.
#[derive(Debug, Clone)]
pub struct Blend {
    /// Boundary sides and pre-image map.
    pub boundary: Boundary,
    /// Interior curves with their pre-images.
    pub interior: Vec<Interior>,
    /// The exponent τ ≥ 0 of eqs. (5)–(7).
    pub tau: f64,
}

impl Blend {
    /// Every intersection of the lines `U = u` and `V = v` with the pre-images: parametric
    /// distance and 3-D curve point.
    pub fn hits(&self, uv: DVec2) -> Vec<(f64, DVec3)> {
        let (u, v) = (uv.x, uv.y);
        let s = &self.boundary.sides;
        let mut hits = vec![
            (v, s[0].point(u)),
            (1.0 - v, s[2].point(u)),
            (u, s[3].point(v)),
            (1.0 - u, s[1].point(v)),
        ];
        let mut found = Vec::new();
        for c in &self.interior {
            for piece in &c.pieces {
                for (axis, value, other) in [(0, u, v), (1, v, u)] {
                    found.clear();
                    crossings(piece, axis, value, &mut found);
                    hits.extend(
                        found
                            .iter()
                            .map(|&(at, param, _)| ((other - at).abs(), c.point(param))),
                    );
                }
            }
        }
        hits
    }

    /// Whether `(u, v)` lies on a curve's pre-image (some intersection at `d = 0`), so that
    /// [`Blend::point`] is a curve point there.
    pub fn on_curve(&self, uv: DVec2) -> bool {
        self.hits(uv).iter().any(|h| h.0 == 0.0)
    }

    /// The surface point at `(u, v)`: eq. (6) over [`Blend::hits`].
    pub fn point(&self, uv: DVec2) -> DVec3 {
        let hits = self.hits(uv);
        let on: Vec<DVec3> = hits.iter().filter(|h| h.0 == 0.0).map(|h| h.1).collect();
        if !on.is_empty() {
            return on.iter().copied().sum::<DVec3>() / on.len() as f64;
        }
        let d_min = hits.iter().map(|h| h.0).fold(f64::INFINITY, f64::min);
        let (mut sum, mut weight) = (DVec3::ZERO, 0.0);
        for &(d, p) in &hits {
            let r = if self.tau == 0.0 {
                1.0
            } else {
                math::powf(d_min / d, self.tau)
            };
            sum += p * r;
            weight += r;
        }
        sum / weight
    }
}
