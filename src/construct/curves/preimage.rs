//! The pre-image map: the boundary's projection onto the unit square, and the pre-images of
//! the interior curves under the same map.
//!
//! **Boundary → square.** The boundary curves, in order around the patch, become the four
//! sides of the unit square `[0, 1]²`, counter-clockwise: the first curve the bottom
//! (`v = 0`, `u` from 0 to 1), the second the right side (`u = 1`, `v` from 0 to 1), the
//! third the top (`v = 1`, run from `u = 1` to 0), the fourth the left side (`u = 0`, run from
//! `v = 1` to 0). Along each side the square's coordinate is the curve's chord-length
//! parameter over its length (the summed chord length of its spline, which tends to the arc
//! length as the points get denser). A 3-sided patch collapses the **top** side (`v = 1`) to
//! one point, where the second curve ends and the third begins: the third curve is then the
//! left side. Where consecutive curves do not meet (open corners) the square's corner stands
//! for the midpoint of the gap.
//!
//! **Inside: transfinite (Coons) interpolation.** With `b₀ … b₃` the projected sides as
//! functions of the square's coordinate along them and `P₀₀, P₁₀, P₁₁, P₀₁` the projected
//! corners (midpoints of the gaps at open corners), the map from the square to the plane is
//! `X(u, v) = (1−v) b₀(u) + v b₂(u) + (1−u) b₃(v) + u b₁(v) − [(1−u)(1−v) P₀₀ + u(1−v) P₁₀ +
//! u v P₁₁ + (1−u) v P₀₁]`. It must be one-to-one: the projected boundary may not cross
//! itself, and the Jacobian `det(X_u, X_v)` must stay positive on a 33 × 33 lattice of the
//! square (the collapsed side of a 3-sided patch excepted); otherwise the input is refused.
//!
//! **Inverting it.** An interior curve's projected point `q` inside the projected boundary
//! (crossing-number test on the densely sampled boundary polygon) gets the `(u, v)` with
//! `X(u, v) = q` by Newton's method on `X` with its analytic Jacobian (the curves'
//! derivatives), started from the previous point along the curve or, for the first point, the
//! nearest node of the 33 × 33 lattice, iterates kept in the square, until `|X − q| ≤ 1e-13 ×`
//! the boundary's size. A curve that leaves the boundary is clipped there: the crossing
//! point is found by bisection on the curve's parameter and mapped the same way. Each
//! interior curve's pre-image is then polylines (one per inside piece) of its densely
//! sampled points, each vertex carrying its curve parameter; the attraction blend reads the
//! 3-D curve point at a pre-image point by interpolating that parameter linearly along the
//! polyline segment and evaluating the curve there.

use glam::{DVec2, DVec3};

use super::projection::Plane;
use crate::curves::SpaceCurve;
use crate::error::{Error, Result};

/// One side of the unit square: a boundary curve, or the collapsed side of a 3-sided patch.
#[derive(Debug, Clone)]
pub enum Side {
    /// A boundary curve; `reversed` when the square's coordinate runs against it.
    Curve {
        /// The curve.
        curve: SpaceCurve,
        /// Whether the side's coordinate runs from the curve's end to its start.
        reversed: bool,
    },
    /// A side collapsed to one point.
    Point(DVec3),
}

impl Side {
    /// The 3-D point at the side's coordinate `t ∈ [0, 1]`.
    pub fn point(&self, t: f64) -> DVec3 {
        match self {
            Side::Curve { curve, reversed } => {
                let f = if *reversed { 1.0 - t } else { t };
                curve.eval(f * curve.length(), false).position
            }
            Side::Point(p) => *p,
        }
    }

    /// The derivative of [`Side::point`] with respect to `t`.
    pub fn derivative(&self, t: f64) -> DVec3 {
        match self {
            Side::Curve { curve, reversed } => {
                let l = curve.length();
                if *reversed {
                    -curve.eval((1.0 - t) * l, false).d1 * l
                } else {
                    curve.eval(t * l, false).d1 * l
                }
            }
            Side::Point(_) => DVec3::ZERO,
        }
    }
}

/// Lattice intervals per side on which the Coons map's Jacobian is checked and from whose
/// nodes Newton starts.
const LATTICE: usize = 32;

/// Largest distance, over the boundary's size, from a point to the map's image for which
/// Newton's stalled iterate on the square's edge is taken.
const STALL_TOLERANCE: f64 = 1e-4;

/// Boundary samples per side for the crossing-number test and the self-crossing check.
const POLYGON_SAMPLES: usize = 128;

/// The boundary sides and the Coons map of their projection.
#[derive(Debug, Clone)]
pub struct Boundary {
    /// Bottom (`v = 0`), right (`u = 1`), top (`v = 1`), left (`u = 0`), each run with
    /// increasing `u` or `v`.
    pub sides: [Side; 4],
    /// The projection plane (oriented so that the square maps counter-clockwise).
    pub plane: Plane,
    /// Whether the top side is collapsed (3-sided patch).
    pub three_sided: bool,
    /// Projected corners `P₀₀, P₁₀, P₁₁, P₀₁`.
    corners: [DVec2; 4],
    /// Dense projected boundary polygon, counter-clockwise.
    polygon: Vec<DVec2>,
    /// The map on the lattice, row by row (`u` fastest).
    lattice: Vec<DVec2>,
    /// Size of the projected boundary (its bounding-box diagonal).
    size: f64,
}

/// Point, `∂/∂u` and `∂/∂v` of the Coons map.
type Jet = (DVec2, DVec2, DVec2);

impl Boundary {
    /// The boundary of `sides` projected on `plane` (flipped if the sides run clockwise
    /// there). Errors ([`Error::InvalidArgument`]): a projection without area, a projected
    /// boundary crossing itself, a Coons map that folds (see the module documentation).
    pub fn new(sides: [Side; 4], plane: Plane, three_sided: bool) -> Result<Boundary> {
        let mut b = Boundary {
            sides,
            plane,
            three_sided,
            corners: [DVec2::ZERO; 4],
            polygon: Vec::new(),
            lattice: Vec::new(),
            size: 0.0,
        };
        b.project();
        let area = signed_area(&b.polygon);
        let (lo, hi) = b
            .polygon
            .iter()
            .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(*p), hi.max(*p))
            });
        b.size = (hi - lo).length();
        if area.is_nan() || area.abs() <= 1e-9 * b.size * b.size {
            return Err(Error::invalid_argument(
                "the boundary's projection encloses no area (the boundary curves project onto \
                 a line): choose another projection normal",
            ));
        }
        if area < 0.0 {
            b.plane = b.plane.flipped();
            b.project();
        }
        b.check_simple()?;
        b.lattice = (0..=LATTICE)
            .flat_map(|j| (0..=LATTICE).map(move |i| (i, j)))
            .map(|(i, j)| b.map(i as f64 / LATTICE as f64, j as f64 / LATTICE as f64))
            .collect();
        b.check_jacobian()?;
        Ok(b)
    }

    /// Projected corners and the dense polygon under the current plane.
    fn project(&mut self) {
        let p = |s: &Side, t: f64| self.plane.project(s.point(t));
        let s = &self.sides;
        let mid = |a: DVec2, b: DVec2| (a + b) * 0.5;
        self.corners = [
            mid(p(&s[0], 0.0), p(&s[3], 0.0)),
            mid(p(&s[0], 1.0), p(&s[1], 0.0)),
            mid(p(&s[2], 1.0), p(&s[1], 1.0)),
            mid(p(&s[2], 0.0), p(&s[3], 1.0)),
        ];
        let n = POLYGON_SAMPLES;
        let mut poly = Vec::with_capacity(4 * n);
        // Counter-clockwise round the square: bottom and right forwards, top and left back.
        for (k, forward) in [(0, true), (1, true), (2, false), (3, false)] {
            if matches!(s[k], Side::Point(_)) {
                poly.push(p(&s[k], 0.0));
                continue;
            }
            for i in 0..n {
                let t = i as f64 / n as f64;
                poly.push(p(&s[k], if forward { t } else { 1.0 - t }));
            }
            poly.push(p(&s[k], if forward { 1.0 } else { 0.0 }));
        }
        // Consecutive duplicates (closed corners) would make zero-length edges.
        poly.dedup_by(|a, b| a.distance(*b) == 0.0);
        if poly.len() > 1 && poly[0] == poly[poly.len() - 1] {
            poly.pop();
        }
        self.polygon = poly;
    }

    /// Error if two non-adjacent edges of the projected boundary polygon cross.
    fn check_simple(&self) -> Result<()> {
        let p = &self.polygon;
        let n = p.len();
        for i in 0..n {
            let (a, b) = (p[i], p[(i + 1) % n]);
            for j in i + 2..n {
                if (j + 1) % n == i {
                    continue;
                }
                let (c, d) = (p[j], p[(j + 1) % n]);
                if segments_cross(a, b, c, d) {
                    let at = self.plane.origin + self.plane.e1 * a.x + self.plane.e2 * a.y;
                    return Err(Error::invalid_argument(format!(
                        "the boundary's projection folds over itself (it crosses itself near \
                         ({}, {}, {})): the boundary curves must project to a simple loop; \
                         choose another projection normal or redraw the boundary",
                        at.x, at.y, at.z
                    )));
                }
            }
        }
        Ok(())
    }

    /// Error if the Coons map's Jacobian is not positive on the lattice.
    fn check_jacobian(&self) -> Result<()> {
        for j in 0..=LATTICE {
            let v = j as f64 / LATTICE as f64;
            if self.three_sided && j == LATTICE {
                continue;
            }
            for i in 0..=LATTICE {
                let u = i as f64 / LATTICE as f64;
                let (_, xu, xv) = self.jet(u, v);
                let det = xu.perp_dot(xv);
                if det.is_nan() || det <= 1e-12 * self.size * self.size {
                    return Err(Error::invalid_argument(format!(
                        "the transfinite (Coons) map of the boundary's projection folds near \
                         (u, v) = ({u}, {v}): the projected boundary is too far from convex for \
                         the pre-image map; choose another projection normal or split the patch"
                    )));
                }
            }
        }
        Ok(())
    }

    /// The Coons map at `(u, v)`.
    pub fn map(&self, u: f64, v: f64) -> DVec2 {
        self.jet(u, v).0
    }

    /// The Coons map and its partial derivatives at `(u, v)`.
    fn jet(&self, u: f64, v: f64) -> Jet {
        let pl = &self.plane;
        let s = &self.sides;
        let b = |k: usize, t: f64| pl.project(s[k].point(t));
        let d = |k: usize, t: f64| pl.project_dir(s[k].derivative(t));
        let [p00, p10, p11, p01] = self.corners;
        let (b0, b1, b2, b3) = (b(0, u), b(1, v), b(2, u), b(3, v));
        let x = b0 * (1.0 - v) + b2 * v + b3 * (1.0 - u) + b1 * u
            - (p00 * ((1.0 - u) * (1.0 - v))
                + p10 * (u * (1.0 - v))
                + p11 * (u * v)
                + p01 * ((1.0 - u) * v));
        let xu =
            d(0, u) * (1.0 - v) + d(2, u) * v - b3 + b1 - (p10 - p00) * (1.0 - v) - (p11 - p01) * v;
        let xv =
            b2 - b0 + d(3, v) * (1.0 - u) + d(1, v) * u - (p01 - p00) * (1.0 - u) - (p11 - p10) * u;
        (x, xu, xv)
    }

    /// Whether the projected point `q` lies inside the projected boundary.
    pub fn contains(&self, q: DVec2) -> bool {
        let p = &self.polygon;
        let mut inside = false;
        for i in 0..p.len() {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            if (a.y > q.y) != (b.y > q.y) {
                let x = a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if q.x < x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// The `(u, v)` of the square that the Coons map takes to `q`, by Newton's method from
    /// `guess` (or the nearest lattice node). `None` if it does not converge.
    pub fn invert(&self, q: DVec2, guess: Option<DVec2>) -> Option<DVec2> {
        let start = guess.unwrap_or_else(|| self.nearest_node(q));
        self.newton(q, start)
            .or_else(|| guess.and_then(|_| self.newton(q, self.nearest_node(q))))
    }

    fn nearest_node(&self, q: DVec2) -> DVec2 {
        let k = (0..self.lattice.len())
            .min_by(|&a, &b| {
                self.lattice[a]
                    .distance_squared(q)
                    .total_cmp(&self.lattice[b].distance_squared(q))
            })
            .unwrap_or(0);
        DVec2::new(
            (k % (LATTICE + 1)) as f64 / LATTICE as f64,
            (k / (LATTICE + 1)) as f64 / LATTICE as f64,
        )
    }

    fn newton(&self, q: DVec2, start: DVec2) -> Option<DVec2> {
        let tolerance = 1e-13 * self.size;
        let mut uv = start.clamp(DVec2::ZERO, DVec2::ONE);
        let mut best = (f64::INFINITY, uv);
        for _ in 0..60 {
            let (x, xu, xv) = self.jet(uv.x, uv.y);
            let r = x - q;
            if r.length() <= tolerance {
                return Some(uv);
            }
            if r.length() < best.0 {
                best = (r.length(), uv);
            }
            let det = xu.perp_dot(xv);
            if det == 0.0 || !det.is_finite() {
                break;
            }
            // Solve [xu xv] δ = −r by Cramer's rule.
            let du = -(r.perp_dot(xv)) / det;
            let dv = -(xu.perp_dot(r)) / det;
            uv = (uv + DVec2::new(du, dv)).clamp(DVec2::ZERO, DVec2::ONE);
        }
        // A point just outside the map's image (the boundary polygon is a chordal
        // approximation of the curves) stalls on the square's edge: its nearest edge point.
        let (r, uv) = best;
        let on_edge = uv.x == 0.0 || uv.x == 1.0 || uv.y == 0.0 || uv.y == 1.0;
        (on_edge && r <= STALL_TOLERANCE * self.size).then_some(uv)
    }
}

/// Twice the signed area of a closed polygon over 2 (the shoelace formula).
fn signed_area(p: &[DVec2]) -> f64 {
    let n = p.len();
    0.5 * (0..n).map(|i| p[i].perp_dot(p[(i + 1) % n])).sum::<f64>()
}

/// Whether the closed segments `ab` and `cd` intersect (touching counts).
fn segments_cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let o = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2, d3, d4) = (o(c, d, a), o(c, d, b), o(a, b, c), o(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    let on = |p: DVec2, q: DVec2, r: DVec2| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    (d1 == 0.0 && on(c, d, a))
        || (d2 == 0.0 && on(c, d, b))
        || (d3 == 0.0 && on(a, b, c))
        || (d4 == 0.0 && on(a, b, d))
}

/// A vertex of an interior curve's pre-image polyline: its square coordinates and its curve
/// parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreVertex {
    /// Coordinates in the unit square.
    pub uv: DVec2,
    /// Parameter on the curve (chord length).
    pub s: f64,
}

/// An interior curve and the pre-image polylines of its pieces inside the boundary.
#[derive(Debug, Clone)]
pub struct Interior {
    /// The 3-D curve.
    pub curve: SpaceCurve,
    /// One polyline per piece inside the boundary.
    pub pieces: Vec<Vec<PreVertex>>,
}

/// Bisection steps for a curve's crossing of the boundary.
const BISECTIONS: usize = 48;

impl Interior {
    /// The pre-image of `curve` (named `what` in messages) sampled at `segments` equal
    /// parameter steps, clipped at the boundary. Errors ([`Error::InvalidArgument`]): no
    /// part of the curve projects inside the boundary, or the map cannot be inverted there.
    pub fn new(
        what: &str,
        curve: SpaceCurve,
        boundary: &Boundary,
        segments: usize,
    ) -> Result<Interior> {
        let l = curve.length();
        let q = |s: f64| boundary.plane.project(curve.eval(s, false).position);
        let inside = |s: f64| boundary.contains(q(s));
        let mut pieces: Vec<Vec<PreVertex>> = Vec::new();
        let mut piece: Vec<PreVertex> = Vec::new();
        let mut guess: Option<DVec2> = None;
        let fail = |s: f64| {
            Error::invalid_argument(format!(
                "{what}: the pre-image map could not be inverted at curve parameter {s}"
            ))
        };
        let push = |piece: &mut Vec<PreVertex>, guess: &mut Option<DVec2>, s: f64| -> Result<()> {
            let uv = boundary.invert(q(s), *guess).ok_or_else(|| fail(s))?;
            *guess = Some(uv);
            piece.push(PreVertex { uv, s });
            Ok(())
        };
        let mut was_inside = false;
        for k in 0..=segments {
            let s = l * k as f64 / segments as f64;
            let now = inside(s);
            if now != was_inside && k > 0 {
                // Bisect for the crossing between the previous sample and this one.
                let (mut a, mut b) = (l * (k - 1) as f64 / segments as f64, s);
                for _ in 0..BISECTIONS {
                    let m = 0.5 * (a + b);
                    if inside(m) == was_inside {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                let crossing = if was_inside { a } else { b };
                push(&mut piece, &mut guess, crossing)?;
                if was_inside {
                    pieces.push(std::mem::take(&mut piece));
                    guess = None;
                }
            }
            if now {
                push(&mut piece, &mut guess, s)?;
            }
            was_inside = now;
        }
        pieces.push(piece);
        pieces.retain(|p| p.len() >= 2);
        if pieces.is_empty() {
            return Err(Error::invalid_argument(format!(
                "{what}: no part of the curve projects inside the boundary"
            )));
        }
        Ok(Interior { curve, pieces })
    }

    /// The 3-D point at curve parameter `s`.
    pub fn point(&self, s: f64) -> DVec3 {
        self.curve.eval(s, false).position
    }
}

/// Where a line `coordinate[axis] = value` of the square crosses a pre-image polyline: the
/// other coordinate, the curve parameter, and the segment's direction. Each segment counts
/// over the half-open range `[min, max)` of its `axis` coordinate (so a polyline passing
/// through a vertex on the line crosses it once; segments along the line do not cross it),
/// and a polyline's end vertex on the line counts too.
pub fn crossings(piece: &[PreVertex], axis: usize, value: f64, out: &mut Vec<(f64, f64, DVec2)>) {
    let other = 1 - axis;
    let n = piece.len();
    for k in 0..n.saturating_sub(1) {
        let (a, b) = (piece[k], piece[k + 1]);
        let (ca, cb) = (a.uv[axis], b.uv[axis]);
        let (lo, hi) = if ca < cb { (ca, cb) } else { (cb, ca) };
        let counts = (lo <= value && value < hi)
            || (value == hi && lo < hi && ((k == 0 && ca == hi) || (k + 2 == n && cb == hi)));
        if !counts {
            continue;
        }
        let t = (value - ca) / (cb - ca);
        // At a vertex, its own coordinates exactly (a + (b − a) need not round to b).
        let (c, s) = if t == 1.0 {
            (b.uv[other], b.s)
        } else {
            (
                a.uv[other] + t * (b.uv[other] - a.uv[other]),
                a.s + t * (b.s - a.s),
            )
        };
        out.push((c, s, b.uv - a.uv));
    }
}
