//! Partial revolutions (wedges): poles on the boundary meridians, sector caps, flat meridian
//! caps.
//!
//! A revolution by `angle_deg < 360` has rings of `n + 1` vertices (`n` = `samples_around`)
//! from the start meridian (θ = 0) to the end meridian (θ = angle).
//!
//! *Sector layout* (`n = 4k`). The region between an end ring and the axis — a pole's
//! neighbourhood on the surface, or a flat cap's circular sector — is closed by two `k × k`
//! grid patches meeting along the sector's bisector. The first has its corners at the apex
//! (on the axis), the ring's first vertex, its quarter point and its middle; the second
//! spans the other half the same way. So the apex has valence 3 (4 with meridian caps), the
//! quarter points valence 3, the other vertices 4: no vertex of valence ≈ `n`, and as each
//! half spans at most 180° no quad has a reflex angle. Each patch is a quarter of a full
//! turn's grid cap (`crate::construct::pole_cap`): its vertices lie, as a relative radius ρ
//! and an angle θ, on the L-shaped lines `max(x, y) = ρ k` mapped to circles, uniformly in
//! angle (`square_polar`), so the radial steps are `1/k` of the radius everywhere, also at
//! the quarter points (a Coons patch squeezed them to nothing there, next to the ring's long
//! cells, and the interpolating fit folded). A flat cap scales ρ by the ring's radius in the
//! ring's plane, a pole maps `(ρ, θ)` onto the surface through [`sector_point`] (ρ along
//! the profile samples it replaces, so radial steps continue the side's ring spacing; where
//! the meridian caps would fold with those, evenly by [`cap_point`], the placement of a
//! full turn's pole cap), and replaces up to `k` profile intervals (its
//! radial lines have `k` intervals; see `RevolveInput::grid`), so that its cells are about as
//! large as the side's faces. A pole's apex is an infinitely sharp corner: the two boundary
//! meridians meet there at the wedge angle, and with caps three creases meet there.
//! Catmull-Clark's corner rule maps the faces between a corner's two creases into the convex
//! cone of their tangents, so a span of 180° or more between two creases folds at the apex,
//! and one close to it leaves the limit normal there ill-conditioned: a sector wider than
//! `SPAN_LIMIT` (150°) creases its bisector, which splits the apex's span into two halves
//! below 150°. The crease runs on to a crease or a boundary (OpenSubdiv's limit is inexact
//! at darts, where a crease ends): a flat sector's to its crease ring, a pole's along the
//! side's middle meridian to the other end (its sector's bisector, a crease ring or the open
//! end), an infinitely sharp crease on a smooth surface whose two sides both interpolate the
//! surface's data points.
//!
//! *Meridian caps* (`"caps": "flat"`; both ends then have a sector). Each meridian plane is
//! closed by one structured grid. Its boundary is the bottom sector's radial line (`k`
//! intervals, apex to ring), the ring column (`R − 1` intervals for `R` rings), the top
//! sector's radial line (`k`) and the axis (vertices shared by both caps). The grid's four
//! corners are the two apexes and the column vertices `a` steps from either end, so its sides
//! are: the bottom radial line and `a` column steps, the column's middle (`R − 1 − 2a`), the
//! top radial line and `a` column steps, and the axis with as many intervals as the column's
//! middle. `a = 0` (rows from the axis to the profile, `k` quads across) is tried first; larger
//! `a` (up to 32 values) bend the grid around the column's ends, which fits thin walls such
//! as a cup's. The axis vertices sit at the heights of the column's middle when those rise
//! strictly (rows are then horizontal); otherwise at a blend of their running-maximum height
//! and a small share (2%, then 10%, 30%, 100%) of its chord-length fraction, which keeps them
//! strictly rising and the rows nearly horizontal (a flat foot or a flat top, say). Interior vertices come from Coons
//! interpolation in the `(r, z)` plane; of the layouts that do not fold the best-shaped is
//! taken (the largest smallest sine of a quad's corner angle: a flat foot continuing the
//! bottom radial line would otherwise leave slivers between it and the first rows). Only if
//! every Coons grid folds, each is relaxed towards the Winslow grid (`winslow_smooth`,
//! whose inverse map is harmonic and so one-to-one on any simply connected region) until
//! it no longer folds, and the first such is taken: a goblet's lid runs on into the top
//! sector's radial line, so the grid's corner there spans a straight angle and its Coons
//! interior tangles next to it. A profile for which no layout is found either (a hollow
//! glass whose bowl and foot both reach the axis) is refused.
//!
//! *Rung caps* ([`CapLayout::Rungs`], tried by `super::build` where the fit of those
//! layouts folds: a goblet's thin stem at 32 x 16, whose Coons cells are 60 times longer
//! than wide and bend, so the limit of the unfolded net folded in-plane). The smallest split
//! `a` whose column part rises strictly is taken; each of its vertices is joined to an axis
//! vertex at its height by a *rung*: a straight grid line of evenly spaced vertices. The
//! rungs are placed on the rim's *control points* (what the fit gives the creased rim,
//! computed beforehand: `MeridianPlane::control_points`), the axis vertices at their
//! heights, and every rung at a corner of the column is creased. Why such a cap cannot fold
//! between its end rows: each block between two creased rungs is a structured grid with
//! creased sides and corners only at its four corners, so its limit is the tensor-product
//! cubic B-spline of the net (the crease's ghost points). Across the rungs the net is linear
//! in the grid index, `P[i][j] = (1 − i/n) A[j] + (i/n) C[j]`, and cubic B-splines
//! reproduce linear functions, so the limit is exactly the ruled map
//! `S(u, v) = (1 − u) A(v) + u C(v)`, `A` and `C` the B-spline curves of the axis and
//! column control points. With `A(v) = (0, z_C(v))` its Jacobian is
//! `det(C − A, (1 − u) A' + u C') = r_C(v) z_C'(v)` for every `u`: positive wherever the
//! column's control points have `r > 0` and rising heights (a B-spline lies in the convex
//! hull of its control points and its derivative in the cone of their differences), which
//! is what the layout requires. Only the two rows of faces next to the end rows (the
//! sectors' radial lines, not straight or not evenly spaced) are outside this argument; the
//! fold check certifies them.
//!
//! Where the column turns towards the axis at a crease ring (a cup's foot, a neck), the cap
//! spans a reflex angle at that corner; the grid line from it across the cap is then creased
//! too (to the axis, a crease), for the same reason as at a sector's apex.
//!
//! Every edge where a flat cap meets the side or another cap is an infinitely sharp crease,
//! and every vertex where three or more creases meet an infinitely sharp corner. A cap's
//! data points lie in its plane; behind its creases its limit surface depends only on its own
//! control points, and their fit is planar too, so the caps are flat in the limit. A meridian
//! cap's inner and axis vertices ([`DesignCoord::Planar`]) carry no data: the fit keeps them
//! at their layout positions as control points (`Fitted::fit_free`), so the cap's inside is
//! the limit of the unfolded planar grid rather than an interpolant bent through every grid
//! point (which overshot in the plane where the cells change size, and folded).
//!
//! *Faired pole sectors.* A pole sector's inner vertices (off its ring, its boundary radial
//! lines and every crease) are marked `Role::Fair`: where the interpolating fit of the turn
//! folds (the sector's `k` small cells against one long profile interval), `super::build`
//! fits again with those data points released and their control points faired
//! (`fit::bending`), the rest still interpolated.

use std::collections::HashSet;
use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};

use super::input::RevolveInput;
use super::profile::{cap_point, revolve_point, sector_point, RevolvedProfile};
use crate::construct::design::DesignCoord;
use crate::construct::grid_mesh::{grid_mesh_coords, GridEnd, SweepGrid};
use crate::construct::settings::{Caps, Settings};
use crate::error::{Error, Result};
use crate::fit::Role;
use crate::mesh::{Corner, Crease, MeshParts, SHARPNESS_INFINITE};

/// Shares of the chord-length fraction tried, in turn, in the axis spacing of a meridian cap
/// whose ring column does not rise strictly (the rest follows its heights).
const CHORD_SHARES: [f64; 4] = [0.02, 0.1, 0.3, 1.0];

/// Most splits of the meridian cap layout tried beyond `a = 0`.
const MAX_SPLITS: usize = 32;

/// How a meridian cap's structured grid is laid out ([`wedge_parts`]; `super::build` tries
/// them in this order where the fit of the previous one folds).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CapLayout {
    /// The best-shaped unfolded Coons grid over the splits and axis spacings tried.
    Coons,
    /// [`CapLayout::Coons`], and where every Coons grid folds, the first that no longer
    /// folds after relaxing towards the Winslow grid.
    Winslow,
    /// Rungs: split `a = 0`, each column vertex joined to the axis vertex at its height by
    /// a straight grid line of evenly spaced vertices, and that line creased where the
    /// column has a corner (see the module documentation: its limit is ruled, and cannot
    /// fold where the column rises). Only for a column rising strictly between the apexes.
    Rungs,
}

/// A sector closing one end ring: its apex and its two radial lines.
struct Sector {
    apex: u32,
    /// Vertex ids from the apex to the ring, along θ = 0 and along θ = angle.
    radials: [Vec<u32>; 2],
    /// The ring position (meridian column) of its bisector if that is creased.
    creased_column: Option<usize>,
    /// Its vertices off the ring and off the two boundary radial lines.
    inner: Vec<u32>,
}

/// Largest span (radians, 150°) left between two creases at a sector's apex: the corner rule
/// maps the faces between two creases at an infinitely sharp corner into the convex cone of
/// the creases' tangents, so a span of 180° or more folds, and one close to 180° leaves the
/// limit normal at the apex ill-conditioned.
const SPAN_LIMIT: f64 = 5.0 * PI / 6.0;

/// Where grid point `(x, y)` (0 to `m` each) of a sector patch lies, as a relative radius and
/// a fraction of the patch's span: the patch is a quarter of a full turn's grid cap
/// (`crate::construct::pole_cap`), whose concentric squares map to circles: the L-shaped
/// square line `max(x, y) = ρ m` to the circle of radius ρ, uniformly in angle from the
/// radial line at 0 (`y = 0`) through the corner `(ρ m, ρ m)` (half the span) to the one at
/// the span (`x = 0`). So the radial steps are `1 / m` everywhere, also at the patch's
/// corner in the middle of its arc, where a Coons patch squeezed them to nothing.
fn square_polar(x: usize, y: usize, m: usize) -> (f64, f64) {
    let r = x.max(y);
    if r == 0 {
        return (0.0, 0.0);
    }
    let (x, y, r) = (x as f64, y as f64, r as f64);
    let turn = if x >= y {
        0.5 * y / r
    } else {
        1.0 - 0.5 * x / r
    };
    (r / m as f64, turn)
}

/// The wedge under construction: the side's parts plus caps.
struct Wedge {
    parts: MeshParts,
    /// The design coordinates of the vertices so far.
    coords: Vec<DesignCoord>,
    /// Directed edges of the faces so far (to orient new patches).
    directed: HashSet<(u32, u32)>,
    /// Crease edges so far, as (min, max).
    creased: HashSet<(u32, u32)>,
}

/// Quads of the structured grid `ids[i][j]`.
fn grid_quads(ids: &[Vec<u32>]) -> Vec<[u32; 4]> {
    let mut quads = Vec::new();
    for i in 0..ids.len() - 1 {
        for j in 0..ids[i].len() - 1 {
            quads.push([ids[i][j], ids[i][j + 1], ids[i + 1][j + 1], ids[i + 1][j]]);
        }
    }
    quads
}

/// Transfinite (Coons) interpolation of a grid `x[i][j]` (`i` in `0..=a`, `j` in `0..=b`)
/// from its sides `x[i][0] = left[i]`, `x[i][b] = right[i]`, `x[0][j] = bottom[j]`,
/// `x[a][j] = top[j]`, at side parameters `u[i]` and `v[j]` (0 to 1).
fn coons(
    left: &[DVec2],
    right: &[DVec2],
    bottom: &[DVec2],
    top: &[DVec2],
    u: &[f64],
    v: &[f64],
) -> Vec<Vec<DVec2>> {
    let (a, b) = (left.len() - 1, bottom.len() - 1);
    (0..=a)
        .map(|i| {
            (0..=b)
                .map(|j| {
                    let (u, v) = (u[i], v[j]);
                    (1.0 - v) * left[i] + v * right[i] + (1.0 - u) * bottom[j] + u * top[j]
                        - ((1.0 - u) * (1.0 - v) * left[0]
                            + (1.0 - u) * v * right[0]
                            + u * (1.0 - v) * left[a]
                            + u * v * right[a])
                })
                .collect()
        })
        .collect()
}

fn uniform(count: usize) -> Vec<f64> {
    (0..=count).map(|i| i as f64 / count as f64).collect()
}

impl Wedge {
    fn new((parts, coords): (MeshParts, Vec<DesignCoord>)) -> Wedge {
        let mut directed = HashSet::new();
        for f in parts.face_indices.chunks_exact(4) {
            for i in 0..4 {
                directed.insert((f[i], f[(i + 1) % 4]));
            }
        }
        let creased = parts
            .creases
            .iter()
            .map(|c| {
                (
                    c.vertices[0].min(c.vertices[1]),
                    c.vertices[0].max(c.vertices[1]),
                )
            })
            .collect();
        Wedge {
            parts,
            coords,
            directed,
            creased,
        }
    }

    fn add_vertex(&mut self, p: DVec3, coord: DesignCoord) -> u32 {
        self.coords.push(coord);
        self.parts.positions.push(p);
        self.parts.positions.len() as u32 - 1
    }

    /// Add a patch's quads, reversed if they run along an existing edge the same way
    /// (consistent orientation); `creased`: its boundary edges become crease edges.
    fn add_patch(&mut self, mut quads: Vec<[u32; 4]>, creased: bool) {
        fn edges(f: &[u32; 4]) -> impl Iterator<Item = (u32, u32)> + '_ {
            (0..4).map(move |i| (f[i], f[(i + 1) % 4]))
        }
        if quads
            .iter()
            .any(|f| edges(f).any(|e| self.directed.contains(&e)))
        {
            for f in &mut quads {
                f.swap(1, 3);
            }
        }
        let own: HashSet<(u32, u32)> = quads.iter().flat_map(edges).collect();
        for f in &quads {
            for (a, b) in edges(f) {
                self.directed.insert((a, b));
                if creased && !own.contains(&(b, a)) {
                    self.crease(a, b);
                }
            }
            self.parts.face_sizes.push(4);
            self.parts.face_indices.extend_from_slice(f);
        }
    }

    /// Close `ring` (`4k + 1` ids from θ = 0 to θ = `angle`) with the two-patch sector
    /// layout (see the module documentation); `place(ρ, θ)` gives the data point at relative
    /// radius ρ and angle θ. `flat`: a flat end, whose boundary edges become creases.
    fn sector(
        &mut self,
        end: usize,
        ring: &[u32],
        angle: f64,
        place: &dyn Fn(f64, f64) -> DVec3,
        flat: bool,
    ) -> Sector {
        let k = (ring.len() - 1) / 4;
        let half = angle / 2.0;
        let at = |rho: f64, theta: f64| DesignCoord::Cap { end, rho, theta };
        let apex = self.add_vertex(place(0.0, 0.0), at(0.0, 0.0));
        // The radial lines at θ = 0, angle / 2 and angle, from the apex to ring vertex 2kp.
        let radials: Vec<Vec<u32>> = (0..3)
            .map(|p| {
                let theta = p as f64 * half;
                let mut ids = vec![apex];
                ids.extend((1..k).map(|j| {
                    let rho = j as f64 / k as f64;
                    self.add_vertex(place(rho, theta), at(rho, theta))
                }));
                ids.push(ring[2 * k * p]);
                ids
            })
            .collect();
        // Patch p spans θ from p·half to (p + 1)·half: `ids[0][j]` its first radial line,
        // `ids[i][0]` its second, `ids[i][k]` the ring from the first to the patch's middle,
        // `ids[k][j]` the ring from the second back to the middle.
        let mut quads = Vec::new();
        for p in 0..2 {
            let ring_at = |q: usize| ring[2 * k * p + q];
            let mut ids = vec![vec![0u32; k + 1]; k + 1];
            for i in 0..=k {
                for j in 0..=k {
                    ids[i][j] = if i == 0 {
                        radials[p][j]
                    } else if j == 0 {
                        radials[p + 1][i]
                    } else if j == k {
                        ring_at(i)
                    } else if i == k {
                        ring_at(2 * k - j)
                    } else {
                        let (rho, share) = square_polar(j, i, k);
                        let theta = (p as f64 + share) * half;
                        self.add_vertex(place(rho, theta), at(rho, theta))
                    };
                }
            }
            quads.extend(grid_quads(&ids));
        }
        self.add_patch(quads, flat);
        // The apex is an infinitely sharp corner: a span between two creases there must stay
        // below SPAN_LIMIT, so a wider sector creases its bisector (a flat sector's crease ends
        // at its crease ring, a pole's goes on along the side's meridian: `wedge_parts`).
        let bisector = angle > SPAN_LIMIT;
        if bisector {
            for e in radials[1].windows(2) {
                self.crease(e[0], e[1]);
            }
        }
        let boundary: HashSet<u32> = radials[0].iter().chain(&radials[2]).copied().collect();
        Sector {
            apex,
            radials: [radials[0].clone(), radials[2].clone()],
            creased_column: bisector.then_some(2 * k),
            inner: (apex..self.parts.positions.len() as u32)
                .filter(|v| !boundary.contains(v))
                .collect(),
        }
    }

    /// Tag the edge `(a, b)` as an infinitely sharp crease (once).
    fn crease(&mut self, a: u32, b: u32) {
        if self.creased.insert((a.min(b), a.max(b))) {
            self.parts.creases.push(Crease {
                vertices: [a, b],
                sharpness: SHARPNESS_INFINITE,
            });
        }
    }

    /// Close the meridian plane at `theta` with a flat structured grid whose boundary is the
    /// sectors' radial line `bottom` (apex to ring), the ring `column` (bottom to top), the
    /// radial line `top` (apex to ring) and the axis. The first call chooses the split `a` and
    /// creates the axis vertices (`shared`); the second reuses both.
    fn meridian_cap(
        &mut self,
        theta: f64,
        column: &[u32],
        bottom: &[u32],
        top: &[u32],
        layout: CapLayout,
        shared: &mut Option<(usize, CapLayout, Vec<u32>)>,
    ) -> Result<()> {
        let rz = |w: &Wedge, v: u32| {
            let p = w.parts.positions[v as usize];
            DVec2::new(p.truncate().length(), p.z)
        };
        let mut plane = MeridianPlane {
            column: column.iter().map(|&v| rz(self, v)).collect(),
            bottom: bottom.iter().map(|&v| rz(self, v)).collect(),
            top: top.iter().map(|&v| rz(self, v)).collect(),
        };
        if shared.as_ref().map_or(layout, |s| s.1) == CapLayout::Rungs {
            // Rungs run between the rim's control points (what the fit will give it), so
            // that the cap's limit is exactly ruled (module documentation).
            let rim: Vec<u32> = bottom
                .iter()
                .chain(&column[1..column.len() - 1])
                .chain(top.iter().rev())
                .copied()
                .collect();
            let corners = self.rim_corners(&rim);
            plane = plane.control_points(&corners);
        }
        let (z0, z1) = (plane.bottom[0].y, plane.top[0].y);
        if z0 == z1 {
            return Err(Error::invalid_argument(format!(
                "caps: the profile's ends lie at one height z = {z0}; the flat caps on the \
                 meridian planes need an axis segment between them"
            )));
        }
        let (a, grid) = match shared {
            Some((a, built, axis)) => {
                let u = axis
                    .iter()
                    .map(|&v| (self.parts.positions[v as usize].z - z0) / (z1 - z0))
                    .collect();
                (*a, plane.grid(*a, u, *built)?)
            }
            None => {
                let (a, built, grid) = plane.choose(layout)?;
                let axis: Vec<u32> = grid[0]
                    .iter()
                    .enumerate()
                    .map(|(j, p)| match j {
                        0 => bottom[0],
                        j if j == grid[0].len() - 1 => top[0],
                        _ => self.add_vertex(DVec3::new(0.0, 0.0, p.y), DesignCoord::Planar),
                    })
                    .collect();
                *shared = Some((a, built, axis));
                (a, grid)
            }
        };
        let axis = &shared.as_ref().expect("set above").2;
        let (n1, n2) = (grid.len() - 1, grid[0].len() - 1);
        let (k, rows) = (bottom.len() - 1, column.len() - 1);
        let mut ids = vec![vec![0u32; n2 + 1]; n1 + 1];
        for (i, row) in ids.iter_mut().enumerate() {
            for (j, id) in row.iter_mut().enumerate() {
                *id = if j == 0 {
                    if i <= k {
                        bottom[i]
                    } else {
                        column[i - k]
                    }
                } else if j == n2 {
                    if i <= k {
                        top[i]
                    } else {
                        column[rows - (i - k)]
                    }
                } else if i == 0 {
                    axis[j]
                } else if i == n1 {
                    column[a + j]
                } else {
                    self.add_vertex(revolve_point(grid[i][j], theta), DesignCoord::Planar)
                };
            }
        }
        self.add_patch(grid_quads(&ids), true);
        if shared.as_ref().expect("set above").1 == CapLayout::Rungs {
            self.crease_corner_rungs(&ids);
        }
        self.split_reflex_corners(&ids, &column[1..rows]);
        Ok(())
    }

    /// Which vertices of the closed cap rim `rim` (bottom apex, bottom radial line, column,
    /// top radial line, top apex) are corners once the rim's edges are creased: three or more
    /// creases ([`Wedge::finish`]), a tagged corner, or an apex.
    fn rim_corners(&self, rim: &[u32]) -> Vec<bool> {
        let mut edges = self.creased.clone();
        edges.extend(rim.windows(2).map(|e| (e[0].min(e[1]), e[0].max(e[1]))));
        let degree = crease_degrees(&edges);
        let tagged: HashSet<u32> = self.parts.corners.iter().map(|c| c.vertex).collect();
        rim.iter()
            .enumerate()
            .map(|(i, v)| i == 0 || i + 1 == rim.len() || tagged.contains(v) || degree[v] >= 3)
            .collect()
    }

    /// Crease every rung of a [`CapLayout::Rungs`] grid `ids` (`ids[i][j]`, `i = 0` the
    /// axis, the last `i` the column) whose column vertex is a corner of the cap's rim (three
    /// or more creases): the rung then splits the cap into blocks whose rims have corners
    /// only at the blocks' four corners, which the ruled limit needs (module documentation).
    fn crease_corner_rungs(&mut self, ids: &[Vec<u32>]) {
        let degree = crease_degrees(&self.creased);
        let n2 = ids[0].len() - 1;
        let column = &ids[ids.len() - 1];
        for j in 1..n2 {
            if degree.get(&column[j]).copied().unwrap_or(0) >= 3 {
                for w in ids.windows(2) {
                    self.crease(w[0][j], w[1][j]);
                }
            }
        }
    }

    /// Crease the grid line from each corner (three creases) among `candidates` on the
    /// boundary of the flat grid `ids` across it, where the grid's span there is reflex: like
    /// a sector's apex, the corner rule cannot fill more than 180° between two creases (a
    /// crease ring meeting a profile that turns towards the axis, a cup's foot or a neck).
    fn split_reflex_corners(&mut self, ids: &[Vec<u32>], candidates: &[u32]) {
        let degree = crease_degrees(&self.creased);
        let (n1, n2) = (ids.len() - 1, ids[0].len() - 1);
        let at = |v: u32| self.parts.positions[v as usize];
        let mut splits = Vec::new();
        for i in 0..=n1 {
            for j in 0..=n2 {
                let v = ids[i][j];
                let interior = |i: usize, j: usize| i > 0 && i < n1 && j > 0 && j < n2;
                if !candidates.contains(&v) || degree.get(&v).copied().unwrap_or(0) < 3 {
                    continue;
                }
                // The boundary vertex's grid neighbours: two on the boundary, one inside.
                let near: Vec<(usize, usize)> = [(1, 0), (0, 1), (-1, 0), (0, -1)]
                    .iter()
                    .map(|&(di, dj)| (i as i64 + di, j as i64 + dj))
                    .filter(|&(a, b)| a >= 0 && b >= 0 && a <= n1 as i64 && b <= n2 as i64)
                    .map(|(a, b)| (a as usize, b as usize))
                    .collect();
                let inside: Vec<&(usize, usize)> =
                    near.iter().filter(|&&(a, b)| interior(a, b)).collect();
                let rim: Vec<u32> = near
                    .iter()
                    .filter(|&&(a, b)| !interior(a, b))
                    .map(|&(a, b)| ids[a][b])
                    .collect();
                let (&[&(qi, qj)], &[p, n]) = (inside.as_slice(), rim.as_slice()) else {
                    continue;
                };
                let q = ids[qi][qj];
                let rz = |w: u32| DVec2::new(at(w).truncate().length(), at(w).z);
                if is_reflex(rz(v), rz(p), rz(n), rz(q)) {
                    // The whole grid line across the cap, so that the crease ends at a
                    // crease (the axis) rather than in a dart.
                    let (di, dj) = (qi as i64 - i as i64, qj as i64 - j as i64);
                    let (mut a, mut b) = (i as i64, j as i64);
                    loop {
                        let (c, d) = (a + di, b + dj);
                        splits.push((ids[a as usize][b as usize], ids[c as usize][d as usize]));
                        (a, b) = (c, d);
                        if !interior(a as usize, b as usize) {
                            break;
                        }
                    }
                }
            }
        }
        for (v, w) in splits {
            self.crease(v, w);
        }
    }

    /// Tag every vertex with three or more crease edges (and each of `extra`) as an
    /// infinitely sharp corner, then return the parts.
    fn finish(mut self, extra: &[u32]) -> (MeshParts, Vec<DesignCoord>) {
        let mut count = vec![0usize; self.parts.positions.len()];
        for c in &self.parts.creases {
            for v in c.vertices {
                count[v as usize] += 1;
            }
        }
        let mut corners: Vec<u32> = (0..count.len() as u32)
            .filter(|&v| count[v as usize] >= 3)
            .chain(extra.iter().copied())
            .chain(self.parts.corners.iter().map(|c| c.vertex))
            .collect();
        corners.sort_unstable();
        corners.dedup();
        self.parts.corners = corners
            .into_iter()
            .map(|vertex| Corner {
                vertex,
                sharpness: SHARPNESS_INFINITE,
            })
            .collect();
        (self.parts, self.coords)
    }
}

/// A meridian cap's boundary in the `(r, z)` plane: the bottom sector's radial line (apex to
/// ring), the ring column (bottom to top) and the top sector's radial line (apex to ring).
struct MeridianPlane {
    bottom: Vec<DVec2>,
    column: Vec<DVec2>,
    top: Vec<DVec2>,
}

impl MeridianPlane {
    /// The rim's control points under an infinitely sharp crease: between two corners
    /// (`corners`, one flag per rim point from the bottom apex round to the top apex) the
    /// crease's limit is the cubic B-spline of its control points, so a point's limit is
    /// `(p₋ + 4p + p₊) / 6`; solving that (tridiagonal, the corners fixed) gives the
    /// control points the fit finds for the data points (the creases decouple the rim).
    fn control_points(&self, corners: &[bool]) -> MeridianPlane {
        let (k, rows) = (self.bottom.len() - 1, self.column.len() - 1);
        let mut rim: Vec<DVec2> = self.bottom.clone();
        rim.extend_from_slice(&self.column[1..rows]);
        rim.extend(self.top.iter().rev());
        let mut control = rim.clone();
        let mut start = 0;
        for end in (1..rim.len()).filter(|&i| corners[i]) {
            solve_crease(&rim[start..=end], &mut control[start..=end]);
            start = end;
        }
        let mut top: Vec<DVec2> = control[control.len() - k - 1..].to_vec();
        top.reverse();
        MeridianPlane {
            bottom: control[..=k].to_vec(),
            column: control[k..=k + rows].to_vec(),
            top,
        }
    }

    /// The best-shaped unfolded layout ([`min_corner_sine`]): split `a = 0, 1, ...` (at most [`MAX_SPLITS`] values,
    /// evenly spread, so that a refusal stays cheap), and for each the axis spacings of
    /// [`MeridianPlane::axis_spacings`]; the Coons grids first, and only if every one of
    /// them folds, the first of the same layouts that folds no longer after
    /// [`winslow_smooth`] if `layout` is [`CapLayout::Winslow`] (the returned layout: how the
    /// grid was built); [`CapLayout::Rungs`]: only the rung grid (module documentation).
    fn choose(&self, layout: CapLayout) -> Result<(usize, CapLayout, Vec<Vec<DVec2>>)> {
        let rows = self.column.len() - 1;
        let last = (rows - 1) / 2;
        if layout == CapLayout::Rungs {
            // The smallest split whose column part rises strictly: the sides then take the
            // column's runs along the ends' heights (a flat foot's underside, a lid).
            let a = (0..=last).find(|&a| self.rises(a)).ok_or_else(|| {
                Error::invalid_argument(
                    "caps: the rung layout of a meridian cap needs the profile's rings to \
                         rise strictly between its two ends",
                )
            })?;
            let u = self.axis_spacings(a).remove(0);
            return Ok((a, layout, self.grid(a, u, layout)?));
        }
        let last = (rows - 1) / 2;
        let splits: Vec<usize> = if last < MAX_SPLITS {
            (0..=last).collect()
        } else {
            (0..=MAX_SPLITS).map(|t| t * last / MAX_SPLITS).collect()
        };
        let mut first_error = None;
        let mut best: Option<(f64, usize, Vec<Vec<DVec2>>)> = None;
        for &a in &splits {
            for u in self.axis_spacings(a) {
                match self.grid(a, u, CapLayout::Coons) {
                    Ok(grid) => {
                        let q = min_corner_sine(&grid);
                        if best.as_ref().map_or(true, |b| q > b.0) {
                            best = Some((q, a, grid));
                        }
                    }
                    Err(e) => {
                        first_error.get_or_insert(e);
                    }
                }
            }
        }
        if let Some((_, a, grid)) = best {
            return Ok((a, CapLayout::Coons, grid));
        }
        let first_error = first_error.expect("at least one layout is tried");
        if layout == CapLayout::Coons {
            return Err(first_error);
        }
        for &a in &splits {
            for u in self.axis_spacings(a) {
                if let Ok(grid) = self.grid(a, u, layout) {
                    return Ok((a, layout, grid));
                }
            }
        }
        Err(first_error)
    }

    /// Candidate axis spacings (fractions from the bottom apex to the top apex) for split
    /// `a`, whose axis faces the column's middle part `column[a..=rows - a]`: its heights if
    /// they rise strictly, else blends of their running maximum with a growing share of the
    /// chord-length fraction ([`CHORD_SHARES`]).
    fn axis_spacings(&self, a: usize) -> Vec<Vec<f64>> {
        let (z0, z1) = (self.bottom[0].y, self.top[0].y);
        let mid = &self.column[a..self.column.len() - a];
        let n = mid.len() - 1;
        let monotone = rising(z0, z1, mid);
        let mut height = Vec::with_capacity(n + 1);
        let mut chord = vec![0.0];
        for (i, c) in mid.iter().enumerate() {
            let h = ((c.y - z0) / (z1 - z0)).clamp(0.0, 1.0);
            height.push(if i == 0 { h } else { h.max(height[i - 1]) });
            if i > 0 {
                chord.push(chord[i - 1] + (mid[i] - mid[i - 1]).length());
            }
        }
        let blend = |mix: f64| -> Vec<f64> {
            (0..=n)
                .map(|j| match j {
                    0 => 0.0,
                    j if j == n => 1.0,
                    j => (1.0 - mix) * height[j] + mix * chord[j] / chord[n],
                })
                .collect()
        };
        let mixes: &[f64] = if monotone { &[0.0] } else { &CHORD_SHARES };
        mixes.iter().map(|&m| blend(m)).collect()
    }

    /// Whether the column's part `column[a..=rows - a]` rises strictly from the bottom
    /// apex's height to the top apex's ([`CapLayout::Rungs`]).
    fn rises(&self, a: usize) -> bool {
        let mid = &self.column[a..self.column.len() - a];
        rising(self.bottom[0].y, self.top[0].y, mid)
    }

    /// The grid `x[i][j]` of split `a` with axis fractions `u` (`rows − 2a + 1` values):
    /// `x[i][0]` runs from the bottom apex along the bottom radial line and up the column to
    /// `column[a]`, `x[i][n2]` from the top apex along the top radial line and down the column
    /// to `column[rows − a]`, `x[0][j]` up the axis, `x[n1][j]` along `column[a..=rows − a]`.
    /// `layout`: [`CapLayout::Winslow`] relaxes the Coons grid's inside by
    /// [`winslow_smooth`]; [`CapLayout::Rungs`] puts it on the straight lines from each axis
    /// vertex to its column vertex instead, evenly. Errors if it folds.
    fn grid(&self, a: usize, u: Vec<f64>, layout: CapLayout) -> Result<Vec<Vec<DVec2>>> {
        let (k, rows) = (self.bottom.len() - 1, self.column.len() - 1);
        let (z0, z1) = (self.bottom[0].y, self.top[0].y);
        let side = |radial: &[DVec2], down: bool| -> Vec<DVec2> {
            let mut s = radial.to_vec();
            s.extend((1..=a).map(|i| self.column[if down { rows - i } else { i }]));
            s
        };
        let axis: Vec<DVec2> = u
            .iter()
            .map(|&f| DVec2::new(0.0, z0 + f * (z1 - z0)))
            .collect();
        let mid = &self.column[a..=rows - a];
        let mut grid = coons(
            &side(&self.bottom, false),
            &side(&self.top, true),
            &axis,
            mid,
            &uniform(k + a),
            &u,
        );
        match layout {
            CapLayout::Coons => {}
            CapLayout::Winslow => winslow_smooth(&mut grid, |g| check_unfolded(g).is_ok()),
            CapLayout::Rungs => {
                let (n1, n2) = (grid.len() - 1, grid[0].len() - 1);
                let (axis, column) = (grid[0].clone(), grid[n1].clone());
                for (i, row) in grid.iter_mut().enumerate().take(n1).skip(1) {
                    let t = i as f64 / n1 as f64;
                    for (j, p) in row.iter_mut().enumerate().take(n2).skip(1) {
                        *p = (1.0 - t) * axis[j] + t * column[j];
                    }
                }
            }
        }
        check_unfolded(&grid)?;
        Ok(grid)
    }
}

/// How many of the crease edges `edges` (as (min, max)) meet at each vertex.
fn crease_degrees(edges: &HashSet<(u32, u32)>) -> std::collections::HashMap<u32, usize> {
    let mut degree = std::collections::HashMap::new();
    for &(a, b) in edges {
        *degree.entry(a).or_insert(0usize) += 1;
        *degree.entry(b).or_insert(0usize) += 1;
    }
    degree
}

/// The control points `p` of a crease chain whose limit points are `d`, its ends fixed:
/// `(p[i − 1] + 4 p[i] + p[i + 1]) / 6 = d[i]` inside (Thomas algorithm; diagonally
/// dominant, so stable).
fn solve_crease(d: &[DVec2], p: &mut [DVec2]) {
    let n = d.len();
    if n < 3 {
        return;
    }
    // Unknowns p[1..n-1]: p[i-1] + 4 p[i] + p[i+1] = 6 d[i].
    let mut c = vec![0.0; n];
    let mut r = vec![DVec2::ZERO; n];
    for i in 1..n - 1 {
        let mut rhs = 6.0 * d[i];
        if i == 1 {
            rhs -= d[0];
        }
        if i == n - 2 {
            rhs -= d[n - 1];
        }
        let below = if i == 1 { 0.0 } else { 1.0 };
        let pivot = 4.0 - below * c[i - 1];
        c[i] = 1.0 / pivot;
        r[i] = (rhs - below * r[i - 1]) / pivot;
    }
    p[0] = d[0];
    p[n - 1] = d[n - 1];
    p[n - 2] = r[n - 2];
    for i in (1..n - 2).rev() {
        p[i] = r[i] - c[i] * p[i + 1];
    }
}

/// Whether the heights of `mid` rise strictly from `z0` to `z1` (the ends of `mid` may lie
/// at those heights; strictly between them, the inner points).
fn rising(z0: f64, z1: f64, mid: &[DVec2]) -> bool {
    let n = mid.len() - 1;
    let rises = |p: f64, q: f64| (q - p) * (z1 - z0) > 0.0;
    mid.windows(2).all(|w| rises(w[0].y, w[1].y))
        && (n < 2 || (rises(z0, mid[1].y) && rises(mid[n - 1].y, z1)))
}

/// Most Gauss-Seidel sweeps of [`winslow_smooth`].
const WINSLOW_SWEEPS: usize = 4000;

/// Relax the inside of the structured grid `x[i][j]` (its boundary fixed) towards the
/// discrete Winslow grid: the one whose grid indices are harmonic functions of the plane
/// (the inverse of a harmonic map, the elliptic grid generation of Winslow 1967 and
/// Thompson, Warsi & Mastin). A harmonic map *onto* a non-convex region may fold; its
/// inverse is one-to-one for any simply connected region (Radó-Kneser-Choquet applied to
/// the convex parameter rectangle), which is why a Coons grid that folds next to a
/// straight-angle grid corner (a goblet's lid running on into the top sector's radial
/// line) is untangled here. The discrete grid is not guaranteed unfolded: the caller
/// checks it ([`check_unfolded`]). Sweeps stop as soon as `done` holds for the grid (the
/// caller's unfolded check: the Coons grid changes no more than it must), when no vertex
/// moves by more than 1e-12 of the grid's extent, or after [`WINSLOW_SWEEPS`];
/// deterministic.
fn winslow_smooth(x: &mut [Vec<DVec2>], done: impl Fn(&[Vec<DVec2>]) -> bool) {
    let (a, b) = (x.len() - 1, x[0].len() - 1);
    if a < 2 || b < 2 {
        return;
    }
    let extent = x.iter().flatten().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let tolerance = 1e-12 * (extent.1 - extent.0).length();
    for _ in 0..WINSLOW_SWEEPS {
        let mut moved = 0.0f64;
        for i in 1..a {
            for j in 1..b {
                let xi = 0.5 * (x[i + 1][j] - x[i - 1][j]);
                let eta = 0.5 * (x[i][j + 1] - x[i][j - 1]);
                let (alpha, beta, gamma) = (eta.length_squared(), xi.dot(eta), xi.length_squared());
                let cross = x[i + 1][j + 1] - x[i + 1][j - 1] - x[i - 1][j + 1] + x[i - 1][j - 1];
                let sum = alpha * (x[i + 1][j] + x[i - 1][j]) + gamma * (x[i][j + 1] + x[i][j - 1])
                    - 0.5 * beta * cross;
                let weight = 2.0 * (alpha + gamma);
                if weight > 0.0 {
                    let p = sum / weight;
                    moved = moved.max((p - x[i][j]).length());
                    x[i][j] = p;
                }
            }
        }
        if moved <= tolerance || done(x) {
            break;
        }
    }
}

/// Whether the span at `v` from its neighbour `p` to its neighbour `n` that holds `q` is
/// reflex (180° or more).
fn is_reflex(v: DVec2, p: DVec2, n: DVec2, q: DVec2) -> bool {
    let turn = |w: DVec2| crate::math::atan2((w - v).y, (w - v).x);
    let ccw = |from: f64, to: f64| (to - from).rem_euclid(TAU);
    let (tp, tn, tq) = (turn(p), turn(n), turn(q));
    let span = if ccw(tp, tq) < ccw(tp, tn) {
        ccw(tp, tn)
    } else {
        ccw(tn, tp)
    };
    span >= PI
}

/// The smallest sine of a quad corner angle in the grid (1 for rectangles, near 0 for
/// slivers), signed by the orientation of the whole grid.
fn min_corner_sine(grid: &[Vec<DVec2>]) -> f64 {
    let (a, b) = (grid.len() - 1, grid[0].len() - 1);
    let sines: Vec<f64> = (0..a)
        .flat_map(|i| (0..b).map(move |j| (i, j)))
        .flat_map(|(i, j)| {
            let q = [
                grid[i][j],
                grid[i][j + 1],
                grid[i + 1][j + 1],
                grid[i + 1][j],
            ];
            (0..4).map(move |c| {
                let (p, n) = (q[(c + 3) % 4] - q[c], q[(c + 1) % 4] - q[c]);
                n.perp_dot(p) / (n.length() * p.length()).max(f64::MIN_POSITIVE)
            })
        })
        .collect();
    let sign = sines.iter().sum::<f64>().signum();
    sines.iter().map(|s| s * sign).fold(f64::INFINITY, f64::min)
}

/// Error if a quad of the meridian cap grid folds: its signed area has the wrong sign, or
/// more than one of its corners turns the wrong way (a bow tie).
fn check_unfolded(grid: &[Vec<DVec2>]) -> Result<()> {
    let quad = |i: usize, j: usize| {
        [
            grid[i][j],
            grid[i][j + 1],
            grid[i + 1][j + 1],
            grid[i + 1][j],
        ]
    };
    let area = |q: &[DVec2; 4]| (0..4).map(|c| q[c].perp_dot(q[(c + 1) % 4])).sum::<f64>();
    let (a, b) = (grid.len() - 1, grid[0].len() - 1);
    let total: f64 = (0..a)
        .flat_map(|i| (0..b).map(move |j| (i, j)))
        .map(|(i, j)| area(&quad(i, j)))
        .sum();
    for i in 0..a {
        for j in 0..b {
            let q = quad(i, j);
            let wrong = (0..4)
                .filter(|&c| {
                    let (p, n) = (q[(c + 3) % 4], q[(c + 1) % 4]);
                    (n - q[c]).perp_dot(p - q[c]) * total < 0.0
                })
                .count();
            if area(&q) * total <= 0.0 || wrong > 1 {
                return Err(Error::invalid_argument(format!(
                    "caps: the flat cap between the profile and the axis would fold near \
                     (r, z) = ({:.6}, {:.6}) in every structured layout tried; the region \
                     between the profile and the axis must be a simple strip that rows from \
                     the axis can fill (a hollow shell reaching the axis twice is not)",
                    q[0].x, q[0].y
                )));
            }
        }
    }
    Ok(())
}

/// The mesh parts of a partial revolution: the side from `grid` (rings of
/// `samples_around + 1` data points, `ring_s` their profile parameters), sectors at poles (their
/// radial lines through `radial[end]`'s profile parameters by [`sector_point`], or evenly in
/// the curve parameter where that is empty) and
/// (with caps) at flat ends, and meridian caps (see the module documentation); and the
/// vertices' design coordinates (sectors as caps, meridian caps planar), and what the fit
/// asks of each vertex: a meridian cap's inside and axis keep their layout positions
/// (`Role::Keep`); a pole sector's inner vertices off creases are faired (`Role::Fair`,
/// see the module documentation); the rest interpolate their data points.
///
/// `layout`: how the meridian caps' grids are laid out ([`CapLayout`]; callers try
/// [`CapLayout::Coons`], then [`CapLayout::Winslow`], then [`CapLayout::Rungs`]).
///
/// Errors ([`Error::InvalidArgument`]): caps with fewer than 2 rings, ends at one height, or
/// a folding meridian cap.
pub fn wedge_parts(
    input: &RevolveInput,
    settings: &Settings,
    profile: &RevolvedProfile,
    grid: &SweepGrid,
    ring_s: &[f64],
    radial: &[Vec<f64>; 2],
    layout: CapLayout,
) -> Result<(MeshParts, Vec<DesignCoord>, Vec<Role>)> {
    let capped = settings.caps == Caps::Flat;
    let rows = grid.rings.len();
    if capped && rows < 2 {
        return Err(Error::invalid_argument(format!(
            "samples_profile = {}: the flat meridian caps need at least two rings between \
             the poles; give more profile intervals",
            input.samples_profile
        )));
    }
    let side = SweepGrid {
        ends: [GridEnd::Open; 2],
        ..grid.clone()
    };
    // No grid caps: the side's ends are open.
    let mut w = Wedge::new(grid_mesh_coords(&side, &|_, _| DVec3::NAN)?);
    let angle = input.angle_deg.to_radians();
    let cols = input.samples_around + 1;
    let ring_ids =
        |i: usize| -> Vec<u32> { (i * cols..(i + 1) * cols).map(|v| v as u32).collect() };
    let mut sectors = Vec::new();
    let mut tips = Vec::new();
    let mut faired = Vec::new();
    for (end, kind) in grid.ends.iter().enumerate() {
        let i = if end == 0 { 0 } else { rows - 1 };
        let s = ring_s[i];
        let sector = match kind {
            GridEnd::Open => continue,
            GridEnd::Flat => {
                let p = profile.point(s);
                let flat = |rho: f64, theta: f64| revolve_point(DVec2::new(rho * p.x, p.y), theta);
                w.sector(end, &ring_ids(i), angle, &flat, true)
            }
            GridEnd::Smooth | GridEnd::Tip(_) => {
                let (params, pole) = (&radial[end], profile.range()[end]);
                let on_surface = |rho: f64, theta: f64| {
                    if params.is_empty() {
                        cap_point(profile, s, pole, rho, theta / TAU)
                    } else {
                        sector_point(profile, params, rho, theta)
                    }
                };
                let sector = w.sector(end, &ring_ids(i), angle, &on_surface, false);
                tips.push(sector.apex);
                faired.extend_from_slice(&sector.inner);
                // A pole's creased radial line goes on along the side's meridian to the
                // other end (a crease ending inside the surface would be a dart).
                if let Some(c) = sector.creased_column {
                    for r in 1..rows {
                        w.crease(ring_ids(r - 1)[c], ring_ids(r)[c]);
                    }
                }
                sector
            }
        };
        sectors.push(sector);
    }
    if capped {
        let mut shared = None;
        for (side, theta) in [(0, 0.0), (1, angle)] {
            let column: Vec<u32> = (0..rows).map(|i| ring_ids(i)[side * (cols - 1)]).collect();
            let (bottom, top) = (&sectors[0].radials[side], &sectors[1].radials[side]);
            w.meridian_cap(theta, &column, bottom, top, layout, &mut shared)?;
        }
    }
    let on_crease: HashSet<u32> = w.creased.iter().flat_map(|&(a, b)| [a, b]).collect();
    let (parts, coords) = w.finish(&tips);
    let mut roles: Vec<Role> = coords
        .iter()
        .map(|c| match c {
            DesignCoord::Planar => Role::Keep,
            _ => Role::Interpolate,
        })
        .collect();
    for v in faired.into_iter().filter(|v| !on_crease.contains(v)) {
        roles[v as usize] = Role::Fair;
    }
    Ok((parts, coords, roles))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coons_reproduces_a_bilinear_patch_and_its_sides() {
        let corner = [
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.5),
            DVec2::new(0.2, 1.0),
            DVec2::new(2.5, 2.0),
        ];
        let bilinear = |u: f64, v: f64| {
            (1.0 - u) * ((1.0 - v) * corner[0] + v * corner[1])
                + u * ((1.0 - v) * corner[2] + v * corner[3])
        };
        let (u, v) = (vec![0.0, 0.3, 1.0], uniform(2));
        let left: Vec<DVec2> = u.iter().map(|&a| bilinear(a, 0.0)).collect();
        let right: Vec<DVec2> = u.iter().map(|&a| bilinear(a, 1.0)).collect();
        let bottom: Vec<DVec2> = v.iter().map(|&b| bilinear(0.0, b)).collect();
        let top: Vec<DVec2> = v.iter().map(|&b| bilinear(1.0, b)).collect();
        let grid = coons(&left, &right, &bottom, &top, &u, &v);
        for (i, row) in grid.iter().enumerate() {
            for (j, p) in row.iter().enumerate() {
                assert!((*p - bilinear(u[i], v[j])).length() < 1e-15, "{i} {j}");
            }
        }
        assert!(check_unfolded(&grid).is_ok());
    }

    #[test]
    fn crease_control_points_reproduce_their_limit_points() {
        // Limit points of a crease chain under the cubic B-spline mask (1, 4, 1) / 6, the
        // ends (corners) their own limits: solving for the control points gives them back.
        let p: Vec<DVec2> = [
            (0.0, 0.0),
            (0.3, 1.0),
            (1.5, 0.2),
            (2.0, 2.5),
            (2.2, 3.0),
            (4.0, 3.1),
        ]
        .iter()
        .map(|&(x, y)| DVec2::new(x, y))
        .collect();
        let n = p.len();
        let d: Vec<DVec2> = (0..n)
            .map(|i| {
                if i == 0 || i == n - 1 {
                    p[i]
                } else {
                    (p[i - 1] + 4.0 * p[i] + p[i + 1]) / 6.0
                }
            })
            .collect();
        let mut solved = d.clone();
        solve_crease(&d, &mut solved);
        for (a, b) in p.iter().zip(&solved) {
            assert!((*a - *b).length() < 1e-14, "{a} {b}");
        }
    }

    #[test]
    #[allow(clippy::needless_range_loop)] // grid[i][j] against column[j]: two indices
    fn rung_grids_are_linear_across_and_follow_the_rim_control_points() {
        // A stem-like plane: a flat bottom radial line, a column rising at r = 0.1 to 0.3,
        // a flat top; the rung grid's rows are evenly spaced straight lines from the axis
        // at the column's control heights to its control points.
        let line = |a: DVec2, b: DVec2, n: usize| -> Vec<DVec2> {
            (0..=n)
                .map(|i| a + (b - a) * (i as f64 / n as f64))
                .collect()
        };
        let column: Vec<DVec2> = (0..=6)
            .map(|j| DVec2::new(0.1 + 0.02 * (j * j) as f64 / 6.0, j as f64))
            .collect();
        let plane = MeridianPlane {
            bottom: line(DVec2::ZERO, column[0], 4),
            top: line(DVec2::new(0.0, 6.0), column[6], 4),
            column,
        };
        let rim = plane.bottom.len() + plane.column.len() - 2 + plane.top.len();
        let mut corners = vec![false; rim];
        (corners[0], corners[rim - 1], corners[4], corners[10]) = (true, true, true, true);
        let control = plane.control_points(&corners);
        let (a, layout, grid) = control.choose(CapLayout::Rungs).unwrap();
        assert_eq!((a, layout), (0, CapLayout::Rungs));
        for j in 1..6 {
            let c = control.column[j];
            assert!((grid[0][j] - DVec2::new(0.0, c.y)).length() < 1e-14);
            assert!((grid[4][j] - c).length() < 1e-14);
            for i in 1..4 {
                let t = i as f64 / 4.0;
                assert!((grid[i][j] - DVec2::new(t * c.x, c.y)).length() < 1e-14);
            }
        }
        // The corners keep their data points; between them the limit mask gives them back.
        assert_eq!(control.column[0], plane.column[0]);
        let d = (control.column[1] + 4.0 * control.column[2] + control.column[3]) / 6.0;
        assert!((d - plane.column[2]).length() < 1e-14);
    }

    #[test]
    fn folded_and_bow_tie_quads_are_refused() {
        let p = |x: f64, y: f64| DVec2::new(x, y);
        // Two quads side by side; the middle column pushed past the right one folds them.
        let good = vec![
            vec![p(0.0, 0.0), p(1.0, 0.0), p(2.0, 0.0)],
            vec![p(0.0, 1.0), p(1.0, 1.0), p(2.0, 1.0)],
        ];
        assert!(check_unfolded(&good).is_ok());
        let mut folded = good.clone();
        folded[0][1] = p(2.5, 0.0);
        folded[1][1] = p(2.5, 1.0);
        let e = check_unfolded(&folded).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("would fold")));
        // A bow tie: the top edge crosses the bottom one.
        let bow = vec![
            vec![p(0.0, 0.0), p(1.0, 0.0)],
            vec![p(1.0, 1.0), p(0.0, 1.0)],
        ];
        assert!(check_unfolded(&bow).is_err());
    }
}
