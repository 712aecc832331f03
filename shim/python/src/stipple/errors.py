# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""The package's one exception type, for the library's failures and for arguments refused before any call."""

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

    Attributes:
        status (int | None): the C status (``stipple.errors.OUT_OF_RANGE`` ...); None when the library could not
            be loaded at all.
        message (str): the library's message (it names the argument, its value and what was expected), or the
            package's own message in the same form.
    """

    def __init__(self, status, message):
        super().__init__(message if status is None else
                         f"{STATUS_NAMES.get(status, f'status {status}')}: {message}")
        self.status = status
        self.message = message
