//! Offset evaluation (`construct::shell`): a sphere by revolution against the analytic
//! sphere of radius R − c, continuity across every edge of OpenSubdiv's closed shapes with
//! extraordinary vertices, and the errors of bad input.

#[path = "support/arc.rs"]
#[allow(dead_code)] // the arcs are not needed here
mod arc;
#[path = "support/osd_shapes.rs"]
#[allow(dead_code)] // the shape index is not needed here
mod osd_shapes;

use glam::DVec3;
use profsubd::construct::shell::{measure, offset_within, OffsetSettings, OffsetSurface, Side};
use profsubd::eval::{Domain, Evaluator};
use profsubd::io::obj::read_obj_file;
use profsubd::mesh::{Crease, MeshParts, SHARPNESS_INFINITE};
use profsubd::{revolve, Error, Mesh, RevolveInput, Settings, SubdivOptions};

const R: f64 = 2.0;

/// A sphere of radius `R` by revolution of a semicircle (smooth poles).
fn sphere() -> Mesh {
    let profile: Vec<[f64; 2]> = arc::semicircle(64)
        .into_iter()
        .map(|[r, z]| [R * r, R * z])
        .collect();
    let mut input = RevolveInput::new(profile);
    (input.samples_profile, input.samples_around) = (32, 64);
    let fitted = revolve::build(&input, &Settings::default()).unwrap();
    (*fitted.mesh).clone()
}

fn options(mesh: &Mesh) -> SubdivOptions {
    mesh.options().resolve()
}

/// Largest `| |O| − (R − c) |` and `| |S| − R |` over an `n × n` lattice of every face.
fn sphere_errors(offset: &OffsetSurface, n: usize, c: f64) -> (f64, f64) {
    let (mut eo, mut es) = (0.0f64, 0.0f64);
    for f in 0..offset.num_parametric_faces() {
        for i in 0..=n {
            for j in 0..=n {
                let o = offset
                    .evaluate(f, i as f64 / n as f64, j as f64 / n as f64)
                    .unwrap();
                eo = eo.max((o.position.length() - (R - c)).abs());
                es = es.max((o.surface.position.length() - R).abs());
            }
        }
    }
    (eo, es)
}

#[test]
fn sphere_offset_lies_on_the_smaller_sphere_and_improves_with_level() {
    let mesh = sphere();
    let c = 0.05 * R;
    let mut previous: Option<f64> = None;
    for level in 0..=3 {
        let settings = OffsetSettings {
            level,
            ..OffsetSettings::new(c)
        };
        let offset = OffsetSurface::new(&mesh, &options(&mesh), settings).unwrap();
        let r = measure(&offset, 3).unwrap();
        eprintln!(
            "level {level}: thickness / c min {:.6} max {:.6} mean {:.6}, max |d - c| / c \
             {:.3e} ({} samples){}",
            r.min,
            r.max,
            r.mean,
            r.max_error / c,
            r.samples,
            previous.map_or(String::new(), |p| format!(", rate {:.2}", p / r.max_error))
        );
        // The crust is exact at its corners: the error falls about 4× a level (h²).
        if let Some(p) = previous {
            assert!(
                r.max_error < p / 3.0,
                "level {level}: {} vs {p}",
                r.max_error
            );
        }
        previous = Some(r.max_error);
        // The offset goes inward.
        let o = offset.evaluate(3, 0.3, 0.6).unwrap();
        assert!(o.position.length() < o.surface.position.length() - 0.9 * c);
    }
    // A tolerance picks the level; O then lies on the sphere of radius R − c up to the
    // surface's own distance from the sphere of radius R, plus the tolerance.
    let t = 1e-4 * c;
    let (offset, report) =
        offset_within(&mesh, &options(&mesh), OffsetSettings::new(c), t).unwrap();
    assert!(report.max_error <= t && report.level == 3, "{report:?}");
    let (eo, es) = sphere_errors(&offset, 4, c);
    eprintln!(
        "tolerance {t:.1e}: level {}, max | |O| - (R - c) | = {eo:.3e}, max | |S| - R | = {es:.3e}",
        report.level
    );
    assert!(eo <= es + 2.0 * t, "{eo} {es}");
    // Outward: the sphere of radius R + c.
    let settings = OffsetSettings {
        side: Side::Outward,
        level: 3,
        ..OffsetSettings::new(c)
    };
    let offset = OffsetSurface::new(&mesh, &options(&mesh), settings).unwrap();
    let o = offset.evaluate(5, 0.25, 0.5).unwrap();
    let s = o.surface.position.length();
    assert!((o.position.length() - s - c).abs() < 1e-4 * c);
}

/// The Ptex points of side `k` of control face `f` at parameter `t` from vertex `k` to
/// vertex `k + 1`, with the derivative of `(u, v)` by `t`.
fn side_point(
    mesh: &Mesh,
    first_ptex: u32,
    f: usize,
    k: usize,
    t: f64,
) -> (u32, f64, f64, [f64; 2]) {
    let n = mesh.face(f).len();
    if n == 4 {
        let (u, v, d) = match k {
            0 => (t, 0.0, [1.0, 0.0]),
            1 => (1.0, t, [0.0, 1.0]),
            2 => (1.0 - t, 1.0, [-1.0, 0.0]),
            _ => (0.0, 1.0 - t, [0.0, -1.0]),
        };
        (first_ptex, u, v, d)
    } else if t < 0.5 {
        (first_ptex + k as u32, 2.0 * t, 0.0, [2.0, 0.0])
    } else {
        let next = ((k + 1) % n) as u32;
        (first_ptex + next, 0.0, 2.0 * (1.0 - t), [0.0, -2.0])
    }
}

#[test]
fn offset_is_continuous_across_every_edge_of_closed_shapes() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let shapes = [
        dir.join("catmark_cube.obj"),
        dir.join("catmark_torus.obj"),
        dir.join("catmark_pyramid.obj"),
        // Crease rings (shoulder, flat base): the sides meet through the mitered corners.
        examples.join("profiles/bottle.obj"),
        // An open surface: its boundary edges have one side only.
        examples.join("profiles/vase.obj"),
    ];
    for path in &shapes {
        let name = path.file_stem().unwrap().to_string_lossy();
        // The bottle's flat base has rings narrower than 2% of the diagonal next to its
        // crease: the mitered corner is feathered into them (corners.rs).
        let fraction = 0.02;
        let mesh = read_obj_file(path).unwrap().mesh;
        let opts = options(&mesh);
        let diag = mesh.bounding_box_diagonal();
        let offset =
            OffsetSurface::new(&mesh, &opts, OffsetSettings::new(fraction * diag)).unwrap();
        let base = Evaluator::new(&mesh, &opts).unwrap();
        let ptex = base.ptex_faces();
        // Each side of each face, keyed by its vertex pair.
        let mut sides = std::collections::HashMap::new();
        for f in 0..mesh.num_faces() {
            let face = mesh.face(f);
            for k in 0..face.len() {
                sides
                    .entry((face[k], face[(k + 1) % face.len()]))
                    .or_insert((f, k));
            }
        }
        let (mut jump, mut surface_jump, mut checked) = (0.0f64, 0.0f64, 0);
        let (mut tangent_jump, mut cross) = (0.0f64, 0.0f64);
        for (&(a, b), &(f, k)) in &sides {
            let Some(&(g, l)) = sides.get(&(b, a)) else {
                assert!(name == "vase", "{name}: edge {a}-{b} is a boundary");
                continue;
            };
            for i in 1..8 {
                let t = i as f64 / 8.0;
                let (pf, u, v, duv) = side_point(&mesh, ptex.first_of(f), f, k, t);
                let (qf, s, w, dsw) = side_point(&mesh, ptex.first_of(g), g, l, 1.0 - t);
                let o1 = offset.evaluate(pf, u, v).unwrap();
                let o2 = offset.evaluate(qf, s, w).unwrap();
                jump = jump.max((o1.position - o2.position).length());
                surface_jump =
                    surface_jump.max((o1.surface.position - o2.surface.position).length());
                // The derivative along the edge (by t), from both sides.
                let along = |o: DVec3, d: DVec3, c: [f64; 2]| o * c[0] + d * c[1];
                let t1 = along(o1.du, o1.dv, duv);
                let t2 = -along(o2.du, o2.dv, dsw);
                let s1 = along(o1.surface.du, o1.surface.dv, duv);
                let s2 = -along(o2.surface.du, o2.surface.dv, dsw);
                tangent_jump = tangent_jump.max(((t1 - t2) - (s1 - s2)).length() / s1.length());
                // Across the edge the crust adds nothing: O's cross derivative is S's.
                let across = |o: DVec3, d: DVec3, c: [f64; 2]| o * -c[1] + d * c[0];
                let x = across(o1.du - o1.surface.du, o1.dv - o1.surface.dv, duv);
                cross = cross.max(x.length() / across(o1.surface.du, o1.surface.dv, duv).length());
                checked += 1;
            }
        }
        eprintln!(
            "{name}: {checked} edge points, position jump {:.2e} x diagonal (surface {:.2e}), \
             tangent derivative jump beyond the surface's {tangent_jump:.2e}, crust cross \
             derivative {cross:.2e} (relative)",
            jump / diag,
            surface_jump / diag
        );
        assert!(jump <= 1e-12 * diag, "{name}: {jump}");
        assert!(tangent_jump <= 1e-10, "{name}: {tangent_jump}");
        assert!(cross <= 1e-12, "{name}: {cross}");
        // The offset's surface is the input's exact limit (through the refined mesh).
        for p in [(0, 0.3, 0.7), (1, 0.5, 0.5), (2, 0.9, 0.1)] {
            let o = offset.evaluate(p.0, p.1, p.2).unwrap();
            let s = base.evaluate(p.0, p.1, p.2).unwrap();
            assert!((o.surface.position - s.position).length() <= 1e-13 * diag);
            assert!((o.surface.du - s.du).length() <= 1e-11 * s.du.length());
        }
    }
}

#[test]
fn bad_input_gives_specific_errors() {
    let mesh = sphere();
    let opts = options(&mesh);
    for c in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = OffsetSurface::new(&mesh, &opts, OffsetSettings::new(c))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("thickness") && e.contains("must be a finite number > 0"),
            "{e}"
        );
    }
    // Beyond the radius of curvature the inward offset folds.
    let e = OffsetSurface::new(&mesh, &opts, OffsetSettings::new(1.2 * R))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("folds at face") && e.contains("(O_u x O_v) . n <= 0"),
        "{e}"
    );
    let accepted = OffsetSettings {
        accept_folds: true,
        ..OffsetSettings::new(1.2 * R)
    };
    let folded = OffsetSurface::new(&mesh, &opts, accepted).unwrap();
    assert!(folded.evaluate(3, 0.5, 0.5).unwrap().folds());
    // A collapsed control mesh: the boundary ring of an open revolution moved to one point
    // has no normal there. (A profile stopping 1e-16 short of the axis would collapse a
    // ring too, but its fit is refused first as ill-conditioned.)
    let open: Vec<[f64; 2]> = vec![[0.5, -R], [1.0, -1.5], [R, 0.0], [1.0, 1.5], [0.0, R]];
    let fitted = revolve::build(&RevolveInput::new(open), &Settings::default()).unwrap();
    let mut parts = fitted.mesh.parts().clone();
    let zmin = parts
        .positions
        .iter()
        .map(|p| p.z)
        .fold(f64::INFINITY, f64::min);
    let ring: Vec<usize> = (0..parts.positions.len())
        .filter(|&i| parts.positions[i].z <= zmin + 1e-9)
        .collect();
    assert!(ring.len() >= 4, "{ring:?}");
    for &i in &ring {
        parts.positions[i] = DVec3::new(0.0, 0.0, zmin);
    }
    let collapsed = Mesh::from_parts(parts).unwrap();
    let e = OffsetSurface::new(&collapsed, &options(&collapsed), OffsetSettings::new(0.1))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains(&format!("vertex {} has no normal", ring[0])),
        "{e}"
    );
}

/// The README's thickness table: min / max / mean thickness over c at L = 0 and at the
/// level a tolerance of 1 % of c chooses, on a sphere, a torus, the bottle, the vase and a
/// creased cube. `cargo test --release --test shell_offset -- --ignored --nocapture`.
#[test]
#[ignore]
fn thickness_table() {
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    // (name, mesh, thickness over the bounding-box diagonal); the sphere's c = 0.05 R.
    let sphere = sphere();
    let f = 0.05 * R / sphere.bounding_box_diagonal();
    let mut models = vec![("sphere (revolution, R = 2)".to_string(), sphere, f)];
    if let Some(dir) = osd_shapes::shapes_dir() {
        let torus = read_obj_file(&dir.join("catmark_torus.obj")).unwrap().mesh;
        models.push(("catmark_torus".into(), torus, 0.02));
    }
    for (name, f) in [
        ("profiles/bottle.obj", 0.005),
        ("profiles/bottle.obj", 0.02),
        ("profiles/vase.obj", 0.01),
        ("meshes/cube_creased.obj", 0.02),
        ("meshes/cube_creased.obj", 0.002),
    ] {
        models.push((
            name.into(),
            read_obj_file(&examples.join(name)).unwrap().mesh,
            f,
        ));
    }
    if let Some(b) = sharp_box() {
        models.push(("sharp box (catmark_cube, all edges sharp)".into(), b, 0.05));
    }
    for (name, mesh, fraction) in &models {
        let c = fraction * mesh.bounding_box_diagonal();
        let opts = options(mesh);
        let at0 = OffsetSurface::new(mesh, &opts, OffsetSettings::new(c)).unwrap();
        let r = measure(&at0, 5).unwrap();
        eprintln!(
            "| {name} | {c:.4} | L = 0 | {:.4} | {:.4} | {:.4} |",
            r.min, r.max, r.mean
        );
        match offset_within(mesh, &opts, OffsetSettings::new(c), 0.01 * c) {
            Ok((_, r)) => eprintln!(
                "| {name} | {c:.4} | t = 1 % c: L = {} | {:.4} | {:.4} | {:.4} |",
                r.level, r.min, r.max, r.mean
            ),
            Err(e) => eprintln!("| {name} | {c:.4} | t = 1 % c | {e} |"),
        }
    }
}

/// A bent plate: the strip `x ∈ [−1, 0]` of the plane `z = 0` and the strip `s ∈ [0, 1]` of
/// the plane through the y axis at angle `turn` from it, on an `8 × 4` grid a side creased
/// infinitely sharp along the y axis. Each side's control points lie in its plane, so its
/// limit surface is that flat strip.
#[allow(clippy::disallowed_methods)] // reference data: the bend's sine and cosine
fn bent_plate(turn: f64) -> Mesh {
    let (nx, ny) = (8usize, 4usize);
    let (sin, cos) = (turn.sin(), turn.cos());
    let mut parts = MeshParts::default();
    for j in 0..=ny {
        for i in 0..=2 * nx {
            let x = i as f64 / nx as f64 - 1.0;
            let y = j as f64 / ny as f64;
            parts.positions.push(if x <= 0.0 {
                DVec3::new(x, y, 0.0)
            } else {
                DVec3::new(x * cos, y, x * sin)
            });
        }
    }
    let id = |i: usize, j: usize| (j * (2 * nx + 1) + i) as u32;
    for j in 0..ny {
        for i in 0..2 * nx {
            parts.face_sizes.push(4);
            parts
                .face_indices
                .extend([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    for j in 0..ny {
        parts.creases.push(Crease {
            vertices: [id(nx, j), id(nx, j + 1)],
            sharpness: SHARPNESS_INFINITE,
        });
    }
    Mesh::from_parts(parts).unwrap()
}

/// The distance from `p` to the bent plate's limit surface (its two flat strips).
#[allow(clippy::disallowed_methods)] // reference data: the bend's sine and cosine
fn distance_to_plate(p: DVec3, turn: f64) -> f64 {
    let flat = DVec3::new(p.x.clamp(-1.0, 0.0), p.y.clamp(0.0, 1.0), 0.0);
    let axis = DVec3::new(turn.cos(), 0.0, turn.sin());
    let along = p.dot(axis).clamp(0.0, 1.0);
    let bent = axis * along + DVec3::new(0.0, p.y.clamp(0.0, 1.0), 0.0);
    (p - flat).length().min((p - bent).length())
}

/// Next to a crease the mitered corner vector moves the inner wall sideways by
/// `c tan(θ/2)`; feathered into the crease's neighbours (corners.rs) the crust no longer
/// folds where faces are narrower than that. On a bent plate the offset toward the convex
/// side is then exactly the true offset: `c` from both flat sides at every point (the two
/// walls meet on the miter line), at every level and for a thickness several faces wide.
#[test]
fn mitered_creases_do_not_fold_on_fine_crusts() {
    for turn_deg in [45.0f64, 90.0, 120.0] {
        let turn = turn_deg.to_radians();
        let mesh = bent_plate(turn);
        let opts = options(&mesh);
        // Level 3: faces 1/64 wide; the miter reaches c tan(θ/2) = 0.04 to 0.26 sideways,
        // and is feathered over three times that (within each 1-wide side).
        let thick = if turn_deg > 100.0 { 0.15 } else { 0.2 };
        for (level, c) in [(0, 0.1), (2, 0.1), (3, thick)] {
            // S_u × S_v is +z on the flat side: outward is the convex side of the bend.
            let settings = OffsetSettings {
                side: Side::Outward,
                level,
                ..OffsetSettings::new(c)
            };
            let offset = OffsetSurface::new(&mesh, &opts, settings)
                .unwrap_or_else(|e| panic!("{turn_deg}° level {level} c {c}: {e}"));
            let (mut worst, mut slope) = (0.0f64, f64::INFINITY);
            let n = 24;
            for f in 0..offset.num_parametric_faces() {
                for i in 0..=n {
                    for j in 0..=n {
                        let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                        let o = offset.evaluate(f, u, v).unwrap();
                        assert!(!o.folds(), "{turn_deg}° level {level}: face {f} ({u}, {v})");
                        worst = worst.max((distance_to_plate(o.position, turn) - c).abs());
                        // How much of the surface's stretch across the crease (u) is left.
                        slope = slope.min(o.du.dot(o.surface.du) / o.surface.du.length_squared());
                    }
                }
            }
            eprintln!(
                "bent plate {turn_deg}°, level {level}, c = {c}: max |distance - c| = \
                 {worst:.2e}, smallest O_u . S_u / |S_u|^2 = {slope:.3}"
            );
            assert!(worst <= 1e-12, "{turn_deg}° level {level}: {worst}");
            assert!(slope > 0.2, "{turn_deg}° level {level}: {slope}");
        }
    }
}

/// Whether vertex `v` of `mesh` is regular and smooth: four faces around it, not on the
/// boundary, no crease edge or corner tag.
fn regular_smooth(mesh: &Mesh, sides: &std::collections::HashSet<(u32, u32)>, v: u32) -> bool {
    let out: Vec<u32> = sides.iter().filter(|s| s.0 == v).map(|s| s.1).collect();
    out.len() == 4
        && out.iter().all(|&w| sides.contains(&(w, v)))
        && !mesh
            .parts()
            .creases
            .iter()
            .any(|c| c.sharpness > 0.0 && c.vertices.contains(&v))
        && !mesh.parts().corners.iter().any(|c| c.vertex == v)
}

/// The unit step into a quad from its side `k`, in its `(u, v)`.
fn inward(k: usize) -> [f64; 2] {
    [[0.0, 1.0], [-1.0, 0.0], [0.0, -1.0], [1.0, 0.0]][k]
}

/// Across the edge between two quads whose four end vertices are regular, O is C² as S is:
/// second derivatives across the edge (and the mixed one, along then across) from both
/// sides, by second-order one-sided differences of the first derivatives at steps h, 2h
/// into each face. Reported relative to the largest second derivative; the offset's
/// jumps are the surface's (the difference error), the crust adding nothing.
#[test]
fn offset_is_c2_across_edges_between_regular_vertices() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let shapes = [
        ("sphere", sphere(), 0.05 * R),
        (
            "catmark_torus",
            read_obj_file(&dir.join("catmark_torus.obj")).unwrap().mesh,
            0.02,
        ),
        (
            "bottle",
            read_obj_file(&examples.join("profiles/bottle.obj"))
                .unwrap()
                .mesh,
            0.02,
        ),
        (
            "vase",
            read_obj_file(&examples.join("profiles/vase.obj"))
                .unwrap()
                .mesh,
            0.02,
        ),
    ];
    let h = 1e-4;
    for (name, mesh, fraction) in &shapes {
        let opts = options(mesh);
        let diag = mesh.bounding_box_diagonal();
        let c = if *name == "sphere" {
            *fraction
        } else {
            fraction * diag
        };
        let offset = OffsetSurface::new(mesh, &opts, OffsetSettings::new(c)).unwrap();
        let base = Evaluator::new(mesh, &opts).unwrap();
        let ptex = base.ptex_faces();
        let mut sides = std::collections::HashMap::new();
        for f in 0..mesh.num_faces() {
            let face = mesh.face(f);
            for k in 0..face.len() {
                sides.insert((face[k], face[(k + 1) % face.len()]), (f, k));
            }
        }
        let keys: std::collections::HashSet<(u32, u32)> = sides.keys().copied().collect();
        // The second derivative across side k of face f at t, and the mixed one.
        let seconds = |f: usize, k: usize, t: f64| {
            let (pf, u, v, along) = side_point(mesh, ptex.first_of(f), f, k, t);
            let n = inward(k);
            let at = |step: f64| {
                let o = offset
                    .evaluate(pf, u + step * n[0], v + step * n[1])
                    .unwrap();
                let d = |du: DVec3, dv: DVec3, w: [f64; 2]| du * w[0] + dv * w[1];
                (
                    d(o.du, o.dv, n),
                    d(o.du, o.dv, along),
                    d(o.surface.du, o.surface.dv, n),
                    d(o.surface.du, o.surface.dv, along),
                )
            };
            let (a, b, c) = (at(0.0), at(h), at(2.0 * h));
            let diff = |x: DVec3, y: DVec3, z: DVec3| (x * -3.0 + y * 4.0 - z) / (2.0 * h);
            [
                diff(a.0, b.0, c.0),
                diff(a.1, b.1, c.1),
                diff(a.2, b.2, c.2),
                diff(a.3, b.3, c.3),
            ]
        };
        let (mut jump, mut surface_jump, mut largest, mut edges) = (0.0f64, 0.0f64, 0.0f64, 0);
        for (&(a, b), &(f, k)) in &sides {
            let Some(&(g, l)) = sides.get(&(b, a)) else {
                continue;
            };
            let quads = mesh.face(f).len() == 4 && mesh.face(g).len() == 4;
            let ends = [mesh.face(f), mesh.face(g)]
                .iter()
                .flat_map(|face| face.iter().copied())
                .all(|v| regular_smooth(mesh, &keys, v));
            if a > b || !quads || !ends {
                continue;
            }
            edges += 1;
            for i in 1..8 {
                let t = i as f64 / 8.0;
                let one = seconds(f, k, t);
                let two = seconds(g, l, 1.0 - t);
                for q in 0..2 {
                    jump = jump.max((one[q] - two[q]).length());
                    surface_jump = surface_jump.max((one[q + 2] - two[q + 2]).length());
                    largest = largest.max(one[q].length()).max(one[q + 2].length());
                }
            }
        }
        eprintln!(
            "{name}: {edges} edges between regular vertices, second derivative jump across \
             them {:.2e} (surface {:.2e}) of the largest second derivative, h = {h}",
            jump / largest,
            surface_jump / largest
        );
        assert!(edges > 0, "{name}");
        assert!(
            jump <= surface_jump + 1e-6 * largest,
            "{name}: {jump} {surface_jump}"
        );
        assert!(jump <= 1e-5 * largest, "{name}: {jump} vs {largest}");
    }
}

/// catmark_cube with every edge infinitely sharp: the limit is the box itself, every vertex
/// a corner of three sectors.
fn sharp_box() -> Option<Mesh> {
    let dir = osd_shapes::shapes_dir()?;
    let mut parts = read_obj_file(&dir.join("catmark_cube.obj"))
        .unwrap()
        .mesh
        .parts()
        .clone();
    let mut edges = std::collections::BTreeSet::new();
    for face in parts.face_indices.chunks(4) {
        for k in 0..4 {
            let (a, b) = (face[k], face[(k + 1) % 4]);
            edges.insert((a.min(b), a.max(b)));
        }
    }
    parts.creases = edges
        .into_iter()
        .map(|(a, b)| Crease {
            vertices: [a, b],
            sharpness: SHARPNESS_INFINITE,
        })
        .collect();
    Some(Mesh::from_parts(parts).unwrap())
}

/// A box with every edge infinitely sharp: the offset is the inner box, `c` from the walls
/// to 1e-10 c at every lattice point and level, with the corners' miters feathered along
/// both walls and the creases (corners.rs): at c = 0.2 the level-3 crust's faces (1/4 wide)
/// are narrower than the corner miter's sideways reach (c √2 = 0.28), which folded before.
#[test]
fn sharp_box_offsets_exactly_next_to_its_corners_at_every_level() {
    let Some(mesh) = sharp_box() else { return };
    let opts = options(&mesh);
    for (c, levels) in [(0.05, 0..=3), (0.2, 0..=3)] {
        for level in levels {
            let settings = OffsetSettings {
                level,
                ..OffsetSettings::new(c)
            };
            let offset = OffsetSurface::new(&mesh, &opts, settings)
                .unwrap_or_else(|e| panic!("c = {c}, level {level}: {e}"));
            let r = measure(&offset, 5).unwrap();
            // The inner box: every coordinate within [c − 1, 1 − c] (side 2 about 0).
            let n = 8;
            let mut outside = 0.0f64;
            for f in 0..offset.num_parametric_faces() {
                for i in 0..=n {
                    for j in 0..=n {
                        let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                        let p = offset.evaluate(f, u, v).unwrap().position;
                        // catmark_cube is turned by 45° about z.
                        let q = DVec3::new(p.x + p.y, p.y - p.x, p.z * 2f64.sqrt());
                        let over = q.abs().max_element() / 2f64.sqrt() - (1.0 - c);
                        outside = outside.max(over);
                    }
                }
            }
            eprintln!(
                "sharp box (side 2), c = {c}, level {level}: thickness / c min {:.15} max \
                 {:.15}, largest coordinate beyond the inner box {outside:.2e}",
                r.min, r.max
            );
            assert!(
                (r.min - 1.0).abs() < 1e-10 && (r.max - 1.0).abs() < 1e-10,
                "c = {c}, level {level}: {r:?}"
            );
            // (The OBJ gives the corners to 6 decimals.)
            assert!(outside < 1e-6, "c = {c}, level {level}: {outside}");
        }
    }
    // At c = 0.3 the corners' feathering reach (3 √2 c = 1.27) is more than half a side:
    // the feathering of opposite walls overlaps, the level-3 crust folds, and the refusal
    // names the crease or corner vertex next to the fold.
    let settings = OffsetSettings {
        level: 3,
        ..OffsetSettings::new(0.3)
    };
    let e = OffsetSurface::new(&mesh, &opts, settings).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("folds at face")
            && m.contains("next to the crease or corner at vertex")
            && m.contains("of the mesh refined 3 times")),
        "{e:?}"
    );
}

/// Batches: on any thread count the same bits as point by point; the surface part of a
/// sample is the evaluator's exactly (the leaf patch kept beside the crust is the
/// evaluator's); errors keep their kind and name the lowest failing point.
#[test]
fn batches_match_points_on_any_thread_count_and_keep_error_kinds() {
    let mesh = sphere();
    let opts = options(&mesh);
    for level in [0, 2] {
        let settings = OffsetSettings {
            level,
            ..OffsetSettings::new(0.05 * R)
        };
        let mut offset = OffsetSurface::new(&mesh, &opts, settings).unwrap();
        let n = 3000;
        let faces: Vec<u32> = (0..n)
            .map(|i| (i * 7919) as u32 % offset.num_parametric_faces())
            .collect();
        let u: Vec<f64> = (0..n)
            .map(|i| (i as f64 * 0.618_033_988_75).fract())
            .collect();
        let v: Vec<f64> = (0..n)
            .map(|i| (i as f64 * 0.414_213_562_37).fract())
            .collect();
        let mut runs = Vec::new();
        for threads in [1, 2, 0] {
            offset.set_threads(threads);
            runs.push(
                offset
                    .evaluate_points(Domain::Ptex, &faces, &u, &v)
                    .unwrap(),
            );
        }
        assert!(runs.iter().all(|r| *r == runs[0]), "level {level}");
        let base = Evaluator::new(&mesh, &opts).unwrap();
        for i in 0..n {
            let one = offset.evaluate(faces[i], u[i], v[i]).unwrap();
            assert_eq!(runs[0][i], Some(one), "level {level}, point {i}");
            let (g, s, t, scale) = offset.locate(faces[i], u[i], v[i]).unwrap();
            let fine = offset.fine().evaluate(g, s, t).unwrap();
            assert_eq!(one.surface.position, fine.position);
            assert_eq!(one.surface.du, fine.du * scale);
            // Through the refined mesh, the input's limit.
            let b = base.evaluate(faces[i], u[i], v[i]).unwrap();
            assert!((one.surface.position - b.position).length() < 1e-13 * R);
        }
        // Errors: the lowest bad point, named, its kind kept.
        let mut bad_u = u.clone();
        bad_u[2500] = 1.5;
        bad_u[1700] = f64::NAN;
        for threads in [1, 2] {
            offset.set_threads(threads);
            let e = offset
                .evaluate_points(Domain::Ptex, &faces, &bad_u, &v)
                .unwrap_err();
            assert!(
                matches!(&e, Error::InvalidArgument(m) if m.starts_with("point 1700: ")),
                "{e:?}"
            );
        }
        let e = offset
            .evaluate_points(Domain::Ptex, &faces, &u[1..], &v)
            .unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("same length")),
            "{e:?}"
        );
    }
}

/// A non-manifold mesh (three quads on one edge) is refused as such.
#[test]
fn a_non_manifold_mesh_is_refused_as_non_manifold() {
    let parts = MeshParts {
        positions: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(-1.0, 1.0, 0.0),
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(0.0, 1.0, 1.0),
        ],
        face_sizes: vec![4, 4, 4],
        face_indices: vec![0, 2, 3, 1, 1, 5, 4, 0, 0, 6, 7, 1],
        ..MeshParts::default()
    };
    let mesh = Mesh::from_parts(parts).unwrap();
    let e = OffsetSurface::new(&mesh, &options(&mesh), OffsetSettings::new(0.1)).unwrap_err();
    assert!(
        matches!(&e, Error::NonManifold(m) if m.contains("an offset needs a manifold mesh")),
        "{e:?}"
    );
}

/// A tolerance no crust level meets is a numerical failure (the procedure did not reach it),
/// naming the error reached at each level; a bad tolerance is an invalid argument.
#[test]
fn an_unmet_tolerance_is_a_numerical_failure() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mesh = read_obj_file(&dir.join("catmark_cube.obj")).unwrap().mesh;
    let opts = options(&mesh);
    let c = 0.02 * mesh.bounding_box_diagonal();
    let e = offset_within(&mesh, &opts, OffsetSettings::new(c), 1e-13 * c).unwrap_err();
    assert!(
        matches!(&e, Error::NumericalFailure(m)
            if m.contains("no crust level keeps the thickness") && m.contains("level 6: ")),
        "{e:?}"
    );
    for t in [0.0, -1.0, f64::NAN] {
        let e = offset_within(&mesh, &opts, OffsetSettings::new(c), t).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("tolerance")),
            "{e:?}"
        );
    }
}
