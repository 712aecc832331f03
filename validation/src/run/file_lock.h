// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// An exclusive advisory lock on a file (flock), held for the object's lifetime: several processes — shards of
// one array job on one machine or on a shared filesystem — that need the same reference take turns, so one
// renders it and the others read what it published.
#pragma once

#include <string>

namespace stipple::validation {

class FileLock {
public:
    // Creates `path` if needed and blocks until the lock is held. Throws std::runtime_error naming the file.
    explicit FileLock(const std::string& path);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

private:
    int fd_ = -1;
};

} // namespace stipple::validation
