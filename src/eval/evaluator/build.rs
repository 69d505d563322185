//! Building an evaluator's quadtrees from topology alone, for a range of faces at a time:
//! ranges built apart (on separate threads) and appended in face order give exactly what
//! one pass over all faces gives.

use std::ops::Range;

use super::{DeepFragment, Node, CACHE_DEPTH, DEGENERATE_BUDGET, DEGENERATE_DEPTH};
use crate::control::{Control, SplitPoll};
use crate::error::Result;
use crate::eval::patch_regular::{regular_patch_points, PatchPoints, PatchTest, NO_POINT};
use crate::eval::patch_topology::{Neighbourhood, Remap};
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

/// Where a face's node goes: a root (a parametric face), or a node below a split.
#[derive(Debug, Clone, Copy)]
enum Slot {
    Root(u32),
    Node(u32),
}

/// What a face refined at some level becomes: a split node (its children its four
/// quadrants), or the roots from the given one on (a non-quad control face: its children
/// are its parametric faces).
#[derive(Debug, Clone, Copy)]
enum Target {
    Split(Slot),
    Roots(u32),
}

/// True when `face` lists a vertex twice.
fn repeats_a_vertex(face: &[u32]) -> bool {
    (0..face.len()).any(|i| face[i + 1..].contains(&face[i]))
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
    /// first range's builder only) is polled at every face of every level through `split`, which
    /// stops the other ranges after a cancel there.
    ///
    /// One sparse refinement serves every face of the range (as Far's adaptive refinement):
    /// level by level, the faces that are not regular patches are refined together with
    /// the faces around them ([`Neighbourhood::faces_around`], which is what refinement
    /// needs to get their children and their children's neighbourhoods right), so a point
    /// shared by neighbouring faces is computed and recorded once.
    ///
    /// Errors: those of the refinement of an irregular neighbourhood; [`crate::Error::Cancelled`].
    pub fn faces(
        &mut self,
        mesh: &Mesh,
        global: &Neighbourhood,
        no_surface: &[bool],
        faces: Range<usize>,
        progress: Option<&Control>,
        split: &SplitPoll,
    ) -> Result<()> {
        let levels = CACHE_DEPTH as f64 + 2.0;
        let poll = |level: u32, i: usize, n: usize| -> Result<()> {
            let l = f64::from(level);
            let stage = progress.map(|p| p.stage(l / levels, (l + 1.0) / levels));
            split.step(stage.as_ref(), i, n)
        };
        let repeats: Vec<bool> = (0..mesh.num_faces() as u32)
            .map(|f| repeats_a_vertex(global.face(f)))
            .collect();
        let any_repeats = repeats.contains(&true);
        let mut around = Vec::new();
        let mut pending: Vec<(Slot, u32)> = Vec::new();
        let mut to_refine: Vec<(Target, u32)> = Vec::new();
        let (start, count) = (faces.start, faces.len());
        for f in faces {
            poll(0, f - start, count)?;
            let size = mesh.face_sizes()[f] as usize;
            let parametric = if size == 4 { 1 } else { size };
            if no_surface[f] {
                self.roots
                    .resize(self.roots.len() + parametric, Node::NoSurface);
                continue;
            }
            if any_repeats {
                global.faces_around(f as u32, &mut around);
                if around.iter().any(|&g| repeats[g as usize]) {
                    let (nb, points) = global.around_face(f as u32);
                    self.faces_from_root(nb, points, size)?;
                    continue;
                }
            }
            let first = self.roots.len() as u32;
            self.roots
                .resize(self.roots.len() + parametric, Node::NoSurface);
            if size == 4 {
                pending.push((Slot::Root(first), f as u32));
            } else {
                to_refine.push((Target::Roots(first), f as u32));
            }
        }
        let control: Vec<u32> = (0..mesh.num_vertices() as u32).collect();
        self.refine_levels(global, control, pending, to_refine, &poll)
    }

    /// The quadtrees of the faces in `pending` (each with the slot its node goes to) and
    /// of the non-quads in `to_refine` (whose children are roots), faces of `global` whose
    /// vertices are `points`: each level's faces are tested, those that are not patches
    /// refined together, their children the next level's.
    fn refine_levels(
        &mut self,
        global: &Neighbourhood,
        mut points: Vec<u32>,
        mut pending: Vec<(Slot, u32)>,
        mut to_refine: Vec<(Target, u32)>,
        poll: &dyn Fn(u32, usize, usize) -> Result<()>,
    ) -> Result<()> {
        let options = self.options;
        let mut owned: Option<Neighbourhood> = None;
        let mut around = Vec::new();
        let mut remap = Remap::Dense(vec![u32::MAX; global.num_vertices()]);
        let mut test = PatchTest::new();
        for depth in 0.. {
            let nb = owned.as_ref().unwrap_or(global);
            test.start(nb.num_vertices());
            let n = pending.len();
            for (i, (slot, f)) in std::mem::take(&mut pending).into_iter().enumerate() {
                poll(depth + 1, i, n)?;
                let node = if let Some(p) = test.points(nb, f, options) {
                    self.leaf(p, &points)
                } else if depth >= CACHE_DEPTH {
                    nb.faces_around(f, &mut around);
                    let (cut, globals) = nb.cut(&around, &mut remap);
                    let pts = globals.iter().map(|&g| points[g as usize]).collect();
                    self.deep_node(cut, pts)
                } else {
                    to_refine.push((Target::Split(slot), f));
                    continue;
                };
                self.set(slot, node);
            }
            if to_refine.is_empty() {
                return Ok(());
            }
            // The faces to refine and those around them, in the level's order (Far's).
            let mut marked = vec![false; nb.num_faces()];
            for &(_, f) in &to_refine {
                nb.faces_around(f, &mut around);
                for &g in &around {
                    marked[g as usize] = true;
                }
            }
            let union: Vec<u32> = (0..nb.num_faces() as u32)
                .filter(|&g| marked[g as usize])
                .collect();
            let (cut, globals) = nb.cut(&union, &mut remap);
            let cut_points: Vec<u32> = globals.iter().map(|&g| points[g as usize]).collect();
            let level = cut.level(options);
            let r = refine_last(&level, VertexOrder::VerticesFirst);
            points = self.program.record(&level, &r, &cut_points);
            for (target, f) in to_refine.drain(..) {
                let local = union.binary_search(&f).expect("a refined face is cut out") as u32;
                let first_child = cut.face_offset(local);
                match target {
                    Target::Split(slot) => {
                        let first = self.nodes.len() as u32;
                        self.nodes.extend([Node::NoSurface; 4]);
                        self.set(slot, Node::Split(first));
                        pending.extend((0..4).map(|q| (Slot::Node(first + q), first_child + q)));
                    }
                    Target::Roots(first) => {
                        let size = cut.face(local).len() as u32;
                        pending.extend((0..size).map(|k| (Slot::Root(first + k), first_child + k)));
                    }
                }
            }
            let child = cut.refined(&level, &r);
            remap = Remap::Dense(vec![u32::MAX; child.num_vertices()]);
            owned = Some(child);
        }
        Ok(())
    }

    /// Put `node` where `slot` says.
    fn set(&mut self, slot: Slot, node: Node) {
        match slot {
            Slot::Root(i) => self.roots[i as usize] = node,
            Slot::Node(i) => self.nodes[i as usize] = node,
        }
    }

    /// The roots of a control face of `size` corners whose fragment `nb` (vertices
    /// `points`) holds a face that repeats a vertex (see [`Builder::build_from_root`]).
    fn faces_from_root(&mut self, nb: Neighbourhood, points: Vec<u32>, size: usize) -> Result<()> {
        let level = nb.level(self.options);
        let mut levels = vec![RootLevel { level, nb, points }];
        for k in 0..(if size == 4 { 1 } else { size as u32 }) {
            let node = if size == 4 {
                self.build_from_root(&mut levels, 0, 0)?
            } else {
                self.build_from_root(&mut levels, 1, k)?
            };
            self.roots.push(node);
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

    /// The node of face `index` of level `depth` of `levels[0]` (whose face 0 is the control face), when that fragment holds a face that repeats a vertex.
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
