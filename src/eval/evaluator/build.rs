//! Building an evaluator's quadtrees from topology alone, for a range of faces at a time:
//! ranges built apart (on separate threads) and appended in face order give exactly what
//! one pass over all faces gives.

use std::ops::Range;
use std::sync::atomic::{AtomicBool, Ordering};

use super::{DeepFragment, Node, CACHE_DEPTH, DEGENERATE_BUDGET, DEGENERATE_DEPTH};
use crate::control::Control;
use crate::error::{Error, Result};
use crate::eval::patch_regular::{regular_patch_points, PatchPoints, NO_POINT};
use crate::eval::patch_topology::Neighbourhood;
use crate::eval::points::PointProgram;
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use crate::refine::step::refine_last;
use crate::refine::{refine, VertexOrder};
use crate::topology::Level;

/// The quadtrees of a range of faces: their nodes, leaves and deep fragments, over a
/// program of their own (on the same control points).
pub(super) struct Builder<'a> {
    options: &'a SubdivOptions,
    /// The root node of each parametric face of the range.
    pub roots: Vec<Node>,
    pub nodes: Vec<Node>,
    pub patch_points: Vec<PatchPoints>,
    pub deep: Vec<DeepFragment>,
    pub program: PointProgram,
}

/// Level `d` of the fragment around a control face that repeats a vertex, refined as a whole
/// (see [`Builder::build_from_root`]).
struct RootLevel {
    level: Level,
    nb: Neighbourhood,
    points: Vec<u32>,
}

impl<'a> Builder<'a> {
    /// An empty builder over `num_control` control points.
    pub fn new(options: &'a SubdivOptions, num_control: usize) -> Builder<'a> {
        Builder {
            options,
            roots: Vec::new(),
            nodes: Vec::new(),
            patch_points: Vec::new(),
            deep: Vec::new(),
            program: PointProgram::new(num_control),
        }
    }

    /// The quadtrees of control faces `faces` of `mesh` (`global`: its neighbourhood
    /// structure; `no_surface`: the faces without limit surface), appended. `progress` (the
    /// first range's builder only) is polled at every face, and a cancel there raises
    /// `cancelled`, which the other ranges poll instead.
    ///
    /// Errors: those of the refinement of an irregular neighbourhood; [`Error::Cancelled`].
    pub fn faces(
        &mut self,
        mesh: &Mesh,
        global: &Neighbourhood,
        no_surface: &[bool],
        faces: Range<usize>,
        progress: Option<&Control>,
        cancelled: &AtomicBool,
    ) -> Result<()> {
        let options = self.options;
        let control: Vec<u32> = (0..mesh.num_vertices() as u32).collect();
        let (start, count) = (faces.start, faces.len());
        for f in faces {
            if let Some(p) = progress {
                p.step(f - start, count)
                    .inspect_err(|_| cancelled.store(true, Ordering::Relaxed))?;
            } else if cancelled.load(Ordering::Relaxed) {
                return Err(Error::Cancelled(
                    "cancelled with the evaluator build".into(),
                ));
            }
            let size = mesh.face_sizes()[f];
            if no_surface[f] {
                let count = if size == 4 { 1 } else { size };
                for _ in 0..count {
                    self.roots.push(Node::NoSurface);
                }
                continue;
            }
            let (around, points) = global.around_face(f as u32);
            if around.has_face_repeating_a_vertex() {
                let level = around.level(options);
                let mut levels = vec![RootLevel {
                    level,
                    nb: around,
                    points,
                }];
                for k in 0..(if size == 4 { 1 } else { size }) {
                    let node = if size == 4 {
                        self.build_from_root(&mut levels, 0, 0)?
                    } else {
                        self.build_from_root(&mut levels, 1, k)?
                    };
                    self.roots.push(node);
                }
            } else if size == 4 {
                let node = self.build(global, &control, f as u32, 0)?;
                self.roots.push(node);
            } else {
                // A non-quad's sub-faces are its children after one refinement, in corner order.
                let (refined, refined_points) = self.refine_recorded(&around, &points);
                for k in 0..size {
                    let node = self.build(&refined, &refined_points, k, 1)?;
                    self.roots.push(node);
                }
            }
        }
        Ok(())
    }

    /// Append `other` (the faces after this builder's), renumbering its nodes, leaves, deep
    /// fragments and points after these.
    pub fn append(&mut self, other: Builder) {
        let (nodes, leaves, deep) = (
            self.nodes.len() as u32,
            self.patch_points.len() as u32,
            self.deep.len() as u32,
        );
        let shift = |n: Node| match n {
            Node::Patch(p) => Node::Patch(p + leaves),
            Node::Split(f) => Node::Split(f + nodes),
            Node::Deep(d) => Node::Deep(d + deep),
            Node::NoSurface => Node::NoSurface,
        };
        self.roots.extend(other.roots.into_iter().map(shift));
        self.nodes.extend(other.nodes.into_iter().map(shift));
        let point = self.program.append(&other.program);
        self.patch_points
            .extend(other.patch_points.into_iter().map(|p| PatchPoints {
                vertices: p.vertices.map(|v| if v == NO_POINT { v } else { point(v) }),
                boundary: p.boundary,
            }));
        self.deep
            .extend(other.deep.into_iter().map(|d| DeepFragment {
                nb: d.nb,
                points: d.points.into_iter().map(point).collect(),
            }));
    }

    /// A leaf whose control points are vertices of a fragment whose vertices are `points`.
    fn leaf(&mut self, p: PatchPoints, points: &[u32]) -> Node {
        self.patch_points.push(PatchPoints {
            vertices: p.vertices.map(|v| {
                if v == NO_POINT {
                    NO_POINT
                } else {
                    points[v as usize]
                }
            }),
            boundary: p.boundary,
        });
        Node::Patch((self.patch_points.len() - 1) as u32)
    }

    /// A deep node for fragment `nb` whose vertices are `points`.
    fn deep_node(&mut self, nb: Neighbourhood, points: Vec<u32>) -> Node {
        self.deep.push(DeepFragment { nb, points });
        Node::Deep((self.deep.len() - 1) as u32)
    }

    /// One level of refinement of `nb` (whose vertices are `points`), the child's points
    /// recorded in the program.
    fn refine_recorded(&mut self, nb: &Neighbourhood, points: &[u32]) -> (Neighbourhood, Vec<u32>) {
        let level = nb.level(self.options);
        let r = refine_last(&level, VertexOrder::VerticesFirst);
        let child_points = self.program.record(&level, &r, points);
        (nb.refined(&level, &r), child_points)
    }

    /// The node for face `f` of `nb` (a fragment holding the faces around `f`, or more; the
    /// patch test only looks at `f`'s corners, whatever else the fragment holds; its vertices
    /// are `points`), refined down to [`CACHE_DEPTH`]. The fragment around `f` is cut out
    /// only when `f` is not regular: most children of a refined face are, and the cut costs
    /// more than the test.
    fn build(&mut self, nb: &Neighbourhood, points: &[u32], f: u32, depth: u32) -> Result<Node> {
        if let Some(p) = regular_patch_points(nb, f, self.options) {
            return Ok(self.leaf(p, points));
        }
        let (nb, globals) = nb.around_face(f);
        let points: Vec<u32> = globals.iter().map(|&g| points[g as usize]).collect();
        if depth >= CACHE_DEPTH {
            return Ok(self.deep_node(nb, points));
        }
        let (refined, refined_points) = self.refine_recorded(&nb, &points);
        let first = self.nodes.len() as u32;
        self.nodes.extend([Node::NoSurface; 4]);
        for q in 0..4u32 {
            let child = self.build(&refined, &refined_points, q, depth + 1)?;
            self.nodes[(first + q) as usize] = child;
        }
        Ok(Node::Split(first))
    }

    /// Like [`Builder::build`] for face `index` of level `depth` of `levels[0]` (whose
    /// face 0 is the control face), when that fragment holds a face that repeats a vertex.
    /// Refining such a face makes two distinct edges join the same two vertices, which a
    /// re-extracted fragment would merge; so every level is the refinement of the previous
    /// level as a whole (`levels[d]` = `levels[0]` refined `d` times, computed on first
    /// use), down to [`DEGENERATE_DEPTH`]. Deeper nodes (or all nodes below the depth where
    /// the fragment would pass [`DEGENERATE_BUDGET`] faces) are refined level by level like
    /// the others, which is exact unless the point is within `2^-depth` of a corner next to
    /// the repeated vertex.
    fn build_from_root(
        &mut self,
        levels: &mut Vec<RootLevel>,
        depth: u32,
        index: u32,
    ) -> Result<Node> {
        while levels.len() <= depth as usize {
            let last = &levels[levels.len() - 1];
            let r = refine(&last.level, VertexOrder::VerticesFirst);
            let points = self.program.record(&last.level, &r, &last.points);
            let nb = last.nb.refined(&last.level, &r);
            levels.push(RootLevel {
                level: r.child,
                nb,
                points,
            });
        }
        let here = &levels[depth as usize];
        let (nb, globals) = here.nb.around_face(index);
        let points: Vec<u32> = globals.iter().map(|&g| here.points[g as usize]).collect();
        if let Some(p) = regular_patch_points(&nb, 0, self.options) {
            return Ok(self.leaf(p, &points));
        }
        let next_size = here.nb.num_faces() * 4;
        if depth >= DEGENERATE_DEPTH
            || (levels.len() <= depth as usize + 1 && next_size > DEGENERATE_BUDGET)
        {
            return Ok(self.deep_node(nb, points));
        }
        let first = self.nodes.len() as u32;
        self.nodes.extend([Node::NoSurface; 4]);
        for q in 0..4u32 {
            let child = self.build_from_root(levels, depth + 1, index * 4 + q)?;
            self.nodes[(first + q) as usize] = child;
        }
        Ok(Node::Split(first))
    }
}
