// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// What the command-line fuzz harnesses share: libFuzzer bytes as an argument vector, and a check that stops the
// fuzzer on a broken promise.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace stipple::testing {

// The input split at NUL bytes into arguments after a program name; at most `maxArguments` (the rest is ignored),
// so the harness explores the parser, not the vector.
inline std::vector<std::string> argumentsFromFuzzInput(const uint8_t* data, size_t size, size_t maxArguments = 64) {
    std::vector<std::string> argv(1);
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            if (argv.size() == maxArguments) break;
            argv.emplace_back();
        } else {
            argv.back() += char(data[i]);
        }
    }
    return argv;
}

// A harness's invariant: trap (a finding with its reproducer) when it does not hold.
inline void fuzzRequire(bool condition) {
    if (!condition) __builtin_trap();
}

} // namespace stipple::testing
