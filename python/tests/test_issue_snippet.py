"""The snippet of issue #16, exactly as written, and what it returns."""

import numpy as np
import pytest

import profsubd


def test_issue_snippet_as_written():
    import numpy as np, profsubd  # noqa: E401,F811 (as in the issue)
    model = profsubd.profile()          # built-in default; profsubd.profile(c1=..., c2=..., around=16, ...)
    ev = profsubd.Evaluator(model.mesh)
    p, du, dv = ev.evaluate(np.array([0, 1]), np.array([0.5, 0.25]), np.array([0.5, 0.75]))  # (n, 3) each
    with pytest.raises(profsubd.ProfsubdError) as err:
        profsubd.profile(c1=[[0, 0]], c2=[[0, 0]])   # raises profsubd.ProfsubdError with the library's message
    assert str(err.value) == "invalid argument: c1 needs at least 2 points, got 1"
    assert isinstance(err.value, profsubd.InvalidArgumentError) and err.value.status == 2
    for a in (p, du, dv):
        assert a.shape == (2, 3) and a.dtype == np.float64 and np.all(np.isfinite(a))


def test_default_model_interpolates_its_targets():
    model = profsubd.profile()
    mesh = model.mesh
    pts, targets = mesh.points, model.targets
    assert pts.shape == targets.shape == (mesh.num_vertices, 3) and pts.dtype == np.float64
    assert mesh.faces.shape == (mesh.num_faces, 4)
    # Corner 0 of every face is a control vertex: its limit position is its data point.
    faces = np.arange(mesh.num_faces)
    p, _, _ = profsubd.Evaluator(mesh).evaluate(faces, np.zeros(len(faces)), np.zeros(len(faces)))
    diag = np.linalg.norm(targets.max(0) - targets.min(0))
    assert np.abs(p - targets[mesh.faces[:, 0]]).max() <= 1e-10 * diag
    assert model.fit_residual <= model.fit_tolerance == pytest.approx(1e-10 * diag, rel=1e-6)
    # Crease tags: the bottle's rings through its corners, infinitely sharp.
    edges, sharp = mesh.creases
    assert edges.shape == (len(sharp), 2) and len(sharp) > 0 and np.all(sharp == 10.0)
    q = model.surface_quality
    assert q["folded_faces"] == 0 and q["worst_reversal_deg"] < 90


def test_profile_keywords_set_sampling():
    curve = [[0, 0], [1, 0.5], [1, 1.5], [0, 2]]
    m = profsubd.profile(c1=curve, c2=curve, around=16, along=8)
    # Two smooth poles (4x4 grid caps, around = 16): rings x meridians on the side.
    assert m.mesh.check().euler_characteristic == 2
    with pytest.raises(profsubd.InvalidArgumentError, match="multiple of 4"):
        profsubd.profile(c1=curve, c2=curve, around=18)
