"""Limit stencils against the evaluator and the fit's targets; tessellations on the limit
surface, closed, and the written files' bytes."""

import struct

import numpy as np
import pytest

import profsubd



def test_stencils_reproduce_limit_positions_and_targets():
    with profsubd.sweep([[0.1, 0], [0, 0.1], [-0.1, 0], [0, -0.1]], [[0, 0, 0], [1, 0, 0.5], [2, 1, 0.5]],
                        closed_profile=True, samples_profile=4, samples_trajectory=8) as model:
        mesh, targets = model.mesh, model.targets
        with profsubd.limit_stencils(mesh) as st, model.evaluator() as ev:
            off, idx, w = st.offsets, st.indices, st.weights
            assert len(off) == mesh.num_vertices + 1 and off[-1] == len(idx) == len(w)
            row_sums = np.add.reduceat(w, off[:-1].astype(np.int64))
            np.testing.assert_allclose(row_sums, 1.0, rtol=0, atol=1e-13)
            limit = st.apply(mesh.points)
            p, du, dv, has = ev.limit_vertices()
        diag = np.linalg.norm(targets.max(0) - targets.min(0))
        assert has.all()
        assert np.abs(limit - p).max() <= 1e-13 * diag
        assert np.abs(limit - targets).max() <= 1e-10 * diag
        with profsubd.limit_stencils(mesh, "du") as sdu:
            np.testing.assert_allclose(np.add.reduceat(sdu.weights, sdu.offsets[:-1].astype(np.int64)), 0, atol=1e-12)
            np.testing.assert_allclose(sdu.apply(mesh.points), du, rtol=0, atol=1e-12 * diag)


def edge_uses(faces_flat, sizes):
    uses = {}
    start = 0
    for n in sizes:
        f = faces_flat[start:start + n]
        start += n
        for a, b in zip(f, np.roll(f, -1)):
            uses[(a, b)] = uses.get((a, b), 0) + 1
    return uses


def test_uniform_tessellation_is_closed_and_on_the_surface(tmp_path, cube):
    with profsubd.Evaluator(cube) as ev, ev.tessellate(rate=3, quads=True) as t:
        pts, sizes, fv = t.points, t.face_sizes, t.face_vertices
        assert len(sizes) == 6 * 9 and np.all(sizes == 4) and len(pts) == 6 * 9 + 2  # V - E + F = 2
        # Closed and consistently oriented: every directed edge once, its reverse once.
        uses = edge_uses(fv, sizes)
        assert set(uses.values()) == {1} and all((b, a) in uses for a, b in uses)
        # Every vertex is the limit at the (face, u, v) it was evaluated at.
        vp = t.vertex_points
        p, _, _ = ev.evaluate(vp[:, 0].astype(np.uint32), vp[:, 1], vp[:, 2])
        assert np.array_equal(p, pts)
        # The cube's limit corners (1/2, 1/2, 1/2) are vertices of the tessellation.
        assert np.abs(np.abs(pts) - 0.5).max(axis=1).min() < 1e-15
        tris = t.triangles
        assert tris.shape == (2 * len(sizes), 3)
        t.write(tmp_path / "c.stl")
        t.write(tmp_path / "c.off")
        t.write(tmp_path / "c.ply", up="y")
    data = (tmp_path / "c.stl").read_bytes()
    (n,) = struct.unpack_from("<I", data, 80)
    assert n == len(tris) and len(data) == 84 + 50 * n
    off = (tmp_path / "c.off").read_text().split("\n")
    assert off[0] == "OFF" and off[1].split()[:2] == [str(len(pts)), str(len(sizes))]
    assert b"element vertex %d" % len(pts) in (tmp_path / "c.ply").read_bytes()


def test_adaptive_tessellation_meets_its_tolerance():
    with profsubd.profile() as model, model.evaluator() as ev:
        coarse = ev.tessellate(tolerance=1e-2)
        fine = ev.tessellate(tolerance=1e-3)
        assert coarse.num_unmet == 0 and fine.num_unmet == 0
        assert len(fine.face_sizes) > len(coarse.face_sizes)
        # Midpoints of the fine triangles are within a few tolerances of the surface: compare
        # with the limit at the midpoint's (u, v) on the same Ptex face.
        uv = fine.corner_uv.reshape(-1, 3, 2)
        ptex = fine.face_ptex
        pts = fine.points[fine.face_vertices.reshape(-1, 3)]
        mid, _, _ = ev.evaluate(ptex, uv[:, :, 0].mean(1), uv[:, :, 1].mean(1))
        assert np.linalg.norm(pts.mean(1) - mid, axis=1).max() < 4e-3
        with pytest.raises(profsubd.InvalidArgumentError):
            ev.tessellate(tolerance=-1)
