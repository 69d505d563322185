//! OpenSubdiv's creasing arithmetic (`Sdc::Crease`) for the vertex-limit code: sharpness
//! decay, Chaikin averaging, vertex rules and fractional weights.
//!
//! Sharpness stays `f32` and every operation is done in `f32` in OpenSubdiv's order, so that
//! fractional weights are bit-identical to Far's.

use crate::options::CreaseMethod;

/// Sharpness at or above which an edge or vertex is infinitely sharp.
pub(crate) const INFINITE: f32 = 10.0;

/// `Sdc::Crease::IsSharp`.
pub(crate) fn is_sharp(s: f32) -> bool {
    s > 0.0
}

/// `Sdc::Crease::IsInfinite`.
pub(crate) fn is_infinite(s: f32) -> bool {
    s >= INFINITE
}

/// `Sdc::Crease::IsSemiSharp`.
pub(crate) fn is_semi_sharp(s: f32) -> bool {
    s > 0.0 && s < INFINITE
}

/// Uniform decay of one level (`Crease::decrementSharpness`).
pub(crate) fn decrement(s: f32) -> f32 {
    if s <= 0.0 {
        0.0
    } else if is_infinite(s) {
        INFINITE
    } else if s > 1.0 {
        s - 1.0
    } else {
        0.0
    }
}

/// The subdivision rule of a vertex (`Sdc::Crease::Rule`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Rule {
    Smooth,
    Dart,
    Crease,
    Corner,
}

/// `Crease::DetermineVertexVertexRule` from the vertex and incident edge sharpness.
pub(crate) fn vertex_rule(vertex_sharpness: f32, edge_sharpness: &[f32]) -> Rule {
    if is_sharp(vertex_sharpness) {
        return Rule::Corner;
    }
    match edge_sharpness.iter().filter(|&&s| is_sharp(s)).count() {
        0 => Rule::Smooth,
        1 => Rule::Dart,
        2 => Rule::Crease,
        _ => Rule::Corner,
    }
}

/// Sharpness of the child of edge `s` at a vertex whose incident edges (in OpenSubdiv's
/// vertex-edge order, `s` among them) have sharpness `incident`
/// (`Crease::SubdivideEdgeSharpnessAtVertex`).
pub(crate) fn child_edge_sharpness(method: CreaseMethod, s: f32, incident: &[f32]) -> f32 {
    if method == CreaseMethod::Uniform || incident.len() < 2 {
        return decrement(s);
    }
    if s <= 0.0 {
        return 0.0;
    }
    if is_infinite(s) {
        return INFINITE;
    }
    let mut sum = 0.0f32;
    let mut count = 0u32;
    for &e in incident {
        if is_semi_sharp(e) {
            count += 1;
            sum += e;
        }
    }
    let mut c = s;
    if count > 1 {
        let avg = (sum - s) / (count - 1) as f32;
        c = 0.75f32 * s + 0.25f32 * avg;
    }
    c -= 1.0;
    if is_sharp(c) {
        c
    } else {
        0.0
    }
}

/// Child sharpness of every edge around a vertex, at that vertex.
pub(crate) fn child_edges_around(method: CreaseMethod, parent: &[f32]) -> Vec<f32> {
    parent
        .iter()
        .map(|&s| child_edge_sharpness(method, s, parent))
        .collect()
}

/// `Crease::ComputeFractionalWeightAtVertex`: weight of the parent rule's mask when a
/// vertex's rule changes between a level and the next.
pub(crate) fn fractional_weight(
    method: CreaseMethod,
    parent_vertex: f32,
    child_vertex: f32,
    parent_edges: &[f32],
    child_edges: &[f32],
) -> f32 {
    let mut count = 0u32;
    let mut sum = 0.0f32;
    if is_sharp(parent_vertex) && !is_sharp(child_vertex) {
        count = 1;
        sum = parent_vertex;
    }
    for (&p, &c) in parent_edges.iter().zip(child_edges) {
        let transition = match method {
            CreaseMethod::Uniform => is_sharp(p) && p <= 1.0,
            CreaseMethod::Chaikin => is_sharp(p) && !is_sharp(c),
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
    w.min(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_decay_and_rules() {
        assert_eq!(decrement(2.5), 1.5);
        assert_eq!(decrement(0.7), 0.0);
        assert_eq!(decrement(12.0), INFINITE);
        assert_eq!(vertex_rule(0.0, &[0.0, 1.0, 0.0]), Rule::Dart);
        assert_eq!(vertex_rule(0.0, &[2.0, 1.0, 0.0]), Rule::Crease);
        assert_eq!(vertex_rule(0.0, &[2.0, 1.0, 3.0]), Rule::Corner);
        assert_eq!(vertex_rule(0.5, &[]), Rule::Corner);
    }

    #[test]
    fn chaikin_averages_the_other_semi_sharp_edges() {
        // 0.75*2 + 0.25*avg(1, 3) - 1 = 1
        let around = [2.0, 1.0, 3.0, 0.0, INFINITE];
        assert_eq!(
            child_edge_sharpness(CreaseMethod::Chaikin, 2.0, &around),
            1.0
        );
        assert_eq!(
            child_edges_around(CreaseMethod::Chaikin, &around),
            vec![1.0, 0.375, 1.625, 0.0, INFINITE]
        );
        // a single semi-sharp edge decays uniformly
        assert_eq!(
            child_edge_sharpness(CreaseMethod::Chaikin, 2.5, &[2.5, 0.0]),
            1.5
        );
    }

    #[test]
    fn fractional_weights_follow_the_transitions() {
        let w = fractional_weight(CreaseMethod::Uniform, 0.0, 0.0, &[0.25, 0.75], &[0.0, 0.0]);
        assert_eq!(w, 0.5);
        let w = fractional_weight(CreaseMethod::Uniform, 0.3, 0.0, &[0.0], &[0.0]);
        assert_eq!(w, 0.3);
        let w = fractional_weight(CreaseMethod::Chaikin, 0.0, 0.0, &[1.2, 3.0], &[0.0, 1.5]);
        assert_eq!(w, 1.0);
    }
}
