"""Error classes and messages per C status; handles freed exactly once."""

import gc
import re

import numpy as np
import pytest

import profsubd
from profsubd import _handle, _lib
from profsubd.errors import ERRORS

from conftest import CUBE_FACES, cube_points


def test_one_error_class_per_status_of_the_header():
    header = {k: v for k, v in _lib.HEADER.enums["profsubd_status"].items() if v != 0}
    # PROFSUBD_ERROR_INVALID_ARGUMENT -> InvalidArgumentError (IO -> ProfsubdIOError).
    expected = {v: re.sub(r"_(\w)", lambda m: m.group(1).upper(), "_" + k[len("PROFSUBD_ERROR_"):].lower())
                for k, v in header.items()}
    assert set(ERRORS) == set(expected)
    for status, cls in ERRORS.items():
        assert issubclass(cls, profsubd.ProfsubdError) and cls.status == status
        assert cls.__name__ in (expected[status] + "Error", "Profsubd" + expected[status].upper() + "Error")


def test_invalid_mesh_message():
    with pytest.raises(profsubd.InvalidMeshError) as err:
        profsubd.Mesh(cube_points(), [[0, 1, 9]])
    assert err.value.status == 3 and "9" in err.value.message and err.value.message == str(err.value)
    with pytest.raises(profsubd.InvalidMeshError, match="(?i)finite|nan"):
        profsubd.Mesh([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(ValueError, match="indices"):
        profsubd.Mesh(cube_points(), [[0, 1, -2]])


def test_io_and_parse_errors(tmp_path):
    with pytest.raises(profsubd.ProfsubdIOError) as err:
        profsubd.Mesh.read_obj(tmp_path / "missing.obj")
    assert isinstance(err.value, OSError) and "missing.obj" in err.value.message
    (tmp_path / "bad.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n")
    with pytest.raises(profsubd.ParseError) as err:
        profsubd.Mesh.read_obj(tmp_path / "bad.obj")
    assert f"{tmp_path / 'bad.obj'}:4" in err.value.message
    with profsubd.Mesh(cube_points(), CUBE_FACES) as m, pytest.raises(profsubd.ProfsubdIOError):
        m.write_obj(tmp_path / "no" / "such" / "dir.obj")


def test_settings_checked_by_the_library_and_by_python():
    with pytest.raises(profsubd.InvalidArgumentError) as err:
        profsubd.Options(sharp_angle_deg=200)
    assert "200" in err.value.message
    with pytest.raises(profsubd.InvalidArgumentError):
        profsubd.revolve([[1, 0], [1, 1]], angle_deg=0)
    with pytest.raises(ValueError, match="edge-only"):
        profsubd.Options(boundary="edges")
    with pytest.raises(TypeError, match="colour"):
        profsubd.revolve([[1, 0], [1, 1]], colour="red")
    with pytest.raises(ValueError, match=r"\(n, 2\)"):
        profsubd.revolve([[1, 0, 0], [1, 1, 0]])


def test_library_message_is_per_call():
    with pytest.raises(profsubd.InvalidArgumentError):
        profsubd.Options(sharp_angle_deg=-1)
    with profsubd.Options(sharp_angle_deg=10):
        assert _lib.last_message() == ""


def test_handles_are_freed_once():
    kinds = ("profsubd_mesh", "profsubd_evaluator", "profsubd_fitted", "profsubd_options", "profsubd_tessellation")
    gc.collect()
    before = {k: _handle.LIVE[k] for k in kinds}
    with profsubd.Mesh(cube_points(), CUBE_FACES) as m:
        with profsubd.Evaluator(m) as ev:
            t = ev.tessellate(rate=2)
            assert _handle.LIVE["profsubd_evaluator"] == before["profsubd_evaluator"] + 1
        assert ev.closed and not m.closed
        with pytest.raises(ValueError, match="closed"):
            ev.evaluate([0], [0.5], [0.5])
    assert m.closed
    ev.close()  # a second close is a no-op
    del t  # collected: its finalizer frees it
    model = profsubd.revolve([[1, 0], [1, 1]], samples_around=8, samples_profile=2)
    mesh = model.mesh
    model.close()
    assert mesh.num_vertices > 0  # the model's mesh outlives the model
    del mesh, model
    gc.collect()
    assert {k: _handle.LIVE[k] for k in kinds} == before
