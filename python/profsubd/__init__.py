"""profsubd: planar profile curves to Catmull-Clark control meshes with crease tags, and an
exact Catmull-Clark evaluator following OpenSubdiv 3.5 — Python bindings over the C ABI
(``libprofsubd.so``, ``profsubd.h``) with NumPy arrays in and out.

>>> import numpy as np, profsubd
>>> model = profsubd.profile()                    # the built-in bottle
>>> ev = profsubd.Evaluator(model.mesh)
>>> p, du, dv = ev.evaluate(np.array([0, 1]), np.array([0.5, 0.25]), np.array([0.5, 0.75]))

Handles (:class:`Mesh`, :class:`Evaluator`, :class:`Model`, :class:`Tessellation`,
:class:`StencilTable`, :class:`Options`) free their C object on ``close()``, at the end of a
``with`` block, or when collected. Errors are :class:`ProfsubdError` subclasses, one per C
status, carrying the library's message. Adding a construction: see
:mod:`profsubd.constructions`.
"""

from ._lib import LIBRARY_PATH
from ._lib import lib as _c
from .constructions import Model, blend, build, curves, default_profile_curves, profile, revolve, shell, sweep
from .errors import (
    BufferTooSmallError,
    CancelledError,
    InternalError,
    InvalidArgumentError,
    InvalidHandleError,
    InvalidMeshError,
    LimitExceededError,
    NonManifoldError,
    NullArgumentError,
    NumericalError,
    ParseError,
    ProfsubdError,
    ProfsubdIOError,
)
from .evaluator import Evaluator, FoldReport, StencilTable, Tessellation, limit_stencils
from .mesh import Mesh, MeshReport
from .options import Options


def library_version() -> str:
    """The loaded library's version, "MAJOR.MINOR.PATCH"."""
    return _c.profsubd_version_string().decode()


__version__ = library_version()

__all__ = [
    "LIBRARY_PATH", "BufferTooSmallError", "CancelledError", "Evaluator", "FoldReport", "InternalError",
    "InvalidArgumentError", "InvalidHandleError", "InvalidMeshError", "LimitExceededError", "Mesh", "MeshReport",
    "Model", "NonManifoldError", "NullArgumentError", "NumericalError", "Options", "ParseError",
    "ProfsubdError", "ProfsubdIOError", "StencilTable", "Tessellation", "blend", "build", "curves",
    "default_profile_curves", "library_version", "limit_stencils", "profile", "revolve", "shell", "sweep",
]
