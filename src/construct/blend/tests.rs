// Reference data (pipe directions round a circle) may use the platform's sin and cos.
#![allow(clippy::disallowed_methods)]

use std::f64::consts::TAU;

use glam::DVec3;

use super::{control_mesh, BlendInput, BlendMesh, Pipe};
use crate::gbs::rules::circle_factor;
use crate::gbs::{limit::limit_points, refine_gbs, GbsOptions};
use crate::mesh::{Mesh, MeshParts};
use crate::topology::Level;
use crate::Error;

/// N pipes of radius 1 in the xy-plane, evenly spread, ends `dist` from the origin.
fn star(n: usize, dist: f64) -> Vec<Pipe> {
    (0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64 + 0.1;
            let d = DVec3::new(a.cos(), a.sin(), 0.0);
            Pipe {
                end: d * dist,
                axis: d,
                radius: 1.0,
                length: 4.0,
            }
        })
        .collect()
}

/// A T-junction: a pipe of radius 1 along x through the junction and one of radius 0.6
/// along y.
fn tee() -> Vec<Pipe> {
    let pipe = |axis: DVec3, radius| Pipe {
        end: axis * 2.0,
        axis,
        radius,
        length: 4.0,
    };
    vec![
        pipe(DVec3::X, 1.0),
        pipe(-DVec3::X, 1.0),
        pipe(DVec3::Y, 0.6),
    ]
}

fn cases() -> Vec<(String, Vec<Pipe>)> {
    let mut v: Vec<(String, Vec<Pipe>)> = (3..=8)
        .map(|n| {
            (
                format!("{n}-way"),
                star(n, 1.2 / (std::f64::consts::PI / n as f64).sin()),
            )
        })
        .collect();
    v.push(("tee".into(), tee()));
    v
}

#[test]
fn blends_are_oriented_manifolds_of_low_valence() {
    for (name, pipes) in cases() {
        for columns in [3, 4, 5, 6, 8] {
            for order in [3, 4, 5, 6] {
                let input = BlendInput {
                    order,
                    columns,
                    ..BlendInput::new(pipes.clone())
                };
                let b = control_mesh(&input).unwrap_or_else(|e| panic!("{name}: {e}"));
                let level = Level::from_mesh(&b.mesh);
                let n = pipes.len();
                let what = format!("{name} n={columns} k={order}");
                let mut boundary = 0;
                for e in 0..level.num_edges() {
                    // Consistent orientation: an edge used twice the same way is non-manifold.
                    assert!(!level.is_edge_non_manifold(e), "{what} edge {e}");
                    boundary += level.is_edge_boundary(e) as usize;
                }
                // The only boundaries are the pipes' free ends.
                assert_eq!(boundary, columns * n, "{what}");
                assert!((0..level.num_vertices()).all(|v| !level.is_vertex_non_manifold(v)));
                let valence = |v: usize| level.valence(v);
                let centres: Vec<usize> = b.centre_vertices().map(valence).collect();
                let valleys: Vec<usize> = b.valley_vertices().map(valence).collect();
                let apexes: Vec<usize> = b.apex_vertices().map(valence).collect();
                assert_eq!(valleys.len(), n * ((columns - 1) / 2 + 1), "{what}");
                // Centres 4 (3 under an odd ring's bottom vertices), one more on a fan's
                // spokes; apexes ⌈N/2⌉; valleys 3 or 4.
                let fan = n >= super::hub::FAN_FROM;
                let bottom = if columns % 2 == 1 { 3 } else { 4 };
                for (i, &c) in centres.iter().enumerate() {
                    let plain = if i < n { 4 } else { bottom };
                    assert!(c == plain || (fan && c == plain + 1), "{what}: {centres:?}");
                }
                assert_eq!(apexes, vec![n.div_ceil(2); 2 * fan as usize], "{what}");
                assert!(valleys.iter().all(|&x| x == 3 || x == 4), "{what}");
                // Every hub vertex is one of those.
                assert_eq!(b.apex_vertices().end, level.num_vertices());
                let max = (0..level.num_vertices()).map(valence).max();
                assert_eq!(max, Some(5), "{what}");
                let mut sizes: Vec<usize> = (0..level.num_faces())
                    .map(|f| level.face_vertices(f).len())
                    .collect();
                sizes.sort();
                sizes.dedup();
                // Quads, the centre triangle (N odd) and (odd n) the pentagons.
                let mut want = vec![4];
                if n % 2 == 1 {
                    want.push(3);
                }
                if columns % 2 == 1 {
                    want.push(5);
                }
                want.sort();
                assert_eq!(sizes, want, "{what}");
                // No valence grows with N, at any level: at most 5 edges per vertex (even
                // orders' quad split), at most 5 sides per face (odd orders' Doo–Sabin split,
                // whose faces stand for vertices), so no vertex of valence N for N ≥ 6.
                for levels in 1..=2 {
                    let l = refine_gbs(&b.mesh, &input.gbs_options(), levels)
                        .unwrap()
                        .level;
                    let most = if order % 2 == 0 {
                        (0..l.num_vertices()).map(|v| l.valence(v)).max()
                    } else {
                        (0..l.num_faces()).map(|f| l.face_vertices(f).len()).max()
                    };
                    assert_eq!(most, Some(5), "{what} level {levels}");
                }
                let refined = refine_gbs(&b.mesh, &input.gbs_options(), 2).unwrap();
                let l2 = &refined.level;
                assert!((0..l2.num_edges()).all(|e| !l2.is_edge_non_manifold(e)));
            }
        }
    }
}

/// The mesh with the positions replaced by (is a hub vertex, pipe number, 0).
fn indicator(b: &BlendMesh) -> Mesh {
    let mut parts: MeshParts = b.mesh.parts().clone();
    parts.positions = (0..parts.positions.len())
        .map(|v| {
            let pipe = b
                .pipes
                .iter()
                .rposition(|p| p.first_vertex <= v)
                .unwrap_or(0);
            DVec3::new((v >= b.first_hub_vertex) as u8 as f64, pipe as f64, 0.0)
        })
        .collect();
    Mesh::from_parts(parts).unwrap()
}

#[test]
fn pipes_stay_exact_away_from_the_hub() {
    let mut runs: Vec<(String, Vec<Pipe>, usize)> =
        cases().into_iter().map(|(n, p)| (n, p, 4)).collect();
    for (name, pipes) in cases().into_iter().take(4) {
        runs.extend([3, 5, 6, 8].map(|c| (format!("{name} n={c}"), pipes.clone(), c)));
    }
    for (name, pipes, columns) in runs {
        for order in 3..=8 {
            let input = BlendInput {
                order,
                columns,
                ..BlendInput::new(pipes.clone())
            };
            let b = control_mesh(&input).unwrap();
            let diag = b.mesh.bounding_box_diagonal();
            // Unit tension: the same supports, all weights ≥ 0, so a refined vertex owes
            // nothing to the hub exactly when its hub share is 0.
            let unit = GbsOptions {
                order,
                tension: 1.0,
            };
            let levels = if order <= 5 { 3 } else { 2 };
            let marks = refine_gbs(&indicator(&b), &unit, levels).unwrap();
            let refined = refine_gbs(&b.mesh, &input.gbs_options(), levels).unwrap();
            let theta = TAU / columns as f64 / 2f64.powi(levels as i32);
            let mut checked = 0;
            for (p, m) in refined.positions.iter().zip(&marks.positions) {
                if m.x != 0.0 {
                    continue;
                }
                let pipe = &b.pipes[m.y.round() as usize];
                let rho = pipe.pipe.radius / circle_factor(order, theta);
                let off = *p - pipe.pipe.end;
                let radial = (off - pipe.axis * off.dot(pipe.axis)).length();
                assert!(
                    (radial - rho).abs() < 1e-12 * diag,
                    "{name} k={order}: {:e}",
                    radial - rho
                );
                checked += 1;
            }
            // A good share of the pipes: the hub's reach grows with the order and is widest
            // on three-column rings.
            assert!(
                checked > refined.positions.len() / 6,
                "{name} k={order}: {checked}"
            );
        }
    }
    // Order 4: the exact limit points off the hub are on the cylinders of the given radii.
    let b = control_mesh(&BlendInput::new(tee())).unwrap();
    let lp = limit_points(&b.mesh, &BlendInput::new(tee()).gbs_options(), 2).unwrap();
    let marks = refine_gbs(
        &indicator(&b),
        &GbsOptions {
            order: 4,
            tension: 1.0,
        },
        2,
    )
    .unwrap();
    let mut on = 0;
    for ((p, m), exact) in lp.points.iter().zip(&marks.positions).zip(&lp.exact) {
        // The limit stencil reaches one ring further than the control point.
        if m.x == 0.0 && *exact {
            let pipe = &b.pipes[m.y.round() as usize];
            let off = *p - pipe.pipe.end;
            let radial = (off - pipe.axis * off.dot(pipe.axis)).length();
            on += ((radial - pipe.pipe.radius).abs() < 1e-12) as usize;
        }
    }
    assert!(on > 100, "{on}");
}

#[test]
fn centre_and_valleys_move_monotonically() {
    for pipes in [3, 4, 5, 6].map(|n| star(n, 2.5)) {
        centre_and_valleys_of(&pipes);
    }
}

fn centre_and_valleys_of(pipes: &[Pipe]) {
    let steps = [0.0, 0.25, 0.5, 1.0, 2.0];
    let heights = |order: u32, columns: usize| -> Vec<[f64; 4]> {
        steps
            .iter()
            .map(|&alpha| {
                let input = BlendInput {
                    order,
                    columns,
                    alpha,
                    ..BlendInput::new(pipes.to_vec())
                };
                let b = control_mesh(&input).unwrap();
                // A centre point and the apex (N ≥ 5; else the centre point again).
                let c = b.centre_vertices().start;
                let apex = b.apex_vertices().next().unwrap_or(c);
                let refined = refine_gbs(&b.mesh, &input.gbs_options(), 3).unwrap();
                // Even orders keep vertex v's descendant at index v (vertices first).
                let (p0, p3) = (b.mesh.positions(), &refined.positions);
                [p0[c], p3[c], p0[apex], p3[apex]].map(|p| p.dot(b.up))
            })
            .collect()
    };
    let valleys = |order: u32, columns: usize| -> Vec<(f64, f64)> {
        steps
            .iter()
            .map(|&k_alpha| {
                let input = BlendInput {
                    order,
                    columns,
                    k_alpha,
                    ..BlendInput::new(pipes.to_vec())
                };
                let b = control_mesh(&input).unwrap();
                let w = b.valley_vertices().start;
                let refined = refine_gbs(&b.mesh, &input.gbs_options(), 3).unwrap();
                let out = b.pipes[0].axis + b.pipes[1].axis;
                (
                    b.mesh.positions()[w].dot(out),
                    refined.positions[w].dot(out),
                )
            })
            .collect()
    };
    for (order, columns) in [(4, 4), (6, 4), (4, 5), (6, 8)] {
        let h = heights(order, columns);
        let w = valleys(order, columns);
        for i in 1..steps.len() {
            assert!(
                (0..4).all(|j| h[i][j] > h[i - 1][j]),
                "N={} k={order} n={columns} α: {h:?}",
                pipes.len()
            );
            assert!(
                w[i].0 < w[i - 1].0 && w[i].1 < w[i - 1].1,
                "N={} k={order} n={columns} k_α: {w:?}",
                pipes.len()
            );
        }
    }
}

#[test]
fn bad_inputs_are_refused() {
    let ok = star(4, 2.0);
    let with = |f: &dyn Fn(&mut BlendInput)| {
        let mut input = BlendInput::new(ok.clone());
        f(&mut input);
        match control_mesh(&input) {
            Err(Error::InvalidArgument(m)) => m,
            Err(other) => panic!("expected an invalid argument, got {other}"),
            Ok(_) => panic!("expected an invalid argument, got a mesh"),
        }
    };
    assert!(with(&|i| i.pipes.truncate(2)).contains("3 to 8 pipes"));
    assert!(with(&|i| i.pipes.clear()).contains("3 to 8 pipes"));
    assert!(with(&|i| i.pipes.extend(star(5, 9.0))).contains("3 to 8 pipes"));
    assert!(with(&|i| i.pipes[1].radius = 0.0).contains("radius"));
    assert!(with(&|i| i.pipes[1].radius = -1.0).contains("radius"));
    assert!(with(&|i| i.pipes[2].length = f64::NAN).contains("length"));
    assert!(with(&|i| i.order = 2).contains("order"));
    assert!(with(&|i| i.columns = 2).contains("columns"));
    assert!(with(&|i| i.columns = 17).contains("columns"));
    assert!(with(&|i| i.order = 9).contains("order"));
    assert!(with(&|i| i.tension = Some(-1.0)).contains("tension"));
    assert!(with(&|i| i.pipes[1].axis = i.pipes[0].axis).contains("parallel"));
    assert!(with(&|i| i.pipes[1].end = i.pipes[0].end).contains("coincident"));
    assert!(with(&|i| i.pipes[0].axis = -i.pipes[0].axis).contains("into the junction"));
    // Two neighbours 20° apart with ends close together cross each other.
    assert!(with(&|i| {
        let a = 0.35f64;
        i.pipes[1].axis = DVec3::new(a.cos(), a.sin(), 0.0);
        i.pipes[1].end = i.pipes[1].axis * 2.0;
    })
    .contains("intersect before the junction"));
    assert!(with(&|i| i.pipes[3].axis = DVec3::new(0.2, -1.0, 5.0)).contains("hub normal"));
}

#[test]
fn catmull_clark_result_interpolates_the_gbs_limit() {
    use crate::construct::design::LATTICE;
    use crate::construct::Settings;
    for (pipes, order) in [(tee(), 4), (star(3, 2.5), 4), (star(6, 2.5), 6)] {
        let input = BlendInput {
            order,
            ..BlendInput::new(pipes)
        };
        let fitted = super::build(&input, &Settings::default()).unwrap();
        assert!(fitted.fit.residual <= fitted.fit.tolerance);
        // The lattice's corners are the targets of the faces' corners.
        let n = LATTICE + 1;
        for f in 0..fitted.mesh.num_faces() {
            let fv = fitted.mesh.face(f);
            let corners = [0, LATTICE, n * n - 1, n * LATTICE];
            for (k, &at) in corners.iter().enumerate() {
                let d = fitted.design.points().unwrap()[f * n * n + at];
                assert_eq!(d, fitted.targets[fv[k] as usize], "face {f} corner {k}");
            }
        }
        let report = fitted.surface_report().unwrap();
        eprintln!("k={order}: {report:?}");
        assert!(report.max_design_distance < 1e-2, "{report:?}");
        assert_eq!(report.folded_faces, 0);
    }
}

/// For each target of a fitted blend off the hub (more than 1.5 rows from either pipe
/// end), its distance from its pipe's axis minus the radius.
fn pipe_radius_errors(pipes: &[Pipe], targets: &[DVec3]) -> Vec<f64> {
    targets
        .iter()
        .filter_map(|t| {
            pipes.iter().find_map(|p| {
                let axis = p.axis.normalize();
                let along = (*t - p.end).dot(axis);
                let row = p.length / (p.length / p.radius).ceil();
                let off = *t - p.end - axis * along;
                (along > 1.5 * row && along < p.length - 1.5 * row && off.length() < 2.0 * p.radius)
                    .then(|| off.length() - p.radius)
            })
        })
        .collect()
}

#[test]
fn odd_order_results_interpolate_the_dual_limit() {
    use crate::construct::design::LATTICE;
    use crate::construct::Settings;
    for (pipes, order, tension, columns) in [
        (tee(), 3, None, 4),
        (star(6, 2.5), 3, Some(1.0), 4),
        (star(4, 2.5), 5, None, 4),
        (star(3, 2.5), 3, None, 6),
        (star(5, 2.5), 3, None, 5),
    ] {
        let input = BlendInput {
            order,
            tension,
            columns,
            ..BlendInput::new(pipes.clone())
        };
        let fitted = super::build(&input, &Settings::default()).unwrap();
        assert!(fitted.fit.residual <= fitted.fit.tolerance);
        let n = LATTICE + 1;
        for f in 0..fitted.mesh.num_faces() {
            let fv = fitted.mesh.face(f);
            for (k, at) in [0, LATTICE, n * n - 1, n * LATTICE].into_iter().enumerate() {
                let d = fitted.design.points().unwrap()[f * n * n + at];
                assert_eq!(d, fitted.targets[fv[k] as usize], "face {f} corner {k}");
            }
        }
        // Order 3: a regular quad's centroid is on the limit, so off the hub every target
        // is on its pipe's cylinder (at tension 1 the pipes are only near-circular).
        let errors = pipe_radius_errors(&pipes, &fitted.targets);
        assert!(errors.len() > 50, "k={order}: {} targets", errors.len());
        let worst = errors.iter().fold(0.0f64, |a, e| a.max(e.abs()));
        if order == 3 && tension.is_none() {
            assert!(worst < 1e-12, "k={order}: {worst:e}");
        }
        let report = fitted.surface_report().unwrap();
        eprintln!("k={order} tension {tension:?}: {report:?}, pipes off the hub {worst:e}");
        assert!(report.max_design_distance < 1e-3, "{report:?}");
        assert_eq!(report.folded_faces, 0);
    }
}
