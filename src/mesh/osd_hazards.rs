//! Where OpenSubdiv 3.5 is not exact or not safe on a mesh under given options: the
//! vertices (and the faces around them) at which its `Bfr::Surface`, `Far::PatchTable`
//! (and `Osd`, which evaluates the PatchTable's patches) or `Far::PrimvarRefiner::Limit`
//! deviate from the true limit surface, or corrupt memory.
//!
//! Pure topology: the base [`Level`] under the options decides (boundary sharpening,
//! crease method). The kinds and what each one means are those measured by the conformance
//! suite (`cpp_tests/conformance_limit_vertices.cpp`, `cpp_tests/conformance_eval.cpp`) and
//! listed in the OpenSubdiv shapes' README; [`HazardKind::figure`] says what was measured
//! and by which ctest. profsubd's own evaluator is exact at all of them.
//!
//! Definitions (an *interior* vertex is manifold, not on a boundary edge, and has a face
//! that is not a hole; sharpness is the [`Level`]'s, so boundary rules apply):
//! - [`HazardKind::Dart`]: an interior vertex that is not infinitely sharp, with exactly one
//!   infinitely sharp edge (semi-sharp edges decay, so it is a dart in the limit), and more
//!   than two faces;
//! - [`HazardKind::Valence2Dart`]: the same with two faces and two edges;
//! - [`HazardKind::Valence2Sharp`]: an interior vertex with two faces and two edges, not a
//!   dart, with a sharp edge or a sharp vertex in its faces;
//! - [`HazardKind::Valence2`]: any other interior vertex with two faces and two edges;
//! - [`HazardKind::Chaikin`] (Chaikin creasing only): a vertex with two or more semi-sharp
//!   edges not all of the same sharpness (the only place where Chaikin's rule differs from
//!   uniform decay);
//! - [`HazardKind::RepeatedVertex`]: a vertex that a face lists more than once;
//! - [`HazardKind::PrimvarLimit`]: darts, interior valence-2 vertices and vertices with a
//!   semi-sharp edge or semi-sharp vertex sharpness (`PrimvarRefiner::Limit` applies the
//!   level-0 rule's mask).

use super::Mesh;
use crate::catmark::crease::{is_infinite, is_semi_sharp, is_sharp};
use crate::options::{CreaseMethod, SubdivOptions};
use crate::topology::Level;

/// What is not exact or not safe in OpenSubdiv 3.5 at a vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum HazardKind {
    /// An interior vertex with one infinitely sharp edge: Bfr, the PatchTable and Osd use
    /// the smooth limit mask at their last isolation level.
    Dart,
    /// An interior valence-2 dart: 3.5's `Far::SourcePatch` writes out of bounds.
    Valence2Dart,
    /// An interior valence-2 vertex with sharp features in its faces: 3.5's Bfr is wrong
    /// or corrupts memory nearby.
    Valence2Sharp,
    /// An interior valence-2 vertex: Bfr's topology cache can give its faces another
    /// face's patch.
    Valence2,
    /// Semi-sharp edges of different sharpness meet, under Chaikin creasing: Bfr disagrees
    /// with refinement.
    Chaikin,
    /// A face lists the vertex more than once.
    RepeatedVertex,
    /// `Far::PrimvarRefiner::Limit` is not the limit at the vertex.
    PrimvarLimit,
}

impl HazardKind {
    /// Every kind, in order.
    pub fn all() -> [HazardKind; 7] {
        [
            HazardKind::Dart,
            HazardKind::Valence2Dart,
            HazardKind::Valence2Sharp,
            HazardKind::Valence2,
            HazardKind::Chaikin,
            HazardKind::RepeatedVertex,
            HazardKind::PrimvarLimit,
        ]
    }

    /// The snake_case name used in the `check` output.
    pub fn name(self) -> &'static str {
        match self {
            HazardKind::Dart => "dart",
            HazardKind::Valence2Dart => "valence2_dart",
            HazardKind::Valence2Sharp => "valence2_sharp",
            HazardKind::Valence2 => "valence2",
            HazardKind::Chaikin => "chaikin",
            HazardKind::RepeatedVertex => "repeated_vertex",
            HazardKind::PrimvarLimit => "primvar_limit",
        }
    }

    /// The OpenSubdiv 3.5 components concerned.
    pub fn affects(self) -> &'static [&'static str] {
        match self {
            HazardKind::Dart => &["Bfr", "Far::PatchTable", "Osd"],
            HazardKind::Valence2Dart => &["Bfr", "Far::PatchTable", "Osd"],
            HazardKind::Valence2Sharp | HazardKind::Valence2 | HazardKind::Chaikin => &["Bfr"],
            HazardKind::RepeatedVertex => &["Bfr", "Far::PatchTable", "Osd"],
            HazardKind::PrimvarLimit => &["Far::PrimvarRefiner::Limit"],
        }
    }

    /// What goes wrong, with the figure measured by the conformance suite and the ctest
    /// that measures it.
    pub fn figure(self) -> &'static str {
        match self {
            HazardKind::Dart => {
                "Bfr, Far's PatchTable and Osd use the smooth limit mask at their last isolation \
                 level (at most 10): not exact at the vertex and within ~2^-level of it in (u, v) \
                 on these faces; at isolation 10 the PatchTable is off by up to 7.4e-6 x diagonal \
                 at the vertex and 2.2e-5 at 2^-12 from it, exact (2e-16) at 2^-8 from it; the \
                 error falls ~0.3x per two isolation levels from level 4 on (ctest \
                 conformance_eval); Bfr up to 7.4e-6 at the vertex (ctest \
                 conformance_limit_vertices)"
            }
            HazardKind::Valence2Dart => {
                "3.5's Far::SourcePatch miscounts the ring and writes one element past an array: \
                 Bfr corrupts the heap (crash) on these faces, Far's PatchTable and Osd get wrong \
                 patch points silently (unchanged in 3.6.0; OpenSubdiv shapes README; the \
                 conformance suite keeps such faces from Bfr and from its PatchTable checks)"
            }
            HazardKind::Valence2Sharp => {
                "not safe for 3.5's Bfr: it is wrong or crashes on 2 faces of 3.6.0's \
                 catmark_val2_interior (semi-sharp creases next to valence-2 vertices; fixed in \
                 3.6.0; OpenSubdiv shapes README); the conformance suite keeps faces this close to such vertices (sharp \
                 edges, boundary edges included, or sharp vertices in their faces) from 3.5's Bfr"
            }
            HazardKind::Valence2 => {
                "Bfr's topology cache can hand a face with this corner another face's patch \
                 (0.03-0.17 x diagonal off, OpenSubdiv shapes README); build these faces without \
                 the cache, as ctest conformance_eval does"
            }
            HazardKind::Chaikin => {
                "under Chaikin creasing Bfr disagrees with Far's PatchTable, which is exact there, \
                 on these faces: up to 1.2e-3 x diagonal (catmark_cube_creases1), and only on \
                 faces listed here (ctest conformance_eval checks both); Osd evaluates the \
                 PatchTable's patches"
            }
            HazardKind::RepeatedVertex => {
                "OpenSubdiv makes the vertex non-manifold (sharp) and the doubled edge two edges; \
                 within 2^-2 of it on these faces no reference has shown Bfr or the PatchTable \
                 exact (profsubd's evaluator is not exact there either); farther out Bfr, the \
                 PatchTable and profsubd agree to 1e-12 x diagonal, and Bfr declines none of the \
                 446 such faces of the shapes (ctest conformance_eval)"
            }
            HazardKind::PrimvarLimit => {
                "PrimvarRefiner::Limit applies the level-0 mask: the smooth mask at darts, the \
                 corner mask at interior valence-2 vertices, the sharp masks before semi-sharp \
                 features decay (up to 0.13 x diagonal off, OpenSubdiv shapes README); Bfr, the \
                 PatchTable or profsubd's limit stencils give the limit"
            }
        }
    }
}

/// One kind of hazard on a mesh: the vertices it concerns and the faces on which the
/// OpenSubdiv components of [`HazardKind::affects`] are wrong or unsafe (holes excluded).
/// Lists are in increasing order.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct Hazard {
    /// What goes wrong.
    pub kind: HazardKind,
    /// The vertices.
    pub vertices: Vec<u32>,
    /// The faces concerned: around the vertices, as wide as the effect reaches (see
    /// [`osd_hazards`]); empty for [`HazardKind::PrimvarLimit`], a per-vertex hazard.
    pub faces: Vec<u32>,
}

/// The hazards of `mesh` under `options`, one entry per kind that occurs, in the order of
/// [`HazardKind`].
///
/// Faces: for darts, the faces at the vertex; for valence-2 darts and valence-2 vertices
/// with sharp features, the faces within two face-rings of those (as far as 3.5's Bfr reads
/// out of bounds or mixes them up); for other valence-2 vertices the faces touching a
/// vertex of their faces (those Bfr's cache may confuse); for Chaikin, the faces at the
/// vertex or at the other end of one of its semi-sharp edges; for repeated vertices, the
/// faces that repeat them.
pub fn osd_hazards(mesh: &Mesh, options: &SubdivOptions) -> Vec<Hazard> {
    let level = Level::from_mesh_with_options(mesh, options);
    let nv = level.num_vertices();
    let mut repeated = vec![false; nv];
    let mut repeated_faces = Vec::new();
    for f in 0..level.num_faces() {
        let verts = level.face_vertices(f);
        let mut repeats = false;
        for i in 1..verts.len() {
            if verts[..i].contains(&verts[i]) {
                repeated[verts[i] as usize] = true;
                repeats = true;
            }
        }
        if repeats && !level.is_face_hole(f) {
            repeated_faces.push(f as u32);
        }
    }
    let kinds: Vec<Vec<HazardKind>> = (0..nv).map(|v| vertex_kinds(&level, v)).collect();
    let mut out = Vec::new();
    for kind in HazardKind::all() {
        let at: Vec<bool> = if kind == HazardKind::RepeatedVertex {
            repeated.clone()
        } else {
            kinds.iter().map(|k| k.contains(&kind)).collect()
        };
        let at = &at;
        let vertices: Vec<u32> = (0..nv).filter(|&v| at[v]).map(|v| v as u32).collect();
        if vertices.is_empty() {
            continue;
        }
        let faces = match kind {
            HazardKind::Dart => faces_touching(&level, at),
            HazardKind::Valence2Dart | HazardKind::Valence2Sharp => {
                faces_touching(&level, &grow(&level, &grow(&level, at)))
            }
            HazardKind::Valence2 => faces_touching(&level, &grow(&level, at)),
            HazardKind::Chaikin => faces_touching(&level, &semi_sharp_neighbours(&level, at)),
            HazardKind::RepeatedVertex => repeated_faces.clone(),
            HazardKind::PrimvarLimit => Vec::new(),
        };
        out.push(Hazard {
            kind,
            vertices,
            faces,
        });
    }
    out
}

/// The per-vertex hazard kinds of vertex `v` (all but [`HazardKind::RepeatedVertex`]).
fn vertex_kinds(level: &Level, v: usize) -> Vec<HazardKind> {
    let mut kinds = Vec::new();
    let faces = level.vertex_faces(v);
    if faces.iter().all(|&f| level.is_face_hole(f as usize)) {
        return kinds; // no limit surface at v
    }
    let edges = level.vertex_edges(v);
    let sharpness: Vec<f32> = edges
        .iter()
        .map(|&e| level.edge_sharpness(e as usize))
        .collect();
    let vertex_sharpness = level.vertex_sharpness(v);
    let interior = !level.is_vertex_boundary(v) && !level.is_vertex_non_manifold(v);
    let infinite = sharpness.iter().filter(|&&s| is_infinite(s)).count();
    let dart = interior && infinite == 1 && !is_infinite(vertex_sharpness);
    let valence2 = interior && faces.len() == 2 && edges.len() == 2;
    if dart && !valence2 {
        kinds.push(HazardKind::Dart);
    } else if valence2 {
        kinds.push(if dart {
            HazardKind::Valence2Dart
        } else if sharp_in_faces(level, faces) {
            HazardKind::Valence2Sharp
        } else {
            HazardKind::Valence2
        });
    }
    let semi: Vec<f32> = sharpness
        .iter()
        .copied()
        .filter(|&s| is_semi_sharp(s))
        .collect();
    if level.options().crease_method == CreaseMethod::Chaikin
        && semi.len() > 1
        && semi.iter().any(|&s| s != semi[0])
    {
        kinds.push(HazardKind::Chaikin);
    }
    if dart || valence2 || !semi.is_empty() || is_semi_sharp(vertex_sharpness) {
        kinds.push(HazardKind::PrimvarLimit);
    }
    kinds
}

/// Whether an edge or a vertex of one of `faces` is sharp.
fn sharp_in_faces(level: &Level, faces: &[u32]) -> bool {
    faces.iter().any(|&f| {
        let f = f as usize;
        level
            .face_edges(f)
            .iter()
            .any(|&e| is_sharp(level.edge_sharpness(e as usize)))
            || level
                .face_vertices(f)
                .iter()
                .any(|&x| is_sharp(level.vertex_sharpness(x as usize)))
    })
}

/// The marked vertices and every vertex of a face touching one.
fn grow(level: &Level, marked: &[bool]) -> Vec<bool> {
    let mut out = marked.to_vec();
    for f in 0..level.num_faces() {
        let verts = level.face_vertices(f);
        if verts.iter().any(|&x| marked[x as usize]) {
            for &x in verts {
                out[x as usize] = true;
            }
        }
    }
    out
}

/// The marked vertices and the other ends of their semi-sharp edges.
fn semi_sharp_neighbours(level: &Level, marked: &[bool]) -> Vec<bool> {
    let mut out = marked.to_vec();
    for e in 0..level.num_edges() {
        let [a, b] = level.edge_vertices(e);
        if is_semi_sharp(level.edge_sharpness(e)) && (marked[a as usize] || marked[b as usize]) {
            out[a as usize] = true;
            out[b as usize] = true;
        }
    }
    out
}

/// The faces (not holes) with a marked vertex.
fn faces_touching(level: &Level, marked: &[bool]) -> Vec<u32> {
    (0..level.num_faces())
        .filter(|&f| {
            !level.is_face_hole(f) && level.face_vertices(f).iter().any(|&x| marked[x as usize])
        })
        .map(|f| f as u32)
        .collect()
}
