// Reference data (exact circles, tori, conics) may use the platform's sin and cos.
#![allow(clippy::disallowed_methods)]

use std::f64::consts::{PI, TAU};

use glam::DVec3;

use super::limit::limit_points;
use super::rules::{
    next_tension, order4_limit_weight, refine_closed_curve, refine_open_curve, tension_at,
};
use super::{refine_gbs, GbsOptions};
use crate::mesh::{Mesh, MeshParts};
use crate::options::SubdivOptions;
use crate::Error;

/// The limit radius of a circle of control radius 1 and angular spacing θ at order k:
/// λ_k(θ) = (sin θ/θ)·(2 sin(θ/2)/θ)^{k−4}.
fn lambda(k: u32, theta: f64) -> f64 {
    (theta.sin() / theta) * (2.0 * (theta / 2.0).sin() / theta).powi(k as i32 - 4)
}

fn polygon(n: usize, radius: f64, phase: f64) -> Vec<DVec3> {
    (0..n)
        .map(|i| {
            let a = phase + TAU * i as f64 / n as f64;
            DVec3::new(radius * a.cos(), radius * a.sin(), 0.0)
        })
        .collect()
}

#[test]
fn circles_are_exact_at_every_level() {
    for k in 3..=8 {
        for n in [3usize, 4, 5, 6, 8] {
            let theta = TAU / n as f64;
            let mut p = polygon(n, 1.0, 0.3);
            let r = lambda(k, theta);
            let mut v = (theta / 2.0).cos();
            for l in 1..=8 {
                p = refine_closed_curve(&p, k, v);
                v = next_tension(v);
                let th = theta / 2f64.powi(l);
                // The refined polygon is the regular 2^l·n-gon of control radius r/λ_k(θ_l).
                let rho = r / lambda(k, th);
                for (j, q) in p.iter().enumerate() {
                    let next = p[(j + 1) % p.len()];
                    assert!((q.length() / rho - 1.0).abs() < 1e-12, "k={k} n={n} l={l}");
                    let gap = q.angle_between(next);
                    assert!((gap - th).abs() < 1e-12 * th.max(1.0), "k={k} n={n} l={l}");
                }
            }
        }
    }
}

#[test]
fn unit_tension_is_lane_riesenfeld_bit_for_bit() {
    // Lane–Riesenfeld for degree k − 1: duplicate, then k − 1 averaging passes.
    let lane_riesenfeld = |p: &[DVec3], k: u32| {
        let mut q: Vec<DVec3> = p.iter().flat_map(|&x| [x, x]).collect();
        let n = q.len();
        for _ in 0..k - 1 {
            q = (0..n).map(|j| (q[j] + q[(j + 1) % n]) / 2.0).collect();
        }
        q
    };
    let start: Vec<DVec3> = (0..7)
        .map(|i| {
            let t = i as f64 * 0.77;
            DVec3::new(t.sin() * 1.3, (2.1 * t).cos(), 0.1 * t * t)
        })
        .collect();
    for k in 3..=8 {
        let (mut a, mut b) = (start.clone(), start.clone());
        for _ in 0..4 {
            a = refine_closed_curve(&a, k, 1.0);
            b = lane_riesenfeld(&b, k);
            assert_eq!(a, b, "k={k}");
        }
    }
}

#[test]
fn order_three_conics_pass_through_the_edge_midpoints() {
    // One span [t1, t2) of length Δ; control points at ξ_i = t1 + (i − ½)Δ (design note).
    let (t1, delta, m) = (-0.9, 0.3, 7);
    let xi = |i: usize| t1 + (i as f64 - 0.5) * delta;
    let (a, b, c) = (0.7, -0.4, 0.2);
    type Conic = (Vec<DVec3>, f64, Box<dyn Fn(DVec3) -> f64>);
    let cases: Vec<(&str, Conic)> = vec![
        (
            "parabola",
            (
                (0..m)
                    .map(|i| {
                        let x = xi(i);
                        DVec3::new(x, a * x * x + b * x + c - a * delta * delta / 4.0, 0.0)
                    })
                    .collect(),
                1.0,
                Box::new(move |p: DVec3| p.y - (a * p.x * p.x + b * p.x + c)),
            ),
        ),
        (
            "hyperbola",
            (
                (0..m)
                    .map(|i| {
                        let s = (delta / 2.0).cosh();
                        DVec3::new(1.5 * xi(i).cosh() / s, 0.8 * xi(i).sinh() / s, 0.0)
                    })
                    .collect(),
                (delta / 2.0).cosh(),
                Box::new(|p: DVec3| (p.x / 1.5).powi(2) - (p.y / 0.8).powi(2) - 1.0),
            ),
        ),
        (
            "arc",
            (
                (0..m)
                    .map(|i| {
                        let s = (delta / 2.0).cos();
                        DVec3::new(2.0 * xi(i).cos() / s, 2.0 * xi(i).sin() / s, 0.0)
                    })
                    .collect(),
                (delta / 2.0).cos(),
                Box::new(|p: DVec3| p.length() / 2.0 - 1.0),
            ),
        ),
    ];
    for (name, (mut p, mut v, residual)) in cases {
        for l in 0..=8 {
            for w in p.windows(2) {
                let r = residual((w[0] + w[1]) / 2.0);
                assert!(r.abs() < 1e-12, "{name} level {l}: residual {r:e}");
            }
            if l < 8 {
                p = refine_open_curve(&p, 3, v);
                v = next_tension(v);
            }
        }
    }
}

#[test]
fn order_four_stencil_puts_every_point_on_the_circle() {
    for n in [3usize, 5, 8] {
        let theta = TAU / n as f64;
        let r = lambda(4, theta);
        let mut p = polygon(n, 1.0, 0.0);
        let mut v = (theta / 2.0).cos();
        for l in 0..6 {
            let w = order4_limit_weight(v);
            for j in 0..p.len() {
                let (a, b) = (p[(j + p.len() - 1) % p.len()], p[(j + 1) % p.len()]);
                let q = (a + p[j] * w + b) / (w + 2.0);
                assert!((q.length() / r - 1.0).abs() < 1e-12, "n={n} l={l}");
            }
            p = refine_closed_curve(&p, 4, v);
            v = next_tension(v);
        }
    }
    // The series and the closed form meet (θ = 2 at v = cos 1), and v = 1 is the B-spline.
    assert!((order4_limit_weight(1.0) - 4.0).abs() < 1e-15);
    let (below, above) = (
        order4_limit_weight(1f64.cos() + 1e-12),
        order4_limit_weight(1f64.cos() - 1e-12),
    );
    assert!((below - above).abs() < 1e-9);
}

/// A closed n × m quad grid (a torus topology) with `point(i, j)`.
fn torus_grid(n: usize, m: usize, point: impl Fn(usize, usize) -> DVec3) -> Mesh {
    let id = |i: usize, j: usize| ((j % m) * n + i % n) as u32;
    let mut indices = Vec::new();
    for j in 0..m {
        for i in 0..n {
            indices.extend([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    Mesh::from_parts(MeshParts {
        positions: (0..m)
            .flat_map(|j| (0..n).map(move |i| (i, j)))
            .map(|(i, j)| point(i, j))
            .collect(),
        face_sizes: vec![4; n * m],
        face_indices: indices,
        ..Default::default()
    })
    .unwrap()
}

/// The torus of radii `big`, `small` as the control net of n × n points whose GBS limit it
/// is: x = (R + r cos w/λ) cos u/λ, z = r sin w/λ.
fn torus_net(n: usize, k: u32, big: f64, small: f64) -> Mesh {
    let theta = TAU / n as f64;
    let lam = lambda(k, theta);
    torus_grid(n, n, |i, j| {
        let (u, w) = (theta * i as f64, theta * j as f64);
        let rr = (big + small * w.cos() / lam) / lam;
        DVec3::new(rr * u.cos(), rr * u.sin(), small * w.sin() / lam)
    })
}

/// Distance of `p` from the level-l net of the torus: (ρ λ − R)² + z² = (r/λ)², λ = λ_k(θ_l).
fn torus_net_residual(p: DVec3, k: u32, theta_l: f64, big: f64, small: f64) -> f64 {
    let lam = lambda(k, theta_l);
    let rho = p.truncate().length() * lam - big;
    (rho * rho + p.z * p.z).sqrt() - small / lam
}

#[test]
fn torus_nets_are_exact_at_every_level() {
    let (big, small) = (2.0, 0.7);
    for k in 3..=8 {
        for n in [3usize, 4, 6] {
            let theta = TAU / n as f64;
            let mesh = torus_net(n, k, big, small);
            let opts = GbsOptions {
                order: k,
                tension: (PI / n as f64).cos(),
            };
            let diag = mesh.bounding_box_diagonal();
            for l in 1..=4 {
                let refined = refine_gbs(&mesh, &opts, l).unwrap();
                let th = theta / 2f64.powi(l as i32);
                assert_eq!(refined.level.num_faces(), n * n * 4usize.pow(l));
                for p in &refined.positions {
                    let r = torus_net_residual(*p, k, th, big, small);
                    assert!(r.abs() < 1e-12 * diag, "k={k} n={n} l={l}: {r:e}");
                }
            }
        }
    }
}

#[test]
fn cylinder_radius_is_exact_for_any_axial_spacing() {
    let n = 6;
    let theta = TAU / n as f64;
    let heights = [0.0, 0.1, 0.5, 0.6, 1.7, 2.0];
    for k in 3..=8 {
        let m = heights.len();
        let mut indices = Vec::new();
        for j in 0..m - 1 {
            for i in 0..n {
                let id = |i: usize, j: usize| (j * n + i % n) as u32;
                indices.extend([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
        let mesh = Mesh::from_parts(MeshParts {
            positions: heights
                .iter()
                .flat_map(|&z| {
                    polygon(n, 1.0, 0.0)
                        .into_iter()
                        .map(move |p| p + DVec3::Z * z)
                })
                .collect(),
            face_sizes: vec![4; n * (m - 1)],
            face_indices: indices,
            ..Default::default()
        })
        .unwrap();
        let opts = GbsOptions {
            order: k,
            tension: (theta / 2.0).cos(),
        };
        for l in 1..=3 {
            let refined = refine_gbs(&mesh, &opts, l).unwrap();
            let rho = lambda(k, theta) / lambda(k, theta / 2f64.powi(l as i32));
            for p in &refined.positions {
                let r = p.truncate().length() / rho - 1.0;
                assert!(r.abs() < 1e-12, "k={k} l={l}: {r:e}");
            }
        }
    }
}

#[test]
fn order_four_limit_points_are_on_the_torus() {
    let (big, small) = (2.0, 0.7);
    for n in [4usize, 6] {
        let mesh = torus_net(n, 4, big, small);
        let opts = GbsOptions {
            order: 4,
            tension: (PI / n as f64).cos(),
        };
        let lp = limit_points(&mesh, &opts, 2).unwrap();
        assert!(lp.exact.iter().all(|&e| e));
        for p in &lp.points {
            let rho = p.truncate().length() - big;
            let r = (rho * rho + p.z * p.z).sqrt() - small;
            assert!(
                r.abs() < 1e-12 * mesh.bounding_box_diagonal(),
                "n={n}: {r:e}"
            );
        }
    }
}

#[test]
fn order_four_unit_tension_limits_are_catmull_clarks() {
    // A cube with a pentagon-free mix: the cube's limit stencils from the Catmark evaluator
    // (checked against OpenSubdiv elsewhere) against GBS refinement plus its stencil.
    let cube = crate::test_support::unit_cube(vec![]);
    let opts = GbsOptions {
        order: 4,
        tension: 1.0,
    };
    let lp = limit_points(&cube, &opts, 1).unwrap();
    let refined = crate::refine_uniform(&cube, &SubdivOptions::default(), 1).unwrap();
    let expected = crate::limit_stencils(&refined, &SubdivOptions::default())
        .unwrap()
        .apply(refined.positions())
        .unwrap();
    for (i, (p, q)) in lp.points.iter().zip(&expected).enumerate() {
        if lp.exact[i] {
            assert!((*p - *q).length() < 1e-14, "vertex {i}");
        }
    }
    // Level 1 of a cube: the 8 valence-3 children are not covered by the stencil.
    assert_eq!(lp.exact.iter().filter(|&&e| !e).count(), 8);
}

#[test]
fn tension_update_is_the_half_angle_formula() {
    let v0 = (PI / 5.0).cos();
    assert!((tension_at(v0, 3) - (PI / 40.0).cos()).abs() < 1e-15);
    let h = (0.8f64).cosh();
    assert!((tension_at(h, 2) - (0.2f64).cosh()).abs() < 1e-15);
}

#[test]
fn bad_options_and_meshes_are_refused() {
    let cube = crate::test_support::unit_cube(vec![]);
    for (order, tension) in [
        (2, 1.0),
        (9, 1.0),
        (4, -1.0),
        (3, f64::NAN),
        (5, f64::INFINITY),
    ] {
        let err = refine_gbs(&cube, &GbsOptions { order, tension }, 1).unwrap_err();
        assert!(
            matches!(err, Error::InvalidArgument(_)),
            "{order} {tension}: {err}"
        );
    }
    let creased = crate::test_support::unit_cube(vec![crate::Crease {
        vertices: [0, 1],
        sharpness: 2.0,
    }]);
    let err = refine_gbs(
        &creased,
        &GbsOptions {
            order: 4,
            tension: 1.0,
        },
        1,
    )
    .unwrap_err();
    assert!(matches!(err, Error::InvalidMesh(_)), "{err}");
    assert!(err.to_string().contains("infinitely sharp"), "{err}");
}

#[test]
fn odd_orders_keep_closed_meshes_oriented_manifolds() {
    // The square pyramid (four triangles and a quad) and the cube.
    let pyramid = Mesh::from_parts(crate::test_support::square_pyramid()).unwrap();
    for mesh in [pyramid, crate::test_support::unit_cube(vec![])] {
        for k in [3, 5, 7] {
            let opts = GbsOptions {
                order: k,
                tension: 0.5,
            };
            let base = super::base_level(&mesh, &opts).unwrap();
            let one = refine_gbs(&mesh, &opts, 1).unwrap();
            let (l0, l1) = (&base.level, &one.level);
            // Doo–Sabin: a face per face, per edge and per vertex; a vertex per face corner.
            assert_eq!(
                l1.num_faces(),
                l0.num_faces() + l0.num_edges() + l0.num_vertices()
            );
            assert_eq!(l1.num_vertices(), l0.num_face_vertices_total());
            for e in 0..l1.num_edges() {
                assert_eq!(l1.edge_faces(e).len(), 2);
                assert!(!l1.is_edge_non_manifold(e), "k={k} edge {e}");
            }
            assert!((0..l1.num_vertices()).all(|v| l1.valence(v) == 4));
        }
    }
    // At v = 1 the triangle corner weights are Zorin–Schröder's 7/12, 5/24, 5/24.
    let (a, b, c) = (DVec3::X, DVec3::Y, DVec3::Z);
    let q = super::rules::face_corner(a, (a + c) / 2.0, (a + b) / 2.0, (a + b + c) / 3.0, 1.0);
    assert!((q - DVec3::new(7.0 / 12.0, 5.0 / 24.0, 5.0 / 24.0)).length() < 1e-15);
}

#[test]
fn control_points_approach_the_limit_by_four_per_level() {
    // Away from the order-4 stencil, limit points are control points: on a k = 6 torus
    // their distance to the exact torus falls about 4× per level (the README's figures).
    let (big, small) = (2.0, 0.7);
    let mesh = torus_net(6, 6, big, small);
    let opts = GbsOptions {
        order: 6,
        tension: (PI / 6.0).cos(),
    };
    let mut previous = f64::INFINITY;
    for l in 2..=5 {
        let lp = limit_points(&mesh, &opts, l).unwrap();
        assert!(lp.exact.iter().all(|&e| !e));
        let worst = lp
            .points
            .iter()
            .map(|p| {
                let rho = p.truncate().length() - big;
                ((rho * rho + p.z * p.z).sqrt() - small).abs()
            })
            .fold(0.0, f64::max)
            / mesh.bounding_box_diagonal();
        eprintln!("k=6 torus, level {l}: control point to limit surface {worst:.3e} x diagonal");
        assert!(
            worst < previous / 3.5,
            "level {l}: {worst:e} after {previous:e}"
        );
        previous = worst;
    }
}
