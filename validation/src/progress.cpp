#include "progress.h"

#include <stipple/render/progress_bar.h>

#include <cstdio>
#include <unistd.h>

namespace stipple::validation {

namespace {
bool quietProgress = false;
}

void Progress::setQuiet(bool quiet) { quietProgress = quiet; }

Progress::Progress(size_t total)
    : total_(total), tty_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

std::string Progress::eta() const {
    if (done_ == 0) return "?";
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_ - paused_).count();
    double remaining = elapsed / double(done_) * double(total_ - done_);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%dm%02ds", int(remaining) / 60, int(remaining) % 60);
    return buf;
}

void Progress::step(const std::string& what) {
    ++done_;
    if (quietProgress) return;
    if (tty_) {
        std::fprintf(stderr, "\r\033[K%s %zu/%zu cells, ETA %s  %.60s", render::progressBar(done_, total_).c_str(),
                     done_, total_, eta().c_str(), what.c_str());
        barShown_ = true;
    } else {
        std::fprintf(stderr, "[%zu/%zu] %s (ETA %s)\n", done_, total_, what.c_str(), eta().c_str());
    }
    std::fflush(stderr);
}

void Progress::note(const std::string& message) {
    if (quietProgress && !message.starts_with("ERROR")) return;
    if (tty_ && barShown_) std::fprintf(stderr, "\r\033[K");
    std::fprintf(stderr, "%s\n", message.c_str());
    barShown_ = false;
    std::fflush(stderr);
}

void Progress::pause() {
    if (isPaused_) return;
    isPaused_ = true;
    pausedAt_ = std::chrono::steady_clock::now();
}

void Progress::resume() {
    if (!isPaused_) return;
    isPaused_ = false;
    paused_ += std::chrono::steady_clock::now() - pausedAt_;
}

void Progress::finish() {
    if (tty_ && barShown_) std::fprintf(stderr, "\n");
    barShown_ = false;
}

} // namespace stipple::validation
