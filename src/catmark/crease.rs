//! The crease rules: sharpness classification and decay, vertex rule classification and the
//! fractional weight that blends two rules while a semi-sharp feature decays.
//!
//! Everything here works on plain sharpness values in `f32`, as OpenSubdiv's `Sdc::Crease`
//! does: the decay, the Chaikin averages and the fractional weights are rounded to single
//! precision at every step, which is what makes refined positions agree with OpenSubdiv to the
//! last bits even though positions themselves are `f64`.

use crate::options::CreaseMethod;

/// Sharpness of a smooth edge or vertex.
pub const SHARPNESS_SMOOTH: f32 = 0.0;
/// Sharpness at or above which an edge or vertex is infinitely sharp.
pub const SHARPNESS_INFINITE: f32 = crate::mesh::SHARPNESS_INFINITE;

/// The subdivision rule of a vertex, from its own sharpness and the number of sharp edges
/// around it (`Sdc::Crease::Rule`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Rule {
    /// No sharp feature: the smooth Catmull-Clark vertex rule.
    Smooth,
    /// Exactly one sharp edge: treated with the smooth rule.
    Dart,
    /// Exactly two sharp edges: the curve rule along them.
    Crease,
    /// A sharp vertex, or more than two sharp edges: the vertex does not move.
    Corner,
}

/// True if `s` is smooth (`<= 0`).
pub fn is_smooth(s: f32) -> bool {
    s <= SHARPNESS_SMOOTH
}

/// True if `s` is sharp (`> 0`), semi-sharp or infinite.
pub fn is_sharp(s: f32) -> bool {
    s > SHARPNESS_SMOOTH
}

/// True if `s` is infinitely sharp (`>= 10`).
pub fn is_infinite(s: f32) -> bool {
    s >= SHARPNESS_INFINITE
}

/// True if `s` is sharp but not infinitely so.
pub fn is_semi_sharp(s: f32) -> bool {
    SHARPNESS_SMOOTH < s && s < SHARPNESS_INFINITE
}

/// Uniform decay by one level: infinite stays infinite, sharpness above 1 loses 1, the rest
/// becomes smooth.
pub fn decrement_sharpness(s: f32) -> f32 {
    if is_smooth(s) {
        SHARPNESS_SMOOTH
    } else if is_infinite(s) {
        SHARPNESS_INFINITE
    } else if s > 1.0 {
        s - 1.0
    } else {
        SHARPNESS_SMOOTH
    }
}

/// Sharpness of the child of a sharp vertex: always the uniform decay, whatever the method.
pub fn subdivide_vertex_sharpness(s: f32) -> f32 {
    decrement_sharpness(s)
}

/// Sharpness of the child edge of an edge with sharpness `s` at one of its end vertices,
/// given the sharpness of all edges around that vertex (the edge itself included).
///
/// Uniform: the decay. Chaikin: `3/4 s + 1/4 (average of the other semi-sharp edges) - 1`,
/// when the vertex has at least two semi-sharp edges.
pub fn subdivide_edge_sharpness_at_vertex(method: CreaseMethod, s: f32, around: &[f32]) -> f32 {
    if method == CreaseMethod::Uniform || around.len() < 2 {
        return decrement_sharpness(s);
    }
    if is_smooth(s) {
        return SHARPNESS_SMOOTH;
    }
    if is_infinite(s) {
        return SHARPNESS_INFINITE;
    }
    let mut sum = 0.0f32;
    let mut count = 0i32;
    for &e in around {
        if is_semi_sharp(e) {
            count += 1;
            sum += e;
        }
    }
    let mut child = s;
    if count > 1 {
        let others = (sum - s) / (count - 1) as f32;
        child = (0.75f32 * s) + (0.25f32 * others);
    }
    child -= 1.0;
    if is_sharp(child) {
        child
    } else {
        SHARPNESS_SMOOTH
    }
}

/// Child sharpness of every edge around a vertex, at that vertex (`parent` and `child` have
/// one entry per incident edge).
///
/// Panics if the slices differ in length.
pub fn subdivide_edge_sharpnesses_around_vertex(
    method: CreaseMethod,
    parent: &[f32],
    child: &mut [f32],
) {
    assert_eq!(parent.len(), child.len());
    if method == CreaseMethod::Uniform || parent.len() < 2 {
        for (c, &p) in child.iter_mut().zip(parent) {
            *c = decrement_sharpness(p);
        }
        return;
    }
    let mut sum = 0.0f32;
    let mut count = 0i32;
    for &p in parent {
        if is_semi_sharp(p) {
            count += 1;
            sum += p;
        }
    }
    if count == 0 {
        child.copy_from_slice(parent);
        return;
    }
    for (c, &p) in child.iter_mut().zip(parent) {
        *c = if is_smooth(p) {
            SHARPNESS_SMOOTH
        } else if is_infinite(p) {
            SHARPNESS_INFINITE
        } else if count == 1 {
            decrement_sharpness(p)
        } else {
            let others = (sum - p) / (count - 1) as f32;
            let s = ((0.75f32 * p) + (0.25f32 * others)) - 1.0;
            if is_smooth(s) {
                SHARPNESS_SMOOTH
            } else {
                s
            }
        };
    }
}

/// The rule of a vertex with sharpness `vertex_sharpness` and `sharp_edge_count` sharp
/// incident edges: corner if the vertex is sharp or more than two edges are, otherwise
/// smooth, dart or crease for 0, 1 or 2 sharp edges.
pub fn vertex_rule(vertex_sharpness: f32, sharp_edge_count: usize) -> Rule {
    if is_sharp(vertex_sharpness) {
        return Rule::Corner;
    }
    match sharp_edge_count {
        0 => Rule::Smooth,
        1 => Rule::Dart,
        2 => Rule::Crease,
        _ => Rule::Corner,
    }
}

/// [`vertex_rule`] counting the sharp edges among `edge_sharpness`.
pub fn vertex_rule_from_edges(vertex_sharpness: f32, edge_sharpness: &[f32]) -> Rule {
    let sharp = edge_sharpness.iter().filter(|&&s| is_sharp(s)).count();
    vertex_rule(vertex_sharpness, sharp)
}

/// The weight of the parent rule when a vertex's rule changes between a parent and its child
/// (`Sdc::Crease::ComputeFractionalWeightAtVertex`): the average sharpness of the features
/// that become smooth (vertex and edges), clamped to 1. The child mask gets `1 - weight`.
///
/// Uniform creasing counts edges with parent sharpness in `(0, 1]`; Chaikin counts edges
/// whose child sharpness is smooth. Panics if the edge slices differ in length.
pub fn fractional_weight_at_vertex(
    method: CreaseMethod,
    parent_vertex: f32,
    child_vertex: f32,
    parent_edges: &[f32],
    child_edges: &[f32],
) -> f32 {
    assert_eq!(parent_edges.len(), child_edges.len());
    let mut count = 0i32;
    let mut sum = 0.0f32;
    if is_sharp(parent_vertex) && is_smooth(child_vertex) {
        count = 1;
        sum = parent_vertex;
    }
    for (&p, &c) in parent_edges.iter().zip(child_edges) {
        let transition = match method {
            CreaseMethod::Uniform => is_sharp(p) && p <= 1.0,
            CreaseMethod::Chaikin => is_sharp(p) && is_smooth(c),
        };
        if transition {
            sum += p;
            count += 1;
        }
    }
    if count == 0 {
        return 0.0;
    }
    let w = sum / count as f32;
    if w > 1.0 {
        1.0
    } else {
        w
    }
}

/// Positions of the first and the last sharp edge around a crease vertex, in incident-edge
/// order. For a vertex with no sharp edge (not a crease) both are `None`.
pub fn sharp_edge_pair_of_crease(edge_sharpness: &[f32]) -> Option<[usize; 2]> {
    let first = edge_sharpness.iter().position(|&s| is_sharp(s))?;
    let last = edge_sharpness.iter().rposition(|&s| is_sharp(s))?;
    Some([first, last])
}

#[cfg(test)]
mod tests {
    use super::*;
    use CreaseMethod::{Chaikin, Uniform};

    #[test]
    fn uniform_decay() {
        assert_eq!(decrement_sharpness(0.0), 0.0);
        assert_eq!(decrement_sharpness(0.7), 0.0);
        assert_eq!(decrement_sharpness(1.0), 0.0);
        assert_eq!(decrement_sharpness(2.5), 1.5);
        assert_eq!(decrement_sharpness(10.0), 10.0);
        assert_eq!(decrement_sharpness(12.0), 10.0);
        // 1.1 - 1 in f32 is not 0.1 in f64:
        assert_eq!(decrement_sharpness(1.1), 1.1f32 - 1.0f32);
        assert_ne!(decrement_sharpness(1.1) as f64, 0.1f64);
    }

    #[test]
    fn chaikin_averages_in_f32() {
        // Edge 2.0 among semi-sharp 2.0 and 1.0 and an infinite edge: others avg = 1.0.
        let around = [2.0f32, 1.0, 10.0, 0.0];
        assert_eq!(
            subdivide_edge_sharpness_at_vertex(Chaikin, 2.0, &around),
            0.75
        );
        assert_eq!(
            subdivide_edge_sharpness_at_vertex(Chaikin, 1.0, &around),
            0.25
        );
        assert_eq!(
            subdivide_edge_sharpness_at_vertex(Chaikin, 10.0, &around),
            10.0
        );
        assert_eq!(
            subdivide_edge_sharpness_at_vertex(Uniform, 2.0, &around),
            1.0
        );
        let mut child = [0.0f32; 4];
        subdivide_edge_sharpnesses_around_vertex(Chaikin, &around, &mut child);
        assert_eq!(child, [0.75, 0.25, 10.0, 0.0]);
        // Single semi-sharp edge: plain decay.
        subdivide_edge_sharpnesses_around_vertex(Chaikin, &[3.0, 0.0], &mut child[..2]);
        assert_eq!(&child[..2], &[2.0, 0.0]);
        // f32 arithmetic: 0.75*1.3 + 0.25*0.7 - 1
        let s = subdivide_edge_sharpness_at_vertex(Chaikin, 1.3, &[1.3, 0.7]);
        assert_eq!(s, (0.75f32 * 1.3f32 + 0.25f32 * 0.7f32) - 1.0f32);
        assert_eq!(
            subdivide_edge_sharpness_at_vertex(Chaikin, 0.7, &[1.3, 0.7]),
            0.0
        );
    }

    #[test]
    fn rules() {
        assert_eq!(vertex_rule(0.0, 0), Rule::Smooth);
        assert_eq!(vertex_rule(0.0, 1), Rule::Dart);
        assert_eq!(vertex_rule(0.0, 2), Rule::Crease);
        assert_eq!(vertex_rule(0.0, 3), Rule::Corner);
        assert_eq!(vertex_rule(0.5, 0), Rule::Corner);
        assert_eq!(
            vertex_rule_from_edges(0.0, &[0.0, 2.0, 0.0, 10.0]),
            Rule::Crease
        );
        assert_eq!(
            sharp_edge_pair_of_crease(&[0.0, 2.0, 0.0, 10.0]),
            Some([1, 3])
        );
        assert_eq!(sharp_edge_pair_of_crease(&[0.0, 0.0]), None);
    }

    #[test]
    fn fractional_weight() {
        // Uniform: edges with sharpness in (0,1] and a decaying vertex are averaged.
        let w = fractional_weight_at_vertex(Uniform, 0.5, 0.0, &[0.3, 0.0, 2.0], &[0.0, 0.0, 1.0]);
        assert_eq!(w, (0.5f32 + 0.3f32) / 2.0);
        assert_eq!(
            fractional_weight_at_vertex(Uniform, 0.0, 0.0, &[2.0, 2.0], &[1.0, 1.0]),
            0.0
        );
        // Chaikin: an edge above 1 may still decay to 0, and the weight clamps to 1.
        assert_eq!(
            fractional_weight_at_vertex(Chaikin, 0.0, 0.0, &[1.2, 0.0], &[0.0, 0.0]),
            1.0
        );
    }
}
