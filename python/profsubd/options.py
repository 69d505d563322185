"""The options object (``profsubd_options``): subdivision rules and construction settings.

Settings are keyword arguments named as in the constructions' JSON inputs, so
``profsubd.sweep(**json.load(f))`` reads a JSON file the command line reads too. Each key
maps to one C setter in :data:`SETTERS` (a grouped setter, such as
``profsubd_options_set_sweep_closed``, takes several keys); a new C setter is one line there.
"""

from __future__ import annotations

import ctypes
from typing import Any, Callable, Dict, Mapping, Optional, Sequence, Tuple

import numpy as np

from ._handle import Handle, as_array, ptr
from ._lib import enum_values, lib
from .errors import check

INFINITE_SHARPNESS = 10.0
"""Sharpness 10 and above is infinitely sharp (OpenSubdiv's ``SHARPNESS_INFINITE``)."""


def _enum(enum: str, prefix: str) -> Callable[[Any], Tuple[int]]:
    names = enum_values(enum, prefix)

    def convert(value: Any) -> Tuple[int]:
        if isinstance(value, str):
            key = value.lower().replace("_", "-")
            if key not in names:
                raise ValueError(f"{value!r}: expected one of {', '.join(sorted(names))}")
            return (names[key],)
        return (int(value),)

    convert.__doc__ = " | ".join(f'"{n}"' for n in names)
    return convert


def _sharpness(value: Any) -> Tuple[float]:
    if isinstance(value, str):
        if value != "infinite":
            raise ValueError(f'crease_sharpness {value!r}: a number >= 0 or "infinite"')
        return (INFINITE_SHARPNESS,)
    return (float(value),)


def _points2(value: Any) -> Tuple[Optional[int], int, np.ndarray]:
    arr = as_array(value if value is not None else np.empty((0, 2)), np.float64, (2,), "profile_end")
    return (ptr(arr), len(arr), arr)


def _sweep_corners(value: Any) -> Tuple[Any, ...]:
    # A list: profile corners (revolutions); a mapping: {"profile": [...], "trajectory": [...]}.
    if isinstance(value, Mapping):
        unknown = set(value) - {"profile", "trajectory"}
        if unknown:
            raise ValueError(f"corners: unknown keys {sorted(unknown)} (profile, trajectory)")
        prof, traj = value.get("profile", []), value.get("trajectory", [])
    else:
        prof, traj = value, []
    p = as_array(prof, np.uint32, name="corners")
    t = as_array(traj, np.uint32, name="corners")
    return (ptr(p), len(p), ptr(t), len(t), p, t)


# key(s) -> (C setter, converter of the key values into the setter's arguments after the
# options handle, default of each key when a grouped setter gets only some of them).
SETTERS: Dict[Tuple[str, ...], Tuple[str, Callable[..., Tuple[Any, ...]], Tuple[Any, ...]]] = {
    ("boundary",): ("profsubd_options_set_boundary", _enum("profsubd_boundary", "PROFSUBD_BOUNDARY_"), ()),
    ("crease_method",): ("profsubd_options_set_crease_method", _enum("profsubd_crease_method", "PROFSUBD_CREASE_"), ()),
    ("triangles",): ("profsubd_options_set_triangle_rule", _enum("profsubd_triangle_rule", "PROFSUBD_TRIANGLES_"), ()),
    ("vertex_order",): ("profsubd_options_set_vertex_order", _enum("profsubd_vertex_order", "PROFSUBD_ORDER_"), ()),
    ("sharp_angle_deg",): ("profsubd_options_set_sharp_angle", lambda d: (float(d),), ()),
    ("crease_sharpness",): ("profsubd_options_set_crease_sharpness", _sharpness, ()),
    ("interpolation",): ("profsubd_options_set_interpolation", _enum("profsubd_interpolation", "PROFSUBD_INTERPOLATION_"), ()),
    ("caps",): ("profsubd_options_set_caps", _enum("profsubd_caps", "PROFSUBD_CAPS_"), ()),
    ("angle_deg",): ("profsubd_options_set_revolve_angle", lambda d: (float(d),), ()),
    ("closed_profile", "closed_trajectory"): (
        "profsubd_options_set_sweep_closed", lambda p, t: (int(bool(p)), int(bool(t))), (False, False)),
    ("frame",): ("profsubd_options_set_sweep_frame", _enum("profsubd_sweep_frame", "PROFSUBD_FRAME_"), ()),
    ("scale",): ("profsubd_options_set_sweep_scale", lambda s: (float(s[0]), float(s[1])), ()),
    ("profile_end",): ("profsubd_options_set_sweep_profile_end", _points2, ()),
    ("corners",): ("profsubd_options_set_sweep_corners", _sweep_corners, ()),
}

SUBDIVISION_KEYS = ("boundary", "crease_method", "triangles", "vertex_order")
"""The keys that set subdivision rules (for meshes, evaluators, refinement, stencils)."""


class Options(Handle):
    """A ``profsubd_options`` handle. ``Options(boundary="edge-only", crease_method="chaikin")``;
    keys: :data:`SETTERS` (and ``samples=(along, around)``). Values are checked by the
    library: a bad one raises :class:`~profsubd.InvalidArgumentError` with its message."""

    _kind = "profsubd_options"

    def __init__(self, samples: Optional[Sequence[int]] = None, **settings: Any) -> None:
        out = ctypes.c_void_p()
        check(lib.profsubd_options_new(ctypes.byref(out)))
        super().__init__(out.value)
        if samples is not None:
            along, around = samples
            check(lib.profsubd_options_set_samples(self._ptr, int(along), int(around)))
        for keys, (setter, convert, defaults) in SETTERS.items():
            given = [k in settings for k in keys]
            if any(given):
                values = [settings.pop(k) if k in settings else d for k, d in zip(keys, defaults or (None,))]
                args = convert(*values)
                # Converters may append arrays after the C arguments to keep them alive.
                nargs = len(getattr(lib, setter).argtypes) - 1
                check(getattr(lib, setter)(self._ptr, *args[:nargs]))
        if settings:
            raise TypeError(f"unknown setting(s): {', '.join(sorted(settings))}")


def options_or_none(settings: Dict[str, Any]) -> Optional[Options]:
    """An :class:`Options` with ``settings``, or None (the C default) when there are none."""
    return Options(**settings) if settings else None


def optr(options: Optional[Options]) -> Optional[int]:
    """The C pointer of optional options (NULL: the mesh's tags and the defaults)."""
    return options._ptr if options is not None else None
