// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Temporary files and folders that become outputs by rename. Every temporary is named
//   <dir>/.<target name>.stipple-tmp-<host>-<pid>-<n>[<extension>]
// beside its target (same file system, so the rename is atomic), registered while it exists, removed when the
// process gets SIGINT / SIGTERM / SIGHUP, and swept by the next run when its process is gone (SIGKILL).
#pragma once

#include <string>

namespace stipple::render {

// A fresh temporary name beside `target`, keeping its extension (OIIO picks the format from it).
std::string tempPathBeside(const std::string& target);

// True when `name` (a file name, no folder) has the temporary pattern above.
bool isTempName(const std::string& name);

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove every registered temporary and then end the
// process with the signal's usual status. The handler only writes to a pipe (async-signal-safe); a cleanup
// thread does the removal, so folders are removed whole. Idempotent.
void installTempCleanupOnSignals();

// A child's process group (its leader's pid) that the signal cleanup kills (SIGKILL) and reaps before it removes the
// temporaries: a program the process started, with its own children, does not outlive an interrupted run.
void registerChildGroup(int pgid);
void unregisterChildGroup(int pgid);

// Removes temporaries in `dir` (not recursive) whose process has ended: same host and no such pid, or older
// than a day from another host. Returns how many were removed. A missing folder is not an error.
// Only what this process could have written is touched: a name of the pattern above, owned by the effective
// user, a regular file or a folder (never a symlink, FIFO or device). Anything else with such a name (another
// user's, planted in a shared sticky folder) is left alone and named in a warning on stderr.
size_t sweepStaleTemps(const std::string& dir);

// True when `path` (not followed if a symlink) is a regular file (or, with `folderToo`, a folder) owned by the
// effective user; otherwise false and `why` says what it is instead.
bool isOwnFile(const std::string& path, bool folderToo, std::string& why);

// The one warning for something a sweep or a journal recovery leaves alone: "warning: left PATH alone: WHY".
void warnLeftAlone(const std::string& path, const std::string& why);

// When the file system holding `path` (or its nearest existing parent) has less than 1 MiB free: a note for an
// error message, " (no space left on device? N bytes free on the file system of DIR)"; otherwise empty. Libraries
// that write files (OIIO) often lose errno on a full disk; this names the likely cause after a failed write.
std::string fullDiskNote(const std::string& path);

// A registered temporary: removed (file or folder) on destruction unless released after its rename.
class TempPath {
public:
    explicit TempPath(const std::string& target);
    ~TempPath();
    TempPath(const TempPath&) = delete;
    TempPath& operator=(const TempPath&) = delete;
    const std::string& path() const { return path_; }
    // The temporary has been renamed into place: forget it.
    void release();

private:
    std::string path_;
    bool released_ = false;
};

// Defers the signal cleanup while alive. Two uses: a group of renames (an EXR and its PNG) is not cut in half by a
// SIGINT / SIGTERM, and a temporary is created, written and closed under one, so it cannot appear after the cleanup
// removed it (once the cleanup has begun, a new SignalHold waits until the process ends). Several threads may hold
// one at once; a thread must not take a second while it holds one.
class SignalHold {
public:
    SignalHold();
    ~SignalHold();
    SignalHold(const SignalHold&) = delete;
    SignalHold& operator=(const SignalHold&) = delete;

private:
    // Holds, shared, the lock the cleanup thread takes exclusively.
};

} // namespace stipple::render
