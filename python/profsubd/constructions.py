"""Constructions: curves in, a fitted :class:`Model` out (control mesh whose exact limit
surface passes through the data points, its targets and fit figures).

Every construction is a C entry point ``profsubd_<name>(inputs..., const profsubd_options *,
profsubd_fitted **)``; its Python function converts the inputs to arrays, the remaining
keyword settings to an :class:`~profsubd.Options` and calls :func:`build`. Adding one, e.g. a
C ``profsubd_shell(const profsubd_mesh *base, const profsubd_options *, profsubd_fitted **)``
with a setter ``profsubd_options_set_shell_thickness``:

1. one line in :data:`profsubd.options.SETTERS`:
   ``("thickness",): ("profsubd_options_set_shell_thickness", lambda t: (float(t),), ()),``
2. the function (and its name in ``__all__`` of ``profsubd/__init__.py``)::

       def shell(base: Mesh, **settings: Any) -> Model:
           \"\"\"Offset shell of ``base`` (settings: thickness, ...).\"\"\"
           return build("profsubd_shell", base._ptr, options=Options(**settings))

The header is read at import (``profsubd/_lib.py``), so the C function needs no ctypes
declaration.
"""

from __future__ import annotations

import ctypes
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple

import numpy as np

from ._handle import Handle, as_array, copy_out, indices, ptr
from ._lib import constant, lib, new_struct
from .errors import check
from .evaluator import Evaluator
from .mesh import Mesh, PathLike
from .options import Options, optr

Points = Any  # (n, 2) or (n, 3) array-like


class Model(Handle):
    """A fitted construction (``profsubd_fitted``): :attr:`mesh` (the control mesh with its
    crease, corner and option tags), :attr:`targets` (the data point each control vertex's
    limit position equals) and the fit report."""

    _kind = "profsubd_fitted"

    _mesh: Optional[Mesh] = None

    @property
    def mesh(self) -> Mesh:
        """The control mesh (one :class:`~profsubd.Mesh`, valid after the model is closed)."""
        if self._mesh is None:
            self._mesh = Mesh._create(lib.profsubd_fitted_get_mesh, self._ptr)
        return self._mesh

    @property
    def targets(self) -> np.ndarray:
        """The data points, (n, 3), in vertex order: vertex ``i``'s limit is ``targets[i]``."""
        n = self.mesh.num_vertices
        return copy_out(lib.profsubd_fitted_get_targets, self._ptr, 3 * n, np.float64).reshape(n, 3)

    @property
    def fit_residual(self) -> float:
        """Largest distance between a vertex's limit position and its data point."""
        r = ctypes.c_double()
        check(lib.profsubd_fitted_get_fit_residual(self._ptr, ctypes.byref(r), None))
        return r.value

    @property
    def fit_tolerance(self) -> float:
        """The tolerance the fit met: 1e-10 x the data points' bounding-box diagonal."""
        t = ctypes.c_double()
        check(lib.profsubd_fitted_get_fit_residual(self._ptr, None, ctypes.byref(t)))
        return t.value

    @property
    def design_distance(self) -> Tuple[float, float]:
        """``(max, mean)`` distance of the limit surface from the design surface between the
        data points, over the limit surface's bounding-box diagonal (computed on first use)."""
        mx, mean = ctypes.c_double(), ctypes.c_double()
        check(lib.profsubd_fitted_get_design_distance(self._ptr, ctypes.byref(mx), ctypes.byref(mean)))
        return mx.value, mean.value

    @property
    def surface_quality(self) -> Dict[str, float]:
        """``folded_faces``, ``worst_reversal_deg`` (above 90 where it folds) and
        ``undulation`` (bending energy over the design surface's; 1 = as fair)."""
        folded, worst, und = ctypes.c_size_t(), ctypes.c_double(), ctypes.c_double()
        check(lib.profsubd_fitted_get_surface_quality(
            self._ptr, ctypes.byref(folded), ctypes.byref(worst), ctypes.byref(und)))
        return {"folded_faces": folded.value, "worst_reversal_deg": worst.value, "undulation": und.value}

    def evaluator(self, **options: Any) -> Evaluator:
        """An :class:`~profsubd.Evaluator` of the control mesh (its tags: the fit's options)."""
        return Evaluator(self.mesh, **options)

    def write_obj(self, path: PathLike) -> None:
        """Write the control mesh as OBJ with its tags (as ``profsubd profile -o``)."""
        self.mesh.write_obj(path)

    def write_targets(self, path: PathLike) -> None:
        """Write the targets, one ``x y z`` line per vertex (as ``--targets``)."""
        np.savetxt(path, self.targets, fmt="%.17g")

    def __repr__(self) -> str:
        if self.closed:
            return "<profsubd.Model (closed)>"
        m = self.mesh
        return f"<profsubd.Model {m.num_vertices} vertices, {m.num_faces} faces, residual {self.fit_residual:.3g}>"


def build(c_function: str, *inputs: Any, options: Optional[Options]) -> Model:
    """Call construction ``c_function(*inputs, options, &fitted)`` and wrap the result."""
    return Model._create(getattr(lib, c_function), *inputs, optr(options))


def points(values: Points, dim: int, name: str) -> np.ndarray:
    """Curve points as a C-contiguous (n, dim) float64 array."""
    return as_array(values, np.float64, (dim,), name)


def default_profile_curves() -> Dict[str, Any]:
    """The built-in model's curves and samples: ``{"c1": (n, 2), ..., "c4": ...,
    "along": 20, "around": 16}`` (``profile(**default_profile_curves())`` builds it)."""
    curves = new_struct("profsubd_profile_curves")
    along, around = ctypes.c_uint32(), ctypes.c_uint32()
    check(lib.profsubd_profile_default_curves(ctypes.byref(curves), ctypes.byref(along), ctypes.byref(around)))
    out: Dict[str, Any] = {"along": along.value, "around": around.value}
    for c in ("c1", "c2", "c3", "c4"):
        n = getattr(curves, f"{c}_points")
        if n:
            arr = (ctypes.c_double * (2 * n)).from_address(getattr(curves, c))
            out[c] = np.array(arr).reshape(n, 2)
    return out


def profile(
    c1: Optional[Points] = None,
    c2: Optional[Points] = None,
    c3: Optional[Points] = None,
    c4: Optional[Points] = None,
    *,
    along: Optional[int] = None,
    around: Optional[int] = None,
    corners: Optional[Mapping[str, Sequence[int]]] = None,
    **settings: Any,
) -> Model:
    """Profile model (Hui & Lai): four planar silhouettes, bottom to top, ``c1`` the +x one
    ``(x, z)``, ``c2`` the +y one ``(y, z)``, ``c3`` the -x one, ``c4`` the -y one
    (default: mirrors of ``c1``/``c2``). Without curves: the built-in bottle.

    ``along`` (ring intervals, default 12; the bottle's 20), ``around`` (meridians, a multiple
    of 4, default 16), ``corners`` (``{"c1": [4]}``: forced corners), and the settings
    ``sharp_angle_deg``, ``crease_sharpness``, ``interpolation``, ``caps``, ``boundary``,
    ``crease_method`` — the keys of ``profsubd profile``'s JSON input."""
    if c1 is None and c2 is None:
        if c3 is not None or c4 is not None or corners:
            raise ValueError("profile: c3, c4 and corners need c1 and c2")
        samples = None
        if along is not None or around is not None:
            d = default_profile_curves()
            samples = (along or d["along"], around or d["around"])
        return build("profsubd_profile_build_default", options=Options(samples=samples, **settings))
    if c1 is None or c2 is None:
        raise ValueError("profile: c1 and c2 are both required (or neither, for the built-in model)")
    desc = new_struct("profsubd_profile_curves")
    keep = []
    for name, curve in (("c1", c1), ("c2", c2), ("c3", c3), ("c4", c4)):
        if curve is not None:
            arr = points(curve, 2, name)
            keep.append(arr)
            setattr(desc, name, ptr(arr))
            setattr(desc, f"{name}_points", len(arr))
    unknown = set(corners or {}) - {"c1", "c2", "c3", "c4"}
    if unknown:
        raise ValueError(f"corners: unknown curves {sorted(unknown)} (c1, c2, c3, c4)")
    for name, idx in (corners or {}).items():
        arr = indices(idx, f"corners[{name}]")
        keep.append(arr)
        setattr(desc, f"{name}_corners", ptr(arr))
        setattr(desc, f"{name}_num_corners", len(arr))
    opts = Options(samples=(along or 12, around or 16), **settings)
    return build("profsubd_profile_build", ctypes.byref(desc), options=opts)


def revolve(profile: Points, *, samples_profile: int = 16, samples_around: int = 32, **settings: Any) -> Model:
    """Surface of revolution: ``profile`` (n, 2) points ``(r, z)``, bottom to top, ``r >= 0``,
    turned about the z axis. Settings (``profsubd revolve``'s JSON keys): ``angle_deg``
    (default 360), ``corners`` (profile point indices), ``caps`` (``"open"``/``"flat"``),
    ``interpolation``, ``sharp_angle_deg``, ``crease_sharpness``, ``boundary``,
    ``crease_method``."""
    p = points(profile, 2, "profile")
    opts = Options(samples=(samples_profile, samples_around), **settings)
    return build("profsubd_revolve", ptr(p), len(p), options=opts)


def sweep(
    profile: Points, trajectory: Points, *, samples_profile: int = 16, samples_trajectory: int = 32, **settings: Any
) -> Model:
    """Sweep: planar ``profile`` (n, 2) points ``(a, b)`` (along the frame's normal and
    binormal) moved along ``trajectory`` (m, 3). Settings (``profsubd sweep``'s JSON keys):
    ``closed_profile``, ``closed_trajectory``, ``frame`` (``"fixed"``, ``"frenet"``,
    ``"rmf"``), ``scale`` ``[start, end]``, ``profile_end`` (n, 2), ``corners``
    (``{"profile": [...], "trajectory": [...]}``), ``interpolation``, ``sharp_angle_deg``,
    ``crease_sharpness``, ``boundary``, ``crease_method``."""
    p = points(profile, 2, "profile")
    t = points(trajectory, 3, "trajectory")
    opts = Options(samples=(samples_profile, samples_trajectory), **settings)
    return build("profsubd_sweep", ptr(p), len(p), ptr(t), len(t), options=opts)


def curves(
    boundary: Sequence[Points],
    interior: Sequence[Points] = (),
    *,
    tau: float = 2.0,
    samples: Tuple[int, int] = (16, 16),
    projection: Any = "auto",
    method: str = "attraction",
    **settings: Any,
) -> Model:
    """Patch through unorganized 3-D sketch curves (Qin & Wright): ``boundary`` 3 or 4 curves
    (each (n, 3)) in order around the patch, ``interior`` any number of curves, ``tau`` the
    attraction exponent, ``samples`` quads ``(nu, nv)`` along the first and second boundary
    curve, ``projection`` ``"auto"`` (best-fit plane) or the plane's normal (3 numbers),
    ``method`` ``"attraction"`` (the paper's blend) or ``"fair"`` (vertices off the curves
    minimize the bending energy; ``tau`` unused). Settings: ``interpolation``, ``crease_method`` and ``boundary_interpolation`` (the
    boundary rule: ``boundary`` names the curves here) — as ``profsubd curves``' JSON input
    and flags."""
    if "boundary_interpolation" in settings:
        settings["boundary"] = settings.pop("boundary_interpolation")
    arrays = [points(c, 3, f"boundary[{i}]") for i, c in enumerate(boundary)]
    arrays += [points(c, 3, f"interior[{i}]") for i, c in enumerate(interior)]
    flat = np.ascontiguousarray(np.concatenate(arrays) if arrays else np.zeros((0, 3)))
    sizes = np.array([len(a) for a in arrays], dtype=np.uintp)
    if isinstance(projection, str):
        if projection != "auto":
            raise ValueError(f'curves: projection must be "auto" or a normal, got {projection!r}')
        normal = None
    else:
        normal = points([projection], 3, "projection").reshape(3)
    opts = Options(samples=tuple(samples), **settings)
    normal_ptr = None if normal is None else ptr(normal)
    if method == "fair":
        return build(
            "profsubd_curves_fair", ptr(flat), ptr(sizes), len(boundary), len(interior), normal_ptr, options=opts
        )
    if method != "attraction":
        raise ValueError(f'curves: method must be "attraction" or "fair", got {method!r}')
    return build(
        "profsubd_curves", ptr(flat), ptr(sizes), len(boundary), len(interior), float(tau), normal_ptr, options=opts
    )


def blend(
    pipes: Sequence[Mapping[str, Any]],
    *,
    columns: int = 4,
    order: int = 4,
    tension: Optional[float] = None,
    alpha: float = 0.5,
    k_alpha: float = 0.5,
    gbs_level: int = 1,
    **settings: Any,
) -> Model:
    """N-way blend of pipes by generalized B-spline subdivision, as a fitted Catmull–Clark
    mesh: ``pipes`` a list of ``{"end": (x, y, z), "axis": (x, y, z), "radius": r, "length":
    l}`` (3 to 8), ``columns`` (control points round a pipe, 3..16), ``order`` (3..8),
    ``tension`` (None: the pipes' exact circles, cos(pi/columns)),
    ``alpha`` (centre), ``k_alpha`` (valleys), ``gbs_level`` — the keys of ``profsubd
    blend``'s JSON input; settings ``boundary``, ``crease_method``."""
    rows = []
    for i, p in enumerate(pipes):
        unknown = set(p) - {"end", "axis", "radius", "length"}
        if unknown:
            raise ValueError(f"pipes[{i}]: unknown keys {sorted(unknown)}")
        rows.append([*p["end"], *p["axis"], p["radius"], p["length"]])
    arr = points(rows if rows else np.zeros((0, 8)), 8, "pipes")
    t = float("nan") if tension is None else float(tension)
    return build(
        "profsubd_blend", ptr(arr), len(arr), int(columns), int(order), t, float(alpha), float(k_alpha), int(gbs_level),
        options=Options(**settings),
    )


def shell(
    mesh: Mesh, thickness: float, *, level: int = 0, tolerance: float = 0.0, outward: bool = False,
    accept_folds: bool = False,
) -> Model:
    """Hollow solid of ``mesh`` (its tags give the subdivision options): outer wall, inner wall
    at the offset by ``thickness`` (inward unless ``outward``), a creased rim for open
    surfaces; the offset taken ``level`` levels finer, or at the level that meets
    ``tolerance`` (absolute; 0: none). Folding offsets are refused unless ``accept_folds``."""
    flags = (constant("PROFSUBD_OFFSET_OUTWARD") if outward else 0) | (
        constant("PROFSUBD_OFFSET_ACCEPT_FOLDS") if accept_folds else 0
    )
    return build("profsubd_shell", mesh._ptr, float(thickness), int(level), float(tolerance), int(flags), options=None)
