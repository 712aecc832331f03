// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Finds and dlopens libstipple, checks its ABI, and hands out its function table. The renderer never links the
// shim: every random number it uses comes through this table.
#pragma once

#include <stipple/stipple.h>

#include <stdexcept>
#include <mutex>
#include <string>
#include <vector>

namespace stipple::render {

class ShimError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ShimLibrary {
public:
    // Search order: explicitPath (--shim), $STIPPLE_LIBRARY (a file or folder; $STIPPLE_SHIM is its older alias), <exe dir>/../lib/libstipple.so.1,
    // <exe dir>/libstipple.so.1, then the dynamic linker's own search for "libstipple.so.1".
    // Throws ShimError listing every place tried when none loads or the ABI does not match (major 1, minor >= 1).
    static const ShimLibrary& get(const std::string& explicitPath = "");

    const stipple_api& api() const { return *api_; }
    const std::string& path() const { return path_; }
    std::string version() const;
    // "libstipple <version> <hash>": the version and an FNV-1a hash of the loaded file's bytes, so that a cache
    // keyed on it notices a rebuilt library whose version string did not change.
    std::string identity() const;
    // The names of the patterns this library serves, in pattern-id order (stipple_pattern_name).
    std::vector<std::string> patternNames() const;
    // The shim's message for the calling thread's last failure.
    std::string lastError() const;

private:
    std::string hashIdentity() const;
    // The library stays loaded until the process ends (its table is handed out by reference), so no handle is kept.
    ShimLibrary(const stipple_api* api, std::string path) : api_(api), path_(std::move(path)) {}
    const stipple_api* api_ = nullptr;
    std::string path_;
    mutable std::once_flag identityOnce_;
    mutable std::string identity_;
};

} // namespace stipple::render
