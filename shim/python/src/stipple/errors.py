# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""The package's exceptions: StippleError and, under it, one subclass per kind of failure that is also the built-in
exception Python users catch (ValueError, TypeError, OSError, MemoryError, RuntimeError)."""

# The C ABI's status codes (stipple.h).
OK = 0
NULL_ARGUMENT = 1
INVALID_ARGUMENT = 2
OUT_OF_RANGE = 3
STRUCT_SIZE = 4
ABI_VERSION = 5
OUT_OF_MEMORY = 6
INTERNAL = 7

STATUS_NAMES = {NULL_ARGUMENT: "null argument", INVALID_ARGUMENT: "invalid argument", OUT_OF_RANGE: "out of range",
                STRUCT_SIZE: "struct size", ABI_VERSION: "ABI version", OUT_OF_MEMORY: "out of memory",
                INTERNAL: "internal error"}


class StippleError(Exception):
    """A failed call: the library's status and message, or an argument this package refused before the call.

    ``StippleError(status, message)`` is an instance of the subclass for the status, as ``OSError(errno, ...)`` is,
    so each failure is also the built-in exception a Python user catches:

    ============================================  =====================================================
    ``ArgumentError`` (``ValueError``)            invalid or out-of-range argument (``INVALID_ARGUMENT``,
                                                  ``OUT_OF_RANGE``, ``NULL_ARGUMENT``)
    ``ArgumentTypeError`` (``TypeError``)         an argument of the wrong type (``"1"`` for an integer)
    ``LibraryError`` (``OSError``)                the library cannot be loaded (status ``None``) or is of
                                                  another ABI (``ABI_VERSION``, ``STRUCT_SIZE``)
    ``StippleMemoryError`` (``MemoryError``)      ``OUT_OF_MEMORY``
    ``InternalError`` (``RuntimeError``)          ``INTERNAL``: a defect of the library
    ============================================  =====================================================

    Attributes:
        status (int | None): the C status (``stipple.errors.OUT_OF_RANGE`` ...); None when the library could not
            be loaded at all.
        message (str): the library's message (it names the argument, its value and what was expected), or the
            package's own message in the same form.
    """

    def __new__(cls, status=None, message="", *args):
        if cls is StippleError:
            cls = _CLASS_FOR_STATUS.get(status, StippleError)
        if issubclass(cls, MemoryError):
            return Exception.__new__(cls)  # MemoryError's own __new__ keeps a free list of plain MemoryErrors
        return super().__new__(cls, status, message)

    def __init__(self, status=None, message="", *args):
        self.status = status
        self.message = message
        self.args = (status, message)

    def __str__(self):
        if self.status is None:
            return self.message
        return f"{STATUS_NAMES.get(self.status, f'status {self.status}')}: {self.message}"


class ArgumentError(StippleError, ValueError):
    """An argument refused: invalid, out of range or missing."""


class ArgumentTypeError(StippleError, TypeError):
    """An argument of the wrong type (a str or float where an integer is expected, ...)."""


class LibraryError(StippleError, OSError):
    """libstipple.so.1 could not be loaded, or it is not of an ABI this package can use."""


class StippleMemoryError(StippleError, MemoryError):
    """The library or the package could not allocate what the call needs."""


class InternalError(StippleError, RuntimeError):
    """A defect of the library (please report it)."""


_CLASS_FOR_STATUS = {NULL_ARGUMENT: ArgumentError, INVALID_ARGUMENT: ArgumentError, OUT_OF_RANGE: ArgumentError,
                     STRUCT_SIZE: LibraryError, ABI_VERSION: LibraryError, None: LibraryError,
                     OUT_OF_MEMORY: StippleMemoryError, INTERNAL: InternalError}
