"""Shared fixtures: the repository's examples and the command-line tool."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import numpy as np
import pytest

import profsubd

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"


@pytest.fixture(scope="session")
def cli() -> str:
    """The `profsubd` command-line tool: $PROFSUBD_CLI, else target/release/profsubd, else PATH.
    With $PROFSUBD_CLI set (as .ci/run does) a missing tool fails instead of skipping."""
    env = os.environ.get("PROFSUBD_CLI")
    if env:
        assert Path(env).is_file(), f"PROFSUBD_CLI={env}: no such file"
        return env
    for candidate in (REPO / "target" / "release" / "profsubd", shutil.which("profsubd")):
        if candidate and Path(candidate).is_file():
            return str(candidate)
    pytest.skip("profsubd command-line tool not built (cargo build --release)")


def cube_points(half: float = 1.0) -> np.ndarray:
    """The corners of the cube [-half, half]^3, vertex i at bits (x, y, z) of i."""
    return np.array([[(-half, half)[(i >> k) & 1] for k in range(3)] for i in range(8)], dtype=float)


# Outward-oriented quads of cube_points.
CUBE_FACES = np.array(
    [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]], dtype=np.uint32
)


@pytest.fixture()
def cube() -> profsubd.Mesh:
    with profsubd.Mesh(cube_points(), CUBE_FACES) as m:
        yield m


def grid(n: int, height=lambda x, y: 0.0 * x) -> profsubd.Mesh:
    """An n x n grid of unit quads over [0, n]^2, vertex (i, j) at index j * (n + 1) + i,
    z = height(x, y); face (i, j) at index j * n + i, corner 0 at (i, j)."""
    ij = np.array([(i, j) for j in range(n + 1) for i in range(n + 1)], dtype=float)
    pts = np.column_stack([ij, height(ij[:, 0], ij[:, 1])])
    faces = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]
             for j in range(n) for i in range(n)]
    return profsubd.Mesh(pts, faces)


def pytest_report_header(config):
    return f"profsubd {profsubd.__version__} from {profsubd.__file__}, library {profsubd.LIBRARY_PATH}"
