//! The triangulation of one parametric face's unit square, from its rates alone (no
//! geometry): an `n × n` grid inside, and each side cut into its own number of segments.
//!
//! When every side has `n` segments the square is the plain grid of `n × n` cells. Otherwise
//! the grid's outer ring is dropped: the inner points `(i/n, j/n)`, `1 ≤ i, j ≤ n-1` (just the
//! centre when `n ≤ 2`) keep their cells, and each side's points are joined to the inner
//! ring's facing row by a strip of triangles (a zipper in the order of the points along the
//! side). Points on the sides are exactly the side's, so two faces that agree on a side's
//! count share its points: no T-junction.

/// Where a point of the square lies; sides run counter-clockwise (side 0 from `(0,0)` to
/// `(1,0)`, side 1 from `(1,0)` to `(1,1)`, side 2 from `(1,1)` to `(0,1)`, side 3 from
/// `(0,1)` to `(0,0)`), and corner `c` is where side `c` starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spot {
    /// Corner 0-3.
    Corner(u8),
    /// Point `k` (1 ≤ k < segments) of a side, counted from the side's start.
    Side(u8, u32),
    /// A point strictly inside: `(i/n, j/n)` of the inner grid.
    Inner(u32, u32),
}

/// A triangulated (or quadrangulated) square: the points with their `(u, v)`, and polygons
/// (3 or 4 corners, counter-clockwise in `(u, v)`) as indices into the points.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Stitched {
    /// Each point's place and `(u, v)`.
    pub points: Vec<(Spot, [f64; 2])>,
    /// Polygon sizes (3 or 4).
    pub sizes: Vec<u8>,
    /// Polygon corners, `sizes` at a time.
    pub corners: Vec<u32>,
}

/// `(u, v)` of the point at fraction `t` along side `s`.
fn on_side(s: u8, t: f64) -> [f64; 2] {
    match s {
        0 => [t, 0.0],
        1 => [1.0, t],
        2 => [1.0 - t, 1.0],
        _ => [0.0, 1.0 - t],
    }
}

impl Stitched {
    fn push(&mut self, spot: Spot, uv: [f64; 2]) -> u32 {
        self.points.push((spot, uv));
        (self.points.len() - 1) as u32
    }

    fn polygon(&mut self, corners: &[u32]) {
        self.sizes.push(corners.len() as u8);
        self.corners.extend_from_slice(corners);
    }
}

/// The points of side `s` with `segments` segments, corners included, in side order.
fn side_points(out: &mut Stitched, s: u8, segments: u32) -> Vec<u32> {
    let mut ids = vec![out.push(Spot::Corner(s), on_side(s, 0.0))];
    for k in 1..segments {
        ids.push(out.push(Spot::Side(s, k), on_side(s, k as f64 / segments as f64)));
    }
    ids
}

/// Triangulate the unit square with an inner rate `n` (≥ 1) and side segment counts `sides`
/// (each ≥ 1). Grid cells are quads (counter-clockwise); transition strips are triangles.
pub fn stitch(n: u32, sides: [u32; 4]) -> Stitched {
    let mut out = Stitched::default();
    let rings: Vec<Vec<u32>> = (0..4)
        .map(|s| side_points(&mut out, s, sides[s as usize]))
        .collect();
    // Point at fraction `k` of side s: rings[s][k], and the next side's corner at the end.
    let side_at = |s: usize, k: usize| {
        if k < rings[s].len() {
            rings[s][k]
        } else {
            rings[(s + 1) % 4][0]
        }
    };
    if sides.iter().all(|&r| r == n) {
        let id = |i: u32, j: u32| -> u32 {
            // Walk the boundary ring: side 0 is j = 0, side 1 i = n, side 2 j = n, side 3 i = 0.
            let n = n as usize;
            let (i, j) = (i as usize, j as usize);
            if j == 0 {
                side_at(0, i)
            } else if i == n {
                side_at(1, j)
            } else if j == n {
                side_at(2, n - i)
            } else if i == 0 {
                side_at(3, n - j)
            } else {
                u32::MAX
            }
        };
        let mut inner = vec![u32::MAX; ((n + 1) * (n + 1)) as usize];
        for j in 0..=n {
            for i in 0..=n {
                let b = id(i, j);
                inner[(j * (n + 1) + i) as usize] = if b != u32::MAX {
                    b
                } else {
                    out.push(
                        Spot::Inner(i, j),
                        [i as f64 / n as f64, j as f64 / n as f64],
                    )
                };
            }
        }
        let at = |i: u32, j: u32| inner[(j * (n + 1) + i) as usize];
        for j in 0..n {
            for i in 0..n {
                out.polygon(&[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
        return out;
    }
    // Inner grid of m × m points (m = n - 1 ≥ 1), at (i/n, j/n) for i, j in 1..n; a rate
    // below 2 uses the centre alone.
    let n = n.max(2);
    let m = n - 1;
    let mut inner = Vec::with_capacity((m * m) as usize);
    for j in 1..n {
        for i in 1..n {
            inner.push(out.push(
                Spot::Inner(i, j),
                [i as f64 / n as f64, j as f64 / n as f64],
            ));
        }
    }
    let at = |i: u32, j: u32| inner[((j - 1) * m + (i - 1)) as usize];
    for j in 1..n - 1 {
        for i in 1..n - 1 {
            out.polygon(&[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    for (s, &segments) in sides.iter().enumerate() {
        // The inner ring's row facing side s, in the side's direction.
        let row: Vec<u32> = (1..n)
            .map(|k| match s {
                0 => at(k, 1),
                1 => at(n - 1, k),
                2 => at(n - k, n - 1),
                _ => at(1, n - k),
            })
            .collect();
        let p = segments as usize;
        let q = row.len() - 1;
        // Fractions along the side: outer k/p, inner (1 + k)/n.
        let (mut i, mut j) = (0usize, 0usize);
        while i < p || j < q {
            let next_outer = (i + 1) as f64 / p as f64;
            let next_inner = (j + 2) as f64 / n as f64;
            if j == q || (i < p && next_outer <= next_inner) {
                out.polygon(&[side_at(s, i), side_at(s, i + 1), row[j]]);
                i += 1;
            } else {
                out.polygon(&[side_at(s, i), row[j + 1], row[j]]);
                j += 1;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Twice the signed area of polygon `k` in (u, v).
    fn signed_area(s: &Stitched, start: usize, size: usize) -> f64 {
        let p: Vec<[f64; 2]> = (0..size)
            .map(|c| s.points[s.corners[start + c] as usize].1)
            .collect();
        (0..size)
            .map(|c| {
                let (a, b) = (p[c], p[(c + 1) % size]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum()
    }

    /// Every polygon is counter-clockwise with positive area, the areas fill the unit square,
    /// and every edge is either on the square's border (used once) or used once each way.
    fn check_tiling(s: &Stitched, sides: [u32; 4]) {
        let mut start = 0;
        let mut area = 0.0;
        let mut edges = std::collections::HashMap::new();
        for &size in &s.sizes {
            let a = signed_area(s, start, size as usize);
            assert!(a > 1e-12, "polygon at {start} has area {a}");
            area += a / 2.0;
            for c in 0..size as usize {
                let e = (
                    s.corners[start + c],
                    s.corners[start + (c + 1) % size as usize],
                );
                assert!(edges.insert(e, ()).is_none(), "directed edge {e:?} twice");
            }
            start += size as usize;
        }
        assert!((area - 1.0).abs() < 1e-12, "area {area}");
        let mut border = 0;
        for &(a, b) in edges.keys() {
            if !edges.contains_key(&(b, a)) {
                border += 1;
                let (pa, pb) = (s.points[a as usize].1, s.points[b as usize].1);
                let on_border = |p: [f64; 2]| p.iter().any(|&x| x == 0.0 || x == 1.0);
                assert!(on_border(pa) && on_border(pb));
            }
        }
        assert_eq!(border, sides.iter().sum::<u32>() as usize);
    }

    #[test]
    fn uniform_grid_is_quads() {
        let s = stitch(3, [3; 4]);
        assert_eq!(s.points.len(), 16);
        assert_eq!(s.sizes, vec![4; 9]);
        check_tiling(&s, [3; 4]);
    }

    #[test]
    fn transitions_tile_the_square_without_t_junctions() {
        for n in 1..6 {
            for sides in [
                [n, n + 1, n, n],
                [1, 2, 3, 4],
                [7, 1, 2, 9],
                [2, 2, 2, 2],
                [n, n, 2 * n, n],
            ] {
                let s = stitch(n, sides);
                check_tiling(&s, sides);
                for (k, &r) in sides.iter().enumerate() {
                    let on = s
                        .points
                        .iter()
                        .filter(
                            |(spot, _)| matches!(spot, Spot::Side(side, _) if *side as usize == k),
                        )
                        .count();
                    assert_eq!(on, r as usize - 1);
                }
            }
        }
    }
}
