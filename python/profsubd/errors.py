"""Errors: one :class:`ProfsubdError` subclass per ``profsubd_status`` of the C API.

Every failing call raises the subclass of its status with the library's own message (its
``profsubd_last_error_message()``); ``err.status`` is the numeric status, ``err.message``
the library's message.
"""

from __future__ import annotations

from typing import Dict, Type

from ._lib import last_message, lib


class ProfsubdError(Exception):
    """A call into libprofsubd failed; ``status`` is its ``profsubd_status``, ``message`` the
    library's message."""

    status: int = -1

    def __init__(self, message: str, status: int | None = None) -> None:
        super().__init__(message)
        self.message = message
        if status is not None:
            self.status = status


class NullArgumentError(ProfsubdError):
    """``PROFSUBD_ERROR_NULL_ARGUMENT``: a required pointer was NULL."""

    status = 1


class InvalidArgumentError(ProfsubdError, ValueError):
    """``PROFSUBD_ERROR_INVALID_ARGUMENT``: an argument out of its documented range."""

    status = 2


class InvalidMeshError(ProfsubdError, ValueError):
    """``PROFSUBD_ERROR_INVALID_MESH``: data OpenSubdiv could not take as a mesh."""

    status = 3


class NonManifoldError(ProfsubdError, ValueError):
    """``PROFSUBD_ERROR_NON_MANIFOLD``: the operation needs a 2-manifold mesh."""

    status = 4


class ProfsubdIOError(ProfsubdError, OSError):
    """``PROFSUBD_ERROR_IO``: reading or writing a file failed."""

    status = 5


class ParseError(ProfsubdError, ValueError):
    """``PROFSUBD_ERROR_PARSE``: a malformed file (the message gives file and line)."""

    status = 6


class BufferTooSmallError(ProfsubdError):
    """``PROFSUBD_ERROR_BUFFER_TOO_SMALL`` (the package sizes buffers itself: a bug if seen)."""

    status = 7


class NumericalError(ProfsubdError, ArithmeticError):
    """``PROFSUBD_ERROR_NUMERICAL``: a singular system or a fit that missed its tolerance."""

    status = 8


class InvalidHandleError(ProfsubdError):
    """``PROFSUBD_ERROR_INVALID_HANDLE``: a handle of another kind, or freed."""

    status = 9


class CancelledError(ProfsubdError):
    """``PROFSUBD_ERROR_CANCELLED``: the options' progress callback asked to stop."""

    status = 10


class LimitExceededError(ProfsubdError, MemoryError):
    """``PROFSUBD_ERROR_LIMIT_EXCEEDED``: a size ceiling or the memory budget was exceeded."""

    status = 11


class InternalError(ProfsubdError):
    """``PROFSUBD_ERROR_INTERNAL``: a bug in profsubd was caught (a Rust panic)."""

    status = 99


ERRORS: Dict[int, Type[ProfsubdError]] = {
    cls.status: cls
    for cls in (
        NullArgumentError,
        InvalidArgumentError,
        InvalidMeshError,
        NonManifoldError,
        ProfsubdIOError,
        ParseError,
        BufferTooSmallError,
        NumericalError,
        InvalidHandleError,
        CancelledError,
        LimitExceededError,
        InternalError,
    )
}


def check(status: int) -> None:
    """Raise the error of a non-zero ``status``, with the thread's last library message."""
    if status == 0:
        return
    message = last_message()
    if not message:
        raw = lib.profsubd_status_string(status)
        message = raw.decode() if raw else f"status {status}"
    raise ERRORS.get(status, ProfsubdError)(message, status)
