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

const char* lastErrorMessage() noexcept { return tLastError; }

} // namespace stipple::detail
