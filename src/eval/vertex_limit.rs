//! Exact limit positions and derivatives at the control vertices, as stencils.
//!
//! For each control vertex:
//! - infinitely sharp corners (vertex sharpness infinite, three or more infinitely sharp
//!   edges, boundary corners under edge-and-corner, non-manifold vertices as Far sharpens
//!   them) stay where they are;
//! - a manifold vertex's one-ring is refined with OpenSubdiv's rules (private module `vertex_ring`)
//!   until the sharpness around it is 0 or infinite and every face is a quad, then the limit
//!   mask of its rule is applied: smooth `(n² v + 4 Σ e + Σ f) / (n (n + 5))`, crease
//!   `(e_a + 4 v + e_b) / 6`, and for darts (exactly one sharp edge), which have no closed
//!   form, the left eigenvector of eigenvalue 1 of the ring's subdivision matrix;
//! - the vertex of a non-manifold crease follows the crease curve alone.
//!
//! This is the true limit everywhere, including where OpenSubdiv 3.5's `Bfr` and
//! `PrimvarRefiner::Limit` are not (darts, level-0 semi-sharp features, interior valence-2
//! vertices).
//!
//! A vertex without limit surface (isolated, or all of its faces holes: see
//! [`super::surface`]) gets empty stencil rows and [`LimitSample::NO_SURFACE`].
//!
//! Derivatives are reported at the corner of the vertex's *first face*: the first face in
//! OpenSubdiv's vertex-face order (`Far::TopologyLevel::GetVertexFaces(v)[0]`, counter-clockwise
//! for manifold vertices, starting at the leading boundary face on a boundary) that is not a
//! hole (a vertex whose faces are all holes has no limit). `du` and `dv` are in that face's
//! parameterization as `Bfr::Surface` has it: for a quad, corner `k` at (0,0), (1,0), (1,1),
//! (0,1); for any other face, sub-face `k` of its quadrangulation with local (0,0) at the
//! vertex, `u` towards the midpoint of the edge to the next vertex and `v` towards the
//! midpoint of the edge from the previous vertex. They are exact (equal to the bicubic
//! patch's) at regular vertices: smooth valence 4, crease sectors of two faces, single-face
//! corners, after any semi-sharp sharpness has decayed. Elsewhere the *direction* they span is
//! OpenSubdiv's limit tangent plane (`Sdc` tangent masks: the exact plane at smooth
//! extraordinary vertices) and their lengths are a convention (the masks scaled by 1/12 at
//! the level where the neighbourhood became stationary, times 2^level), since the limit
//! parameterization has a zero or unbounded derivative at an extraordinary vertex. At darts,
//! interior valence-2 vertices, crease sectors of other than two faces and corners whose
//! first face has a smooth edge at the vertex, the tangent masks are OpenSubdiv's, which are
//! approximate there.

use crate::control::{Control, SplitPoll};
use crate::error::Result;
use crate::mesh::Mesh;
use crate::options::SubdivOptions;

use super::sample::LimitSample;
use super::stencil::StencilTable;
use super::surface::vertices_with_surface_in;
use super::vertex_ring::{self, sub, CreaseLine, Point, Ring, MAX_LEVELS};
use crate::catmark::crease::{is_infinite, is_semi_sharp, is_sharp};
use crate::topology::Level;

/// Limit position, `du` and `dv` stencils of every control vertex, rows in vertex order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VertexLimitStencils {
    /// Limit positions.
    pub position: StencilTable,
    /// Derivative with respect to u at the corner of the vertex's first face.
    pub du: StencilTable,
    /// Derivative with respect to v at the corner of the vertex's first face.
    pub dv: StencilTable,
}

/// Exact limit position of every control vertex as a stencil on the control vertices (one
/// row per vertex, in vertex order; an empty row for a vertex without limit surface).
///
/// Errors ([`crate::Error::NumericalFailure`]): a dart's subdivision matrix is degenerate
/// (not seen with OpenSubdiv's rules).
pub fn limit_stencils(mesh: &Mesh, options: &SubdivOptions) -> Result<StencilTable> {
    limit_stencils_with(mesh, options, &Control::NONE)
}

/// [`limit_stencils`] on `control`'s threads ([`Control::threads`], 0: all cores), reporting
/// to `control` through the base level's build (0–10 %), then each vertex (the fit's first stage). Contiguous ranges of vertices, one per thread, are joined
/// in vertex order: the table is the one-thread table bit for bit. The first range reports
/// (its fraction stands for the whole: the ranges are equal); a cancel there stops the
/// others at their next vertex.
pub(crate) fn limit_stencils_with(
    mesh: &Mesh,
    options: &SubdivOptions,
    control: &Control,
) -> Result<StencilTable> {
    // The base level of a large mesh takes tens of milliseconds: polled (0–10 %).
    let level = Level::from_mesh_polled(mesh, options, &control.stage(0.0, 0.1))?;
    let surface = vertices_with_surface_in(&level);
    let control = &control.stage(0.1, 1.0);
    let poll = SplitPoll::default();
    let parts = super::parallel::map_ranges(mesh.num_vertices(), control.threads(), |range| {
        let mut table = StencilTable::new();
        let mut row = Vec::new();
        let (reporter, len) = ((range.start == 0).then_some(control), range.len());
        for (k, v) in range.enumerate() {
            poll.step(reporter, k, len)?;
            if !surface[v] {
                table.push_row([]);
                continue;
            }
            if closed_form_row(&level, v as u32, &mut row) {
                table.push_row(row.iter().copied());
                continue;
            }
            let local = Local::new(&level, v as u32);
            let (p, _) = vertex_limit(options, &level, &local, v as u32, false)?;
            table.push_row(local.sparse(&p));
        }
        Ok(table)
    });
    let mut table = StencilTable::new();
    for part in parts {
        let part = part?;
        for r in 0..part.num_rows() {
            let (a, b) = (part.offsets[r] as usize, part.offsets[r + 1] as usize);
            table.push_row(
                part.indices[a..b]
                    .iter()
                    .copied()
                    .zip(part.weights[a..b].iter().copied()),
            );
        }
    }
    Ok(table)
}

/// The limit stencil row of vertex `v` without refining its ring, where its level-0
/// neighbourhood is already stationary (vertex sharpness 0, every incident edge smooth or
/// infinitely sharp, every face a quad) and its rule has a closed form: smooth at an interior
/// vertex or crease. `row` gets the entries in vertex order and the result is `true`; the
/// weights are computed as [`Ring::limit`] computes them, so the row is the general path's bit
/// for bit (checked on every vertex of the examples and OpenSubdiv's shapes by the tests).
/// `false` (row undefined) everywhere else, and where a vertex would appear twice in the
/// mask (a degenerate neighbourhood, whose weights the general path sums).
fn closed_form_row(level: &Level, v: u32, row: &mut Vec<(u32, f64)>) -> bool {
    let vi = v as usize;
    if is_sharp(level.vertex_sharpness(vi)) || level.is_vertex_non_manifold(vi) {
        return false;
    }
    let (edges, faces) = (level.vertex_edges(vi), level.vertex_faces(vi));
    let mut sharp = [0usize; 2];
    let mut count = 0;
    for (k, &e) in edges.iter().enumerate() {
        let s = level.edge_sharpness(e as usize);
        if is_semi_sharp(s) {
            return false;
        }
        if is_sharp(s) {
            if count == 2 {
                return false;
            }
            sharp[count] = k;
            count += 1;
        }
    }
    if faces
        .iter()
        .any(|&f| level.face_vertices(f as usize).len() != 4)
    {
        return false;
    }
    row.clear();
    match count {
        0 if faces.len() == edges.len() => {
            let n = edges.len() as f64;
            let d = n * (n + 5.0);
            row.push((v, n * n / d));
            for (&e, (&f, &c)) in edges
                .iter()
                .zip(faces.iter().zip(level.vertex_face_local_indices(vi)))
            {
                row.push((other_end(level, e, v), 4.0 / d));
                row.push((
                    level.face_vertices(f as usize)[(c as usize + 2) % 4],
                    1.0 / d,
                ));
            }
        }
        2 => {
            row.push((v, 4.0 / 6.0));
            for k in sharp {
                row.push((other_end(level, edges[k], v), 1.0 / 6.0));
            }
        }
        _ => return false,
    }
    row.sort_unstable_by_key(|&(g, _)| g);
    row.windows(2).all(|w| w[0].0 != w[1].0)
}

/// Limit position and derivative stencils of every control vertex (see the module doc for
/// the derivatives' convention). A vertex without limit surface has empty rows in all three
/// tables; every other vertex has non-empty rows (a derivative that is exactly zero keeps
/// one entry of weight 0).
///
/// Errors: as [`limit_stencils`].
pub fn vertex_limit_stencils(mesh: &Mesh, options: &SubdivOptions) -> Result<VertexLimitStencils> {
    let level = Level::from_mesh_with_options(mesh, options);
    let surface = vertices_with_surface_in(&level);
    let mut out = VertexLimitStencils {
        position: StencilTable::new(),
        du: StencilTable::new(),
        dv: StencilTable::new(),
    };
    for v in 0..mesh.num_vertices() as u32 {
        if !surface[v as usize] {
            for t in [&mut out.position, &mut out.du, &mut out.dv] {
                t.push_row([]);
            }
            continue;
        }
        let local = Local::new(&level, v);
        let (p, d) = vertex_limit(options, &level, &local, v, true)?;
        let (du, dv) = d.unwrap_or_else(|| (vec![0.0; p.len()], vec![0.0; p.len()]));
        out.position.push_row(local.sparse(&p));
        out.du.push_row(local.sparse_keeping(&du, v));
        out.dv.push_row(local.sparse_keeping(&dv, v));
    }
    Ok(out)
}

/// Limit position and derivatives at every control vertex, in vertex order (see the module
/// doc for the derivatives' convention; [`LimitSample::normal`] gives the unit normal);
/// [`LimitSample::NO_SURFACE`] for a vertex without limit surface.
///
/// Errors: as [`limit_stencils`].
pub fn limit_vertex_samples(mesh: &Mesh, options: &SubdivOptions) -> Result<Vec<LimitSample>> {
    let st = vertex_limit_stencils(mesh, options)?;
    let p = mesh.positions();
    Ok((0..mesh.num_vertices())
        .map(|i| LimitSample {
            position: st.position.apply_row(i, p),
            du: st.du.apply_row(i, p),
            dv: st.dv.apply_row(i, p),
        })
        .collect())
}

/// The local basis of a vertex: the control vertices of its faces (and of its edges, for
/// isolated or non-manifold ones), sorted.
struct Local {
    globals: Vec<u32>,
}

impl Local {
    fn new(level: &Level, v: u32) -> Local {
        let mut globals = vec![v];
        for &f in level.vertex_faces(v as usize) {
            globals.extend_from_slice(level.face_vertices(f as usize));
        }
        for &e in level.vertex_edges(v as usize) {
            globals.extend_from_slice(&level.edge_vertices(e as usize));
        }
        globals.sort_unstable();
        globals.dedup();
        Local { globals }
    }

    fn unit(&self, g: u32) -> Point {
        let mut p = vec![0.0; self.globals.len()];
        p[self
            .globals
            .binary_search(&g)
            .expect("vertex in its own neighbourhood")] = 1.0;
        p
    }

    fn sparse<'a>(&'a self, p: &'a [f64]) -> impl Iterator<Item = (u32, f64)> + 'a {
        self.globals
            .iter()
            .zip(p)
            .filter(|(_, &w)| w != 0.0)
            .map(|(&g, &w)| (g, w))
    }

    /// [`Local::sparse`], but an all-zero row keeps the entry `(v, 0)`: an empty row would
    /// mean "no limit surface".
    fn sparse_keeping(&self, p: &[f64], v: u32) -> Vec<(u32, f64)> {
        let row: Vec<(u32, f64)> = self.sparse(p).collect();
        if row.is_empty() {
            vec![(v, 0.0)]
        } else {
            row
        }
    }
}

type Derivatives = Option<(Point, Point)>;

fn vertex_limit(
    options: &SubdivOptions,
    level: &Level,
    local: &Local,
    v: u32,
    with_derivatives: bool,
) -> Result<(Point, Derivatives)> {
    let vi = v as usize;
    let faces = level.vertex_faces(vi);
    let center = local.unit(v);
    // The callers skip vertices without limit surface: `faces` has one that is not a hole.
    let first = faces
        .iter()
        .position(|&f| !level.is_face_hole(f as usize))
        .unwrap_or(0);
    let face = level.face_vertices(faces[first] as usize);
    let corner = level.vertex_face_local_indices(vi)[first] as usize;
    let edge_derivatives = || {
        // Derivatives along the first face's edges at the vertex: exact at a corner whose
        // two edges there are sharp.
        let n = face.len();
        let here = local.unit(v);
        let next = sub(&local.unit(face[(corner + 1) % n]), &here);
        let prev = sub(&local.unit(face[(corner + n - 1) % n]), &here);
        let scale = if n == 4 { 1.0 } else { 0.5 };
        orient(n, corner, next, prev, scale)
    };
    let sharpness = incident_sharpness(level, v);
    let infinite_edges = sharpness.iter().filter(|&&s| is_infinite(s)).count();
    if is_infinite(level.vertex_sharpness(vi)) || infinite_edges > 2 {
        // A corner for ever: the limit is the vertex itself.
        return Ok((center, with_derivatives.then(edge_derivatives)));
    }
    if level.is_vertex_non_manifold(vi) {
        // Far leaves only non-manifold creases unsharpened: two infinitely sharp edges.
        let ends: Vec<Point> = level
            .vertex_edges(vi)
            .iter()
            .zip(&sharpness)
            .filter(|(_, &s)| is_infinite(s))
            .map(|(&e, _)| local.unit(other_end(level, e, v)))
            .collect();
        if ends.len() != 2 {
            return Ok((center, with_derivatives.then(edge_derivatives)));
        }
        let line = CreaseLine {
            center,
            ends: [ends[0].clone(), ends[1].clone()],
            sharpness,
            vertex_sharpness: level.vertex_sharpness(vi),
        };
        let p = line.limit(options.crease_method)?;
        return Ok((p, with_derivatives.then(edge_derivatives)));
    }
    let mut ring = level0_ring(level, local, v);
    while !ring.is_stationary() {
        if ring.level >= MAX_LEVELS {
            return Err(vertex_ring::too_deep());
        }
        ring = ring.refine(options);
    }
    let p = ring.limit()?;
    if !with_derivatives {
        return Ok((p, None));
    }
    let (next, prev) = ring.tangents(first);
    let n = face.len();
    let level_scale = (2.0f64).powi(ring.level as i32);
    let scale = if n == 4 {
        level_scale
    } else {
        0.5 * level_scale
    };
    Ok((p, Some(orient(n, corner, next, prev, scale))))
}

fn other_end(level: &Level, e: u32, v: u32) -> u32 {
    let [a, b] = level.edge_vertices(e as usize);
    if a == v {
        b
    } else {
        a
    }
}

fn incident_sharpness(level: &Level, v: u32) -> Vec<f32> {
    level
        .vertex_edges(v as usize)
        .iter()
        .map(|&e| level.edge_sharpness(e as usize))
        .collect()
}

/// `(du, dv)` at `corner` of a face of size `n` from the derivatives towards the next and
/// previous corners.
fn orient(n: usize, corner: usize, next: Point, prev: Point, scale: f64) -> (Point, Point) {
    let s = |p: &Point, w: f64| -> Point { p.iter().map(|x| x * w * scale).collect() };
    if n != 4 {
        return (s(&next, 1.0), s(&prev, 1.0));
    }
    match corner {
        0 => (s(&next, 1.0), s(&prev, 1.0)),
        1 => (s(&prev, -1.0), s(&next, 1.0)),
        2 => (s(&next, -1.0), s(&prev, -1.0)),
        _ => (s(&prev, 1.0), s(&next, -1.0)),
    }
}

/// The level-0 one-ring of a manifold vertex, in OpenSubdiv's counter-clockwise order.
fn level0_ring(level: &Level, local: &Local, v: u32) -> Ring {
    let vi = v as usize;
    let edges = level.vertex_edges(vi);
    let faces = level
        .vertex_faces(vi)
        .iter()
        .zip(level.vertex_face_local_indices(vi))
        .map(|(&f, &c)| {
            let fv = level.face_vertices(f as usize);
            (1..fv.len())
                .map(|k| local.unit(fv[(c as usize + k) % fv.len()]))
                .collect()
        })
        .collect();
    Ring {
        center: local.unit(v),
        ends: edges
            .iter()
            .map(|&e| local.unit(other_end(level, e, v)))
            .collect(),
        sharpness: incident_sharpness(level, v),
        far_sharpness: edges
            .iter()
            .map(|&e| incident_sharpness(level, other_end(level, e, v)))
            .collect(),
        faces,
        vertex_sharpness: level.vertex_sharpness(vi),
        level: 0,
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::mesh::{Corner, Crease, MeshParts};
    use crate::options::{BoundaryInterpolation, CreaseMethod};

    /// An `nx × ny` grid of quads on z = height(i, j).
    fn grid(nx: u32, ny: u32, height: impl Fn(u32, u32) -> f64) -> MeshParts {
        let mut p = MeshParts::default();
        for j in 0..=ny {
            for i in 0..=nx {
                p.positions
                    .push(DVec3::new(i as f64, j as f64, height(i, j)));
            }
        }
        let id = |i: u32, j: u32| j * (nx + 1) + i;
        for j in 0..ny {
            for i in 0..nx {
                p.face_sizes.push(4);
                p.face_indices
                    .extend([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
        p
    }

    fn bumpy(i: u32, j: u32) -> f64 {
        ((i * 7 + j * 13) % 5) as f64 * 0.3 - (i * j % 3) as f64 * 0.2
    }

    fn cube() -> MeshParts {
        let mut p = MeshParts::default();
        for k in 0..8 {
            p.positions.push(DVec3::new(
                (k & 1) as f64,
                ((k >> 1) & 1) as f64,
                ((k >> 2) & 1) as f64 * 1.3,
            ));
        }
        for f in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            p.face_sizes.push(4);
            p.face_indices.extend(f);
        }
        p
    }

    fn close(a: DVec3, b: DVec3, tol: f64) -> bool {
        (a - b).length() <= tol
    }

    #[test]
    fn regular_grid_vertex_is_the_bicubic_spline_value_and_derivative() {
        let mesh = Mesh::from_parts(grid(4, 4, bumpy)).unwrap();
        let s = limit_vertex_samples(&mesh, &SubdivOptions::default()).unwrap();
        let w = [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0];
        let d = [-0.5, 0.0, 0.5];
        let at = |i: u32, j: u32| mesh.positions()[(j * 5 + i) as usize];
        for (ci, cj) in [(1, 1), (2, 2), (3, 1), (2, 3)] {
            let (mut p, mut du, mut dv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
            for a in 0..3 {
                for b in 0..3 {
                    let q = at(ci + a - 1, cj + b - 1);
                    p += q * w[a as usize] * w[b as usize];
                    du += q * d[a as usize] * w[b as usize];
                    dv += q * w[a as usize] * d[b as usize];
                }
            }
            let v = (cj * 5 + ci) as usize;
            let got = s[v];
            assert!(close(got.position, p, 1e-15), "{v}: {got:?} vs {p}");
            // The first face of an interior vertex is its lowest-numbered face, where the
            // vertex is corner 2 ((1,1) of the face); u and v run along x and y.
            assert!(close(got.du, du, 1e-14), "{v}: {:?} vs {du}", got.du);
            assert!(close(got.dv, dv, 1e-14), "{v}: {:?} vs {dv}", got.dv);
        }
    }

    #[test]
    fn boundary_rules_give_crease_and_corner_limits() {
        let parts = grid(3, 2, bumpy);
        let p = parts.positions.clone();
        let mesh = Mesh::from_parts(parts).unwrap();
        let edge_only = SubdivOptions {
            boundary: BoundaryInterpolation::EdgeOnly,
            ..SubdivOptions::default()
        };
        let t = limit_stencils(&mesh, &edge_only).unwrap();
        let lim = t.apply(&p).unwrap();
        // boundary vertex 1 between 0 and 2: cubic B-spline along the boundary
        assert!(close(lim[1], (p[0] + p[1] * 4.0 + p[2]) / 6.0, 1e-15));
        // corner vertex 0 with one face under edge-only: crease through its two edges
        assert!(close(lim[0], (p[1] + p[0] * 4.0 + p[4]) / 6.0, 1e-15));
        let t = limit_stencils(&mesh, &SubdivOptions::default()).unwrap();
        assert_eq!(t.row(0), (&[0u32][..], &[1.0][..]));
        // Under "none" every face of this grid touches the boundary: no vertex has a
        // limit surface, every row is empty.
        let none = SubdivOptions {
            boundary: BoundaryInterpolation::None,
            ..SubdivOptions::default()
        };
        let t = limit_stencils(&mesh, &none).unwrap();
        assert_eq!((t.num_rows(), t.num_entries()), (12, 0));
        // On a 4 x 4 grid the 4 inner faces keep their surface: the 9 vertices around them
        // have the limits of edge-only (boundary edges are sharp for vertex data), the 16
        // on the border none.
        let mesh = Mesh::from_parts(grid(4, 4, bumpy)).unwrap();
        let (a, b) = (
            limit_stencils(&mesh, &none).unwrap(),
            limit_stencils(&mesh, &edge_only).unwrap(),
        );
        for v in 0..25 {
            let (i, j) = (v % 5, v / 5);
            if (1..4).contains(&i) && (1..4).contains(&j) {
                assert_eq!(a.row(v), b.row(v), "vertex {v}");
            } else {
                assert!(a.is_empty_row(v), "vertex {v}");
            }
        }
    }

    #[test]
    fn closed_form_smooth_limit_equals_the_eigenvector_for_every_valence() {
        for n in 2..=9usize {
            let ring = synthetic_ring(n, &vec![0.0; n], 0.0);
            let a = ring.limit().unwrap();
            let b = ring.eigen_limit().unwrap();
            let err = a
                .iter()
                .zip(&b)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max);
            assert!(err < 1e-15, "valence {n}: {a:?} vs {b:?}");
        }
    }

    /// Ring with unit-vector points: centre 0, edge ends 1..=n, opposite corners n+1..=2n.
    fn synthetic_ring(n: usize, sharpness: &[f32], vertex_sharpness: f32) -> Ring {
        let m = 1 + 2 * n;
        let unit = |k: usize| {
            let mut p = vec![0.0; m];
            p[k] = 1.0;
            p
        };
        Ring {
            center: unit(0),
            ends: (0..n).map(|i| unit(1 + i)).collect(),
            sharpness: sharpness.to_vec(),
            far_sharpness: sharpness.iter().map(|&s| vec![s, 0.0, 0.0, 0.0]).collect(),
            faces: (0..n)
                .map(|i| vec![unit(1 + i), unit(1 + n + i), unit(1 + (i + 1) % n)])
                .collect(),
            vertex_sharpness,
            level: 0,
        }
    }

    /// Refine a ring `levels` times and return its centre: converges to the limit.
    fn deep_center(mut ring: Ring, levels: u32, options: &SubdivOptions) -> Point {
        for _ in 0..levels {
            ring = ring.refine(options);
        }
        ring.center
    }

    fn max_diff(a: &[f64], b: &[f64]) -> f64 {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn dart_and_semi_sharp_limits_match_deep_refinement() {
        let opts = SubdivOptions::default();
        let chaikin = SubdivOptions {
            crease_method: CreaseMethod::Chaikin,
            ..opts
        };
        let cases: Vec<(usize, Vec<f32>, f32)> = vec![
            (5, vec![10.0, 0.0, 0.0, 0.0, 0.0], 0.0),
            (3, vec![10.0, 0.0, 0.0], 0.0),
            (2, vec![10.0, 0.0], 0.0),
            (6, vec![1.5, 0.0, 2.7, 0.0, 0.3, 0.0], 0.0),
            (4, vec![1.5, 0.0, 0.0, 0.0], 2.25),
            (4, vec![10.0, 0.0, 0.4, 0.0], 0.0),
            (3, vec![3.0, 10.0, 10.0], 0.0),
        ];
        for (n, sharp, vs) in cases {
            for o in [&opts, &chaikin] {
                let mut ring = synthetic_ring(n, &sharp, vs);
                let deep = deep_center(ring.clone(), 90, o);
                while !ring.is_stationary() {
                    ring = ring.refine(o);
                }
                let lim = ring.limit().unwrap();
                assert!(
                    max_diff(&lim, &deep) < 1e-14,
                    "n={n} {sharp:?} {vs}: {lim:?} vs {deep:?}"
                );
            }
        }
    }

    #[test]
    fn crease_line_agrees_with_the_ring_for_manifold_creases() {
        let opts = SubdivOptions::default();
        let sharp = vec![10.0, 0.7, 10.0, 0.0, 1.6];
        let mut ring = synthetic_ring(5, &sharp, 1.3);
        let line = CreaseLine {
            center: ring.center.clone(),
            ends: [ring.ends[0].clone(), ring.ends[2].clone()],
            sharpness: sharp.clone(),
            vertex_sharpness: 1.3,
        };
        let a = line.limit(opts.crease_method).unwrap();
        while !ring.is_stationary() {
            ring = ring.refine(&opts);
        }
        assert!(max_diff(&a, &ring.limit().unwrap()) < 1e-15);
    }

    #[test]
    fn closed_cube_with_tags_matches_deep_refinement_of_each_ring() {
        let mut parts = cube();
        parts.creases.push(Crease {
            vertices: [0, 2],
            sharpness: 1.5,
        });
        parts.creases.push(Crease {
            vertices: [7, 5],
            sharpness: 10.0,
        });
        parts.corners.push(Corner {
            vertex: 3,
            sharpness: 0.5,
        });
        let mesh = Mesh::from_parts(parts).unwrap();
        let t = limit_stencils(&mesh, &SubdivOptions::default()).unwrap();
        let level = Level::from_mesh_with_options(&mesh, &SubdivOptions::default());
        for v in 0..8u32 {
            let local = Local::new(&level, v);
            let ring = level0_ring(&level, &local, v);
            let deep = deep_center(ring, 90, &SubdivOptions::default());
            let row: Vec<(u32, f64)> = local.sparse(&deep).collect();
            let (idx, w) = t.row(v as usize);
            assert_eq!(idx, row.iter().map(|r| r.0).collect::<Vec<_>>());
            let err = w
                .iter()
                .zip(&row)
                .map(|(a, b)| (a - b.1).abs())
                .fold(0.0, f64::max);
            assert!(err < 1e-14, "vertex {v}: {w:?} vs {row:?}");
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        }
    }

    /// Every `.obj` of the bundled examples and of OpenSubdiv's regression shapes
    /// (`$PROFSUBD_OSD_SHAPES`, else `../shared/conformance/osd_shapes`, skipped if absent).
    fn example_and_shape_meshes() -> Vec<(std::path::PathBuf, Mesh)> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let shapes = std::env::var_os("PROFSUBD_OSD_SHAPES")
            .map(std::path::PathBuf::from)
            .unwrap_or_else(|| root.join("../shared/conformance/osd_shapes"));
        let mut dirs: Vec<_> = ["profiles", "sweeps", "curves", "blends"]
            .iter()
            .map(|d| root.join("examples").join(d))
            .collect();
        dirs.push(shapes);
        let mut out = Vec::new();
        for dir in dirs.iter().filter(|d| d.is_dir()) {
            let mut paths: Vec<_> = std::fs::read_dir(dir)
                .unwrap()
                .map(|e| e.unwrap().path())
                .filter(|p| p.extension().is_some_and(|x| x == "obj"))
                .collect();
            paths.sort();
            for path in paths {
                // Shapes the reader refuses (OpenSubdiv's deliberately invalid ones) are
                // not meshes with limit stencils.
                if let Ok(read) = crate::io::obj::read_obj_file(&path) {
                    out.push((path, read.mesh));
                }
            }
        }
        out
    }

    #[test]
    fn closed_form_rows_are_the_general_rows_bit_for_bit() {
        let (mut fast, mut general, mut meshes) = (0usize, 0usize, 0usize);
        for (path, mesh) in example_and_shape_meshes() {
            meshes += 1;
            for options in [
                mesh.options().resolve(),
                SubdivOptions {
                    boundary: BoundaryInterpolation::EdgeOnly,
                    crease_method: CreaseMethod::Chaikin,
                    ..SubdivOptions::default()
                },
            ] {
                let level = Level::from_mesh_with_options(&mesh, &options);
                let surface = vertices_with_surface_in(&level);
                let mut row = Vec::new();
                for v in 0..mesh.num_vertices() as u32 {
                    if !surface[v as usize] || !closed_form_row(&level, v, &mut row) {
                        general += 1;
                        continue;
                    }
                    fast += 1;
                    let local = Local::new(&level, v);
                    let (p, _) = vertex_limit(&options, &level, &local, v, false).unwrap();
                    let want: Vec<(u32, f64)> = local.sparse(&p).collect();
                    // `==` on the weights: the same bits (no zero weights, no NaN).
                    assert_eq!(row, want, "{} vertex {v} {options:?}", path.display());
                }
            }
        }
        println!("{meshes} meshes: {fast} closed-form rows, {general} general");
        // The examples alone hold thousands of regular vertices.
        assert!(
            meshes >= 20 && fast > 10_000 && general > 100,
            "{meshes} {fast} {general}"
        );
    }

    #[test]
    fn non_quads_and_isolated_vertices() {
        // A pyramid: square base, four triangles; apex valence 4 over triangles.
        // Plus an isolated vertex.
        let mut parts = crate::test_support::square_pyramid();
        parts.positions.push(DVec3::new(9.0, 9.0, 9.0));
        let mesh = Mesh::from_parts(parts).unwrap();
        let s = limit_vertex_samples(&mesh, &SubdivOptions::default()).unwrap();
        // symmetric: apex limit on the axis, normal up
        assert!((s[4].position.x - 0.5).abs() < 1e-15 && (s[4].position.y - 0.5).abs() < 1e-15);
        assert!(s[4].position.z < 1.0 && s[4].position.z > 0.0);
        assert!(s[4].normal().z > 0.999_999, "{:?}", s[4].normal());
        // the isolated vertex has no limit surface: marked, no made-up position
        assert!(!s[5].has_surface() && s[5].du.is_nan() && s[5].dv.is_nan());
        let t = vertex_limit_stencils(&mesh, &SubdivOptions::default()).unwrap();
        for table in [&t.position, &t.du, &t.dv] {
            assert!((0..5).all(|v| !table.is_empty_row(v)) && table.is_empty_row(5));
        }
    }

    /// A bumpy 4×4 grid with semi-sharp creases of several sharpness values, a dart (the
    /// infinitely sharp edge 12-17), a semi-sharp corner and two triangles.
    fn tagged_mixed_mesh() -> MeshParts {
        let mut p = grid(4, 4, bumpy);
        // face 0 (0 1 6 5) becomes two triangles
        p.face_sizes.remove(0);
        p.face_indices.drain(0..4);
        p.face_sizes.extend([3, 3]);
        p.face_indices.extend([0, 1, 6, 0, 6, 5]);
        p.creases.extend([
            Crease {
                vertices: [6, 7],
                sharpness: 1.5,
            },
            Crease {
                vertices: [7, 8],
                sharpness: 2.75,
            },
            Crease {
                vertices: [12, 17],
                sharpness: 10.0,
            },
            Crease {
                vertices: [11, 16],
                sharpness: 0.4,
            },
            Crease {
                vertices: [16, 17],
                sharpness: 1.2,
            },
        ]);
        p.corners.push(Corner {
            vertex: 18,
            sharpness: 2.3,
        });
        p
    }

    #[test]
    fn limits_are_invariant_under_independent_uniform_refinement() {
        let mesh = Mesh::from_parts(tagged_mixed_mesh()).unwrap();
        for crease_method in [CreaseMethod::Uniform, CreaseMethod::Chaikin] {
            for boundary in [
                BoundaryInterpolation::EdgeOnly,
                BoundaryInterpolation::EdgeAndCorner,
            ] {
                let opts = SubdivOptions {
                    crease_method,
                    boundary,
                    ..SubdivOptions::default()
                };
                let base = limit_stencils(&mesh, &opts)
                    .unwrap()
                    .apply(mesh.positions())
                    .unwrap();
                for k in 1..=4 {
                    // Far order: the child of control vertex v is vertex v of the child level.
                    let fine = crate::refine::refine_uniform(&mesh, &opts, k).unwrap();
                    let lim = limit_stencils(&fine, &opts)
                        .unwrap()
                        .apply(fine.positions())
                        .unwrap();
                    for (v, (a, b)) in base.iter().zip(&lim).enumerate() {
                        assert!(
                            close(*a, *b, 1e-14),
                            "{opts:?} level {k} vertex {v}: {a} vs {b}"
                        );
                    }
                }
            }
        }
    }
}
