"""Exact limit evaluation (``profsubd_evaluator``), fold checks, limit stencils and
tessellation of the limit surface."""

from __future__ import annotations

import ctypes
import os
from dataclasses import dataclass
from typing import Any, Optional, Tuple

import numpy as np

from ._handle import Handle, as_array, copy_out, indices, ptr
from ._lib import enum_values, lib, new_struct
from .errors import check
from .mesh import Mesh, PathLike
from .options import Options, optr

DOMAINS = enum_values("profsubd_domain", "PROFSUBD_DOMAIN_")
"""Parameterizations of (face, u, v): ``"ptex"`` (OpenSubdiv's Ptex faces) or ``"bfr"``
(Bfr's base faces)."""
QUANTITIES = enum_values("profsubd_limit_quantity", "PROFSUBD_LIMIT_")
"""Limit stencil rows: ``"position"``, ``"du"``, ``"dv"``."""
FORMATS = enum_values("profsubd_surface_format", "PROFSUBD_FORMAT_")
"""Tessellation file formats: ``"stl"``, ``"stl-ascii"``, ``"off"``, ``"ply"``, ``"obj"``."""
UP_AXES = enum_values("profsubd_up_axis", "PROFSUBD_UP_")
"""Up axis of written files: ``"z"`` (unchanged) or ``"y"`` ((x, y, z) written (x, z, -y))."""


@dataclass(frozen=True)
class FoldReport:
    """Where the limit surface folds (``profsubd_check_folds``); ``folded_faces`` empty:
    fold-free."""

    folded_faces: np.ndarray
    faces_checked: int
    samples: int
    worst_reversal_deg: float
    worst_face: int
    worst_u: float
    worst_v: float
    min_relative_jacobian: float


class Evaluator(Handle):
    """Exact Catmull-Clark limit evaluator of ``mesh`` under ``options`` (keyword settings of
    :class:`~profsubd.Options`: ``boundary``, ``crease_method``, ``triangles``; unset: the
    mesh's tags, then the defaults). Build once, evaluate many points."""

    _kind = "profsubd_evaluator"

    def __init__(self, mesh: Mesh, **options: Any) -> None:
        opts = Options(**options) if options else None
        out = ctypes.c_void_p()
        check(lib.profsubd_evaluator_new(mesh._ptr, optr(opts), ctypes.byref(out)))
        super().__init__(out.value)

    @property
    def num_parametric_faces(self) -> int:
        """Number of Ptex faces (the face count on a mesh of quads)."""
        n = ctypes.c_size_t()
        check(lib.profsubd_evaluator_num_parametric_faces(self._ptr, ctypes.byref(n)))
        return n.value

    def face_to_parametric(self, face: int) -> Tuple[int, int]:
        """``(first, count)``: the Ptex faces of control face ``face``."""
        first, count = ctypes.c_uint32(), ctypes.c_uint32()
        check(lib.profsubd_evaluator_face_to_parametric(self._ptr, int(face), ctypes.byref(first), ctypes.byref(count)))
        return first.value, count.value

    def set_threads(self, threads: int) -> None:
        """Threads used by evaluation (0: all cores, 1: the calling thread); same bits either way."""
        check(lib.profsubd_evaluator_set_threads(self._ptr, int(threads)))

    def update_positions(self, points: Any) -> None:
        """Replace the control points ((n, 3), the mesh's vertex count), keeping the topology."""
        pts = as_array(points, np.float64, (3,), "points")
        check(lib.profsubd_evaluator_update_positions(self._ptr, ptr(pts), len(pts)))

    def _points(self, faces: Any, u: Any, v: Any) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        f = indices(np.atleast_1d(faces), "faces")
        uu = as_array(np.atleast_1d(u), np.float64, name="u")
        vv = as_array(np.atleast_1d(v), np.float64, name="v")
        if not len(f) == len(uu) == len(vv):
            raise ValueError(f"faces, u, v: lengths {len(f)}, {len(uu)}, {len(vv)} differ")
        return f, uu, vv

    def evaluate(self, faces: Any, u: Any, v: Any) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Limit positions and first derivatives at Ptex points ``(faces[i], u[i], v[i])``:
        ``(p, du, dv)``, each (n, 3). A point off the surface (hole, face out of range, u or v
        outside [0, 1]) raises :class:`~profsubd.InvalidArgumentError` naming it."""
        p, du, dv, _ = self.evaluate_points(faces, u, v, domain="ptex", strict=True)
        return p, du, dv

    def evaluate_points(
        self, faces: Any, u: Any, v: Any, domain: str = "ptex", strict: bool = False
    ) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Like :meth:`evaluate` in ``domain`` (``"ptex"`` or ``"bfr"``: Bfr's base faces,
        derivatives with respect to Bfr's (u, v)); returns ``(p, du, dv, has_surface)``.
        Not ``strict``: points without limit surface get NaN and ``has_surface`` False."""
        f, uu, vv = self._points(faces, u, v)
        n = len(f)
        p, du, dv = (np.empty((n, 3)) for _ in range(3))
        has = np.empty(n, np.uint8)
        check(lib.profsubd_evaluator_evaluate_points(
            self._ptr, DOMAINS[domain], int(bool(strict)), ptr(f), ptr(uu), ptr(vv), n,
            ptr(p), ptr(du), ptr(dv), ptr(has)))
        return p, du, dv, has.astype(bool)

    def limit_vertices(self, strict: bool = False) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Exact limit of every control vertex: ``(p, du, dv, has_surface)``, (n, 3) each
        (derivatives along the vertex's first face); NaN where a vertex has no limit."""
        needed = ctypes.c_size_t()
        status = lib.profsubd_evaluator_limit_vertices_masked(self._ptr, 0, None, None, None, None, 0,
                                                              ctypes.byref(needed))
        if status not in (0, 7):  # 7: PROFSUBD_ERROR_BUFFER_TOO_SMALL, the count written
            check(status)
        n = needed.value
        p, du, dv = (np.empty((n, 3)) for _ in range(3))
        has = np.empty(n, np.uint8)
        check(lib.profsubd_evaluator_limit_vertices_masked(
            self._ptr, int(bool(strict)), ptr(p), ptr(du), ptr(dv), ptr(has), n, ctypes.byref(needed)))
        return p, du, dv, has.astype(bool)

    def check_folds(
        self, samples_per_edge: int = 9, adaptive_depth: int = 4, refine_turn_deg: float = 45.0
    ) -> FoldReport:
        """Sample the limit surface and report where it folds (``profsubd check --surface``)."""
        settings = new_struct("profsubd_fold_settings")
        settings.samples_per_edge, settings.adaptive_depth = samples_per_edge, adaptive_depth
        settings.refine_turn_deg = refine_turn_deg
        out = ctypes.c_void_p()
        check(lib.profsubd_check_folds(self._ptr, ctypes.byref(settings), ctypes.byref(out)))
        try:
            s = new_struct("profsubd_fold_summary")
            check(lib.profsubd_fold_report_get_summary(out, ctypes.byref(s)))
            folded = copy_out(lib.profsubd_fold_report_get_folded_faces, out.value, s.num_folded_faces, np.uint32)
        finally:
            lib.profsubd_fold_report_free(out)
        return FoldReport(folded, s.faces_checked, s.samples, s.worst_reversal_deg, s.worst_face,
                          s.worst_u, s.worst_v, s.min_relative_jacobian)

    def tessellate(
        self, rate: Optional[int] = None, tolerance: Optional[float] = None, max_rate: int = 64, quads: bool = False
    ) -> "Tessellation":
        """Tessellate the limit surface: uniform ``rate`` x ``rate`` per quad (default 4), or
        adaptive within ``tolerance`` (model units) up to ``max_rate``. Watertight wherever
        the control mesh is closed."""
        if tolerance is not None:
            if rate is not None:
                raise ValueError("rate or tolerance, not both")
            return Tessellation._create(lib.profsubd_tessellation_new_adaptive, self._ptr, float(tolerance),
                                        int(max_rate), int(quads))
        return Tessellation._create(lib.profsubd_tessellation_new_uniform, self._ptr, int(rate or 4), int(quads))


def _array(what: str, count: int, dtype: Any, width: int, doc: str) -> property:
    """A property copying ``profsubd_tessellation_get_WHAT``; ``count`` indexes the counts
    (vertices, polygons, face-vertex entries, normals)."""

    def get(self: "Tessellation") -> np.ndarray:
        fn = getattr(lib, f"profsubd_tessellation_get_{what}")
        return copy_out(fn, self._ptr, self._counts()[count], dtype, width=width)

    return property(get, doc=doc)


class Tessellation(Handle):
    """Polygons on the limit surface (``profsubd_tessellation``), made by
    :meth:`Evaluator.tessellate`; counter-clockwise seen from where ``du x dv`` points."""

    _kind = "profsubd_tessellation"

    def _counts(self) -> Tuple[int, int, int, int, int]:
        c = [ctypes.c_size_t() for _ in range(5)]
        check(lib.profsubd_tessellation_counts(self._ptr, *(ctypes.byref(x) for x in c)))
        return tuple(x.value for x in c)  # type: ignore[return-value]

    @property
    def num_unmet(self) -> int:
        """Parametric faces that missed the tolerance at the maximum rate (adaptive)."""
        return self._counts()[4]

    points = _array("positions", 0, np.float64, 3, "Vertex positions on the limit surface, (n, 3).")
    vertex_normals = _array("vertex_normals", 0, np.float64, 3,
                            "One unit normal per vertex, (n, 3) (split normals averaged).")
    normals = _array("normals", 3, np.float64, 3,
                     "Unit normals split along infinitely sharp creases, (m, 3); see :attr:`face_normals`.")
    face_sizes = _array("face_sizes", 1, np.uint32, 1, "Polygon sizes (3 or 4), (F,).")
    face_vertices = _array("face_vertices", 2, np.uint32, 1, "Polygon vertex indices, polygon after polygon.")
    face_normals = _array("face_normals", 2, np.uint32, 1, "Index into :attr:`normals` of every polygon corner.")
    face_ptex = _array("face_ptex", 1, np.uint32, 1, "Parametric (Ptex) face of every polygon.")
    corner_uv = _array("corner_uv", 2, np.float64, 2, "(u, v) of every polygon corner in its Ptex face, (corners, 2).")
    vertex_points = _array("vertex_points", 0, np.float64, 3,
                           "Where each vertex was evaluated: ``(ptex face, u, v)`` rows, (n, 3).")

    @property
    def triangles(self) -> np.ndarray:
        """The polygons as triangles (quads split along their 0-2 diagonal), (T, 3) uint32."""
        sizes, fv = self.face_sizes, self.face_vertices
        starts = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
        tris = [np.stack([fv[starts], fv[starts + 1], fv[starts + 2]], axis=1)]
        q = starts[sizes == 4]
        tris.append(np.stack([fv[q], fv[q + 2], fv[q + 3]], axis=1))
        return np.concatenate(tris).astype(np.uint32)

    def write(self, path: PathLike, format: Optional[str] = None, up: str = "z") -> None:
        """Write as ``"stl"`` (binary), ``"stl-ascii"``, ``"off"``, ``"ply"`` or ``"obj"``
        (default: from the extension), with ``up`` ``"z"`` or ``"y"``."""
        fmt = format or os.path.splitext(os.fspath(path))[1].lstrip(".").lower()
        if fmt not in FORMATS:
            raise ValueError(f"format {fmt!r}: expected one of {', '.join(FORMATS)}")
        check(lib.profsubd_tessellation_write(self._ptr, os.fsencode(os.fspath(path)), FORMATS[fmt], UP_AXES[up]))


class StencilTable(Handle):
    """Limit stencils (``profsubd_stencil_table``): row ``i`` is a weighted sum of control
    vertices giving vertex ``i``'s limit position (or derivative). Compressed sparse rows:
    :attr:`offsets`, :attr:`indices`, :attr:`weights`."""

    _kind = "profsubd_stencil_table"

    def __init__(self, mesh: Mesh, quantity: str = "position", **options: Any) -> None:
        opts = Options(**options) if options else None
        out = ctypes.c_void_p()
        check(lib.profsubd_limit_stencils_new(mesh._ptr, optr(opts), QUANTITIES[quantity], ctypes.byref(out)))
        super().__init__(out.value)

    def _n(self, what: str) -> int:
        n = ctypes.c_size_t()
        check(getattr(lib, f"profsubd_stencil_table_num_{what}")(self._ptr, ctypes.byref(n)))
        return n.value

    @property
    def offsets(self) -> np.ndarray:
        """Row offsets, (rows + 1,) uint32."""
        return copy_out(lib.profsubd_stencil_table_get_offsets, self._ptr, self._n("rows") + 1, np.uint32)

    @property
    def indices(self) -> np.ndarray:
        """Control vertex of every entry."""
        return copy_out(lib.profsubd_stencil_table_get_indices, self._ptr, self._n("entries"), np.uint32)

    @property
    def weights(self) -> np.ndarray:
        """Weight of every entry."""
        return copy_out(lib.profsubd_stencil_table_get_weights, self._ptr, self._n("entries"), np.float64)

    def apply(self, points: Any) -> np.ndarray:
        """Every row applied to ``points`` ((n, 3) control points): (rows, 3); NaN for empty rows."""
        pts = as_array(points, np.float64, (3,), "points")
        rows = self._n("rows")
        out = np.empty((rows, 3))
        needed = ctypes.c_size_t()
        check(lib.profsubd_stencil_table_apply(self._ptr, ptr(pts), len(pts), ptr(out), rows, ctypes.byref(needed)))
        return out


def limit_stencils(mesh: Mesh, quantity: str = "position", **options: Any) -> StencilTable:
    """The limit stencils of every control vertex of ``mesh``: ``quantity`` ``"position"``,
    ``"du"`` or ``"dv"``."""
    return StencilTable(mesh, quantity, **options)
