// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// consumer_dlopen.cpp — a dlopen host of the installed package (stipple::headers only, nothing linked): the kit
// over the function table of the library named on the command line.
#include <stipple/stipple.hpp>

#include <dlfcn.h>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: consumer_dlopen <libstipple.so.1>\n");
        return 2;
    }
    void* library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        std::fprintf(stderr, "consumer_dlopen: %s\n", dlerror());
        return 1;
    }
    stipple_get_api_fn getApi = reinterpret_cast<stipple_get_api_fn>(dlsym(library, "stipple_get_api"));
    const stipple_api* api = nullptr;
    if (!getApi || getApi(STIPPLE_ABI_MAJOR, &api) != STIPPLE_OK) return 1;
    stipple::Sampler sampler;
    const stipple::Status status = stipple::Sampler::create(sampler, "sobol", 16, 1, 0, *api);
    float uv[2];
    if (!status.ok() || !sampler.stream(stipple::Pixel{0, 0}, 0, 0, 2, uv).ok()) {
        std::fprintf(stderr, "consumer_dlopen: %s\n", status.message().c_str());
        return 1;
    }
    std::printf("consumer_dlopen: a sobol value through stipple::headers and dlopen\n");
    return 0;
}
