// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "sampling/shim_loader.h"

#include <stipple/render/content_hash.h>
#include <stipple/stipple.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace stipple::render {

namespace {

std::string exeDirectory() {
    char buf[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
    if (n <= 0) return {};
    std::string exe(buf, size_t(n));
    size_t slash = exe.rfind('/');
    return slash == std::string::npos ? std::string{} : exe.substr(0, slash);
}

// The renderer needs ABI 1.1 or later (stipple.hpp's Sampler, which PixelSampler holds, needs the 1.1 table): a
// table up to sampler_stream_fill. A 1.0 library is refused with this size in the message.
constexpr size_t kMinimumApiSize = offsetof(stipple_api, sampler_stream_fill) + sizeof(stipple_api::sampler_stream_fill);

} // namespace

// Loaded libraries stay loaded for the life of the process (a table pointer may be held anywhere).
const ShimLibrary& ShimLibrary::get(const std::string& explicitPath) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<ShimLibrary>> loaded;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = loaded.find(explicitPath);
    if (found != loaded.end()) return *found->second;

    std::vector<std::pair<std::string, std::string>> candidates; // (path, where it came from)
    if (!explicitPath.empty()) {
        candidates.push_back({explicitPath, "--shim"});
    } else {
        // One variable across front ends (the Python package reads it too); STIPPLE_SHIM is its older alias.
        for (const char* variable : {"STIPPLE_LIBRARY", "STIPPLE_SHIM"}) {
            const char* env = std::getenv(variable);
            if (!env || !*env) continue;
            std::string path = env;
            std::error_code ec;
            if (std::filesystem::is_directory(path, ec)) // a folder holding the library, or its lib/
                path += std::filesystem::exists(path + "/libstipple.so.1", ec) ? "/libstipple.so.1"
                                                                                 : "/lib/libstipple.so.1";
            candidates.push_back({path, variable});
            break;
        }
        std::string dir = exeDirectory();
        if (!dir.empty()) {
            candidates.push_back({dir + "/../lib/libstipple.so.1", "<exe dir>/../lib"});
            candidates.push_back({dir + "/libstipple.so.1", "<exe dir>"});
        }
        candidates.push_back({"libstipple.so.1", "the dynamic linker's search path"});
    }
    std::string tried;
    for (const auto& [path, origin] : candidates) {
        std::string why;
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* e = dlerror();
            tried += "\n  " + path + " (" + origin + "): " + (e ? e : "dlopen failed");
            // An explicit choice that fails is an error, not a reason to pick some other library.
            if (!explicitPath.empty() || origin == "STIPPLE_LIBRARY" || origin == "STIPPLE_SHIM") break;
            continue;
        }
        auto getApi = reinterpret_cast<stipple_get_api_fn>(dlsym(handle, "stipple_get_api"));
        if (!getApi) {
            tried += "\n  " + path + " (" + origin + "): no symbol stipple_get_api (not a libstipple?)";
            dlclose(handle);
            break;
        }
        const stipple_api* api = nullptr;
        stipple_status st = getApi(STIPPLE_ABI_MAJOR, &api);
        if (st != STIPPLE_OK || !api) {
            tried += "\n  " + path + " (" + origin + "): stipple_get_api(" + std::to_string(STIPPLE_ABI_MAJOR) +
                     ") failed with status " + std::to_string(st) + " (this renderer needs ABI major " +
                     std::to_string(STIPPLE_ABI_MAJOR) + ")";
            dlclose(handle);
            break;
        }
        if (api->struct_size < kMinimumApiSize || api->abi_major != STIPPLE_ABI_MAJOR) {
            tried += "\n  " + path + " (" + origin + "): function table of size " + std::to_string(api->struct_size) +
                     " and ABI major " + std::to_string(api->abi_major) +
                     "; expected size >= " + std::to_string(kMinimumApiSize) + " and major " +
                     std::to_string(STIPPLE_ABI_MAJOR);
            dlclose(handle);
            break;
        }
        auto lib = std::unique_ptr<ShimLibrary>(new ShimLibrary(api, path));
        const ShimLibrary& ref = *lib;
        loaded[explicitPath] = std::move(lib);
        return ref;
    }
    throw ShimError("cannot load libstipple (the sample-stream library); tried:" + tried +
                    "\n  (set --shim PATH or STIPPLE_LIBRARY to the library or its folder)");
}

std::string ShimLibrary::version() const {
    uint32_t major = 0, minor = 0, patch = 0;
    if (api_->get_version(&major, &minor, &patch) != STIPPLE_OK) return "unknown";
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

std::string ShimLibrary::identity() const {
    std::call_once(identityOnce_, [this] { identity_ = hashIdentity(); }); // once: the loaded code does not change
    return identity_;
}

std::string ShimLibrary::hashIdentity() const {
    // The file the dynamic linker actually mapped (path_ may be a bare soname it resolved).
    Dl_info info{};
    std::string file = path_;
    if (dladdr(reinterpret_cast<void*>(api_->get_version), &info) && info.dli_fname) file = info.dli_fname;
    ContentHash hash;
    if (!hash.addFile(file)) return "libstipple " + version() + " (unreadable: " + file + ")";
    const std::string hex = hash.hex();
    return "libstipple " + version() + " " + hex;
}

std::vector<std::string> ShimLibrary::patternNames() const {
    std::vector<std::string> names;
    if (stipple::patternNames(names, *api_).ok()) return names; // ABI 1.2: the library's own listing
    names.clear();
    for (uint32_t p = 0; p < STIPPLE_PATTERN_COUNT; ++p) { // 1.1: the ids this header knows
        const char* name = nullptr;
        if (api_->pattern_name(p, &name) != STIPPLE_OK || !name) break; // an older library serves fewer
        names.emplace_back(name);
    }
    return names;
}

std::string ShimLibrary::lastError() const {
    const char* m = api_->last_error_message();
    return m ? m : "";
}

} // namespace stipple::render
