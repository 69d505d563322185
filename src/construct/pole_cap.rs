//! Closing a ring of `n = 4k` vertices with quads.
//!
//! A *grid cap* is a `k × k` grid patch whose boundary is the ring: its four corners are ring
//! vertices of valence 3 and every other vertex of the patch has valence 4, so a pole never
//! becomes a vertex of valence `n`. The patch's interior vertices lie on concentric squares;
//! each is described by a [`CapVertex`] (relative radius and angle) so that the caller can
//! place its data point on the surface: square ring `ρ` maps to the curve ring at relative
//! radius `ρ`, and a square's perimeter maps uniformly to the full turn.
//!
//! A *tip fan* closes the ring at a single vertex with `n / 2` quads `(tip, r₂ⱼ, r₂ⱼ₊₁,
//! r₂ⱼ₊₂)`; the tip (valence `n / 2`) is meant to be tagged as an infinitely sharp corner,
//! the odd ring vertices get valence 3.
//!
//! Orientation: faces are produced counter-clockwise when the ring runs counter-clockwise
//! seen from the side the cap faces (`flip = false`); `flip = true` reverses every face.

use crate::error::{Error, Result};

/// Where an interior vertex of a grid cap lies, relative to the ring it fills.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapVertex {
    /// Relative radius: 0 at the centre, 1 on the ring (interior vertices are `< 1`).
    pub radius: f64,
    /// Angle as a fraction of a full turn, measured like the ring's vertex angles
    /// (ring vertex `p` sits at `p / n`).
    pub turn: f64,
}

/// Quads and new interior vertices of a cap.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Cap {
    /// Quads, as vertex ids (ring ids and new ids starting at the `first_new` given).
    pub faces: Vec<[u32; 4]>,
    /// The new interior vertices, in id order.
    pub vertices: Vec<CapVertex>,
}

/// A `k × k` grid patch filling `ring` (`n = 4k` vertex ids in counter-clockwise order,
/// ring vertex `p` at angle `p / n` turns). New vertices get ids from `first_new` on.
///
/// Errors: [`Error::InvalidArgument`] if the ring size is not a positive multiple of 4.
pub fn grid_cap(ring: &[u32], first_new: u32, flip: bool) -> Result<Cap> {
    let n = ring.len();
    if n == 0 || n % 4 != 0 {
        return Err(Error::invalid_argument(format!(
            "a grid cap needs a ring of 4k vertices, got {n}"
        )));
    }
    let k = (n / 4) as i64;
    // Doubled grid coordinates G = 2i - k, H = 2j - k keep everything integral for odd k.
    let mut ids = vec![u32::MAX; ((k + 1) * (k + 1)) as usize];
    let mut cap = Cap::default();
    for j in 0..=k {
        for i in 0..=k {
            let (g, h) = (2 * i - k, 2 * j - k);
            let rho2 = g.abs().max(h.abs());
            let id = if rho2 == k {
                let p = ((square_arc2(g, h, rho2) - k % 2) / 2) as usize;
                ring[p]
            } else {
                let id = first_new + cap.vertices.len() as u32;
                cap.vertices.push(interior_vertex(g, h, rho2, k, n));
                id
            };
            ids[(j * (k + 1) + i) as usize] = id;
        }
    }
    let at = |i: i64, j: i64| ids[(j * (k + 1) + i) as usize];
    for j in 0..k {
        for i in 0..k {
            let f = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            cap.faces
                .push(if flip { [f[0], f[3], f[2], f[1]] } else { f });
        }
    }
    Ok(cap)
}

/// Doubled perimeter position of grid point `(g, h)` (doubled coordinates) on its square of
/// doubled Chebyshev radius `rho2`, counter-clockwise from the point `(rho2, 0)`.
fn square_arc2(g: i64, h: i64, rho2: i64) -> i64 {
    let arc = if g == rho2 && h > -rho2 {
        h
    } else if h == rho2 {
        2 * rho2 - g
    } else if g == -rho2 {
        4 * rho2 - h
    } else {
        6 * rho2 + g
    };
    arc.rem_euclid(8 * rho2)
}

fn interior_vertex(g: i64, h: i64, rho2: i64, k: i64, n: usize) -> CapVertex {
    if rho2 == 0 {
        return CapVertex {
            radius: 0.0,
            turn: 0.0,
        };
    }
    let radius = rho2 as f64 / k as f64;
    // For odd k the ring's vertex 0 sits half a grid step past the square's axis point; the
    // inner squares turn back by a share of that proportional to their radius.
    let shift = (k % 2) as f64 / (2.0 * n as f64);
    let turn = square_arc2(g, h, rho2) as f64 / (8 * rho2) as f64 - shift * radius;
    CapVertex { radius, turn }
}

/// How many ring intervals a smooth pole's grid cap on a ring of `n = 4k` vertices should
/// replace: `k / 4` rounded, at least 2 (but at most `k / 2`). The cap's `k / 2` concentric
/// squares step inwards by `2ρ / k` of its radius `ρ` and along its perimeter by `πρ / 2k`,
/// so its cells are nearly square for any depth, within a factor 2 or so of the faces around
/// them at this depth (`k / 2` would make them equal). A cap inside the first ring (depth 1
/// at any `n`) left cells `k / 2` times smaller than their neighbours and the interpolating
/// fit folded there (spheres and ellipsoids at 64 × 32); deeper caps move the valence-3
/// corners, where the fit's error is largest, to where the faces are larger (measured on
/// the unit sphere by profiles at 32 × 16, with [`crate::construct::equidistribute`]'s mild
/// pole grading: 8.2e-4 of its size at depth 2, 1.0e-3 at 3, 1.2e-3 at 4).
pub fn grid_cap_depth(n: usize) -> usize {
    let k = n / 4;
    ((k + 2) / 4).max(2).min((k / 2).max(1))
}

/// How many ring intervals the grid cap of each smooth pole replaces (0 at an end that is
/// not a smooth pole): `want` ([`grid_cap_depth`]), but at most what leaves one interval of the pole's run
/// outside the cap (a crease ring at the run's end would otherwise meet the cap's
/// valence-3 corners, whose one face there spans a straight angle), and room for the other
/// end's cap or tip (`tips`: that end is closed by a fan, one interval); at least 1.
/// `runs` are the ring intervals of the runs between breakpoints, bottom to top.
pub fn cap_depths(smooth: [bool; 2], tips: [bool; 2], runs: &[usize], want: usize) -> [usize; 2] {
    let mut depth = [0, 0];
    let Some(&last) = runs.last() else {
        return depth;
    };
    if runs.len() == 1 {
        let budget = last.saturating_sub(1 + usize::from(tips[0]) + usize::from(tips[1]));
        let share = if smooth[0] && smooth[1] {
            budget / 2
        } else {
            budget
        };
        for e in 0..2 {
            if smooth[e] {
                depth[e] = want.min(share).max(1);
            }
        }
    } else {
        for (e, run) in [(0, runs[0]), (1, last)] {
            if smooth[e] {
                depth[e] = want.min(run.saturating_sub(1)).max(1);
            }
        }
    }
    depth
}

/// Quads closing `ring` (even length ≥ 4) at the vertex `tip`.
///
/// Errors: [`Error::InvalidArgument`] if the ring size is odd or below 4.
pub fn tip_fan(ring: &[u32], tip: u32, flip: bool) -> Result<Vec<[u32; 4]>> {
    let n = ring.len();
    if n < 4 || n % 2 != 0 {
        return Err(Error::invalid_argument(format!(
            "a tip fan needs an even ring of at least 4 vertices, got {n}"
        )));
    }
    Ok((0..n / 2)
        .map(|j| {
            let f = [tip, ring[2 * j], ring[2 * j + 1], ring[(2 * j + 2) % n]];
            if flip {
                [f[0], f[3], f[2], f[1]]
            } else {
                f
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    fn valences(faces: &[[u32; 4]]) -> HashMap<u32, usize> {
        let mut edges = std::collections::HashSet::new();
        for f in faces {
            for i in 0..4 {
                let (a, b) = (f[i], f[(i + 1) % 4]);
                edges.insert((a.min(b), a.max(b)));
            }
        }
        let mut v = HashMap::new();
        for (a, b) in edges {
            *v.entry(a).or_insert(0) += 1;
            *v.entry(b).or_insert(0) += 1;
        }
        v
    }

    #[test]
    fn grid_cap_has_k_squared_quads_and_closes_the_ring() {
        for k in 1..=5u32 {
            let n = 4 * k;
            let ring: Vec<u32> = (0..n).collect();
            let cap = grid_cap(&ring, n, false).unwrap();
            assert_eq!(cap.faces.len() as u32, k * k);
            assert_eq!(cap.vertices.len() as u32, (k - 1) * (k - 1));
            let val = valences(&cap.faces);
            // Inside the patch: ring corners have 2 edges, other ring vertices 3, interior 4.
            let corners = ring.iter().filter(|r| val[r] == 2).count();
            assert_eq!(corners, 4, "k={k}");
            assert!((n..n + (k - 1) * (k - 1)).all(|v| val[&v] == 4));
            // Every ring edge (p, p+1) is a patch edge used by exactly one face, in ring order
            // (counter-clockwise faces traverse the boundary forwards).
            for p in 0..n {
                let q = (p + 1) % n;
                let fwd = cap
                    .faces
                    .iter()
                    .filter(|f| (0..4).any(|i| f[i] == p && f[(i + 1) % 4] == q))
                    .count();
                assert_eq!(fwd, 1, "k={k} edge {p}-{q}");
            }
        }
    }

    #[test]
    fn grid_cap_interior_angles_follow_the_ring() {
        let ring: Vec<u32> = (0..16).collect();
        let cap = grid_cap(&ring, 16, false).unwrap();
        // k = 4: the centre and two squares of radius 1/2 with 8 vertices.
        assert_eq!(cap.vertices.len(), 9);
        let centre: Vec<_> = cap.vertices.iter().filter(|v| v.radius == 0.0).collect();
        assert_eq!(centre.len(), 1);
        let mut turns: Vec<f64> = cap
            .vertices
            .iter()
            .filter(|v| v.radius == 0.5)
            .map(|v| v.turn)
            .collect();
        turns.sort_by(f64::total_cmp);
        let expect: Vec<f64> = (0..8).map(|i| i as f64 / 8.0).collect();
        assert_eq!(turns, expect);
        // Odd k: the inner square is turned back by half a ring step times its radius.
        let ring: Vec<u32> = (0..12).collect();
        let cap = grid_cap(&ring, 12, false).unwrap();
        let mut turns: Vec<f64> = cap.vertices.iter().map(|v| v.turn).collect();
        turns.sort_by(f64::total_cmp);
        let shift = 1.0 / 24.0 / 3.0;
        assert!((turns[0] - (1.0 / 8.0 - shift)).abs() < 1e-15, "{turns:?}");
    }

    #[test]
    fn caps_take_their_squares_but_leave_a_ring_before_a_crease() {
        let depths: Vec<usize> = [4, 8, 16, 32, 64, 128].map(grid_cap_depth).to_vec();
        assert_eq!(depths, vec![1, 1, 2, 2, 4, 8]);
        // Two runs: each smooth end keeps one interval of its run outside the cap.
        assert_eq!(cap_depths([true, true], [false; 2], &[3, 10, 8], 4), [2, 4]);
        assert_eq!(cap_depths([true, false], [false; 2], &[1, 10], 4), [1, 0]);
        // One run between two poles: they share it, one interval between the caps.
        assert_eq!(cap_depths([true, true], [false; 2], &[16], 4), [4, 4]);
        assert_eq!(cap_depths([true, true], [false; 2], &[5], 4), [2, 2]);
        assert_eq!(cap_depths([true, true], [false; 2], &[3], 4), [1, 1]);
        // A tip at the other end takes one interval.
        assert_eq!(cap_depths([true, false], [false, true], &[4], 8), [2, 0]);
        assert_eq!(cap_depths([false; 2], [false; 2], &[4], 8), [0, 0]);
    }

    #[test]
    fn tip_fan_gives_valence_3_on_odd_ring_vertices() {
        let ring: Vec<u32> = (0..8).collect();
        let faces = tip_fan(&ring, 8, false).unwrap();
        assert_eq!(faces.len(), 4);
        let val = valences(&faces);
        assert_eq!(val[&8], 4);
        assert_eq!(val[&1], 2);
        assert_eq!(val[&2], 3);
        assert!(tip_fan(&ring[..6], 8, false).is_ok());
        assert!(tip_fan(&ring[..3], 8, false).is_err());
        assert!(grid_cap(&ring[..6], 8, false).is_err());
    }
}
