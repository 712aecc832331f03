// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/file_lock.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stipple::validation {

FileLock::FileLock(const std::string& path) {
    // Never through a symlink (one planted in the cache would create or truncate a file elsewhere), never a FIFO
    // or device (open would block, or lock something else).
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd_ < 0)
        throw std::runtime_error("cannot open lock file " + path + ": " +
                                 (errno == ELOOP ? std::string("it is a symlink") : std::strerror(errno)));
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd_);
        throw std::runtime_error("lock file " + path + " is not a regular file");
    }
    int rc;
    while ((rc = ::flock(fd_, LOCK_EX)) != 0 && errno == EINTR) {}
    if (rc != 0) {
        const int err = errno;
        ::close(fd_);
        throw std::runtime_error("cannot lock " + path + ": " + std::strerror(err));
    }
}

FileLock::~FileLock() {
    if (fd_ >= 0) ::close(fd_); // closing the last descriptor releases the lock
}

} // namespace stipple::validation
