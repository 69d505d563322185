"""Limit evaluation against analytic values: uniform cubic B-splines reproduce linear
functions exactly and map control values i^2 to x^2 + 1/3; the smooth cube's limit corner."""

import numpy as np
import pytest

import profsubd

from conftest import CUBE_FACES, cube_points, grid

N = 6  # grid size; faces (i, j) with 1 <= i, j <= 4 are regular, away from the boundary rules


def interior_points(rng, count=40):
    i, j = rng.integers(1, N - 1, count), rng.integers(1, N - 1, count)
    return j * N + i, i, j, rng.random(count), rng.random(count)


def test_plane_is_reproduced_with_derivatives():
    rng = np.random.default_rng(1)
    with grid(N, lambda x, y: 0.3 * x - 0.7 * y + 2) as mesh, profsubd.Evaluator(mesh) as ev:
        faces, i, j, u, v = interior_points(rng)
        p, du, dv = ev.evaluate(faces, u, v)
    x, y = i + u, j + v
    np.testing.assert_allclose(p, np.column_stack([x, y, 0.3 * x - 0.7 * y + 2]), rtol=0, atol=1e-13)
    np.testing.assert_allclose(du, np.tile([1, 0, 0.3], (len(x), 1)), rtol=0, atol=1e-13)
    np.testing.assert_allclose(dv, np.tile([0, 1, -0.7], (len(x), 1)), rtol=0, atol=1e-13)


def test_quadratic_control_values_give_x2_plus_one_third():
    rng = np.random.default_rng(2)
    with grid(N, lambda x, y: x * x + 2 * y * y) as mesh, profsubd.Evaluator(mesh) as ev:
        faces, i, j, u, v = interior_points(rng)
        p, du, dv = ev.evaluate(faces, u, v)
    x, y = i + u, j + v
    np.testing.assert_allclose(p[:, 2], x * x + 1 / 3 + 2 * (y * y + 1 / 3), rtol=0, atol=1e-12)
    np.testing.assert_allclose(du[:, 2], 2 * x, rtol=0, atol=1e-12)
    np.testing.assert_allclose(dv[:, 2], 4 * y, rtol=0, atol=1e-12)


def test_smooth_cube_limit_corner_and_limit_vertices(cube):
    # Catmull-Clark limit mask at a valence-3 vertex: (n^2 v + 4 sum e + sum f) / (n (n + 5)):
    # (9 - 1 + 4 * 1 - 1 * 1) ... = 12 / 24 for the cube [-1, 1]^3, i.e. (1/2, 1/2, 1/2).
    with profsubd.Evaluator(cube) as ev:
        p, du, dv, has = ev.limit_vertices()
        assert has.all()
        np.testing.assert_allclose(p, 0.5 * cube_points(), rtol=0, atol=1e-15)
        # The same point through (face, u, v): corner 0 of face 0 is vertex 0.
        q, _, _ = ev.evaluate([0], [0.0], [0.0])
        np.testing.assert_allclose(q[0], p[CUBE_FACES[0, 0]], rtol=0, atol=1e-15)
        assert ev.num_parametric_faces == 6 and ev.face_to_parametric(5) == (5, 1)
        # Threads: the same bits with 1 or all.
        f = np.repeat(np.arange(6), 50)
        uv = np.random.default_rng(3).random((2, len(f)))
        ev.set_threads(1)
        one = ev.evaluate(f, uv[0], uv[1])
        ev.set_threads(0)
        for a, b in zip(one, ev.evaluate(f, uv[0], uv[1])):
            assert np.array_equal(a, b)


def test_bfr_parameterization_on_triangles():
    # A tetrahedron: each triangle is 3 Ptex faces; in Bfr's domain sub-face k sits at
    # (k % 2 + s / 2, k // 2 + t / 2), so derivatives are twice the Ptex ones.
    pts = [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]
    with profsubd.Mesh(pts, [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]) as mesh, profsubd.Evaluator(mesh) as ev:
        assert ev.num_parametric_faces == 12 and ev.face_to_parametric(2) == (6, 3)
        s, t = np.array([0.1, 0.7, 0.3]), np.array([0.2, 0.4, 0.9])
        for k in range(3):
            ptex = ev.evaluate_points([6 + k] * 3, s, t, domain="ptex")
            bfr = ev.evaluate_points([2] * 3, k % 2 + s / 2, k // 2 + t / 2, domain="bfr")
            np.testing.assert_allclose(bfr[0], ptex[0], rtol=0, atol=1e-14)
            np.testing.assert_allclose(bfr[1], 2 * ptex[1], rtol=0, atol=1e-13)
            np.testing.assert_allclose(bfr[2], 2 * ptex[2], rtol=0, atol=1e-13)
        with pytest.raises(profsubd.InvalidArgumentError, match="gap|outside|domain"):
            ev.evaluate_points([2], [0.75], [0.25], domain="bfr")


def test_holes_marked_or_refused():
    with grid(3) as g:
        pts, faces = g.points, g.faces
    with profsubd.Mesh(pts, faces, holes=[4]) as mesh, profsubd.Evaluator(mesh) as ev:
        p, _, _, has = ev.evaluate_points([3, 4], [0.5, 0.5], [0.5, 0.5])
        assert has.tolist() == [True, False] and np.isnan(p[1]).all() and np.isfinite(p[0]).all()
        with pytest.raises(profsubd.InvalidArgumentError, match="no limit surface"):
            ev.evaluate([4], [0.5], [0.5])


def test_update_positions_scales_the_surface(cube):
    with profsubd.Evaluator(cube) as ev:
        before, _, _ = ev.evaluate([1, 2], [0.3, 0.6], [0.8, 0.1])
        ev.update_positions(3 * cube.points)
        after, _, _ = ev.evaluate([1, 2], [0.3, 0.6], [0.8, 0.1])
        np.testing.assert_allclose(after, 3 * before, rtol=0, atol=1e-14)
        with pytest.raises(profsubd.InvalidArgumentError):
            ev.update_positions(cube.points[:7])


def test_boundary_option_changes_the_surface():
    # Under "none" the boundary faces of a grid have no limit surface.
    with grid(3) as g, profsubd.Evaluator(g, boundary="none") as ev:
        _, _, _, has = ev.evaluate_points(np.arange(9), np.full(9, 0.5), np.full(9, 0.5))
        assert has.tolist() == [False] * 4 + [True] + [False] * 4


def test_fold_check():
    with profsubd.profile() as model, model.evaluator() as ev:
        rep = ev.check_folds()
        assert len(rep.folded_faces) == 0 and rep.worst_reversal_deg < 90 and rep.faces_checked == model.mesh.num_faces
    # A grid whose interior vertex is pulled past its neighbours folds around it.
    with grid(4) as g:
        pts = g.points
        faces = g.faces
    pts[12] += [2.5, 0, 0]  # vertex (2, 2) moved beyond (4, 2)
    with profsubd.Mesh(pts, faces) as folded, profsubd.Evaluator(folded) as ev:
        rep = ev.check_folds(samples_per_edge=5)
        assert len(rep.folded_faces) > 0 and rep.worst_reversal_deg > 90
        assert set(rep.folded_faces.tolist()) <= set(range(16))
    with pytest.raises(profsubd.InvalidArgumentError):
        profsubd.Evaluator(faces_mesh := profsubd.Mesh(pts, faces)).check_folds(samples_per_edge=1)
    faces_mesh.close()
