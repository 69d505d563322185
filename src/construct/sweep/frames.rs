//! Orientation frames along a sampled trajectory: fixed, Frenet and rotation-minimizing.
//!
//! A sweep places the profile point `(a, b)` at `origin + a·normal + b·binormal` of the
//! frame of each trajectory sample. The three kinds differ only in how `normal` turns:
//!
//! - [`FrameKind::Fixed`]: the start frame, translated. The profile plane never turns, so the
//!   trajectory must keep moving through it: a tangent within [`FIXED_MIN_COS`] of that plane
//!   is an error (the surface would fold or flatten there). A closed trajectory always comes
//!   back through the plane, so it is always rejected with this frame.
//! - [`FrameKind::Frenet`]: the normal is the direction of the curvature vector. *Fallback*,
//!   documented here once: where the curvature vanishes (`κ·L ≤` [`FRENET_MIN_CURVATURE`], `L`
//!   the trajectory length: straight stretches, inflection points) the frame is carried over
//!   from the neighbouring sample with the rotation-minimizing step; at an inflection the
//!   curvature vector reverses, and the Frenet normal would flip by 180°: the sign is chosen
//!   so that the normal stays within 90° of the carried-over one, so the frame never flips.
//!   Curvature zero everywhere (a straight trajectory) has no Frenet frame: an error. On a
//!   closed trajectory whose normal would come back reversed (an odd number of inflections)
//!   the frame cannot close: an error that suggests the rotation-minimizing frame.
//! - [`FrameKind::RotationMinimizing`]: the double-reflection method of Wang, Jüttler, Zheng
//!   & Liu (2008), "Computation of rotation minimizing frames", ACM TOG 27(1), with global
//!   error O(h⁴). The start normal is the Frenet normal at the first sample where the
//!   curvature is defined (carried back along the curve), so that on a circle or a planar
//!   curve all three moving frames agree; a trajectory without curvature starts from the
//!   first corner's turn direction (carried back), and a straight one from the world axis
//!   least aligned with its direction. On a closed trajectory the frame comes back rotated by
//!   the *closing twist* `φ`; frame `i` is turned by `φ·s_i/L` (arc length `s_i`) so that it
//!   closes exactly, with the twist spread uniformly.
//!
//! Trajectory corners (tangent discontinuities) carry two tangents. Moving frames turn across
//! the corner by the smallest rotation taking the incoming tangent to the outgoing one, and the
//! corner sample's section lies in the *miter* plane (the bisector plane), so that the straight
//! pieces on both sides meet like a mitered pipe elbow.

use crate::math;
use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// Curvature below which the Frenet normal is undefined, relative to `1/L` (`L` the trajectory
/// length): `κ·L ≤ 1e-7`.
pub const FRENET_MIN_CURVATURE: f64 = 1e-7;

/// Sine of the smallest turn at a corner that gives a polyline trajectory its start normal.
const CORNER_MIN_TURN: f64 = 1e-9;

/// Smallest cosine allowed between a tangent and the start tangent with a fixed frame.
pub const FIXED_MIN_COS: f64 = 1e-3;

/// How the profile is oriented along the trajectory.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
pub enum FrameKind {
    /// Translation only: the start frame everywhere (JSON `"fixed"`).
    #[serde(rename = "fixed")]
    Fixed,
    /// Frenet frame, with the fallback described in the module documentation (JSON `"frenet"`).
    #[serde(rename = "frenet")]
    Frenet,
    /// Rotation-minimizing frame by double reflection (JSON `"rmf"`). The default.
    #[default]
    #[serde(rename = "rmf")]
    RotationMinimizing,
}

/// One trajectory sample, as the frame computations need it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FramePoint {
    /// The point on the trajectory.
    pub position: DVec3,
    /// Unit tangent; at a corner, the incoming one.
    pub tangent: DVec3,
    /// Curvature vector `dT/ds = κ·N` (zero on straight parts); only the Frenet frame uses it.
    pub curvature: DVec3,
    /// At a corner, the outgoing unit tangent.
    pub tangent_out: Option<DVec3>,
}

impl FramePoint {
    /// A smooth sample.
    pub fn smooth(position: DVec3, tangent: DVec3, curvature: DVec3) -> FramePoint {
        FramePoint {
            position,
            tangent,
            curvature,
            tangent_out: None,
        }
    }

    fn tangent_after(&self) -> DVec3 {
        self.tangent_out.unwrap_or(self.tangent)
    }
}

/// An orthonormal frame at a trajectory sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// The trajectory point.
    pub origin: DVec3,
    /// Unit tangent (the incoming one at a corner).
    pub tangent: DVec3,
    /// Unit normal: the profile's first coordinate `a` runs along it.
    pub normal: DVec3,
    /// Unit binormal `tangent × normal`: the profile's second coordinate `b` runs along it.
    pub binormal: DVec3,
    /// At a corner with a moving frame, the unit normal of the miter plane the section lies in.
    pub miter: Option<DVec3>,
}

impl Frame {
    /// Where the profile point `(a, b)` goes: `origin + a·normal + b·binormal`, moved along the
    /// tangent onto the miter plane at a corner.
    pub fn place(&self, a: f64, b: f64) -> DVec3 {
        let d = a * self.normal + b * self.binormal;
        match self.miter {
            None => self.origin + d,
            // The line origin + d + λ·tangent meets the plane through origin normal to m.
            Some(m) => self.origin + d - (d.dot(m) / self.tangent.dot(m)) * self.tangent,
        }
    }
}

/// Compute one frame per sample.
///
/// `points` are consecutive samples of one trajectory (for a closed one, the last joins the
/// first, which is not repeated). Tangents must be unit length and consecutive positions
/// distinct; [`super::trajectory`] guarantees this. Errors ([`Error::InvalidArgument`]): fewer
/// than 2 samples, a non-finite or non-unit input, a fixed frame that the trajectory leaves
/// its plane against, a Frenet frame that is undefined everywhere or cannot close.
pub fn compute_frames(points: &[FramePoint], closed: bool, kind: FrameKind) -> Result<Vec<Frame>> {
    check_points(points, closed)?;
    let length = polyline_length(points, closed);
    let min_curv = FRENET_MIN_CURVATURE / length;
    let frenet_at = |p: &FramePoint| frenet_normal(p, min_curv);
    let mut frames = match kind {
        FrameKind::Fixed => fixed_frames(points, closed, &frenet_at)?,
        FrameKind::RotationMinimizing => rmf_frames(points, closed, &frenet_at)?,
        FrameKind::Frenet => frenet_frames(points, closed, &frenet_at)?,
    };
    if kind != FrameKind::Fixed {
        for (f, p) in frames.iter_mut().zip(points) {
            if let Some(t_out) = p.tangent_out {
                f.miter = Some((p.tangent + t_out).normalize());
            }
        }
    }
    Ok(frames)
}

/// The Frenet normal of a sample: the unit curvature vector made perpendicular to the tangent,
/// or `None` where `|κ| ≤ min_curvature`. Exposed so that tests can show where it flips.
pub fn frenet_normal(p: &FramePoint, min_curvature: f64) -> Option<DVec3> {
    let k = p.curvature - p.curvature.dot(p.tangent) * p.tangent;
    let len = k.length();
    (len > min_curvature).then(|| k / len)
}

/// Signed angle from `from` to `to` about the unit `axis` (both perpendicular to it).
pub fn signed_angle(from: DVec3, to: DVec3, axis: DVec3) -> f64 {
    math::atan2(from.cross(to).dot(axis), from.dot(to))
}

fn check_points(points: &[FramePoint], closed: bool) -> Result<()> {
    let need = if closed { 3 } else { 2 };
    if points.len() < need {
        return Err(Error::invalid_argument(format!(
            "a {} trajectory needs at least {need} samples to have frames, got {}",
            if closed { "closed" } else { "open" },
            points.len()
        )));
    }
    for (i, p) in points.iter().enumerate() {
        let unit = |t: DVec3| t.is_finite() && (t.length() - 1.0).abs() < 1e-9;
        if !p.position.is_finite()
            || !unit(p.tangent)
            || !p.curvature.is_finite()
            || p.tangent_out.is_some_and(|t| !unit(t))
        {
            return Err(Error::invalid_argument(format!(
                "trajectory sample {i} has a non-finite position or curvature or a non-unit tangent"
            )));
        }
    }
    Ok(())
}

fn polyline_length(points: &[FramePoint], closed: bool) -> f64 {
    let open: f64 = points
        .windows(2)
        .map(|w| w[0].position.distance(w[1].position))
        .sum();
    if closed {
        open + points[points.len() - 1]
            .position
            .distance(points[0].position)
    } else {
        open
    }
}

/// A frame from a tangent and a normal (made exactly perpendicular).
fn frame_from(p: &FramePoint, tangent: DVec3, normal: DVec3) -> Frame {
    let normal = (normal - normal.dot(tangent) * tangent).normalize();
    Frame {
        origin: p.position,
        tangent,
        normal,
        binormal: tangent.cross(normal),
        miter: None,
    }
}

/// A unit vector perpendicular to `t`, from the world axis least aligned with it.
pub(crate) fn any_perpendicular(t: DVec3) -> DVec3 {
    let a = t.abs();
    let axis = if a.x <= a.y && a.x <= a.z {
        DVec3::X
    } else if a.y <= a.z {
        DVec3::Y
    } else {
        DVec3::Z
    };
    (axis - axis.dot(t) * t).normalize()
}

/// The smallest rotation taking unit `from` to unit `to` (about `from × to`).
fn min_rotation(from: DVec3, to: DVec3) -> DMat3 {
    let axis = from.cross(to);
    let s = axis.length();
    if s < 1e-15 {
        return DMat3::IDENTITY;
    }
    DMat3::from_axis_angle(axis / s, math::atan2(s, from.dot(to)))
}

/// One double-reflection step: carry the normal `r` (perpendicular to `t0` at `x0`) to the
/// sample at `x1` with tangent `t1`.
pub fn double_reflection(x0: DVec3, t0: DVec3, r: DVec3, x1: DVec3, t1: DVec3) -> DVec3 {
    let v1 = x1 - x0;
    let c1 = v1.dot(v1);
    let (r_l, t_l) = if c1 > 0.0 {
        (
            r - (2.0 / c1) * v1.dot(r) * v1,
            t0 - (2.0 / c1) * v1.dot(t0) * v1,
        )
    } else {
        (r, t0)
    };
    let v2 = t1 - t_l;
    let c2 = v2.dot(v2);
    let r1 = if c2 > 1e-300 {
        r_l - (2.0 / c2) * v2.dot(r_l) * v2
    } else {
        r_l
    };
    (r1 - r1.dot(t1) * t1).normalize()
}

/// Carry a normal from sample `i` to sample `j = i + 1` (or 0 after the last when closed),
/// turning through the corner at `i` first.
fn transport(points: &[FramePoint], i: usize, j: usize, r: DVec3) -> DVec3 {
    let (p, q) = (&points[i], &points[j]);
    let r = min_rotation(p.tangent, p.tangent_after()) * r;
    double_reflection(p.position, p.tangent_after(), r, q.position, q.tangent)
}

/// Carry a normal backwards from sample `j` to sample `i = j - 1`.
fn transport_back(points: &[FramePoint], j: usize, i: usize, r: DVec3) -> DVec3 {
    let (p, q) = (&points[i], &points[j]);
    let r = double_reflection(q.position, q.tangent, r, p.position, p.tangent_after());
    min_rotation(p.tangent_after(), p.tangent) * r
}

/// The rotation-minimizing normals from `r0` at sample 0, without closing.
fn rmf_normals(points: &[FramePoint], r0: DVec3) -> Vec<DVec3> {
    let mut normals = Vec::with_capacity(points.len());
    normals.push(r0);
    for i in 1..points.len() {
        normals.push(transport(points, i - 1, i, normals[i - 1]));
    }
    normals
}

/// Start normal for rotation-minimizing and fixed frames, see the module documentation.
fn start_normal(points: &[FramePoint], frenet_at: &dyn Fn(&FramePoint) -> Option<DVec3>) -> DVec3 {
    let t0 = points[0].tangent;
    // Without curvature anywhere, the first corner's turn direction (a polyline's own
    // normal), so that a rotated polyline gets the rotated frames; only a straight line falls
    // back to a world axis (#17 item 7: the world axis turned a polyline's sections by up to
    // 4e-4 of its size under rotation).
    let turn = |p: &FramePoint| {
        let out = p.tangent_after();
        let n = out - out.dot(p.tangent) * p.tangent;
        (n.length() > CORNER_MIN_TURN).then(|| n.normalize())
    };
    let found = points
        .iter()
        .position(|p| frenet_at(p).is_some())
        .map(|k| (k, frenet_at(&points[k])))
        .or_else(|| {
            let k = points.iter().position(|p| turn(p).is_some())?;
            Some((k, turn(&points[k])))
        });
    let Some((k, normal)) = found else {
        return any_perpendicular(t0);
    };
    let mut r = normal.unwrap_or_else(|| any_perpendicular(t0));
    for j in (1..=k).rev() {
        r = transport_back(points, j, j - 1, r);
    }
    r
}

fn fixed_frames(
    points: &[FramePoint],
    closed: bool,
    frenet_at: &dyn Fn(&FramePoint) -> Option<DVec3>,
) -> Result<Vec<Frame>> {
    let t0 = points[0].tangent;
    if closed {
        return Err(Error::invalid_argument(
            "a fixed frame cannot follow a closed trajectory: the trajectory must come back \
             through the profile plane, where the translated profile would fold; use \"rmf\"",
        ));
    }
    for (i, p) in points.iter().enumerate() {
        let c = p.tangent.dot(t0).min(p.tangent_after().dot(t0));
        if c <= FIXED_MIN_COS {
            return Err(Error::invalid_argument(format!(
                "fixed frame: at trajectory sample {i} the trajectory turns {:.1}° away from \
                 its start direction, so the translated profile would fold; use \"rmf\"",
                math::acos(c.clamp(-1.0, 1.0)).to_degrees()
            )));
        }
    }
    let n0 = start_normal(points, frenet_at);
    let f0 = frame_from(&points[0], t0, n0);
    Ok(points
        .iter()
        .map(|p| Frame {
            origin: p.position,
            ..f0
        })
        .collect())
}

fn rmf_frames(
    points: &[FramePoint],
    closed: bool,
    frenet_at: &dyn Fn(&FramePoint) -> Option<DVec3>,
) -> Result<Vec<Frame>> {
    let n = points.len();
    let normals = rmf_normals(points, start_normal(points, frenet_at));
    let mut frames: Vec<Frame> = points
        .iter()
        .zip(&normals)
        .map(|(p, &r)| frame_from(p, p.tangent, r))
        .collect();
    if closed {
        // Closing twist: the normal carried once round, compared with the start normal.
        let back = transport(points, n - 1, 0, normals[n - 1]);
        let t0 = points[0].tangent;
        let phi = signed_angle(back, normals[0], t0);
        let total = polyline_length(points, true);
        let mut s = 0.0;
        for i in 0..n {
            if i > 0 {
                s += points[i - 1].position.distance(points[i].position);
            }
            let rot = DMat3::from_axis_angle(points[i].tangent, phi * s / total);
            frames[i] = frame_from(&points[i], points[i].tangent, rot * normals[i]);
        }
    }
    Ok(frames)
}

fn frenet_frames(
    points: &[FramePoint],
    closed: bool,
    frenet_at: &dyn Fn(&FramePoint) -> Option<DVec3>,
) -> Result<Vec<Frame>> {
    let n = points.len();
    let Some(first) = points.iter().position(|p| frenet_at(p).is_some()) else {
        return Err(Error::invalid_argument(
            "the Frenet frame is undefined everywhere: the trajectory is straight (no \
             curvature); use \"rmf\" or \"fixed\"",
        ));
    };
    // Walk forward from the first defined sample (all the way round when closed), carrying
    // the frame where the curvature vanishes and choosing the sign that does not flip.
    let mut normals = vec![DVec3::ZERO; n];
    normals[first] = frenet_at(&points[first]).unwrap_or(DVec3::ZERO);
    let steps = if closed { n - 1 } else { n - 1 - first };
    let mut i = first;
    for _ in 0..steps {
        let j = (i + 1) % n;
        let carried = transport(points, i, j, normals[i]);
        normals[j] = pick_sign(frenet_at(&points[j]), carried);
        i = j;
    }
    if closed {
        let carried = transport(points, i, first, normals[i]);
        if carried.dot(normals[first]) < 0.0 {
            return Err(Error::invalid_argument(
                "the Frenet frame of this closed trajectory does not close: its normal comes \
                 back reversed (an odd number of inflections); use \"rmf\"",
            ));
        }
    } else {
        for j in (0..first).rev() {
            normals[j] = transport_back(points, j + 1, j, normals[j + 1]);
        }
    }
    Ok(points
        .iter()
        .zip(&normals)
        .map(|(p, &r)| frame_from(p, p.tangent, r))
        .collect())
}

/// The Frenet normal with the sign that keeps it within 90° of `carried`, or `carried` where
/// the Frenet normal is undefined.
fn pick_sign(frenet: Option<DVec3>, carried: DVec3) -> DVec3 {
    match frenet {
        Some(nf) if nf.dot(carried) < 0.0 => -nf,
        Some(nf) => nf,
        None => carried,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{PI, TAU};

    /// Helix (R cos t, R sin t, h t) sampled at `n` points over `turns` turns.
    fn helix(r: f64, h: f64, turns: f64, n: usize) -> Vec<FramePoint> {
        let c = (r * r + h * h).sqrt();
        (0..n)
            .map(|i| {
                let t = TAU * turns * i as f64 / (n - 1) as f64;
                let pos = DVec3::new(r * math::cos(t), r * math::sin(t), h * t);
                let tan = DVec3::new(-r * math::sin(t), r * math::cos(t), h) / c;
                let curv = DVec3::new(-math::cos(t), -math::sin(t), 0.0) * (r / (c * c));
                FramePoint::smooth(pos, tan, curv)
            })
            .collect()
    }

    fn assert_orthonormal(f: &Frame) {
        assert!((f.normal.length() - 1.0).abs() < 1e-12);
        assert!(f.normal.dot(f.tangent).abs() < 1e-12);
        assert!((f.binormal - f.tangent.cross(f.normal)).length() < 1e-12);
    }

    #[test]
    fn rmf_on_a_helix_twists_against_frenet_at_minus_torsion() {
        let (r, h) = (2.0, 0.5);
        let c2 = r * r + h * h;
        let tau = h / c2;
        for (n, tol) in [(65, 2e-4), (129, 1.5e-5)] {
            let pts = helix(r, h, 2.0, n);
            let rmf = compute_frames(&pts, false, FrameKind::RotationMinimizing).unwrap();
            let fre = compute_frames(&pts, false, FrameKind::Frenet).unwrap();
            // The start normal is the Frenet normal.
            assert!((rmf[0].normal - fre[0].normal).length() < 1e-12);
            let ds = pts[0].position.distance(pts[1].position);
            let arc = c2.sqrt() * TAU * 2.0 / (n - 1) as f64;
            let mut worst: f64 = 0.0;
            for (i, (a, b)) in rmf.iter().zip(&fre).enumerate() {
                assert_orthonormal(a);
                // Frenet frame of the helix is exact: normal points at the axis.
                assert!((b.normal - pts[i].curvature.normalize()).length() < 1e-12);
                let theta = signed_angle(b.normal, a.normal, a.tangent);
                let expect = -tau * arc * i as f64;
                let diff = (theta - expect + PI).rem_euclid(TAU) - PI;
                worst = worst.max(diff.abs());
            }
            assert!(ds > 0.0);
            assert!(worst < tol, "n={n}: worst twist error {worst}");
        }
    }

    #[test]
    fn rmf_twist_error_falls_fourth_order() {
        let (r, h) = (1.0, 0.8);
        let tau = h / (r * r + h * h);
        let err = |n: usize| {
            let pts = helix(r, h, 1.0, n);
            let rmf = compute_frames(&pts, false, FrameKind::RotationMinimizing).unwrap();
            let fre = compute_frames(&pts, false, FrameKind::Frenet).unwrap();
            let len = (r * r + h * h).sqrt() * TAU;
            let theta = signed_angle(fre[n - 1].normal, rmf[n - 1].normal, pts[n - 1].tangent);
            ((theta + tau * len + PI).rem_euclid(TAU) - PI).abs()
        };
        let (e1, e2) = (err(33), err(65));
        let rate = e1 / e2;
        eprintln!("helix twist error {e1} -> {e2}, rate {rate}");
        assert!(rate > 12.0, "errors {e1} {e2}, rate {rate}");
    }

    /// (p, q) = (2, 3) torus knot with radii (2, 0.7) at parameter t: position and the first
    /// three derivatives, exact.
    fn knot_derivatives(t: f64) -> [DVec3; 4] {
        let (p, q, big, small) = (2.0, 3.0, 2.0, 0.7);
        // Position = (ρ cos pt, ρ sin pt, small sin qt), ρ = big + small cos qt; the k-th
        // derivative of cos/sin(ωt) is ω^k times a phase shift of kπ/2.
        let c = |w: f64, k: i32| w.powi(k) * math::cos(w * t + k as f64 * PI / 2.0);
        let s = |w: f64, k: i32| w.powi(k) * math::sin(w * t + k as f64 * PI / 2.0);
        let rho = |k: i32| {
            if k == 0 {
                big + small * c(q, 0)
            } else {
                small * c(q, k)
            }
        };
        let binom = [
            [1.0, 0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0, 0.0],
            [1.0, 2.0, 1.0, 0.0],
            [1.0, 3.0, 3.0, 1.0],
        ];
        let mut out = [DVec3::ZERO; 4];
        for (k, o) in out.iter_mut().enumerate() {
            let mut x = 0.0;
            let mut y = 0.0;
            for (j, &b) in binom[k].iter().enumerate().take(k + 1) {
                x += b * rho(j as i32) * c(p, (k - j) as i32);
                y += b * rho(j as i32) * s(p, (k - j) as i32);
            }
            *o = DVec3::new(x, y, small * s(q, k as i32));
        }
        out
    }

    fn torus_knot(n: usize) -> Vec<FramePoint> {
        (0..n)
            .map(|i| {
                let [pos, d1, d2, _] = knot_derivatives(TAU * i as f64 / n as f64);
                let speed = d1.length();
                let tan = d1 / speed;
                let curv = (d2 - d2.dot(tan) * tan) / (speed * speed);
                FramePoint::smooth(pos, tan, curv)
            })
            .collect()
    }

    /// Torsion times speed, `τ·ds/dt`, of the torus knot.
    fn knot_twist_density(t: f64) -> f64 {
        let [_, d1, d2, d3] = knot_derivatives(t);
        let b = d1.cross(d2);
        b.dot(d3) / b.length_squared() * d1.length()
    }

    #[test]
    fn rmf_closes_on_a_torus_knot_with_uniform_twist() {
        let n = 800;
        let pts = torus_knot(n);
        let rmf = compute_frames(&pts, true, FrameKind::RotationMinimizing).unwrap();
        let fre = compute_frames(&pts, true, FrameKind::Frenet).unwrap();
        // No seam: every step, the wrap-around one included, adds the same correction per
        // unit length to the carried normal (φ/L), so the last frame joins the first smoothly.
        let rates: Vec<f64> = (0..n)
            .map(|i| {
                let j = (i + 1) % n;
                let ds = pts[i].position.distance(pts[j].position);
                signed_angle(
                    transport(&pts, i, j, rmf[i].normal),
                    rmf[j].normal,
                    pts[j].tangent,
                ) / ds
            })
            .collect();
        for r in &rates {
            assert!(
                (r - rates[0]).abs() < 1e-9,
                "correction rate {r} vs {}",
                rates[0]
            );
        }
        assert!(rates[0].abs() > 1e-3, "a torus knot has a closing twist");
        // Twist relative to Frenet: θ' = −τ + φ/L, integrated along the curve.
        let len = polyline_length(&pts, true);
        let phi_over_l = {
            let raw = rmf_normals(&pts, rmf[0].normal);
            signed_angle(
                transport(&pts, n - 1, 0, raw[n - 1]),
                raw[0],
                pts[0].tangent,
            ) / len
        };
        assert!((phi_over_l - rates[0]).abs() < 1e-9);
        // Expected angle from Frenet to RMF: ∫(−τ + φ/L) ds, by Simpson's rule on the
        // parameter between samples.
        let mut theta_expect = signed_angle(fre[0].normal, rmf[0].normal, pts[0].tangent);
        let mut worst: f64 = 0.0;
        let dt = TAU / n as f64;
        for i in 1..n {
            let t0 = dt * (i - 1) as f64;
            let simpson =
                |f: &dyn Fn(f64) -> f64| dt / 6.0 * (f(t0) + 4.0 * f(t0 + dt / 2.0) + f(t0 + dt));
            let speed = |t: f64| knot_derivatives(t)[1].length();
            theta_expect += -simpson(&knot_twist_density) + phi_over_l * simpson(&speed);
            let theta = signed_angle(fre[i].normal, rmf[i].normal, pts[i].tangent);
            let diff = (theta - theta_expect + PI).rem_euclid(TAU) - PI;
            worst = worst.max(diff.abs());
        }
        eprintln!("torus knot: worst twist deviation {worst}");
        assert!(worst < 1e-4, "worst twist deviation {worst}");
        for f in &rmf {
            assert_orthonormal(f);
        }
    }

    /// Planar S curve y = x³ on [-1, 1]: inflection at x = 0 (a sample lands on it).
    fn s_curve(n: usize) -> Vec<FramePoint> {
        (0..n)
            .map(|i| {
                let x = -1.0 + 2.0 * i as f64 / (n - 1) as f64;
                let d1 = DVec3::new(1.0, 3.0 * x * x, 0.0);
                let d2 = DVec3::new(0.0, 6.0 * x, 0.0);
                let sp = d1.length();
                let t = d1 / sp;
                let curv = (d2 - d2.dot(t) * t) / (sp * sp);
                FramePoint::smooth(DVec3::new(x, x * x * x, 0.0), t, curv)
            })
            .collect()
    }

    #[test]
    fn no_flip_at_an_inflection_where_raw_frenet_flips() {
        let pts = s_curve(41);
        let raw: Vec<Option<DVec3>> = pts.iter().map(|p| frenet_normal(p, 1e-9)).collect();
        // The raw Frenet normal flips across the inflection (and is undefined on it).
        assert!(raw[20].is_none());
        assert!(raw[19].unwrap().dot(raw[21].unwrap()) < -0.99);
        for kind in [FrameKind::RotationMinimizing, FrameKind::Frenet] {
            let f = compute_frames(&pts, false, kind).unwrap();
            for w in f.windows(2) {
                assert!(w[0].normal.dot(w[1].normal) > 0.9, "{kind:?} flips");
                // Planar curve: the binormal is the plane normal throughout.
                assert!((w[1].binormal.z.abs() - 1.0).abs() < 1e-12);
            }
            assert_eq!(f[0].binormal.z.signum(), f[40].binormal.z.signum());
        }
    }

    #[test]
    fn frenet_on_a_straight_line_is_an_error_rmf_and_fixed_are_not() {
        let pts: Vec<FramePoint> = (0..5)
            .map(|i| FramePoint::smooth(DVec3::new(0.0, 0.0, i as f64), DVec3::Z, DVec3::ZERO))
            .collect();
        let e = compute_frames(&pts, false, FrameKind::Frenet).unwrap_err();
        assert!(matches!(&e, Error::InvalidArgument(m) if m.contains("undefined everywhere")));
        let f = compute_frames(&pts, false, FrameKind::RotationMinimizing).unwrap();
        assert_eq!(f[0].normal, DVec3::X);
        assert_eq!(f[4].normal, DVec3::X);
        assert_eq!(
            compute_frames(&pts, false, FrameKind::Fixed).unwrap()[3].binormal,
            DVec3::Y
        );
    }

    #[test]
    fn fixed_frame_translates_and_rejects_folding() {
        let pts = helix(1.0, 3.0, 0.2, 9);
        let f = compute_frames(&pts, false, FrameKind::Fixed).unwrap();
        for g in &f {
            assert_eq!(g.normal, f[0].normal);
            assert_eq!(g.tangent, f[0].tangent);
        }
        let closed = torus_knot(50);
        assert!(compute_frames(&closed, true, FrameKind::Fixed).is_err());
        let half_turn = helix(1.0, 0.1, 0.5, 20);
        let e = compute_frames(&half_turn, false, FrameKind::Fixed).unwrap_err();
        assert!(matches!(&e, Error::InvalidArgument(m) if m.contains("fold")));
    }

    #[test]
    fn frenet_equals_rmf_on_a_circle() {
        // A circle has no inflection and no torsion: both frames turn with the curve alone.
        let n = 64;
        let circle: Vec<FramePoint> = (0..n)
            .map(|i| {
                let t = TAU * i as f64 / n as f64;
                FramePoint::smooth(
                    DVec3::new(math::cos(t), math::sin(t), 0.0),
                    DVec3::new(-math::sin(t), math::cos(t), 0.0),
                    -DVec3::new(math::cos(t), math::sin(t), 0.0),
                )
            })
            .collect();
        let a = compute_frames(&circle, true, FrameKind::Frenet).unwrap();
        let b = compute_frames(&circle, true, FrameKind::RotationMinimizing).unwrap();
        for (x, y) in a.iter().zip(&b) {
            assert!((x.normal - y.normal).length() < 1e-9);
        }
    }

    #[test]
    fn frenet_that_comes_back_reversed_cannot_close() {
        // A circle whose curvature direction turns half a turn about the tangent on the way
        // round (synthetic data): the sign-continuous Frenet normal comes back reversed.
        let n = 48;
        let pts: Vec<FramePoint> = (0..n)
            .map(|i| {
                let t = TAU * i as f64 / n as f64;
                let tangent = DVec3::new(-math::sin(t), math::cos(t), 0.0);
                let inward = -DVec3::new(math::cos(t), math::sin(t), 0.0);
                let k = DMat3::from_axis_angle(tangent, t / 2.0) * inward;
                FramePoint::smooth(DVec3::new(math::cos(t), math::sin(t), 0.0), tangent, k)
            })
            .collect();
        let e = compute_frames(&pts, true, FrameKind::Frenet).unwrap_err();
        assert!(matches!(&e, Error::InvalidArgument(m) if m.contains("does not close")));
        // The rotation-minimizing frame does not look at the curvature and closes.
        assert!(compute_frames(&pts, true, FrameKind::RotationMinimizing).is_ok());
    }

    #[test]
    fn frenet_carries_its_frame_across_a_straight_stretch() {
        // A quarter circle in the xy plane (from the origin, heading +y, turning to −x), a
        // straight piece along −x, then a quarter circle bending down (−z): the Frenet normal
        // is undefined on the straight piece.
        let mut pts = Vec::new();
        for i in 0..8 {
            let t = TAU / 4.0 * i as f64 / 8.0;
            let (c, s) = (math::cos(t), math::sin(t));
            let radial = DVec3::new(c, s, 0.0);
            pts.push(FramePoint::smooth(
                radial - DVec3::X,
                DVec3::new(-s, c, 0.0),
                -radial,
            ));
        }
        for i in 0..4 {
            let p = DVec3::new(-1.0 - 0.25 * i as f64, 1.0, 0.0);
            pts.push(FramePoint::smooth(p, -DVec3::X, DVec3::ZERO));
        }
        for i in 0..=8 {
            let t = TAU / 4.0 * i as f64 / 8.0;
            let (c, s) = (math::cos(t), math::sin(t));
            let p = DVec3::new(-2.0 - s, 1.0, c - 1.0);
            pts.push(FramePoint::smooth(
                p,
                DVec3::new(-c, 0.0, -s),
                DVec3::new(s, 0.0, -c),
            ));
        }
        let f = compute_frames(&pts, false, FrameKind::Frenet).unwrap();
        // On the first arc the normal points at its centre; on the straight piece it is the
        // one carried from the arc's end (−y); on the second arc, that arc's Frenet normal
        // (−z at its start, +x at its end): Frenet's own twist, but no flip.
        for g in &f[..8] {
            assert!(
                (g.normal - (DVec3::new(-1.0, 0.0, 0.0) - g.origin).normalize()).length() < 1e-12
            );
        }
        for g in &f[8..12] {
            assert!((g.normal - (-DVec3::Y)).length() < 1e-12, "{}", g.normal);
        }
        assert!(
            (f[12].normal - (-DVec3::Z)).length() < 1e-12,
            "{}",
            f[12].normal
        );
        assert!(
            (f[20].normal - DVec3::X).length() < 1e-12,
            "{}",
            f[20].normal
        );
        for g in &f {
            assert_orthonormal(g);
        }
    }

    #[test]
    fn corner_turns_minimally_and_sections_are_mitered() {
        // L: along +x to the origin, then along +y.
        let mut pts = vec![
            FramePoint::smooth(DVec3::new(-2.0, 0.0, 0.0), DVec3::X, DVec3::ZERO),
            FramePoint::smooth(DVec3::new(-1.0, 0.0, 0.0), DVec3::X, DVec3::ZERO),
            FramePoint {
                position: DVec3::ZERO,
                tangent: DVec3::X,
                curvature: DVec3::ZERO,
                tangent_out: Some(DVec3::Y),
            },
            FramePoint::smooth(DVec3::new(0.0, 1.0, 0.0), DVec3::Y, DVec3::ZERO),
        ];
        let f = compute_frames(&pts, false, FrameKind::RotationMinimizing).unwrap();
        // Start normal from the world axis least aligned with +x: +y; binormal +z.
        assert_eq!(f[0].normal, DVec3::Y);
        assert!((f[3].normal - (-DVec3::X)).length() < 1e-12);
        assert!((f[3].binormal - DVec3::Z).length() < 1e-12);
        // Section at the corner: the miter plane x = -y through the origin, widened by √2.
        let p = f[2].place(0.5, 0.25);
        assert!((p - DVec3::new(-0.5, 0.5, 0.25)).length() < 1e-12);
        // The same point is reached from the outgoing side: the section of sample 3 moved back.
        let q = f[3].place(0.5, 0.25) - DVec3::new(0.0, 0.5, 0.0);
        assert!((p - q).length() < 1e-12);
        // Fixed frame: no miter, translation only; here the L turns by 90° so it is refused.
        pts.truncate(3);
        pts[2].tangent_out = None;
        assert!(compute_frames(&pts, false, FrameKind::Fixed).is_ok());
    }

    #[test]
    fn bad_samples_are_refused() {
        let mut pts = helix(1.0, 1.0, 1.0, 5);
        assert!(compute_frames(&pts[..1], false, FrameKind::RotationMinimizing).is_err());
        assert!(compute_frames(&pts[..2], true, FrameKind::RotationMinimizing).is_err());
        pts[2].position.x = f64::NAN;
        assert!(compute_frames(&pts, false, FrameKind::RotationMinimizing).is_err());
        let mut pts = helix(1.0, 1.0, 1.0, 5);
        pts[1].tangent *= 2.0;
        assert!(compute_frames(&pts, false, FrameKind::RotationMinimizing).is_err());
    }
}
