// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// error.cpp — the per-thread error message.
#include "error.h"

#include <cstdio>

namespace stipple::detail {

namespace {
// A fixed buffer: recording an out-of-memory error must not itself allocate.
thread_local char tLastError[1024] = "";
} // namespace

void setLastError(const char* function, const char* message) noexcept {
    std::snprintf(tLastError, sizeof tLastError, "%s: %s", function ? function : "stipple", message ? message : "");
}

void setInternalError(const char* function, const char* message) noexcept {
#ifndef STIPPLE_VERSION_PATCH
#define STIPPLE_VERSION_PATCH 0
#endif
    std::snprintf(tLastError, sizeof tLastError,
                  "%s: internal error: %s (a bug in libstipple %d.%d.%d: please send this message and the library "
                  "version to the stipple maintainers through the project's issue tracker; see CHANGELOG.md)",
                  function ? function : "stipple", message ? message : "", STIPPLE_ABI_MAJOR, STIPPLE_ABI_MINOR,
                  STIPPLE_VERSION_PATCH);
}

const char* lastErrorMessage() noexcept { return tLastError; }

} // namespace stipple::detail
