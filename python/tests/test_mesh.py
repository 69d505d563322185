"""Meshes: arrays in and out, OBJ bytes as the command-line tool writes them, checks,
hazards, refinement against hand-computed Catmull-Clark points."""

import json
import subprocess

import numpy as np
import pytest

import profsubd

from conftest import CUBE_FACES, EXAMPLES, cube_points, grid


def test_arrays_round_trip_through_the_library():
    creases = (np.array([[0, 2], [2, 3]]), np.array([2.5, 10.0]))
    corners = (np.array([7]), np.array([1.5]))
    with profsubd.Mesh(cube_points(), CUBE_FACES, creases=creases, corners=corners, holes=[5]) as m:
        assert m.num_vertices == 8 and m.num_faces == 6
        assert np.array_equal(m.points, cube_points()) and m.points.dtype == np.float64
        assert np.array_equal(m.faces, CUBE_FACES) and m.faces.dtype == np.uint32
        assert np.array_equal(m.creases[0], creases[0]) and np.array_equal(m.creases[1], [2.5, 10.0])
        assert m.corners[0].tolist() == [7] and m.corners[1].tolist() == [1.5]
        assert m.holes.tolist() == [5]
        assert len(m.edges) == 12 and m.valences.tolist() == [3] * 8
        es = dict(zip(map(tuple, np.sort(m.edges, axis=1).tolist()), m.edge_sharpness().tolist()))
        assert es[(0, 2)] == 2.5 and es[(2, 3)] == 10.0 and es[(0, 1)] == 0.0
        assert m.vertex_sharpness().tolist() == [0] * 7 + [1.5]


def test_mixed_face_sizes_give_a_list():
    with profsubd.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0.5, 0]], [[0, 1, 2, 3], [1, 4, 2]]) as m:
        faces = m.faces
        assert isinstance(faces, list) and [f.tolist() for f in faces] == [[0, 1, 2, 3], [1, 4, 2]]
        assert m.face_sizes.tolist() == [4, 3]


@pytest.mark.parametrize("name", ["profiles/bottle.obj", "sweeps/handrail.obj", "meshes/cube_creased.obj"])
def test_obj_read_write_is_byte_exact(tmp_path, name):
    src = EXAMPLES / name
    with profsubd.Mesh.read_obj(src) as m:
        m.write_obj(tmp_path / "out.obj")
    with profsubd.Mesh.read_obj(tmp_path / "out.obj") as again:
        again.write_obj(tmp_path / "again.obj")
    assert (tmp_path / "out.obj").read_bytes() == (tmp_path / "again.obj").read_bytes()
    if name.startswith(("profiles", "sweeps")):  # written by profsubd itself
        assert (tmp_path / "out.obj").read_bytes() == src.read_bytes()


@pytest.mark.parametrize(
    "kind, example",
    [("profile", None), ("profile", "profiles/vase.json"), ("profile", "profiles/spinning_top.json"),
     ("revolve", "sweeps/vase_cutaway.json"), ("sweep", "sweeps/handrail.json"),
     ("sweep", "sweeps/torus_knot_tube.json"), ("curves", "curves/bonnet.json"),
     ("curves", "curves/three_sided.json"), ("curves", "curves/open_corners.json"), ("curves", "curves/bonnet_fair.json"),
     ("blend", "blends/tee.json"), ("blend", "blends/six_way.json"), ("blend", "blends/three_way_n6.json"),
     ("blend", "blends/six_way_k3_v1.json"), ("blend", "blends/six_way_k3_cosh.json")],
)
def test_constructions_write_the_cli_bytes(tmp_path, cli, kind, example):
    # JSON keys are the keyword arguments: profsubd.KIND(**json) == `profsubd KIND file.json`.
    args = [cli, kind] + ([str(EXAMPLES / example)] if example else [])
    subprocess.run(args + ["-o", str(tmp_path / "cli.obj"), "--targets", str(tmp_path / "cli.txt")], check=True)
    kwargs = json.loads((EXAMPLES / example).read_text()) if example else {}
    with getattr(profsubd, kind)(**kwargs) as model:
        model.write_obj(tmp_path / "py.obj")
        targets = model.targets
    assert (tmp_path / "py.obj").read_bytes() == (tmp_path / "cli.obj").read_bytes()
    assert np.array_equal(targets, np.loadtxt(tmp_path / "cli.txt"))


def test_shell_writes_the_cli_bytes(tmp_path, cli):
    src = EXAMPLES / "profiles" / "bottle.obj"
    subprocess.run([cli, "shell", str(src), "--thickness", "0.05", "-o", str(tmp_path / "cli.obj"),
                    "--targets", str(tmp_path / "cli.txt")], check=True)
    with profsubd.Mesh.read_obj(src) as base, profsubd.shell(base, 0.05) as model:
        model.write_obj(tmp_path / "py.obj")
        targets = model.targets
        assert model.mesh.num_vertices == 2 * base.num_vertices  # closed: two walls, no rim
    assert (tmp_path / "py.obj").read_bytes() == (tmp_path / "cli.obj").read_bytes()
    assert np.array_equal(targets, np.loadtxt(tmp_path / "cli.txt"))
    with profsubd.Mesh.read_obj(src) as base, pytest.raises(profsubd.InvalidArgumentError, match="thickness"):
        profsubd.shell(base, -1.0)


def test_options_reach_the_construction(tmp_path, cli):
    profile = [[0.5, 0], [1, 1], [0.8, 2]]
    subprocess.run([cli, "revolve", "--boundary", "edge-only", "--crease", "chaikin", "--crease-sharpness", "3",
                    "-o", str(tmp_path / "cli.obj"), "/dev/stdin"],
                   input=json.dumps({"profile": profile, "caps": "flat", "angle_deg": 180,
                                     "samples_around": 8}).encode(), check=True)
    with profsubd.revolve(profile, caps="flat", angle_deg=180, samples_around=8, boundary="edge-only",
                          crease_method="chaikin", crease_sharpness=3) as m:
        m.write_obj(tmp_path / "py.obj")
    text = (tmp_path / "py.obj").read_text()
    assert "t interpolateboundary 1/0/0 2" in text and "t creasemethod 0/0/1 chaikin" in text
    assert (tmp_path / "py.obj").read_bytes() == (tmp_path / "cli.obj").read_bytes()


def test_obj_warnings(tmp_path):
    text = (EXAMPLES / "meshes" / "cube_creased.obj").read_text() + "t faceVaryingInterpolateBoundary 0/1/0 1\n"
    (tmp_path / "w.obj").write_text(text)
    with profsubd.Mesh.read_obj(tmp_path / "w.obj") as m:
        assert len(m.warnings) == 1 and m.warnings[0].startswith(str(tmp_path / "w.obj") + ":")


def test_check_reports(cube):
    r = cube.check()
    assert (r.num_vertices, r.num_edges, r.num_faces, r.euler_characteristic) == (8, 12, 6, 2)
    assert r.is_manifold and r.is_consistently_oriented and r.num_boundary_edges == 0
    with grid(3) as g:
        r = g.check()
    assert (r.num_boundary_edges, r.num_boundary_loops, r.euler_characteristic) == (12, 1, 1)
    # Three quads on one edge: non-manifold.
    pts = [[0, 0, 0], [0, 0, 1], [1, 0, 0], [1, 0, 1], [-1, 0, 0], [-1, 0, 1], [0, 1, 0], [0, 1, 1]]
    with profsubd.Mesh(pts, [[0, 2, 3, 1], [0, 1, 5, 4], [0, 6, 7, 1]]) as nm:
        r = nm.check()
    assert r.num_non_manifold_edges == 1 and not r.is_manifold


def test_dart_hazard_at_the_ends_of_a_lone_crease(cube):
    with profsubd.Mesh(cube.points, cube.faces, creases=([[0, 2]], [10.0])) as m:
        v, f = m.osd_hazards("dart")
        assert v.tolist() == [0, 2]
        assert len(f) > 0 and set(f.tolist()) <= {0, 2, 3, 4}  # faces at vertex 0 or 2
        assert m.osd_hazards("chaikin")[0].tolist() == []


def test_refine_cube_level_one(cube):
    # Catmull-Clark level 1 on [-1, 1]^3: vertex points (Q + 2R + (n - 3)S) / n = 5/9 corners,
    # face points the face centres, edge points 3/4 along the edges' axes.
    with cube.refine(1) as r:
        pts = r.points
        assert (r.num_vertices, r.num_faces) == (26, 24)
        np.testing.assert_allclose(pts[:8], 5 / 9 * cube_points(), rtol=0, atol=1e-15)
        centres = cube_points()[CUBE_FACES].mean(axis=1)
        np.testing.assert_allclose(pts[8:14], centres, rtol=0, atol=1e-15)
        np.testing.assert_allclose(np.sort(np.abs(pts[14:]), axis=1), np.tile([0, 0.75, 0.75], (12, 1)), atol=1e-15)
    with cube.refine(1, vertex_order="faces-first") as r:
        np.testing.assert_allclose(r.points[:6], centres, rtol=0, atol=1e-15)
    with pytest.raises(profsubd.InvalidArgumentError, match="level"):
        cube.refine(9)
