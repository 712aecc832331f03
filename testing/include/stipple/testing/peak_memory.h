// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The peak memory a piece of work adds, measured in a child process: fork, note the child's ru_maxrss (which
// starts at the resident size it inherits), run the work, note it again and send the difference back. Sanitizer
// builds (shadow memory, quarantine, redzones) change what memory means: tests skip there (kUnderSanitizer).
#pragma once

#include "stipple/testing/sanitizers.h"

#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace stipple::testing {

// Bytes by which `work` raised the peak resident size of a child process running it; nullopt when the child
// failed (an exception from `work`, a crash). `work` runs in the child only: nothing it changes comes back.
inline std::optional<uint64_t> peakGrowthInChild(const std::function<void()>& work) {
    int fds[2];
    if (pipe(fds) != 0) return std::nullopt;
    const pid_t pid = fork();
    if (pid < 0) return std::nullopt;
    if (pid == 0) {
        close(fds[0]);
        struct rusage before {
        }, after{};
        getrusage(RUSAGE_SELF, &before);
        int status = 0;
        try {
            work();
        } catch (const std::exception&) {
            status = 3;
        }
        getrusage(RUSAGE_SELF, &after);
        const uint64_t grown = uint64_t(after.ru_maxrss - before.ru_maxrss) * 1024; // ru_maxrss is in KiB
        if (write(fds[1], &grown, sizeof grown) != ssize_t(sizeof grown)) status = 4;
        _exit(status);
    }
    close(fds[1]);
    uint64_t grown = 0;
    const bool got = read(fds[0], &grown, sizeof grown) == ssize_t(sizeof grown);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
    return grown;
}

} // namespace stipple::testing
