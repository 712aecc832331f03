// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// error.h — how failures travel inside the library and how they reach the host.
//
// Inside: code throws stipple::detail::Error (a status + a message naming the argument, its value and what was
// expected). At the C boundary every entry point runs its body through callGuarded(), which turns any exception
// into a status and the calling thread's message. No exception ever crosses into the host.
#pragma once

#include <stipple/stipple.h>

#include <stdexcept>
#include <string>

namespace stipple::detail {

class Error : public std::runtime_error {
public:
    Error(stipple_status status, const std::string& message) : std::runtime_error(message), status_(status) {}
    stipple_status status() const { return status_; }

private:
    stipple_status status_;
};

// Stores the calling thread's message (truncated to a fixed buffer: recording an error never allocates).
void setLastError(const char* function, const char* message) noexcept;
// The same for a failure that is a bug in the library: the message also says so, gives the library's version
// and says where to report it.
void setInternalError(const char* function, const char* message) noexcept;
const char* lastErrorMessage() noexcept;

// Runs body(); maps Error / std::bad_alloc / anything else to a status and records the message.
template <typename Body>
stipple_status callGuarded(const char* function, Body&& body) noexcept {
    try {
        body();
        return STIPPLE_OK;
    } catch (const Error& e) {
        setLastError(function, e.what());
        return e.status();
    } catch (const std::bad_alloc&) {
        setLastError(function, "out of memory");
        return STIPPLE_ERROR_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        setInternalError(function, e.what());
        return STIPPLE_ERROR_INTERNAL;
    } catch (...) {
        setInternalError(function, "unknown internal exception");
        return STIPPLE_ERROR_INTERNAL;
    }
}

// Argument checks used by the ABI layer: each throws Error with a message naming the argument.
inline void requireNonNull(const void* pointer, const char* argument) {
    if (!pointer)
        throw Error(STIPPLE_ERROR_NULL_ARGUMENT, std::string(argument) + " is NULL; expected a valid pointer");
}

} // namespace stipple::detail
