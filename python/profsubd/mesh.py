"""Control meshes (``profsubd_mesh``): NumPy arrays in and out, OBJ files with OpenSubdiv's
tags, topology checks, OpenSubdiv 3.5 hazards and uniform refinement."""

from __future__ import annotations

import ctypes
import os
from dataclasses import dataclass, fields
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from ._handle import Handle, as_array, copy_out, copy_out_sized, indices, ptr, size_getter
from ._lib import enum_values, lib, new_struct
from .errors import check
from .options import Options, optr

PathLike = Union[str, "os.PathLike[str]"]
Faces = Union[np.ndarray, Sequence[Sequence[int]]]

HAZARDS = enum_values("profsubd_osd_hazard", "PROFSUBD_OSD_HAZARD_")
"""OpenSubdiv 3.5 hazard kinds: ``{"dart": 0, "valence2-dart": 1, ...}``."""


@dataclass(frozen=True)
class MeshReport:
    """What :meth:`Mesh.check` finds (``profsubd_mesh_report``; see ``profsubd check``)."""

    num_vertices: int
    num_edges: int
    num_faces: int
    num_boundary_edges: int
    num_boundary_loops: int
    num_non_manifold_edges: int
    num_non_manifold_vertices: int
    num_isolated_vertices: int
    num_faces_with_repeated_vertices: int
    num_components: int
    euler_characteristic: int
    is_manifold: bool
    is_consistently_oriented: bool
    num_inconsistent_edges: int


def _path(path: PathLike) -> bytes:
    return os.fsencode(os.fspath(path))


class Mesh(Handle):
    """An immutable control mesh with crease, corner and hole tags.

    ``Mesh(points, faces, creases=..., corners=..., holes=...)``: ``points`` (n, 3),
    ``faces`` an (F, k) integer array or a list of index lists, ``creases`` a pair
    ``(edges (m, 2), sharpness (m,))``, ``corners`` ``(vertices (c,), sharpness (c,))``,
    ``holes`` face indices. Sharpness 10 or more is infinitely sharp. Invalid data raises
    :class:`~profsubd.InvalidMeshError` with the library's message."""

    _kind = "profsubd_mesh"

    def __init__(
        self,
        points: Any,
        faces: Faces,
        creases: Optional[Tuple[Any, Any]] = None,
        corners: Optional[Tuple[Any, Any]] = None,
        holes: Optional[Any] = None,
    ) -> None:
        pts = as_array(points, np.float64, (3,), "points")
        if isinstance(faces, np.ndarray) and faces.ndim == 2:
            sizes = np.full(len(faces), faces.shape[1], dtype=np.uint32)
            idx = indices(faces.reshape(-1), "faces")
        else:
            face_list = [list(f) for f in faces]
            sizes = np.array([len(f) for f in face_list], dtype=np.uint32)
            idx = indices([i for f in face_list for i in f], "faces")
        cv, cs = creases if creases is not None else (np.empty((0, 2)), np.empty(0))
        cv = indices(cv, "crease edges", (2,))
        cs = as_array(cs, np.float32, name="crease sharpness")
        kv, ks = corners if corners is not None else (np.empty(0), np.empty(0))
        kv = indices(kv, "corner vertices")
        ks = as_array(ks, np.float32, name="corner sharpness")
        hv = indices(holes if holes is not None else [], "holes")
        if len(cv) != len(cs) or len(kv) != len(ks):
            raise ValueError("creases / corners: as many sharpness values as edges / vertices")
        desc = new_struct("profsubd_mesh_desc")
        desc.positions, desc.num_vertices = ptr(pts), len(pts)
        desc.face_sizes, desc.num_faces = ptr(sizes), len(sizes)
        desc.face_indices, desc.num_face_indices = ptr(idx), len(idx)
        desc.crease_vertices, desc.crease_sharpness, desc.num_creases = ptr(cv), ptr(cs), len(cs)
        desc.corner_vertices, desc.corner_sharpness, desc.num_corners = ptr(kv), ptr(ks), len(ks)
        desc.hole_faces, desc.num_holes = ptr(hv), len(hv)
        out = ctypes.c_void_p()
        check(lib.profsubd_mesh_new(ctypes.byref(desc), ctypes.byref(out)))
        super().__init__(out.value)

    @classmethod
    def read_obj(cls, path: PathLike) -> "Mesh":
        """Read an OBJ file with OpenSubdiv's tag lines (``t crease``, ``t corner``, ...)."""
        return cls._create(lib.profsubd_mesh_read_obj, _path(path))

    def write_obj(self, path: PathLike) -> None:
        """Write the mesh as OBJ with its tags (exact: reading it back gives the same mesh);
        the bytes ``profsubd`` (the command-line tool) writes for the same mesh."""
        check(lib.profsubd_mesh_write_obj(self._ptr, _path(path)))

    def _count(self, what: str) -> int:
        return size_getter(getattr(lib, f"profsubd_mesh_num_{what}"), self._ptr)

    @property
    def num_vertices(self) -> int:
        """Number of vertices."""
        return self._count("vertices")

    @property
    def num_faces(self) -> int:
        """Number of faces."""
        return self._count("faces")

    @property
    def points(self) -> np.ndarray:
        """Vertex positions, (n, 3) float64 (a copy)."""
        n = self.num_vertices
        return copy_out(lib.profsubd_mesh_get_positions, self._ptr, 3 * n, np.float64).reshape(n, 3)

    @property
    def face_sizes(self) -> np.ndarray:
        """Vertex count of every face, (F,) uint32."""
        return copy_out(lib.profsubd_mesh_get_face_sizes, self._ptr, self.num_faces, np.uint32)

    @property
    def face_indices(self) -> np.ndarray:
        """Face vertex indices, face after face, (sum of face sizes,) uint32."""
        return copy_out(lib.profsubd_mesh_get_face_indices, self._ptr, self._count("face_indices"), np.uint32)

    @property
    def faces(self) -> Union[np.ndarray, List[np.ndarray]]:
        """The faces: an (F, k) uint32 array when every face has k vertices (all quads:
        (F, 4)), else a list of 1-D arrays."""
        sizes, idx = self.face_sizes, self.face_indices
        if len(sizes) and np.all(sizes == sizes[0]):
            return idx.reshape(len(sizes), int(sizes[0]))
        return np.split(idx, np.cumsum(sizes)[:-1])

    @property
    def creases(self) -> Tuple[np.ndarray, np.ndarray]:
        """Crease tags: ``(edges (m, 2) uint32, sharpness (m,) float32)``."""
        m = self._count("creases")
        v, s = np.empty(2 * m, np.uint32), np.empty(m, np.float32)
        needed = ctypes.c_size_t()
        check(lib.profsubd_mesh_get_creases(self._ptr, ptr(v), ptr(s), m, ctypes.byref(needed)))
        return v.reshape(m, 2), s

    @property
    def corners(self) -> Tuple[np.ndarray, np.ndarray]:
        """Corner tags: ``(vertices (c,) uint32, sharpness (c,) float32)``."""
        c = self._count("corners")
        v, s = np.empty(c, np.uint32), np.empty(c, np.float32)
        needed = ctypes.c_size_t()
        check(lib.profsubd_mesh_get_corners(self._ptr, ptr(v), ptr(s), c, ctypes.byref(needed)))
        return v, s

    @property
    def holes(self) -> np.ndarray:
        """Hole faces, (h,) uint32."""
        return copy_out(lib.profsubd_mesh_get_holes, self._ptr, self._count("holes"), np.uint32)

    @property
    def edges(self) -> np.ndarray:
        """Edges in OpenSubdiv's level-0 order, (E, 2) uint32."""
        e = self._count("edges")
        return copy_out(lib.profsubd_mesh_get_edges, self._ptr, e, np.uint32, width=2)

    @property
    def valences(self) -> np.ndarray:
        """Edges at each vertex, (n,) uint32."""
        return copy_out(lib.profsubd_mesh_get_valences, self._ptr, self.num_vertices, np.uint32)

    @property
    def warnings(self) -> List[str]:
        """What the OBJ reader ignored, as ``"file:line: ..."``."""
        out = []
        for i in range(self._count("warnings")):
            s = ctypes.c_char_p()
            check(lib.profsubd_mesh_get_warning(self._ptr, i, ctypes.byref(s)))
            out.append((s.value or b"").decode("utf-8", "replace"))
        return out

    def edge_sharpness(self, **options: Any) -> np.ndarray:
        """Far's level-0 sharpness of every edge (:attr:`edges` order; boundary edges 10)."""
        opts = Options(**options) if options else None
        return copy_out(lib.profsubd_mesh_get_edge_sharpness, self._ptr, self._count("edges"), np.float32, optr(opts))

    def vertex_sharpness(self, **options: Any) -> np.ndarray:
        """Far's level-0 sharpness of every vertex (boundary corners under edge-and-corner)."""
        opts = Options(**options) if options else None
        return copy_out(lib.profsubd_mesh_get_vertex_sharpness, self._ptr, self.num_vertices, np.float32, optr(opts))

    def check(self) -> MeshReport:
        """Topology report: boundary, non-manifold and orientation findings, Euler number."""
        rep = new_struct("profsubd_mesh_report")
        check(lib.profsubd_mesh_check(self._ptr, ctypes.byref(rep)))
        values: Dict[str, Any] = {f.name: getattr(rep, f.name) for f in fields(MeshReport)}
        typed: Dict[str, Any] = {k: bool(v) if k.startswith("is_") else int(v) for k, v in values.items()}
        return MeshReport(**typed)

    def osd_hazards(self, kind: str, **options: Any) -> Tuple[np.ndarray, np.ndarray]:
        """Vertices and faces of OpenSubdiv 3.5 hazard ``kind`` (a key of :data:`HAZARDS`)."""
        k = HAZARDS[kind.replace("_", "-")]
        opts = Options(**options) if options else None
        v = copy_out_sized(lib.profsubd_mesh_get_osd_hazard_vertices, self._ptr, np.uint32, optr(opts), k)
        f = copy_out_sized(lib.profsubd_mesh_get_osd_hazard_faces, self._ptr, np.uint32, optr(opts), k)
        return v, f

    def refine(self, level: int, **options: Any) -> "Mesh":
        """Refine uniformly ``level`` times in OpenSubdiv Far's order (``vertex_order=
        "faces-first"`` for Far's ``orderVerticesFromFacesFirst``)."""
        opts = Options(**options) if options else None
        return Mesh._create(lib.profsubd_refine_uniform, self._ptr, optr(opts), int(level))

    def __repr__(self) -> str:
        if self.closed:
            return "<profsubd.Mesh (closed)>"
        return f"<profsubd.Mesh {self.num_vertices} vertices, {self.num_faces} faces>"
