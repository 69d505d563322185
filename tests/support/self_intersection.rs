//! Self-intersection of a triangle mesh: every pair of triangles that share no vertex, found
//! by a uniform grid over their bounding boxes, tested for contact by the separating axis
//! theorem (the two normals, the nine edge-by-edge crosses, and the six in-plane edge
//! normals that separate coplanar triangles). A pair counts as intersecting unless some
//! axis separates it *strictly*: touching counts. Vertices at bit-identical positions are
//! welded first, so triangles meeting across a patch seam are neighbours, not a contact.
//!
//! Floating point: a pair is reported separated when the gap along some axis is positive
//! in f64; on a shell the gaps between non-neighbouring triangles are of the order of the
//! thickness or of a triangle's size, far above rounding. The smallest such gap found
//! (over the separating axis of each tested pair, a lower bound of the pair's distance) is
//! reported with the count, so a near miss is visible.

use std::collections::HashMap;

use glam::DVec3;

/// What [`self_intersections`] found.
#[derive(Debug, Clone, Copy)]
pub struct Contacts {
    /// Triangles tested.
    pub triangles: usize,
    /// Pairs of triangles sharing no vertex whose bounding boxes overlap (tested exactly).
    pub pairs_tested: usize,
    /// Pairs in contact.
    pub intersecting: usize,
    /// Smallest gap of a separated tested pair along its best separating axis.
    pub smallest_gap: f64,
}

/// The contacts between triangles `tris` of `positions` that share no vertex.
pub fn self_intersections(positions: &[DVec3], tris: &[[u32; 3]]) -> Contacts {
    // Weld bit-identical positions.
    let mut ids: HashMap<[u64; 3], u32> = HashMap::new();
    let weld: Vec<u32> = positions
        .iter()
        .map(|p| {
            let key = p.to_array().map(f64::to_bits);
            let next = ids.len() as u32;
            *ids.entry(key).or_insert(next)
        })
        .collect();
    let tris: Vec<[u32; 3]> = tris.iter().map(|t| t.map(|v| weld[v as usize])).collect();
    let mut points = vec![DVec3::ZERO; ids.len()];
    for (i, p) in positions.iter().enumerate() {
        points[weld[i] as usize] = *p;
    }
    let corners = |t: &[u32; 3]| t.map(|v| points[v as usize]);
    let boxes: Vec<(DVec3, DVec3)> = tris
        .iter()
        .map(|t| {
            let [a, b, c] = corners(t);
            (a.min(b).min(c), a.max(b).max(c))
        })
        .collect();
    // Grid cell: twice the mean box extent.
    let mean = boxes
        .iter()
        .map(|(lo, hi)| (*hi - *lo).max_element())
        .sum::<f64>()
        / boxes.len().max(1) as f64;
    let cell = (2.0 * mean).max(f64::MIN_POSITIVE);
    let key = |p: DVec3| (p / cell).floor().as_i64vec3().to_array();
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
    for (i, (lo, hi)) in boxes.iter().enumerate() {
        let (a, b) = (key(*lo), key(*hi));
        for x in a[0]..=b[0] {
            for y in a[1]..=b[1] {
                for z in a[2]..=b[2] {
                    grid.entry([x, y, z]).or_default().push(i as u32);
                }
            }
        }
    }
    let mut found = Contacts {
        triangles: tris.len(),
        pairs_tested: 0,
        intersecting: 0,
        smallest_gap: f64::INFINITY,
    };
    for (cell_key, list) in &grid {
        for (k, &i) in list.iter().enumerate() {
            for &j in &list[k + 1..] {
                let (ti, tj) = (&tris[i as usize], &tris[j as usize]);
                if ti.iter().any(|v| tj.contains(v)) {
                    continue;
                }
                let (bi, bj) = (boxes[i as usize], boxes[j as usize]);
                let (lo, hi) = (bi.0.max(bj.0), bi.1.min(bj.1));
                if lo.cmpgt(hi).any() {
                    continue;
                }
                // Test each pair once: in the cell holding the low corner of the overlap.
                if key(lo) != *cell_key {
                    continue;
                }
                found.pairs_tested += 1;
                match separation(corners(ti), corners(tj)) {
                    Some(gap) => found.smallest_gap = found.smallest_gap.min(gap),
                    None => found.intersecting += 1,
                }
            }
        }
    }
    found
}

/// The largest gap between triangles `a` and `b` along a separating axis (unit length),
/// `None` if no axis separates them strictly (they touch or intersect).
fn separation(a: [DVec3; 3], b: [DVec3; 3]) -> Option<f64> {
    let edges = |t: &[DVec3; 3]| [t[1] - t[0], t[2] - t[1], t[0] - t[2]];
    let (ea, eb) = (edges(&a), edges(&b));
    let (na, nb) = (ea[0].cross(ea[1]), eb[0].cross(eb[1]));
    let mut axes = vec![na, nb];
    for x in &ea {
        for y in &eb {
            axes.push(x.cross(*y));
        }
        axes.push(na.cross(*x));
    }
    for y in &eb {
        axes.push(nb.cross(*y));
    }
    let scale = a.iter().chain(&b).map(|p| p.length()).fold(0.0, f64::max);
    let mut best: Option<f64> = None;
    for axis in axes {
        let len = axis.length();
        if len <= 1e-300 || !len.is_finite() {
            continue;
        }
        let axis = axis / len;
        let range = |t: &[DVec3; 3]| {
            let d = t.map(|p| p.dot(axis));
            (d[0].min(d[1]).min(d[2]), d[0].max(d[1]).max(d[2]))
        };
        let ((a0, a1), (b0, b1)) = (range(&a), range(&b));
        let gap = (b0 - a1).max(a0 - b1);
        // Axes from nearly parallel edges lose digits: a gap must beat their rounding.
        if gap > 1e-15 * scale {
            best = Some(best.map_or(gap, |g: f64| g.max(gap)));
        }
    }
    best
}
