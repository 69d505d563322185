//! Hollow solids (`construct::shell::build`): an open vase and a closed bottle give closed,
//! consistently oriented quad manifolds whose enclosed volume is the wall's area times the
//! thickness, and whose limit passes through the outer limit and the offset at every vertex.

use std::path::Path;

#[path = "support/self_intersection.rs"]
mod self_intersection;

use glam::DVec3;
use profsubd::construct::shell::{build, OffsetSettings, OffsetSurface, ShellInput};
use profsubd::eval::{limit_vertex_samples, Evaluator};
use profsubd::io::obj::read_obj_file;
use profsubd::mesh::validate::check;
use profsubd::tessellate::{tessellate, Rate, TessellateOptions};
use profsubd::{Mesh, Settings};

fn example(name: &str) -> Mesh {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name);
    read_obj_file(&path).unwrap().mesh
}

/// `mesh`'s limit surface tessellated at `rate` a face: positions and triangles.
fn triangles(mesh: &Mesh, rate: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let ev = Evaluator::new(mesh, &mesh.options().resolve()).unwrap();
    let options = TessellateOptions {
        rate: Rate::Uniform(rate),
        ..TessellateOptions::default()
    };
    let t = tessellate(&ev, &options).unwrap();
    let tris = t.triangles();
    (t.positions, tris)
}

/// Signed volume and area of `mesh`'s limit surface, tessellated at `rate` a face.
fn volume_and_area(mesh: &Mesh, rate: u32) -> (f64, f64) {
    let ev = Evaluator::new(mesh, &mesh.options().resolve()).unwrap();
    let options = TessellateOptions {
        rate: Rate::Uniform(rate),
        ..TessellateOptions::default()
    };
    let t = tessellate(&ev, &options).unwrap();
    let (mut volume, mut area) = (0.0, 0.0);
    for [a, b, c] in t.triangles() {
        let [a, b, c]: [DVec3; 3] = [a, b, c].map(|i| t.positions[i as usize]);
        volume += a.dot(b.cross(c)) / 6.0;
        area += (b - a).cross(c - a).length() / 2.0;
    }
    (volume, area)
}

#[test]
fn shells_of_an_open_vase_and_a_closed_bottle() {
    // (file, thickness as a fraction of the diagonal, Euler characteristic of the solid)
    for (name, fraction, euler) in [
        ("profiles/vase.obj", 0.01, 2),
        ("profiles/bottle.obj", 0.005, 4),
    ] {
        let mesh = example(name);
        let c = fraction * mesh.bounding_box_diagonal();
        let input = ShellInput {
            mesh: mesh.clone(),
            offset: OffsetSettings::new(c),
            tolerance: None,
        };
        let solid = build(&input, &Settings::default()).unwrap();
        let report = check(&solid.mesh);
        assert!(
            report.is_manifold() && report.is_closed(),
            "{name}: {report:?}"
        );
        assert!(report.is_consistently_oriented(), "{name}");
        assert!(report.boundary_edges.is_empty());
        assert_eq!(report.euler_characteristic, euler, "{name}");
        assert!(solid.mesh.face_sizes().iter().all(|&n| n == 4));
        // Outward orientation: the solid encloses volume outer − inner ≈ area × c.
        let (volume, _) = volume_and_area(&solid.mesh, 4);
        let (_, area) = volume_and_area(&mesh, 4);
        eprintln!(
            "{name}: c = {c:.4}, solid volume {volume:.5}, wall area x c {:.5}, ratio {:.4}, \
             fit residual {:.2e}",
            area * c,
            volume / (area * c),
            solid.fit.residual
        );
        assert!(volume > 0.0, "{name}: {volume}");
        assert!(
            (volume / (area * c) - 1.0).abs() < 0.05,
            "{name}: {volume} vs {}",
            area * c
        );
        // The solid's limit at every vertex is its target: the outer wall's limit and the
        // offset there.
        let limits = limit_vertex_samples(&solid.mesh, &solid.mesh.options().resolve()).unwrap();
        let diag = solid.mesh.bounding_box_diagonal();
        for (l, t) in limits.iter().zip(&solid.targets) {
            assert!((l.position - *t).length() <= 1e-10 * diag);
        }
        let offset =
            OffsetSurface::new(&mesh, &mesh.options().resolve(), OffsetSettings::new(c)).unwrap();
        let n = mesh.num_vertices();
        let outer = limit_vertex_samples(&mesh, &mesh.options().resolve()).unwrap();
        for (v, limit) in outer.iter().enumerate() {
            assert!((solid.targets[v] - limit.position).length() <= 1e-12 * diag);
            let inner = limit.position - offset.corner_vectors()[v];
            assert!((solid.targets[n + v] - inner).length() <= 1e-12 * diag);
        }
    }
}

/// No self-intersection: the limit surface of each solid, tessellated at 6 × 6 quads an
/// input face
/// (split into triangles), has no two triangles sharing no vertex in contact
/// (support/self_intersection.rs: grid, separating axes), at the paper's level and at the
/// level a tolerance of 1 % of c chooses, and with a thickness several refined faces wide
/// next to the creases (feathered miters). The check itself finds the contacts of the
/// vase's shell overlapping a copy of itself moved by c / 3.
#[test]
fn shells_do_not_intersect_themselves() {
    for (name, fraction, tolerance) in [
        ("profiles/vase.obj", 0.01, false),
        ("profiles/vase.obj", 0.01, true),
        ("profiles/bottle.obj", 0.005, false),
        ("profiles/bottle.obj", 0.005, true),
        ("profiles/bottle.obj", 0.02, false),
    ] {
        let mesh = example(name);
        let c = fraction * mesh.bounding_box_diagonal();
        let input = ShellInput {
            mesh,
            offset: OffsetSettings::new(c),
            tolerance: tolerance.then_some(0.01 * c),
        };
        let level = input.offset().unwrap().0.settings().level;
        let solid = build(&input, &Settings::default()).unwrap();
        // About the same density at every level: the solid has 4^level faces a face.
        let (positions, tris) = triangles(&solid.mesh, (6 >> level).max(2));
        let found = self_intersection::self_intersections(&positions, &tris);
        eprintln!(
            "{name}, c = {fraction} x diagonal{}, level {level}: {} triangles, {} pairs tested, {} in \
             contact, smallest gap {:.3e} ({:.3} c)",
            if tolerance { ", tolerance 1 % c" } else { "" },
            found.triangles,
            found.pairs_tested,
            found.intersecting,
            found.smallest_gap,
            found.smallest_gap / c
        );
        assert_eq!(found.intersecting, 0, "{name}");
        assert!(found.pairs_tested > 0, "{name}: {found:?}");
        if name == "profiles/vase.obj" && !tolerance {
            // The check finds contacts: the shell and a copy moved by c / 3.
            let n = positions.len() as u32;
            let mut both = positions.clone();
            both.extend(positions.iter().map(|p| *p + DVec3::splat(c / 3.0)));
            let mut pairs = tris.clone();
            pairs.extend(tris.iter().map(|t| t.map(|v| v + n)));
            let overlap = self_intersection::self_intersections(&both, &pairs);
            assert!(overlap.intersecting > 100, "{overlap:?}");
        }
    }
}
