"""Owned C handles (freed by ``close()``, ``with`` or the garbage collector) and the C API's
copy-out protocol."""

from __future__ import annotations

import ctypes
import weakref
from collections import Counter
from typing import Any, Callable, Optional

import numpy as np

from ._lib import lib
from .errors import check

#: Live handles per C type (``"profsubd_mesh"``...): incremented on creation, decremented
#: when the library's ``_free`` function has been called. For tests and leak hunting.
LIVE: Counter = Counter()


def _release(free: Callable[[int], None], kind: str, address: int) -> None:
    free(address)
    LIVE[kind] -= 1


class Handle:
    """A C handle owned by this object: released exactly once, by :meth:`close`, at the end
    of a ``with`` block, or when the object is collected (a ``weakref.finalize``)."""

    _kind = ""  # the C type, e.g. "profsubd_mesh"; its free function is KIND_free
    _free_name = ""  # a free function not named KIND_free

    def __init__(self, address: Optional[int]) -> None:
        if not address:
            raise ValueError(f"{self._kind}: NULL handle")
        self._address: Optional[int] = address
        free = getattr(lib, self._free_name or f"{self._kind}_free")
        LIVE[self._kind] += 1
        self._finalizer = weakref.finalize(self, _release, free, self._kind, address)

    @classmethod
    def _create(cls, fn: Callable[..., int], *args: Any) -> Any:
        """Call ``fn(*args, &out)`` and wrap ``out``."""
        out = ctypes.c_void_p()
        check(fn(*args, ctypes.byref(out)))
        obj = cls.__new__(cls)
        Handle.__init__(obj, out.value)
        return obj

    @property
    def _ptr(self) -> int:
        if self._address is None:
            raise ValueError(f"{type(self).__name__} is closed")
        return self._address

    @property
    def closed(self) -> bool:
        """Whether the handle has been released."""
        return self._address is None

    def close(self) -> None:
        """Release the C handle now (a no-op when already closed)."""
        self._address = None
        self._finalizer()

    def __enter__(self) -> Any:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def copy_out(fn: Callable[..., int], handle: Any, count: int, dtype: Any, *pre: Any, width: int = 1) -> np.ndarray:
    """``fn(handle, *pre, out, capacity, &needed)`` for ``count`` elements of ``width`` values
    each (the C function's capacity counts elements): a (count,) or (count, width) array."""
    out = np.empty(count * width, dtype=dtype)
    needed = ctypes.c_size_t()
    check(fn(handle, *pre, out.ctypes.data if count else None, count, ctypes.byref(needed)))
    if needed.value != count:
        raise RuntimeError(f"{fn.__name__}: {needed.value} elements, expected {count}")
    return out.reshape(count, width) if width > 1 else out


def copy_out_sized(fn: Callable[..., int], handle: int, dtype: Any, *pre: Any) -> np.ndarray:
    """Copy-out when the count is not known: ask for it with a zero capacity first."""
    needed = ctypes.c_size_t()
    status = fn(handle, *pre, None, 0, ctypes.byref(needed))
    if status not in (0, 7):  # 7: PROFSUBD_ERROR_BUFFER_TOO_SMALL, needed written
        check(status)
    return copy_out(fn, handle, needed.value, dtype, *pre)


def size_getter(fn: Callable[..., int], handle: int) -> int:
    """``fn(handle, &n)`` -> n."""
    n = ctypes.c_size_t()
    check(fn(handle, ctypes.byref(n)))
    return n.value


def as_array(values: Any, dtype: Any, shape_tail: tuple = (), name: str = "array") -> np.ndarray:
    """``values`` as a C-contiguous array of ``dtype`` with trailing shape ``shape_tail``."""
    arr = np.ascontiguousarray(np.asarray(values, dtype=dtype))
    if shape_tail:
        if arr.size == 0:
            arr = arr.reshape((0,) + shape_tail)
        if arr.ndim != 1 + len(shape_tail) or arr.shape[1:] != shape_tail:
            raise ValueError(f"{name}: expected shape (n, {', '.join(map(str, shape_tail))}), got {arr.shape}")
    elif arr.ndim != 1:
        raise ValueError(f"{name}: expected a 1-D array, got shape {arr.shape}")
    return arr


def indices(values: Any, name: str, shape_tail: tuple = ()) -> np.ndarray:
    """Non-negative integers below 2**32 as a uint32 array (refusing what would wrap)."""
    arr = as_array(values, np.int64, shape_tail, name)
    if arr.size and (arr.min() < 0 or arr.max() > 0xFFFFFFFF):
        raise ValueError(f"{name}: indices must be in [0, 2**32)")
    return arr.astype(np.uint32)


def ptr(arr: Optional[np.ndarray]) -> Optional[int]:
    """The address of an array's data (None for None or an empty array)."""
    if arr is None or arr.size == 0:
        return None
    return arr.ctypes.data
