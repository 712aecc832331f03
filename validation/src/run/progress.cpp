// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/progress.h"

#include <stipple/render/progress_bar.h>

#include <cstdio>
#include <unistd.h>

namespace stipple::validation {

using Clock = std::chrono::steady_clock;

namespace {
bool quietProgress = false;
}

void Progress::setQuiet(bool quiet) { quietProgress = quiet; }

Progress::Progress(size_t cells, double totalWork)
    : cells_(cells), total_(totalWork), tty_(isatty(STDERR_FILENO)), start_(Clock::now()) {}

Progress::~Progress() {
    if (taskRunning_) endTask(true);
}

double Progress::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_ - paused_).count(); }

std::string Progress::eta(double extraDone) const {
    const double done = done_ + extraDone;
    if (!(done > 0)) return "?";
    const double remaining = std::max(elapsed() / done * (total_ - done), 0.0);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%dm%02ds", int(remaining) / 60, int(remaining) % 60);
    return buf;
}

void Progress::step(const std::string& what, double work) {
    std::lock_guard lock(mutex_);
    ++cellsDone_;
    done_ += work;
    if (quietProgress) return;
    if (tty_) {
        std::fprintf(stderr, "\r\033[K%s %zu/%zu cells, ETA %s  %.60s",
                     render::progressBar(size_t(done_), size_t(total_)).c_str(), cellsDone_, cells_, eta().c_str(),
                     what.c_str());
        barShown_ = true;
    } else {
        std::fprintf(stderr, "[%zu/%zu] %s (ETA %s)\n", cellsDone_, cells_, what.c_str(), eta().c_str());
    }
    std::fflush(stderr);
}

void Progress::note(const std::string& message) {
    if (quietProgress && !message.starts_with("ERROR")) return;
    std::lock_guard lock(mutex_);
    if (tty_ && barShown_) std::fprintf(stderr, "\r\033[K");
    std::fprintf(stderr, "%s\n", message.c_str());
    barShown_ = false;
    std::fflush(stderr);
}

void Progress::beginTask(const std::string& what, double work) {
    if (taskRunning_) endTask(true);
    {
        std::lock_guard lock(mutex_);
        task_ = what;
        taskWork_ = work;
        taskStart_ = Clock::now();
        taskRunning_ = true;
    }
    heartbeat_ = std::thread([this] { heartbeat(); });
}

void Progress::endTask(bool rendered) {
    {
        std::lock_guard lock(mutex_);
        if (!taskRunning_) return;
        taskRunning_ = false;
        if (rendered)
            done_ += taskWork_;
        else
            total_ -= taskWork_;
    }
    wake_.notify_all();
    if (heartbeat_.joinable()) heartbeat_.join();
}

void Progress::heartbeat() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::seconds(kHeartbeatSeconds), [this] { return !taskRunning_; })) {
        if (quietProgress) continue;
        const double s = std::chrono::duration<double>(Clock::now() - taskStart_).count();
        if (tty_ && barShown_) std::fprintf(stderr, "\r\033[K");
        // The ETA counts the task as done: until it is, it is a lower bound.
        std::fprintf(stderr, "  %s: %.0f s so far (run ETA after it: %s)\n", task_.c_str(), s,
                     eta(taskWork_).c_str());
        barShown_ = false;
        std::fflush(stderr);
    }
}

void Progress::pause() {
    if (isPaused_) return;
    isPaused_ = true;
    pausedAt_ = Clock::now();
}

void Progress::resume() {
    if (!isPaused_) return;
    isPaused_ = false;
    paused_ += Clock::now() - pausedAt_;
}

void Progress::finish() {
    if (taskRunning_) endTask(true);
    if (tty_ && barShown_) std::fprintf(stderr, "\n");
    barShown_ = false;
}

} // namespace stipple::validation
