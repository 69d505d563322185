//! The (face, u, v) evaluator against the exact limit of deeply refined vertices, levels 1-6.
//!
//! Reference: refine the mesh uniformly to level `L` with `refine::refine_uniform` (bit for
//! bit OpenSubdiv's `Far::PrimvarRefinerReal<double>`), then take the limit of the level-`L`
//! face point of each level-`(L-1)` face. A face point is a smooth vertex whose incident
//! edges are smooth, at every later level too, so its limit is the smooth limit mask
//! `(n² v + 4 Σ e + Σ f) / (n (n + 5))` applied to its level-`L` one-ring, whatever sharpness
//! surrounds it. That vertex is the limit surface at the centre of the sub-square of the base
//! face that the level-`(L-1)` face covers (child quad `j` keeps its parent's corner `j` at
//! position `j`; a non-quad's level-1 children are its Ptex sub-faces).
//!
//! Under Chaikin creasing an edge point's rule depends on the sharpness of every edge around
//! both ends of its edge, so a neighbourhood that misses some of the edges around a vertex
//! next to the face gets that point wrong a few levels down: these shapes caught it.

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use glam::DVec3;
use profsubd::eval::Evaluator;
use profsubd::io::obj::read_obj_file;
use profsubd::refine::refine_uniform;
use profsubd::{CreaseMethod, Mesh, SubdivOptions};

/// Ptex face and the lower-left corner and size of the region of a level-`level` face.
fn region(base: &Mesh, ev: &Evaluator, level: u32, mut g: u32) -> (u32, f64, f64, f64) {
    let (mut u0, mut v0, mut size) = (0.0, 0.0, 1.0);
    let mut quadrants = Vec::new();
    for _ in 1..level {
        quadrants.push(g % 4);
        g /= 4;
    }
    // `g` is now a level-1 face: child `j` of base face `f`.
    let offsets = base.face_offsets();
    let f = offsets.partition_point(|&o| o <= g) - 1;
    let j = g - offsets[f];
    let ptex = if base.face_sizes()[f] == 4 {
        quadrants.push(j);
        ev.ptex_faces().first_of(f)
    } else {
        ev.ptex_faces().first_of(f) + j
    };
    for &q in quadrants.iter().rev() {
        size *= 0.5;
        if q == 1 || q == 2 {
            u0 += size;
        }
        if q == 2 || q == 3 {
            v0 += size;
        }
    }
    (ptex, u0, v0, size)
}

/// Smooth limit of the face point `w` of `refined` (valence = the parent face's size).
fn face_point_limit(refined: &Mesh, faces: &[u32], w: u32) -> DVec3 {
    let p = refined.positions();
    let n = faces.len() as f64;
    let mut sum = n * n * p[w as usize];
    for &g in faces {
        let face = refined.face(g as usize);
        let k = face.iter().position(|&x| x == w).expect("w in its face");
        // Each edge end is seen from two faces: half of 4 from each.
        sum += 2.0 * p[face[(k + 1) % 4] as usize] + 2.0 * p[face[(k + 3) % 4] as usize];
        sum += p[face[(k + 2) % 4] as usize];
    }
    sum / (n * (n + 5.0))
}

/// Largest distance / diagonal between the evaluator and the face-point limits of level
/// `level`, at most `cap` points (faces of level `level - 1` taken at a regular stride).
fn worst_at_level(mesh: &Mesh, options: &SubdivOptions, level: u32, cap: usize) -> (f64, usize) {
    let ev = Evaluator::new(mesh, options).unwrap();
    let parent = refine_uniform(mesh, options, level - 1).unwrap();
    let refined = refine_uniform(mesh, options, level).unwrap();
    let mut faces_of = vec![Vec::new(); refined.num_vertices()];
    for f in 0..refined.num_faces() {
        for &v in refined.face(f) {
            faces_of[v as usize].push(f as u32);
        }
    }
    let diag = mesh.bounding_box_diagonal();
    let stride = parent.num_faces().div_ceil(cap).max(1);
    let (mut worst, mut count) = (0.0f64, 0usize);
    for g in (0..parent.num_faces() as u32).step_by(stride) {
        // Child 0 of any face holds the face point at its position 2.
        let child = parent.face_offsets()[g as usize];
        let w = refined.face(child as usize)[2];
        let (ptex, u0, v0, size) = if level == 1 {
            let f = g as usize;
            if mesh.face_sizes()[f] == 4 {
                (ev.ptex_faces().first_of(f), 0.0, 0.0, 1.0)
            } else {
                // A non-quad's face point is the (1, 1) corner of each of its sub-faces.
                (ev.ptex_faces().first_of(f), 0.0, 0.0, 2.0)
            }
        } else {
            region(mesh, &ev, level - 1, g)
        };
        let Ok(got) = ev.evaluate(ptex, u0 + 0.5 * size, v0 + 0.5 * size) else {
            continue; // hole or no surface
        };
        let want = face_point_limit(&refined, &faces_of[w as usize], w);
        worst = worst.max((got.position - want).length() / diag);
        count += 1;
    }
    (worst, count)
}

#[test]
fn chaikin_shapes_match_deep_refinement() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mut failures = Vec::new();
    for name in [
        "catmark_cube_creases1",
        "catmark_cubes_semisharp",
        "catmark_chaikin0",
        "catmark_chaikin1",
        "catmark_chaikin2",
    ] {
        let mesh = read_obj_file(&dir.join(format!("{name}.obj")))
            .unwrap()
            .mesh;
        for crease_method in [CreaseMethod::Chaikin, CreaseMethod::Uniform] {
            let options = SubdivOptions {
                crease_method,
                ..mesh.options().resolve()
            };
            for level in 1..=6 {
                let (worst, count) = worst_at_level(&mesh, &options, level, 4000);
                eprintln!("{name} {crease_method:?} L={level}: {count} points, worst {worst:.2e}");
                assert!(count > 0);
                if worst > 1e-12 {
                    failures.push(format!(
                        "{name} {crease_method:?} level {level}: {worst:.2e}"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn every_shape_matches_deep_refinement() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let rows = osd_shapes::index(&dir);
    let (mut failures, mut compared, mut worst) = (Vec::new(), 0usize, 0.0f64);
    for row in &rows {
        let mesh = read_obj_file(&row.path).unwrap().mesh;
        // Faces that repeat a vertex: exact only outside a small neighbourhood of that vertex
        // (see `Evaluator`), not compared here.
        let degenerate = (0..mesh.num_faces()).any(|f| {
            let face = mesh.face(f);
            (0..face.len()).any(|i| face[i + 1..].contains(&face[i]))
        });
        if degenerate {
            continue;
        }
        for crease_method in [CreaseMethod::Chaikin, CreaseMethod::Uniform] {
            let options = SubdivOptions {
                crease_method,
                ..mesh.options().resolve()
            };
            let mut level = 1;
            // Deepest level with at most ~120,000 refined faces.
            while level <= 6 && mesh.face_indices().len() << (2 * (level - 1)) <= 120_000 {
                let (w, count) = worst_at_level(&mesh, &options, level, 150);
                compared += count;
                worst = worst.max(w);
                if w > 1e-12 {
                    failures.push(format!(
                        "{} {crease_method:?} level {level}: {w:.2e}",
                        row.name
                    ));
                }
                level += 1;
            }
        }
    }
    eprintln!("{compared} face points of levels 1-6, worst {worst:.2e} x diagonal");
    assert!(compared > 50_000, "{compared}");
    assert!(failures.is_empty(), "{failures:#?}");
}

/// A perturbed 6 x 6 grid whose every interior edge is semi-sharp with its own fractional
/// sharpness: every vertex averages three or four different values under Chaikin's rule, a
/// sum in `f32` whose last bits depend on where the order round the vertex starts (a
/// fragment that started elsewhere than Far was 6.4e-10 x diagonal off).
fn semi_sharp_grid() -> Mesh {
    let n = 6u32;
    let id = |i: u32, j: u32| j * (n + 1) + i;
    let mut parts = profsubd::MeshParts::default();
    for j in 0..=n {
        for i in 0..=n {
            let h = ((i * 7 + j * 11) % 5) as f64 * 0.13;
            parts
                .positions
                .push(DVec3::new(i as f64 + 0.05 * h, j as f64 - 0.03 * h, h));
        }
    }
    for j in 0..n {
        for i in 0..n {
            parts.face_sizes.push(4);
            parts
                .face_indices
                .extend([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    let mut k = 0u32;
    for j in 1..n {
        for i in 0..n {
            for [a, b] in [[id(i, j), id(i + 1, j)], [id(j, i), id(j, i + 1)]] {
                k += 1;
                parts.creases.push(profsubd::Crease {
                    vertices: [a, b],
                    sharpness: 0.3 + ((k * 37) % 29) as f32 * 0.1173,
                });
            }
        }
    }
    Mesh::from_parts(parts).unwrap()
}

#[test]
fn fractional_sharpness_everywhere_matches_deep_refinement() {
    let mesh = semi_sharp_grid();
    for crease_method in [CreaseMethod::Chaikin, CreaseMethod::Uniform] {
        let options = SubdivOptions {
            crease_method,
            ..SubdivOptions::default()
        };
        for level in 1..=6 {
            let (worst, count) = worst_at_level(&mesh, &options, level, 3000);
            eprintln!("{crease_method:?} L={level}: {count} points, worst {worst:.2e}");
            assert!(count > 0);
            assert!(
                worst <= 1e-12,
                "{crease_method:?} level {level}: {worst:.2e} x diagonal"
            );
        }
    }
}
