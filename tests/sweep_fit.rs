//! Fitted sweeps and revolutions: the exact limit at every control vertex equals its data
//! point, and the meshes have the topology the construction promises.

use std::f64::consts::{PI, TAU};

use profsubd::construct::sweep::revolve::RevolveInput;
use profsubd::construct::sweep::sweep::SweepInput;
use profsubd::construct::sweep::{revolve, sweep, SweptSurface};
use profsubd::eval::limit_stencils;
use profsubd::mesh::validate::check;

fn circle(n: usize, r: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let t = TAU * i as f64 / n as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// Largest distance between a vertex's exact limit position and its target, over the diagonal.
fn relative_residual(s: &SweptSurface) -> f64 {
    let table = limit_stencils(&s.mesh, &s.mesh.options().resolve()).unwrap();
    let limits = table.apply(s.mesh.positions()).unwrap();
    let worst = limits
        .iter()
        .zip(&s.targets)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    worst / s.mesh.bounding_box_diagonal()
}

#[test]
fn torus_sphere_cylinder_cone_interpolate_their_targets() {
    let mut torus = SweepInput::new(
        circle(16, 0.5),
        circle(24, 2.0)
            .into_iter()
            .map(|[x, y]| [x, y, 0.0])
            .collect(),
    );
    torus.closed_profile = true;
    torus.closed_trajectory = true;
    let semicircle: Vec<[f64; 2]> = (0..=12)
        .map(|i| {
            let t = -PI / 2.0 + PI * i as f64 / 12.0;
            [if i == 0 || i == 12 { 0.0 } else { t.cos() }, t.sin()]
        })
        .collect();
    let surfaces = [
        ("torus", sweep(&torus).unwrap()),
        ("sphere", revolve(&RevolveInput::new(semicircle)).unwrap()),
        (
            "cylinder",
            revolve(&RevolveInput::new(vec![[1.0, 0.0], [1.0, 2.0]])).unwrap(),
        ),
        (
            "cone",
            revolve(&RevolveInput::new(vec![[1.0, 0.0], [0.0, 2.0]])).unwrap(),
        ),
    ];
    for (name, s) in &surfaces {
        let r = relative_residual(s);
        eprintln!(
            "{name}: {} vertices, residual {r:.2e} x diagonal",
            s.mesh.num_vertices()
        );
        assert!(r <= 1e-10, "{name}: residual {r}");
        assert!(s.mesh.face_sizes().iter().all(|&n| n == 4));
        let report = check(&s.mesh);
        assert!(
            report.is_manifold() && report.is_consistently_oriented(),
            "{name}"
        );
    }
}
